"""A render's OCIO processors, created from one config file on first use.

A render goes through an OCIO config -- by default the package's baked config
(:data:`DEFAULT_CONFIG`: in a checkout its ``configs/thinfilm/config.ocio``, baked first
when missing; installed from a wheel, the copy the wheel carries as package data) -- so
it is an end-to-end test of what users load:

- a scene's table (:class:`ocio_thinfilm.render.scenes.TableSpec`) is the config's
  thin-film input colour space, pixel encoding -> CIE-XYZ-D65
  (``config.getProcessor("Thin Film Morpho Iridescence", "CIE-XYZ-D65")``);
- a display view is ``config.getProcessor("CIE-XYZ-D65", display, view, ...)``:
  CIE-XYZ-D65 -> display code values.

Only the colour spaces and views a scene uses become processors
(:attr:`ConfigProcessors.created` lists them); nothing is computed from the spectra at
render time.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.io import StrPath
from ocio_thinfilm.lut import ocio_ops, tables

if TYPE_CHECKING:
    from ocio_thinfilm.render.scenes import Lookup, Picture, TableSpec

__all__ = [
    "DEFAULT_CONFIG",
    "PACKAGE_CONFIG",
    "table_colorspace",
    "load_config",
    "ConfigProcessors",
    "make_lookup",
    "display_image",
]

#: The baked config a wheel carries as package data (setup.py copies the checkout's
#: ``configs/thinfilm`` into ``ocio_thinfilm/data/thinfilm``); read-only, never baked.
PACKAGE_CONFIG = Path(
    str(resources.files("ocio_thinfilm").joinpath("data", "thinfilm", "config.ocio"))
)


def _checkout_config() -> Path | None:
    """Return ``configs/thinfilm/config.ocio`` of the checkout this module runs from.

    The checkout is recognised by the repository's pyproject.toml beside the package;
    None when installed.
    """
    root = Path(__file__).resolve().parents[2]
    try:
        if 'name = "ocio-thinfilm"' in (root / "pyproject.toml").read_text(encoding="utf-8"):
            return root / "configs" / "thinfilm" / "config.ocio"
    except OSError:
        pass
    return None


#: The config a render goes through by default: a checkout's ``configs/thinfilm``
#: (baked with ``ocio-thinfilm bake`` first when it is missing), else
#: :data:`PACKAGE_CONFIG`. Nothing is ever written beside the installed code.
DEFAULT_CONFIG = _checkout_config() or PACKAGE_CONFIG


def table_colorspace(spec: TableSpec) -> str:
    """Return the config's input colour space for a scene's table.

    The thin-film colour space (pixel value -> CIE-XYZ-D65) of the table the config
    ships for the spec's kind.

    Parameters
    ----------
    spec : ocio_thinfilm.render.scenes.TableSpec
        The table a scene declares.

    Returns
    -------
    str
        The colour space's name.

    Raises
    ------
    ValueError
        If the spec's range or entries are not those of the config's table (the Morpho
        table: cos(theta) in [0, 1] with :data:`~ocio_thinfilm.lut.tables.MORPHO_SIZE`
        entries; the thickness tables: t' in [0, 100] um with
        :data:`~ocio_thinfilm.lut.tables.FILM_SIZE` entries).

    Examples
    --------
    >>> from ocio_thinfilm.render.scenes import MORPHO_TABLE
    >>> table_colorspace(MORPHO_TABLE)
    'Thin Film Morpho Iridescence'
    """
    lo, hi = spec.range
    if spec.kind == "user":
        return spec.space
    if spec.kind == "morpho":
        if (lo, hi) != (0.0, 1.0) or spec.entries != tables.MORPHO_SIZE:
            raise ValueError(
                f"the config's Morpho table covers cos(theta) in [0, 1] with "
                f"{tables.MORPHO_SIZE} entries, got {spec}"
            )
    elif (lo, hi) != (0.0, tables.FILM_TMAX_UM) or spec.entries != tables.FILM_SIZE:
        raise ValueError(
            f"the config's thickness tables cover t' in [0, {tables.FILM_TMAX_UM:g}] "
            f"um with {tables.FILM_SIZE} entries, got {spec}"
        )
    return registry.thin_film_space_for_kind(spec.kind).name


def load_config(config: StrPath | None = None) -> ocio_ops.Config:
    """Load the OCIO config of the file ``config``.

    The default config :data:`DEFAULT_CONFIG` is baked with
    :func:`ocio_thinfilm.export.bake.bake` first when missing, unless it is the
    installed :data:`PACKAGE_CONFIG`.

    Parameters
    ----------
    config : str or os.PathLike, optional
        The config file (default :data:`DEFAULT_CONFIG`).

    Returns
    -------
    PyOpenColorIO.Config

    Raises
    ------
    ParameterError
        Naming ``config``: the file does not exist (the installed package's config
        included), or OCIO cannot load it (the first line of its message).
    """
    import PyOpenColorIO as ocio

    if config is None:
        path = DEFAULT_CONFIG
        if not path.is_file():
            if path == PACKAGE_CONFIG:
                raise ParameterError(
                    "config",
                    f" is needed: the package's config {path} is "
                    "missing (an install without its data? "
                    "reinstalling the wheel restores it)",
                )
            from ocio_thinfilm.export import bake

            bake.bake(path.parent)
    path = DEFAULT_CONFIG if config is None else Path(config)
    if not path.is_file():
        raise ParameterError("config", f" {path}: no such config file")
    try:
        return ocio.Config.CreateFromFile(str(path))
    except Exception as error:  # OCIO's parse errors
        raise ParameterError("config", f" {path}: {str(error).splitlines()[0]}") from None


class ConfigProcessors:
    """The OCIO CPU processors a render needs, created from one config on first use.

    ``table(spec)`` for a scene's table (its thin-film colour space -> CIE-XYZ-D65),
    ``view(display, view)`` for a view (CIE-XYZ-D65 -> display code values). A config
    without a ``CIE-XYZ-D65`` colour space (an ACES config the thin-film spaces were
    merged into with ``bake --into``) reaches CIE-XYZ-D65 through its ``scene_linear``
    role and ``cie_xyz_d65_interchange`` role.

    Parameters
    ----------
    config : PyOpenColorIO.Config, str or os.PathLike, optional
        The config, or its file (:func:`load_config`; default :data:`DEFAULT_CONFIG`).

    Attributes
    ----------
    config : PyOpenColorIO.Config
        The config.
    created : list of str
        The processors created so far, in order: ``"colorspace:<name>"`` and
        ``"view:<display>/<view>"``.

    Raises
    ------
    ParameterError
        Naming ``config``, if the file cannot be loaded (:func:`load_config`).
    """

    def __init__(self, config=None, films=None):
        self.config = (
            config
            if config is not None and not isinstance(config, (str, Path))
            else load_config(config)
        )
        #: Users' films a render may use: colour space name -> its transform to
        #: CIE-XYZ-D65 (the table ``bake --films`` writes), used when the config has no
        #: colour space of that name.
        self.films = dict(films or {})
        self._cpu = {}
        #: The processors created so far, in order: ``"colorspace:<name>"`` and
        #: ``"view:<display>/<view>"`` (a scene builds only what it shows).
        self.created: list[str] = []
        self._bridge = None  # (scene-linear space, its transform to CIE-XYZ-D65)

    def _xyz_bridge(self):
        """Return the config's scene-linear colour space and its transform to CIE-XYZ-D65.

        For a config without a ``CIE-XYZ-D65`` colour space (an ACES config the thin-film
        spaces were merged into with ``bake --into``): its ``scene_linear`` colour space S
        and the transform S -> CIE-XYZ-D65, through the config's
        ``cie_xyz_d65_interchange`` role (:func:`ocio_thinfilm.config.merge.interchange`).
        """
        if self._bridge is None:
            from ocio_thinfilm.config import merge
            from ocio_thinfilm.lut import ocio_ops

            name = dict(self.config.getRoles()).get("scene_linear")
            cs = self.config.getColorSpace(name) if name else None
            if cs is None:
                raise ParameterError(
                    "config",
                    f": no {registry.REFERENCE} colour space and no scene_linear role to reach it",
                )
            scene_to_xyz, _ = merge.interchange(self.config)
            self._bridge = (
                cs.getName(),
                ocio_ops.group([merge.colorspace_transform(cs, to_reference=True), scene_to_xyz]),
            )
        return self._bridge

    def _xyz_transform(self, source):
        """Return a processor-ready transform ``source`` colour space -> CIE-XYZ-D65."""
        import PyOpenColorIO as ocio

        if self.config.getColorSpace(registry.REFERENCE) is not None:
            return ocio.ColorSpaceTransform(source, registry.REFERENCE)
        linear, to_xyz = self._xyz_bridge()
        return ocio.GroupTransform([ocio.ColorSpaceTransform(source, linear), to_xyz])

    def _processor(self, key, make):
        if key not in self._cpu:
            try:
                self._cpu[key] = make().getDefaultCPUProcessor()
            except Exception as error:  # a missing space / view / LUT file
                raise ParameterError(
                    "config", f": cannot build {key}: {str(error).splitlines()[0]}"
                ) from None
            self.created.append(key)
        return self._cpu[key]

    def table(self, spec: TableSpec) -> ocio_ops.CPUProcessor:
        """Return the CPU processor of a scene's table: its colour space -> CIE-XYZ-D65.

        Parameters
        ----------
        spec : ocio_thinfilm.render.scenes.TableSpec
            The table a scene declares.

        Returns
        -------
        PyOpenColorIO.CPUProcessor
            Created on the first call for its colour space, then reused.

        Raises
        ------
        ValueError
            If the config ships no table for ``spec`` (:func:`table_colorspace`).
        ParameterError
            Naming ``config``, if the processor cannot be built (a missing colour space
            or LUT file).
        """
        space = table_colorspace(spec)
        if self.config.getColorSpace(space) is None and space in self.films:
            return self._processor(
                f"film:{space}", lambda: self.config.getProcessor(self.films[space])
            )
        return self._processor(
            f"colorspace:{space}", lambda: self.config.getProcessor(self._xyz_transform(space))
        )

    def view(self, display: str, view: str) -> ocio_ops.CPUProcessor:
        """Return the CPU processor of a display's view: CIE-XYZ-D65 -> display code values.

        Parameters
        ----------
        display : str
            A display of the config.
        view : str
            A view of that display.

        Returns
        -------
        PyOpenColorIO.CPUProcessor
            Created on the first call for the pair, then reused.

        Raises
        ------
        ParameterError
            Naming ``config``, if the processor cannot be built (an unknown display or
            view, a missing LUT file).
        """
        import PyOpenColorIO as ocio

        def make():
            if self.config.getColorSpace(registry.REFERENCE) is not None:
                return self.config.getProcessor(
                    registry.REFERENCE, display, view, ocio.TRANSFORM_DIR_FORWARD
                )
            linear, to_xyz = self._xyz_bridge()
            from_xyz = ocio.GroupTransform([to_xyz])
            from_xyz.setDirection(ocio.TRANSFORM_DIR_INVERSE)
            return self.config.getProcessor(
                ocio.GroupTransform([from_xyz, ocio.DisplayViewTransform(linear, display, view)])
            )

        return self._processor(f"view:{display}/{view}", make)

    def check_display_view(self, display: str, view: str) -> None:
        """Check that the config has ``display`` with ``view``.

        Parameters
        ----------
        display : str
            The display's name.
        view : str
            The view's name.

        Raises
        ------
        ParameterError
            Naming ``display`` or ``view`` (and listing the config's choices) if the
            config does not have it.
        """
        displays = list(self.config.getDisplays())
        if display not in displays:
            raise ParameterError("display", f" {display!r}: the config has {', '.join(displays)}")
        views = list(self.config.getViews(display))
        if view not in views:
            raise ParameterError(
                "view", f" {view!r}: the config's display {display} has {', '.join(views)}"
            )


def _apply(cpu, pixels) -> np.ndarray:
    out = np.array(pixels, dtype=np.float32, order="C", copy=True)
    flat = out.reshape(-1, 3)
    if flat.size:
        cpu.applyRGB(flat)
    return flat.reshape(out.shape)


def _as_rgb(values: np.ndarray) -> np.ndarray:
    """Return (H, W) encoded values as (H, W, 3) float32 with all three channels equal."""
    v = np.ascontiguousarray(values, dtype=np.float32)
    return np.repeat(v[..., None], 3, axis=-1)


def make_lookup(processors: ConfigProcessors | None = None) -> Lookup:
    """Return a scene ``lookup(spec, encoded)`` that applies the config's table spaces.

    The lookup applies the config's colour space of each table (pixel encoding ->
    CIE-XYZ-D65) with OCIO's CPU processor, each built once on first use.

    Parameters
    ----------
    processors : ConfigProcessors, optional
        The processors to use (default: a new :class:`ConfigProcessors` of
        :data:`DEFAULT_CONFIG`).

    Returns
    -------
    callable
        ``lookup(spec, encoded)``: (H, W) encoded values -> float32 (H, W, 3) CIE XYZ.
        Its ``processors`` attribute holds ``processors``
        (:func:`ocio_thinfilm.render.frames.render_scene` reuses them).

    Raises
    ------
    ParameterError
        Naming ``config``, if the default config cannot be loaded.
    """
    processors = processors if processors is not None else ConfigProcessors()

    def lookup(spec: TableSpec, encoded: np.ndarray) -> np.ndarray:
        return _apply(processors.table(spec), _as_rgb(encoded))

    # the processors travel with the lookup (render_scene reuses them); mypy does not
    # model attributes set on a function
    lookup.processors = processors  # type: ignore[attr-defined]
    return lookup


def display_image(
    picture: Picture, display: str, view: str, processors: ConfigProcessors | None = None
) -> np.ndarray:
    """Return the display-encoded RGB of a scene's picture.

    Each column region goes through its view (the config's display/view processors).

    Parameters
    ----------
    picture : ocio_thinfilm.render.scenes.Picture
        The scene-linear picture and its column regions.
    display : str
        A display of the config.
    view : str
        The view of the regions that name none.
    processors : ConfigProcessors, optional
        The processors to use (default: a new :class:`ConfigProcessors` of
        :data:`DEFAULT_CONFIG`).

    Returns
    -------
    numpy.ndarray
        float32 (H, W, 3) code values clipped to [0, 1]; columns outside every region
        are 0.

    Raises
    ------
    ParameterError
        Naming ``config``, if a view's processor cannot be built.
    """
    processors = processors if processors is not None else ConfigProcessors()
    h, w, _ = picture.xyz.shape
    out = np.zeros((h, w, 3), np.float32)
    for x0, x1, region_view in picture.regions:
        cpu = processors.view(display, region_view or view)
        out[:, x0:x1] = _apply(cpu, np.ascontiguousarray(picture.xyz[:, x0:x1]))
    return np.clip(out, 0.0, 1.0)
