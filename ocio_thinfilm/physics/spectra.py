"""Thin-film interference spectra (Smits & Meyer 1990, Section 2).

Stage 1 of the pipeline: spectra -> XYZ -> clip -> tables/LUTs -> config -> render.

Every model returns a reflectance ``R(lambda)`` relative to the illuminant, so a
perfect reflector (``R == 1``) is white. Arrays broadcast: the wavelength grid is
always the *last* axis of the result; thickness, angle and index arrays broadcast
against each other in front of it. Lengths are in nanometres, angles in degrees.

Public functions
----------------
- :func:`optical_thickness` -- Eq. 10 form (refraction angle, default) or literal Eq. 11
- :func:`two_beam_reflectance` -- Eq. 5-8 (phase change / no phase change)
- :func:`morpho_layer_thickness` -- Eq. 14
- :func:`multilayer_reflectance` -- Eq. 9 (Anderson & Richards), peak-normalised

The wavelength grid, the argument checks and the band-limited integration all models
share are in :mod:`ocio_thinfilm.physics.sampling`; the exact optics used as references
(Airy sum with Fresnel amplitudes, transfer matrices) in
:mod:`ocio_thinfilm.physics.exact`.
"""

from __future__ import annotations

from typing import TypedDict

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import ParameterError, as_array, as_count
from ocio_thinfilm.physics.sampling import (
    MAX_LAYERS,
    as_angle,
    as_index,
    check_wavelengths,
    cosine_series,
    phase,
)

__all__ = [
    "MORPHO",
    "optical_thickness",
    "two_beam_reflectance",
    "morpho_layer_thickness",
    "multilayer_reflectance",
]


class MorphoGeometry(TypedDict):
    """The keys of :data:`MORPHO`."""

    d1: float
    d2: float
    n: float
    layers: int


#: Morpho wing scale geometry from the paper (Section 4.3, Eq. 14): spacing d1 and
#: thickness d2 of the mullions in nm, their index n, and the number of layers l
#: ("twelve horizontal mullions").
MORPHO: MorphoGeometry = {"d1": 150.0, "d2": 50.0, "n": 1.53, "layers": 12}


# --------------------------------------------------------------------------- #
# The paper's models.
# --------------------------------------------------------------------------- #
def optical_thickness(
    thickness: npt.ArrayLike,
    n: npt.ArrayLike,
    theta: npt.ArrayLike = 0.0,
    *,
    mode: str = "refraction",
) -> np.ndarray:
    """Optical thickness t' of a film (paper Eq. 10 and Eq. 11).

    ``mode="refraction"`` (default) uses the refraction angle inside the film:
    ``t' = t n cos(theta_t) = t sqrt(n^2 - sin^2(theta))`` -- the paper's own Eq. 10
    form, the correct optical path for a film seen from air. ``mode="literal"`` is
    Eq. 11 as printed, ``t' = t n cos(theta)`` with the *viewing* angle; it
    under-estimates t' away from normal incidence (at 60 degrees and n = 1.33 by
    34 %), shifting colours too fast with angle.

    Parameters
    ----------
    thickness : array_like
        Physical thickness t in nm, >= 0.
    n : array_like
        Refractive index of the film, > 0.
    theta : array_like, optional
        Viewing angle in air, degrees in [0, 90]. Below the critical angle of an
        ``n < 1`` film the refracted wave is evanescent and t' is 0.
    mode : {"refraction", "literal"}

    Returns
    -------
    numpy.ndarray
        t' in nm, broadcast over the inputs.

    References
    ----------
    Smits, B. E., Meyer, G. W. (1990). Newton's Colors: Simulating Interference
    Phenomena in Realistic Image Synthesis. Eq. 10-11.

    Examples
    --------
    A soap film (n = 1.33), 300 nm thick, at normal incidence and at 60 degrees
    (300 * sqrt(1.33^2 - 0.75) = 302.82):

    >>> float(optical_thickness(300, 1.33))
    399.0
    >>> round(float(optical_thickness(300, 1.33, 60)), 2)
    302.82
    """
    t = as_array("thickness", thickness, minimum=0.0, unit=" nm")
    n = as_index("n", n)
    theta = np.deg2rad(as_angle(theta))
    if mode == "refraction":
        return t * np.sqrt(np.maximum(n * n - np.sin(theta) ** 2, 0.0))
    if mode == "literal":
        return t * n * np.cos(theta)
    raise ParameterError("mode", f" must be 'refraction' or 'literal', got {mode!r}")


