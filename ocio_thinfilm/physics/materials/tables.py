r"""CSV tables of optical constants: a header ``wavelength_nm,n,k``, one row per wavelength.

``k`` may be left out (0: transparent); ``#`` comments are allowed.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

import numpy as np

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.physics.materials.model import Dispersion, Material, checked_table

__all__ = ["read_csv"]


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
    n = checked_table(name, a[:, 0], a[:, 1], "n", where)
    k: Dispersion = checked_table(name, a[:, 0], a[:, 2], "k", where) if len(header) == 3 else 0.0
    return Material(name, n, k, f"table {path.name}", str(path))
