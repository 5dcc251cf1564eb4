"""A film under a coloured light: the spectral colour against an RGB renderer's product.

A spectral renderer computes a film's colour under a light as the tristimulus integral of
the film's reflectance times the light's spectrum; an RGB renderer multiplies the film's
RGB (a material table made under D65, :mod:`ocio_thinfilm.lut.material_tables`) by the
light's RGB, channel by channel. This module gives both sides of that comparison
(docs/rgb_vs_spectral.md, ``benchmarks/bench_rgb_vs_spectral.py``):

- :func:`led_spectrum` -- a narrow-band RGB LED white at D65's chromaticity (three Ohno
  2005 LED peaks, :data:`LED_PEAKS_NM`), a light colour-science's illuminants lack;
- :func:`light_weights` -- the tristimulus weights under a light (colour-science's
  illuminants by name, or :data:`LED_NAME`), the perfect reflector under it at Y = 1,
  optionally adapted to D65 as a film file's ``illuminant`` does;
- :func:`film_light_XYZ` -- a film's XYZ over thickness x cos theta under several lights
  at once (one set of spectra, one integral per light): the spectral truth;
- :func:`light_white_XYZ`, :func:`light_RGB` -- the light's colour (the perfect
  reflector under it) as XYZ and as the RGB a renderer stores;
- :func:`rgb_path_XYZ` -- what an RGB renderer computes: table RGB times the light's RGB;
- :func:`scene_adaptation` -- the von Kries matrix from the light's white to D65 (the
  ``adaptation`` of a film file), which :func:`delta_E_under` applies to both colours
  before CIEDE2000, so that a difference is the film's, not the light's;
- :func:`table_lookup` -- the bilinear read of a node-centred table a host does.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import reproducible
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.colour import adaptation, colorimetry
from ocio_thinfilm.lut import film_tables, material_tables
from ocio_thinfilm.physics import films as films_module
from ocio_thinfilm.physics import light, sampling
from ocio_thinfilm.physics.films import Film
from ocio_thinfilm.physics.materials import VISIBLE_NM

__all__ = [
    "LED_NAME",
    "LED_PEAKS_NM",
    "LED_WIDTHS_NM",
    "LED_POWER_RATIOS",
    "FINE_STEP_NM",
    "led_spectrum",
    "light_weights",
    "light_white_XYZ",
    "light_RGB",
    "scene_adaptation",
    "film_light_XYZ",
    "rgb_path_XYZ",
    "delta_E_under",
    "table_lookup",
]

#: The name of the RGB LED white of :func:`led_spectrum`.
LED_NAME = "RGB-LED-D65"
#: Its three peaks (nm): blue, green and red emitters (Ohno 2005's three-chip white).
LED_PEAKS_NM = (450.0, 530.0, 630.0)
#: Their widths, the ``half_spectral_width`` of Ohno 2005's model (about the FWHM), nm.
LED_WIDTHS_NM = (20.0, 30.0, 20.0)
#: Their peak power ratios (green = 1), solved so that the white is D65's chromaticity
#: (CIE 1931 2 degree; x, y within 4e-6 of (0.3127, 0.3290), CCT 6504 K).
LED_POWER_RATIOS = (1.0182, 1.0, 1.4687)
#: The coarsest wavelength step of :func:`film_light_XYZ` (nm): fine enough for the
#: lines of the fluorescent lamps and the LED's peaks.
FINE_STEP_NM = 1.0


def led_spectrum(wavelengths: npt.ArrayLike) -> np.ndarray:
    """Return the relative spectrum of the RGB LED white :data:`LED_NAME`.

    The sum over the three emitters of Ohno's (2005) LED model ``(g + 2 g**5) / 3``,
    ``g = exp(-((l - peak) / width)**2)`` (colour-science's
    ``colour.colorimetry.sd_multi_leds_Ohno2005``), with :data:`LED_PEAKS_NM`,
    :data:`LED_WIDTHS_NM` and :data:`LED_POWER_RATIOS`: a narrow-band white at D65's
    chromaticity, whose colour rendering index Ra is 44.

    Parameters
    ----------
    wavelengths : array_like
        Wavelengths in nm.

    Returns
    -------
    numpy.ndarray
        The relative power at each wavelength, rounded to 32 significant bits (the
        same on every CPU, :func:`ocio_thinfilm.reproducible.canonical`).

    References
    ----------
    Ohno, Y. (2005). Spectral design considerations for white LED color rendering.
    Optical Engineering, 44(11), 111302.

    Examples
    --------
    The red peak is the strongest:

    >>> led_spectrum([450.0, 530.0, 630.0]).round(3).tolist()
    [1.018, 1.0, 1.469]
    """
    wl = np.asarray(wavelengths, dtype=np.float64)
    total = np.zeros(wl.shape)
    for peak, width, ratio in zip(LED_PEAKS_NM, LED_WIDTHS_NM, LED_POWER_RATIOS, strict=True):
        g = np.exp(-(((wl - peak) / width) ** 2))
        total = total + ratio * (g + 2.0 * g**5) / 3.0
    return reproducible.canonical(total)


def _check_light(name: str) -> str:
    """Return colour-science's key of ``name``, or :data:`LED_NAME`."""
    if name == LED_NAME:
        return name
    try:
        return light.check_illuminant(name, "light")
    except ParameterError as error:
        raise ParameterError(
            "light", f" must be {LED_NAME!r} or a key of colour.SDS_ILLUMINANTS, got {name!r}"
        ) from error


