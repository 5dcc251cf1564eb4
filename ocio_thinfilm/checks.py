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
    """A bad command-line argument that is no library parameter.

    The command line prints it on one line and exits with 2.
    """


class ParameterError(ValueError):
    """A library function's argument outside what it allows, naming the parameter.

    ``str(error)`` is ``parameter + detail`` (``"index applies to film tables only"``,
    ``"value_range: thickness must not be negative, got -1"``). The command line
    names its option instead (:meth:`for_option`; ``--index applies to ...``).

    Parameters
    ----------
    parameter : str
        The Python parameter's name: the start of the message.
    detail : str
        The rest of the message, beginning with its separator (``" must be ..."``,
        ``": thickness ..."``).

    Attributes
    ----------
    parameter : str
        The parameter's name, as given.
    detail : str
        The rest of the message, as given.

    Examples
    --------
    >>> error = ParameterError("size", " must be in [2, 1048576], got 1")
    >>> str(error)
    'size must be in [2, 1048576], got 1'
    >>> error.for_option("--size")
    '--size must be in [2, 1048576], got 1'
    """

    def __init__(self, parameter: str, detail: str) -> None:
        super().__init__(parameter + detail)
        self.parameter = parameter
        self.detail = detail

    def for_option(self, option: str) -> str:
        """Return the message with ``option`` in place of the parameter.

        Parameters
        ----------
        option : str
            The command-line option that gave the value, e.g. ``--range``.

        Returns
        -------
        str
            ``option + detail``.
        """
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
    """Return ``value`` as a finite float64 (or complex) array within the bounds.

    Parameters
    ----------
    name : str
        The parameter's name, for the error messages.
    value : array_like
        A number or an array of numbers (bool, integer, float or complex). A string is
        not parsed: ``n='1.33'`` is refused.
    minimum : float, optional
        Lower bound of the values (of their real parts for complex values); ``None``
        (default) for none.
    maximum : float, optional
        Upper bound, inclusive; ``None`` (default) for none.
    strict : bool, optional
        Whether values must be greater than ``minimum`` (default ``False``: greater
        or equal).
    unit : str, optional
        Appended to the bounds in the messages (e.g. ``" nm"``); default none.

    Returns
    -------
    numpy.ndarray
        ``value`` as a float64 array (no copy when it already is one); complex values
        stay complex.

    Raises
    ------
    TypeError
        If ``value`` is not a number or an array of numbers.
    ParameterError
        If a value (a real part) is not finite or lies outside the bounds; the message
        names ``name``, the bounds and the first offending value.

    Examples
    --------
    >>> as_array("thickness", [0, 250.5], minimum=0.0)
    array([  0. , 250.5])
    >>> as_array("thickness", [-1.0], minimum=0.0, unit=" nm")
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: thickness must be >= 0 nm, got -1
    """
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
        bounds = _bounds(minimum, maximum, strict, unit)
        raise ParameterError(name, " must be finite" + (f" and {bounds}" if bounds else ""))
    if not check.size:
        return a
    below = (check <= minimum if strict else check < minimum) if minimum is not None else None
    above = check > maximum if maximum is not None else None
    for bad in (below, above):
        if bad is not None and np.any(bad):
            raise ParameterError(
                name,
                f" must be {_bounds(minimum, maximum, strict, unit)}, got {check[bad].flat[0]:g}",
            )
    return a


def short_repr(value: object) -> str:
    """Return ``repr(value)``, cut to 40 characters for an error message.

    Parameters
    ----------
    value : object
        Any object.

    Returns
    -------
    str
        ``repr(value)``, or its first 37 characters followed by ``...``.

    Examples
    --------
    >>> short_repr("x" * 50)
    "'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx..."
    """
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _bounds(minimum: float | None, maximum: float | None, strict: bool, unit: str) -> str:
    """``">= 0 nm"``, ``"<= 90 degrees"``, ``"in [0, 90] degrees"`` or ``""`` (no bounds)."""
    if minimum is None and maximum is None:
        return ""
    if maximum is None:
        return f"{'>' if strict else '>='} {minimum:g}{unit}"
    if minimum is None:
        return f"<= {maximum:g}{unit}"
    if strict:
        return f"> {minimum:g}{unit} and <= {maximum:g}{unit}"
    return f"in [{minimum:g}, {maximum:g}]{unit}"


