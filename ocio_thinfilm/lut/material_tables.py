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
:func:`default_resolution` the measured default size (docs/materials.md).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import reproducible
from ocio_thinfilm.checks import ParameterError, as_array
from ocio_thinfilm.lut import film_tables
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
#: Spectral samples per block of spectra (thicknesses x wavelengths).
_BLOCK_SAMPLES = 1 << 20


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


def _grid(film: Film, top_nm: float) -> np.ndarray:
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


def film_angle_XYZ(
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
            wl = _grid(row_film, float(d[cols].max()))
            w = film_tables.film_weights(film, wl)
            step = max(1, _BLOCK_SAMPLES // wl.size)
            for start in range(0, cols.size, step):
                part = cols[start : start + step]
                R, T = film_spectra(row_film, d[part], wl, transmittance)
                out_R[row, part] = reproducible.matmul(R, w)
                if out_T is not None and T is not None:
                    out_T[row, part] = reproducible.matmul(T, w)
    return out_R, out_T
