"""A film file: TOML -> :class:`Film` objects (their spectra: :mod:`.films`).

A film file (read with the standard library's :mod:`tomllib`) names materials and
films::

    [materials.Oil]          # also k = ..., file = "x.csv" / "x.yml", database = "..."
    n = 1.47

    [films.OilOnWater]
    stack = ["air", "Oil", "water"]   # incident medium, layers, substrate
    vary = "Oil"                      # the layer whose physical thickness is the pixel
    range_um = [0, 1.5]               # the pixel value's range

Materials not defined in the file come from the built-in library
(:mod:`ocio_thinfilm.physics.materials`); relative paths resolve against the film file's
folder. Every key (``thickness_nm``, ``angle_deg``, ``model``, ``name``, ``normalise``,
``illuminant``, ``adaptation``), with the full example: docs/films.md.

Every error is a :class:`~ocio_thinfilm.checks.ParameterError` for the ``films``
parameter on one line naming the file, the film (or material), the key and what is
allowed.
"""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.physics import light as viewing
from ocio_thinfilm.physics import materials
from ocio_thinfilm.physics.materials import VISIBLE_NM, Material

__all__ = [
    "MODELS",
    "MAX_RANGE_UM",
    "NAME_FORMAT",
    "INCIDENT_MAX_K",
    "PAPER_WAVELENGTH",
    "Film",
    "parse_films",
    "read_films",
    "check_names",
]

#: The film models (see the module docstring).
MODELS = ("exact", "paper")
#: Largest thickness (um) a film's range may reach.
MAX_RANGE_UM = 20.0
#: The colour space name of a film without a ``name``.
NAME_FORMAT = "Thin Film {key}"
#: Largest k of an incident medium (taken as 0: a glass's bulk absorption).
INCIDENT_MAX_K = 1e-4
#: Wavelength at which the paper model takes its one index (nm).
PAPER_WAVELENGTH = 550.0

_MATERIAL_KEYS = ("n", "k", "file", "database")
_FILM_KEYS = (
    "stack",
    "vary",
    "thickness_nm",
    "range_um",
    "angle_deg",
    "model",
    "name",
    "normalise",
    "illuminant",
    "adaptation",
)


@dataclass(frozen=True, eq=False)
class Film:
    """A film a user described: its stack and the layer whose thickness varies.

    ``key``: its key in the film file; ``name``: its colour space's name; ``stack``:
    the media from the incidence side (incident medium, layers, substrate);
    ``vary``: the varying layer (0-based among the layers, ``stack[vary + 1]``);
    ``thickness_nm``: every layer's thickness (the varying one's entry is 0);
    ``range_um``: the pixel value's range (physical thickness of the varying layer, um);
    ``angle_deg``: the viewing angle in the incident medium; ``model``: ``"exact"`` or
    ``"paper"``; ``source``: the film file; ``normalise``: its table scaled so that
    its brightest entry has Y = 1 (for compositors that expect a colour, not a
    reflectance); ``illuminant``, ``adaptation``: the light it is seen under and the
    chromatic adaptation to the scene white D65
    (:mod:`ocio_thinfilm.physics.light`).
    """

    key: str
    name: str
    stack: tuple[Material, ...]
    vary: int
    thickness_nm: tuple[float, ...]
    range_um: tuple[float, float]
    angle_deg: float = 0.0
    model: str = "exact"
    source: str = ""
    normalise: bool = False
    illuminant: str = viewing.SCENE_ILLUMINANT
    adaptation: str = viewing.DEFAULT_ADAPTATION

    @property
    def layers(self) -> tuple[Material, ...]:
        """The layers between the incident medium and the substrate."""
        return self.stack[1:-1]

    @property
    def varying(self) -> Material:
        """The material of the varying layer."""
        return self.stack[self.vary + 1]

    def describe(self) -> str:
        """Describe the film in one line.

        Returns
        -------
        str
            The stack, the varying layer, the range, the angle and the model.

        Examples
        --------
        >>> water = materials.builtin("water")
        >>> Film("W", "Thin Film W", (materials.builtin("air"), water, materials.builtin("air")),
        ...      0, (0.0,), (0.0, 1.5)).describe()
        'air | water (0-1.5 um) | air at 0 deg, exact model'
        """
        parts = [self.stack[0].name]
        for j, layer in enumerate(self.layers):
            if j == self.vary:
                parts.append(f"{layer.name} ({self.range_um[0]:g}-{self.range_um[1]:g} um)")
            else:
                parts.append(f"{layer.name} {self.thickness_nm[j]:g} nm")
        parts.append(self.stack[-1].name)
        seen = self.illuminant != viewing.SCENE_ILLUMINANT
        light = f", under {self.illuminant} ({self.adaptation} to D65)" if seen else ""
        return f"{' | '.join(parts)} at {self.angle_deg:g} deg, {self.model} model{light}"


