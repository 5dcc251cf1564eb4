"""The views of every display as OCIO transforms: CIE-XYZ-D65 -> display code values.

The views are the registry's (:data:`ocio_thinfilm.registry.VIEWS`): the
``Constant-Lightness Clip`` (:mod:`ocio_thinfilm.lut.clip_lut`) and the baselines it is
compared with, ``Channel Clamp`` and ``ACES Gamut Compression``, and ``Raw``.

- :func:`view_linear_transform` -- CIE-XYZ-D65 -> display-linear RGB in [0, 1];
- :func:`view_transform` -- CIE-XYZ-D65 -> display-encoded RGB;
- :func:`hdr_scaled` -- an SDR view's chain as the view of an HDR display.

HDR displays (:data:`ocio_thinfilm.registry.HDR_DISPLAYS`) show the reference white Y = 1
at 203 cd/m2 and their volume is the gamut's RGB parallelepiped up to k = peak / 203
(1000 / 203). Every view here is scale-covariant, ``view_k(X) = k view_1(X / k)``: the
clip's ray towards the grey of the same Y and its faces scale with k (Smits & Meyer
1990, Section 3.2), a per-channel clamp to [0, k] and ACES gamut compression (degree
1 homogeneous) too. So an HDR view is the SDR view of its gamut (the same LUT files)
between two exact scales, and a colour brighter than the peak white is the peak white.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.clip_lut import (
    CLIP_SIZE,
    clip_lut,
    clip_transform,
    working_decoding_transform,
)
from ocio_thinfilm.lut.compress_lut import compress_lut
from ocio_thinfilm.lut.display_transforms import (
    aces_gamut_compression_transform,
    display_encoding_transform,
    display_matrix_transform,
    hdr_encoding_transform,
)
from ocio_thinfilm.lut.ocio_ops import finite_limit_transform, group, transform_id

__all__ = ["LINEAR_VIEWS", "LUT_VIEWS", "view_linear_transform", "view_transform", "hdr_scaled"]


#: HLG (ITU-R BT.2100, Table 5): the OOTF's system gamma for a 1000 cd/m2 peak and the
#: scene-linear range of OCIO's built-in HLG display transform (E in [0, 3]).
HLG_GAMMA = 1.2
HLG_E_MAX = 3.0
#: The luminance weights of BT.2100's OOTF (Table 5, Y_S = 0.2627 R + 0.6780 G + 0.0593 B)
#: as OCIO's ``FIXED_FUNCTION_REC2100_SURROUND`` applies them (float32 constants, on the
#: CPU and in its GLSL alike).
HLG_LUMA = np.array([0.2627, 0.6780, 0.0593], dtype=np.float32).astype(np.float64)
#: Scale of X and Z in :func:`_hlg_luma_chart` (a power of two: exact in float32 and in
#: the 12 decimals of :func:`ocio_thinfilm.lut.ocio_ops.matrix`).
HLG_CHART_XZ = 2.0**-12


def _hlg_luma_chart(a: float) -> np.ndarray:
    """Return the matrix N taking CIE XYZ to the vector v that ``REC2100_SURROUND`` scales.

    With HLG_LUMA . v = a Y exactly and v_0 = p X, v_2 = p Z (p = :data:`HLG_CHART_XZ`).

    The OOTF multiplies all three channels by the same function of HLG_LUMA . v, so
    any N with that luminance row gives the same scaled XYZ as the BT.2020 RGB of the
    built-in display transform (whose luminance is Y). Through the BT.2020 matrix a
    colour with a large X or Z and a small Y (the XYZ (1e4, 0, 1) of an imaginary
    colour) has RGB channels of 1e4 whose weighted sum cancels, and the float32
    round-off of that sum and of the matrix back (1e-3 there) would become its
    scene-light Y, which the clip keeps: a dim colour whose size depends on the
    processor's rounding (CPU or GPU). With X and Z scaled down by p before they enter
    the sum, that round-off shrinks by p (to 1e-6 of X).
    """
    p = HLG_CHART_XZ
    w0, w1, w2 = (float(w) for w in HLG_LUMA)
    return np.array(
        [
            [p, 0.0, 0.0],
            [-w0 * p / w1, a / w1, -w2 * p / w1],
            [0.0, 0.0, p],
        ]
    )


def _hlg_scene_ops(entry: registry.HDRDisplay, inverse: bool = False) -> list:
    """HLG display light -> scene light (or back), as OCIO's built-in HLG display does it.

    The built-in is ``DISPLAY - CIE-XYZ-D65_to_REC.2100-HLG-1000nit``: the BT.2100 inverse OOTF
    (``FIXED_FUNCTION_REC2100_SURROUND``, each pixel scaled by Y ** (1 / gamma - 1) of
    its luminance Y in units where the peak is E_MAX ** gamma), then / E_MAX: the HLG
    signal's parallelepiped [0, 1] is the SDR gamut's.

    The way in starts with :func:`ocio_thinfilm.lut.ocio_ops.finite_limit_transform`
    (components limited to +-1e6, as every SDR view starts; +-Inf and NaN become
    finite before the OOTF, which would give NaN or Inf for them) and applies the
    OOTF to XYZ through :func:`_hlg_luma_chart` (luminance exact, no cancellation
    between large channels). ``inverse``: the OOTF way back, from display-linear RGB
    of the chain (in [0, 1]) to display-linear RGB (1 = 203 cd/m2).
    """
    ocio = ocio_ops.module()
    a = HLG_E_MAX**HLG_GAMMA * registry.HDR_REFERENCE_WHITE / entry.peak
    if not inverse:
        N = _hlg_luma_chart(a)
        return [
            finite_limit_transform(),
            ocio_ops.matrix(N),
            ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_REC2100_SURROUND, [1.0 / HLG_GAMMA]),
            ocio_ops.matrix(reproducible.inv3(N) * a / HLG_E_MAX),
        ]
    return [
        ocio_ops.matrix(np.eye(3) * HLG_E_MAX),
        ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_REC2100_SURROUND, [HLG_GAMMA]),
        ocio_ops.matrix(np.eye(3) / a),
    ]


def hdr_scaled(display: registry.DisplayLike, transforms: list) -> list:
    """Return an SDR view's chain as the HDR display's.

    The SDR view's chain (CIE-XYZ-D65 -> display-linear RGB in [0, 1] of the HDR display's
    gamut, a list of OCIO transforms) as the HDR display's, ending in display-linear RGB in
    units of the reference white (203 cd/m2).

    PQ: XYZ scaled by 1 / k, the chain, RGB scaled by k, k = peak / 203 (output in
    [0, k]): exact for the scale-covariant views (module docstring). HLG: the display's
    volume in display light is the BT.2100 OOTF of the signal's parallelepiped, and the
    OOTF scales each pixel by a function of its Y only, so it maps the constant-Y ray
    towards the grey onto the same ray of the scene light: the chain runs in HLG scene
    light (:func:`_hlg_scene_ops`, the built-in display transform's own inverse OOTF),
    between the inverse OOTF and the OOTF (exact above OCIO's minimum luminance of the
    OOTF, 1e-4 of E_MAX ** gamma, 0.027 cd/m2). Either way the peak white stays, colours
    brighter become it, and the views keep Y where the SDR one does.

    Parameters
    ----------
    display : str or registry display
        A display of :data:`ocio_thinfilm.registry.HDR_DISPLAYS` or its name.
    transforms : list
        The chain for its gamut (``display.gamut``).

    Returns
    -------
    list
        PQ: ``[MatrixTransform(1 / k), *transforms, MatrixTransform(k)]``.

    References
    ----------
    ITU-R BT.2100-2 (2018), Table 5 (HLG OOTF); Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    The 1000 cd/m2 peak white (Y = 1000 / 203) stays itself through the Rec.2100-PQ
    clip and twice that becomes it:

    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> k = 1000 / 203
    >>> chain = hdr_scaled("Rec.2100-PQ", [view_linear_transform("Rec.2020",
    ...                                                          "Constant-Lightness Clip")])
    >>> out = apply(group(chain), [np.array([0.95047, 1.0, 1.08883]) * f for f in (k, 2 * k)])
    >>> (out / k).round(3).tolist()
    [[1.0, 1.0, 1.0], [1.0, 1.0, 1.0]]
    """
    entry = registry.as_display(display)
    if not isinstance(entry, registry.HDRDisplay):
        raise ParameterError(
            "display", f" must be one of {registry.HDR_DISPLAYS}, got {entry.name!r}"
        )
    if entry.transfer == "HLG":
        return _hlg_scene_ops(entry) + list(transforms) + _hlg_scene_ops(entry, True)
    k = entry.scale
    return [ocio_ops.matrix(np.eye(3) / k)] + list(transforms) + [ocio_ops.matrix(np.eye(3) * k)]


def _clip_linear(entry: registry.Display, size: int) -> ocio_ops.Transform:
    return clip_transform(entry, size)


def _compress_linear(entry: registry.Display, size: int) -> ocio_ops.Transform:
    return group(compress_lut(entry, clip_size=size).transforms() + [working_decoding_transform()])


# the baselines limit XYZ to +-LIMIT first: +-Inf (and NaN, which OCIO's CPU Range takes
# to the lower bound) stay finite through the matrices at every optimisation level
# (OPTIMIZATION_NONE does not compose them, so F32_MAX inputs overflowed to Inf - Inf = NaN)
def _clamp_linear(entry: registry.Display, size: int) -> ocio_ops.Transform:
    return group(
        [finite_limit_transform(), display_matrix_transform(entry), ocio_ops.range_(0.0, 1.0)]
    )


def _aces_linear(entry: registry.Display, size: int) -> ocio_ops.Transform:
    return group(
        [
            finite_limit_transform(),
            display_matrix_transform(entry),
            aces_gamut_compression_transform(),
            ocio_ops.range_(0.0, 1.0),
        ]
    )


#: View kind (:data:`ocio_thinfilm.registry.VIEW_KINDS`) -> ``f(display, size)``,
#: CIE-XYZ-D65 -> display-linear RGB in [0, 1] of an SDR display; ``None`` for the raw
#: view (no view transform).
LINEAR_VIEWS: dict[str, Callable[[registry.Display, int], ocio_ops.Transform] | None] = {
    "clip": _clip_linear,
    "compress": _compress_linear,
    "clamp": _clamp_linear,
    "aces": _aces_linear,
    "raw": None,
}
#: View kind -> its LUT chain (:func:`ocio_thinfilm.lut.clip_lut.clip_lut`,
#: :func:`ocio_thinfilm.lut.compress_lut.compress_lut`) for the views that end in sRGB code
#: values, named after the LUT; ``None`` for the views made of a linear transform.
LUT_VIEWS: dict[str, Callable[[registry.Display, int], Any] | None] = {
    "clip": lambda entry, size: clip_lut(entry, size),
    "compress": lambda entry, size: compress_lut(entry, clip_size=size),
    "clamp": None,
    "aces": None,
    "raw": None,
}


def view_linear_transform(
    display: registry.DisplayLike, view: str | registry.View, size: int = CLIP_SIZE
) -> ocio_ops.Transform:
    """CIE-XYZ-D65 -> display-linear RGB in [0, 1] for ``view`` (not for Raw).

    ``Constant-Lightness Clip``: :func:`ocio_thinfilm.lut.clip_lut.clip_transform`
    (Smits & Meyer 1990, Section 3.2). ``Channel Clamp``: the display matrix, then a
    clamp of each channel to [0, 1]. ``ACES Gamut Compression``: the display matrix,
    OCIO's ACES 1.3 reference gamut compression, then the clamp. The baselines limit
    XYZ to +-1e6 first (:func:`ocio_thinfilm.lut.ocio_ops.finite_limit_transform`).

    For an HDR display, the view of its gamut through :func:`hdr_scaled`: output in
    [0, k], k = peak / 203.

    Parameters
    ----------
    display : str or registry display
        A display of :data:`ocio_thinfilm.registry.ALL_DISPLAYS`.
    view : str or View
        A view of :data:`ocio_thinfilm.registry.VIEWS` (or its name) other than the raw
        one: its kind picks the transform (:data:`LINEAR_VIEWS`).
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
    ocio_thinfilm.checks.ParameterError: view must be one of (...), got 'Raw'
    """
    entry = registry.as_display(display)
    kind = registry.as_view(view, raw=False).kind
    if entry.hdr:
        return group(hdr_scaled(entry, [view_linear_transform(entry.gamut, view, size)]))
    linear = LINEAR_VIEWS[kind]
    assert linear is not None  # as_view refused the raw view
    return linear(entry.gamut, size)


def view_transform(
    display: registry.DisplayLike, view: str | registry.View, size: int = CLIP_SIZE
) -> ocio_ops.Transform:
    """OCIO transform CIE-XYZ-D65 -> display-encoded RGB for ``view`` in :data:`VIEWS`.

    ``Raw`` passes values through unchanged (an empty group). The constant-lightness
    clip's second LUT ends in sRGB code values: decoded, then the display's encoding
    (OCIO's optimiser removes the pair for the sRGB-encoded displays).

    The other views are :func:`view_linear_transform` followed by
    :func:`ocio_thinfilm.lut.display_transforms.display_encoding_transform`. An HDR
    display's views are its gamut's chains through :func:`hdr_scaled`, back to XYZ and
    :func:`ocio_thinfilm.lut.display_transforms.hdr_encoding_transform` (PQ or HLG).

    Parameters
    ----------
    display : str or registry display
        A display of :data:`ocio_thinfilm.registry.ALL_DISPLAYS`.
    view : str or View
        A view of :data:`ocio_thinfilm.registry.VIEWS` (or its name).
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
    entry = registry.as_display(display)
    kind = registry.as_view(view).kind
    if kind == "raw":
        return group([])
    if entry.hdr:
        return group(
            [
                view_linear_transform(entry, view, size),
                display_matrix_transform(entry.gamut, inverse=True),
                hdr_encoding_transform(entry),
            ]
        )
    make_lut = LUT_VIEWS[kind]
    if make_lut is not None:
        # the LUT chain ends in sRGB code values: decoded, then the display's encoding
        lut = make_lut(entry.gamut, size)
        return group(
            lut.transforms() + [working_decoding_transform(), display_encoding_transform(entry)],
            name=lut.name,
            id=transform_id("Gamut_Map", lut.name),
        )
    return group([view_linear_transform(entry, view, size), display_encoding_transform(entry)])