def light_weights(
    wavelengths: npt.ArrayLike, light_name: str, adaptation_name: str | None = None
) -> np.ndarray:
    """Return weights ``W`` so that ``XYZ = R @ W`` is a reflectance seen under a light.

    The trapezoid weights of the CIE 1931 2 degree colour matching functions times the
    light's spectrum, scaled so the perfect reflector has Y = 1 (for colour-science's
    illuminants :func:`ocio_thinfilm.colour.colorimetry.spectral_weights`; for
    :data:`LED_NAME`, :func:`led_spectrum` on the same rule).

    Parameters
    ----------
    wavelengths : array_like
        Sample wavelengths in nm.
    light_name : str
        A key of ``colour.SDS_ILLUMINANTS`` (CIE's ``F1``-``F12`` too) or :data:`LED_NAME`.
    adaptation_name : str, optional
        None (default): the colour under the light, not adapted. A key of
        ``colour.CHROMATIC_ADAPTATION_TRANSFORMS``: adapted from the perfect reflector
        under the light (on these wavelengths) to D65, as a film file's ``illuminant``
        and ``adaptation`` make the tables
        (:func:`ocio_thinfilm.lut.film_tables.viewing_weights`, which these equal for
        colour-science's illuminants).

    Returns
    -------
    numpy.ndarray
        (len(wavelengths), 3).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``light``) for an unknown light.

    Examples
    --------
    Under the LED the perfect reflector is the D65 white:

    >>> wl = np.arange(380.0, 781.0, 1.0)
    >>> light_weights(wl, LED_NAME).sum(axis=0).round(3).tolist()
    [0.95, 1.0, 1.089]
    """
    name = _check_light(light_name)
    if name != LED_NAME:
        if adaptation_name is None:
            return colorimetry.spectral_weights(wavelengths, illuminant=name)
        return film_tables.viewing_weights(wavelengths, name, adaptation_name)
    wl = sampling.check_wavelengths(wavelengths)
    lower, upper = sampling.bin_edges(wl)
    width = (upper - lower) if wl.size > 1 else np.ones(1)
    W = colorimetry.cmfs_at(wl) * (led_spectrum(wl) * width)[:, None]
    W = W / W[:, 1].sum()
    if adaptation_name is None:
        return W
    white = reproducible.matmul(np.ones(W.shape[0]), W)
    return reproducible.matmul(W, _to_d65(white, adaptation_name).T)


