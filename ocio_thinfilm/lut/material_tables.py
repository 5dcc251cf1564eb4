"""A film's colour against thickness and view angle: the numeric core of the material tables.

:func:`film_angle_XYZ` evaluates a film (:class:`~ocio_thinfilm.physics.films.Film`) at
every (thickness, cos theta) pair of two axes: its spectra by the film's model (the
exact model: transfer matrices with dispersive complex indices, s and p averaged,
:func:`ocio_thinfilm.physics.exact.stack_transmittance`; the paper model: Smits &
Meyer's Eq. 7 / 8, :func:`ocio_thinfilm.physics.films.film_reflectance`) on the
wavelength grid :func:`~ocio_thinfilm.physics.films.film_wavelengths` chooses for that
angle and the thickest layer (fine enough for the stack's optical path and the
sharpness of its fringes up to :data:`MAX_SHARPNESS`, so films of 10 um do not
alias), integrated to CIE XYZ with the colorimetry's weights
(:func:`ocio_thinfilm.colour.colorimetry.spectral_weights`, the perfect reflector at
Y = 1). theta is the angle in the incident medium; at
cos theta = 0 (grazing) every film reflects everything (R = 1, T = 0).

:func:`texel_centres` gives the axes of a table (texel-centre sampling) and
:func:`default_resolution` its measured default size (docs/materials.md).
"""

from __future__ import annotations

import concurrent.futures
import dataclasses
import math
import os
from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import reproducible
from ocio_thinfilm.checks import ParameterError, as_array, as_count
from ocio_thinfilm.lut import film_tables
from ocio_thinfilm.physics import exact, phasor
from ocio_thinfilm.physics import films as films_module
from ocio_thinfilm.physics.films import INCIDENT_MAX_K, Film
from ocio_thinfilm.physics.materials import VISIBLE_NM

__all__ = [
    "TEXELS_PER_FRINGE",
    "MIN_WIDTH",
    "MAX_WIDTH",
    "DEFAULT_HEIGHT",
    "MAX_SHARPNESS",
    "free_standing",
    "check_film",
    "texel_centres",
    "default_resolution",
    "available_workers",
    "film_angle_XYZ",
]

#: Texels of the thickness axis per shortest interference fringe (a thickness step of
#: ``380 nm / (2 n)``), measured in docs/materials.md.
TEXELS_PER_FRINGE = 40
#: Bounds of the default width.
MIN_WIDTH = 64
MAX_WIDTH = 1536
#: Rows of the cos theta axis, measured in docs/materials.md.
DEFAULT_HEIGHT = 192
#: The sharpest fringes (``|r_a r_b|`` of the varying layer) the wavelength step
#: resolves: near grazing incidence ``|r_a r_b| -> 1`` and the full criterion asks for
#: up to 20001 wavelengths per row; capped at 0.5 the colours move by Delta E 2000 <=
#: 0.004 (soap films of 1.5 and 10 um, anodised titanium, cos theta 0.01-0.3) with 6 to 16
#: times fewer wavelengths (docs/materials.md).
MAX_SHARPNESS = 0.5
#: Blocks of columns (by thickness) with a wavelength grid each.
_COLUMN_BLOCKS = 8
#: Columns per run of one exponential (uniform thickness axes, :func:`_phasors`).
_RUN = 64
#: Rows (and their samples: wavelengths x blocks) per unit of work of a thread.
_GROUP_ROWS = 16
_GROUP_SAMPLES = 1 << 14
#: Wavelengths per slice of a run's spectra (a run x a slice stays in cache), and of
#: the integration's sums by halves (:func:`_weigh`).
_SLICE = 256
#: Rows whose denominators ``|S z + U|`` may come within this of zero are evaluated in
#: complex form (the expanded ``|U|^2 + |S|^2 |z|^2 + 2 Re(S conj(U) z)`` would cancel).
_MARGIN = 1e-2
#: A thickness axis within this of uniform (nm) gets the powers of one phasor.
_UNIFORM_NM = 1e-9


