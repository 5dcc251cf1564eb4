"""The ``.glb``'s ``KHR_materials_iridescence`` fallback against the exact film.

For every film of docs/films.toml: the default material table (linear Rec.709), the
fallback fitted as ``export material --gltf`` fits it (48 x 12 table nodes), and
Delta E 2000 between what three.js's iridescence shows on a mirror
(:func:`ocio_thinfilm.lut.khr_iridescence.mirror_reflectance`) and the exact film at
every node of the table (thickness x cos theta), for the fitted parameters and for the
extension's defaults (ior 1.3, 100-400 nm, factor 1; base: glTF's ior 1.5, or a metal
with the bare substrate's colour). Prints the table of docs/gltf.md.

Run: ``PYTHONPATH=. python benchmarks/bench_gltf_fallback.py``.
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from ocio_thinfilm.export.material import material_table
from ocio_thinfilm.lut import iridescence_fit
from ocio_thinfilm.physics.films import read_films

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    films = read_films(ROOT / "docs" / "films.toml")
    print(
        "| film | fitted (ior, nm, factor, base) | default p50 / p95 / max "
        "| fitted p50 / p95 / max | fit |"
    )
    print("|---|---|---|---|---|")
    for key, film in films.items():
        table = material_table(film)
        start = time.perf_counter()
        target = iridescence_fit.target_from_table(film, table.reflectance, table.range_um, 48, 12)
        model = iridescence_fit.fit_iridescence(target)
        took = time.perf_counter() - start
        h, w = table.size[1], table.size[0]
        full = iridescence_fit.target_from_table(film, table.reflectance, table.range_um, w, h)
        rows = []
        for m in (iridescence_fit.unfitted(full), model):
            d = iridescence_fit.fallback_errors(m, full)
            rows.append(f"{np.percentile(d, 50):.1f} / {np.percentile(d, 95):.1f} / {d.max():.1f}")
        base = f"base colour {model.base_colour}" if model.metalness else f"ior {model.base_ior}"
        fitted = (
            f"{model.ior}, {model.thickness_nm[0]}-{model.thickness_nm[1]}, {model.factor}, {base}"
        )
        print(f"| {key} | {fitted} | {rows[0]} | {rows[1]} | {took:.1f} s |", flush=True)


if __name__ == "__main__":
    main()
