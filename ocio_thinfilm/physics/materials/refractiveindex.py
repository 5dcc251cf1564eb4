"""refractiveindex.info database files (YAML): tabulated data and dispersion formulas 1-9.

References
----------
Polyanskiy, M. N. (2024). Refractiveindex.info database of optical constants.
Scientific Data 11, 94. https://doi.org/10.1038/s41597-023-02898-2.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.physics.materials.model import (
    FORMULAS,
    Dispersion,
    Formula,
    Material,
    check_formula,
    checked_table,
)
from ocio_thinfilm.physics.materials.yaml_subset import numbers, parse

__all__ = ["read_refractiveindex_yaml"]


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
    top, entries = parse(text, where)
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
                numbers(row, where, line_data + 1 + j)
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
                n = checked_table(name, wl, a[:, 1], "n", f"{where}:{line_data}")
            if "k" in what:
                k = checked_table(name, wl, a[:, -1], "k", f"{where}:{line_data}")
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
            r = numbers(wrange, where, line_r)
            line_c, coefficients = entry.get("coefficients", (line, ""))
            c = numbers(coefficients, where, line_c)
            if len(r) != 2 or not 0 < r[0] < r[1] or not c:
                raise ParameterError(
                    "path", f": {where}:{line}: {kind} needs wavelength_range and coefficients"
                )
            formula = Formula(number, tuple(c), (r[0] * 1000.0, r[1] * 1000.0))
            check_formula(name, formula, "path")
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
