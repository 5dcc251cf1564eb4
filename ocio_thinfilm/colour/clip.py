"""The constant-lightness parallelepiped clip (Smits & Meyer 1990, Section 3.2).

Stage 3 of the pipeline. An out-of-gamut colour is pulled along the ray towards
the grey of the same luminance Y on the display's neutral diagonal (R = G = B) until it
meets the display's RGB parallelepiped: Y is preserved, saturation drops. Two forms with
identical results, each defined at every edge (in-gamut colours unchanged bit for bit,
NaN pixels NaN, +-Inf finite and in gamut; docs/gamut_map.md, *Design notes*):

- :func:`clip_XYZ` -- the paper's form in CIE XYZ (outcodes against the six planes);
- :func:`clip_RGB` -- the faster form for colours in the display's linear RGB.

The clip is exactly U o L along the same ray (what the baked LUTs of
:mod:`ocio_thinfilm.lut.clip_lut` rely on; a test checks it):

- :func:`clip_black_faces_RGB` -- L, the clip against the faces through black only;
- :func:`clip_white_faces_RGB` -- U, the clip against the faces through white only;
- :func:`clip_white_faces_continued_RGB` -- U and its analytic continuation past white;
- :func:`luminance_weights` -- the display's row ``w`` with ``Y = w . RGB``.

Baselines for comparison: :func:`clamp_RGB` (per-channel clamp) and
:func:`aces_gamut_compress_RGB` (OCIO's ACES 1.3 reference gamut compression).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.colour import colorimetry

__all__ = [
    "DISPLAYS",
    "LIMIT",
    "NEUTRAL_TOLERANCE",
    "luminance_weights",
    "clip_XYZ",
    "clip_RGB",
    "clip_black_faces_RGB",
    "clip_white_faces_RGB",
    "clip_white_faces_continued_RGB",
    "in_gamut",
    "clamp_RGB",
    "aces_gamut_compress_RGB",
    "ACES_GAMUT_COMP13_PARAMS",
]

#: The display gamuts we ship, by the name used in the OCIO config (:mod:`.registry`).
DISPLAYS = registry.GAMUT_DISPLAYS

#: Magnitude to which components are limited before clipping (+-Inf included).
LIMIT = 1e100

#: OCIO ACES_GamutComp13 parameters: limits (cyan, magenta, yellow), thresholds
#: (cyan, magenta, yellow), power -- the ACES 1.3 reference gamut compression.
ACES_GAMUT_COMP13_PARAMS = (1.147, 1.264, 1.312, 0.815, 0.803, 0.880, 1.2)

#: Relative size of max(c) - Y below which a colour counts as neutral (a grey to
#: rounding: the luminance row sums to 1 only to a few ulps).
NEUTRAL_TOLERANCE = 1e-12


def _space(display: registry.DisplayLike) -> str:
    """Return the colorimetry's RGB space of ``display`` (the clip's gamut).

    A name as it is, an SDR display of the registry as its object.
    """
    if isinstance(display, (registry.Display, registry.HDRDisplay)):
        return registry.as_display(display, hdr=False).gamut.name
    return display


def _display_matrix(display: registry.DisplayLike) -> np.ndarray:
    """XYZ -> RGB of ``display`` (:func:`_space`)."""
    display = _space(display)
    if registry.colorimetry_of(display) is None:
        raise ParameterError("display", f" must be one of {DISPLAYS}, got {display!r}")
    return colorimetry.matrix_XYZ_to_RGB(display)


def luminance_weights(display: registry.DisplayLike) -> np.ndarray:
    """Return the row ``w`` with ``Y = w . RGB`` for ``display``'s linear RGB.

    RGB = 1, its white, has Y = 1: ``w`` is the second row of its RGB -> XYZ matrix.

    Parameters
    ----------
    display : str or registry display
        One of :data:`DISPLAYS` (or another RGB space of
        :data:`ocio_thinfilm.registry.RGB_COLORIMETRY`).

    Returns
    -------
    numpy.ndarray
        float64, (3,).

    Raises
    ------
    ValueError
        (:class:`~ocio_thinfilm.checks.ParameterError`) for an unknown display.

    Examples
    --------
    The Rec.709 weights of sRGB:

    >>> luminance_weights("sRGB").round(4).tolist()
    [0.2126, 0.7152, 0.0722]
    """
    return reproducible.inv3(_display_matrix(display))[1]


#: Pixels per block: the working set stays in cache, and results do not depend on
#: how an image is batched.
_CHUNK = 1 << 14


def _apply(values, name, kernel):
    """Run ``kernel`` on planar float64 (3, N) blocks of ``values``.

    Same shape and dtype out.

    Per block: NaN rows are noted and zeroed, components limited to +-LIMIT (so
    +-Inf is finite), the kernel runs on the three contiguous channel rows, NaN rows
    are put back as NaN.
    """
    a = np.asarray(values)
    if a.ndim == 0 or a.shape[-1] != 3:
        raise ValueError(f"{name} must have a last axis of length 3, got shape {a.shape}")
    dtype = a.dtype if a.dtype in (np.float32, np.float64) else np.float64
    flat = a.reshape(-1, 3)
    out = np.empty(flat.shape, dtype)
    for start in range(0, flat.shape[0], _CHUNK):
        work = np.ascontiguousarray(flat[start : start + _CHUNK].T, dtype=np.float64)
        nan_rows = np.isnan(work[0]) | np.isnan(work[1]) | np.isnan(work[2])
        np.nan_to_num(work, copy=False, nan=0.0)
        np.clip(work, -LIMIT, LIMIT, out=work)
        result = kernel(work)
        result[:, nan_rows] = np.nan
        out[start : start + _CHUNK] = result.T
    return out.reshape(a.shape)


def _fraction_to_boundary(values, grey):
    """Return where the ray from the grey to the colour first leaves the cube.

    The fraction ``t`` of the way from the grey to the colour at which the ray
    first leaves the cube (1 when it never does), and whether it is outside at all.

    ``values``: the three (N,) signed positions against the plane pairs (RGB);
    ``grey``: (N,), the grey's position, the same in every channel (the grey is on
    the neutral diagonal, R = G = B) and inside [0, 1]. Per plane pair this is the
    paper's intersection ``s`` written as ``t = 1 - s`` so that huge inputs do not
    cancel: ``t = (grey - bound) / (grey - value)``, only used where ``value`` is
    outside the slab and the grey inside, so ``|grey - value| > 0``; the smallest t
    is the intersection furthest from the colour.
    """
    t = np.ones_like(grey)
    outside = np.zeros(grey.shape, bool)
    for value in values:
        above = value > 1.0
        out_j = (value < 0.0) | above
        with np.errstate(divide="ignore", invalid="ignore"):
            t_j = (grey - above) / (grey - value)
        np.minimum(t, t_j, out=t, where=out_j)
        outside |= out_j
    return t, outside


def clip_RGB(RGB: npt.ArrayLike, display: registry.DisplayLike = "sRGB") -> np.ndarray:
    """Constant-lightness clip of display-linear RGB into the unit cube (Section 3.2).

    The ray test of the paper's Section 3.2 in the display's RGB, where the
    parallelepiped is the unit cube and the grey of luminance Y is (Y, Y, Y).

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB of ``display``, last axis 3 (RGB = 1 is its white).
    display : str or registry display
        One of :data:`DISPLAYS`.

    Returns
    -------
    numpy.ndarray
        The clipped RGB, same shape and dtype (float32 or float64).

    References
    ----------
    Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    In-gamut colours are unchanged; an out-of-gamut colour keeps its luminance:

    >>> clip_RGB([0.5, 0.4, 0.3]).tolist()
    [0.5, 0.4, 0.3]
    >>> w = colorimetry.RGB_to_XYZ(np.eye(3), "sRGB")[:, 1]  # luminance weights
    >>> out = clip_RGB([1.2, 0.5, -0.1])
    >>> bool(in_gamut(out)), bool(np.isclose(out @ w, np.dot([1.2, 0.5, -0.1], w)))
    (True, True)
    """
    luminance = luminance_weights(display)  # Y = luminance . RGB
    Y_white = luminance.sum()

    def kernel(rgb):
        Y = luminance[0] * rgb[0] + luminance[1] * rgb[1] + luminance[2] * rgb[2]
        grey = np.clip(Y / Y_white, 0.0, 1.0)
        t, outside = _fraction_to_boundary(rgb, grey)
        clipped = np.clip(grey + t * (rgb - grey), 0.0, 1.0)
        out = np.where(outside, clipped, rgb)
        out[:, Y <= 0.0] = 0.0
        out[:, Y >= Y_white] = 1.0
        return out

    return _apply(RGB, "RGB", kernel)


def clip_XYZ(XYZ: npt.ArrayLike, display: registry.DisplayLike = "sRGB") -> np.ndarray:
    """Constant-lightness clip of D65-relative XYZ into ``display``'s gamut.

    The paper's XYZ form. Returns XYZ, same shape and dtype.

    1. Outcodes: for each plane pair ``n_j . X = 0`` and ``n_j . X = 1`` (``n_j`` the
       rows of the XYZ -> RGB matrix) the colour is below, between or above.
    2. Grey point on the neutral diagonal at the colour's Y: ``G = W Y / Y_W``,
       ``W`` the display white (RGB = 1), not x = y = z. Its position against
       every plane pair is ``Y / Y_W``.
    3. The ray from X towards G meets each plane the colour is outside of; the
       intersection furthest from X (smallest remaining fraction t) is the result.
    """
    M = _display_matrix(display)
    white = reproducible.matmul(reproducible.inv3(M), np.ones(3))

    def kernel(xyz):
        Y = xyz[1].copy()
        s = np.clip(Y / white[1], 0.0, 1.0)
        planes = [n[0] * xyz[0] + n[1] * xyz[1] + n[2] * xyz[2] for n in M]
        t, outside = _fraction_to_boundary(planes, s)
        grey = s * white[:, None]
        out = np.where(outside, grey + t * (xyz - grey), xyz)
        out[:, Y <= 0.0] = 0.0
        out[:, Y >= white[1]] = white[:, None]
        return out

    return _apply(XYZ, "XYZ", kernel)


def in_gamut(RGB: npt.ArrayLike, tolerance: float = 0.0) -> np.ndarray | np.bool_:
    """Return True where all channels lie in [-tolerance, 1 + tolerance].

    The paper's first step of the clip (Smits & Meyer 1990, Section 3.2) in the
    display's RGB: a colour is inside the parallelepiped when it lies between both
    planes of every pair, i.e. inside the unit cube. Points on a face are inside.

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB (RGB = 1 is the display white), last axis 3.
    tolerance : float, optional
        Allowance outside [0, 1] on every channel (default 0: exact).

    Returns
    -------
    numpy.ndarray or numpy.bool_
        bool, the shape of ``RGB`` without its last axis. A NaN channel is never
        inside (every comparison with NaN is False).

    References
    ----------
    Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    >>> bool(in_gamut([0.5, 0.5, 0.5])), bool(in_gamut([1.2, 0.0, 0.0]))
    (True, False)
    >>> in_gamut([[0.0, 1.0, 0.5], [1.0005, 0.0, 0.0]]).tolist()
    [True, False]
    >>> bool(in_gamut([1.0005, 0.0, 0.0], tolerance=1e-3))
    True
    """
    a = np.asarray(RGB)
    return np.all((a >= -tolerance) & (a <= 1.0 + tolerance), axis=-1)


def clip_black_faces_RGB(RGB: npt.ArrayLike, display: registry.DisplayLike) -> np.ndarray:
    """L: the clip against the faces R, G, B >= 0 only (float64, (N, 3) display RGB).

    ``Y <= 0`` gives black; otherwise the colour moves towards the grey of its Y until
    its smallest channel is 0 (unchanged when no channel is negative).

    The ray of Smits & Meyer (1990), Section 3.2, against the three faces through
    black: with ``Y = w . RGB`` (``w`` the display's luminance row) and
    ``lo = min(R, G, B) < 0`` the result is ``Y + t (RGB - Y)`` with
    ``t = Y / (Y - lo)``, so its smallest channel is 0 and its luminance is Y.
    Channels may still exceed 1 (that is :func:`clip_white_faces_RGB`'s part).

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB of ``display`` (RGB = 1 its white), last axis 3.
    display : str or registry display
        One of :data:`DISPLAYS`.

    Returns
    -------
    numpy.ndarray
        float64, shape of ``RGB``. Non-finite inputs give non-finite rows (no
        warning).

    References
    ----------
    Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    In-gamut colours are unchanged; (1.2, 0.5, -0.1) (Y = 0.6055 with the Rec.709
    weights) moves with t = 0.6055 / 0.7055 to (1.116, 0.515, 0), keeping Y; a colour
    with Y <= 0 is black:

    >>> out = clip_black_faces_RGB([[0.5, 0.4, 0.3], [1.2, 0.5, -0.1],
    ...                             [-0.1, -0.2, 0.3]], "sRGB")
    >>> out.round(2).tolist()
    [[0.5, 0.4, 0.3], [1.12, 0.51, 0.0], [0.0, 0.0, 0.0]]
    >>> w = colorimetry.RGB_to_XYZ(np.eye(3), "sRGB")[:, 1]  # luminance weights
    >>> bool(np.isclose(out[1] @ w, np.dot([1.2, 0.5, -0.1], w)))
    True
    """
    rgb = np.asarray(RGB, dtype=np.float64)
    with np.errstate(all="ignore"):  # non-finite inputs give non-finite rows, no warning
        Y = reproducible.matmul(rgb, luminance_weights(display))
        lo = rgb.min(axis=-1)
        t = np.where(lo < 0.0, Y / (Y - lo), 1.0)
        out = Y[..., None] + t[..., None] * (rgb - Y[..., None])
    out[Y <= 0.0] = 0.0
    return out


def clip_white_faces_RGB(RGB: npt.ArrayLike, display: registry.DisplayLike) -> np.ndarray:
    """U = C o L o C with C(c) = 1 - c: the clip against R, G, B <= 1 only.

    C maps the display white to black and the faces R, G, B = 1 to the faces through
    black, and Y(C(c)) = Y_W - Y(c): the ray of :func:`clip_black_faces_RGB` in the
    complement is the paper's ray towards the same grey (Smits & Meyer 1990,
    Section 3.2), so U keeps Y, brings the largest channel of an out-of-gamut colour
    to 1 and gives white for Y >= Y_W. Applied after L, the composition is
    :func:`clip_RGB`.

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB of ``display``, last axis 3.
    display : str or registry display
        One of :data:`DISPLAYS` (its white has Y = 1).

    Returns
    -------
    numpy.ndarray
        float64, shape of ``RGB``.

    References
    ----------
    Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    In-gamut colours are unchanged; (1.2, 0.5, 0.1) keeps Y = 0.62 with R = 1
    (the complement (-0.2, 0.5, 0.9) has Y = 0.38, t = 0.38 / 0.58); a colour brighter
    than white is white:

    >>> clip_white_faces_RGB([[0.5, 0.4, 0.3], [1.2, 0.5, 0.1],
    ...                       [1.1, 1.2, 0.9]], "sRGB").round(2).tolist()
    [[0.5, 0.4, 0.3], [1.0, 0.54, 0.28], [1.0, 1.0, 1.0]]
    """
    return 1.0 - clip_black_faces_RGB(1.0 - np.asarray(RGB, dtype=np.float64), display)


def clip_white_faces_continued_RGB(RGB: npt.ArrayLike, display: registry.DisplayLike) -> np.ndarray:
    """U of :func:`clip_white_faces_RGB` for Y <= 1, continued analytically above.

    For c >= 0 with Y = w . c <= 1, U(c) = Y + t (c - Y) with t = (1 - Y) / (max c - Y)
    where max c > 1 (else c): the paper's ray (Section 3.2) brought to the face
    through white. The same formula for Y > 1 (t < 0) is its smooth continuation past
    white, which the white pass stores at its nodes brighter than white: the cells that
    straddle Y = 1 then interpolate a smooth function instead of a kink towards white
    (the pre-clip keeps the pass's inputs at Y <= 1). At Y = 1 both give white.

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB of ``display`` with no negative channel (after L), last
        axis 3.
    display : str or registry display
        One of :data:`DISPLAYS`.

    Returns
    -------
    numpy.ndarray
        float64, shape of ``RGB``: U(c) for Y <= 1, its continuation above; a neutral
        colour past white gives white exactly.

    References
    ----------
    Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    >>> rgb = np.array([[0.5, 0.4, 0.3], [1.2, 0.5, 0.1], [2.0, 1.0, 0.5]])
    >>> bool(np.allclose(clip_white_faces_continued_RGB(rgb[:2], "sRGB"),
    ...                  clip_white_faces_RGB(rgb[:2], "sRGB")))
    True
    >>> out = clip_white_faces_continued_RGB(rgb[2:], "sRGB")  # Y = 1.18: past white
    >>> bool(out[0, 0] == 1.0 and np.all(out[0, 1:] > 1.0))
    True
    """
    rgb = np.asarray(RGB, dtype=np.float64)
    Y = reproducible.matmul(rgb, luminance_weights(display))
    top = rgb.max(axis=-1)
    # a neutral colour (max c - Y at rounding level) has every channel as its largest,
    # and the largest always goes to 1: past white a grey goes to white, not to 0 / 0
    # (whose rounding differs between CPUs)
    neutral = top - Y <= NEUTRAL_TOLERANCE * np.maximum(np.abs(top), 1.0)
    with np.errstate(all="ignore"):
        t = np.where((top > 1.0) & ~neutral, (1.0 - Y) / (top - Y), 1.0)
    out = Y[..., None] + t[..., None] * (rgb - Y[..., None])
    return np.where(((top > 1.0) & neutral)[..., None], 1.0, out)


def clamp_RGB(RGB: npt.ArrayLike) -> np.ndarray:
    """Baseline: the per-channel clamp to [0, 1] (NaN stays NaN).

    Each channel is clamped on its own, so an out-of-gamut colour changes luminance
    and hue; the comparison for the constant-lightness clip (:func:`clip_RGB`).

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB, any shape (usually last axis 3).

    Returns
    -------
    numpy.ndarray
        ``numpy.clip(RGB, 0, 1)``: same shape and dtype as the input array (float64
        for lists of Python floats).

    Examples
    --------
    >>> clamp_RGB([1.2, 0.5, -0.1]).tolist()
    [1.0, 0.5, 0.0]
    >>> clamp_RGB([float("nan"), 0.5, 2.0]).tolist()
    [nan, 0.5, 1.0]
    """
    return np.clip(np.asarray(RGB), 0.0, 1.0)


def aces_gamut_compress_RGB(RGB: npt.ArrayLike) -> np.ndarray:
    """Baseline: OCIO's ACES 1.3 reference gamut compression, then a clamp to [0, 1].

    The compression (``ACES_GamutComp13``) is applied to display-linear RGB, then the clamp.
    Runs through an OCIO CPU processor; returns float32.

    Per pixel, the achromatic value ``ach = max(R, G, B)`` is kept and each channel's
    distance ``d = (ach - c) / |ach|`` above its threshold ``thr`` is compressed by
    ``thr + (d - thr) / (1 + ((d - thr) / s) ** p) ** (1 / p)``, with the scale ``s``
    chosen so that the limit distance ``lim`` maps to 1 (the gamut boundary, c = 0).
    Parameters :data:`ACES_GAMUT_COMP13_PARAMS`: limits (1.147, 1.264, 1.312) and
    thresholds (0.815, 0.803, 0.880) for R, G, B (cyan, magenta, yellow distances),
    power p = 1.2. It holds max(RGB), not luminance, so unlike :func:`clip_RGB` it
    changes Y.

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB, last axis 3. Not modified. +-Inf are taken as +-3e38;
        huge negative components are handled by scaling (see the code's comments).

    Returns
    -------
    numpy.ndarray
        float32, shape of ``RGB``, in [0, 1]; a pixel with a NaN channel gives NaN.

    References
    ----------
    Academy of Motion Picture Arts and Sciences (2021). ACES Reference Gamut
    Compression Specification, ACES 1.3 (from the ACES Gamut Mapping Virtual Working
    Group); OpenColorIO ``FIXED_FUNCTION_ACES_GAMUT_COMP_13``.

    Examples
    --------
    Distances below every threshold are unchanged; a channel at its limit distance
    (G = 1 - 1.264, B = 1 - 1.312 for max = 1) lands on 0; the blue distance 1.1
    (B = -0.1) compresses to 0.97845 by the formula above, B = 0.0216:

    >>> [round(float(v), 4) for v in aces_gamut_compress_RGB([0.5, 0.4, 0.3])]
    [0.5, 0.4, 0.3]
    >>> [round(float(v), 4) + 0.0 for v in aces_gamut_compress_RGB([1.0, -0.264, -0.312])]
    [1.0, 0.0, 0.0]
    >>> [round(float(v), 4) for v in aces_gamut_compress_RGB([1.0, 0.5, -0.1])]
    [1.0, 0.5, 0.0216]
    >>> str(aces_gamut_compress_RGB([0.5, 0.4, 0.3]).dtype)
    'float32'
    """
    import PyOpenColorIO as ocio

    transform = ocio.FixedFunctionTransform(
        ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13, list(ACES_GAMUT_COMP13_PARAMS)
    )
    cpu = ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()
    # On a copy (never the caller's array). The compression works on distances
    # d = (max - c) / |max|, so it commutes with a positive scale: each pixel is scaled
    # to max |c| = 1 and back, and d is capped at 1e6 (the curve is then within 1e-7
    # of its limit), which keeps OCIO's float32 arithmetic from overflowing to NaN
    # for huge (<= -1e30) components. Infinities are taken as +-3e38; NaN stays NaN.
    a = np.array(RGB, dtype=np.float64, copy=True).reshape(-1, 3)
    np.clip(a, -3e38, 3e38, out=a)
    ach = np.max(a, axis=1, keepdims=True)
    with np.errstate(invalid="ignore"):
        np.maximum(a, ach - 1e6 * np.abs(ach), out=a, where=ach != 0)
    scale = np.max(np.abs(a), axis=1, keepdims=True)
    scale = np.where(np.isfinite(scale) & (scale > 0), scale, 1.0)
    unit = np.ascontiguousarray(a / scale, dtype=np.float32)
    cpu.applyRGB(unit)
    out = np.clip(unit.astype(np.float64) * scale, 0.0, 1.0).astype(np.float32)
    return out.reshape(np.shape(RGB))
