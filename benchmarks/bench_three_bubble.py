"""A bubble in three.js: the film module's transmission and thickness maps, measured.

The flat films' page (:func:`evaluation.three_film.write_flat_site`) in headless Chromium
(three.js 0.187, WebGL2 on SwiftShader), a soap film (water, n = 1.33) in air with
128 x 128 R and T tables over 0.2-0.7 µm from colour-science (:mod:`evaluation.materials`):

- a thickness map: a mirror plane whose thickness is a ramp of G codes 0-255 across the
  canvas mapped to 0.25-0.65 µm, under a white environment: |canvas - exact R| (1/255);
- a flat bubble (0.45 µm, facing the camera) over a checker, environment radiance 0.25:
  |canvas - (R L + T background)| (1/255) inside the bubble, away from the checker's
  edges, and at 0, 1, 2, 3 pixels from them (three.js's transmission pass reads its
  render target with a bicubic B-spline: a blur of about a pixel at edges);
- the alternative mechanism, premultiplied blending into the 8-bit sRGB canvas (``dst *=
  T``, then ``dst += R L``): blending acts on encoded values, so its error is computed
  from the same colours: |enc(bg) T + enc(R L) - enc(bg T + R L)|;
- with ``--update-docs``, the pictures ``docs/gallery/threejs_bubble.png`` (a
  double-sided sphere of 0.35 µm over a dark grey checker, white environment) and
  ``docs/gallery/threejs_thickness_map.png`` (the sphere with a thickness map: 0.7 µm
  at the bottom of its uv to 0.2 µm at the top, a draining bubble).

Frame times are not measured: the page runs in Chromium's virtual time, differences of
whole runs' wall-clock times went negative on the shared two-core machine (±10 s of
noise against 5 s of frames), and Chromium's GPU process, where SwiftShader draws, is
not in the CPU time of the processes Python waits for.

Writes reports/bench_three_bubble.json (``_reports.write_json``: the errors above, in
1/255).

Run: ``PYTHONPATH=. python benchmarks/bench_three_bubble.py [--update-docs]``.
"""

from __future__ import annotations

import argparse
import base64
import shutil
import sys
import tempfile
from pathlib import Path

import colour
import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # benchmarks._reports, the evaluation package

from benchmarks import _reports  # noqa: E402  (after the path above)
from evaluation import browser, materials, three_film  # noqa: E402
from ocio_thinfilm.export.hosts.three import three_module  # noqa: E402

STACK = materials.SOAP_BUBBLE
RANGE_UM = (0.2, 0.7)
SIZE = 256
MAP_RANGE = (0.25, 0.65)
CODES = [round(i * 255 / (SIZE - 1)) for i in range(SIZE)]
CHECKER = ((0.8, 0.25, 0.05), (0.05, 0.4, 0.9))
SQUARES, HALF, BUBBLE_UM, L = 8, 0.75, 0.45, 0.25
GALLERY = ROOT / "docs" / "gallery"


def _scenes() -> list[dict]:
    bubble = {"kind": "bubble", "environment": L, "squares": SQUARES, "checker": CHECKER}
    # the pictures: a dark checker under a white environment shows the film's colours
    picture = {**bubble, "environment": 1.0, "checker": ((0.02,) * 3, (0.12,) * 3)}
    return [
        {"kind": "map", "environment": 1.0, "codes": CODES, "thicknessRange": MAP_RANGE},
        {**bubble, "bubble": HALF, "thickness": BUBBLE_UM},
        {**picture, "shape": "sphere", "bubble": 0.8, "thickness": 0.35},
        {
            **picture,
            "shape": "sphere",
            "bubble": 0.8,
            "codes": [255 - c for c in CODES],
            "mapAxis": "v",
            "thicknessRange": [0.2, 0.7],
        },
    ]


