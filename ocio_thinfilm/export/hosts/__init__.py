"""The film-as-material table in renderers: one writer per host.

Each writer takes only the table's file names and numbers, :class:`TableFiles` (the table
itself: ``export material``). The tables' axes are node-centred
(:func:`ocio_thinfilm.lut.material_tables.axis_nodes`): every host reads fraction ``f`` of
an axis of ``N`` texels at the texture coordinate ``(f (N - 1) + 0.5) / N``.

- :mod:`.blender` -- a Python script Blender runs: the film's node group and material
  (Cycles, EEVEE);
- :mod:`.three` -- an ES module for three.js that turns a ``MeshPhysicalMaterial`` into
  the film;
- :mod:`.gltf` -- a binary glTF of the film on a sample sphere (a fitted
  ``KHR_materials_iridescence`` fallback and the exact table in a vendor extension) and
  the three.js ``GLTFLoader`` plugin that reads it;
- :mod:`.materialx` -- a MaterialX 1.39 document: the film as a node reading the tables
  by thickness and view angle, feeding BSDFs;
- :mod:`.mitsuba` -- no table: a spectral Mitsuba 3 BSDF evaluating the film's stack
  exactly per sampled wavelength (the optional extra ``mitsuba``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path, PurePath

from ocio_thinfilm.checks import ParameterError, as_pair

__all__ = ["TableFiles", "thickness_range", "table_name"]


@dataclass(frozen=True)
class TableFiles:
    """A film's written material tables, as the host writers see them.

    ``key``: the film's key; ``name``: its display name (the key where the film file
    gives none); ``reflectance``, ``transmittance``: the EXRs' paths (``transmittance``
    None unless the film is free-standing); ``range_um``: the thickness axis ``(lo,
    hi)``; ``size``: ``(width, height)`` in texels; ``space``: the tables' scene-linear
    space; ``outside``: ``(fraction, lowest)``, the fraction of the tables' texels with a
    negative channel (outside the space's gamut) and the most negative channel value;
    ``others``: the same film's tables in further spaces, written beside these (their
    own ``others`` empty).
    """

    key: str
    name: str
    reflectance: Path
    transmittance: Path | None
    range_um: tuple[float, float]
    size: tuple[int, int]
    space: str
    outside: tuple[float, float] = (0.0, 0.0)
    others: tuple[TableFiles, ...] = ()


def thickness_range(range_um: object) -> tuple[float, float]:
    """Return the table's thickness axis ``(lo, hi)`` in µm, checked.

    Parameters
    ----------
    range_um : sequence of two numbers
        The film's ``range_um``: the thickness at u = 0 and u = 1 of the table.

    Returns
    -------
    tuple of float
        ``(lo, hi)``.

    Raises
    ------
    ParameterError
        Unless ``0 <= lo < hi`` and both are finite.
    """
    lo, hi = as_pair("range_um", range_um)
    if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo < hi):
        raise ParameterError("range_um", f" must be finite with 0 <= lo < hi, got ({lo}, {hi})")
    return lo, hi


def table_name(parameter: str, path: object) -> str:
    """Return the file name of a table EXR, checked.

    A host loads the table from beside the material's file.

    Parameters
    ----------
    parameter : str
        The Python parameter's name, for the error message.
    path : str or os.PathLike
        The table's path; only its last component is kept.

    Returns
    -------
    str
        The file name, ending in ``.exr``.

    Raises
    ------
    ParameterError
        If it does not end in ``.exr`` or holds a quote, ``<``, ``>`` or ``&``.
    """
    if not isinstance(path, (str, PurePath)):
        raise TypeError(f"{parameter} must be a path, got {type(path).__name__}")
    name = PurePath(path).name
    if not name.lower().endswith(".exr") or any(c in name for c in "\"'<>&\\"):
        raise ParameterError(
            parameter, f" must be an .exr file name without quotes, <, > or &, got {name!r}"
        )
    return name
