"""The log curves of the encoded input spaces, vectorised: encoding and decoding by kind.

Each curve is a :class:`ocio_thinfilm.registry.LogCurve` (its published constants, its
kind, the model's assumptions checked at import); these are its float64 numpy forms,
one per kind of :data:`ocio_thinfilm.registry.CURVE_KINDS`. The tests hold them against
colour-science's functions the curve names (``LogCurve.colour_science``).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.registry import LogCurve

__all__ = ["encode", "decode"]


def _log(curve: LogCurve, x: np.ndarray) -> np.ndarray:
    with np.errstate(divide="ignore", invalid="ignore"):
        inner = np.log(curve.lin_slope * x + curve.lin_offset) / math.log(curve.base)
    return curve.log_slope * inner + curve.log_offset


def _unlog(curve: LogCurve, y: np.ndarray) -> np.ndarray:
    with np.errstate(over="ignore"):
        power = curve.base ** ((y - curve.log_offset) / curve.log_slope)
    return (power - curve.lin_offset) / curve.lin_slope


def encode(curve: LogCurve, x: npt.ArrayLike) -> np.ndarray:
    """Return the code values of scene-linear ``x`` (float64) by ``curve``.

    Parameters
    ----------
    curve : LogCurve
        A curve of :data:`ocio_thinfilm.registry.LOG_CURVE_LIST`.
    x : array_like
        Scene-linear values.

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> from ocio_thinfilm.registry import find_curve
    >>> float(encode(find_curve("ACEScct"), 0.18)).__round__(6)
    0.413588
    >>> encode(find_curve("Canon Log 3"), [-1.0, 0.0]).round(6).tolist()
    [-0.330033, 0.125122]
    """
    x = np.asarray(x, dtype=np.float64)
    if curve.kind == "quadratic-toe":
        toe = np.where(x > curve.toe_origin, curve.toe_slope * (x - curve.toe_origin) ** 2, 0.0)
    else:
        toe = curve.toe_slope * x + curve.toe_intercept
    code = np.where(x > curve.lin_break, _log(curve, x), toe)
    if curve.kind == "mirrored-log":
        code = np.where(x < -curve.lin_break, 2.0 * curve.black - _log(curve, -x), code)
    return code


def decode(curve: LogCurve, code: npt.ArrayLike) -> np.ndarray:
    """Return the scene-linear values of ``code`` (float64; the inverse of :func:`encode`).

    Parameters
    ----------
    curve : LogCurve
        A curve of :data:`ocio_thinfilm.registry.LOG_CURVE_LIST`.
    code : array_like
        Code values.

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> from ocio_thinfilm.registry import find_curve
    >>> float(decode(find_curve("S-Log3"), 420 / 1023)).__round__(6)
    0.18
    >>> curves = [find_curve(n) for n in ("Panasonic V-Log", "Apple Log")]
    >>> [float(decode(c, c.black)) for c in curves]
    [0.0, 0.0]
    """
    y = np.asarray(code, dtype=np.float64)
    if curve.kind == "quadratic-toe":
        toe = curve.toe_origin + np.sqrt(np.maximum(y, 0.0) / curve.toe_slope)
    else:
        toe = (y - curve.toe_intercept) / curve.toe_slope
    linear = np.where(y >= curve.toe_break, _unlog(curve, y), toe)
    if curve.kind == "mirrored-log":
        mirror = 2.0 * curve.black - y
        linear = np.where(mirror >= curve.toe_break, -_unlog(curve, mirror), linear)
    return linear
