"""The registry's gamuts and log curves: each one object with its numbers and its truth.

A :class:`Gamut` names colour-science's RGB colourspace; a :class:`LogCurve` carries its
published constants, the kind of its model (:data:`CURVE_KINDS`), the model's
assumptions (checked when the object is made, so at import) and colour-science's
functions of it. Every stage derives its code from these fields. Part of
:mod:`ocio_thinfilm.registry` (import it from there).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["Gamut", "LogCurve", "CURVE_KINDS", "BLACK_TOLERANCE"]

#: The kinds of log curve: a log part above a break with a linear toe (``"log"``); the
#: same mirrored about its black code below ``-lin_break``, three segments
#: (``"mirrored-log"``: Canon Log 3); a log part with a quadratic toe, 0 below its origin
#: (``"quadratic-toe"``: Apple Log).
CURVE_KINDS = ("log", "mirrored-log", "quadratic-toe")
#: How far the model's code of linear 0 may be from the published black code.
BLACK_TOLERANCE = 1e-7


@dataclass(frozen=True)
class Gamut:
    """An RGB gamut (primaries and white) of the colorimetry.

    Parameters
    ----------
    name : str
        Our name (a key of :data:`ocio_thinfilm.registry.RGB_COLORIMETRY`).
    colour_science : str
        colour-science's name of it (a key of ``colour.RGB_COLOURSPACES``): its
        primaries and white, the colorimetry's matrices and the tests' truth.
    """

    name: str
    colour_science: str


@dataclass(frozen=True)
class LogCurve:
    """A log encoding of scene-linear values, as published, with its model's assumptions.

    Above ``lin_break`` every kind is the log part
    ``code = log_slope * log_base(lin_slope * x + lin_offset) + log_offset``; below it
    the toe: the line ``toe_slope * x + toe_offset`` (``"log"``, ``"mirrored-log"``) or
    ``toe_slope * (x - toe_origin) ** 2``, 0 below ``toe_origin``
    (``"quadratic-toe"``). A ``"mirrored-log"`` curve is odd about (0, ``black``): below
    ``-lin_break`` its code is ``2 black - log part(-x)``. Decoding splits at the toe's
    code at the break (:attr:`toe_break`), as the documents do.

    The assumptions, checked when the object is made: the log part and the toe meet at
    the break within ``continuity`` (code values); linear 0 encodes to ``black``; a
    mirrored curve's toe passes through (0, ``black``). Where a document publishes the
    toe's offset (``toe_offset``) the model uses it as printed, continuous or not
    (Panasonic's V-Log misses by 3.1e-7), so black decodes exactly; ``None`` derives it
    from continuity (OCIO's ``LogCameraTransform`` rule).

    Parameters
    ----------
    name : str
        The curve's name.
    reference : str
        The document that defines it.
    kind : str
        One of :data:`CURVE_KINDS`.
    base, log_slope, log_offset, lin_slope, lin_offset : float
        The log part's base and constants.
    lin_break : float
        The linear value where the toe ends.
    toe_slope : float
        The linear toe's slope, or the quadratic toe's scale.
    black : float
        The published code value of linear 0.
    colour_science : tuple of str
        colour-science's names of its encoding and decoding (``colour.models``), each
        with its defaults: the independent truth of every stage's code.
    toe_offset : float or None, optional
        The linear toe's published offset; ``None`` (default): from continuity.
    toe_origin : float, optional
        The quadratic toe's origin (code 0 there and below); default 0.
    continuity : float, optional
        The largest gap of the published curve at the break (default 1e-9).
    ocio_builtin : tuple of str or None, optional
        An OCIO 2.1 built-in decoding to ACES2065-1 and the built-in whose inverse
        returns to the curve's gamut, where OCIO has one (ACEScct); default ``None``.
    """

    name: str
    reference: str
    kind: str
    base: float
    log_slope: float
    log_offset: float
    lin_slope: float
    lin_offset: float
    lin_break: float
    toe_slope: float
    black: float
    colour_science: tuple[str, str]
    toe_offset: float | None = None
    toe_origin: float = 0.0
    continuity: float = 1e-9
    ocio_builtin: tuple[str, str] | None = None

    def __post_init__(self) -> None:
        """Check the model's assumptions (raise ``ValueError`` naming each broken one)."""
        problems = []
        if self.kind not in CURVE_KINDS:
            problems.append(f"kind must be one of {CURVE_KINDS}")
        if not (self.base > 1 and self.log_slope * self.lin_slope > 0 and self.toe_slope > 0):
            problems.append("the curve must increase (base > 1, slopes > 0)")
        if len(self.colour_science) != 2 or not all(self.colour_science):
            problems.append("colour_science names its encoding and decoding")
        if self.kind == "mirrored-log" and self.toe_intercept != self.black:
            problems.append("a mirrored curve's toe passes through (0, black)")
        if self.kind == "quadratic-toe" and not self.toe_origin < 0.0 < self.lin_break:
            problems.append("a quadratic toe runs from its origin < 0 past 0")
        if not problems and abs(self.gap) > self.continuity:
            problems.append(f"toe and log part meet {self.gap:.3g} apart (> {self.continuity})")
        if not problems and abs(self.encode_one(0.0) - self.black) > BLACK_TOLERANCE:
            problems.append(f"black encodes to {self.encode_one(0.0)!r}, not {self.black!r}")
        if problems:
            raise ValueError(f"registry: log curve {self.name!r}: " + "; ".join(problems))

    def log_one(self, x: float) -> float:
        """Return the log part's code of one linear value (Python's ``math``)."""
        inner = self.lin_slope * x + self.lin_offset
        return self.log_slope * math.log(inner) / math.log(self.base) + self.log_offset

    @property
    def toe_intercept(self) -> float:
        """The linear toe's offset: the published one, or the line through the break."""
        if self.toe_offset is not None:
            return self.toe_offset
        return self.code_break - self.toe_slope * self.lin_break

    def toe_one(self, x: float) -> float:
        """Return the toe's code of one linear value."""
        if self.kind == "quadratic-toe":
            return self.toe_slope * (x - self.toe_origin) ** 2 if x > self.toe_origin else 0.0
        return self.toe_slope * x + self.toe_intercept

    @property
    def code_break(self) -> float:
        """The log part's code at the break."""
        return self.log_one(self.lin_break)

    @property
    def toe_break(self) -> float:
        """The toe's code at the break: where decoding switches to the log part."""
        if self.kind != "quadratic-toe" and self.toe_offset is None:
            return self.code_break
        return self.toe_one(self.lin_break)

    @property
    def gap(self) -> float:
        """The log part's code minus the toe's at the break (0 for a continuous curve)."""
        return self.code_break - self.toe_break

    def encode_one(self, x: float) -> float:
        """Return the code value of one scene-linear value (Python's ``math``, no SIMD).

        Examples
        --------
        >>> from ocio_thinfilm.registry import find_curve
        >>> round(find_curve("ARRI LogC4").encode_one(0.18), 6)
        0.278396
        >>> find_curve("Panasonic V-Log").encode_one(0.0)
        0.125
        """
        if self.kind == "mirrored-log" and x < -self.lin_break:
            return 2.0 * self.black - self.log_one(-x)
        return self.log_one(x) if x > self.lin_break else self.toe_one(x)
