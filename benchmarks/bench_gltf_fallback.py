"""The ``.glb``'s ``KHR_materials_iridescence`` fallback against the exact film.

For every film of docs/films.toml: the default material table (linear Rec.709), the
fallback fitted as ``export material --gltf`` fits it (48 x 12 table nodes), and
Delta E 2000 between what three.js's iridescence shows on a mirror
(:func:`ocio_thinfilm.lut.khr_iridescence.mirror_reflectance`) and the exact film at
every node of the table (thickness x cos theta), for the fitted parameters and for the
extension's defaults (ior 1.3, 100-400 nm, factor 1; base: glTF's ior 1.5, or a metal
with the bare substrate's colour). For a free-standing film also the scene in front of
a uniform grey background (:data:`BACKGROUND`): the exact ``R + T b`` against the
fallback without ``KHR_materials_transmission`` (a black-backed mirror) and with it
(:func:`ocio_thinfilm.lut.iridescence_fit.scene_errors`).

Writes ``reports/bench_gltf_fallback.json``; with ``--update-docs`` rewrites the tables
of docs/gltf.md between :data:`BEGIN` and :data:`END` (tests/test_gltf.py holds the doc
to the JSON).

Run: ``PYTHONPATH=. python benchmarks/bench_gltf_fallback.py [--films KEY ...]
[--update-docs]`` (minutes: the fit of every film).
"""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # benchmarks._reports

from benchmarks import _reports  # noqa: E402  (after the path above)
from ocio_thinfilm.export.material import material_table  # noqa: E402
from ocio_thinfilm.lut import iridescence_fit  # noqa: E402
from ocio_thinfilm.physics.films import read_films  # noqa: E402

DOC = ROOT / "docs" / "gltf.md"
BEGIN, END = "<!-- bench_gltf_fallback:begin -->", "<!-- bench_gltf_fallback:end -->"
#: The fit's table nodes (thickness x cos theta), as ``export material --gltf``.
FIT_NODES = (48, 12)
#: The uniform background (linear grey) behind a free-standing film.
BACKGROUND = 0.5


def _stats(d: np.ndarray) -> list[float]:
    return [
        round(float(np.percentile(d, 50)), 1),
        round(float(np.percentile(d, 95)), 1),
        round(float(d.max()), 1),
    ]


def measure(key: str, film: Any) -> dict[str, Any]:
    """Return one film's row: the fitted parameters and the Delta E 2000 statistics."""
    table = material_table(film)
    start = time.perf_counter()
    target = iridescence_fit.target_from_table(
        film, table.reflectance, table.range_um, *FIT_NODES, transmittance=table.transmittance
    )
    model = iridescence_fit.fit_iridescence(target)
    took = time.perf_counter() - start
    h, w = table.size[1], table.size[0]
    full = iridescence_fit.target_from_table(
        film, table.reflectance, table.range_um, w, h, transmittance=table.transmittance
    )
    row: dict[str, Any] = {
        "film": key,
        "ior": model.ior,
        "thickness_nm": list(model.thickness_nm),
        "factor": model.factor,
        "base_ior": model.base_ior,
        "metalness": model.metalness,
        "base_colour": list(model.base_colour),
        "transmission": model.transmission,
        "default": _stats(iridescence_fit.fallback_errors(iridescence_fit.unfitted(full), full)),
        "fitted": _stats(iridescence_fit.fallback_errors(model, full)),
        "fit_s": round(took, 1),
    }
    if model.transmission > 0.0:
        mirror = replace(model, transmission=0.0)
        row["mirror_on_grey"] = _stats(iridescence_fit.scene_errors(mirror, full, [BACKGROUND] * 3))
        row["transmission_on_grey"] = _stats(
            iridescence_fit.scene_errors(model, full, [BACKGROUND] * 3)
        )
    return row


def _triple(s: list[float]) -> str:
    return " / ".join(f"{v:.1f}" for v in s)


def markdown(result: dict[str, Any]) -> str:
    """Return docs/gltf.md's tables (between :data:`BEGIN` and :data:`END`) of a result."""
    lines = [
        "| film | fitted (ior, nm, factor, base) | default p50 / p95 / max "
        "| fitted p50 / p95 / max | fit |",
        "|---|---|---|---|---|",
    ]
    for r in result["rows"]:
        lo, hi = r["thickness_nm"]
        if r["metalness"]:
            base = "metal " + ", ".join(f"{c:.4f}" for c in r["base_colour"])
        else:
            base = f"ior {r['base_ior']}"
        fitted = f"{r['ior']}, {lo}-{hi}, {r['factor']}, {base}"
        lines.append(
            f"| {r['film']} | {fitted} | {_triple(r['default'])} | {_triple(r['fitted'])} "
            f"| {r['fit_s']:.1f} s |"
        )
    free = [r for r in result["rows"] if "transmission_on_grey" in r]
    if free:
        lines += [
            "",
            f"A free-standing film in front of a uniform grey of {result['background']} "
            "(R + T · grey; ΔE2000 p50 / p95 / max):",
            "",
            "| film | transmission, base colour | without transmission | with transmission |",
            "|---|---|---|---|",
        ]
        for r in free:
            tint = ", ".join(f"{c:.4f}" for c in r["base_colour"])
            lines.append(
                f"| {r['film']} | {r['transmission']}, {tint} "
                f"| {_triple(r['mirror_on_grey'])} | {_triple(r['transmission_on_grey'])} |"
            )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:
    """Measure, write the JSON, and (``--update-docs``) docs/gltf.md's tables."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--films", nargs="+", help="only these films (default: every film)")
    parser.add_argument("--json", type=Path, help="write the JSON here instead of reports/")
    _reports.add_update_docs(parser)
    args = parser.parse_args(argv)
    films = read_films(ROOT / "docs" / "films.toml")
    keys = args.films or list(films)
    rows = []
    for key in keys:
        rows.append(measure(key, films[key]))
        print(markdown({"rows": rows[-1:], "background": BACKGROUND}), flush=True)
    result = {"fit_nodes": list(FIT_NODES), "background": BACKGROUND, "rows": rows}
    _reports.write_json("gltf_fallback", result, path=args.json)
    if args.films and args.update_docs:
        raise SystemExit("--update-docs needs every film (no --films)")
    _reports.update_section(DOC, BEGIN, END, markdown(result), update=args.update_docs)


if __name__ == "__main__":
    main()
