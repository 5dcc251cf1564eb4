"""The views of every display as OCIO transforms: CIE-XYZ-D65 -> display code values.

The views are the registry's (:data:`ocio_thinfilm.registry.VIEWS`): the
``Constant-Lightness Clip`` (:mod:`ocio_thinfilm.lut.clip_lut`) and the baselines it is
compared with, ``Channel Clamp`` and ``ACES Gamut Compression``, and ``Raw``.

- :func:`view_linear_transform` -- CIE-XYZ-D65 -> display-linear RGB in [0, 1];
- :func:`view_transform` -- CIE-XYZ-D65 -> display-encoded RGB.
"""

from __future__ import annotations

from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.compress_lut import compress_lut
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
    """CIE-XYZ-D65 -> display-linear RGB in [0, 1] for ``view`` (not for Raw).

    ``Constant-Lightness Clip``: :func:`ocio_thinfilm.lut.clip_lut.clip_transform`
    (Smits & Meyer 1990, Section 3.2). ``Channel Clamp``: the display matrix, then a
    clamp of each channel to [0, 1]. ``ACES Gamut Compression``: the display matrix,
    OCIO's ACES 1.3 reference gamut compression, then the clamp. The baselines limit
    XYZ to +-1e6 first (:func:`ocio_thinfilm.lut.ocio_ops.finite_limit_transform`).

    Parameters
    ----------
    display : str
        A display of :data:`ocio_thinfilm.registry.DISPLAYS`.
    view : str
        ``"Constant-Lightness Clip"``, ``"Channel Clamp"`` or
        ``"ACES Gamut Compression"``.
    size : int, optional
        Edge length of the clip's Lut3Ds, in [9, 129] (default 65).

    Returns
    -------
    PyOpenColorIO.GroupTransform
        Input CIE XYZ with the D65 perfect reflector at Y = 1, output display-linear
        RGB (RGB = 1 the display white).

    Raises
    ------
    ValueError
        For an unknown display or view (``Raw`` included).

    Examples
    --------
    An 18 % grey of D65 is (0.18, 0.18, 0.18) in every view; the sRGB colour
    (1.2, 0.5, -0.1), given as XYZ, is clamped per channel by ``Channel Clamp`` and
    keeps its luminance Y = 0.2126 * 1.2 + 0.7152 * 0.5 - 0.0722 * 0.1 = 0.6055
    through the constant-lightness clip:

    >>> import numpy as np
    >>> from ocio_thinfilm.colour import colorimetry
    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> px = [0.18 * np.array([0.95047, 1.0, 1.08883]),
    ...       colorimetry.RGB_to_XYZ([1.2, 0.5, -0.1], "sRGB")]
    >>> apply(view_linear_transform("sRGB", "Channel Clamp"), px).astype(float).round(3).tolist()
    [[0.18, 0.18, 0.18], [1.0, 0.5, 0.0]]
    >>> out = apply(view_linear_transform("sRGB", "Constant-Lightness Clip"), px)
    >>> round(float(out[1] @ [0.2126, 0.7152, 0.0722]), 2)
    0.61
    >>> view_linear_transform("sRGB", "Raw")
    Traceback (most recent call last):
    ...
    ValueError: view must be one of (...), got 'Raw'
    """
    check_display(display)
    if view == "Constant-Lightness Clip":
        return clip_transform(display, size)
    if view == "Constant-Lightness Compress":
        return group(compress_lut(display, clip_size=size).transforms()
                     + [working_decoding_transform()])
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
    raise ValueError(f"view must be one of {VIEWS[:-1]}, got {view!r}")


def view_transform(display: str, view: str, size: int = CLIP_SIZE):
    """OCIO transform CIE-XYZ-D65 -> display-encoded RGB for ``view`` in :data:`VIEWS`.

    ``Raw`` passes values through unchanged (an empty group). The constant-lightness
    clip's second LUT ends in sRGB code values: decoded, then the display's encoding
    (OCIO's optimiser removes the pair for the sRGB-encoded displays).

    The other views are :func:`view_linear_transform` followed by
    :func:`ocio_thinfilm.lut.display_transforms.display_encoding_transform`.

    Parameters
    ----------
    display : str
        A display of :data:`ocio_thinfilm.registry.DISPLAYS`.
    view : str
        A view of :data:`ocio_thinfilm.registry.VIEWS`.
    size : int, optional
        Edge length of the clip's Lut3Ds, in [9, 129] (default 65).

    Returns
    -------
    PyOpenColorIO.GroupTransform
        Input CIE XYZ with the D65 perfect reflector at Y = 1; output display code
        values in [0, 1] (``Raw``: the input).

    Raises
    ------
    ValueError
        For an unknown display or view.

    References
    ----------
    Smits & Meyer (1990), Section 3.2 (the constant-lightness clip); IEC 61966-2-1
    and ITU-R BT.1886 (the display encodings).

    Examples
    --------
    18 % grey encodes to sRGB code 1.055 * 0.18 ** (1 / 2.4) - 0.055 = 0.461 and the
    clamped (1.0, 0.5, 0.0) to (1.0, 0.735, 0.0); ``Raw`` returns its input:

    >>> import numpy as np
    >>> from ocio_thinfilm.colour import colorimetry
    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> px = [0.18 * np.array([0.95047, 1.0, 1.08883]),
    ...       colorimetry.RGB_to_XYZ([1.2, 0.5, -0.1], "sRGB")]
    >>> apply(view_transform("sRGB", "Channel Clamp"), px).astype(float).round(3).tolist()
    [[0.461, 0.461, 0.461], [1.0, 0.735, 0.0]]
    >>> bool(np.array_equal(apply(view_transform("sRGB", "Raw"), px), np.float32(px)))
    True
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
    if view == "Constant-Lightness Compress":
        soft = compress_lut(display, clip_size=size)
        return group(soft.transforms() + [working_decoding_transform(),
                                          display_encoding_transform(display)],
                     name=soft.name, id=transform_id("Gamut_Map", soft.name))
    return group([view_linear_transform(display, view, size),
                  display_encoding_transform(display)])
