"""A display's colorimetry and encoding as OCIO transforms (from the one registry).

- :func:`display_matrix_transform` -- CIE-XYZ-D65 -> display-linear RGB (or back);
- :data:`DISPLAY_ENCODINGS`, :func:`display_encoding_transform` -- display-linear RGB
  -> display code values (the inverse EOTF, as the ACES OCIO configs' display spaces);
- :func:`aces_gamut_compression_transform` -- OCIO's ACES 1.3 reference gamut
  compression, the baseline view the clip is compared with.
"""

from __future__ import annotations

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import ocio_ops

__all__ = [
    "DISPLAY_ENCODINGS",
    "check_display",
    "display_matrix_transform",
    "display_encoding_transform",
    "aces_gamut_compression_transform",
]


def check_display(display: str) -> str:
    """``display`` if the registry has it, else ValueError naming the choices."""
    if display not in registry.DISPLAYS:
        raise ValueError(f"display must be one of {registry.DISPLAYS}, got {display!r}")
    return display


def display_matrix_transform(display: str, inverse: bool = False):
    """CIE-XYZ-D65 -> display-linear RGB (or back) as an OCIO MatrixTransform."""
    M = colorimetry.matrix_XYZ_to_RGB(check_display(display))
    return ocio_ops.matrix(np.linalg.inv(M) if inverse else M)



#: Display encodings (inverse EOTFs), as in the ACES OCIO configs' display spaces.
#: Display -> (description, gamma, offset or None for a pure power) (:mod:`.registry`).
DISPLAY_ENCODINGS = {d.name: d.encoding for d in registry.DISPLAY_LIST}


def display_encoding_transform(display: str):
    """Display-linear RGB -> display code values (the display's inverse EOTF)."""
    ocio = ocio_ops.module()
    _, gamma, offset = DISPLAY_ENCODINGS[check_display(display)]
    if offset is None:
        t = ocio.ExponentTransform([gamma, gamma, gamma, 1.0])
        t.setNegativeStyle(ocio.NEGATIVE_CLAMP)
    else:
        t = ocio.ExponentWithLinearTransform([gamma] * 3 + [1.0], [offset] * 3 + [0.0])
    t.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return t


def aces_gamut_compression_transform():
    ocio = ocio_ops.module()
    return ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13,
                                       list(clip.ACES_GAMUT_COMP13_PARAMS))
