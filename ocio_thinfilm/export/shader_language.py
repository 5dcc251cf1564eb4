"""The tokens in which GLSL and DaVinci Resolve DCTL differ, and their float literals.

The shaders' code (:mod:`.shader_parts`) is shared between the two languages; a
:class:`Language` holds the names that differ (the vector type and its constructor, the
function qualifier, the built-ins: DCTL's documented ``_powf``, ``_fmaxf``, ...) and
prints float literals that round to the float32 nearest the value.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Language", "GLSL", "DCTL", "TOKENS", "matrix_rows"]


@dataclass(frozen=True)
class Language:
    """The tokens in which GLSL and DCTL differ (the code is otherwise shared)."""

    vec3: str
    make3: str
    qualifier: str
    suffix: str
    pow: str
    max: str
    sqrt: str
    log: str
    exp2: str
    exp: str
    log2: str
    saturate: str

    def lit(self, x: float) -> str:
        """Return a float literal that rounds to the float32 nearest ``x`` (finite)."""
        mantissa, _, exponent = f"{float(np.float32(x)):.9g}".partition("e")
        if "." not in mantissa:
            mantissa += ".0"
        return mantissa + (f"e{exponent}" if exponent else "") + self.suffix


GLSL = Language(
    vec3="vec3",
    make3="vec3",
    qualifier="",
    suffix="",
    pow="pow",
    max="max",
    sqrt="sqrt",
    log="log",
    exp2="exp2",
    exp="exp",
    log2="log2",
    saturate="ocio_thinfilm_saturate",
)
DCTL = Language(
    vec3="float3",
    make3="make_float3",
    qualifier="__DEVICE__ ",
    suffix="f",
    pow="_powf",
    max="_fmaxf",
    sqrt="_sqrtf",
    log="_logf",
    exp2="_exp2f",
    exp="_expf",
    log2="_log2f",
    saturate="_saturatef",
)
TOKENS = {"glsl": GLSL, "dctl": DCTL}


def matrix_rows(L: Language, M: np.ndarray, names: tuple[str, str, str]) -> list[str]:
    """Return the three rows of ``M`` applied to the expressions ``names``, in ``L``.

    Parameters
    ----------
    L : Language
        The language whose literals print the coefficients.
    M : numpy.ndarray
        A 3 x 3 matrix.
    names : tuple of str
        The three expressions the rows multiply (e.g. ``("r", "g", "b")``).

    Returns
    -------
    list of str
        ``M[i, 0] * a + M[i, 1] * b + M[i, 2] * c`` for each row ``i``.
    """
    a, b, c = names
    return [
        f"{L.lit(M[i, 0])} * {a} + {L.lit(M[i, 1])} * {b} + {L.lit(M[i, 2])} * {c}"
        for i in range(3)
    ]