def _run(chromium: str, three: Path) -> list:
    """The page's frames (bottom row first, RGB)."""
    tmp = Path(tempfile.mkdtemp(prefix="bench-bubble-"))
    site = tmp / "site"
    module = three_module("Soap", "Soap_R.exr", RANGE_UM, transmittance_exr="Soap_T.exr")
    config = {"size": SIZE, "scenes": _scenes()}
    three_film.write_flat_site(site, three, module, config)
    for quantity, suffix in (("reflectance", "R"), ("transmittance", "T")):
        rgb = materials.table(STACK, RANGE_UM, 128, 128, quantity=quantity)
        path = site / f"Soap_{suffix}.exr"
        materials.write_table(path, rgb, key="Soap", quantity=quantity, range_um=RANGE_UM)
    with browser.serve(site) as url:
        dom, stderr, _ = browser.dump_dom(
            chromium, url + "index.html", tmp / "profile", "--window-size=400,400", timeout=900
        )
    shutil.rmtree(tmp, ignore_errors=True)
    out = browser.page_readback(dom, stderr)
    if "error" in out:
        sys.exit(out["error"])
    return [
        np.frombuffer(base64.b64decode(f), np.uint8).reshape(SIZE, SIZE, 4)[:, :, :3]
        for f in out["frames"]
    ]


def _encode(linear: np.ndarray) -> np.ndarray:
    return colour.cctf_encoding(np.clip(linear, 0.0, 1.0), "sRGB")


def _errors(frames: list) -> dict[str, float]:
    thickness = MAP_RANGE[0] + (MAP_RANGE[1] - MAP_RANGE[0]) * np.array(CODES) / 255.0
    exact = _encode(materials.film_rgb(STACK, thickness, 1.0))
    result = {"map": float((np.abs(frames[0] / 255.0 - exact[None]).max(axis=2) * 255).max())}
    x, y = np.meshgrid(np.arange(SIZE), np.arange(SIZE))
    side = SIZE // SQUARES
    even = ((x // side + y // side) % 2 == 0)[..., None]
    background = np.where(even, np.array(CHECKER[0]), np.array(CHECKER[1]))
    edge = np.minimum.reduce([x % side, side - 1 - x % side, y % side, side - 1 - y % side])
    centres = np.abs((np.arange(SIZE) + 0.5) / SIZE * 2.0 - 1.0)
    inside = np.maximum(centres[None, :], centres[:, None]) < HALF - 8.0 / SIZE
    r = materials.film_rgb(STACK, BUBBLE_UM, 1.0)
    t = materials.film_rgb(STACK, BUBBLE_UM, 1.0, quantity="transmittance")
    error = np.abs(frames[1] / 255.0 - _encode(r * L + t * background)).max(axis=2) * 255
    result["bubble"] = float(error[inside & (edge >= 3)].max())
    for d in range(4):
        result[f"bubble at {d} px from an edge"] = float(error[inside & (edge == d)].max())
    colours = np.array(CHECKER)
    blended = _encode(colours) * t + _encode(r * L)
    result["sRGB blending"] = float((np.abs(blended - _encode(colours * t + r * L)) * 255).max())
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    _reports.add_update_docs(parser)
    args = parser.parse_args()
    chromium = browser.chromium()
    if chromium is None:
        sys.exit("no chromium")
    frames = _run(chromium, browser.install_three())
    errors = _errors(frames)
    import OpenImageIO as oiio

    pictures = ((2, "threejs_bubble.png"), (3, "threejs_thickness_map.png"))
    if args.update_docs:
        for index, name in pictures:
            image = oiio.ImageBuf(np.ascontiguousarray(frames[index][::-1]))
            if not image.write(str(GALLERY / name)):
                sys.exit(oiio.geterror())
    print(f"three.js {browser.THREE_VERSION}, {SIZE}x{SIZE} px, SwiftShader (CPU):")
    for label, value in errors.items():
        print(f"  |canvas - exact| {label:32s} {value:6.2f}/255")
    _reports.write_json(
        "three_bubble",
        {"three": browser.THREE_VERSION, "size": SIZE, "canvas_vs_exact_255": errors},
        indent=2,
    )
    shown = ", ".join(str((GALLERY / name).relative_to(ROOT)) for _, name in pictures)
    if args.update_docs:
        print(f"  pictures: {shown}")
    else:
        print(f"  pictures not written (--update-docs writes them): {shown}")


if __name__ == "__main__":
    main()