def two_beam_reflectance(
    optical_thickness_nm: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    *,
    phase_change: bool = True,
    band_limited: bool = False,
) -> np.ndarray:
    """Two-beam reflectance of a single film, normalised to a peak of 1 (Eq. 5-8).

    Eq. 7 (phase change: soap film, oil on water):   ``R = sin^2(2 pi t'/lambda)``;
    Eq. 8 (no phase change: film on a denser base):  ``R = cos^2(2 pi t'/lambda)``.
    Eq. 6 -> 7 drops the factor 4 of the two-beam amplitude sum, so R is relative
    to the illuminant with a peak of 1 and a thick-film (incoherent) mean of 1/2.
    Written as the cosine series ``1/2 (1 -/+ cos(phi))`` with ``phi = 4 pi t'/lambda``.

    Parameters
    ----------
    optical_thickness_nm : array_like
        t' = n t cos(theta_t) in nm (:func:`optical_thickness`), >= 0.
    wavelengths : array_like
        Wavelengths in nm (the last axis of the result).
    phase_change : bool, optional
        Eq. 7 (True) or Eq. 8 (False).
    band_limited : bool, optional
        Average each sample over its trapezoid hat (see the module docstring).

    Returns
    -------
    numpy.ndarray
        R in [0, 1], shape ``t'.shape + (len(wavelengths),)``.

    References
    ----------
    Smits & Meyer (1990), Eq. 5-8.

    Examples
    --------
    No film reflects nothing with a phase change; a quarter wave (t' = lambda/4)
    reflects fully:

    >>> two_beam_reflectance([0.0, 137.5], [550.0]).tolist()
    [[0.0], [1.0]]
    """
    t = as_array("optical_thickness", optical_thickness_nm, minimum=0.0, unit=" nm")
    wl = check_wavelengths(wavelengths)
    phi, dphi = phase(2.0 * t, wl, band_limited)
    return np.clip(cosine_series([0.5, -0.5 if phase_change else 0.5], phi, dphi), 0.0, 1.0)


def morpho_layer_thickness(
    theta: npt.ArrayLike = 0.0,
    d1: npt.ArrayLike = MORPHO["d1"],
    d2: npt.ArrayLike = MORPHO["d2"],
    n: npt.ArrayLike = MORPHO["n"],
) -> np.ndarray:
    """Effective layer thickness of the Morpho wing scale (paper Eq. 14).

    ``t = d1 cos(theta) + d2 sqrt(n^2 - sin^2(theta))``: the air gap d1 and the
    mullion d2 of index n, seen at the viewing angle theta.

    Parameters
    ----------
    theta : array_like, optional
        Viewing angle, degrees in [0, 90].
    d1, d2 : float, optional
        Spacing and thickness of the mullions in nm (paper: 150 and 50).
    n : float, optional
        Index of the mullions (paper: 1.53).

    Returns
    -------
    numpy.ndarray
        t in nm.

    References
    ----------
    Smits & Meyer (1990), Eq. 14.

    Examples
    --------
    >>> float(morpho_layer_thickness(0.0))  # 150 + 50 * 1.53
    226.5
    """
    theta = np.deg2rad(as_angle(theta))
    d1 = as_array("d1", d1, minimum=0.0, unit=" nm")
    d2 = as_array("d2", d2, minimum=0.0, unit=" nm")
    n = as_index("n", n)
    return d1 * np.cos(theta) + d2 * np.sqrt(np.maximum(n * n - np.sin(theta) ** 2, 0.0))


def multilayer_reflectance(
    thickness: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    layers: int = MORPHO["layers"],
    *,
    band_limited: bool = False,
) -> np.ndarray:
    """Multiple-film reflectance, Eq. 9 (Anderson & Richards 1942), peak-normalised.

    Eq. 9 reads ``I = 1/2 A0 (sin(2 pi (l+1) t/lambda) / sin(2 pi t/lambda))^2``. With
    ``x = 2 pi t/lambda`` the ratio is the Fejer kernel

        (sin((l+1)x) / sin x)^2 = (l+1) + 2 sum_{k=1..l} (l+1-k) cos(2 k x),

    a finite cosine series that is exact everywhere, including the 0/0 points
    ``sin x = 0`` where it takes its peak ``(l+1)^2``, with no cancellation
    spike next to them. We divide by that peak (and drop the 1/2), so R peaks at 1.

    Parameters
    ----------
    thickness : array_like
        Effective layer thickness t (Eq. 10 or 14) in nm, >= 0.
    wavelengths : array_like
        Wavelengths in nm (the last axis of the result).
    layers : int, optional
        The number of layers l (paper: 12 for the Morpho).
    band_limited : bool, optional
        Average each sample over its trapezoid hat (see the module docstring).

    Returns
    -------
    numpy.ndarray
        R in [0, 1], shape ``thickness.shape + (len(wavelengths),)``.

    References
    ----------
    Smits & Meyer (1990), Eq. 9; Anderson, T. F., Richards, A. G. (1942). An Electron
    Microscope Study of Some Structural Colors of Insects. J. Appl. Phys. 13.

    Examples
    --------
    The Morpho layer (t = 226.5 nm) peaks at lambda = 2 t, the 0/0 point of Eq. 9:

    >>> multilayer_reflectance(226.5, [453.0]).tolist()
    [1.0]
    """
    t = as_array("thickness", thickness, minimum=0.0, unit=" nm")
    wl = check_wavelengths(wavelengths)
    l = as_count("layers", layers, 1, MAX_LAYERS)
    peak = float((l + 1) ** 2)
    coefficients = [(l + 1) / peak] + [2.0 * (l + 1 - k) / peak for k in range(1, l + 1)]
    # cos(2 k x) = cos(k phi) with phi = 4 pi t / lambda: optical path P = 2 t.
    phi, dphi = phase(2.0 * t, wl, band_limited)
    # The series is >= 0 and <= 1 exactly; rounding can leave it 1e-11 outside.
    return np.clip(cosine_series(coefficients, phi, dphi), 0.0, 1.0)
