"""A soft constant-lightness gamut compression: the paper's ray, a smooth curve on it.

Beside the hard clip of Smits & Meyer (1990), Section 3.2 (:mod:`.clip`), and built on
the same ray towards the grey of the colour's own luminance Y (kept exactly): where the
clip stops every colour beyond the boundary on it, the compression maps the colour's
normalised distance ``d`` (1 on the boundary) with :func:`compression_curve`, the power
curve of the ACES 1.3 reference gamut compression (S-2020-001, power 1.2): unchanged up
to ``threshold``, reaching the boundary at ``limit``, the clip beyond. The distance, the
curve and why: docs/compress.md, *Design notes*.

:func:`compress_RGB` (display-linear RGB) and :func:`compress_XYZ` have the clip's
defined behaviour at every edge. The compression factors as
``compress = U o S_w o L o S_b`` exactly (L and U: the clip's factors; the baked view,
:mod:`ocio_thinfilm.lut.compress_lut`, is one LUT per factor):

- :func:`soft_black_RGB` -- S_b, the squeeze by the distance to the faces through black;
- :func:`soft_white_RGB` -- S_w, the rest of the squeeze, after L.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.checks import ParameterError, as_real
from ocio_thinfilm.colour import clip, colorimetry

__all__ = [
    "THRESHOLD",
    "LIMIT",
    "POWER",
    "LIMIT_MAX",
    "check_knobs",
    "knob_text",
    "compression_curve",
    "compression_curve_inverse",
    "boundary_distance",
    "compress_RGB",
    "compress_RGB_inverse",
    "compress_XYZ",
    "soft_black_RGB",
    "soft_white_RGB",
]

#: Normalised boundary distance up to which colours are unchanged (the default).
THRESHOLD = 0.8
#: Normalised distance mapped onto the boundary (the default); further out: the clip.
LIMIT = 1.3
#: Exponent of the ACES 1.3 compression curve (S-2020-001).
POWER = 1.2
#: The largest limit a shader accepts from a host (its fallback refuses larger uniforms).
LIMIT_MAX = 100.0


def check_knobs(
    threshold: object,
    limit: object,
    *,
    names: tuple[str, str] = ("threshold", "limit"),
    limit_max: float | None = None,
) -> tuple[float, float]:
    """Return the compression's knobs ``(threshold, limit)`` as floats, checked.

    The threshold is a fraction of the distance to the gamut boundary, so it lies in
    (0, 1); the limit is the distance mapped onto the boundary, beyond it: ``0 <
    threshold < 1 < limit``, both finite.

    Parameters
    ----------
    threshold, limit : float
        The knobs (:func:`compression_curve`).
    names : tuple of str, optional
        The parameters' names in the error messages (e.g. ``("compress_threshold",
        "compress_limit")`` for the functions that bake the view).
    limit_max : float, optional
        The largest limit allowed (:data:`LIMIT_MAX` for the shaders); ``None``
        (default) for no bound.

    Returns
    -------
    tuple of float
        ``(threshold, limit)``.

    Raises
    ------
    TypeError
        If a knob is not a real number (a string is not parsed).
    ParameterError
        Naming the parameter, for a knob that is not finite or out of its range, or a
        threshold not below the limit.

    Examples
    --------
    >>> check_knobs(0.6, 1.5)
    (0.6, 1.5)
    >>> check_knobs(1.0, 1.3, names=("compress_threshold", "compress_limit"))
    ... # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: compress_threshold must be ... < 1 ..., got 1
    """
    t_name, l_name = names
    t, lim = as_real(t_name, threshold), as_real(l_name, limit)
    if not (np.isfinite(t) and 0.0 < t < 1.0):
        raise ParameterError(
            t_name,
            " must be a finite number > 0 and < 1 (a fraction of the distance to the "
            f"gamut boundary), got {t:g}",
        )
    if not (np.isfinite(lim) and lim > 1.0):
        raise ParameterError(
            l_name,
            " must be a finite number > 1 (the distance mapped onto the gamut boundary), "
            f"got {lim:g}",
        )
    if limit_max is not None and lim > limit_max:
        raise ParameterError(l_name, f" must be at most {limit_max:g} here, got {lim:g}")
    if t >= lim:  # implied by the two ranges; kept for a clear message if they change
        raise ParameterError(t_name, f" must be below {l_name} ({lim:g}), got {t:g}")
    return t, lim


def knob_text(value: float) -> str:
    """Return a knob as the descriptions state it: the shortest decimal that reads back.

    Examples
    --------
    >>> knob_text(0.8), knob_text(2.0), knob_text(0.8123456)
    ('0.8', '2', '0.8123456')
    """
    return format(float(value), ".15g")


def _check(threshold, limit, power):
    threshold, limit = check_knobs(threshold, limit)
    if not (np.isfinite(power) and power > 0.0):
        raise ParameterError("power", f" must be a positive number, got {power!r}")
    return float(threshold), float(limit), float(power)


def _scale(threshold, limit, power):
    """Return the ACES curve's scale s such that the curve reaches 1 at ``limit``.

    Its asymptote is threshold + s (S-2020-001, Section 'compress').
    """
    return (limit - threshold) / (((limit - threshold) / (1.0 - threshold)) ** power - 1.0) ** (
        1.0 / power
    )


def compression_curve(
    d: npt.ArrayLike,
    threshold: float = THRESHOLD,
    limit: float = LIMIT,
    power: float = POWER,
    *,
    clipped: bool = True,
) -> np.ndarray:
    """Return the distance ``d`` (>= 0) after compression.

    ``d`` up to ``threshold`` is unchanged; beyond it,
    ``threshold + x / (1 + (x / s) ** power) ** (1 / power)`` with ``x = d - threshold``
    and ``s`` such that the value is 1 at ``limit`` (ACES 1.3 reference gamut
    compression, S-2020-001): continuous in value and slope at the threshold and
    strictly increasing. ``clipped`` (default): values above 1 (``d > limit``) become 1;
    otherwise the curve goes on to its asymptote ``threshold + s``.

    Examples
    --------
    >>> [round(float(v), 4) for v in compression_curve([0.5, 0.8, 1.0, 1.3, 2.0])]
    [0.5, 0.8, 0.9306, 1.0, 1.0]
    >>> round(float(compression_curve(2.0, clipped=False)), 4)
    1.0451
    """
    threshold, limit, power = _check(threshold, limit, power)
    d = np.asarray(d, dtype=np.float64)
    s = _scale(threshold, limit, power)
    x = np.maximum(d - threshold, 0.0)
    with np.errstate(over="ignore", invalid="ignore"):
        y = threshold + x / (1.0 + (x / s) ** power) ** (1.0 / power)
    y = np.where(d > threshold, np.where(np.isfinite(y), y, threshold + s), d)
    return np.minimum(y, 1.0) if clipped else y


def compression_curve_inverse(
    y: npt.ArrayLike, threshold: float = THRESHOLD, limit: float = LIMIT, power: float = POWER
) -> np.ndarray:
    """Return the distance whose unclipped :func:`compression_curve` is ``y``.

    For ``y`` below the asymptote threshold + s; at or above it: +inf.

    ``x = u / (1 - (u / s) ** power) ** (1 / power)`` with ``u = y - threshold``.

    Examples
    --------
    >>> round(float(compression_curve_inverse(1.0)), 6)
    1.3
    """
    threshold, limit, power = _check(threshold, limit, power)
    y = np.asarray(y, dtype=np.float64)
    s = _scale(threshold, limit, power)
    u = np.maximum(y - threshold, 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        base = 1.0 - (u / s) ** power
        x = np.where(base > 0.0, u / np.maximum(base, 1e-300) ** (1.0 / power), np.inf)
    return np.where(y > threshold, threshold + x, y)


def _distance(rgb, grey):
    """Return the normalised boundary distance along the ray of planar display-linear RGB.

    Planar (3, N) display-linear RGB and its grey (N,) in (0, 1): the normalised
    boundary distance along the ray (the largest of the fractions to the six faces).
    """
    d = np.zeros_like(grey)
    for value in rgb:
        with np.errstate(divide="ignore", invalid="ignore"):
            below = (grey - value) / grey
            above = (value - grey) / (1.0 - grey)
        np.maximum(d, np.where(value < grey, below, above), out=d)
    return d


def boundary_distance(RGB: npt.ArrayLike, display: registry.DisplayLike = "sRGB") -> np.ndarray:
    """Normalised distance of display-linear ``RGB`` to ``display``'s gamut boundary.

    Along the paper's ray (0 at the grey, 1 on the boundary); NaN where Y <= 0 or
    Y >= 1 (no ray: the colour is black or white). Returns (N...,) float64.

    Examples
    --------
    >>> boundary_distance([[0.5, 0.5, 0.5], [0.6, 0.3, 0.0]], "sRGB").round(3).tolist()
    [0.0, 1.0]
    """
    w = clip.luminance_weights(display)
    a = np.asarray(RGB, dtype=np.float64)
    if a.ndim == 0 or a.shape[-1] != 3:
        raise ValueError(f"RGB must have a last axis of length 3, got shape {a.shape}")
    flat = a.reshape(-1, 3).T
    Y = reproducible.matmul(w, flat)
    with np.errstate(invalid="ignore"):
        d = _distance(flat, Y)
    d[~((Y > 0.0) & (Y < 1.0))] = np.nan
    return d.reshape(a.shape[:-1])


def compress_RGB(
    RGB: npt.ArrayLike,
    display: registry.DisplayLike = "sRGB",
    threshold: float = THRESHOLD,
    limit: float = LIMIT,
    power: float = POWER,
) -> np.ndarray:
    """Soft constant-lightness gamut compression of display-linear RGB.

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB of ``display``, last axis 3 (RGB = 1 is its white).
    display : str or registry display
        One of :data:`ocio_thinfilm.colour.clip.DISPLAYS`.
    threshold, limit, power : float
        The curve (:func:`compression_curve`): ``0 < threshold < 1 < limit``.

    Returns
    -------
    numpy.ndarray
        Same shape and dtype (float32 or float64): Y kept, on the segment between the
        colour and its grey, in gamut.

    Examples
    --------
    In-gamut colours away from the boundary are unchanged; a colour 1.12 boundary
    distances out keeps its luminance and lands inside, at the curve's distance
    (the clip would put it on the boundary):

    >>> compress_RGB([0.5, 0.4, 0.3]).tolist()
    [0.5, 0.4, 0.3]
    >>> c = np.array([1.05, 0.45, 0.3])
    >>> d = boundary_distance(c)
    >>> w = colorimetry.RGB_to_XYZ(np.eye(3), "sRGB")[:, 1]  # luminance weights
    >>> out = compress_RGB(c)
    >>> round(float(d), 2), bool(np.isclose(out @ w, c @ w))
    (1.12, True)
    >>> round(float(boundary_distance(out)), 4) == round(float(compression_curve(d)), 4)
    True
    """
    threshold, limit, power = _check(threshold, limit, power)
    luminance = clip.luminance_weights(display)

    def kernel(rgb):
        Y = luminance[0] * rgb[0] + luminance[1] * rgb[1] + luminance[2] * rgb[2]
        grey = np.clip(Y, 0.0, 1.0)
        d = _distance(rgb, grey)
        beyond = d >= limit
        with np.errstate(divide="ignore", invalid="ignore"):
            k = np.where(
                beyond,
                1.0 / d,
                compression_curve(np.where(beyond, 0.0, d), threshold, limit, power) / d,
            )
        k = np.where(d > threshold, k, 1.0)
        out = np.where(d > threshold, np.clip(grey + k * (rgb - grey), 0.0, 1.0), rgb)
        out[:, Y <= 0.0] = 0.0
        out[:, Y >= 1.0] = 1.0
        return out

    return clip._apply(RGB, "RGB", kernel)


def compress_RGB_inverse(
    RGB: npt.ArrayLike,
    display: registry.DisplayLike = "sRGB",
    threshold: float = THRESHOLD,
    limit: float = LIMIT,
    power: float = POWER,
) -> np.ndarray:
    """Return the colours that :func:`compress_RGB` maps onto display-linear ``RGB``.

    The compression is strictly increasing along each ray up to the limit, so every
    colour of the gamut has one preimage at most ``limit`` boundary distances out: the
    distance ``d'`` of the colour from its grey becomes
    :func:`compression_curve_inverse` (d') (``limit`` on the boundary itself, where the
    colours further out land too), along the same ray, Y kept. Colours up to the
    threshold are their own preimage; ``Y <= 0`` gives black, ``Y >= 1`` white. Input
    outside the unit cube is clamped to it first (the view's output range).

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB of ``display``, last axis 3.
    display : str or registry display
        One of :data:`ocio_thinfilm.colour.clip.DISPLAYS`.
    threshold, limit, power : float
        The curve (:func:`compression_curve`).

    Returns
    -------
    numpy.ndarray
        Same shape and dtype (float32 or float64).

    Examples
    --------
    The boundary colour (0.6, 0.3, 0) came from 1.3 boundary distances out; the map
    takes it back there:

    >>> out = compress_RGB_inverse([0.6, 0.3, 0.0])
    >>> round(float(boundary_distance(out)), 6)
    1.3
    >>> bool(np.allclose(compress_RGB(out), [0.6, 0.3, 0.0], atol=1e-12))
    True
    """
    threshold, limit, power = _check(threshold, limit, power)
    luminance = clip.luminance_weights(display)

    def kernel(rgb):
        np.clip(rgb, 0.0, 1.0, out=rgb)
        Y = luminance[0] * rgb[0] + luminance[1] * rgb[1] + luminance[2] * rgb[2]
        grey = np.clip(Y, 0.0, 1.0)
        d = _distance(rgb, grey)
        with np.errstate(divide="ignore", invalid="ignore"):
            k = compression_curve_inverse(np.minimum(d, 1.0), threshold, limit, power) / d
        k = np.where(d >= 1.0, limit / d, k)
        out = np.where(d > threshold, grey + k * (rgb - grey), rgb)
        out[:, Y <= 0.0] = 0.0
        out[:, Y >= 1.0] = 1.0
        return out

    return clip._apply(RGB, "RGB", kernel)


def compress_XYZ(
    XYZ: npt.ArrayLike,
    display: registry.DisplayLike = "sRGB",
    threshold: float = THRESHOLD,
    limit: float = LIMIT,
    power: float = POWER,
) -> np.ndarray:
    """:func:`compress_RGB` for D65-relative CIE XYZ (Y = 1 the display's white).

    XYZ in, XYZ out, same shape and dtype.

    >>> xyz = [0.4034, 0.414, 0.3425]  # sRGB (0.5, 0.4, 0.3): far inside, unchanged
    >>> bool(np.allclose(compress_XYZ(xyz), xyz, rtol=0, atol=1e-15))
    True
    """
    display = clip._space(display)
    M = clip._display_matrix(display)
    a = np.asarray(XYZ)
    dtype = a.dtype if a.dtype in (np.float32, np.float64) else np.float64
    limited = np.clip(np.asarray(a, dtype=np.float64), -clip.LIMIT, clip.LIMIT)  # NaN stays
    rgb = colorimetry.XYZ_to_RGB(limited, display)
    out = reproducible.matmul(
        compress_RGB(rgb, display, threshold, limit, power), reproducible.inv3(M).T
    )
    return out.astype(dtype)


def _sigma(d, threshold, limit, power):
    """f(d) / d for the unclipped curve (1 up to the threshold)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        k = compression_curve(d, threshold, limit, power, clipped=False) / d
    return np.where(d > threshold, k, 1.0)


def soft_black_RGB(
    RGB: npt.ArrayLike,
    display: registry.DisplayLike,
    threshold: float = THRESHOLD,
    limit: float = LIMIT,
    power: float = POWER,
) -> np.ndarray:
    """S_b: ``Y + sigma(d_black) (c - Y)``, d_black = (Y - min c) / Y.

    For display-linear (N, 3) RGB with Y > 0 (float64 out; rows with Y <= 0 unchanged).

    ``sigma(d) = f(d) / d`` with ``f`` the unclipped :func:`compression_curve` (1 up to
    the threshold): the colour moves along the ray of Smits & Meyer (1990), Section 3.2,
    to the curve's distance from its grey, taken against the faces through black
    alone. Homogeneous of degree 1 like the clip's L, and Y is kept.

    Examples
    --------
    Far inside: unchanged; the point of sRGB's face B = 0 at (0.6, 0.3, 0) (d_black = 1)
    moves to f(1) of the way from its grey:

    >>> out = soft_black_RGB([[0.5, 0.4, 0.3], [0.6, 0.3, 0.0]], "sRGB")
    >>> out[0].tolist()
    [0.5, 0.4, 0.3]
    >>> Y = 0.2126 * 0.6 + 0.7152 * 0.3  # Rec.709 weights: kept
    >>> bool(np.isclose(out[1] @ [0.2126, 0.7152, 0.0722], Y, atol=1e-4))
    True
    >>> round(float((Y - out[1].min()) / Y), 3), round(float(compression_curve(1.0)), 3)
    (0.931, 0.931)
    """
    rgb = np.asarray(RGB, dtype=np.float64)
    Y = reproducible.matmul(rgb, clip.luminance_weights(display))
    with np.errstate(all="ignore"):
        d = np.where(Y > 0.0, (Y - rgb.min(axis=-1)) / Y, 0.0)
    k = _sigma(d, threshold, limit, power)
    return np.where((Y > 0.0)[..., None], Y[..., None] + k[..., None] * (rgb - Y[..., None]), rgb)


def soft_white_RGB(
    RGB: npt.ArrayLike,
    display: registry.DisplayLike,
    threshold: float = THRESHOLD,
    limit: float = LIMIT,
    power: float = POWER,
) -> np.ndarray:
    """S_w for display-linear (N, 3) RGB after L (no negative channel); float64 out.

    For 0 < Y < 1: ``d_black = f^-1((Y - min c) / Y)`` (the limit on the faces through
    black), ``d_white = max(c - Y) / (1 - Y) / sigma(d_black)``, and the result is
    ``Y + sigma(D) / sigma(d_black) (c - Y)`` with D the larger. As Y -> 1 this tends to
    ``Y + A (1 - Y) / max(c - Y) (c - Y)`` (A = the curve's asymptote), which is also
    its continuation for Y >= 1 (the nodes brighter than white).

    Together with the clip's factors, ``clip_white_faces_RGB(soft_white_RGB(
    clip_black_faces_RGB(soft_black_RGB(c))))`` is :func:`compress_RGB` (Smits & Meyer
    1990, Section 3.2's ray; checked to 1e-9 in ``tests/test_compress.py``).

    Examples
    --------
    Far inside: unchanged.

    >>> soft_white_RGB([[0.5, 0.4, 0.3]], "sRGB").tolist()
    [[0.5, 0.4, 0.3]]
    """
    rgb = np.asarray(RGB, dtype=np.float64)
    Y = reproducible.matmul(rgb, clip.luminance_weights(display))
    top = (rgb - Y[..., None]).max(axis=-1)
    asymptote = compression_curve(np.inf, threshold, limit, power, clipped=False)
    with np.errstate(all="ignore"):
        d_black = compression_curve_inverse(
            np.clip((Y - rgb.min(axis=-1)) / Y, 0.0, 1.0), threshold, limit, power
        )
        s_black = _sigma(d_black, threshold, limit, power)
        d_white = top / (1.0 - Y) / s_black
        D = np.maximum(d_black, d_white)
        k = _sigma(D, threshold, limit, power) / s_black
        k = np.where(Y < 1.0, k, asymptote * (1.0 - Y) / top)
        k = np.where((top > 0.0) & (Y > 0.0) & np.isfinite(k), k, 1.0)
    out = Y[..., None] + k[..., None] * (rgb - Y[..., None])
    # past white a neutral colour (max(c - Y) at rounding level) has every channel as its
    # largest: Y + A (1 - Y) in each, the formula's limit, not a ratio of rounding errors
    # (which differ between CPUs)
    neutral = (Y >= 1.0) & (top <= clip.NEUTRAL_TOLERANCE * np.maximum(np.abs(Y), 1.0))
    return np.where(neutral[..., None], (Y + asymptote * (1.0 - Y))[..., None], out)
