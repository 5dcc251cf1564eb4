"""The material tables' engine: a group of rows of a film's table, evaluated.

:func:`evaluate_rows` is the numeric core of
:func:`ocio_thinfilm.lut.material_tables.film_angle_XYZ` for a group of rows (one cos
theta each) whose column blocks and wavelength grids are planned (:class:`Block`): the
stack's coefficients of its varying layer's phasor
(:func:`ocio_thinfilm.physics.phasor.stack_coefficients`) for all the group's wavelengths
in one call, the phasors of a uniform thickness axis as an exponential per run of
:data:`_RUN` columns times powers of one step's phasor, the spectra in real arithmetic
:data:`_SLICE` wavelengths at a time, weighted and summed by halves
(:func:`weigh`, :func:`ocio_thinfilm.reproducible.pairwise_sum`) while in cache. Every
operation is correctly rounded or libm's complex exponential: the same bits on every CPU,
and a row's arithmetic never depends on the other rows of its group.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from ocio_thinfilm import reproducible
from ocio_thinfilm.physics import phasor
from ocio_thinfilm.physics.films import Film

__all__ = ["Block", "Spectra", "row_film", "axis_step", "weigh", "evaluate_rows"]

#: Columns per run of one exponential (uniform thickness axes, :func:`_phasors`).
_RUN = 64
#: Wavelengths per slice of a run's spectra (a run x a slice stays in cache), and of
#: the integration's sums by halves (:func:`weigh`).
_SLICE = 256
#: Rows whose denominators ``|S z + U|`` may come within this of zero are evaluated in
#: complex form (the expanded ``|U|^2 + |S|^2 |z|^2 + 2 Re(S conj(U) z)`` would cancel).
_MARGIN = 1e-2
#: A thickness axis within this of uniform (nm) gets the powers of one phasor.
_UNIFORM_NM = 1e-9

#: A film's spectra at its angle: (film, thicknesses nm, wavelengths, transmit) -> (R, T),
#: the reference engine (:func:`ocio_thinfilm.lut.material_tables.film_spectra`).
Spectra = Callable[[Film, np.ndarray, np.ndarray, bool], "tuple[np.ndarray, np.ndarray | None]"]


@dataclasses.dataclass(frozen=True)
class Block:
    """A row's block of columns (the plan of :func:`evaluate_rows`).

    Their indices (ascending thickness), wavelengths, weights (transposed, (3, N)), the
    stack's indices there and the white (the weights' sums by halves).
    """

    cols: np.ndarray
    wl: np.ndarray
    wT: np.ndarray
    n: np.ndarray | None
    white: np.ndarray


def row_film(film: Film, cosine: float) -> Film:
    """Return ``film`` seen at the angle whose cosine is ``cosine``.

    Parameters
    ----------
    film : Film
        The film.
    cosine : float
        cos theta in the incident medium, in [0, 1].

    Returns
    -------
    Film
        The film with ``angle_deg = degrees(arccos(cosine))``.
    """
    return dataclasses.replace(film, angle_deg=float(np.degrees(np.arccos(cosine))))


def axis_step(d: np.ndarray) -> float:
    """Return the step of the (sorted) thickness axis.

    On a uniform axis the phasors are anchors times powers of one step's phasor
    (:func:`_runs`).

    Parameters
    ----------
    d : numpy.ndarray
        Thicknesses (nm), any order.

    Returns
    -------
    float
        ``(max - min) / (count - 1)``.
    """
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
    """The coefficients of a group of rows (all their blocks' wavelengths).

    Real where they can be: ``0.5 |P z + Q|^2 = q0 + q2 |z|^2 + Re(X z)``,
    ``|S z + U|^2 = u0 + u2 |z|^2 + Re(Y z)``; and the gaps ``|U| - |S|`` that bound the
    denominators from below.
    """

    def __init__(self, k: phasor.StackCoefficients) -> None:
        self.k = k
        self.X = [phasor.cmul(k.P[i], np.conj(k.Q[i])) for i in (0, 1)]
        self.Y = [2.0 * phasor.cmul(k.S[i], np.conj(k.U[i])) for i in (0, 1)]
        self.q = [(0.5 * phasor.abs2(k.Q[i]), 0.5 * phasor.abs2(k.P[i])) for i in (0, 1)]
        self.u = [(phasor.abs2(k.U[i]), phasor.abs2(k.S[i])) for i in (0, 1)]
        pairs = [*zip(k.S, k.U, strict=True), *(pair for above in k.above for pair in above)]
        self.gaps = [np.sqrt(phasor.abs2(U)) - np.sqrt(phasor.abs2(S)) for S, U in pairs]


def _prepare(
    g: _GroupCoefficients,
    part: slice,
    dd: np.ndarray,
    run: int,
    W: np.ndarray,
    A: np.ndarray,
    shared: tuple | None = None,
) -> tuple[list[_Run], np.ndarray, np.ndarray, np.ndarray | None]:
    """Return a row-block's runs and its powers (real, imaginary, ``|w|^2`` or None).

    ``part``: its wavelengths among the group's; ``W``: the powers ``w^j`` (>= ``run``
    rows) and ``A``: the runs' anchors (>= the block's runs), on those wavelengths. The
    expanded form holds where every denominator is at least :data:`_MARGIN` from 0:
    ``|S z + U| >= |U| - |S| |z| >= |U| - |S|`` for ``|z| <= 1``, ``||U| - |S||`` for
    ``|z| = 1`` (a lossless layer). ``shared``: the group's (lossless, direct, Wr, Wi,
    W2, X A, Y A, |A|^2) on those wavelengths, when the group computed them at once.
    """
    k = g.k
    count = -(-dd.size // run)
    if shared is None:
        lossless = not np.any(k.phase[part].imag)
        gap = min(float((np.abs(x[part]) if lossless else x[part]).min()) for x in g.gaps)
        direct = not gap >= _MARGIN
        Wr, Wi = np.ascontiguousarray(W[:run].real), np.ascontiguousarray(W[:run].imag)
        W2 = None if lossless else Wr * Wr + Wi * Wi
        XA = YA = None
        size2 = None if lossless else phasor.abs2(A[:count])
    else:
        lossless, direct, Wr, Wi, W2, XA, YA, size2 = shared
        Wr, Wi = Wr[:run], Wi[:run]
        W2 = None if lossless or W2 is None else W2[:run]
        size2 = None if lossless or size2 is None else size2[:count]
    A = A[:count]
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
        if XA is None or YA is None:
            X, Y = phasor.cmul(g.X[i][part], A), phasor.cmul(g.Y[i][part], A)
            xr, xi, yr, yi = X.real.copy(), -X.imag, Y.real.copy(), -Y.imag
        else:
            (xr, xi), (yr, yi) = XA[i], YA[i]
            xr, xi, yr, yi = xr[:count], xi[:count], yr[:count], yi[:count]
        (q0, q2), (u0, u2) = g.q[i], g.u[i]
        q0, q2, u0, u2 = q0[part], q2[part], u0[part], u2[part]
        if size2 is None:  # |z| = 1
            q0, u0 = q0 + q2, u0 + u2
            q2s = u2s = q2  # unused
        else:
            q2s, u2s = q2 * size2, u2 * size2
        forms.append((q0, q2s, xr, xi, u0, u2s, yr, yi))
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
    """A run's coefficients, per polarisation.

    Its columns' spectra are those of the powers ``w^j`` with the anchor's phasor folded
    into the coefficients (``z = anchor w^j``: ``P z = (P anchor) w^j``), :func:`_spectra`.
    """

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
        zero = None
        if co.direct:
            P, Q, S, U, above = co.complex[i]
            num = _abs2_of(P[sl], Q[sl], Wr, Wi)
            num *= 0.5
            den = _abs2_of(S[sl], U[sl], Wr, Wi)
            zero = den == 0
            if above:  # the recursion's rule inside the stack: the caller re-evaluates
                for Sj, Uj in above:
                    zero |= _abs2_of(Sj[sl], Uj[sl], Wr, Wi) == 0
                if zero.any():
                    bad = zero.any(axis=1) if bad is None else bad | zero.any(axis=1)
            if zero.any():
                # Rouard's rule where 1 + rho r z = 0 (grazing incidence on an absentee
                # layer): the interface's own reflection, r = rho = Q, and t = 0
                num = np.where(zero, 0.5 * phasor.abs2(Q[sl]), num)
                den[zero] = 1.0
            else:
                zero = None
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
            if zero is not None:
                den[zero] = 0.0
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


def evaluate_rows(
    film: Film,
    c: np.ndarray,
    d: np.ndarray,
    plan: list[list[Block]],
    transmit: bool,
    out_R: np.ndarray,
    out_T: np.ndarray | None,
    spectra: Spectra,
) -> None:
    """Evaluate a group of rows of a film's table into ``out_R`` (and ``out_T``).

    The stack's coefficients of all the group's rows and blocks are computed together
    (elementwise: each value is what it would be alone), the runs' anchors and the
    step's powers once per group, then each row, a run of columns and :data:`_SLICE`
    wavelengths at a time. Where Rouard's recursion divides by zero (grazing incidence on
    an absentee layer) its rule is kept: the interface's own reflection, no
    transmission (``spectra`` evaluates such samples of a stack with layers above the
    varying one). A lossless free-standing stack's transmittance is the white minus its
    reflectance (energy conservation, Byrnes 2016).

    Parameters
    ----------
    film : Film
        The film.
    c : numpy.ndarray
        The rows' cos theta.
    d : numpy.ndarray
        The columns' thicknesses (nm).
    plan : list of list of Block
        Each row's blocks (the same columns in every row).
    transmit : bool
        Also the transmittance.
    out_R, out_T : numpy.ndarray
        (rows, W, 3) XYZ, written (``out_T`` None without ``transmit``).
    spectra : Spectra
        The reference engine: the paper model's rows, and the samples above.
    """
    prepared: list[list] = [[] for _ in plan]
    if film.model != "paper":
        g = _group_coefficients(film, c, plan, transmit)
        # the blocks' columns are the same in every row: their runs, anchors and powers
        # for all the group's wavelengths at once
        blocks = plan[0]
        dds = [d[blk.cols] for blk in blocks]
        step = axis_step(d)
        run_of = [_runs(dd, step) for dd in dds]
        offsets = np.cumsum([0] + [blk.wl.size for row in plan for blk in row])
        if min(run_of) > 1:  # a uniform axis: one set of powers
            _prepare_uniform(g, len(plan), dds, run_of, step, offsets, prepared)
        else:
            for s_, (j, b) in enumerate(
                (j, b) for j in range(len(plan)) for b in range(len(blocks))
            ):
                part = slice(offsets[s_], offsets[s_ + 1])
                W = _powers(g.k.phase[part], step, run_of[b])
                A = phasor.cexp_i(g.k.phase[part], dds[b][:: run_of[b], None])
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
            spectra,
        )


def _group_coefficients(
    film: Film, c: np.ndarray, plan: list[list[Block]], transmit: bool
) -> _GroupCoefficients:
    """Return the stack's coefficients of all a group's rows and blocks (one call)."""
    n_all = np.concatenate([blk.n for row in plan for blk in row if blk.n is not None], axis=1)
    wl_all = np.concatenate([blk.wl for row in plan for blk in row])
    c_all = np.concatenate(
        [np.full(blk.wl.size, c[j]) for j, row in enumerate(plan) for blk in row]
    )
    return _GroupCoefficients(
        phasor.stack_coefficients(n_all, film.thickness_nm, film.vary, wl_all, c_all, transmit)
    )


def _prepare_uniform(
    g: _GroupCoefficients,
    rows: int,
    dds: list[np.ndarray],
    run_of: list[int],
    step: float,
    offsets: np.ndarray,
    prepared: list[list],
) -> None:
    """Append each row's prepared runs to ``prepared`` on a uniform thickness axis.

    One set of the step's powers, the runs' anchors and what every segment needs are
    computed for the whole group at once.
    """
    phase = g.k.phase
    blocks = len(dds)
    W_all = _powers(phase, step, max(run_of))
    starts = [dd[::run] for dd, run in zip(dds, run_of, strict=True)]
    count = max(a.size for a in starts)
    L = np.empty((count, phase.size))
    for s_, b in enumerate(b for _ in range(rows) for b in range(blocks)):
        anchor_d = starts[b]
        L[:, offsets[s_] : offsets[s_ + 1]] = np.pad(
            anchor_d, (0, count - anchor_d.size), mode="edge"
        )[:, None]
    A_all = phasor.cexp_i(phase, L)
    # what every segment needs, for the whole group at once
    Wr_all, Wi_all = np.ascontiguousarray(W_all.real), np.ascontiguousarray(W_all.imag)
    lossy = phase.imag != 0
    any_lossy = bool(lossy.any())
    W2_all = Wr_all * Wr_all + Wi_all * Wi_all if any_lossy else None
    size2_all = phasor.abs2(A_all) if any_lossy else None
    # real, contiguous: (Re X A, -Im X A) and (Re Y A, -Im Y A) per polarisation
    XA = [(x.real.copy(), -x.imag) for x in (phasor.cmul(g.X[i], A_all) for i in (0, 1))]
    YA = [(y.real.copy(), -y.imag) for y in (phasor.cmul(g.Y[i], A_all) for i in (0, 1))]
    starts_at = offsets[:-1]
    seg_lossy = np.maximum.reduceat(lossy, starts_at)
    gap = np.minimum.reduceat(np.minimum.reduce(g.gaps), starts_at)
    gap_abs = np.minimum.reduceat(np.minimum.reduce(np.abs(g.gaps)), starts_at)
    for s_, (j, b) in enumerate((j, b) for j in range(rows) for b in range(blocks)):
        part = slice(offsets[s_], offsets[s_ + 1])
        lossless = not seg_lossy[s_]
        direct = not (gap_abs[s_] if lossless else gap[s_]) >= _MARGIN
        shared = (
            lossless,
            direct,
            Wr_all[:, part],
            Wi_all[:, part],
            None if W2_all is None else W2_all[:, part],
            [(xr[:, part], xi[:, part]) for xr, xi in XA],
            [(yr[:, part], yi[:, part]) for yr, yi in YA],
            None if size2_all is None else size2_all[:, part],
        )
        prepared[j].append(
            _prepare(g, part, dds[b], run_of[b], W_all[:, part], A_all[:, part], shared)
        )


def _row(
    film: Film,
    cosine: float,
    d: np.ndarray,
    blocks: list[Block],
    prepared: list,
    transmit: bool,
    out_R: np.ndarray,
    out_T: np.ndarray | None,
    spectra: Spectra,
) -> None:
    """Evaluate one row (one cos theta) into ``out_R`` (and ``out_T``): (W, 3) views.

    Its arithmetic depends on the row alone, never on which worker runs it or with
    which other rows: the tables are the same bits on any number of workers. The
    stack's coefficients are computed once for the row (all its blocks' wavelengths
    together: elementwise, so each value is what it would be alone); a run of columns
    is evaluated :data:`_SLICE` wavelengths at a time, each slice's spectra weighted and
    summed (:func:`weigh`) while they are in cache.
    """
    if film.model == "paper":
        at_angle = row_film(film, cosine)
        for blk in blocks:
            dd = d[blk.cols]
            for start in range(0, dd.size, _RUN):
                part = slice(start, start + _RUN)
                R, T = spectra(at_angle, dd[part], blk.wl, transmit)
                out_R[blk.cols[part]] = weigh(R, blk.wT).T
                if out_T is not None and T is not None:
                    out_T[blk.cols[part]] = weigh(T, blk.wT).T
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
                    R_old, T_old = spectra(
                        row_film(film, cosine), dd[start + redo], blk.wl[sl], T is not None
                    )
                    R[redo] = R_old
                    if T is not None and T_old is not None:
                        T[redo] = T_old
                acc_R += weigh(R, blk.wT[:, sl])
                if acc_T is not None and T is not None:
                    acc_T += weigh(T, blk.wT[:, sl])
            out_R[cols] = acc_R.T[: cols.size]
            if out_T is not None and white is not None:
                out_T[cols] = white - out_R[cols]
            elif out_T is not None and acc_T is not None:
                out_T[cols] = acc_T.T[: cols.size]


def weigh(S: np.ndarray, wT: np.ndarray) -> np.ndarray:
    """Return ``(S @ wT.T).T``: spectra integrated with weights, by halves.

    The spectra times each weight, summed over the wavelengths by
    :func:`ocio_thinfilm.reproducible.pairwise_sum` (a fixed tree of elementwise
    additions: the same bits on every CPU) :data:`_SLICE` wavelengths at a time, the
    slices' sums added in order (the order :func:`evaluate_rows` sums in).

    Parameters
    ----------
    S : numpy.ndarray
        Spectra, (columns, N).
    wT : numpy.ndarray
        Weights, (3, N).

    Returns
    -------
    numpy.ndarray
        (3, columns).
    """
    out = np.zeros((wT.shape[0], S.shape[0]))
    for lo in range(0, S.shape[1], _SLICE):
        sl = slice(lo, lo + _SLICE)
        out += reproducible.pairwise_sum(S[None, :, sl] * wT[:, None, sl], overwrite=True)
    return out
