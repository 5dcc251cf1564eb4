"""The viewing illuminant: spectra seen under one light, adapted to the scene white D65.

A film is seen under an illuminant (fab colour charts are made under fluorescent
light, a studio under tungsten): its colours are the tristimulus integrals of its
reflectance under that illuminant, with the perfect reflector under it as white, then
carried to the scene white D65 by a von Kries chromatic adaptation in a named cone
space (CAT02 by default), as the eye adapts to the light (CIE 15:2004, Section 7;
CIE 159:2004 for CAT02).

- :func:`von_kries_matrix` -- the 3x3 von Kries adaptation from one white to another;
- :func:`check_illuminant`, :func:`check_adaptation` -- colour-science's names;
- :func:`viewing_weights` -- integration weights under an illuminant, adapted to D65.

The matrices are computed in elementwise arithmetic from colour-science's CAT matrices
(:mod:`ocio_thinfilm.reproducible`: the same bits on every CPU), not with its
BLAS-based ``matrix_chromatic_adaptation_VonKries``, which they equal to 1e-15
(``tests/test_illuminant.py``).
"""

from __future__ import annotations

import re

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import reproducible
from ocio_thinfilm.checks import ParameterError

__all__ = [
    "SCENE_ILLUMINANT",
    "DEFAULT_ADAPTATION",
    "von_kries_matrix",
    "check_illuminant",
    "check_adaptation",
    "viewing_weights",
]

#: The scene white every colour is adapted to.
SCENE_ILLUMINANT = "D65"
#: The default chromatic adaptation transform (a key of
#: ``colour.CHROMATIC_ADAPTATION_TRANSFORMS``).
DEFAULT_ADAPTATION = "CAT02"


def von_kries_matrix(
    source_XYZ: npt.ArrayLike, target_XYZ: npt.ArrayLike, transform: npt.ArrayLike
) -> np.ndarray:
    """Return the von Kries adaptation matrix from one white to another.

    ``M^-1 diag(M w_target / M w_source) M`` with ``M`` the cone space's matrix
    (colour-science's ``matrix_chromatic_adaptation_VonKries``), in a fixed order of
    elementwise operations: the same bits on every CPU.

    Parameters
    ----------
    source_XYZ, target_XYZ : array_like
        The two whites, CIE XYZ (3,).
    transform : array_like
        The cone space's 3x3 matrix, e.g. ``colour.adaptation.CAT_CAT02``.

    Returns
    -------
    numpy.ndarray
        (3, 3): ``XYZ_target = A @ XYZ_source``.

    Examples
    --------
    The source white goes to the target white:

    >>> import colour
    >>> A = von_kries_matrix([1.0985, 1.0, 0.3558], [0.9505, 1.0, 1.0888],
    ...                      colour.adaptation.CAT_CAT02)
    >>> (A @ [1.0985, 1.0, 0.3558]).round(4).tolist()
    [0.9505, 1.0, 1.0888]
    """
    M = np.asarray(transform, dtype=np.float64)
    gain = reproducible.matmul(M, np.asarray(target_XYZ, np.float64)) / reproducible.matmul(
        M, np.asarray(source_XYZ, np.float64)
    )
    return reproducible.matmul(reproducible.inv3(M) * gain, M)


def _fluorescent(name: str) -> str:
    """Return colour-science's key of CIE's name for a fluorescent illuminant (F2 -> FL2)."""
    return re.sub(r"^F(\d)", r"FL\1", name)


def check_illuminant(name: str, parameter: str = "illuminant") -> str:
    """Return colour-science's key of an illuminant's name.

    Parameters
    ----------
    name : str
        A key of ``colour.SDS_ILLUMINANTS`` (``D65``, ``A``, ``FL2``, ...); CIE's names
        of the fluorescent illuminants (``F1`` to ``F12``, ``F3.1`` to ``F3.15``) are
        accepted for colour-science's ``FL1`` ...
    parameter : str, optional
        The parameter named in the error.

    Returns
    -------
    str
        The key.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``parameter``) naming the allowed names.

    Examples
    --------
    >>> check_illuminant("F11"), check_illuminant("D65")
    ('FL11', 'D65')
    """
    if name == SCENE_ILLUMINANT:  # the default needs no colour-science import
        return name
    import colour

    if isinstance(name, str):
        for key in (name, _fluorescent(name)):
            if key in colour.SDS_ILLUMINANTS:
                return key
    raise ParameterError(
        parameter,
        f" must be one of colour-science's colour.SDS_ILLUMINANTS (F1-F12 for FL1-FL12 too): "
        f"{', '.join(colour.SDS_ILLUMINANTS)}; got {name!r}",
    )


