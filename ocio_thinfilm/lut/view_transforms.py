"""The views of every display as OCIO transforms: CIE-XYZ-D65 -> display code values.

The views are the registry's (:data:`ocio_thinfilm.registry.VIEWS`): the
``Constant-Lightness Clip`` (:mod:`ocio_thinfilm.lut.clip_lut`) and the baselines it is
compared with, ``Channel Clamp`` and ``ACES Gamut Compression``, and ``Raw``.

- :func:`view_linear_transform` -- CIE-XYZ-D65 -> display-linear RGB in [0, 1];
- :func:`view_transform` -- CIE-XYZ-D65 -> display-encoded RGB.
"""

from __future__ import annotations

from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.clip_lut import (
    CLIP_SIZE,
    clip_lut,
    clip_transform,
    working_decoding_transform,
)
from ocio_thinfilm.lut.display_transforms import (
    aces_gamut_compression_transform,
    check_display,
    display_encoding_transform,
    display_matrix_transform,
)
from ocio_thinfilm.lut.ocio_ops import finite_limit_transform, group, transform_id
from ocio_thinfilm.registry import VIEWS

__all__ = ["view_linear_transform", "view_transform"]


def view_linear_transform(display: str, view: str, size: int = CLIP_SIZE):
    """CIE-XYZ-D65 -> display-linear RGB in [0, 1] for ``view`` (not for Raw)."""
    check_display(display)
    if view == "Constant-Lightness Clip":
        return clip_transform(display, size)
    # the baselines limit XYZ to +-LIMIT first: +-Inf (and NaN, which OCIO's CPU Range
    # takes to the lower bound) stay finite through the matrices at every
    # optimisation level (OPTIMIZATION_NONE does not compose them, so F32_MAX inputs
    # overflowed to Inf - Inf = NaN)
    if view == "Channel Clamp":
        return group([finite_limit_transform(), display_matrix_transform(display),
                      ocio_ops.range_(0.0, 1.0)])
    if view == "ACES Gamut Compression":
        return group([finite_limit_transform(), display_matrix_transform(display),
                      aces_gamut_compression_transform(), ocio_ops.range_(0.0, 1.0)])
    raise ValueError(f"view must be one of {VIEWS[:3]}, got {view!r}")


def view_transform(display: str, view: str, size: int = CLIP_SIZE):
    """OCIO transform CIE-XYZ-D65 -> display-encoded RGB for ``view`` in :data:`VIEWS`.

    ``Raw`` passes values through unchanged (an empty group). The constant-lightness
    clip's second LUT ends in sRGB code values: decoded, then the display's encoding
    (OCIO's optimiser removes the pair for the sRGB-encoded displays).
    """
    check_display(display)
    if view not in VIEWS:
        raise ValueError(f"view must be one of {VIEWS}, got {view!r}")
    if view == "Raw":
        return group([])
    if view == "Constant-Lightness Clip":
        lut = clip_lut(display, size)
        return group(lut.transforms() + [working_decoding_transform(),
                                         display_encoding_transform(display)],
                     name=lut.name, id=transform_id("Gamut_Map", lut.name))
    return group([view_linear_transform(display, view, size),
                  display_encoding_transform(display)])
