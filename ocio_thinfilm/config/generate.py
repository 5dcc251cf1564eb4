"""One entry point from data to a validated config, and the writer of the config folder.

- :func:`generate_config` -- :class:`~ocio_thinfilm.config.data.ConfigData` -> a
  validated ``PyOpenColorIO.Config`` (the factories of
  :mod:`ocio_thinfilm.config.factories`);
- :func:`write_config` -- ``config.ocio`` and ``luts/*.clf`` (CLF with IDs and
  descriptors) into a directory.
"""

from __future__ import annotations

from pathlib import Path

from ocio_thinfilm import registry
from ocio_thinfilm.config.data import LUT_DIRECTORY, ConfigData, config_data
from ocio_thinfilm.config.factories import (
    colorspace_factory,
    named_transform_factory,
    view_transform_factory,
)
from ocio_thinfilm.lut import clip_lut, tables

__all__ = ["generate_config", "write_config"]


def generate_config(data: ConfigData | None = None, *, validate: bool = True,
                    search_path: str = LUT_DIRECTORY, working_dir: str | None = None):
    """Build (and by default validate) the OCIO config from ``data``."""
    import PyOpenColorIO as ocio

    data = data or config_data()
    config = ocio.Config.CreateRaw()
    for cs_name in list(config.getColorSpaceNames()):
        config.removeColorSpace(cs_name)
    config.setVersion(*data.profile_version)
    config.setName(data.name)
    config.setDescription(data.description)
    config.setSearchPath(search_path)
    if working_dir:
        config.setWorkingDir(str(working_dir))
    config.clearEnvironmentVars()
    config.setFamilySeparator("/")
    for spec in data.colorspaces:
        config.addColorSpace(colorspace_factory(**spec))
    for spec in data.view_transforms:
        config.addViewTransform(view_transform_factory(**spec))
    for spec in data.named_transforms:
        config.addNamedTransform(named_transform_factory(**spec))
    config.setDefaultViewTransformName(data.view_transforms[0]["name"])
    config.clearDisplays()
    for display, views in data.displays.items():
        for view in views:
            if "view_transform" in view:
                config.addDisplayView(display, view["name"], view["view_transform"],
                                      view["display_colorspace"], "", "", "")
            else:
                config.addDisplayView(display, view["name"], view["colorspace"], "")
    config.setActiveDisplays(", ".join(data.displays))
    config.setActiveViews(", ".join(registry.VIEWS))
    for role in list(dict(config.getRoles())):
        config.setRole(role, None)
    for role, space in data.roles.items():
        config.setRole(role, space)
    rules = ocio.FileRules()
    position = 0
    for rule in data.file_rules:
        if rule["name"] == "Default":
            rules.setDefaultRuleColorSpace(rule["colorspace"])
            continue
        rules.insertRule(position, rule["name"], rule["colorspace"], rule["pattern"],
                         rule["extension"])
        position += 1
    config.setFileRules(rules)
    config.setInactiveColorSpaces("")
    if validate:
        config.validate()
    return config


def write_config(directory, *, clip_size: int = clip_lut.CLIP_SIZE,
                 film_size: int = tables.FILM_SIZE, morpho_size: int = tables.MORPHO_SIZE,
                 progress=None) -> Path:
    """Write ``config.ocio`` and ``luts/*.clf`` into the (existing, empty) ``directory``.

    ``progress``: optional callable ``progress(step_name)`` called once per file.
    Returns the config path. The files carry no timestamps: equal inputs give equal
    bytes.
    """
    import PyOpenColorIO as ocio

    directory = Path(directory)
    data = config_data(clip_size=clip_size, film_size=film_size, morpho_size=morpho_size)
    (directory / LUT_DIRECTORY).mkdir(parents=True, exist_ok=True)
    raw = ocio.Config.CreateRaw()
    for filename, transform in sorted(data.luts.items()):
        transform.write("Academy/ASC Common LUT Format",
                        str(directory / LUT_DIRECTORY / filename), raw)
        if progress:
            progress(filename)
    config = generate_config(data, validate=False, working_dir=directory)
    config.validate()
    # Check that every FileTransform resolves and every processor builds.
    for display in config.getDisplays():
        for view in config.getViews(display):
            config.getProcessor("CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD)
    for name in config.getColorSpaceNames():
        config.getProcessor(name, "CIE-XYZ-D65")
    path = directory / "config.ocio"
    text = config.serialize()
    path.write_text(text if text.endswith("\n") else text + "\n")
    if progress:
        progress("config.ocio")
    return path
