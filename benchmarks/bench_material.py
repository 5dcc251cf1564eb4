"""``export material``: the tables' error against resolution, and the time of one export.

For the films of docs/films.toml and a 10 um soap film, the table (texel-centre, read
bilinearly with clamp-to-edge as a host does: ``MaterialTable.lookup``) is compared
with the exact film evaluated at random (thickness, cos theta) points, uniform over the
range and [0, 1], by CIE Delta E 2000 of the reflectance (and transmittance); then
``export material`` at the default resolution is timed per film.

Run: ``PYTHONPATH=. python benchmarks/bench_material.py [--samples N]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import tempfile
import time
from pathlib import Path

import numpy as np

from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.export.material import export_material, material_table
from ocio_thinfilm.lut import material_tables
from ocio_thinfilm.physics import exact, films

ROOT = Path(__file__).resolve().parents[1]
SPACE = "Linear Rec.709 (sRGB)"


def uniform_weights(wl):
    """colour-science's CMFs times D65 on a uniform grid ``wl``, Y = 1 for the perfect
    reflector (``align`` interpolates both to the grid)."""
    import colour

    shape = colour.SpectralShape(float(wl[0]), float(wl[-1]), float(wl[1] - wl[0]))
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    w = cmfs.values * d65.values[:, None]
    white = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    return w / w[:, 1].sum(), white


def exact_points(film, t, c, transmit):
    """XYZ of the film at the points (t, c), one evaluation each: the exact engine on the
    film's full wavelength criterion (no sharpness cap), colour-science's CMFs and D65."""
    R = np.empty((t.size, 3))
    T = np.empty((t.size, 3))
    for i, (ti, ci) in enumerate(zip(t, c, strict=True)):
        row = dataclasses.replace(film, angle_deg=float(np.degrees(np.arccos(ci))))
        wl = films.film_wavelengths(row, ti * 1000.0)
        w, _ = uniform_weights(wl)
        if row.model == "paper":
            r = films.film_reflectance(row, [ti * 1000.0], wl)
            tt = 1.0 - r
        else:
            n = np.stack([m.index(wl) for m in row.stack])
            r, tt = exact.stack_transmittance(
                n, row.thickness_nm, row.vary, [ti * 1000.0], wl, row.angle_deg
            )
        R[i] = r[0] @ w
        T[i] = tt[0] @ w
    return R, (T if transmit else None)


def errors(film, table, t, c, ref_R, ref_T):
    """Delta E 2000 (p99, max) of the table's lookups against the references."""
    out = []
    for quantity, ref in (("reflectance", ref_R), ("transmittance", ref_T)):
        if ref is None:
            continue
        rgb = table.lookup(t, c, quantity)
        XYZ = colorimetry.RGB_to_XYZ(rgb, "sRGB")
        dE = colorimetry.delta_E2000(XYZ, ref)
        out.append((quantity[0].upper(), float(np.percentile(dE, 99)), float(dE.max())))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=400)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--film", action="append", help="only these films (keys)")
    args = parser.parse_args()
    fs = films.read_films(ROOT / "docs" / "films.toml")
    thick = dataclasses.replace(fs["SoapFilm"], key="Soap10um", range_um=(0.0, 10.0))
    chosen = [f for f in (*fs.values(), thick) if not args.film or f.key in args.film]
    rng = np.random.default_rng(args.seed)
    print("Delta E 2000 of bilinear lookups against the exact film (p99 / max)")
    for film in chosen:
        lo, hi = film.range_um
        t = rng.uniform(lo, hi, args.samples)
        c = rng.uniform(0.0, 1.0, args.samples)
        transmit = material_tables.free_standing(film)
        ref_R, ref_T = exact_points(film, t, c, transmit)
        w0, h0 = material_tables.default_resolution(film)
        for scale_w, scale_h in ((0.5, 1), (1, 0.5), (1, 1)):
            w, h = max(2, int(w0 * scale_w)), max(2, int(h0 * scale_h))
            table = material_table(film, space=SPACE, width=w, height=h)
            cells = "  ".join(
                f"{q} {p99:.3f} / {mx:.3f}"
                for q, p99, mx in errors(film, table, t, c, ref_R, ref_T)
            )
            mark = "  (default)" if (w, h) == (w0, h0) else ""
            print(f"  {film.key:18s} {w:5d} x {h:4d}: {cells}{mark}")
    print("\nexport material at the default resolution (best of 3, s)")
    for film in chosen:
        best = np.inf
        for _ in range(3):
            with tempfile.TemporaryDirectory() as tmp:
                start = time.perf_counter()
                export_material(film, Path(tmp) / "out")
                best = min(best, time.perf_counter() - start)
        w, h = material_tables.default_resolution(film)
        print(f"  {film.key:18s} {w:5d} x {h:4d}: {best:.2f} s")


if __name__ == "__main__":
    main()
