"""Figure of docs/shaders.md, and the knob page: the spectrum through the exported GLSL.

The spectrum (380-700 nm, monochromatic colours at Y = 0.1 and Y = 0.4, sRGB display),
and a ramp at Y = 0.25 from grey to 2.5 sRGB boundary distances towards 510 nm (linear
in the distance), through the ``Constant-Lightness Clip`` view and the
``Constant-Lightness Compress`` view with three settings of its knobs: the default
0.8 / 1.3, a gentler 0.6 / 1.5 and a harder 0.9 / 1.1. Every pixel is computed by the
GLSL that ``ocio-thinfilm export shader`` writes, run on Mesa's headless llvmpipe
(:class:`evaluation.shaders.GlslView`, GLSL 3.30), with the knobs set as its uniforms;
the script checks each row against the double-precision analytic view
(:func:`evaluation.shaders.analytic_view`) and prints the largest difference. Labels are
drawn with OpenImageIO; the PNG is written through the package's safe writes.

It also rewrites docs/knobs.html (:func:`ocio_thinfilm.export.knob_page.write_knob_page`).

Usage: python benchmarks/fig_shaders.py [--out docs/shader_knobs.png]
"""

from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

DISPLAY = "sRGB"
LUMINANCES = (0.1, 0.4)
#: (label, view, knobs) of each row, top to bottom.
ROWS = [
    ("Clip", "Constant-Lightness Clip", None),
    ("Compress 0.8 / 1.3 (default)", "Constant-Lightness Compress", (0.8, 1.3)),
    ("Compress 0.6 / 1.5 (gentler)", "Constant-Lightness Compress", (0.6, 1.5)),
    ("Compress 0.9 / 1.1 (harder)", "Constant-Lightness Compress", (0.9, 1.1)),
]
#: The ramp block: luminance, wavelength (nm) and reach (sRGB boundary distances).
RAMP_Y = 0.25
RAMP_NM = 510.0
RAMP_REACH = 2.5
WIDTH = 960  # columns
LEFT = 300  # label margin
RIGHT = 24
ROW_HEIGHT = 40
ROW_GAP = 4
TITLE = 40  # above each block
AXIS = 34  # below each block: wavelength ticks
BACKGROUND = 0.13


def figure() -> tuple[np.ndarray, float]:
    """The figure's code values (H, W, 3) and the largest |GLSL - analytic| code value."""
    from evaluation.shaders import GlslView, analytic_view
    from ocio_thinfilm import registry
    from ocio_thinfilm.colour import colorimetry, compress
    from ocio_thinfilm.export import shader
    from ocio_thinfilm.render.frames import draw_labels

    wl = np.linspace(380.0, 700.0, WIDTH)
    blocks = [
        (
            f"Spectrum 380-700 nm at Y = {Y:g}, {DISPLAY} display (exported GLSL)",
            colorimetry.spectral_locus_XYZ(Y, wl),
            (380.0, 700.0),
            [(float(nm), f"{nm}") for nm in range(400, 701, 50)],
        )
        for Y in LUMINANCES
    ]
    # the ramp: grey -> RAMP_REACH sRGB boundary distances towards RAMP_NM, linear in d
    grey = RAMP_Y * colorimetry.white_XYZ(DISPLAY)
    spectral = colorimetry.spectral_locus_XYZ(RAMP_Y, [RAMP_NM])[0]
    d = float(compress.boundary_distance(colorimetry.XYZ_to_RGB(spectral, DISPLAY), DISPLAY))
    s = np.linspace(0.0, RAMP_REACH / d, WIDTH)[:, None]
    blocks.append(
        (
            f"Ramp at Y = {RAMP_Y:g} from grey towards {RAMP_NM:g} nm, {DISPLAY} boundary distance",
            grey + s * (spectral - grey),
            (0.0, RAMP_REACH),
            [(float(v), f"{v:g}") for v in np.arange(0.0, RAMP_REACH + 1e-9, 0.5)],
        )
    )
    block = TITLE + len(ROWS) * (ROW_HEIGHT + ROW_GAP) - ROW_GAP + AXIS
    height = block * len(blocks) + 8
    width = LEFT + WIDTH + RIGHT
    image = np.full((height, width, 3), BACKGROUND, np.float32)
    programs = {
        view: GlslView(shader.shader_source("glsl", DISPLAY, view)) for view in shader.SHADER_VIEWS
    }
    labels = []
    worst = 0.0
    for b, (title, XYZ, (lo, hi), ticks) in enumerate(blocks):
        top = b * block
        labels.append((LEFT + WIDTH // 2, top + TITLE - 12, title, 20))
        XYZ = XYZ.astype(np.float32)
        for r, (label, view, knobs) in enumerate(ROWS):
            t, lim = knobs if knobs else (None, None)
            codes = programs[view].apply(XYZ, t, lim)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                truth = analytic_view(XYZ, registry.REFERENCE, DISPLAY, view, *(knobs or ()))
            worst = max(worst, float(np.abs(codes - truth).max()))
            y0 = top + TITLE + r * (ROW_HEIGHT + ROW_GAP)
            image[y0 : y0 + ROW_HEIGHT, LEFT : LEFT + WIDTH] = codes[None]
            labels.append((LEFT // 2, y0 + ROW_HEIGHT // 2 + 7, label, 18))
        axis = top + TITLE + len(ROWS) * (ROW_HEIGHT + ROW_GAP) - ROW_GAP
        for value, text in ticks:
            x = LEFT + int(round((value - lo) / (hi - lo) * (WIDTH - 1)))
            image[axis : axis + 6, x] = 0.92
            labels.append((x, axis + 24, text, 15))
    for program in programs.values():
        program.release()
    image, drawn = draw_labels(image, labels)
    if not drawn:
        print("note: OpenImageIO could not draw the labels (no font); the figure has none")
    return image, worst


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs" / "shader_knobs.png"))
    parser.add_argument("--page", default=str(ROOT / "docs" / "knobs.html"))
    args = parser.parse_args()

    from ocio_thinfilm.export.knob_page import write_knob_page
    from ocio_thinfilm.io import write_image

    image, worst = figure()
    write_image(args.out, image)
    print(
        f"wrote {args.out}: the spectrum and a ramp through the clip and three compressions; "
        "exported "
        f"GLSL on Mesa, max |GLSL - analytic view| = {worst * 255:.3f}/255"
    )
    print(f"wrote {write_knob_page(args.page)}")


if __name__ == "__main__":
    main()