def check_adaptation(name: str, parameter: str = "adaptation") -> str:
    """Return ``name`` if it is a chromatic adaptation transform of colour-science.

    Parameters
    ----------
    name : str
        A key of ``colour.CHROMATIC_ADAPTATION_TRANSFORMS`` (``CAT02``, ``Bradford``,
        ``CAT16``, ``Von Kries``, ``XYZ Scaling``, ...).
    parameter : str, optional
        The parameter named in the error.

    Returns
    -------
    str
        ``name``.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``parameter``) naming the allowed names.
    """
    if name == DEFAULT_ADAPTATION:
        return name
    import colour

    if isinstance(name, str) and name in colour.CHROMATIC_ADAPTATION_TRANSFORMS:
        return name
    raise ParameterError(
        parameter,
        " must be one of colour-science's colour.CHROMATIC_ADAPTATION_TRANSFORMS: "
        f"{', '.join(colour.CHROMATIC_ADAPTATION_TRANSFORMS)}; got {name!r}",
    )


def viewing_weights(
    wavelengths: npt.ArrayLike,
    illuminant: str = SCENE_ILLUMINANT,
    adaptation: str = DEFAULT_ADAPTATION,
) -> np.ndarray:
    """Return weights ``W`` so that ``XYZ = R @ W`` is a reflectance seen under ``illuminant``.

    The tristimulus weights under the illuminant
    (:func:`ocio_thinfilm.colour.colorimetry.spectral_weights`: the perfect reflector
    under it has Y = 1), followed by the von Kries adaptation (:func:`von_kries_matrix`,
    in the cone space ``adaptation``) from the perfect reflector under the illuminant
    on the same wavelengths to the scene white D65 (colour-science's chromaticity,
    Y = 1, the white of the colour spaces' matrices). Under D65 these are
    :func:`~ocio_thinfilm.colour.colorimetry.spectral_weights` themselves.

    Parameters
    ----------
    wavelengths : array_like
        Sample wavelengths in nm (as ``spectral_weights``).
    illuminant : str, optional
        A name :func:`check_illuminant` takes (default D65).
    adaptation : str, optional
        A name :func:`check_adaptation` takes (default CAT02).

    Returns
    -------
    numpy.ndarray
        (len(wavelengths), 3); the perfect reflector's XYZ, the column sums, is the
        D65 white.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``illuminant`` or ``adaptation``) for names colour-science does not know.

    Examples
    --------
    A reflectance of 1 is the D65 white under any illuminant:

    >>> wl = np.arange(380.0, 781.0, 5.0)
    >>> viewing_weights(wl, "F11").sum(axis=0).round(4).tolist()
    [0.9505, 1.0, 1.089]
    """
    from ocio_thinfilm.colour import colorimetry

    illuminant = check_illuminant(illuminant)
    adaptation = check_adaptation(adaptation)
    if illuminant == SCENE_ILLUMINANT:
        return colorimetry.spectral_weights(wavelengths)
    import colour

    W = colorimetry.spectral_weights(wavelengths, illuminant=illuminant)
    white = reproducible.matmul(np.ones(W.shape[0]), W)
    xy = np.asarray(
        colour.CCS_ILLUMINANTS[colorimetry.DEFAULT_OBSERVER][SCENE_ILLUMINANT], np.float64
    )
    target = np.array([xy[0] / xy[1], 1.0, (1.0 - xy[0] - xy[1]) / xy[1]])
    A = von_kries_matrix(white, target, colour.CHROMATIC_ADAPTATION_TRANSFORMS[adaptation])
    return reproducible.matmul(W, A.T)