def _visible_index(material) -> np.ndarray:
    return material.index(np.linspace(*VISIBLE_NM, 81))


def free_standing(film: Film) -> bool:
    """Return whether ``film`` transmits into the medium it is seen from.

    True when the substrate is the incident medium (the same indices over the
    visible) and neither absorbs: a soap bubble in air. Its transmittance is then a
    colour a renderer can use for the light passing through.

    Parameters
    ----------
    film : Film
        The film.

    Returns
    -------
    bool
        Whether its table has a transmittance.
    """
    n0, ns = _visible_index(film.stack[0]), _visible_index(film.stack[-1])
    return bool(np.abs(ns.imag).max() <= INCIDENT_MAX_K and np.allclose(n0.real, ns.real))


def check_film(film: Film) -> None:
    """Refuse a film no angle table can describe.

    Parameters
    ----------
    film : Film
        The film.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``film``) if its incident medium absorbs (no angle is defined in a lossy
        medium) or its thickness range has zero width.
    TypeError
        If ``film`` is not a :class:`~ocio_thinfilm.physics.films.Film`.
    """
    if not isinstance(film, Film):
        raise TypeError(f"film must be a Film, got {type(film).__name__}")
    k = float(np.abs(_visible_index(film.stack[0]).imag).max())
    if k > 0:
        raise ParameterError(
            "film",
            f" {film.key}: stack: the incident medium {film.stack[0].name!r} absorbs (k up to "
            f"{k:.3g}); an angle table needs a transparent incident medium, k = 0",
        )
    lo, hi = film.range_um
    if not (math.isfinite(lo) and math.isfinite(hi) and 0 <= lo < hi):
        raise ParameterError(
            "film", f" {film.key}: range_um: must satisfy 0 <= lo < hi, got [{lo:g}, {hi:g}]"
        )


def texel_centres(lo: float, hi: float, count: int) -> np.ndarray:
    """Return the centres ``lo + (i + 0.5) (hi - lo) / count`` of ``count`` texels over [lo, hi].

    Parameters
    ----------
    lo, hi : float
        The axis' range.
    count : int
        Texels.

    Returns
    -------
    numpy.ndarray
        ``count`` values, ascending.

    Examples
    --------
    >>> texel_centres(0.0, 1.0, 4).tolist()
    [0.125, 0.375, 0.625, 0.875]
    """
    return lo + (np.arange(count) + 0.5) * ((hi - lo) / count)


def default_resolution(film: Film) -> tuple[int, int]:
    r"""Return the default (width, height) of a film's table.

    The width: :data:`TEXELS_PER_FRINGE` texels per shortest fringe of the varying layer
    over its range (the thickness step ``380 nm / (2 n)`` of one fringe at 380 nm,
    ``n`` the layer's largest ``|index|`` there), rounded up to a multiple of 16 in
    [:data:`MIN_WIDTH`, :data:`MAX_WIDTH`]; the height :data:`DEFAULT_HEIGHT`.

    Parameters
    ----------
    film : Film
        The film.

    Returns
    -------
    tuple of int
        (width, height).

    Examples
    --------
    >>> from ocio_thinfilm.physics.films import parse_films
    >>> default_resolution(parse_films('[films.S]\nstack = ["air", "water", "air"]')["S"])
    (432, 192)
    """
    lo, hi = film.range_um
    n = float(np.abs(film.varying.index(np.array([380.0]))).max())
    fringes = (hi - lo) * 1000.0 / (380.0 / (2.0 * n))
    width = 16 * math.ceil(fringes * TEXELS_PER_FRINGE / 16)
    return int(min(MAX_WIDTH, max(MIN_WIDTH, width))), DEFAULT_HEIGHT


