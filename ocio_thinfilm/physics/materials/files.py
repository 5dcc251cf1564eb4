"""A material file, read by its extension: a CSV table or a refractiveindex.info file."""

from __future__ import annotations

from pathlib import Path

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.physics.materials.model import Material
from ocio_thinfilm.physics.materials.refractiveindex import read_refractiveindex_yaml
from ocio_thinfilm.physics.materials.tables import read_csv

__all__ = ["read_material"]


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
