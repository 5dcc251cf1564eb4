"""A display's colorimetry and encoding as OCIO transforms (from the one registry).

- :func:`display_matrix_transform` -- CIE-XYZ-D65 -> display-linear RGB (or back);
- :func:`display_encoding_transform` -- display-linear RGB
  -> display code values (the inverse EOTF, as the ACES OCIO configs' display spaces);
- :func:`hdr_encoding_transform` -- an HDR display's CIE-XYZ-D65 (Y = 1 at 203 cd/m2)
  -> code values (PQ or HLG, OCIO's built-in display transforms);
- :func:`display_colorspace_transform` -- any display's CIE-XYZ-D65 -> code values
  (its display colour space);
- :func:`code_limit` -- the largest code value an SDR display's colour space passes
  (the code of display light :data:`~ocio_thinfilm.lut.ocio_ops.LIMIT`);
- :func:`aces_gamut_compression_transform` -- OCIO's ACES 1.3 reference gamut
  compression, the baseline view the clip is compared with.
"""

from __future__ import annotations

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import ocio_ops

__all__ = [
    "display_matrix_transform",
    "display_encoding_transform",
    "hdr_encoding_transform",
    "display_colorspace_transform",
    "code_limit",
    "aces_gamut_compression_transform",
]


def display_matrix_transform(
    display: registry.DisplayLike, inverse: bool = False
) -> ocio_ops.Transform:
    """CIE-XYZ-D65 -> display-linear RGB (or back) as an OCIO MatrixTransform.

    The matrix of :func:`ocio_thinfilm.colour.colorimetry.matrix_XYZ_to_RGB` (the
    inverse normalised primary matrix, RGB = 1 at the display white), rounded to 12
    decimals; the XYZ -> monitor RGB step of Smits & Meyer (1990), Section 2.1.

    Parameters
    ----------
    display : str or registry display
        A display of :data:`ocio_thinfilm.registry.DISPLAYS`.
    inverse : bool, optional
        Return display-linear RGB -> CIE XYZ instead.

    Returns
    -------
    PyOpenColorIO.MatrixTransform
        XYZ with the D65 perfect reflector at Y = 1 on the XYZ side; no offset.

    Raises
    ------
    ValueError
        For an unknown display.

    Examples
    --------
    The D65 white (0.95047, 1, 1.08883) is RGB = 1, and back:

    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> rgb = apply(display_matrix_transform("sRGB"), [0.95047, 1.0, 1.08883])
    >>> rgb.astype(float).round(3).tolist()
    [1.0, 1.0, 1.0]
    >>> xyz = apply(display_matrix_transform("sRGB", inverse=True), [1.0, 1.0, 1.0])
    >>> xyz.astype(float).round(3).tolist()
    [0.95, 1.0, 1.089]
    """
    entry = registry.as_display(display, hdr=False)
    M = colorimetry.matrix_XYZ_to_RGB(entry.colorimetry)
    return ocio_ops.matrix(reproducible.inv3(M) if inverse else M)


def display_encoding_transform(display: registry.DisplayLike) -> ocio_ops.Transform:
    """Display-linear RGB -> display code values (the display's inverse EOTF).

    For the sRGB-encoded displays (sRGB, Display P3) the IEC 61966-2-1 piecewise
    curve, ``12.92 L`` up to L = 0.0031308 and ``1.055 L ** (1 / 2.4) - 0.055`` above
    (OCIO ``ExponentWithLinearTransform``, gamma 2.4, offset 0.055, inverse); for
    Rec.2020 the BT.1886 pure power ``L ** (1 / 2.4)``, negative values clamped to 0
    (OCIO ``ExponentTransform``, inverse), as in the ACES OCIO configs' display spaces.

    Parameters
    ----------
    display : str or registry display
        A display of :data:`ocio_thinfilm.registry.DISPLAYS` or its name (its
        ``encoding`` gives the curve).

    Returns
    -------
    PyOpenColorIO.ExponentWithLinearTransform or PyOpenColorIO.ExponentTransform
        In the inverse direction (linear -> code values).

    Raises
    ------
    ValueError
        For an unknown display.

    References
    ----------
    IEC 61966-2-1:1999 (sRGB); ITU-R BT.1886 (2011), Reference electro-optical
    transfer function for flat panel displays.

    Examples
    --------
    Linear 0.18 is sRGB code 1.055 * 0.18 ** (1 / 2.4) - 0.055 = 0.4614 and BT.1886
    code 0.18 ** (1 / 2.4) = 0.4894:

    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> px = [0.0, 0.18, 1.0]
    >>> apply(display_encoding_transform("sRGB"), px).astype(float).round(3).tolist()
    [0.0, 0.461, 1.0]
    >>> apply(display_encoding_transform("Rec.2020"), px).astype(float).round(3).tolist()
    [0.0, 0.489, 1.0]
    """
    ocio = ocio_ops.module()
    entry = registry.as_display(display, hdr=False)
    gamma, offset = entry.encoding.gamma, entry.encoding.offset
    if offset is None:
        t = ocio.ExponentTransform([gamma, gamma, gamma, 1.0])
        t.setNegativeStyle(ocio.NEGATIVE_CLAMP)
    else:
        t = ocio.ExponentWithLinearTransform([gamma] * 3 + [1.0], [offset] * 3 + [0.0])
    t.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return t


