"""The material model: a complex refractive index ``n + ik`` against wavelength.

:class:`Material` holds ``n`` and ``k`` each as a constant, a :class:`Tabulated` table
(interpolated linearly in wavelength, as refractiveindex.info does) or a :class:`Formula`
(refractiveindex.info's dispersion formulas 1-9); :func:`constant` makes one of constant
index. :func:`check_nk` and :func:`checked_table` are the checks every reader shares.

References
----------
Polyanskiy, M. N. (2024). Refractiveindex.info database of optical constants.
Scientific Data 11, 94. https://doi.org/10.1038/s41597-023-02898-2 (formulas:
https://refractiveindex.info/database/doc/Dispersion%20formulas.pdf).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import ParameterError, as_real

__all__ = [
    "VISIBLE_NM",
    "FORMULAS",
    "Tabulated",
    "Formula",
    "Dispersion",
    "Material",
    "constant",
    "check_nk",
    "check_formula",
    "checked_table",
]

#: The wavelength range (nm) a material's data must cover to colour a film.
VISIBLE_NM = (380.0, 780.0)
#: refractiveindex.info dispersion formulas this module evaluates (all nine).
FORMULAS = (1, 2, 3, 4, 5, 6, 7, 8, 9)


@dataclass(frozen=True, eq=False)
class Tabulated:
    """Values (``n`` or ``k``) tabulated against wavelength, interpolated linearly.

    The values are tabulated at ``wavelength_nm`` (strictly increasing) and defined on
    ``[wavelength_nm[0], wavelength_nm[-1]]``.
    """

    wavelength_nm: np.ndarray
    values: np.ndarray

    @property
    def coverage(self) -> tuple[float, float]:
        """The wavelength range (nm) the table covers."""
        return float(self.wavelength_nm[0]), float(self.wavelength_nm[-1])

    def __call__(self, wavelengths: np.ndarray) -> np.ndarray:
        """Return the values interpolated linearly at ``wavelengths``.

        Parameters
        ----------
        wavelengths : numpy.ndarray
            Wavelengths in nm, within :attr:`coverage` (outside it ``numpy.interp``
            holds the end values; :meth:`Material.index` refuses such wavelengths).

        Returns
        -------
        numpy.ndarray
            The interpolated values, the shape of ``wavelengths``.
        """
        return np.interp(wavelengths, self.wavelength_nm, self.values)


@dataclass(frozen=True)
class Formula:
    """A refractiveindex.info dispersion formula with its coefficients and valid range.

    ``number`` is one of :data:`FORMULAS`, the ``coefficients`` take wavelengths in um and
    ``range_nm`` is where the formula is valid.

    With C the coefficients and lambda in um:

    - 1 (Sellmeier): ``n^2 - 1 = C1 + sum_i C(2i) lambda^2 / (lambda^2 - C(2i+1)^2)``;
    - 2 (Sellmeier-2): ``n^2 - 1 = C1 + sum_i C(2i) lambda^2 / (lambda^2 - C(2i+1))``;
    - 3 (polynomial): ``n^2 = C1 + sum_i C(2i) lambda^C(2i+1)``;
    - 4 (RefractiveIndex.INFO): ``n^2 = C1 + C2 lambda^C3 / (lambda^2 - C4^C5)
      + C6 lambda^C7 / (lambda^2 - C8^C9) + sum_{i>=5} C(2i) lambda^C(2i+1)``;
    - 5 (Cauchy): ``n = C1 + sum_i C(2i) lambda^C(2i+1)``;
    - 6 (gases): ``n - 1 = C1 + sum_i C(2i) / (C(2i+1) - lambda^-2)``;
    - 7 (Herzberger): ``n = C1 + C2 / (lambda^2 - 0.028) + C3 / (lambda^2 - 0.028)^2
      + C4 lambda^2 + C5 lambda^4 + C6 lambda^6``;
    - 8 (Retro): ``(n^2 - 1) / (n^2 + 2) = C1 + C2 lambda^2 / (lambda^2 - C3) + C4 lambda^2``;
    - 9 (Exotic): ``n^2 = C1 + C2 / (lambda^2 - C3) + C4 (lambda - C5) /
      ((lambda - C5)^2 + C6)``.

    (Polyanskiy, refractiveindex.info, "Dispersion formulas".)
    """

    number: int
    coefficients: tuple[float, ...]
    range_nm: tuple[float, float]

    @property
    def coverage(self) -> tuple[float, float]:
        """The wavelength range (nm) the formula is valid for."""
        return self.range_nm

    def __call__(self, wavelengths: np.ndarray) -> np.ndarray:
        """Evaluate the formula at ``wavelengths``.

        Parameters
        ----------
        wavelengths : numpy.ndarray
            Wavelengths in nm, within :attr:`coverage` (the formula takes them in um).

        Returns
        -------
        numpy.ndarray
            The index the formula gives, float64, the shape of ``wavelengths``; NaN where
            a square root of the formula has a negative argument.
        """
        lam = np.asarray(wavelengths, dtype=np.float64) / 1000.0  # um
        c = self.coefficients
        pairs = list(zip(c[1::2], c[2::2], strict=False))
        total = np.full(lam.shape, c[0] if c else 0.0)
        if self.number in (1, 2):
            lam2 = lam * lam
            for b, r in pairs:
                total = total + b * lam2 / (lam2 - (r * r if self.number == 1 else r))
            return np.sqrt(1.0 + total)
        if self.number in (3, 5):
            for b, e in pairs:
                total = total + b * lam**e
            return np.sqrt(total) if self.number == 3 else total
        if self.number == 6:
            for b, r in pairs:
                total = total + b / (r - lam**-2.0)
            return 1.0 + total
        k = list(c) + [0.0] * (17 - len(c)) if len(c) < 17 else list(c)
        lam2 = lam * lam
        if self.number == 4:
            total = (
                k[0]
                + k[1] * lam ** k[2] / (lam2 - k[3] ** k[4])
                + k[5] * lam ** k[6] / (lam2 - k[7] ** k[8])
            )
            for b, e in zip(k[9::2], k[10::2], strict=False):
                total = total + b * lam**e
            return np.sqrt(total)
        if self.number == 7:
            q = 1.0 / (lam2 - 0.028)
            return k[0] + k[1] * q + k[2] * q * q + k[3] * lam2 + k[4] * lam2**2 + k[5] * lam2**3
        if self.number == 8:
            lorentz = k[0] + k[1] * lam2 / (lam2 - k[2]) + k[3] * lam2
            return np.sqrt((1.0 + 2.0 * lorentz) / (1.0 - lorentz))
        # formula 9
        x = lam - k[4]
        return np.sqrt(k[0] + k[1] / (lam2 - k[2]) + k[3] * x / (x * x + k[5]))


Dispersion = float | Tabulated | Formula


def _coverage(part: Dispersion) -> tuple[float, float]:
    return (-math.inf, math.inf) if isinstance(part, float) else part.coverage


@dataclass(frozen=True, eq=False)
class Material:
    """A material's complex refractive index ``n + ik`` against wavelength.

    ``name``: how films refer to it; ``n``, ``k``: a constant, a :class:`Tabulated`
    or a :class:`Formula` each (``k >= 0``); ``source``: where the data come from (a
    citation, a file); ``path``: the file read, if any.
    """

    name: str
    n: Dispersion
    k: Dispersion = 0.0
    source: str = ""
    path: str = field(default="", compare=False)

    @property
    def coverage(self) -> tuple[float, float]:
        """The wavelength range (nm) where both n and k are defined."""
        (a, b), (c, d) = _coverage(self.n), _coverage(self.k)
        return max(a, c), min(b, d)

    @property
    def absorbing(self) -> bool:
        """Whether k is anywhere > 0 (a constant 0 or an all-zero table is not)."""
        k = self.k
        if isinstance(k, float):
            return k > 0
        if isinstance(k, Tabulated):
            return bool(np.any(k.values > 0))
        return True

    def covers(self, lo: float = VISIBLE_NM[0], hi: float = VISIBLE_NM[1]) -> bool:
        """Whether the data cover ``[lo, hi]`` nm.

        Parameters
        ----------
        lo, hi : float, optional
            The range in nm (default :data:`VISIBLE_NM`, 380-780 nm).

        Returns
        -------
        bool
        """
        a, b = self.coverage
        return a <= lo and b >= hi

    def index(self, wavelengths: npt.ArrayLike) -> np.ndarray:
        """Return the complex index ``n + ik`` at ``wavelengths`` (nm).

        Parameters
        ----------
        wavelengths : array_like
            Wavelengths in nm, within :attr:`coverage`.

        Returns
        -------
        numpy.ndarray
            complex128, the shape of ``wavelengths``.

        Raises
        ------
        ocio_thinfilm.checks.ParameterError
            For wavelengths outside the data (no extrapolation).

        Examples
        --------
        >>> constant("glass", 1.5, 0.01).index([400.0, 700.0]).tolist()
        [(1.5+0.01j), (1.5+0.01j)]
        """
        wl = np.asarray(wavelengths, dtype=np.float64)
        lo, hi = self.coverage
        if wl.size and (wl.min() < lo - 1e-9 or wl.max() > hi + 1e-9):
            raise ParameterError(
                "wavelengths",
                f" must lie within {self.name}'s data, {lo:g}-{hi:g} nm, got "
                f"{wl.min():g}-{wl.max():g} nm",
            )
        parts = []
        for part in (self.n, self.k):
            parts.append(np.full(wl.shape, part) if isinstance(part, float) else part(wl))
        return (parts[0] + 1j * parts[1]).astype(np.complex128)


def check_nk(name: str, what: str, values: np.ndarray, parameter: str) -> None:
    """Refuse non-finite values, ``n <= 0`` and ``k < 0`` (gain) of material ``name``.

    Parameters
    ----------
    name : str
        The material (named in the message).
    what : str
        ``"n"`` or ``"k"``.
    values : numpy.ndarray
        The values to check.
    parameter : str
        The Python parameter the error names.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        Naming ``parameter``, the material and the bound.
    """
    if not np.all(np.isfinite(values)):
        raise ParameterError(parameter, f": {name}: {what} must be finite")
    if what == "n" and np.any(values <= 0):
        raise ParameterError(parameter, f": {name}: n must be > 0, got {values.min():g}")
    if what == "k" and np.any(values < 0):
        raise ParameterError(
            parameter, f": {name}: k must be >= 0 (k < 0 is gain), got {values.min():g}"
        )


def check_formula(name: str, formula: Formula, parameter: str) -> None:
    """Refuse a dispersion formula whose ``n`` is not finite and > 0 over its range.

    Parameters
    ----------
    name : str
        The material (named in the message).
    formula : Formula
        The formula, probed at 64 wavelengths across its range.
    parameter : str
        The Python parameter the error names.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        As :func:`check_nk`.
    """
    with np.errstate(all="ignore"):
        check_nk(name, "n", formula(np.linspace(*formula.range_nm, 64)), parameter)


def constant(name: str, n: float, k: float = 0.0, *, source: str = "") -> Material:
    """Return a material of constant index ``n + ik``.

    Parameters
    ----------
    name : str
        Its name.
    n : float
        Real part, > 0.
    k : float, optional
        Extinction coefficient, >= 0 (default 0: transparent).
    source : str, optional
        Where the value comes from.

    Returns
    -------
    Material

    Examples
    --------
    >>> constant("oil", 1.47).index(550.0).real.item()
    1.47
    >>> constant("gain", 1.5, -0.1)
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: k: gain: k must be >= 0 (k < 0 is gain), got -0.1
    """
    n_value, k_value = as_real("n", n), as_real("k", k)
    check_nk(name, "n", np.array([n_value]), "n")
    check_nk(name, "k", np.array([k_value]), "k")
    return Material(name, n_value, k_value, source or f"constant n = {n_value:g}, k = {k_value:g}")


def checked_table(
    name: str, wl_nm: npt.ArrayLike, values: npt.ArrayLike, what: str, where: str
) -> Tabulated:
    """Return a read-only :class:`Tabulated` of ``values`` (``n`` or ``k``) at ``wl_nm``.

    Parameters
    ----------
    name : str
        The material.
    wl_nm : array_like
        Wavelengths in nm: at least 2, finite and strictly increasing.
    values : array_like
        The values, checked with :func:`check_nk`.
    what : str
        ``"n"`` or ``"k"``.
    where : str
        The file (and line) named in errors.

    Returns
    -------
    Tabulated

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        Naming ``path`` and ``where``.
    """
    wl = np.asarray(wl_nm, dtype=np.float64)
    v = np.asarray(values, dtype=np.float64)
    if wl.size < 2:
        raise ParameterError("path", f": {where}: a table needs at least 2 rows")
    if not np.all(np.isfinite(wl)) or np.any(np.diff(wl) <= 0):
        raise ParameterError(
            "path", f": {where}: wavelengths must be finite and strictly increasing"
        )
    check_nk(name, what, v, "path")
    wl.setflags(write=False)
    v.setflags(write=False)
    return Tabulated(wl, v)
