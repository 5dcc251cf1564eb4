"""The drop-in OpenColorIO config (stage 5): data -> factories -> config -> validate.

In the style of OpenColorIO-Config-ACES: the config is described as plain data
(:func:`config_data`), turned into OCIO objects by small factories
(:func:`colorspace_factory`, :func:`view_transform_factory`, ...), assembled by one
entry point, :func:`generate_config`, which validates the result, and written by
:func:`write_config` (LUTs as CLF with IDs and descriptors, then ``config.ocio``).

Reference spaces: the scene reference and the display reference are both
CIE-XYZ-D65 with the perfect reflector (and the display white) at Y = 1. Scene-linear
is ``Linear Rec.709 (sRGB)`` (what Blender users expect): scene-linear 1.0 is the
display white and every view maps it to code value 1.0 (no tone mapping).

Public names
------------
- :data:`CONFIG_NAME`, :data:`PROFILE_VERSION`, :data:`DISPLAY_SPACES`, :data:`ROLES`
- :func:`config_data` -- the config as data, plus the LUT files it needs
- :func:`colorspace_factory`, :func:`view_transform_factory`,
  :func:`named_transform_factory`, :func:`named_lut`
- :func:`named_transforms` -- the clip per display (display-linear in and out) and the
  thin-film tables (pixel value in, CIE XYZ out) as named transforms
- :func:`generate_config` -- data -> validated ``PyOpenColorIO.Config``
- :func:`write_config` -- write ``config.ocio`` and ``luts/*.clf`` into a directory
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import (
    clip_lut,
    display_transforms,
    ocio_ops,
    tables,
    view_transforms,
)

__all__ = [
    "CONFIG_NAME",
    "PROFILE_VERSION",
    "LUT_DIRECTORY",
    "DISPLAY_SPACES",
    "ROLES",
    "THIN_FILM_SPACES",
    "ConfigData",
    "colorspace_factory",
    "view_transform_factory",
    "named_transform_factory",
    "named_transforms",
    "named_lut",
    "config_data",
    "generate_config",
    "write_config",
    "lut_files",
]

CONFIG_NAME = "ocio-thinfilm"
PROFILE_VERSION = (2, 1)
LUT_DIRECTORY = "luts"

#: Display -> (display colour space name, description) (from :mod:`.registry`).
DISPLAY_SPACES = {d.name: (d.colorspace, d.description) for d in registry.DISPLAY_LIST}

#: Scene-linear RGB spaces: name -> (colorimetry space, description).
LINEAR_SPACES = {
    "ACES2065-1": ("ACES2065-1", "ACES2065-1: AP0 primaries, ACES white (Bradford from D65)"),
    "ACEScg": ("ACEScg", "ACEScg: AP1 primaries, ACES white (Bradford from D65)"),
    "Linear Rec.709 (sRGB)": ("Rec.709", "Scene-linear Rec.709 / sRGB primaries, D65"),
    "Linear P3-D65": ("Display P3", "Scene-linear P3 primaries, D65"),
    "Linear Rec.2020": ("Rec.2020", "Scene-linear Rec.2020 primaries, D65"),
}

#: Thin-film input spaces: name -> (table factory, arguments, LUT file stem) (from
#: :mod:`.registry`).
THIN_FILM_SPACES = {s.name: (s.table, s.args, s.lut_stem) for s in registry.THIN_FILM_LIST}

#: Views that show the data unchanged (the config's Raw colour space).
_RAW_VIEWS = tuple(v.name for v in registry.VIEW_LIST if v.raw)

ROLES = {
    "scene_linear": "Linear Rec.709 (sRGB)",
    "rendering": "Linear Rec.709 (sRGB)",
    "default": "Linear Rec.709 (sRGB)",
    "data": "Raw",
    "reference": "CIE-XYZ-D65",
    "color_picking": "sRGB - Texture",
    "texture_paint": "Linear Rec.709 (sRGB)",
    "matte_paint": "sRGB - Texture",
    "compositing_log": "ACEScct",
    "color_timing": "ACEScct",
    "aces_interchange": "ACES2065-1",
    "cie_xyz_d65_interchange": "CIE-XYZ-D65",
    "default_byte": "sRGB - Texture",
    "default_float": "Linear Rec.709 (sRGB)",
    "default_sequencer": "sRGB - Texture",
}


# --------------------------------------------------------------------------- #
# Data
# --------------------------------------------------------------------------- #
@dataclass
class ConfigData:
    """The config as data (cf. OpenColorIO-Config-ACES ``ConfigData``)."""

    name: str
    description: str
    roles: dict
    colorspaces: list  # dicts for colorspace_factory
    view_transforms: list  # dicts for view_transform_factory
    displays: dict  # display -> list of view dicts
    file_rules: list
    luts: dict = field(default_factory=dict)  # file name -> GroupTransform
    named_transforms: list = field(default_factory=list)  # dicts for named_transform_factory
    profile_version: tuple = PROFILE_VERSION


def named_lut(stem: str) -> str:
    return f"{stem}.clf"


def _file_transform(filename):
    import PyOpenColorIO as ocio

    t = ocio.FileTransform(filename)
    t.setInterpolation(ocio.INTERP_DEFAULT)
    return t


def lut_files(clip_size: int = clip_lut.CLIP_SIZE, film_size: int = tables.FILM_SIZE,
              morpho_size: int = tables.MORPHO_SIZE) -> dict:
    """LUT file name -> GroupTransform (CLF-writable) for every LUT the config uses."""
    files = {}
    for space, (factory, args, stem) in THIN_FILM_SPACES.items():
        table = (tables.film_table(*args, size=film_size) if factory == "film"
                 else tables.morpho_table(size=morpho_size))
        files[named_lut(stem)] = table.transform()
    for display in clip.DISPLAYS:
        lut = clip_lut.clip_lut(display, clip_size)
        files[named_lut(_clip_stem(display))] = lut.black_core()
        files[named_lut(_clip_stem(display, True))] = lut.white_core()
    return files


def _clip_stem(display, white=False):
    """Clip LUT file stem: the pass against the faces through black or white."""
    return registry.clip_lut_stem(display, white)


def _matrix_to_reference(space):
    """Linear RGB of ``space`` -> CIE-XYZ-D65, after limiting the components to
    +-ocio_ops.LIMIT: float32-max or infinite values (e.g. ACEScct codes above ~7.9)
    would overflow the matrix to Inf - Inf = NaN, which no later op can repair at
    OPTIMIZATION_NONE (ops not composed); no real pixel comes near 1e6."""
    M = colorimetry.matrix_XYZ_to_RGB(space)
    return ocio_ops.group([ocio_ops.finite_limit_transform(), ocio_ops.matrix(np.linalg.inv(M))])


def _view_parts(display, view, inline, luts, clip_size=clip_lut.CLIP_SIZE):
    """CIE-XYZ-D65 (scene) -> CIE-XYZ-D65 (display reference) for one view."""
    if view == "Constant-Lightness Clip":
        lut = clip_lut.clip_lut(display, clip_size)
        cores = [named_lut(_clip_stem(display, white)) for white in (False, True)]
        cores = [luts[name] if inline else _file_transform(name) for name in cores]
        # the second LUT ends in sRGB code values: back to display-linear here, the
        # display colour space encodes again (OCIO's optimiser removes the pair for
        # the sRGB-encoded displays)
        linear = lut.transforms(*cores) + [clip_lut.working_decoding_transform()]
    else:
        linear = [view_transforms.view_linear_transform(display, view)]
    return ocio_ops.group(linear + [display_transforms.display_matrix_transform(display, inverse=True)])


def config_data(*, inline: bool = False, clip_size: int = clip_lut.CLIP_SIZE,
                film_size: int = tables.FILM_SIZE,
                morpho_size: int = tables.MORPHO_SIZE) -> ConfigData:
    """The config as data. ``inline=True`` puts the LUTs into the transforms
    (an in-memory config needing no files, for baking and tests); otherwise colour
    spaces refer to ``luts/*.clf`` by FileTransform."""
    luts = lut_files(clip_size, film_size, morpho_size)
    ref = "CIE-XYZ-D65"
    cs = []
    cs.append(dict(name=ref, family="Utility", encoding="scene-linear",
                   categories=["file-io", "working-space"],
                   aliases=["cie_xyz_d65"],
                   description="CIE XYZ, D65-relative: the perfect reflector under D65 has "
                               "Y = 1 (CIE 1931 2 degree observer). The reference space."))
    for name, (space, description) in LINEAR_SPACES.items():
        cs.append(dict(name=name, family="Scene-Linear", encoding="scene-linear",
                       categories=["file-io", "working-space"],
                       description=description, to_reference=_matrix_to_reference(space)))
    acescct = _acescct_to_reference()
    cs.append(dict(name="ACEScct", family="ACES", encoding="log",
                   categories=["file-io", "working-space"],
                   description="ACEScct: ACEScg with the ACEScct log encoding (S-2016-001)",
                   to_reference=acescct))
    cs.append(dict(name="sRGB - Texture", family="Texture", encoding="sdr-video",
                   categories=["file-io", "texture"],
                   aliases=["srgb_tx"],
                   description="sRGB-encoded Rec.709 primaries, D65 (8-bit textures, colour "
                               "picking)",
                   to_reference=ocio_ops.group([
                       ocio_ops.inverse([display_transforms.display_encoding_transform("sRGB")]),
                       _matrix_to_reference("Rec.709")])))
    cs.append(dict(name="Raw", family="Utility", encoding="data", is_data=True,
                   categories=["file-io"], aliases=["Utility - Raw"],
                   description="Non-colour data: passed through unchanged"))
    for name, (factory, args, stem) in THIN_FILM_SPACES.items():
        table = (tables.film_table(*args, size=film_size) if factory == "film"
                 else tables.morpho_table(size=morpho_size))
        if factory == "film":
            encoding = ("Pixel value (all three channels equal) = optical thickness t' = "
                        "n t cos(theta_t) in micrometres; beyond 100 um the incoherent grey, "
                        "negative values black.")
        else:
            encoding = ("Pixel value (all three channels equal) = cos(theta), the facing "
                        "ratio N.V of the viewing direction; clamped to [0, 1] (0 = grazing, "
                        "1 = normal incidence).")
        cs.append(dict(name=name, family="Thin Film", encoding="scene-linear",
                       categories=["file-io"],
                       description=f"{table.description} {encoding}",
                       to_reference=(luts[named_lut(stem)] if inline
                                     else _file_transform(named_lut(stem)))))
    for display, (name, description) in DISPLAY_SPACES.items():
        cs.append(dict(name=name, family="Display", encoding="sdr-video",
                       categories=["file-io"], reference_space="display",
                       description=description,
                       from_reference=ocio_ops.group([
                           display_transforms.display_matrix_transform(display),
                           display_transforms.display_encoding_transform(display)])))

    # The default view transform links the two reference spaces when a conversion
    # crosses them without a view (e.g. display space -> scene space): an identity,
    # as "Un-tone-mapped" in the ACES configs (inverting the clip is meaningless).
    view_transforms = [dict(name="Un-tone-mapped", family="Utility",
                            description="Identity between the scene and display reference "
                                        "spaces (both CIE-XYZ-D65): no tone mapping, no "
                                        "gamut mapping. Used for conversions between scene "
                                        "and display colour spaces.",
                            from_reference=ocio_ops.group([ocio_ops.matrix()]))]
    displays = {}
    descriptions = {v.name: v.description for v in registry.VIEW_LIST}
    for display, (display_space, _) in DISPLAY_SPACES.items():
        views = []
        for view in registry.VIEWS:
            if view in _RAW_VIEWS:
                views.append(dict(name=view, colorspace="Raw"))
                continue
            vt = f"{view} - {display}"
            view_transforms.append(dict(name=vt, family="Thin Film",
                                        description=f"{descriptions[view]} Display: {display}.",
                                        from_reference=_view_parts(display, view, inline, luts,
                                                                    clip_size)))
            views.append(dict(name=view, view_transform=vt, display_colorspace=display_space))
        displays[display] = views

    file_rules = [
        dict(name="OpenEXR", colorspace=ROLES["scene_linear"], pattern="*",
             extension="[eE][xX][rR]"),
        dict(name="PNG", colorspace="sRGB - Texture", pattern="*", extension="[pP][nN][gG]"),
        dict(name="JPEG", colorspace="sRGB - Texture", pattern="*",
             extension="[jJ][pP][gG]"),
        dict(name="Default", colorspace=ROLES["default"]),
    ]
    return ConfigData(
        name=CONFIG_NAME,
        description=("Thin-film interference colours (Smits & Meyer 1990, \"Newton's "
                     "Colors\") with the paper's constant-lightness gamut clip. Reference: "
                     "CIE-XYZ-D65; scene-linear: Linear Rec.709 (sRGB). Generated by "
                     "ocio-thinfilm (`ocio-thinfilm bake`); do not edit by hand."),
        roles=dict(ROLES), colorspaces=cs, view_transforms=view_transforms,
        displays=displays, file_rules=file_rules, luts=luts,
        named_transforms=named_transforms(clip.DISPLAYS, inline=inline, luts=luts,
                                          clip_size=clip_size))


#: Named transform of the clip alone, per display (display-linear RGB in and out).
CLIP_NAMED_TRANSFORM = "Constant-Lightness Clip - {display} (display-linear)"
#: Named transform of a thin-film table (pixel value in, CIE XYZ out).
TABLE_NAMED_TRANSFORM = "{space} to CIE-XYZ-D65"


def clip_named_transform(display, *, inline=False, luts=None, clip_size=clip_lut.CLIP_SIZE):
    """The constant-lightness clip of ``display`` on its own: display-linear RGB in,
    display-linear RGB in [0, 1] out (XYZ -> the two LUT passes -> decoded), for
    hosts that apply a named transform as a node (Nuke OCIONamedTransform, Houdini)."""
    luts = luts if luts is not None else {}
    lut = clip_lut.clip_lut(display, clip_size)
    cores = [named_lut(_clip_stem(display, white)) for white in (False, True)]
    cores = [luts[name] if inline else _file_transform(name) for name in cores]
    return ocio_ops.group([display_transforms.display_matrix_transform(display, inverse=True)]
                        + lut.transforms(*cores) + [clip_lut.working_decoding_transform()])


def named_transforms(displays=clip.DISPLAYS, *, inline=False, luts=None,
                     clip_size=clip_lut.CLIP_SIZE) -> list:
    """Named transforms (OCIO >= 2.0) as data: the clip per display in ``displays``
    and the three thin-film tables (pixel value in, CIE-XYZ-D65 out, whatever the
    config's reference space: merged configs add the same ones)."""
    out = []
    for display in displays:
        out.append(dict(
            name=CLIP_NAMED_TRANSFORM.format(display=display), family="Thin Film",
            categories=["gamut-mapping"], encoding="display-linear",
            description=(f"Smits & Meyer 1990 constant-lightness clip into {display} on "
                         f"its own: {display} display-linear RGB in (any values), "
                         "display-linear RGB in [0, 1] out, luminance kept. Apply it as "
                         "a node, then encode for the display."),
            transform=clip_named_transform(display, inline=inline, luts=luts,
                                           clip_size=clip_size)))
    for space, (_, _, stem) in THIN_FILM_SPACES.items():
        table = named_lut(stem)
        out.append(dict(
            name=TABLE_NAMED_TRANSFORM.format(space=space), family="Thin Film",
            categories=["thin-film"], encoding="scene-linear",
            description=(f"The {space} table on its own: pixel value in (all channels "
                         "equal, as for the colour space of that name), unclipped CIE XYZ "
                         "(D65, perfect reflector Y = 1) out."),
            transform=(luts[table] if inline else _file_transform(table))))
    return out


def _acescct_to_reference():
    """ACEScct -> CIE-XYZ-D65: inverse ACEScct curve (LogCameraTransform), AP1 -> XYZ."""
    import PyOpenColorIO as ocio

    curve = ocio.LogCameraTransform([0.0078125] * 3)
    curve.setBase(2.0)
    curve.setLogSideSlopeValue([1.0 / 17.52] * 3)
    curve.setLogSideOffsetValue([9.72 / 17.52] * 3)
    curve.setLinSideSlopeValue([1.0] * 3)
    curve.setLinSideOffsetValue([0.0] * 3)
    curve.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return ocio_ops.group([curve, _matrix_to_reference("ACEScg")])


# --------------------------------------------------------------------------- #
# Factories
# --------------------------------------------------------------------------- #
def colorspace_factory(name, family="", encoding="", categories=(), description="",
                       to_reference=None, from_reference=None, is_data=False, aliases=(),
                       reference_space="scene"):
    """One ``PyOpenColorIO.ColorSpace`` from data (cf. OpenColorIO-Config-ACES)."""
    import PyOpenColorIO as ocio

    kind = (ocio.REFERENCE_SPACE_DISPLAY if reference_space == "display"
            else ocio.REFERENCE_SPACE_SCENE)
    cs = ocio.ColorSpace(kind)
    cs.setName(name)
    cs.setFamily(family)
    cs.setEncoding(encoding)
    cs.setDescription(description)
    cs.setIsData(bool(is_data))
    cs.setBitDepth(ocio.BIT_DEPTH_F32)
    for category in categories:
        cs.addCategory(category)
    for alias in aliases:
        cs.addAlias(alias)
    if to_reference is not None:
        cs.setTransform(to_reference, ocio.COLORSPACE_DIR_TO_REFERENCE)
    if from_reference is not None:
        cs.setTransform(from_reference, ocio.COLORSPACE_DIR_FROM_REFERENCE)
    return cs


def view_transform_factory(name, family="", description="", from_reference=None,
                           reference_space="scene"):
    """One ``PyOpenColorIO.ViewTransform`` from data."""
    import PyOpenColorIO as ocio

    kind = (ocio.REFERENCE_SPACE_DISPLAY if reference_space == "display"
            else ocio.REFERENCE_SPACE_SCENE)
    vt = ocio.ViewTransform(kind)
    vt.setName(name)
    vt.setFamily(family)
    vt.setDescription(description)
    if from_reference is not None:
        vt.setTransform(from_reference, ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
    return vt


def named_transform_factory(name, transform, family="", description="", categories=(),
                            encoding=""):
    """One ``PyOpenColorIO.NamedTransform`` (forward direction) from data."""
    import PyOpenColorIO as ocio

    nt = ocio.NamedTransform()
    nt.setName(name)
    nt.setFamily(family)
    nt.setDescription(description)
    nt.setEncoding(encoding)
    for category in categories:
        nt.addCategory(category)
    nt.setTransform(transform, ocio.TRANSFORM_DIR_FORWARD)
    return nt


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