#: OCIO's built-in ST 2084 inverse EOTF (linear, 1.0 = 100 cd/m2 -> PQ code), OCIO >= 2.1.
PQ_CURVE = "CURVE - LINEAR_to_ST-2084"


def hdr_encoding_transform(display: registry.DisplayLike) -> ocio_ops.Transform:
    """Return the transform from an HDR display's CIE-XYZ-D65 to its code values.

    CIE-XYZ-D65 is the display reference: Y = 1 at
    :data:`~ocio_thinfilm.registry.HDR_REFERENCE_WHITE` = 203 cd/m2.

    The matrix to the display's primaries scaled by 203 / 100 (OCIO's built-ins take
    1.0 as 100 cd/m2), a clamp to [0, 10000 cd/m2], then OCIO's built-ins (OCIO >= 2.1):
    the ST 2084 curve (:data:`PQ_CURVE`) for PQ, for HLG the registry entry's display
    transform (the BT.2100 HLG inverse EOTF for a 1000 cd/m2 peak) after the matrix
    back to XYZ, then a clamp of the codes to [0, 1]. The same code values as the registry
    entry's built-in display transform (the ACES configs' display colour spaces) of XYZ
    scaled by 203 / 100.

    Parameters
    ----------
    display : str or registry display
        A display of :data:`ocio_thinfilm.registry.HDR_DISPLAYS`.

    Returns
    -------
    PyOpenColorIO.GroupTransform

    Raises
    ------
    ValueError
        For a name that is not an HDR display of the registry.

    References
    ----------
    SMPTE ST 2084:2014; ITU-R BT.2100-2 (2018), Table 4 and 5; ITU-R BT.2408-7, HDR
    reference white 203 cd/m2.

    Examples
    --------
    The reference white Y = 1 is 203 cd/m2: PQ code 0.5807; the 1000 cd/m2 peak (Y =
    1000 / 203) is PQ code 0.7518:

    >>> import numpy as np
    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> white = np.array([0.95047, 1.0, 1.08883])
    >>> out = apply(hdr_encoding_transform("Rec.2100-PQ"), [white, white * 1000 / 203])
    >>> out.astype(float).round(4).tolist()
    [[0.5807, 0.5807, 0.5807], [0.7518, 0.7518, 0.7518]]
    """
    ocio = ocio_ops.module()
    entry = registry.as_display(display)
    if not isinstance(entry, registry.HDRDisplay):
        raise ParameterError(
            "display", f" must be one of {registry.HDR_DISPLAYS}, got {entry.name!r}"
        )
    unit = registry.HDR_REFERENCE_WHITE / registry.OCIO_XYZ_UNIT
    M = colorimetry.matrix_XYZ_to_RGB(entry.colorimetry)
    # the built-in curves are odd (OCIO >= 2.2 mirrors its half-float LUTs): a channel a
    # float32 round-off below 0 (a gamut face after a matrix pair that OPTIMIZATION_NONE
    # does not compose) would encode to a negative code, so the display RGB is clamped
    # to [0, 10000 cd/m2] (the range of ST 2084) first
    clamp = [ocio_ops.matrix(M * unit), ocio_ops.range_(0.0, 1e4 / registry.OCIO_XYZ_UNIT)]
    if entry.transfer == "PQ":
        return ocio_ops.group(clamp + [ocio.BuiltinTransform(PQ_CURVE)])
    # HLG: the built-in's own matrix brings the round-off back, so its odd curve can
    # still give a code a few 1e-4 below 0 at OPTIMIZATION_NONE: codes clamped to [0, 1]
    return ocio_ops.group(
        clamp
        + [
            ocio_ops.matrix(reproducible.inv3(M)),
            ocio.BuiltinTransform(entry.builtin),
            ocio_ops.range_(0.0, 1.0),
        ]
    )


