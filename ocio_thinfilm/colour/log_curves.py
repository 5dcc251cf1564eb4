"""The log curves of the encoded input spaces, as one parametric family.

Every curve of :data:`ocio_thinfilm.registry.LOG_CURVES` is a logarithm with a linear
toe, the form of OpenColorIO's ``LogCameraTransform`` (OCIO >= 2.0): above the break
``x_b``

    code = log_slope * log_base(lin_slope * x + lin_offset) + log_offset

and below it the line ``code = linear_slope * x + linear_offset`` that meets the log
part at the break (``linear_offset`` follows from the others, as OCIO computes it).
:data:`LOG_CURVES` holds each curve's numbers, typed once from its document; the config
builds its OCIO transform from them, the shaders write them as code. The tests hold them
against colour-science's own functions of each curve.

- ACEScct: Academy S-2016-001 (2016), ``(log2(x) + 9.72) / 17.52`` above
  ``2 ** -7``, ``10.5402377416545 x + 0.0729055341958355`` below;
- DaVinci Intermediate: Blackmagic Design, *DaVinci Resolve 17 Wide Gamut
  Intermediate* (2020), ``(log2(x + 0.0075) + 7) * 0.07329248`` above 0.00262409,
  ``10.44426855 x`` below;
- ARRI LogC4: ARRI, *LogC4 Logarithmic Color Space Specification* (2022),
  ``((log2(a x + 64) - 6) / 14) b + c`` above ``t``, ``(x - t) / s`` below, with
  ``a = (2 ** 18 - 16) / 117.45``, ``b = (1023 - 95) / 1023``, ``c = 95 / 1023``;
- S-Log3: Sony, *Technical Summary for S-Gamut3.Cine/S-Log3 and S-Gamut3/S-Log3*
  (2016), ``(420 + 261.5 log10((x + 0.01) / 0.19)) / 1023`` above 0.01125,
  ``(x (171.2102946929 - 95) / 0.01125 + 95) / 1023`` below (scene reflection: 0.18 is
  the 18 % grey card).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

__all__ = ["LogCameraCurve", "LOG_CURVES"]


@dataclass(frozen=True)
class LogCameraCurve:
    """A log curve with a linear toe (OCIO's ``LogCameraTransform`` parameters).

    Parameters
    ----------
    base : float
        The logarithm's base.
    log_slope, log_offset : float
        The log side's scale and offset (OCIO ``logSideSlope``, ``logSideOffset``).
    lin_slope, lin_offset : float
        The linear side's scale and offset inside the log (``linSideSlope``,
        ``linSideOffset``).
    lin_break : float
        The linear value where the toe ends (``linSideBreak``).
    linear_slope : float
        The toe's slope (``linearSlope``).
    """

    base: float
    log_slope: float
    log_offset: float
    lin_slope: float
    lin_offset: float
    lin_break: float
    linear_slope: float

    def _log(self, x: np.ndarray) -> np.ndarray:
        with np.errstate(divide="ignore", invalid="ignore"):
            return (
                self.log_slope * np.log(self.lin_slope * x + self.lin_offset) / math.log(self.base)
                + self.log_offset
            )

    def encode_one(self, x: float) -> float:
        """Return the code value of one scene-linear value (Python's ``math``, no SIMD).

        Examples
        --------
        >>> round(LOG_CURVES["ARRI LogC4"].encode_one(0.18), 6)
        0.278396
        """
        if x > self.lin_break:
            return (
                self.log_slope
                * math.log(self.lin_slope * x + self.lin_offset)
                / math.log(self.base)
                + self.log_offset
            )
        return self.linear_slope * x + self.linear_offset

    @property
    def code_break(self) -> float:
        """The code value at the break."""
        return (
            self.log_slope
            * math.log(self.lin_slope * self.lin_break + self.lin_offset)
            / math.log(self.base)
            + self.log_offset
        )

    @property
    def linear_offset(self) -> float:
        """The toe's offset: the line through the log part's value at the break."""
        return self.code_break - self.linear_slope * self.lin_break

    def encode(self, x: npt.ArrayLike) -> np.ndarray:
        """Return the code values of scene-linear ``x`` (float64).

        Examples
        --------
        >>> float(LOG_CURVES["ACEScct"].encode(0.18)).__round__(6)
        0.413588
        """
        x = np.asarray(x, dtype=np.float64)
        return np.where(
            x > self.lin_break, self._log(x), self.linear_slope * x + self.linear_offset
        )

    def decode(self, code: npt.ArrayLike) -> np.ndarray:
        """Return the scene-linear values of ``code`` (float64; the inverse of :meth:`encode`).

        Examples
        --------
        >>> float(LOG_CURVES["S-Log3"].decode(420 / 1023)).__round__(6)
        0.18
        """
        y = np.asarray(code, dtype=np.float64)
        with np.errstate(over="ignore"):
            log_part = (
                self.base ** ((y - self.log_offset) / self.log_slope) - self.lin_offset
            ) / self.lin_slope
        return np.where(y > self.code_break, log_part, (y - self.linear_offset) / self.linear_slope)


_LOGC4_A = (2.0**18 - 16.0) / 117.45
_LOGC4_B = (1023.0 - 95.0) / 1023.0
_LOGC4_C = 95.0 / 1023.0
_LOGC4_S = (7.0 * math.log(2.0) * 2.0 ** (7.0 - 14.0 * _LOGC4_C / _LOGC4_B)) / (_LOGC4_A * _LOGC4_B)
_LOGC4_T = (2.0 ** (14.0 * (-_LOGC4_C / _LOGC4_B) + 6.0) - 64.0) / _LOGC4_A

#: The curves by their registry names (:data:`ocio_thinfilm.registry.LOG_CURVES`).
LOG_CURVES = {
    "ACEScct": LogCameraCurve(
        base=2.0,
        log_slope=1.0 / 17.52,
        log_offset=9.72 / 17.52,
        lin_slope=1.0,
        lin_offset=0.0,
        lin_break=0.0078125,
        linear_slope=10.5402377416545,
    ),
    "DaVinci Intermediate": LogCameraCurve(
        base=2.0,
        log_slope=0.07329248,
        log_offset=7.0 * 0.07329248,
        lin_slope=1.0,
        lin_offset=0.0075,
        lin_break=0.00262409,
        linear_slope=10.44426855,
    ),
    "ARRI LogC4": LogCameraCurve(
        base=2.0,
        log_slope=_LOGC4_B / 14.0,
        log_offset=_LOGC4_C - 6.0 * _LOGC4_B / 14.0,
        lin_slope=_LOGC4_A,
        lin_offset=64.0,
        lin_break=_LOGC4_T,
        linear_slope=1.0 / _LOGC4_S,
    ),
    "S-Log3": LogCameraCurve(
        base=10.0,
        log_slope=261.5 / 1023.0,
        log_offset=420.0 / 1023.0,
        lin_slope=1.0 / 0.19,
        lin_offset=0.01 / 0.19,
        lin_break=0.01125,
        linear_slope=(171.2102946929 - 95.0) / 0.01125 / 1023.0,
    ),
}
