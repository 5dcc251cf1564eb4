"""Benchmark: what users' films cost a bake, and the exact model's accuracy and time.

1. ``ocio-thinfilm bake`` (the default config) against the same bake with ``--films``
   of ten films (dielectric, absorbing, metal substrates, a two-layer stack, the paper
   model), each in a fresh process with a warm disk cache (the default config's clip
   LUTs are cached; the films' tables are computed each time), best of ``--repeat``:
   prints both times, the difference and the ratio.
2. Per film: its table size, the time to compute its table, and the ΔE2000 (p99 / max)
   of its table against colour-science's TMM on a 1 nm grid (normal incidence or
   constant indices: where colour-science 0.4.7 is right) or PyPI tmm (4 nm).
3. The exact model's error against time: the Airy sum (``exact.airy_reflectance``)
   against the transfer matrices (``exact.stack_reflectance``) for one film (cost, and
   that they agree), and table size against ΔE2000 (max over 500 thicknesses against
   colour-science at 1 nm) and build time.

Usage: python benchmarks/bench_films.py [--repeat 2]; writes reports/bench_films.json.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from benchmarks import _reports  # noqa: E402  (after the path above)

TEN_FILMS = """
[materials.Oil]
n = 1.47
[materials.Oxide]
n = 2.9
k = 0.2
[films.Soap]
stack = ["air", "soap film", "air"]
[films.OilOnWater]
stack = ["air", "Oil", "water"]
angle_deg = 30
[films.ARCoat]
stack = ["air", "MgF2", "BK7"]
range_um = [0, 0.5]
[films.Temper]
stack = ["air", "Oxide", "Fe"]
range_um = [0, 0.3]
[films.AnodisedTi]
stack = ["air", "TiO2", "Ti"]
range_um = [0, 0.4]
angle_deg = 45
[films.Stack]
stack = ["air", "SiO2", "TiO2", "Al"]
vary = "TiO2"
thickness_nm = { SiO2 = 100.0 }
range_um = [0, 0.6]
[films.PaperSoap]
stack = ["air", "soap film", "air"]
model = "paper"
[films.SilicaOnGold]
stack = ["air", "fused silica", "Au"]
range_um = [0, 1.0]
[films.Chitin]
stack = ["air", "chitin", "air"]
[films.OxideOnCopper]
stack = ["air", "Oxide", "Cu"]
range_um = [0, 0.3]
"""


def _bake(out: Path, films: Path | None) -> float:
    cmd = [sys.executable, "-m", "ocio_thinfilm", "bake", "--out", str(out), "--quiet"]
    if films is not None:
        cmd += ["--films", str(films)]
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    start = time.perf_counter()
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        films = tmp / "films.toml"
        films.write_text(TEN_FILMS)
        _bake(tmp / "warm", None)  # fills the disk cache of the default config
        default = min(_bake(tmp / f"d{i}", None) for i in range(args.repeat))
        with_films = min(_bake(tmp / f"f{i}", films) for i in range(args.repeat))
    result: dict = {"bake_s": {"default": default, "with_10_films": with_films}, "films": {}}
    print(
        f"bake: default {default:.2f} s, with 10 films {with_films:.2f} s "
        f"(+{with_films - default:.2f} s, ratio {with_films / default:.2f})"
    )

    import colour

    from evaluation.films import WL, colour_R, tmm_RTA
    from evaluation.films import delta_E as _delta_E
    from ocio_thinfilm.lut import film_tables
    from ocio_thinfilm.physics import films as films_module

    shape = colour.SpectralShape(380, 780, 1)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    w1 = cmfs.values * d65.values[:, None]
    w1 /= w1[:, 1].sum()
    white = np.array([0.3127, 0.329])
    print(f"{'film':<14} {'size':>6} {'table s':>8} {'reference':>12} {'dE p99':>7} {'max':>6}")
    for key, film in films_module.parse_films(TEN_FILMS, "films.toml").items():
        start = time.perf_counter()
        table = film_tables.user_film_table(film)
        seconds = time.perf_counter() - start
        t = np.linspace(*film.range_um, 97)
        oblique = film.angle_deg > 0
        if film.model == "paper":
            continue
        if not oblique:
            ref, name = colour_R(film, t * 1000.0) @ w1, "colour 1 nm"
        else:
            t = t[::4]
            wl = np.arange(380.0, 781.0, 4.0)
            w = np.array([w1[np.searchsorted(WL, x)] for x in wl]) * 4.0
            w[[0, -1]] /= 2.0
            w /= w[:, 1].sum()
            ref = np.array([tmm_RTA(film, x * 1000.0, wl)[:, 0] for x in t]) @ w
            name = "tmm 4 nm"
        dE = _delta_E(table.lookup(t), ref, white)
        p99 = float(np.percentile(dE, 99))
        print(f"{key:<14} {table.size:>6} {seconds:>8.2f} {name:>12} {p99:>7.3f} {dE.max():>6.3f}")
        result["films"][key] = dict(
            size=table.size, table_s=seconds, reference=name, dE_p99=p99, dE_max=float(dE.max())
        )
    result["error_against_time"] = error_against_time()
    _reports.write_json("films", result)


def error_against_time() -> dict:
    """Section 3 of the module docstring (:func:`evaluation.films.error_against_time`)."""
    from evaluation.films import error_against_time as measure

    result = measure()
    print(
        f"one film, {result['thicknesses']} thicknesses x {result['wavelengths']} "
        f"wavelengths: Airy {result['airy_seconds'] * 1e3:.0f} ms, transfer matrices "
        f"{result['transfer_matrix_seconds'] * 1e3:.0f} ms, max |dR| {result['max_abs_dR']:.1e}"
    )
    sizes = [row["size"] for row in next(iter(result["tables"].values()))]
    print(f"{'film':<14} " + " ".join(f"{n:>11}" for n in sizes))
    for key, rows in result["tables"].items():
        cells = [f"{r['dE_max']:.3f}/{r['seconds']:.2f}s" for r in rows]
        print(f"{key:<14} " + " ".join(f"{v:>11}" for v in cells))
    return result


if __name__ == "__main__":
    main()
