"""Argument checks: one place that words every error message of the package.

Every public function checks its arguments at its door with these, so the same mistake
gets the same answer wherever it is made:

- a value of the wrong *type* (a string where a number goes: ``"65"`` is never parsed,
  a bool where an integer goes) is a :class:`TypeError` naming the parameter;
- a value of the right type outside what is allowed (out of range, not finite, not one
  of the choices) is a :class:`ParameterError`, a :class:`ValueError` whose message
  starts with the Python parameter's name (``"size must be in [2, 1048576], got 1"``);
  the command line prints the same message with its option in place of the parameter
  (:meth:`ParameterError.for_option`: ``"--size must be ..."``);
- a bad command-line argument that is no library parameter is a :class:`UsageError`.

This module is a leaf: it imports nothing of the package, so every stage may use it.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, TypeVar

import numpy as np
import numpy.typing as npt

__all__ = [
    "UsageError",
    "ParameterError",
    "as_array",
    "as_count",
    "as_real",
    "as_positive",
    "as_pair",
    "as_choice",
]

_T = TypeVar("_T")


class UsageError(ValueError):
    """A bad command-line argument: the CLI prints it on one line and exits with 2."""


class ParameterError(ValueError):
    """A library function's argument outside what it allows, naming the Python parameter:
    ``str(error)`` is ``parameter + detail`` (``"index applies to film tables only"``,
    ``"value_range: thickness must not be negative, got -1"``). The command line
    names its option instead (:meth:`for_option`; ``--index applies to ...``)."""

    def __init__(self, parameter: str, detail: str) -> None:
        super().__init__(parameter + detail)
        self.parameter = parameter
        self.detail = detail

    def for_option(self, option: str) -> str:
        """The message with ``option`` (e.g. ``--range``) in place of the parameter."""
        return option + self.detail


def as_array(
    name: str,
    value: npt.ArrayLike,
    *,
    minimum: float | None = None,
    maximum: float | None = None,
    strict: bool = False,
    unit: str = "",
) -> np.ndarray:
    """``value`` as a float64 (or complex) array, finite and within the bounds, else a
    ValueError naming ``name``, the bounds and the first offending value (a TypeError
    for what is not numbers: a string is not parsed, ``n='1.33'`` is refused)."""
    a = np.asarray(value)
    if a.dtype.kind not in "biufc":
        raise TypeError(
            f"{name} must be a number or an array of numbers, got "
            f"{short_repr(value)} ({type(value).__name__})"
        )
    if a.dtype.kind == "c":
        check = a.real
    else:
        a = a.astype(np.float64, copy=False)
        check = a
    if check.size and not np.all(np.isfinite(check)):
        raise ParameterError(name, f" must be finite{_range_text(minimum, maximum, strict, unit)}")
    if minimum is not None and check.size:
        bad = check <= minimum if strict else check < minimum
        if np.any(bad):
            raise ParameterError(
                name,
                f" must be {'>' if strict else '>='} {minimum:g}{unit}"
                f"{'' if maximum is None else f' and <= {maximum:g}{unit}'}, "
                f"got {check[bad].flat[0]:g}",
            )
    if maximum is not None and check.size and np.any(check > maximum):
        raise ParameterError(
            name,
            f" must be in [{minimum:g}, {maximum:g}]{unit}, got {check[check > maximum].flat[0]:g}",
        )
    return a


def short_repr(value: object) -> str:
    """``repr(value)``, cut to 40 characters for an error message."""
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _range_text(minimum: float | None, maximum: float | None, strict: bool, unit: str) -> str:
    if minimum is None:
        return ""
    if maximum is None:
        return f" and {'>' if strict else '>='} {minimum:g}{unit}"
    return f" and in [{minimum:g}, {maximum:g}]{unit}"


def as_count(name: str, value: object, minimum: int = 1, maximum: int | None = None) -> int:
    """An integer parameter (layers, harmonics): a TypeError naming it for a value that
    is not a number (a string is not parsed: ``layers='3'`` is refused), a ValueError
    for a number that is not an integer in range."""
    if isinstance(value, (bool, np.bool_)):
        raise ParameterError(name, f" must be an integer >= {minimum}, got {value!r}")
    if not isinstance(value, (int, float, np.number)):  # a string is not parsed
        raise TypeError(
            f"{name} must be an integer >= {minimum}, got {value!r} ({type(value).__name__})"
        )
    f = float(value)
    if not np.isfinite(f) or f != int(f) or f < minimum or (maximum is not None and f > maximum):
        allowed = f">= {minimum}" if maximum is None else f"in [{minimum}, {maximum}]"
        raise ParameterError(name, f" must be an integer {allowed}, got {value!r}")
    return int(f)


def as_real(name: str, value: object) -> float:
    """A real-number parameter as a float; a TypeError naming it for what is not one
    (a string is not parsed, a bool is not a number). Ranges are the caller's to check."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(
        value, (int, float, np.integer, np.floating)
    ):
        raise TypeError(
            f"{name} must be a number, got {short_repr(value)} ({type(value).__name__})"
        )
    return float(value)


def as_pair(name: str, value: Any) -> tuple[float, float]:
    """Two real numbers ``(lo, hi)`` as floats; a TypeError naming ``name`` otherwise."""
    if isinstance(value, (str, bytes)) or np.ndim(value) != 1 or len(value) != 2:
        raise TypeError(f"{name} must be two numbers (lo, hi), got {short_repr(value)}")
    lo, hi = value
    return as_real(name, lo), as_real(name, hi)


def as_positive(name: str, value: object) -> float:
    """A finite real number > 0 as a float: a TypeError naming ``name`` for what is not
    a number (a string is not parsed), a :class:`ParameterError` otherwise."""
    f = as_real(name, value)
    if not np.isfinite(f) or f <= 0:
        raise ParameterError(name, f" must be a finite number > 0, got {f:g}")
    return f


def as_choice(name: str, value: _T, choices: Iterable[_T]) -> _T:
    """``value`` if it is one of ``choices``, else a :class:`ParameterError` naming
    ``name`` and listing the choices.

    >>> as_choice("kind", "morpho", ("phase-change", "morpho"))
    'morpho'
    >>> as_choice("kind", "oil", ("phase-change", "morpho"))
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: kind must be one of ('phase-change', 'morpho'), got 'oil'
    """
    options = tuple(choices)
    try:
        if value in options:
            return value
    except TypeError:  # an unhashable or uncomparable value is not a choice
        pass
    raise ParameterError(name, f" must be one of {options}, got {short_repr(value)}")