# --------------------------------------------------------------------------- #
# Reading and checking a film file
# --------------------------------------------------------------------------- #
class _Where:
    """Words one error: ``films: FILE: film 'KEY': KEY2: ...``."""

    def __init__(self, path: str, what: str) -> None:
        self.path, self.what = path, what

    def error(self, key: str, detail: str) -> ParameterError:
        return ParameterError("films", f" {self.path}: {self.what}: {key}: {detail}")


def _toml(text: str, path: str) -> dict[str, Any]:
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        message = str(error)
        m = re.search(r"\(at line (\d+), column (\d+)\)", message)
        end = "(at end of document)" in message
        line = m.group(1) if m else str(max(1, len(text.splitlines()))) if end else ""
        where = f"{path}:{line}" if line else path
        detail = re.sub(r"\s*\(at (line \d+, column \d+|end of document)\)", "", message)
        if m:
            detail += f" (column {m.group(2)})"
        elif end:
            detail += " (at the end of the file)"
        raise ParameterError("films", f" {where}: TOML syntax error: {detail}") from None


def _number(where: _Where, key: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise where.error(key, f"must be a number, got {value!r}")
    if not math.isfinite(value):
        raise where.error(key, f"must be finite, got {value!r}")
    return float(value)


def _material(key: str, table: Any, folder: Path, path: str) -> Material:
    where = _Where(path, f"material {key!r}")
    if not isinstance(table, dict):
        raise where.error("materials", "must be a table with n (and k) or file")
    unknown = sorted(set(table) - set(_MATERIAL_KEYS))
    if unknown:
        raise where.error(unknown[0], f"unknown key; allowed: {', '.join(_MATERIAL_KEYS)}")
    given = [key for key in ("n", "file", "database") if key in table]
    if len(given) != 1:
        raise where.error(
            given[1] if len(given) > 1 else "n",
            "give one of n (and k), file or database (shelf/book/page)",
        )
    if "database" in table:
        if "k" in table:
            raise where.error("k", "goes with n, not with database (the page holds k)")
        try:
            material = materials.from_database(table["database"], key)
        except ParameterError as error:
            raise where.error("database", error.detail.lstrip(": ")) from None
        if not material.covers():
            lo, hi = material.coverage
            raise where.error(
                "database",
                f"{table['database']} covers {lo:g}-{hi:g} nm; a film needs data over "
                f"{VISIBLE_NM[0]:g}-{VISIBLE_NM[1]:g} nm",
            )
        return material
    if "file" in table:
        if "k" in table:
            raise where.error("k", "goes with n, not with file (the file holds k)")
        name = table["file"]
        if not isinstance(name, str) or not name:
            raise where.error("file", f"must be a file name, got {name!r}")
        file = Path(name) if Path(name).is_absolute() else folder / name
        if file.suffix.lower() not in (".csv", ".yml", ".yaml"):
            raise where.error(
                "file", f"{name}: must be a .csv table (wavelength_nm,n,k) or a .yml file"
            )
        try:
            material = materials.read_material(file, key)
        except OSError as error:
            raise where.error("file", f"cannot read {file}: {error.strerror or error}") from None
        except ParameterError as error:
            raise where.error("file", error.detail.lstrip(": ")) from None
        lo, hi = material.coverage
        if not material.covers():
            raise where.error(
                "file",
                f"{name} covers {lo:g}-{hi:g} nm; a film needs data over "
                f"{VISIBLE_NM[0]:g}-{VISIBLE_NM[1]:g} nm",
            )
        return material
    n = _number(where, "n", table["n"])
    k = _number(where, "k", table.get("k", 0.0))
    if n <= 0:
        raise where.error("n", f"must be > 0, got {n:g}")
    if k < 0:
        raise where.error("k", f"must be >= 0 (k < 0 is gain, not absorption), got {k:g}")
    return materials.constant(key, n, k, source=f"{path}: n = {n:g}, k = {k:g}")


def _layer(where: _Where, key: str, value: Any, layers: list[str]) -> int:
    """Return the index of a layer named by its material (once in the stack) or its position.

    Positions count from 1 (1 = first); the index returned counts from 0.
    """
    if isinstance(value, bool):
        raise where.error(key, f"must be a layer of the stack {layers}, got {value!r}")
    if isinstance(value, int):
        if not 1 <= value <= len(layers):
            raise where.error(key, f"layer positions are 1-{len(layers)} ({layers}), got {value}")
        return value - 1
    if isinstance(value, str):
        hits = [j for j, name in enumerate(layers) if name == value]
        if len(hits) == 1:
            return hits[0]
        if len(hits) > 1:
            raise where.error(
                key, f"{value!r} appears {len(hits)} times in the stack: give its position"
            )
    raise where.error(key, f"must be one of the stack's layers {layers}, got {value!r}")


def _film(key: str, table: Any, known: Mapping[str, Material], path: str) -> Film:
    where = _Where(path, f"film {key!r}")
    if not isinstance(table, dict):
        raise where.error("films", "must be a table")
    unknown = sorted(set(table) - set(_FILM_KEYS))
    if unknown:
        raise where.error(unknown[0], f"unknown key; allowed: {', '.join(_FILM_KEYS)}")
    stack, layers = _stack(where, table, known)
    vary = _vary(where, table, layers)
    thickness = _thicknesses(where, table, layers, vary)
    lo, hi = _range(where, table)
    angle, model, normalise = _model(where, table, layers)
    light = _light(where, table)
    name = table.get("name", NAME_FORMAT.format(key=key))
    if not isinstance(name, str) or not name.strip() or name != name.strip():
        raise where.error("name", f"must be a non-empty name without outer spaces, got {name!r}")
    return Film(
        key=key,
        name=name,
        stack=tuple(stack),
        vary=vary,
        thickness_nm=tuple(thickness),
        range_um=(lo, hi),
        angle_deg=angle,
        model=model,
        source=path,
        normalise=normalise,
        illuminant=light[0],
        adaptation=light[1],
    )


def _stack(
    where: _Where, table: dict, known: Mapping[str, Material]
) -> tuple[list[Material], list[str]]:
    """Return a film's ``stack`` as materials (incident medium lossless) and its layers."""
    if "stack" not in table:
        raise where.error(
            "stack", "the key is missing: list the incident medium, layer(s) and substrate"
        )
    stack_names = table.get("stack")
    if (
        not isinstance(stack_names, list)
        or len(stack_names) < 3
        or not all(isinstance(s, str) for s in stack_names)
    ):
        raise where.error(
            "stack",
            "must list at least 3 material names: incident medium, layer(s), substrate; "
            f"got {stack_names!r}",
        )
    stack = []
    for name in stack_names:
        if name in known:
            stack.append(known[name])
        elif materials.find_builtin(name) is not None:
            stack.append(materials.builtin(name))
        else:
            defined = f"the file's materials ({', '.join(known)}) or " if known else ""
            raise where.error(
                "stack",
                f"unknown material {name!r}; allowed: {defined}the built-in "
                f"{', '.join(materials.builtin_names())}",
            )
    layers = stack_names[1:-1]
    if stack[0].absorbing:
        k = stack[0].index(np.linspace(*VISIBLE_NM, 81)).imag.max()
        if k > INCIDENT_MAX_K:
            raise where.error(
                "stack",
                f"the incident medium {stack_names[0]!r} absorbs (k up to {k:.3g}); it must "
                f"be transparent, k <= {INCIDENT_MAX_K:g}",
            )
        # a glass's bulk absorption (k ~ 1e-8): the incident medium is taken lossless
        stack[0] = Material(stack[0].name, stack[0].n, 0.0, stack[0].source, stack[0].path)
    return stack, layers


def _vary(where: _Where, table: dict, layers: list[str]) -> int:
    """Return the index of the varying layer among ``layers``."""
    if "vary" in table:
        return _layer(where, "vary", table["vary"], layers)
    if len(layers) == 1:
        return 0
    raise where.error("vary", f"must name the varying layer, one of {layers}")


def _thicknesses(where: _Where, table: dict, layers: list[str], vary: int) -> list[float]:
    """Return each layer's thickness (nm), 0 for the varying one."""
    thickness = [math.nan] * len(layers)
    thickness[vary] = 0.0
    given = table.get("thickness_nm", {})
    if isinstance(given, list):
        if len(given) != len(layers):
            raise where.error("thickness_nm", f"a list needs one entry per layer {layers}")
        items = [(j + 1, v) for j, v in enumerate(given) if j != vary]
    elif isinstance(given, dict):
        items = list(given.items())
    else:
        raise where.error("thickness_nm", "must be a table {layer = nm} or a list, one per layer")
    for layer_key, value in items:
        j = _layer(
            where, "thickness_nm", int(layer_key) if str(layer_key).isdigit() else layer_key, layers
        )
        if j == vary:
            raise where.error(
                "thickness_nm", f"{layers[j]!r} is the varying layer: its thickness is the pixel"
            )
        t = _number(where, "thickness_nm", value)
        if t < 0:
            raise where.error("thickness_nm", f"{layers[j]}: must be >= 0 nm, got {t:g}")
        thickness[j] = t
    missing = [layers[j] for j in range(len(layers)) if math.isnan(thickness[j])]
    if missing:
        raise where.error("thickness_nm", f"needs the thickness of {', '.join(missing)} (nm)")
    return thickness


def _range(where: _Where, table: dict) -> tuple[float, float]:
    """Return the film's thickness range ``range_um`` (lo, hi) in um."""
    rng = table.get("range_um", [0.0, 1.5])
    if not isinstance(rng, list) or len(rng) != 2:
        raise where.error("range_um", f"must be [lo, hi] in um, got {rng!r}")
    lo, hi = (_number(where, "range_um", v) for v in rng)
    if lo < 0 or not lo < hi or hi > MAX_RANGE_UM:
        raise where.error(
            "range_um", f"must satisfy 0 <= lo < hi <= {MAX_RANGE_UM:g} um, got [{lo:g}, {hi:g}]"
        )
    return lo, hi


def _model(where: _Where, table: dict, layers: list[str]) -> tuple[float, str, bool]:
    """Return the film's ``angle_deg``, ``model`` and ``normalise``."""
    angle = _number(where, "angle_deg", table.get("angle_deg", 0.0))
    if not 0 <= angle < 90:
        raise where.error("angle_deg", f"must be in [0, 90) degrees, got {angle:g}")
    model = table.get("model", "exact")
    if model not in MODELS:
        raise where.error("model", f"must be one of {', '.join(MODELS)}, got {model!r}")
    if model == "paper" and len(layers) != 1:
        raise where.error("model", "'paper' (Eq. 7/8) describes one layer; use 'exact' for stacks")
    normalise = table.get("normalise", False)
    if not isinstance(normalise, bool):
        raise where.error("normalise", f"must be true or false, got {normalise!r}")
    return angle, model, normalise


def _light(where: _Where, table: dict) -> list[str]:
    """Return the ``illuminant`` and ``adaptation`` the film is seen under."""
    light = []
    for option, default, check in (
        ("illuminant", viewing.SCENE_ILLUMINANT, viewing.check_illuminant),
        ("adaptation", viewing.DEFAULT_ADAPTATION, viewing.check_adaptation),
    ):  # the light it is seen under
        try:
            light.append(check(table.get(option, default)))
        except ParameterError as error:
            raise where.error(option, error.detail.lstrip(": ")) from None
    return light


def parse_films(text: str, path: str | Path = "<films>", *, taken: Iterable[str] = ()) -> dict:
    r"""Films from the text of a film file (see the module docstring).

    Parameters
    ----------
    text : str
        The TOML text.
    path : str or pathlib.Path, optional
        The file it came from: named in errors; relative material files resolve
        against its folder.
    taken : iterable of str, optional
        Colour space names in use (:func:`check_names`); the registry's are always.

    Returns
    -------
    dict
        Film key -> :class:`Film`, in the file's order.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``films``) one line naming the file (with the line of a TOML syntax error),
        the film or material, the key and what is allowed.

    Examples
    --------
    >>> films = parse_films('[films.Soap]\nstack = ["air", "soap film", "air"]')
    >>> films["Soap"].name, films["Soap"].range_um
    ('Thin Film Soap', (0.0, 1.5))
    >>> parse_films('[films.Soap]\nstack = ["air", "soap", "air"]\nangle_deg = 95')
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: films <films>: film 'Soap': angle_deg: must be ...
    """
    where = str(path)
    data = _toml(text, where)
    unknown = sorted(set(data) - {"materials", "films"})
    if unknown:
        raise ParameterError(
            "films", f" {where}: {unknown[0]}: unknown table; allowed: materials, films"
        )
    folder = Path(path).parent
    user_materials = data.get("materials", {})
    films = data.get("films", {})
    if not isinstance(user_materials, dict) or not isinstance(films, dict):
        raise ParameterError("films", f" {where}: materials and films must be tables")
    known = {key: _material(key, t, folder, where) for key, t in user_materials.items()}
    if not films:
        raise ParameterError("films", f" {where}: films: no [films.NAME] table")
    out = {key: _film(key, t, known, where) for key, t in films.items()}
    check_names(out.values(), taken)
    return out


def read_films(path: str | Path, *, taken: Iterable[str] = ()) -> dict:
    """Films from a film file: :func:`parse_films` of its text.

    Parameters
    ----------
    path : str or pathlib.Path
        The TOML file.
    taken : iterable of str, optional
        Colour space names in use besides the registry's.

    Returns
    -------
    dict
        Film key -> :class:`Film`.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``films``) naming the file if it cannot be read or is not UTF-8 text, and the
        errors of :func:`parse_films`.
    """
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as error:
        raise ParameterError("films", f" {p}: cannot read: {error.strerror or error}") from None
    except UnicodeDecodeError:
        raise ParameterError("films", f" {p}: not a UTF-8 text (TOML) file") from None
    return parse_films(text, p, taken=taken)


def _registry_names() -> list[str]:
    """Return the registry's colour space names.

    The config adds a few more of its own, which
    :func:`ocio_thinfilm.config.data.film_parts` checks with the whole config.
    """
    return (
        [registry.REFERENCE]
        + list(registry.SCENE_LINEAR_SPACES)
        + list(registry.ENCODED_SPACES)
        + list(registry.THIN_FILM_SPACES)
        + [d.colorspace for d in registry.ALL_DISPLAY_LIST]
    )


def check_names(films: Iterable[Film], taken: Iterable[str] = ()) -> None:
    """Refuse films whose colour space names repeat or clash with the config's.

    OCIO compares names without case; a film's name must differ from every other film's
    and from every colour space of the config (``taken``, and the registry's).

    Parameters
    ----------
    films : iterable of Film
        The films.
    taken : iterable of str, optional
        Names (and aliases) in use besides the registry's.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``films``) naming the film, its ``name`` and the clash.
    """
    used = {n.casefold(): f"an existing colour space ({n!r})" for n in _registry_names()}
    used.update({n.casefold(): f"an existing colour space ({n!r})" for n in taken})
    for film in films:
        folded = film.name.casefold()
        if folded in used:
            raise ParameterError(
                "films",
                f" {film.source}: film {film.key!r}: name: {film.name!r} is already "
                f"{used[folded]}; set a different name",
            )
        used[folded] = f"the name of film {film.key!r}"
