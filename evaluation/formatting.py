"""The number format of the report's tables and of the stability cases' observed text.

A module of its own (not in :mod:`evaluation.report.measure`, which
re-exports it) so that :mod:`evaluation.stability` can format numbers
without importing the report package, which imports the stability cases.
"""

from __future__ import annotations

import numpy as np

__all__ = ["fmt"]


def fmt(x, digits: int = 3) -> str:
    """A number as the report prints it.

    Parameters
    ----------
    x : float, int, str or None
        The value. Strings pass through, None is a dash, integers print in full,
        non-finite floats as ``nan`` / ``inf``.
    digits : int, optional
        Significant digits; the exponent form is used outside [1e-3, 1e4).

    Returns
    -------
    str
    """
    if x is None:
        return "–"
    if isinstance(x, str):
        return x
    if isinstance(x, (int, np.integer)) and not isinstance(x, bool):
        return str(x)
    if not np.isfinite(x):
        return str(x)
    if x == 0:
        return "0"
    if abs(x) >= 1e4 or abs(x) < 1e-3:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}"
