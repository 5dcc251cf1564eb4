"""The SDR displays' encodings (inverse EOTFs) in float64.

The curves of :class:`ocio_thinfilm.registry.Encoding` as the config's OCIO ops apply
them (``ExponentWithLinearTransform``, ``ExponentTransform``), computed in float64 by
numpy: the LUT builders quantise these values, so they must not come from OCIO's float32
CPU path, whose SIMD kernels differ between CPUs (:mod:`ocio_thinfilm.reproducible`).

- :func:`piecewise` -- where the sRGB-style curve's linear segment ends, and its slope;
- :func:`encode` -- display-linear -> code values;
- :func:`decode` -- code values -> display-linear.

References
----------
IEC 61966-2-1:1999 (sRGB; it rounds the breakpoint and slope to 0.0031308 and 12.92);
ITU-R BT.1886 (2011) with a black level of 0 (a pure power).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import registry

__all__ = ["piecewise", "encode", "decode"]


def piecewise(encoding: registry.Encoding) -> tuple[float, float]:
    """Return where the sRGB-style curve's linear segment ends (linear) and its slope.

    Value and slope continuous there, as OCIO's ExponentWithLinearTransform computes
    them from the gamma and the offset.

    Parameters
    ----------
    encoding : registry.Encoding
        With an ``offset``.

    Returns
    -------
    tuple of float
        (breakpoint, slope).

    Examples
    --------
    >>> brk, slope = piecewise(registry.as_display("sRGB").encoding)
    >>> round(brk, 7), round(slope, 2)
    (0.0030399, 12.92)
    """
    gamma, offset = encoding.gamma, float(encoding.offset or 0.0)
    brk = (offset * gamma / ((1.0 + offset) * (gamma - 1.0))) ** gamma
    return brk, (1.0 + offset) / gamma * brk ** (1.0 / gamma - 1.0)


def encode(values: npt.ArrayLike, encoding: registry.Encoding) -> np.ndarray:
    """Display-linear values -> code values, float64.

    The piecewise curve is linear below 0 (OCIO's default negative style); the pure
    power clamps negative values to 0 (the config sets ``NEGATIVE_CLAMP``).

    Examples
    --------
    Linear 0.18 is sRGB code 1.055 * 0.18 ** (1 / 2.4) - 0.055 = 0.4614 and BT.1886
    code 0.18 ** (1 / 2.4) = 0.4894:

    >>> srgb = registry.as_display("sRGB").encoding
    >>> bt1886 = registry.as_display("Rec.2020").encoding
    >>> encode([0.0, 0.18, 1.0], srgb).round(4).tolist()
    [0.0, 0.4614, 1.0]
    >>> encode([-0.1, 0.18, 1.0], bt1886).round(4).tolist()
    [0.0, 0.4894, 1.0]
    """
    v = np.asarray(values, dtype=np.float64)
    inv = 1.0 / encoding.gamma
    with np.errstate(invalid="ignore"):
        if encoding.offset is None:
            return np.power(np.maximum(v, 0.0), inv)
        brk, slope = piecewise(encoding)
        offset = encoding.offset
        power = (1.0 + offset) * np.power(np.maximum(v, brk), inv) - offset
        return np.where(v <= brk, slope * v, power)


def decode(codes: npt.ArrayLike, encoding: registry.Encoding) -> np.ndarray:
    """Code values -> display-linear values, float64 (the inverse of :func:`encode`).

    Examples
    --------
    >>> srgb = registry.as_display("sRGB").encoding
    >>> decode(encode([0.001, 0.18, 1.0], srgb), srgb).round(12).tolist()
    [0.001, 0.18, 1.0]
    """
    c = np.asarray(codes, dtype=np.float64)
    with np.errstate(invalid="ignore"):
        if encoding.offset is None:
            return np.power(np.maximum(c, 0.0), encoding.gamma)
        brk, slope = piecewise(encoding)
        offset = encoding.offset
        power = np.power((np.maximum(c, slope * brk) + offset) / (1.0 + offset), encoding.gamma)
        return np.where(c <= slope * brk, c / slope, power)