def _fine_grid() -> np.ndarray:
    """Return 380-780 nm in steps of :data:`FINE_STEP_NM`."""
    count = int(round((VISIBLE_NM[1] - VISIBLE_NM[0]) / FINE_STEP_NM)) + 1
    return np.linspace(VISIBLE_NM[0], VISIBLE_NM[1], count)


def light_white_XYZ(light_name: str) -> np.ndarray:
    """Return the XYZ of the perfect reflector under a light, Y = 1 (380-780 nm, 1 nm).

    Parameters
    ----------
    light_name : str
        As :func:`light_weights`.

    Returns
    -------
    numpy.ndarray
        (3,), not adapted: the light's colour.

    Examples
    --------
    Illuminant A (CIE 15:2004, over 300-830 nm: 1.0985, 1, 0.3558):

    >>> light_white_XYZ("A").round(2).tolist()
    [1.1, 1.0, 0.36]
    """
    W = light_weights(_fine_grid(), light_name)
    return reproducible.matmul(np.ones(W.shape[0]), W)


def light_RGB(light_name: str, space: str = "sRGB") -> np.ndarray:
    """Return the light's colour as a renderer stores it: its white in linear RGB.

    :func:`light_white_XYZ` through the colourspace's matrix from D65-relative XYZ
    (:func:`ocio_thinfilm.colour.colorimetry.XYZ_to_RGB`; no adaptation: D65 is
    RGB 1, 1, 1).

    Parameters
    ----------
    light_name : str
        As :func:`light_weights`.
    space : str, optional
        A linear RGB space of the colorimetry (default ``"sRGB"``, linear Rec.709).

    Returns
    -------
    numpy.ndarray
        (3,), luminance 1.

    Examples
    --------
    Tungsten is red > green > blue, at the Rec.709 luminance
    0.2126 R + 0.7152 G + 0.0722 B = 1 (ITU-R BT.709-6):

    >>> r, g, b = light_RGB("A")
    >>> bool(r > g > b), round(float(0.2126 * r + 0.7152 * g + 0.0722 * b), 4)
    (True, 1.0)
    """
    return colorimetry.XYZ_to_RGB(light_white_XYZ(light_name), space)


def _to_d65(white_XYZ: np.ndarray, adaptation_name: str) -> np.ndarray:
    """Return the von Kries matrix from ``white_XYZ`` to D65 (as viewing_weights)."""
    import colour

    name = light.check_adaptation(adaptation_name, "adaptation_name")
    xy = np.asarray(
        colour.CCS_ILLUMINANTS[colorimetry.DEFAULT_OBSERVER][light.SCENE_ILLUMINANT], np.float64
    )
    target = np.array([xy[0] / xy[1], 1.0, (1.0 - xy[0] - xy[1]) / xy[1]])
    cat = colour.CHROMATIC_ADAPTATION_TRANSFORMS[name]
    return adaptation.von_kries_matrix(white_XYZ, target, cat)


def scene_adaptation(
    light_name: str, adaptation_name: str = light.DEFAULT_ADAPTATION
) -> np.ndarray:
    """Return the von Kries matrix from the light's white to the scene white D65.

    Parameters
    ----------
    light_name : str
        As :func:`light_weights`.
    adaptation_name : str, optional
        A key of ``colour.CHROMATIC_ADAPTATION_TRANSFORMS`` (default CAT02).

    Returns
    -------
    numpy.ndarray
        (3, 3): ``XYZ_D65 = A @ XYZ_light``; it takes :func:`light_white_XYZ` to the
        D65 white.

    Examples
    --------
    >>> A = scene_adaptation("A")
    >>> (A @ light_white_XYZ("A")).round(3).tolist()
    [0.95, 1.0, 1.089]
    """
    return _to_d65(light_white_XYZ(light_name), adaptation_name)


