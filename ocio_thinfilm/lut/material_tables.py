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

:func:`axis_nodes` gives the axes of a table (node-centred sampling: the first and last
samples lie exactly on the ends of the range, so normal incidence, grazing incidence and
both ends of the thickness range are table values, not extrapolations),
:func:`texture_coordinate` the texture coordinate a host reads a value at, and
:func:`default_resolution` the default size (chosen in docs/materials.md).
"""

from __future__ import annotations

import concurrent.futures
import math
import os
from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import ParameterError, as_array, as_count
from ocio_thinfilm.lut import film_tables, material_engine
from ocio_thinfilm.physics import exact
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
    "axis_nodes",
    "texture_coordinate",
    "default_resolution",
    "available_workers",
    "sample_count",
    "film_angle_XYZ",
]

#: Texels of the thickness axis per shortest interference fringe (a thickness step of
#: ``380 nm / (2 n)``), chosen in docs/materials.md.
TEXELS_PER_FRINGE = 40
#: Bounds of the default width.
MIN_WIDTH = 64
MAX_WIDTH = 1536
#: Rows of the cos theta axis, chosen in docs/materials.md.
DEFAULT_HEIGHT = 192
#: The sharpest fringes (``|r_a r_b|`` of the varying layer) the wavelength step
#: resolves: near grazing incidence ``|r_a r_b| -> 1`` and the full criterion asks for
#: up to 20001 wavelengths per row; capped at 0.5 the colours move by Delta E 2000 <=
#: 0.004 (soap films of 1.5 and 10 um, anodised titanium, cos theta 0.01-0.3) with 6 to 16
#: times fewer wavelengths (docs/materials.md).
MAX_SHARPNESS = 0.5
#: Blocks of columns (by thickness) with a wavelength grid each.
_COLUMN_BLOCKS = 8
#: Rows (and their samples: wavelengths x blocks) per unit of work of a thread.
_GROUP_ROWS = 16
_GROUP_SAMPLES = 1 << 14


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


def axis_nodes(lo: float, hi: float, count: int) -> np.ndarray:
    """Return the ``count`` samples ``lo + i (hi - lo) / (count - 1)`` of a table axis.

    Node-centred sampling: the first sample is ``lo`` and the last ``hi`` exactly.

    Parameters
    ----------
    lo, hi : float
        The axis' range.
    count : int
        Samples, >= 2.

    Returns
    -------
    numpy.ndarray
        ``count`` values, ascending.

    Examples
    --------
    >>> axis_nodes(0.0, 1.0, 5).tolist()
    [0.0, 0.25, 0.5, 0.75, 1.0]
    """
    if count < 2:
        raise ParameterError("count", f" must be >= 2, got {count}")
    return np.linspace(lo, hi, count)


def texture_coordinate(fraction: npt.ArrayLike, count: int) -> np.ndarray:
    """Return the texture coordinate of a table axis' ``fraction`` in [0, 1].

    A texture of ``count`` texels has its texel centres at ``(i + 0.5) / count``; the
    table's sample ``i`` (:func:`axis_nodes`) sits at fraction ``i / (count - 1)``, so
    a host reads fraction ``f`` (clamped to [0, 1]) at ``(f (count - 1) + 0.5) / count``
    with linear filtering: exact at every node, linear in between, the ends never
    extrapolated.

    Parameters
    ----------
    fraction : array_like
        Position along the axis, 0 at the first sample, 1 at the last.
    count : int
        Texels along the axis.

    Returns
    -------
    numpy.ndarray
        Texture coordinates in ``[0.5 / count, 1 - 0.5 / count]``.

    Examples
    --------
    >>> texture_coordinate([0.0, 0.5, 1.0], 4).tolist()
    [0.125, 0.5, 0.875]
    """
    f = np.clip(np.asarray(fraction, dtype=float), 0.0, 1.0)
    return (f * (count - 1) + 0.5) / count


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
    if film.model == "paper":
        return films_module.film_wavelengths(film, top_nm, MAX_SHARPNESS)
    return _grids(film, [top_nm], sharpness)[0]


def _grids(film: Film, tops_nm: npt.ArrayLike, sharpness: float | None) -> list[np.ndarray]:
    """:func:`_grid` of the exact model for several blocks' tops at once."""
    out = []
    for size in films_module.film_wavelength_counts(
        film, tops_nm, MAX_SHARPNESS, sharpness=sharpness
    ):
        m = max(0, math.ceil(2.0 * math.log2(max(size - 1, 1) / 50.0) - 1e-9))
        out.append(np.linspace(*VISIBLE_NM, 1 + round(50 * 2 ** (m / 2))))
    return out


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