def _grid(film: Film, top_nm: float, sharpness: float | None = None) -> np.ndarray:
    """Return the wavelengths of one block: the film's grid, its count rounded up on a ladder.

    :func:`~ocio_thinfilm.physics.films.film_wavelengths` for the block's thickest
    layer, with the number of samples rounded up to ``1 + round(50 * 2**(m / 2))``: a
    few grids serve every film and angle, so their colorimetric weights are computed
    once (and cached on disk, :func:`ocio_thinfilm.colour.colorimetry.spectral_weights`).
    """
    wl = films_module.film_wavelengths(film, top_nm, MAX_SHARPNESS, sharpness=sharpness)
    if film.model == "paper":
        return wl
    m = max(0, math.ceil(2.0 * math.log2(max(wl.size - 1, 1) / 50.0) - 1e-9))
    count = 1 + round(50 * 2 ** (m / 2))
    return np.linspace(wl[0], wl[-1], count)


def film_spectra(
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


def available_workers() -> int:
    """Return the CPUs this process may run on (its affinity, else ``os.cpu_count()``).

    Returns
    -------
    int
        At least 1.
    """
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


@dataclasses.dataclass(frozen=True)
class _Block:
    """A row's block of columns: their indices (ascending thickness), wavelengths, weights
    (transposed, (3, N)) and the stack's indices there."""

    cols: np.ndarray
    wl: np.ndarray
    wT: np.ndarray
    n: np.ndarray | None
    white: np.ndarray


def _plan(film: Film, d: np.ndarray, c: np.ndarray) -> list[list[_Block]]:
    """Return each row's blocks: the serial, cheap part (grids, weights, indices).

    Columns in blocks of thickness (:data:`_COLUMN_BLOCKS`), each on the grid its
    thickest column needs at the row's angle (:func:`_grid`); grids, weights and indices
    are computed once per distinct grid.
    """
    order = np.argsort(d, kind="stable")
    blocks = [b for b in np.array_split(order, max(1, min(_COLUMN_BLOCKS, d.size // 64))) if b.size]
    known: dict[bytes, tuple[np.ndarray, np.ndarray, np.ndarray | None, np.ndarray]] = {}
    plan = []
    angles = np.degrees(np.arccos(c))
    sharpness = None if film.model == "paper" else films_module.fringe_sharpness(film, angles)
    for j, cosine in enumerate(c):
        row_film = _row_film(film, float(cosine))
        sharp = None if sharpness is None else float(sharpness[j])
        row = []
        for cols in blocks:
            wl = _grid(row_film, float(d[cols].max()), sharp)
            key = wl.tobytes()
            if key not in known:
                n = None if film.model == "paper" else np.stack([m.index(wl) for m in film.stack])
                wT = np.ascontiguousarray(film_tables.film_weights(film, wl).T)
                known[key] = (wl, wT, n, _weigh(np.ones((1, wl.size)), wT)[:, 0])
            wl, wT, n, white = known[key]
            row.append(_Block(cols, wl, wT, n, white))
        plan.append(row)
    return plan


def _row_film(film: Film, cosine: float) -> Film:
    return dataclasses.replace(film, angle_deg=float(np.degrees(np.arccos(cosine))))


def _axis_step(d: np.ndarray) -> float:
    """Return the step of the thickness axis (sorted): its phasors are anchors times
    powers of one step's phasor (:func:`_runs`)."""
    ds = np.sort(d)
    return float((ds[-1] - ds[0]) / max(ds.size - 1, 1))


def _runs(dd: np.ndarray, step: float) -> int:
    """Columns per run: one exponential per run when the (sorted) thicknesses are uniform.

    Runs of about :data:`_RUN` columns (equal lengths) when ``dd`` is ``dd[0] + k step``
    to :data:`_UNIFORM_NM`; else 1 (every column its own exponential).
    """
    m = dd.size
    if m < 3 or np.abs(dd - (dd[0] + step * np.arange(m))).max() > _UNIFORM_NM:
        return 1
    return -(-m // -(-m // _RUN))


def _powers(phase: np.ndarray, step: float, run: int) -> np.ndarray:
    """Return ``w^j`` for j < ``run``, ``w = exp(i phase step)``, shape (run, N).

    By products of earlier powers (``w^(n + i) = w^i w^n``): each is within
    ``2 log2(run)`` roundings (1e-15) of the exponential, in real arithmetic (the same
    bits on every CPU).
    """
    W = np.empty((run, phase.size), dtype=np.complex128)
    W[0] = 1.0
    if run > 1:
        W[1] = phasor.cexp_i(phase, step)
    n = 2
    while n < run:
        wn = phasor.cmul(W[n - 1], W[1])
        m = min(n, run - n)
        W[n : n + m] = phasor.cmul(W[:m], wn)
        n += m
    return W


class _GroupCoefficients:
    """The coefficients of a group of rows (all their blocks' wavelengths), real where
    they can be: 0.5 |P z + Q|^2 = q0 + q2 |z|^2 + Re(X z), |S z + U|^2 = u0 + u2 |z|^2 +
    Re(Y z), and the gaps ``|U| - |S|`` that bound the denominators from below."""

    def __init__(self, k: phasor.StackCoefficients) -> None:
        self.k = k
        self.X = [phasor.cmul(k.P[i], np.conj(k.Q[i])) for i in (0, 1)]
        self.Y = [2.0 * phasor.cmul(k.S[i], np.conj(k.U[i])) for i in (0, 1)]
        self.q = [(0.5 * phasor.abs2(k.Q[i]), 0.5 * phasor.abs2(k.P[i])) for i in (0, 1)]
        self.u = [(phasor.abs2(k.U[i]), phasor.abs2(k.S[i])) for i in (0, 1)]
        pairs = [*zip(k.S, k.U, strict=True), *(pair for above in k.above for pair in above)]
        self.gaps = [np.sqrt(phasor.abs2(U)) - np.sqrt(phasor.abs2(S)) for S, U in pairs]


def _prepare(
    g: _GroupCoefficients, part: slice, dd: np.ndarray, run: int, W: np.ndarray, A: np.ndarray
) -> tuple[list[_Run], np.ndarray, np.ndarray, np.ndarray | None]:
    """Return a row-block's runs and its powers (real, imaginary, ``|w|^2`` or None).

    ``part``: its wavelengths among the group's; ``W``: the powers ``w^j`` (>= ``run``
    rows) and ``A``: the runs' anchors (>= the block's runs), on those wavelengths. The
    expanded form holds where every denominator is at least :data:`_MARGIN` from 0:
    ``|S z + U| >= |U| - |S| |z| >= |U| - |S|`` for ``|z| <= 1``, ``||U| - |S||`` for
    ``|z| = 1`` (a lossless layer).
    """
    k = g.k
    lossless = not np.any(k.phase[part].imag)
    gap = min(float((np.abs(x[part]) if lossless else x[part]).min()) for x in g.gaps)
    direct = not gap >= _MARGIN
    count = -(-dd.size // run)
    A = A[:count]
    Wr, Wi = np.ascontiguousarray(W[:run].real), np.ascontiguousarray(W[:run].imag)
    W2 = None if lossless else Wr * Wr + Wi * Wi
    size2 = None if lossless else phasor.abs2(A)
    power = [
        k.power[i][part] if size2 is None else k.power[i][part] * np.sqrt(size2) for i in (0, 1)
    ]
    forms: list[tuple] = []
    for i in (0, 1):
        if direct:
            above = [(phasor.cmul(Sj[part], A), Uj[part]) for Sj, Uj in k.above[i]]
            P, S = phasor.cmul(k.P[i][part], A), phasor.cmul(k.S[i][part], A)
            forms.append((P, k.Q[i][part], S, k.U[i][part], above))
            continue
        X, Y = phasor.cmul(g.X[i][part], A), phasor.cmul(g.Y[i][part], A)
        (q0, q2), (u0, u2) = g.q[i], g.u[i]
        q0, q2, u0, u2 = q0[part], q2[part], u0[part], u2[part]
        if size2 is None:  # |z| = 1
            q0, u0 = q0 + q2, u0 + u2
            q2s = u2s = q2  # unused
        else:
            q2s, u2s = q2 * size2, u2 * size2
        forms.append((q0, q2s, X.real.copy(), -X.imag, u0, u2s, Y.real.copy(), -Y.imag))
    runs = []
    for r in range(count):
        co = _Run()
        co.direct = direct
        co.power = [p[r] if p.ndim == 2 else p for p in power]
        if direct:
            co.complex = [
                (P[r], Q, S[r], U, [(Sj[r], Uj) for Sj, Uj in above]) for P, Q, S, U, above in forms
            ]
        else:
            co.real = [tuple(x[r] if x.ndim == 2 else x for x in f) for f in forms]
        runs.append(co)
    return runs, Wr, Wi, W2


class _Run:
    """A run's coefficients, per polarisation: its columns' spectra are those of the
    powers ``w^j`` with the anchor's phasor folded into the coefficients
    (``z = anchor w^j``: ``P z = (P anchor) w^j``), :func:`_spectra`."""

    direct: bool
    power: list[np.ndarray]
    complex: list[tuple]  # (P A, Q, S A, U, [(S_j A, U_j)]): the direct form
    real: list[tuple]  # (q0, q2, Re X, -Im X, u0, u2, Re Y, -Im Y): the expanded form


def _spectra(
    co: _Run,
    Wr: np.ndarray,
    Wi: np.ndarray,
    W2: np.ndarray | None,
    sl: slice,
    R: np.ndarray,
    T: np.ndarray | None,
) -> np.ndarray | None:
    """Write ``R`` (and ``T``) of the powers ``Wr + i Wi`` (columns x wavelengths ``sl``).

    ``W2``: ``|w|^2`` (None for a lossless layer, ``|w| = 1``). Returns a mask of the
    columns where a denominator is 0 (Rouard's recursion takes the interface's own
    reflection there: the caller re-evaluates them), or None.
    """
    bad = None
    tmp = np.empty_like(Wr)
    num_buf = np.empty_like(Wr)
    den_buf = np.empty_like(Wr)
    for i in (0, 1):
        if co.direct:
            P, Q, S, U, above = co.complex[i]
            num = _abs2_of(P[sl], Q[sl], Wr, Wi)
            num *= 0.5
            den = _abs2_of(S[sl], U[sl], Wr, Wi)
            zero = den == 0
            for Sj, Uj in above:
                zero |= _abs2_of(Sj[sl], Uj[sl], Wr, Wi) == 0
            if zero.any():
                bad = zero.any(axis=1) if bad is None else bad | zero.any(axis=1)
                den[zero] = 1.0
        else:
            q0, q2, xr, xi, u0, u2, yr, yi = co.real[i]
            num = np.multiply(Wr, xr[sl], out=num_buf)
            num += np.multiply(Wi, xi[sl], out=tmp)
            num += q0[sl]
            den = np.multiply(Wr, yr[sl], out=den_buf)
            den += np.multiply(Wi, yi[sl], out=tmp)
            den += u0[sl]
            if W2 is not None:
                num += np.multiply(W2, q2[sl], out=tmp)
                den += np.multiply(W2, u2[sl], out=tmp)
        np.reciprocal(den, out=den)
        if i == 0:
            np.multiply(num, den, out=R)
        else:
            R += np.multiply(num, den, out=num)
        if T is not None:
            if i == 0:
                np.multiply(den, co.power[i][sl], out=T)
            else:
                T += np.multiply(den, co.power[i][sl], out=den)
    np.clip(R, 0.0, 1.0, out=R)
    if T is not None:
        if W2 is not None:
            T *= np.sqrt(W2, out=tmp)
        np.clip(T, 0.0, 1.0, out=T)
    return bad


def _abs2_of(S: np.ndarray, U: np.ndarray, zr: np.ndarray, zi: np.ndarray) -> np.ndarray:
    """``|S z + U|^2`` in real arithmetic, ``z = zr + i zi``."""
    re = zr * S.real
    re -= zi * S.imag
    re += U.real
    im = zi * S.real
    im += zr * S.imag
    im += U.imag
    re *= re
    im *= im
    re += im
    return re


def _rows(
    film: Film,
    c: np.ndarray,
    d: np.ndarray,
    plan: list[list[_Block]],
    transmit: bool,
    out_R: np.ndarray,
    out_T: np.ndarray | None,
) -> None:
    """Evaluate a group of rows into ``out_R`` (and ``out_T``), (rows, W, 3) views.

    The stack's coefficients of all the group's rows and blocks are computed together
    (elementwise: each value is what it would be alone), then each row by :func:`_row`.
    """
    g = None
    if film.model != "paper":
        n_all = np.concatenate([blk.n for row in plan for blk in row if blk.n is not None], axis=1)
        wl_all = np.concatenate([blk.wl for row in plan for blk in row])
        c_all = np.concatenate(
            [np.full(blk.wl.size, c[j]) for j, row in enumerate(plan) for blk in row]
        )
        g = _GroupCoefficients(
            phasor.stack_coefficients(n_all, film.thickness_nm, film.vary, wl_all, c_all, transmit)
        )
    prepared: list[list] = [[] for _ in plan]
    if g is not None:
        # the blocks' columns are the same in every row: their runs, anchors and powers
        # for all the group's wavelengths at once
        blocks = plan[0]
        dds = [d[blk.cols] for blk in blocks]
        step = _axis_step(d)
        run_of = [_runs(dd, step) for dd in dds]
        phase = g.k.phase
        offsets = np.cumsum([0] + [blk.wl.size for row in plan for blk in row])
        if min(run_of) > 1:  # a uniform axis: one set of powers
            W_all = _powers(phase, step, max(run_of))
            starts = [dd[::run] for dd, run in zip(dds, run_of, strict=True)]
            count = max(a.size for a in starts)
            L = np.empty((count, phase.size))
            for s_, (j, b) in enumerate(
                (j, b) for j in range(len(plan)) for b in range(len(blocks))
            ):
                anchor_d = starts[b]
                L[:, offsets[s_] : offsets[s_ + 1]] = np.pad(
                    anchor_d, (0, count - anchor_d.size), mode="edge"
                )[:, None]
            A_all = phasor.cexp_i(phase, L)
            for s_, (j, b) in enumerate(
                (j, b) for j in range(len(plan)) for b in range(len(blocks))
            ):
                part = slice(offsets[s_], offsets[s_ + 1])
                prepared[j].append(
                    _prepare(g, part, dds[b], run_of[b], W_all[:, part], A_all[:, part])
                )
        else:
            for s_, (j, b) in enumerate(
                (j, b) for j in range(len(plan)) for b in range(len(blocks))
            ):
                part = slice(offsets[s_], offsets[s_ + 1])
                W = _powers(phase[part], step, run_of[b])
                A = phasor.cexp_i(phase[part], dds[b][:: run_of[b], None])
                prepared[j].append(_prepare(g, part, dds[b], run_of[b], W, A))
    for j, row in enumerate(plan):
        _row(
            film,
            float(c[j]),
            d,
            row,
            prepared[j],
            transmit,
            out_R[j],
            None if out_T is None else out_T[j],
        )


def _row(
    film: Film,
    cosine: float,
    d: np.ndarray,
    blocks: list[_Block],
    prepared: list,
    transmit: bool,
    out_R: np.ndarray,
    out_T: np.ndarray | None,
) -> None:
    """Evaluate one row (one cos theta) into ``out_R`` (and ``out_T``): (W, 3) views.

    Its arithmetic depends on the row alone, never on which worker runs it or with
    which other rows: the tables are the same bits on any number of workers. The
    stack's coefficients are computed once for the row (all its blocks' wavelengths
    together: elementwise, so each value is what it would be alone); a run of columns
    is evaluated :data:`_SLICE` wavelengths at a time, each slice's spectra weighted and
    summed (:func:`_weigh`) while they are in cache.
    """
    if film.model == "paper":
        row_film = _row_film(film, cosine)
        for blk in blocks:
            dd = d[blk.cols]
            for start in range(0, dd.size, _RUN):
                part = slice(start, start + _RUN)
                R, T = film_spectra(row_film, dd[part], blk.wl, transmit)
                out_R[blk.cols[part]] = _weigh(R, blk.wT).T
                if out_T is not None and T is not None:
                    out_T[blk.cols[part]] = _weigh(T, blk.wT).T
        return
    for blk, (runs, Wr, Wi, W2) in zip(blocks, prepared, strict=True):
        size = blk.wl.size
        dd = d[blk.cols]
        run = Wr.shape[0]
        # a lossless stack conserves energy: T = 1 - R (Byrnes 2016, Section 4), so its
        # colour is the white minus R's (the same sums by halves: T = 0 where R = 1)
        conserving = transmit and blk.n is not None and not np.any(blk.n.imag)
        R_buf = np.empty((run, min(_SLICE, size)))
        T_buf = np.empty_like(R_buf) if transmit and not conserving else None
        white = blk.white if conserving else None
        for start, co in zip(range(0, dd.size, run), runs, strict=True):
            cols = blk.cols[start : start + run]
            acc_R = np.zeros((3, run))
            acc_T = np.zeros((3, run)) if T_buf is not None else None
            for lo in range(0, size, _SLICE):
                sl = slice(lo, min(lo + _SLICE, size))
                R = R_buf[:, : sl.stop - lo]
                T = None if T_buf is None else T_buf[:, : sl.stop - lo]
                bad = _spectra(
                    co, Wr[:, sl], Wi[:, sl], None if W2 is None else W2[:, sl], sl, R, T
                )
                if bad is not None and bad[: cols.size].any():
                    # Rouard's recursion divides by 0 there: its own rule (stack_transmittance)
                    redo = np.flatnonzero(bad[: cols.size])
                    R_old, T_old = film_spectra(
                        _row_film(film, cosine), dd[start + redo], blk.wl[sl], T is not None
                    )
                    R[redo] = R_old
                    if T is not None and T_old is not None:
                        T[redo] = T_old
                acc_R += _weigh(R, blk.wT[:, sl])
                if acc_T is not None and T is not None:
                    acc_T += _weigh(T, blk.wT[:, sl])
            out_R[cols] = acc_R.T[: cols.size]
            if out_T is not None and white is not None:
                out_T[cols] = white - out_R[cols]
            elif out_T is not None and acc_T is not None:
                out_T[cols] = acc_T.T[: cols.size]


def _weigh(S: np.ndarray, wT: np.ndarray) -> np.ndarray:
    """Return ``(S @ wT.T).T`` for ``S`` (columns, <= :data:`_SLICE`), by halves.

    The spectra times each weight, summed over the wavelengths by
    :func:`ocio_thinfilm.reproducible.pairwise_sum` (a fixed tree of elementwise
    additions: the same bits on every CPU); longer spectra go :data:`_SLICE` wavelengths
    at a time, the slices' sums added in order. Shape (3, columns).
    """
    out = np.zeros((wT.shape[0], S.shape[0]))
    for lo in range(0, S.shape[1], _SLICE):
        sl = slice(lo, lo + _SLICE)
        out += reproducible.pairwise_sum(S[None, :, sl] * wT[:, None, sl], overwrite=True)
    return out


def film_angle_XYZ(
    film: Film,
    thickness_um: npt.ArrayLike,
    cos_theta: npt.ArrayLike,
    *,
    transmittance: bool = False,
    workers: int | None = None,
    progress: Callable[[int], object] | None = None,
) -> tuple[np.ndarray, np.ndarray | None]:
    r"""Return CIE XYZ of a film's reflectance (and transmittance) over thickness x cos theta.

    The exact model is evaluated through
    :func:`~ocio_thinfilm.physics.phasor.stack_coefficients`: per row (cos theta) and
    wavelength grid the stack reduces to coefficients that do not depend on the
    varying thickness, and each (thickness, wavelength) sample costs a few real
    operations on the layer's phasor ``z = exp(i phase d)``; on a uniform thickness
    axis ``z`` is one exponential per run of :data:`_RUN` columns times powers of one
    step's phasor. Where Rouard's recursion would divide by zero (grazing incidence on
    an absentee layer) the sample is evaluated by
    :func:`~ocio_thinfilm.physics.exact.stack_transmittance` and its rule. Every
    operation is elementwise and correctly rounded, or libm's complex exponential, and
    the integration is :func:`ocio_thinfilm.reproducible.matmul`: the same bits on every
    CPU, and for any ``workers`` (rows are split among threads, a row's arithmetic
    never depends on the split).

    Parameters
    ----------
    film : Film
        The film (its ``angle_deg`` is replaced by each angle).
    thickness_um : array_like
        1-D physical thicknesses of the varying layer, um, >= 0 (the columns).
    cos_theta : array_like
        1-D cosines of the angle of incidence in the incident medium, in [0, 1] (the
        rows; 0 and 1 exactly are grazing and normal incidence).
    transmittance : bool, optional
        Also the transmittance (the incident medium must not absorb).
    workers : int, optional
        Threads that evaluate rows (numpy releases the GIL in its loops); default
        :func:`available_workers`.
    progress : callable, optional
        Called with the number of rows finished, as they finish (a progress bar's
        ``update``).

    Returns
    -------
    XYZ_R : numpy.ndarray
        Shape ``(len(cos_theta), len(thickness_um), 3)``, the perfect reflector at the
        D65 white with Y = 1 (the film's illuminant adapted to D65).
    XYZ_T : numpy.ndarray or None
        The same for the transmittance, or None.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``thickness_um``, ``cos_theta``, ``workers``) out of range or not 1-D.

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
    workers = available_workers() if workers is None else as_count("workers", workers, 1, 4096)
    d = t * 1000.0
    out_R = np.empty((c.size, d.size, 3))
    out_T = np.empty((c.size, d.size, 3)) if transmittance else None
    plan = _plan(film, d, c)
    # groups of consecutive rows: one coefficient call each, the unit of work of a thread
    groups, start, samples = [], 0, 0
    for j, row in enumerate(plan):
        samples += sum(blk.wl.size for blk in row)
        if samples >= _GROUP_SAMPLES or j + 1 - start >= _GROUP_ROWS or j + 1 == len(plan):
            groups.append(slice(start, j + 1))
            start, samples = j + 1, 0

    def run(rows: slice) -> int:
        _rows(
            film,
            c[rows],
            d,
            plan[rows],
            transmittance,
            out_R[rows],
            None if out_T is None else out_T[rows],
        )
        return rows.stop - rows.start

    if workers == 1 or len(groups) == 1:
        for rows in groups:
            done = run(rows)
            if progress is not None:
                progress(done)
    else:
        with concurrent.futures.ThreadPoolExecutor(min(workers, len(groups))) as pool:
            for future in concurrent.futures.as_completed([pool.submit(run, g) for g in groups]):
                done = future.result()
                if progress is not None:
                    progress(done)
    return out_R, out_T