def film_light_XYZ(
    film: Film,
    thickness_um: npt.ArrayLike,
    cos_theta: npt.ArrayLike,
    lights: Sequence[str],
    adaptation_name: str | None = None,
) -> np.ndarray:
    r"""Return a film's reflectance as CIE XYZ under each light, over thickness x cos theta.

    Each row's spectra (the film's model at that angle,
    :func:`ocio_thinfilm.lut.material_tables.film_spectra`) are evaluated on the grid
    :func:`~ocio_thinfilm.physics.films.film_wavelengths` gives for the row and the
    thickest column (fringe sharpness capped at
    :data:`~ocio_thinfilm.lut.material_tables.MAX_SHARPNESS`, as the tables), or on
    380-780 nm in steps of :data:`FINE_STEP_NM` where that grid is coarser, and
    integrated with :func:`light_weights` of every light.

    Parameters
    ----------
    film : Film
        The film (its ``angle_deg`` is replaced by each row's angle; its
        ``illuminant`` is not used).
    thickness_um : array_like
        1-D thicknesses of the varying layer, um (the columns).
    cos_theta : array_like
        1-D cosines of the angle of incidence, in [0, 1] (the rows).
    lights : sequence of str
        Names :func:`light_weights` takes.
    adaptation_name : str, optional
        As :func:`light_weights` (default None: the colour under each light).

    Returns
    -------
    numpy.ndarray
        ``(len(lights), len(cos_theta), len(thickness_um), 3)``, the perfect reflector
        under each light at Y = 1.

    Examples
    --------
    At grazing incidence a film reflects the light's white:

    >>> from ocio_thinfilm.physics.films import parse_films
    >>> soap = parse_films('[films.S]\nstack = ["air", "soap film", "air"]')["S"]
    >>> film_light_XYZ(soap, [0.3], [0.0], ["A"]).round(2).tolist()
    [[[[1.1, 1.0, 0.36]]]]
    """
    t = np.atleast_1d(np.asarray(thickness_um, dtype=np.float64))
    c = np.atleast_1d(np.asarray(cos_theta, dtype=np.float64))
    if t.ndim != 1 or c.ndim != 1 or t.size == 0 or c.size == 0:
        raise ParameterError("thickness_um", " and cos_theta must be non-empty and 1-D")
    if np.any(t < 0) or np.any((c < 0) | (c > 1)):
        raise ParameterError("thickness_um", " must be >= 0 and cos_theta in [0, 1]")
    names = [_check_light(name) for name in lights]
    d = t * 1000.0
    out = np.empty((len(names), c.size, d.size, 3))
    fine = _fine_grid()
    for row, cosine in enumerate(c):
        row_film = dataclasses.replace(film, angle_deg=float(np.degrees(np.arccos(cosine))))
        wl = films_module.film_wavelengths(row_film, float(d.max()), material_tables.MAX_SHARPNESS)
        if wl.size < fine.size:
            wl = fine
        R, _ = material_tables.film_spectra(row_film, d, wl, False)
        for k, name in enumerate(names):
            out[k, row] = reproducible.matmul(R, light_weights(wl, name, adaptation_name))
    return out


def rgb_path_XYZ(table_RGB: npt.ArrayLike, light_name: str, space: str = "sRGB") -> np.ndarray:
    """Return what an RGB renderer computes: the table's RGB times the light's, as XYZ.

    Parameters
    ----------
    table_RGB : array_like
        A film's reflectance in linear RGB of ``space`` (a material table made under D65),
        last axis 3.
    light_name : str
        As :func:`light_weights`.
    space : str, optional
        The renderer's working space (default ``"sRGB"``, linear Rec.709).

    Returns
    -------
    numpy.ndarray
        D65-relative XYZ of ``table_RGB * light_RGB(light_name)`` (the light's colour
        included, not adapted), shape of ``table_RGB``.

    Examples
    --------
    A white surface under A is A's white:

    >>> rgb_path_XYZ([1.0, 1.0, 1.0], "A").round(2).tolist()
    [1.1, 1.0, 0.36]
    """
    product = np.asarray(table_RGB, dtype=np.float64) * light_RGB(light_name, space)
    return colorimetry.RGB_to_XYZ(product, space)