def _plan(film: Film, d: np.ndarray, c: np.ndarray) -> list[list[material_engine.Block]]:
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
        row_film = material_engine.row_film(film, float(cosine))
        sharp = None if sharpness is None else float(sharpness[j])
        row = []
        tops = [float(d[cols].max()) for cols in blocks]
        if film.model == "paper":
            grids = [_grid(row_film, top) for top in tops]
        else:
            grids = _grids(row_film, tops, sharp)
        for cols, wl in zip(blocks, grids, strict=True):
            key = wl.tobytes()
            if key not in known:
                n = None if film.model == "paper" else np.stack([m.index(wl) for m in film.stack])
                wT = np.ascontiguousarray(film_tables.film_weights(film, wl).T)
                known[key] = (wl, wT, n, material_engine.weigh(np.ones((1, wl.size)), wT)[:, 0])
            wl, wT, n, white = known[key]
            row.append(material_engine.Block(cols, wl, wT, n, white))
        plan.append(row)
    return plan


def sample_count(film: Film, width: int, height: int, *, rows: int = 9) -> float:
    r"""Estimate the (thickness, wavelength) samples :func:`film_angle_XYZ` evaluates.

    A table of ``width`` x ``height`` texels (node-centred axes) evaluates each column
    block on its own wavelength grid per row; the grids of ``rows`` rows spread over
    cos theta stand for all (their mean per row, times ``height``). For the cost checks
    of :func:`ocio_thinfilm.export.material_cost.check_size`: milliseconds for any size.

    Parameters
    ----------
    film : Film
        The film.
    width, height : int
        The table's size.
    rows : int, optional
        Rows sampled.

    Returns
    -------
    float
        Estimated samples (texels x wavelengths).

    Examples
    --------
    >>> from ocio_thinfilm.physics.films import parse_films
    >>> film = parse_films('[films.S]\nstack = ["air", "MgF2", "BK7"]\nrange_um = [0, 0.5]')["S"]
    >>> samples = sample_count(film, 160, 192)  # 380-780 nm: at least 51 a texel
    >>> bool(160 * 192 * 51 <= samples <= 160 * 192 * 20001)
    True
    """
    lo, hi = film.range_um
    d = axis_nodes(lo, hi, width) * 1000.0
    c = axis_nodes(0.0, 1.0, max(2, min(rows, height)))
    order = np.argsort(d, kind="stable")
    blocks = [b for b in np.array_split(order, max(1, min(_COLUMN_BLOCKS, d.size // 64))) if b.size]
    tops = [float(d[b].max()) for b in blocks]
    total = 0.0
    for cosine in c:
        row_film = material_engine.row_film(film, float(cosine))
        sharp = None if film.model == "paper" else float(films_module.fringe_sharpness(row_film))
        grids = (
            [_grid(row_film, top) for top in tops]
            if film.model == "paper"
            else _grids(row_film, tops, sharp)
        )
        total += sum(b.size * wl.size for b, wl in zip(blocks, grids, strict=True))
    return total / c.size * height


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
        material_engine.evaluate_rows(
            film,
            c[rows],
            d,
            plan[rows],
            transmittance,
            out_R[rows],
            None if out_T is None else out_T[rows],
            film_spectra,
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
