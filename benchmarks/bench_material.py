"""``export material``: the tables' error against resolution, and their speed.

For the films of docs/films.toml and a 10 um soap film:

- accuracy: the table (node-centred, read bilinearly as a host does:
  ``MaterialTable.lookup``) against the exact film evaluated at random (thickness,
  cos theta) points, uniform over the range and [0, 1], by CIE Delta E 2000 of the
  reflectance (and transmittance); and at the fixed angles 0, 30, 60, 80 and 89
  degrees over thicknesses across the range (``--fixed-points``);
- speed: ``film_angle_XYZ`` at the default resolution, the previous implementation
  (commit 241d2f2: a per-row loop over Rouard's complex recursion, one complex
  exponential per sample; copied below verbatim as ``old_film_angle_XYZ``) against the
  current one with 1 worker and with all, best of ``--repeats`` (the old one once: it
  takes minutes); the whole ``export material`` (files written) with all workers; ns per
  sample (a texel at one wavelength: the samples the plan actually evaluates); and the
  arithmetic's lower bound: the elementwise passes the engine makes per sample (counted
  from lut/material_engine.py's expanded form) times numpy's measured time per element of
  one such pass (a float64 multiply on cache-resident arrays), plus one complex
  exponential per run of 64 columns.

Writes ``reports/bench_material.json`` (``--json``; ``_reports.write_json``); never a
tracked doc. Timing with
``time.perf_counter`` only. The machine's load average is recorded: the numbers are
only comparable on an idle machine.

Run: ``PYTHONPATH=. python benchmarks/bench_material.py [--samples N] [--no-accuracy]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import numpy.typing as npt

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # benchmarks._reports

from benchmarks import _reports  # noqa: E402  (after the path above)
from ocio_thinfilm import reproducible  # noqa: E402
from ocio_thinfilm.checks import ParameterError, as_array  # noqa: E402
from ocio_thinfilm.colour import colorimetry  # noqa: E402
from ocio_thinfilm.export.material import export_material, material_table  # noqa: E402
from ocio_thinfilm.lut import film_tables, material_tables  # noqa: E402
from ocio_thinfilm.lut.material_tables import MAX_SHARPNESS, Film  # noqa: E402
from ocio_thinfilm.physics import exact, films  # noqa: E402
from ocio_thinfilm.physics import films as films_module  # noqa: E402

_COLUMN_BLOCKS = 8  # the previous implementation's constants
_BLOCK_SAMPLES = 1 << 20

SPACE = "Linear Rec.709 (sRGB)"
JSON = _reports.json_path("material")


# --------------------------------------------------------------------------- #
# The previous implementation (commit 241d2f2, ocio_thinfilm/lut/material_tables.py),
# verbatim but for the names
# --------------------------------------------------------------------------- #
def _old_grid(film: Film, top_nm: float) -> np.ndarray:
    """Return the wavelengths of one block: the film's grid, its count rounded up on a ladder.

    :func:`~ocio_thinfilm.physics.films.film_wavelengths` for the block's thickest
    layer, with the number of samples rounded up to ``1 + round(50 * 2**(m / 2))``: a
    few grids serve every film and angle, so their colorimetric weights are computed
    once (and cached on disk, :func:`ocio_thinfilm.colour.colorimetry.spectral_weights`).
    """
    wl = films_module.film_wavelengths(film, top_nm, MAX_SHARPNESS)
    if film.model == "paper":
        return wl
    m = max(0, math.ceil(2.0 * math.log2(max(wl.size - 1, 1) / 50.0) - 1e-9))
    count = 1 + round(50 * 2 ** (m / 2))
    return np.linspace(wl[0], wl[-1], count)


def _old_film_spectra(
    film: Film, d_nm: np.ndarray, wl: np.ndarray, transmit: bool
) -> tuple[np.ndarray, np.ndarray | None]:
    """Return the R (and T) spectra of ``film`` at its ``angle_deg``, thicknesses ``d_nm``.

    By the film's model: the exact engine's R and T of the stack
    (:func:`ocio_thinfilm.physics.exact.stack_transmittance`), or the paper's lossless
    film (T = 1 - R). ``transmit``: also T (the film must be :func:`free_standing`),
    else None. Shapes (len(d_nm), len(wl)).
    """
    if film.model == "paper":
        R = films_module.film_reflectance(film, d_nm, wl)
        # the paper's film is lossless: what it does not reflect it transmits
        return R, (1.0 - R) if transmit else None
    n = np.stack([m.index(wl) for m in film.stack])
    if transmit:
        return exact.stack_transmittance(n, film.thickness_nm, film.vary, d_nm, wl, film.angle_deg)
    return exact.stack_reflectance(n, film.thickness_nm, film.vary, d_nm, wl, film.angle_deg), None


def old_film_angle_XYZ(
    film: Film,
    thickness_um: npt.ArrayLike,
    cos_theta: npt.ArrayLike,
    *,
    transmittance: bool = False,
) -> tuple[np.ndarray, np.ndarray | None]:
    r"""Return CIE XYZ of a film's reflectance (and transmittance) over thickness x cos theta.

    Parameters
    ----------
    film : Film
        The film (its ``angle_deg`` is replaced by each angle).
    thickness_um : array_like
        1-D physical thicknesses of the varying layer, um, >= 0 (the columns).
    cos_theta : array_like
        1-D cosines of the angle of incidence in the incident medium, in [0, 1] (the
        rows).
    transmittance : bool, optional
        Also the transmittance (the incident medium must not absorb).

    Returns
    -------
    XYZ_R : numpy.ndarray
        Shape ``(len(cos_theta), len(thickness_um), 3)``, the perfect reflector at the
        D65 white with Y = 1 (the film's illuminant adapted to D65).
    XYZ_T : numpy.ndarray or None
        The same for the transmittance, or None.

    Examples
    --------
    At grazing incidence a soap film reflects everything (the D65 white):

    >>> from ocio_thinfilm.physics.films import parse_films
    >>> soap = parse_films('[films.S]\nstack = ["air", "soap film", "air"]')["S"]
    >>> R, T = film_angle_XYZ(soap, [0.3], [0.0], transmittance=True)
    >>> R.round(3).tolist(), T.round(6).tolist()
    ([[[0.95, 1.0, 1.089]]], [[[0.0, 0.0, 0.0]]])
    """
    t = np.atleast_1d(as_array("thickness_um", thickness_um, minimum=0.0, unit=" um"))
    c = np.atleast_1d(as_array("cos_theta", cos_theta, minimum=0.0, maximum=1.0))
    if t.ndim != 1 or c.ndim != 1:
        raise ParameterError("thickness_um", " and cos_theta must be 1-D")
    d = t * 1000.0
    out_R = np.empty((c.size, d.size, 3))
    out_T = np.empty((c.size, d.size, 3)) if transmittance else None
    # columns in blocks of thickness, each on the grid its thickest column needs
    order = np.argsort(d, kind="stable")
    blocks = np.array_split(order, max(1, min(_COLUMN_BLOCKS, d.size // 64)))
    for row, cosine in enumerate(c):
        row_film = dataclasses.replace(film, angle_deg=float(np.degrees(np.arccos(cosine))))
        for cols in blocks:
            if cols.size == 0:
                continue
            wl = _old_grid(row_film, float(d[cols].max()))
            w = film_tables.film_weights(film, wl)
            step = max(1, _BLOCK_SAMPLES // wl.size)
            for start in range(0, cols.size, step):
                part = cols[start : start + step]
                R, T = _old_film_spectra(row_film, d[part], wl, transmittance)
                out_R[row, part] = reproducible.matmul(R, w)
                if out_T is not None and T is not None:
                    out_T[row, part] = reproducible.matmul(T, w)
    return out_R, out_T


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


def accuracy(chosen, samples: int, seed: int) -> list[dict]:
    """The Delta E 2000 table: half width, half height, default, per film."""
    rng = np.random.default_rng(seed)
    rows = []
    print("Delta E 2000 of bilinear lookups against the exact film (p99 / max)")
    for film in chosen:
        lo, hi = film.range_um
        t = rng.uniform(lo, hi, samples)
        c = rng.uniform(0.0, 1.0, samples)
        transmit = material_tables.free_standing(film)
        ref_R, ref_T = exact_points(film, t, c, transmit)
        w0, h0 = material_tables.default_resolution(film)
        for scale_w, scale_h in ((0.5, 1), (1, 0.5), (1, 1)):
            w, h = max(2, int(w0 * scale_w)), max(2, int(h0 * scale_h))
            table = material_table(film, space=SPACE, width=w, height=h)
            found = errors(film, table, t, c, ref_R, ref_T)
            cells = "  ".join(f"{q} {p99:.3f} / {mx:.3f}" for q, p99, mx in found)
            mark = "  (default)" if (w, h) == (w0, h0) else ""
            print(f"  {film.key:18s} {w:5d} x {h:4d}: {cells}{mark}", flush=True)
            for q, p99, mx in found:
                rows.append(
                    {
                        "film": film.key,
                        "quantity": q,
                        "width": w,
                        "height": h,
                        "p99": round(p99, 4),
                        "max": round(mx, 4),
                        "default": bool(mark),
                    }
                )
    return rows


#: The angles a render sees most: a sphere's centre (0 deg) to its silhouette (89 deg).
FIXED_ANGLES_DEG = (0.0, 30.0, 60.0, 80.0, 89.0)


def fixed_angles(chosen, points: int) -> list[dict]:
    """Delta E 2000 (p99, max) of the default table at fixed angles, thicknesses across
    the range (ends included), against the exact film: normal incidence is the centre of
    every sphere, which random angles rarely sample."""
    rows = []
    print("Delta E 2000 of the default table at fixed angles (p99 / max)")
    for film in chosen:
        table = material_table(film, space=SPACE)
        lo, hi = film.range_um
        t = np.linspace(lo, hi, points)
        transmit = material_tables.free_standing(film)
        cells = []
        for angle in FIXED_ANGLES_DEG:
            c = np.full(t.shape, np.cos(np.radians(angle)))
            ref_R, ref_T = exact_points(film, t, c, transmit)
            for q, p99, mx in errors(film, table, t, c, ref_R, ref_T):
                cells.append(f"{angle:g}deg {q} {mx:.3f}")
                rows.append(
                    {
                        "film": film.key,
                        "angle_deg": angle,
                        "quantity": q,
                        "p99": round(p99, 4),
                        "max": round(mx, 4),
                    }
                )
        print(f"  {film.key:18s} " + "  ".join(cells), flush=True)
    return rows


def _best(fn, repeats: int) -> float:
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - start)
    return best


def pass_time() -> tuple[float, float]:
    """ns per element of one elementwise float64 pass (a multiply of cache-resident
    arrays, 64 x 256 as the engine's), and of numpy's complex exponential."""
    rng = np.random.default_rng(0)
    a, b, out = rng.random((64, 256)), rng.random(256), np.empty((64, 256))
    reps = 2000
    t_pass = _best(lambda: [np.multiply(a, b, out=out) for _ in range(reps)], 5) / reps / a.size
    z = 1j * rng.uniform(0.0, 100.0, 1 << 20)
    t_exp = _best(lambda: np.exp(z), 5) / z.size
    return t_pass * 1e9, t_exp * 1e9


def passes_per_sample(film: Film) -> int:
    """Elementwise passes per sample of the engine's expanded form (material_engine):
    per polarisation 4 for 0.5 |P w + Q|^2, 4 for |S w + U|^2, a reciprocal, a product,
    a sum; a clip; the integration's 3 products and about 3 additions by halves; a
    transmittance that is not 1 - R: 2 a polarisation and a clip; an absorbing varying
    layer: |w|^2 terms, 2 a polarisation each, and |w| for T."""
    n = 2 * (4 + 4 + 1 + 1 + 1) + 1 + 6
    wl = np.linspace(380.0, 780.0, 81)
    indices = np.stack([m.index(wl) for m in film.stack])
    lossless_stack = not np.any(indices.imag)
    if material_tables.free_standing(film) and not lossless_stack:
        n += 2 * 2 + 1 + 6
    if np.any(indices[film.vary + 1].imag):
        n += 2 * 4
    return n


def speed(chosen, repeats: int, all_workers: int, old_stride: int = 1) -> list[dict]:
    """Old against new, per film: film_angle_XYZ and the whole export."""
    t_pass, t_exp = pass_time()
    print(
        f"\nnumpy here: {t_pass:.2f} ns per element of a float64 pass (in cache), "
        f"{t_exp:.1f} ns per complex exponential; load average {os.getloadavg()[0]:.1f}"
    )
    print(
        "film_angle_XYZ at the default resolution (old: once; new: best of "
        f"{repeats}); export material with {all_workers} workers"
    )
    return [_time_film(film, repeats, all_workers, t_pass, t_exp, old_stride) for film in chosen]


def _time_film(
    film: Film, repeats: int, all_workers: int, t_pass: float, t_exp: float, old_stride: int
) -> dict:
    """Old against new for one film: film_angle_XYZ and the whole export."""
    w, h = material_tables.default_resolution(film)
    t = material_tables.axis_nodes(*film.range_um, w)
    c = material_tables.axis_nodes(0.0, 1.0, h)
    transmit = material_tables.free_standing(film)
    plan = material_tables._plan(film, t * 1000.0, c)
    samples = sum(b.cols.size * b.wl.size for row in plan for b in row)
    new_1 = _best(
        lambda: material_tables.film_angle_XYZ(film, t, c, transmittance=transmit, workers=1),
        repeats,
    )
    new_n = _best(
        lambda: material_tables.film_angle_XYZ(
            film, t, c, transmittance=transmit, workers=all_workers
        ),
        repeats,
    )

    def export() -> None:
        with tempfile.TemporaryDirectory() as tmp:
            export_material(film, Path(tmp) / "out", workers=all_workers)

    whole = _best(export, repeats)
    old = old_stride * _best(
        lambda: old_film_angle_XYZ(film, t, c[::old_stride], transmittance=transmit), 1
    )
    n_pass = passes_per_sample(film)
    bound = n_pass * t_pass + t_exp / 64.0
    ns_1, ns_n = new_1 / samples * 1e9, new_n / samples * 1e9
    print(
        f"  {film.key:16s} {w:5d} x {h:3d} {samples / 1e6:6.1f} M samples: old {old:7.2f} s, "
        f"new {new_1:6.2f} s (x{old / new_1:4.1f}) / {all_workers} workers {new_n:6.2f} s "
        f"(x{old / new_n:4.1f}); export {whole:6.2f} s; {ns_1:5.1f} / {ns_n:5.1f} ns a "
        f"sample, bound {bound:4.1f} ns ({n_pass} passes)",
        flush=True,
    )
    return {
        "film": film.key,
        "width": w,
        "height": h,
        "samples": samples,
        "old_s": round(old, 3),
        "new_1_worker_s": round(new_1, 3),
        f"new_{all_workers}_workers_s": round(new_n, 3),
        "ratio_1_worker": round(old / new_1, 2),
        f"ratio_{all_workers}_workers": round(old / new_n, 2),
        "export_s": round(whole, 3),
        "ns_per_sample_1_worker": round(ns_1, 2),
        f"ns_per_sample_{all_workers}_workers": round(ns_n, 2),
        "passes_per_sample": n_pass,
        "bound_ns_per_sample": round(bound, 2),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=400)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--film", action="append", help="only these films (keys)")
    parser.add_argument("--repeats", type=int, default=3, help="timed repeats (best kept)")
    parser.add_argument("--workers", type=int, default=material_tables.available_workers())
    parser.add_argument(
        "--old-stride",
        type=int,
        default=1,
        help="time the previous implementation on every k-th row only, times k (its rows "
        "are spread evenly over cos theta; 1: all rows, exact)",
    )
    parser.add_argument("--no-accuracy", action="store_true", help="speed only")
    parser.add_argument(
        "--fixed-points",
        type=int,
        default=32,
        help="thicknesses per film at each fixed angle (0 to skip that table)",
    )
    parser.add_argument("--no-speed", action="store_true", help="accuracy only")
    parser.add_argument("--json", default=str(JSON))
    args = parser.parse_args()
    fs = films.read_films(ROOT / "docs" / "films.toml")
    thick = dataclasses.replace(fs["SoapFilm"], key="Soap10um", range_um=(0.0, 10.0))
    chosen = [f for f in (*fs.values(), thick) if not args.film or f.key in args.film]
    material_table(chosen[0], width=8, height=4)  # imports and caches before timing
    result: dict = {
        "cpus": material_tables.available_workers(),
        "load_average": round(os.getloadavg()[0], 2),
    }
    if not args.no_accuracy and args.fixed_points > 0:
        result["fixed_angles"] = fixed_angles(chosen, args.fixed_points)
    if not args.no_accuracy and args.samples > 0:
        result["accuracy"] = accuracy(chosen, args.samples, args.seed)
    if not args.no_speed:
        result["old_stride"] = args.old_stride
        result["speed"] = speed(chosen, args.repeats, args.workers, args.old_stride)
    result["load_average_after"] = round(os.getloadavg()[0], 2)
    _reports.write_json("material", result, path=args.json, indent=1)


if __name__ == "__main__":
    main()