def delta_E_under(
    XYZ_a: npt.ArrayLike,
    XYZ_b: npt.ArrayLike,
    light_name: str,
    adaptation_name: str = light.DEFAULT_ADAPTATION,
) -> np.ndarray:
    """Return CIEDE2000 between two colours seen under a light, relative to its white.

    Both colours (XYZ under the light, its perfect reflector at Y = 1) go through the
    same :func:`scene_adaptation` to D65, then
    :func:`ocio_thinfilm.colour.colorimetry.delta_E2000` (CIELAB with the D65 white).

    Parameters
    ----------
    XYZ_a, XYZ_b : array_like
        CIE XYZ under the light, last axis 3.
    light_name : str
        As :func:`light_weights`.
    adaptation_name : str, optional
        The cone space of the adaptation (default CAT02).

    Returns
    -------
    numpy.ndarray
        The broadcast shape without the last axis.

    Examples
    --------
    The light's white and a grey of half its luminance differ by lightness alone:
    L* 100 and 76.07, so Delta E 2000 = 23.93 / S_L with S_L = 1.567 (L* mean 88.04):

    >>> w = light_white_XYZ("FL11")
    >>> round(float(delta_E_under(w, 0.5 * w, "FL11")), 1)
    15.3
    """
    A = scene_adaptation(light_name, adaptation_name)
    a = reproducible.matmul(np.asarray(XYZ_a, dtype=np.float64), A.T)
    b = reproducible.matmul(np.asarray(XYZ_b, dtype=np.float64), A.T)
    return np.asarray(colorimetry.delta_E2000(a, b), dtype=np.float64)


def table_lookup(
    table: npt.ArrayLike,
    range_um: tuple[float, float],
    thickness_um: npt.ArrayLike,
    cos_theta: npt.ArrayLike,
) -> np.ndarray:
    """Return a node-centred table read bilinearly, as a host reads a material table.

    Parameters
    ----------
    table : array_like
        (H, W, C): row j at cos theta ``j / (H - 1)``, column i at thickness
        ``lo + i (hi - lo) / (W - 1)`` (:func:`~.material_tables.axis_nodes`).
    range_um : tuple of float
        (lo, hi) of the thickness axis, um.
    thickness_um, cos_theta : array_like
        Where to read, broadcasting together; clamped to the table.

    Returns
    -------
    numpy.ndarray
        The broadcast shape + (C,).

    Examples
    --------
    >>> tab = np.arange(6.0).reshape(2, 3, 1)  # rows cos 0, 1; columns 0, 1, 2 um
    >>> table_lookup(tab, (0.0, 2.0), [0.5, 2.0], [0.5, 1.0])[:, 0].tolist()
    [2.0, 5.0]
    """
    tab = np.asarray(table, dtype=np.float64)
    H, W = tab.shape[:2]
    lo, hi = range_um
    t, c = np.broadcast_arrays(
        np.asarray(thickness_um, dtype=np.float64), np.asarray(cos_theta, dtype=np.float64)
    )
    x = np.clip((t - lo) / (hi - lo), 0.0, 1.0) * (W - 1)
    y = np.clip(c, 0.0, 1.0) * (H - 1)
    i = np.minimum(np.floor(x).astype(int), W - 2)
    j = np.minimum(np.floor(y).astype(int), H - 2)
    fx = (x - i)[..., None]
    fy = (y - j)[..., None]
    top = tab[j, i] * (1.0 - fx) + tab[j, i + 1] * fx
    bottom = tab[j + 1, i] * (1.0 - fx) + tab[j + 1, i + 1] * fx
    return top * (1.0 - fy) + bottom * fy
