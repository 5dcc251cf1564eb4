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


def _plan(film: Film, d: np.ndarray, c: np.ndarray) -> list[list[_Block]]:
    """Return each row's blocks: the serial, cheap part (grids, weights, indices).

    Columns in blocks of thickness (:data:`_COLUMN_BLOCKS`), each on the grid its
    thickest column needs at the row's angle (:func:`_grid`); grids, weights and indices
    are computed once per distinct grid.
    """
    order = np.argsort(d, kind="stable")
    blocks = [b for b in np.array_split(order, max(1, min(_COLUMN_BLOCKS, d.size // 64))) if b.size]
    known: dict[bytes, tuple[np.ndarray, np.ndarray, np.ndarray | None]] = {}
    plan = []
    for cosine in c:
        row_film = _row_film(film, float(cosine))
        sharp = None if film.model == "paper" else films_module.fringe_sharpness(row_film)
        row = []
        for cols in blocks:
            wl = _grid(row_film, float(d[cols].max()), sharp)
            key = wl.tobytes()
            if key not in known:
                n = None if film.model == "paper" else np.stack([m.index(wl) for m in film.stack])
                wT = np.ascontiguousarray(film_tables.film_weights(film, wl).T)
                known[key] = (wl, wT, n)
            wl, wT, n = known[key]
            row.append(_Block(cols, wl, wT, n))
        plan.append(row)
    return plan


def _row_film(film: Film, cosine: float) -> Film:
    return dataclasses.replace(film, angle_deg=float(np.degrees(np.arccos(cosine))))


def _runs(dd: np.ndarray) -> int:
    """Columns per run: one exponential per run when the (sorted) thicknesses are uniform.

    Runs of about :data:`_RUN` columns (equal lengths); 1 (every column its own
    exponential) when the axis is not uniform to :data:`_UNIFORM_NM`.
    """
    m = dd.size
    if m < 3:
        return 1
    step = (dd[-1] - dd[0]) / (m - 1)
    if np.abs(dd - (dd[0] + step * np.arange(m))).max() > _UNIFORM_NM:
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


class _BlockCoefficients:
    """A row-block's coefficients (:class:`~ocio_thinfilm.physics.phasor.StackCoefficients`
    on its wavelengths), real where they can be, and whether the expanded form holds."""

    def __init__(self, k: phasor.StackCoefficients, sl: slice, lossless: bool) -> None:
        self.lossless = lossless
        pairs = [(k.S[i][sl], k.U[i][sl]) for i in (0, 1)]
        pairs += [(S[sl], U[sl]) for above in k.above for S, U in above]

        def gap(S: np.ndarray, U: np.ndarray) -> float:
            # |S z + U| >= |U| - |S| |z| >= |U| - |S| for |z| <= 1; ||U| - |S|| for |z| = 1
            diff = np.sqrt(phasor.abs2(U)) - np.sqrt(phasor.abs2(S))
            return float((np.abs(diff) if lossless else diff).min())

        # denominators at least _MARGIN^2 from 0: the expanded form loses nothing there
        self.direct = not min(gap(S, U) for S, U in pairs) >= _MARGIN
        self.power = [k.power[i][sl] for i in (0, 1)]
        self.P = [k.P[i][sl] for i in (0, 1)]
        self.Q = [k.Q[i][sl] for i in (0, 1)]
        self.S = [k.S[i][sl] for i in (0, 1)]
        self.U = [k.U[i][sl] for i in (0, 1)]
        self.above = [[(S[sl], U[sl]) for S, U in k.above[i]] for i in (0, 1)]
        # 0.5 |P z + Q|^2 = q0 + q2 |z|^2 + Re(X z), |S z + U|^2 = u0 + u2 |z|^2 + Re(Y z)
        self.X = [phasor.cmul(self.P[i], np.conj(self.Q[i])) for i in (0, 1)]
        self.Y = [2.0 * phasor.cmul(self.S[i], np.conj(self.U[i])) for i in (0, 1)]
        self.q = [(0.5 * phasor.abs2(self.Q[i]), 0.5 * phasor.abs2(self.P[i])) for i in (0, 1)]
        self.u = [(phasor.abs2(self.U[i]), phasor.abs2(self.S[i])) for i in (0, 1)]

    def run(self, anchor: np.ndarray) -> _Run:
        """Return the coefficients of a run whose first column's phasor is ``anchor``."""
        return _Run(self, anchor)


class _Run:
    """A run's coefficients, per polarisation: its columns' spectra are those of the
    powers ``w^j`` with the anchor's phasor folded into the coefficients
    (``z = anchor w^j``: ``P z = (P anchor) w^j``), :func:`_spectra`."""

    def __init__(self, b: _BlockCoefficients, anchor: np.ndarray) -> None:
        self.direct, self.lossless = b.direct, b.lossless
        self.power = b.power
        size2 = None if b.lossless else phasor.abs2(anchor)
        if size2 is not None:
            size = np.sqrt(size2)
            self.power = [p * size for p in b.power]
        self.complex = []  # (P A, Q, S A, U, [(S_j A, U_j)]): the direct form
        self.real = []  # the expanded form
        for i in (0, 1):
            if self.direct:
                above = [(phasor.cmul(Sj, anchor), Uj) for Sj, Uj in b.above[i]]
                P, S = phasor.cmul(b.P[i], anchor), phasor.cmul(b.S[i], anchor)
                self.complex.append((P, b.Q[i], S, b.U[i], above))
                continue
            X, Y = phasor.cmul(b.X[i], anchor), phasor.cmul(b.Y[i], anchor)
            (q0, q2), (u0, u2) = b.q[i], b.u[i]
            if size2 is None:  # |z| = 1
                q0, u0 = q0 + q2, u0 + u2
            else:
                q2, u2 = q2 * size2, u2 * size2
            self.real.append((q0, q2, X.real.copy(), -X.imag, u0, u2, Y.real.copy(), -Y.imag))


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
            num = np.multiply(Wr, xr[sl])
            num += np.multiply(Wi, xi[sl], out=tmp)
            num += q0[sl]
            den = np.multiply(Wr, yr[sl])
            den += np.multiply(Wi, yi[sl], out=tmp)
            den += u0[sl]
            if W2 is not None:
                num += np.multiply(W2, q2[sl], out=tmp)
                den += np.multiply(W2, u2[sl], out=tmp)
        np.reciprocal(den, out=den)
        num *= den
        if i == 0:
            R[...] = num
        else:
            R += num
        if T is not None:
            den *= co.power[i][sl]
            if i == 0:
                T[...] = den
            else:
                T += den
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


def _row(
    film: Film,
    cosine: float,
    d: np.ndarray,
    blocks: list[_Block],
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
    n_all = np.concatenate([blk.n for blk in blocks if blk.n is not None], axis=1)
    wl_all = np.concatenate([blk.wl for blk in blocks])
    k = phasor.stack_coefficients(n_all, film.thickness_nm, film.vary, wl_all, cosine, transmit)
    offset = 0
    for blk in blocks:
        size = blk.wl.size
        part = slice(offset, offset + size)
        offset += size
        phase = k.phase[part]
        lossless = not np.any(phase.imag)
        dd = d[blk.cols]
        run = _runs(dd)
        W = _powers(phase, float((dd[-1] - dd[0]) / max(dd.size - 1, 1)), run)
        Wr, Wi = np.ascontiguousarray(W.real), np.ascontiguousarray(W.imag)
        W2 = None if lossless else Wr * Wr + Wi * Wi
        R_buf = np.empty((run, min(_SLICE, size)))
        T_buf = np.empty_like(R_buf) if transmit else None
        coefficients = _BlockCoefficients(k, part, lossless)
        for start in range(0, dd.size, run):
            cols = blk.cols[start : start + run]
            co = coefficients.run(phasor.cexp_i(phase, float(dd[start])))
            acc_R = np.zeros((3, run))
            acc_T = np.zeros((3, run)) if transmit else None
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
                        _row_film(film, cosine), dd[start + redo], blk.wl[sl], transmit
                    )
                    R[redo] = R_old
                    if T is not None and T_old is not None:
                        T[redo] = T_old
                acc_R += _weigh(R, blk.wT[:, sl])
                if acc_T is not None and T is not None:
                    acc_T += _weigh(T, blk.wT[:, sl])
            out_R[cols] = acc_R.T[: cols.size]
            if out_T is not None and acc_T is not None:
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

    def run(row: int) -> int:
        _row(
            film,
            float(c[row]),
            d,
            plan[row],
            transmittance,
            out_R[row],
            None if out_T is None else out_T[row],
        )
        return row

    if workers == 1 or c.size == 1:
        for row in range(c.size):
            run(row)
            if progress is not None:
                progress(1)
    else:
        with concurrent.futures.ThreadPoolExecutor(min(workers, c.size)) as pool:
            for future in concurrent.futures.as_completed([pool.submit(run, r) for r in range(c.size)]):
                future.result()
                if progress is not None:
                    progress(1)
    return out_R, out_T
