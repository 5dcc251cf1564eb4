"""Figure: films of docs/films.toml as Blender materials, rendered in Cycles.

The user's path end to end: ``export material`` (the package's exact tables, with
``--gamut clip``: Cycles clamps negative colours) writes each film's tables and Blender
script; PyPI ``bpy`` (:mod:`evaluation.blender`, its own venv) runs the script and renders
the test scene of tests/test_blender.py (a mirror sphere in a uniform white world,
orthographic camera, Cycles on the CPU) with the film's thickness ramping over its whole
range from the sphere's left edge to its right. Writes docs/gallery/blender_films.png
(an oil slick on water, anodised titanium, temper colours on iron; sRGB).

Usage: python benchmarks/fig_materials.py [--size 192] [--samples 16]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/
PICTURE = ROOT / "docs" / "gallery" / "blender_films.png"
#: The films of docs/films.toml shown, left to right.
FILMS = ("OilOnWater", "AnodisedTitanium", "Temper")


def render_film(key: str, work: Path, size: int, samples: int) -> np.ndarray:
    """Export the film's material with the package and render it in Cycles (linear RGB)."""
    from evaluation import blender
    from ocio_thinfilm.export import material
    from ocio_thinfilm.physics import films

    film = films.read_films(ROOT / "docs" / "films.toml")[key]
    out = work / key
    written = material.export_material(film, out, hosts=material.host_files(film), gamut="clip")
    script = next(p for p in written if p.suffix == ".py")
    exr = work / f"{key}.exr"
    # the script names the node group and material by the film's name (the EXR header's)
    job = {"kind": "script", "script": str(script), "name": film.name}
    blender.render(
        {
            "engine": "CYCLES",
            "size": size,
            "out": str(exr),
            "material": job,
            "thickness_um": list(film.range_um),
            "samples": samples,
        }
    )
    return blender.read_exr(exr)


def main() -> None:
    import colour
    import OpenImageIO as oiio

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=192)
    parser.add_argument("--samples", type=int, default=16)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        images = [render_film(key, Path(tmp), args.size, args.samples) for key in FILMS]
    row = np.concatenate(images, axis=1)
    code = colour.cctf_encoding(np.clip(row, 0.0, 1.0), function="sRGB")
    pixels = np.round(code * 255.0).astype(np.uint8)
    out = oiio.ImageOutput.create(str(PICTURE))
    spec = oiio.ImageSpec(pixels.shape[1], pixels.shape[0], 3, oiio.UINT8)
    if out is None or not out.open(str(PICTURE), spec):
        raise SystemExit(f"cannot write {PICTURE}: {oiio.geterror()}")
    ok = out.write_image(np.ascontiguousarray(pixels))
    if not (out.close() and ok):
        raise SystemExit(f"cannot write {PICTURE}: {oiio.geterror()}")
    print(f"wrote {PICTURE.relative_to(ROOT)} ({', '.join(FILMS)})")


if __name__ == "__main__":
    main()
