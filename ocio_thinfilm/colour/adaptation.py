"""The viewing illuminant: spectra seen under one light, adapted to the scene white D65.

A film is seen under an illuminant (fab colour charts are made under fluorescent
light, a studio under tungsten): its colours are the tristimulus integrals of its
reflectance under that illuminant, with the perfect reflector under it as white, then
carried to the scene white D65 by a von Kries chromatic adaptation in a named cone
space (CAT02 by default), as the eye adapts to the light (CIE 15:2004, Section 7;
CIE 159:2004 for CAT02).

- :func:`von_kries_matrix` -- the 3x3 von Kries adaptation from one white to another
  (also the Bradford adaptation of the ACES spaces' matrices,
  :mod:`ocio_thinfilm.colour.colorimetry`).

The names (colour-science's illuminants and adaptation transforms) are checked by
:mod:`ocio_thinfilm.physics.light`, where a film file's are; the weights under an
illuminant are :func:`ocio_thinfilm.lut.film_tables.viewing_weights`.

The matrices are computed in elementwise arithmetic from colour-science's CAT matrices
(:mod:`ocio_thinfilm.reproducible`: the same bits on every CPU), not with its
BLAS-based ``matrix_chromatic_adaptation_VonKries``, which they equal to 1e-15
(``tests/test_illuminant.py``).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import reproducible

__all__ = ["von_kries_matrix"]


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