def as_count(name: str, value: object, minimum: int = 1, maximum: int | None = None) -> int:
    """Return an integer parameter (layers, harmonics) as an int, checked.

    Parameters
    ----------
    name : str
        The parameter's name, for the error messages.
    value : object
        The value: an int, a float or a NumPy number equal to an integer (``3.0`` is
        accepted). A string is not parsed (``layers='3'`` is refused).
    minimum : int, optional
        Smallest allowed value (default 1).
    maximum : int, optional
        Largest allowed value; ``None`` (default) for none.

    Returns
    -------
    int
        ``value`` as an int.

    Raises
    ------
    TypeError
        If ``value`` is not a number (a string, a bool).
    ParameterError
        If ``value`` is not finite, not an integer or outside ``[minimum, maximum]``.

    Examples
    --------
    >>> as_count("layers", 12.0)
    12
    >>> as_count("layers", 3.5, 1, 10)
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: layers must be an integer in [1, 10], got 3.5
    """
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.number)):
        # a string is not parsed, a bool is not a count
        allowed = f">= {minimum}" if maximum is None else f"in [{minimum}, {maximum}]"
        raise TypeError(
            f"{name} must be an integer {allowed}, got {value!r} ({type(value).__name__})"
        )
    f = float(value)
    if not np.isfinite(f) or f != int(f) or f < minimum or (maximum is not None and f > maximum):
        allowed = f">= {minimum}" if maximum is None else f"in [{minimum}, {maximum}]"
        raise ParameterError(name, f" must be an integer {allowed}, got {value!r}")
    return int(f)


def as_real(name: str, value: object) -> float:
    """Return a real-number parameter as a float.

    Ranges (and finiteness) are the caller's to check.

    Parameters
    ----------
    name : str
        The parameter's name, for the error message.
    value : object
        An int, a float or a NumPy integer or floating-point number.

    Returns
    -------
    float
        ``value`` as a float.

    Raises
    ------
    TypeError
        If ``value`` is not a real number: a string is not parsed, a bool is not a
        number.
    """
    if isinstance(value, (bool, np.bool_)) or not isinstance(
        value, (int, float, np.integer, np.floating)
    ):
        raise TypeError(
            f"{name} must be a number, got {short_repr(value)} ({type(value).__name__})"
        )
    return float(value)


def as_pair(name: str, value: Any) -> tuple[float, float]:
    """Return two real numbers ``(lo, hi)`` as floats.

    Their order, range and finiteness are the caller's to check.

    Parameters
    ----------
    name : str
        The parameter's name, for the error message.
    value : sequence of two numbers
        A one-dimensional sequence or array of exactly two real numbers.

    Returns
    -------
    tuple of float
        ``(lo, hi)``.

    Raises
    ------
    TypeError
        If ``value`` is a string, not one-dimensional, not of length 2 or holds
        something that is not a real number (:func:`as_real`).

    Examples
    --------
    >>> as_pair("value_range", [0, 1.5])
    (0.0, 1.5)
    """
    if isinstance(value, (str, bytes)) or np.ndim(value) != 1 or len(value) != 2:
        raise TypeError(f"{name} must be two numbers (lo, hi), got {short_repr(value)}")
    lo, hi = value
    return as_real(name, lo), as_real(name, hi)


def as_positive(name: str, value: object) -> float:
    """Return a finite real number > 0 as a float.

    Parameters
    ----------
    name : str
        The parameter's name, for the error messages.
    value : object
        A real number (as :func:`as_real` accepts).

    Returns
    -------
    float
        ``value`` as a float.

    Raises
    ------
    TypeError
        If ``value`` is not a real number (a string is not parsed).
    ParameterError
        If ``value`` is not finite or not > 0.
    """
    f = as_real(name, value)
    if not np.isfinite(f) or f <= 0:
        raise ParameterError(name, f" must be a finite number > 0, got {f:g}")
    return f


def as_choice(name: str, value: _T, choices: Iterable[_T]) -> _T:
    """Return ``value`` if it is one of ``choices``.

    Parameters
    ----------
    name : str
        The parameter's name, for the error message.
    value : object
        The value to check; an unhashable or uncomparable value is no choice.
    choices : iterable
        The allowed values.

    Returns
    -------
    object
        ``value`` itself.

    Raises
    ------
    ParameterError
        If ``value`` is not one of ``choices``; the message lists them.

    Examples
    --------
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
