"""Films a user describes: a TOML film file -> :class:`Film` objects -> reflectance spectra.

The film file and its :class:`Film` objects are :mod:`ocio_thinfilm.physics.film_file`
(its names are re-exported here); this module gives a film's spectra.

Models (:func:`film_reflectance`):

- ``"exact"``: the unpolarised reflectance ``(R_s + R_p) / 2`` of the whole stack with
  Fresnel amplitudes and complex, dispersive indices, by transfer matrices
  (:func:`ocio_thinfilm.physics.exact.stack_reflectance`), sampled finely enough in
  wavelength for the stack's longest optical path
  (:func:`~ocio_thinfilm.physics.exact.adequate_step`) so thick films do not alias. A
  physical reflectance: a free soap film reflects at most about 16 %.
- ``"paper"``: Smits & Meyer's Eq. 7 / 8 (equal amplitudes, normalised to a peak of 1)
  with ``t' = n t cos(theta_t)``, n the film's real index at 550 nm (the paper's model
  has one index); Eq. 7 (phase change) when the two interfaces' Fresnel amplitudes have
  opposite signs (a soap film in air, oil on water), Eq. 8 otherwise (MgF2 on glass).
  One layer only.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import as_array
from ocio_thinfilm.physics import exact
from ocio_thinfilm.physics.film_file import (
    INCIDENT_MAX_K,
    MAX_RANGE_UM,
    MODELS,
    NAME_FORMAT,
    PAPER_WAVELENGTH,
    Film,
    check_names,
    parse_films,
    read_films,
)
from ocio_thinfilm.physics.materials import VISIBLE_NM
from ocio_thinfilm.physics.sampling import check_wavelengths, wavelength_grid
from ocio_thinfilm.physics.spectra import two_beam_reflectance

__all__ = [
    "MODELS",
    "MAX_RANGE_UM",
    "NAME_FORMAT",
    "INCIDENT_MAX_K",
    "PAPER_WAVELENGTH",
    "Film",
    "parse_films",
    "read_films",
    "check_names",
    "film_wavelengths",
    "film_wavelength_counts",
    "fringe_sharpness",
    "paper_parameters",
    "film_reflectance",
]


# --------------------------------------------------------------------------- #
# Spectra
# --------------------------------------------------------------------------- #
def _optical_path_nm(film: Film, max_thickness_nm: npt.ArrayLike) -> np.ndarray:
    """Return the stack's longest round-trip optical path (nm), for the wavelength step.

    For each of ``max_thickness_nm`` (the varying layer's), in the same order of
    additions for each: the values do not depend on how many are asked for.
    """
    wl = np.array([VISIBLE_NM[0]])
    sin0 = film.stack[0].index(wl).real * np.sin(np.deg2rad(film.angle_deg))
    total: np.ndarray = np.zeros(np.shape(max_thickness_nm))
    for j, layer in enumerate(film.layers):
        n = layer.index(wl)
        ncos = np.sqrt(n * n - sin0 * sin0 + 0j)
        d = np.asarray(max_thickness_nm, float) if j == film.vary else film.thickness_nm[j]
        total = total + 2.0 * float(np.abs(ncos.real).max()) * d
    return total


def film_wavelength_counts(
    film: Film,
    max_thickness_nm: npt.ArrayLike,
    max_sharpness: float = 1.0,
    *,
    sharpness: float | None = None,
) -> list[int]:
    """Return how many wavelengths :func:`film_wavelengths` takes for several thicknesses.

    The exact model's counts for each of ``max_thickness_nm`` at once (the material tables
    plan several blocks of thickness at each angle); the grid is
    ``numpy.linspace(380, 780, count)``.

    Parameters
    ----------
    film : Film
        The film (exact model).
    max_thickness_nm : array_like
        1-D, the thickest the varying layer gets, nm.
    max_sharpness : float, optional
        As :func:`film_wavelengths`.
    sharpness : float, optional
        As :func:`film_wavelengths`.

    Returns
    -------
    list of int
        One count per thickness.
    """
    sharp = float(fringe_sharpness(film) if sharpness is None else sharpness)
    paths = np.atleast_1d(_optical_path_nm(film, np.atleast_1d(max_thickness_nm)))
    counts = []
    for path in paths.tolist():
        step = exact.adequate_step(path, VISIBLE_NM[0], sharpness=min(sharp, max_sharpness))
        counts.append(int(math.ceil((VISIBLE_NM[1] - VISIBLE_NM[0]) / step)) + 1)
    return counts


def fringe_sharpness(film: Film, angles_deg: npt.ArrayLike | None = None) -> np.ndarray:
    """Return ``max |r_a r_b|`` of the varying layer's two interfaces.

    The maximum is over the visible and both polarisations: how sharp the layer's Airy
    fringes get (:func:`exact.adequate_step`).

    Parameters
    ----------
    film : Film
        The film.
    angles_deg : array_like, optional
        Angles of incidence (degrees), default the film's ``angle_deg``.

    Returns
    -------
    numpy.ndarray
        In [0, 1], the shape of ``angles_deg`` (0-d without it).
    """
    wl = np.linspace(*VISIBLE_NM, 41)
    n = np.stack([m.index(wl) for m in film.stack])
    angles = np.asarray(film.angle_deg if angles_deg is None else angles_deg, dtype=np.float64)
    amplitudes = exact.interface_amplitudes(n, angles[..., None])
    above, below = amplitudes[film.vary], amplitudes[film.vary + 1]
    return np.maximum(*(np.abs(above[p] * below[p]).max(axis=-1) for p in (0, 1)))


def film_wavelengths(
    film: Film,
    max_thickness_nm: float | None = None,
    max_sharpness: float = 1.0,
    *,
    sharpness: float | None = None,
) -> np.ndarray:
    """Return the wavelength grid (nm) a film's spectra are evaluated on.

    The paper model: 360-780 nm in 5 nm steps, band-limited like the built-in tables
    (380-780 nm when a material's data start above 360 nm). The exact model: 380-780
    nm, with the step of :func:`~ocio_thinfilm.physics.exact.adequate_step` for the
    stack's longest optical path (the varying layer at ``max_thickness_nm``, default
    the top of its range) and the sharpness of the varying layer's fringes.

    Parameters
    ----------
    film : Film
        The film.
    max_thickness_nm : float, optional
        The thickest the varying layer gets.
    max_sharpness : float, optional
        A cap on the fringes' sharpness the step resolves (the material tables' choice,
        :mod:`ocio_thinfilm.lut.material_tables`).
    sharpness : float, optional
        The film's :func:`fringe_sharpness`, if the caller has it (it depends on the
        angle only; the material tables ask for several thicknesses at each angle).

    Returns
    -------
    numpy.ndarray
        Wavelengths in nm.
    """
    if film.model == "paper":
        start = 360.0 if all(m.covers(360.0, 780.0) for m in film.stack) else 380.0
        return wavelength_grid(start, 780.0, 5.0)
    top = film.range_um[1] * 1000.0 if max_thickness_nm is None else float(max_thickness_nm)
    (count,) = film_wavelength_counts(film, [top], max_sharpness, sharpness=sharpness)
    return check_wavelengths(np.linspace(VISIBLE_NM[0], VISIBLE_NM[1], count))


def paper_parameters(film: Film) -> tuple[float, float, bool]:
    r"""Return the paper model's film index n, cos(theta_t) and whether Eq. 7 applies.

    All three are at :data:`PAPER_WAVELENGTH` (see the module docstring); Eq. 7 is the
    one with the phase change.

    Parameters
    ----------
    film : Film
        A one-layer film.

    Returns
    -------
    n : float
        The film's real index at 550 nm.
    cos_t : float
        cos(theta_t) in the film (Snell's law from the incident medium).
    phase_change : bool
        Eq. 7 (True) or Eq. 8.

    Examples
    --------
    >>> soap = parse_films('[films.S]\nstack = ["vacuum", "soap film", "vacuum"]')["S"]
    >>> n, cos_t, phase_change = paper_parameters(soap)
    >>> round(n, 3), cos_t, phase_change
    (1.335, 1.0, True)
    """
    wl = np.array([PAPER_WAVELENGTH])
    n0, n1, n2 = (m.index(wl)[0] for m in film.stack)
    sin_t = n0.real * np.sin(np.deg2rad(film.angle_deg)) / n1.real
    cos_t = float(np.sqrt(max(0.0, 1.0 - sin_t * sin_t)))
    # normal-incidence Fresnel amplitudes (n_i - n_j) / (n_i + n_j): a sign change
    # between the two interfaces is the half-wave phase change of Eq. 7
    r01 = ((n0 - n1) / (n0 + n1)).real
    r12 = ((n1 - n2) / (n1 + n2)).real
    return float(n1.real), cos_t, bool(r01 * r12 < 0)


def film_reflectance(
    film: Film, thickness_nm: npt.ArrayLike, wavelengths: npt.ArrayLike | None = None
) -> np.ndarray:
    r"""Return a film's reflectance spectra against the physical thickness of its varying layer.

    Parameters
    ----------
    film : Film
        The film (its model, stack, angle).
    thickness_nm : array_like
        Thicknesses of the varying layer in nm, >= 0.
    wavelengths : array_like, optional
        Wavelengths in nm (default :func:`film_wavelengths` for the largest thickness
        asked for); within every material's data.

    Returns
    -------
    numpy.ndarray
        R, shape ``thickness.shape + (len(wavelengths),)``: the physical unpolarised
        reflectance (``"exact"``) or the paper's normalised Eq. 7 / 8 (``"paper"``,
        band-limited).

    Examples
    --------
    A free soap film at a quarter wave reflects 4 r^2 / (1 + r^2)^2 = 7.8 % (r = -0.1427) at
    n = 1.333 (Born & Wolf 1.6 (59)) in the exact model and 1 in the paper's:

    >>> text = '[films.S]\nstack = ["air", "Soap", "air"]\n[materials.Soap]\nn = 1.333'
    >>> soap = parse_films(text)["S"]
    >>> float(film_reflectance(soap, 550 / (4 * 1.333), [550.0])[0]).__round__(3)
    0.078
    """
    d = as_array("thickness_nm", thickness_nm, minimum=0.0, unit=" nm")
    if wavelengths is None:
        wl = film_wavelengths(film, float(d.max()) if d.size else None)
    else:
        wl = check_wavelengths(wavelengths)
    if film.model == "paper":
        n, cos_t, phase_change = paper_parameters(film)
        return two_beam_reflectance(d * n * cos_t, wl, phase_change=phase_change, band_limited=True)
    indices = np.stack([m.index(wl) for m in film.stack])
    return exact.stack_reflectance(indices, film.thickness_nm, film.vary, d, wl, film.angle_deg)