def code_limit(display: registry.DisplayLike) -> float:
    """Return the code value of display-linear LIMIT through an SDR display's encoding.

    :data:`~ocio_thinfilm.lut.ocio_ops.LIMIT` is 1e6 times the display white. The encoding:
    IEC 61966-2-1's ``1.055 L ** (1 / 2.4) - 0.055`` for the sRGB-encoded displays,
    BT.1886's ``L ** (1 / 2.4)`` for Rec.2020.

    Parameters
    ----------
    display : str or registry display
        A display of :data:`ocio_thinfilm.registry.DISPLAYS` or its name.

    Returns
    -------
    float

    Raises
    ------
    ValueError
        For an unknown display or an HDR one (its codes are limited to [0, 1]).

    Examples
    --------
    >>> round(code_limit("sRGB"), 2), round(code_limit("Rec.2020"), 2)
    (333.57, 316.23)
    """
    entry = registry.as_display(display, hdr=False)
    gamma, offset = entry.encoding.gamma, entry.encoding.offset
    if offset is None:
        return float(ocio_ops.LIMIT ** (1.0 / gamma))
    return float((1.0 + offset) * ocio_ops.LIMIT ** (1.0 / gamma) - offset)


def display_colorspace_transform(display: registry.DisplayLike) -> ocio_ops.Transform:
    """CIE-XYZ-D65 (the display reference) -> code values of any display.

    Any display of :data:`ocio_thinfilm.registry.ALL_DISPLAYS`: the display matrix and
    encoding of an SDR display, :func:`hdr_encoding_transform` of an HDR one (the config's display
    colour spaces).

    An SDR display's code values end in a clamp to +-:func:`code_limit`, the codes of
    display light +-1e6 (no real pixel comes near it). OCIO applies a display colour
    space in reverse to convert from it (a display space as a view's input, or to
    CIE-XYZ-D65), and then the clamp comes first: code values of 1e30 or +-Inf would
    decode to +-Inf (1e30 ** 2.4 overflows float32) and the matrix to XYZ would turn
    Inf - Inf into NaN. Limited, they decode to at most 1e6, like every scene space's
    input (:func:`ocio_thinfilm.lut.ocio_ops.finite_limit_transform`); NaN counts as
    the lower bound, as in OCIO's Range on the CPU and the GPU. The clamp is last on
    the way from XYZ, so a view's decoding and the display's encoding still meet and
    cancel in OCIO's optimiser.

    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> apply(display_colorspace_transform("sRGB"), [0.95047, 1.0, 1.08883]).round(3).tolist()
    [1.0, 1.0, 1.0]
    """
    entry = registry.as_display(display)
    if entry.hdr:
        return hdr_encoding_transform(entry)
    c = code_limit(entry)
    return ocio_ops.group(
        [
            display_matrix_transform(entry),
            display_encoding_transform(entry),
            ocio_ops.range_(-c, c),
        ]
    )


def aces_gamut_compression_transform() -> ocio_ops.Transform:
    """OCIO's ACES 1.3 reference gamut compression, the baseline view's core.

    ``FixedFunctionTransform(FIXED_FUNCTION_ACES_GAMUT_COMP_13)`` with
    :data:`ocio_thinfilm.colour.clip.ACES_GAMUT_COMP13_PARAMS` (limits 1.147, 1.264,
    1.312; thresholds 0.815, 0.803, 0.880; power 1.2), applied here to display-linear
    RGB. Per pixel it keeps max(R, G, B) and compresses each channel's distance
    ``(max - c) / |max|`` beyond its threshold so that the limit distance lands on
    the gamut boundary (c = 0); no clamp (the views add one). Needs
    ``ocio_profile_version`` 2.1.

    Returns
    -------
    PyOpenColorIO.FixedFunctionTransform

    References
    ----------
    Academy of Motion Picture Arts and Sciences (2021). ACES Reference Gamut
    Compression Specification, ACES 1.3.

    See Also
    --------
    ocio_thinfilm.colour.clip.aces_gamut_compress_RGB : the same with a clamp, in
        NumPy.

    Examples
    --------
    Distances below the thresholds are unchanged; channels at their limit distances
    (G = 1 - 1.264, B = 1 - 1.312 for max = 1) land on 0:

    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> out = apply(aces_gamut_compression_transform(),
    ...             [[0.5, 0.4, 0.3], [1.0, -0.264, -0.312]])
    >>> (out.astype(float).round(4) + 0.0).tolist()
    [[0.5, 0.4, 0.3], [1.0, 0.0, 0.0]]
    """
    ocio = ocio_ops.module()
    return ocio.FixedFunctionTransform(
        ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13, list(clip.ACES_GAMUT_COMP13_PARAMS)
    )
