"""One entry point from data to a validated config.

:func:`generate_config` -- :class:`~ocio_thinfilm.config.data.ConfigData` -> a validated
``PyOpenColorIO.Config`` (the factories of :mod:`ocio_thinfilm.config.factories`). This
stage writes no file: :func:`ocio_thinfilm.export.bake.write_config` writes the folder.
"""

from __future__ import annotations

from ocio_thinfilm import registry
from ocio_thinfilm.config.data import LUT_DIRECTORY, ConfigData, config_data
from ocio_thinfilm.config.factories import (
    colorspace_factory,
    named_transform_factory,
    view_transform_factory,
)
from ocio_thinfilm.io import StrPath
from ocio_thinfilm.lut import ocio_ops

__all__ = ["generate_config"]


def generate_config(
    data: ConfigData | None = None,
    *,
    validate: bool = True,
    search_path: str = LUT_DIRECTORY,
    working_dir: StrPath | None = None,
) -> ocio_ops.Config:
    """Build (and by default validate) the OCIO config from ``data``.

    Parameters
    ----------
    data : ConfigData, optional
        The config as data; default :func:`~ocio_thinfilm.config.data.config_data`
        (LUTs referred to by FileTransform).
    validate : bool, optional
        Whether to validate the config (default ``True``).
    search_path : str, optional
        The config's search path (default :data:`LUT_DIRECTORY`, ``"luts"``).
    working_dir : str or os.PathLike, optional
        The config's working directory, against which the search path is resolved
        (default: none set).

    Returns
    -------
    PyOpenColorIO.Config
        The config; its active views are :data:`ocio_thinfilm.registry.VIEWS`.

    Raises
    ------
    PyOpenColorIO.Exception
        If the validation fails.
    """
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
                config.addDisplayView(
                    display,
                    view["name"],
                    view["view_transform"],
                    view["display_colorspace"],
                    "",
                    "",
                    "",
                )
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
        rules.insertRule(
            position, rule["name"], rule["colorspace"], rule["pattern"], rule["extension"]
        )
        position += 1
    config.setFileRules(rules)
    config.setInactiveColorSpaces("")
    if validate:
        config.validate()
    return config
