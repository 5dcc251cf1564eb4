"""Tables of the films a user describes (:mod:`ocio_thinfilm.physics.films`).

:func:`user_film_table` turns a :class:`~ocio_thinfilm.physics.films.Film` into a
:class:`~ocio_thinfilm.lut.tables.Table1D`: pixel value = physical thickness of the
film's varying layer in micrometres (all channels equal), nodes uniform over the film's
``range_um`` (the LUT's clamp holds the end colours outside it), values CIE XYZ (D65,
CIE 1931 2 degree observer, perfect reflector Y = 1) of the film's reflectance
(:func:`ocio_thinfilm.physics.films.film_reflectance`) through the colorimetry's
trapezoid weights under the film's illuminant, adapted to D65 (:func:`film_weights`).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import cache, reproducible
from ocio_thinfilm.checks import as_count
from ocio_thinfilm.colour import adaptation, colorimetry
from ocio_thinfilm.lut.tables import Table1D
from ocio_thinfilm.physics import films as films_module
from ocio_thinfilm.physics import light
from ocio_thinfilm.physics.films import Film

__all__ = [
    "MIN_SIZE",
    "MAX_SIZE",
    "NODES_PER_FRINGE",
    "default_size",
    "viewing_weights",
    "film_weights",
    "light_words",
    "film_XYZ",
    "user_film_table",
]

#: Bounds of the default table size, and nodes per shortest interference fringe.
MIN_SIZE = 1024
MAX_SIZE = 1 << 16
NODES_PER_FRINGE = 64
#: Spectral samples per block of spectra (thicknesses x wavelengths complex values:
#: 32 MB a temporary).
_BLOCK_SAMPLES = 1 << 21


def default_size(film: Film) -> int:
    r"""Return the number of entries of a film's table.

    That is :data:`NODES_PER_FRINGE` nodes per shortest fringe of the varying layer (a
    thickness step of ``380 nm / (2 n)`` at 380 nm), a power of two in
    [:data:`MIN_SIZE`, :data:`MAX_SIZE`].

    Parameters
    ----------
    film : Film
        The film.

    Returns
    -------
    int
        The table size.

    Examples
    --------
    >>> from ocio_thinfilm.physics.films import parse_films
    >>> default_size(parse_films('[films.S]\nstack = ["air", "water", "air"]')["S"])
    1024
    """
    lo, hi = film.range_um
    n = float(np.abs(film.varying.index(np.array([380.0]))).max())
    fringes = (hi - lo) * 1000.0 / (380.0 / (2.0 * n))
    size = 1 << max(0, math.ceil(math.log2(max(fringes * NODES_PER_FRINGE, 2.0))))
    return int(min(MAX_SIZE, max(MIN_SIZE, size)))


def viewing_weights(
    wavelengths: npt.ArrayLike,
    illuminant: str = light.SCENE_ILLUMINANT,
    adaptation_name: str = light.DEFAULT_ADAPTATION,
) -> np.ndarray:
    """Return weights ``W`` so that ``XYZ = R @ W`` is a reflectance seen under ``illuminant``.

    The tristimulus weights under the illuminant
    (:func:`ocio_thinfilm.colour.colorimetry.spectral_weights`: the perfect reflector
    under it has Y = 1), followed by the von Kries adaptation
    (:func:`ocio_thinfilm.colour.adaptation.von_kries_matrix`, in the cone space
    ``adaptation_name``) from the perfect reflector under the illuminant on the same
    wavelengths to the scene white D65 (colour-science's chromaticity,
    Y = 1, the white of the colour spaces' matrices). Under D65 these are
    :func:`~ocio_thinfilm.colour.colorimetry.spectral_weights` themselves.

    Parameters
    ----------
    wavelengths : array_like
        Sample wavelengths in nm (as ``spectral_weights``).
    illuminant : str, optional
        A name :func:`~ocio_thinfilm.physics.light.check_illuminant` takes (default D65).
    adaptation_name : str, optional
        A name :func:`~ocio_thinfilm.physics.light.check_adaptation` takes (default CAT02).

    Returns
    -------
    numpy.ndarray
        (len(wavelengths), 3); the perfect reflector's XYZ, the column sums, is the
        D65 white.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``illuminant`` or ``adaptation_name``) for names colour-science does not know.

    Examples
    --------
    A reflectance of 1 is the D65 white under any illuminant:

    >>> wl = np.arange(380.0, 781.0, 5.0)
    >>> viewing_weights(wl, "F11").sum(axis=0).round(3).tolist()
    [0.95, 1.0, 1.089]
    """
    illuminant = light.check_illuminant(illuminant)
    adaptation_name = light.check_adaptation(adaptation_name, "adaptation_name")
    if illuminant == light.SCENE_ILLUMINANT:
        return colorimetry.spectral_weights(wavelengths)
    import colour

    W = colorimetry.spectral_weights(wavelengths, illuminant=illuminant)
    white = reproducible.matmul(np.ones(W.shape[0]), W)
    xy = np.asarray(
        colour.CCS_ILLUMINANTS[colorimetry.DEFAULT_OBSERVER][light.SCENE_ILLUMINANT], np.float64
    )
    target = np.array([xy[0] / xy[1], 1.0, (1.0 - xy[0] - xy[1]) / xy[1]])
    cat = colour.CHROMATIC_ADAPTATION_TRANSFORMS[adaptation_name]
    A = adaptation.von_kries_matrix(white, target, cat)
    return reproducible.matmul(W, A.T)


def film_weights(film: Film, wavelengths: np.ndarray) -> np.ndarray:
    """Return the weights ``W`` so that ``XYZ = R @ W`` is a film's colour under its light.

    :func:`viewing_weights` with the film's
    ``illuminant`` and ``adaptation``: the trapezoid weights under the illuminant with
    the perfect reflector under it as white, adapted to D65 (under D65 the plain
    weights).

    Parameters
    ----------
    film : Film
        The film.
    wavelengths : numpy.ndarray
        Wavelengths in nm.

    Returns
    -------
    numpy.ndarray
        (len(wavelengths), 3).
    """
    return viewing_weights(wavelengths, film.illuminant, film.adaptation)


def light_words(film: Film) -> str:
    """Describe the light a film is seen under, for its descriptions.

    ``""`` under D65, else e.g. ``" under FL2, CAT02-adapted to D65,"``.

    Parameters
    ----------
    film : Film
        The film.

    Returns
    -------
    str
        The words.
    """
    if film.illuminant == light.SCENE_ILLUMINANT:
        return ""
    return f" under {film.illuminant}, {film.adaptation}-adapted to D65,"


def film_XYZ(film: Film, thickness_um: np.ndarray) -> np.ndarray:
    """Return CIE XYZ of ``film`` at physical thicknesses of its varying layer (um).

    The colours are CIE XYZ (D65, perfect reflector Y = 1) of the film's reflectance
    spectra on :func:`films.film_wavelengths
    <ocio_thinfilm.physics.films.film_wavelengths>` through the trapezoid weights
    under the film's illuminant (:func:`film_weights`).

    Parameters
    ----------
    film : Film
        The film.
    thickness_um : numpy.ndarray
        Thicknesses in um, >= 0.

    Returns
    -------
    numpy.ndarray
        Shape ``thickness_um.shape + (3,)``.
    """
    t_nm = np.asarray(thickness_um, dtype=np.float64) * 1000.0
    flat = t_nm.reshape(-1)
    top = max(float(flat.max()) if flat.size else 0.0, film.range_um[1] * 1000.0)
    wl = films_module.film_wavelengths(film, top)
    w = film_weights(film, wl)
    out = np.empty((flat.size, 3))
    rows = max(1, _BLOCK_SAMPLES // wl.size)
    for start in range(0, flat.size, rows):
        block = flat[start : start + rows]
        out[start : start + rows] = reproducible.matmul(
            films_module.film_reflectance(film, block, wl), w
        )
    return out.reshape(t_nm.shape + (3,))


@cache.memoize(maxsize=32)
def _user_film_table(film: Film, size: int) -> Table1D:
    lo, hi = film.range_um
    nodes = np.linspace(lo, hi, size)
    values = film_XYZ(film, nodes)
    scale = ""
    if film.normalise:
        brightest = float(values[:, 1].max())
        if brightest > 0:
            values /= brightest
            scale = f" Normalised: scaled by 1/{brightest:.6g} (brightest entry Y = 1)."
    values.setflags(write=False)
    nodes.setflags(write=False)
    model = (
        "exact unpolarised reflectance (transfer matrices, Fresnel amplitudes, dispersive "
        "complex indices)"
        if film.model == "exact"
        else "Smits & Meyer 1990 Eq. 7/8 with t' = n t cos(theta_t), band-limited"
    )
    return Table1D(
        kind="film",
        values=values,
        encoding="linear",
        domain_min=lo,
        domain_max=hi,
        nodes=nodes,
        name=film.name,
        pixel=f"physical thickness of the {film.varying.name} layer in micrometres, "
        "all channels equal",
        description=(
            f"Thin film {film.key}: {film.describe()}; {model}; CIE XYZ (D65, CIE 1931 "
            f"2 deg, perfect reflector{light_words(film)} Y = 1) against the "
            f"{film.varying.name} layer's "
            f"physical thickness {lo:g}-{hi:g} um (clamped outside); {size}-entry Lut1D."
            f"{scale}"
        ),
    )


def user_film_table(film: Film, size: int | None = None) -> Table1D:
    r"""Return the 1D table of a user's film: physical thickness (um) -> CIE XYZ.

    Parameters
    ----------
    film : Film
        The film (:func:`ocio_thinfilm.physics.films.read_films`).
    size : int, optional
        Entries, uniform over ``film.range_um``, in [2, 2**20] (default
        :func:`default_size`).

    Returns
    -------
    Table1D
        Linear encoding over the film's range; cached per film object and size.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``size``) a size that is not a finite integer in [2, 2**20].
    TypeError
        If ``size`` is not a number.

    Examples
    --------
    A free soap film thinner than any wavelength reflects nothing:

    >>> from ocio_thinfilm.physics.films import parse_films
    >>> soap = parse_films('[films.S]\nstack = ["air", "soap film", "air"]')["S"]
    >>> table = user_film_table(soap)
    >>> table.lookup(0.0).round(6).tolist()
    [0.0, 0.0, 0.0]
    """
    size = default_size(film) if size is None else as_count("size", size, 2, 1 << 20)
    return _user_film_table(film, size)
