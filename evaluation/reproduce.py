"""Regenerate a sample of the package's files, to compare their bytes across CPUs.

``python -m evaluation.reproduce OUT`` writes into the directory ``OUT``:

- ``cfg/`` -- the config's LUT files for one display, Display P3 (its clip's two passes
  and its compression's two squeezes), and the three thin-film tables, as ``bake``
  writes them into ``configs/thinfilm/luts``;
- ``luts/`` -- ``ACEScct_to_Rec2020_ConstantLightnessClip.cube``, the lattice-fitted
  display LUT of ``luts/`` (the fit that amplifies last-bit differences most);
- ``shaders/`` -- ``export shader`` output, GLSL and DCTL, for both mapped views on an
  SDR and an HDR display;
- ``knobs.html`` -- the knob page;
- ``render/`` -- ``render all --size 64``: the four scenes' EXRs and PNGs (the noise,
  the scenes' shading and the config's processors, as the gallery's
  ``render all --out docs/gallery`` computes them, at a small size).

Run under other ``OPENBLAS_CORETYPE`` and ``NPY_DISABLE_CPU_FEATURES`` settings, with
``OCIO_THINFILM_CACHE=0`` so that nothing comes from a disk memo, the files must be the
bytes committed (``tests/test_reproducible.py``).
"""

from __future__ import annotations

import sys
from pathlib import Path

#: (display, view, language) of the shaders written. Pinned, not the registry's lists:
#: the committed reference bytes (tests/test_reproducible.py) are of these samples.
SHADERS = (
    ("Display P3", "Constant-Lightness Clip", "glsl"),
    ("Display P3", "Constant-Lightness Compress", "dctl"),
    ("Rec.2100-PQ", "Constant-Lightness Clip", "dctl"),
    ("Rec.2100-PQ", "Constant-Lightness Compress", "glsl"),
)
#: The display whose config LUTs are written.
CONFIG_DISPLAY = "Display P3"
#: The display of the luts/ .cube written.
CUBE_DISPLAY = "Rec.2020"
#: The size (pixels a side) of the scenes rendered.
RENDER_SIZE = 64
#: The render command (``--out DIR`` follows).
RENDER_ARGV = ("render", "all", "--size", str(RENDER_SIZE), "--quiet")


def shader_name(display: str, view: str, language: str) -> str:
    """Return the file name of a regenerated shader."""
    return f"{display}_{view}.{language}".replace(" ", "_")


def regenerate(out: Path) -> list[Path]:
    """Write the sample into ``out`` (which must exist); return the files written."""
    import PyOpenColorIO as ocio

    from ocio_thinfilm import config
    from ocio_thinfilm.cli.main import main as cli_main
    from ocio_thinfilm.export import knob_page
    from ocio_thinfilm.export import view as export_view
    from ocio_thinfilm.lut import clip_lut, compress_lut

    written = []
    (out / "cfg").mkdir()
    files = config.data.lut_files(
        {CONFIG_DISPLAY: clip_lut.clip_lut(CONFIG_DISPLAY)},
        compress_by_display={CONFIG_DISPLAY: compress_lut.compress_lut(CONFIG_DISPLAY)},
    )
    raw = ocio.Config.CreateRaw()
    for name, transform in sorted(files.items()):
        transform.write("Academy/ASC Common LUT Format", str(out / "cfg" / name), raw)
        written.append(out / "cfg" / name)

    (out / "luts").mkdir()
    source, view = "ACEScct", "Constant-Lightness Clip"
    name = export_view.set_name(source, CUBE_DISPLAY, view) + ".cube"
    written += export_view.export_view(
        source, CUBE_DISPLAY, view, out / "luts" / name, size=export_view.DEFAULT_VIEW_SIZE
    )

    (out / "shaders").mkdir()
    for display, view, language in SHADERS:
        path = out / "shaders" / shader_name(display, view, language)
        argv = ["export", "shader", "--lang", language, "--from", "ACEScct"]
        argv += ["--display", display, "--view", view, "--out", str(path)]
        if cli_main(argv) != 0:
            raise RuntimeError(f"export shader failed: {argv}")
        written.append(path)

    written.append(knob_page.write_knob_page(out / "knobs.html"))

    (out / "render").mkdir()
    if cli_main([*RENDER_ARGV, "--out", str(out / "render")]) != 0:
        raise RuntimeError(f"render failed: {RENDER_ARGV}")
    written += sorted((out / "render").iterdir())
    return written


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: python -m evaluation.reproduce OUT")
    target = Path(sys.argv[1])
    target.mkdir(parents=True, exist_ok=False)
    for path in regenerate(target):
        print(path)
