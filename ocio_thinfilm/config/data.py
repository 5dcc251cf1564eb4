"""The drop-in OpenColorIO config as plain data (cf. OpenColorIO-Config-ACES ``ConfigData``).

:func:`config_data` describes every colour space, view transform, display, role, file
rule and named transform as dicts for the factories of
:mod:`ocio_thinfilm.config.factories`, plus the LUTs the config needs (``luts``: CLF file
name -> GroupTransform). Displays, views and thin-film spaces come from the one
registry (:mod:`ocio_thinfilm.registry`); each display's clip LUT is computed once and
handed to every part that uses it.

Reference spaces: the scene reference and the display reference are both
CIE-XYZ-D65 with the perfect reflector (and the display white) at Y = 1. Scene-linear
is ``Linear Rec.709 (sRGB)`` (what Blender users expect): scene-linear 1.0 is the
display white and every view maps it to code value 1.0 (no tone mapping).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ocio_thinfilm import registry
from ocio_thinfilm.colour import compress as compress_map
from ocio_thinfilm.config import spaces
from ocio_thinfilm.config.luts import (
    clip_luts,
    clip_passes,
    compress_luts,
    compress_passes,
    lut_files,
    lut_reference,
    named_lut,
)
from ocio_thinfilm.config.named import TABLE_NAMED_TRANSFORM, named_transforms
from ocio_thinfilm.lut import (
    clip_lut,
    compress_lut,
    display_transforms,
    film_tables,
    ocio_ops,
    tables,
    view_transforms,
)
from ocio_thinfilm.lut.options import MapOptions, as_options

__all__ = [
    "CONFIG_NAME",
    "PROFILE_VERSION",
    "LUT_DIRECTORY",
    "ROLES",
    "ConfigData",
    "view_parts",
    "LUT_FILE_VIEWS",
    "config_data",
    "thin_film_colorspaces",
    "display_views",
    "file_rules",
    "FILM_LUT_PREFIX",
    "film_lut_stem",
    "film_parts",
]

CONFIG_NAME = "ocio-thinfilm"
PROFILE_VERSION = (2, 1)
LUT_DIRECTORY = "luts"

ROLES = {
    "scene_linear": "Linear Rec.709 (sRGB)",
    "rendering": "Linear Rec.709 (sRGB)",
    "default": "Linear Rec.709 (sRGB)",
    "data": registry.RAW_SPACE,
    "reference": "CIE-XYZ-D65",
    "color_picking": registry.TEXTURE_SPACE,
    "texture_paint": "Linear Rec.709 (sRGB)",
    "matte_paint": registry.TEXTURE_SPACE,
    "compositing_log": "ACEScct",
    "color_timing": "ACEScct",
    "aces_interchange": "ACES2065-1",
    "cie_xyz_d65_interchange": "CIE-XYZ-D65",
    "default_byte": registry.TEXTURE_SPACE,
    "default_float": "Linear Rec.709 (sRGB)",
    "default_sequencer": registry.TEXTURE_SPACE,
}


# --------------------------------------------------------------------------- #
# Data
# --------------------------------------------------------------------------- #
@dataclass
class ConfigData:
    """The config as data (cf. OpenColorIO-Config-ACES ``ConfigData``).

    Parameters
    ----------
    name : str
        The config's name.
    description : str
        The config's description.
    roles : dict
        Role -> colour space name.
    colorspaces : list of dict
        Keyword arguments of :func:`~ocio_thinfilm.config.factories.colorspace_factory`.
    view_transforms : list of dict
        Keyword arguments of
        :func:`~ocio_thinfilm.config.factories.view_transform_factory`; the first is the
        default view transform.
    displays : dict
        Display -> list of view dicts: ``name`` with ``view_transform`` and
        ``display_colorspace``, or ``name`` with ``colorspace`` (a Raw view).
    file_rules : list of dict
        ``name``, ``colorspace``, ``pattern``, ``extension``; the rule named
        ``Default`` gives only its colour space.
    luts : dict, optional
        LUT file name -> GroupTransform (CLF-writable).
    named_transforms : list of dict, optional
        Keyword arguments of
        :func:`~ocio_thinfilm.config.factories.named_transform_factory`.
    profile_version : tuple of int, optional
        The config's (major, minor) profile version (default :data:`PROFILE_VERSION`).
    """

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


def _clip_chain(lut, soft, luts, inline):
    # the second LUT ends in sRGB code values: back to display-linear here, the display
    # colour space encodes again (OCIO's optimiser removes the pair for the sRGB-encoded
    # displays)
    return clip_passes(lut, luts, inline) + [clip_lut.working_decoding_transform()]


def _compress_chain(lut, soft, luts, inline):
    return compress_passes(soft, luts, inline) + [clip_lut.working_decoding_transform()]


#: View kind -> its chain in the config, CIE-XYZ-D65 -> display-linear RGB of an SDR
#: display, from the config's LUT files: ``f(clip LUT, compression LUT, luts, inline)``;
#: ``None`` where the view is its linear transform
#: (:data:`ocio_thinfilm.lut.view_transforms.LINEAR_VIEWS`) or has none (raw).
LUT_FILE_VIEWS = {
    "clip": _clip_chain,
    "compress": _compress_chain,
    "clamp": None,
    "aces": None,
    "raw": None,
}


def _linear_parts(gamut, view, lut, luts, inline, compress=None):
    """Return CIE-XYZ-D65 -> display-linear RGB in [0, 1] of one view of an SDR display.

    A list of transforms, for the SDR display ``gamut`` (the config's LUT files for
    the clip and the compression).
    """
    chain = LUT_FILE_VIEWS[view.kind]
    if chain is not None:
        return chain(lut, compress, luts, inline)
    return [view_transforms.view_linear_transform(gamut, view.name)]


def view_parts(
    display: registry.DisplayLike,
    view: str | registry.View,
    *,
    lut: clip_lut.ClipLUT | None = None,
    luts: dict | None = None,
    inline: bool = False,
    compress: compress_lut.CompressLUT | None = None,
) -> ocio_ops.Transform:
    """Return CIE-XYZ-D65 (scene) -> CIE-XYZ-D65 (display reference) for one view.

    An HDR display's view is its gamut's chain (the same LUT files) between the exact
    scales of :func:`ocio_thinfilm.lut.view_transforms.hdr_scaled`, whatever the chain:
    the display reference then has Y = 1 at 203 cd/m2 and the volume up to
    peak / 203.

    Parameters
    ----------
    display : str, Display or HDRDisplay
        A display of :data:`ocio_thinfilm.registry.ALL_DISPLAYS` or its name.
    view : str or View
        A view of :data:`ocio_thinfilm.registry.VIEWS` (or its name) other than the raw
        one.
    lut : ClipLUT, optional
        The ClipLUT of the display's gamut; required for the Constant-Lightness Clip
        and the Constant-Lightness Compress.
    luts : dict, optional
        The LUT files (:func:`lut_files`); required with ``inline=True``.
    inline : bool, optional
        Put the LUTs into the transform (``True``) or refer to the config's LUT files
        by FileTransform (``False``, the default).
    compress : CompressLUT, optional
        The CompressLUT of the display's gamut; required for the Constant-Lightness
        Compress.

    Returns
    -------
    PyOpenColorIO.GroupTransform
        The view transform's ``from_reference`` transform.

    Raises
    ------
    ParameterError
        For a display that is not the registry's.
    TypeError
        For a ``display`` that is neither a name nor a registry display.
    ValueError
        For an unknown view (``Raw`` included).
    """
    entry = registry.as_display(display)
    view_entry = registry.as_view(view, raw=False)
    linear = _linear_parts(entry.gamut, view_entry, lut, luts, inline, compress)
    if entry.hdr:
        linear = view_transforms.hdr_scaled(entry, linear)
    return ocio_ops.group(
        linear + [display_transforms.display_matrix_transform(entry.gamut, inverse=True)]
    )


def config_data(
    *,
    inline: bool = False,
    films: Sequence[Any] = (),
    options: MapOptions | None = None,
) -> ConfigData:
    """Return the config as data.

    Parameters
    ----------
    inline : bool, optional
        Put the LUTs into the transforms (an in-memory config needing no files, for
        baking and tests) if ``True``; otherwise (the default) colour spaces refer to
        ``luts/*.clf`` by FileTransform.
    films : sequence of Film, optional
        Users' films (:class:`ocio_thinfilm.physics.films.Film`): one input colour
        space and named transform each (:func:`film_parts`); none (the default) leaves
        the config as it is without them.
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`: the
        Constant-Lightness Compress view's knobs, the clip size, the table sizes);
        ``None`` (default) for the defaults.

    Returns
    -------
    ConfigData
        Every colour space, view transform, display, role, file rule and named
        transform, and the LUT files (``luts``).
    """
    options = as_options(options)
    threshold, limit = options.knobs()
    by_display = clip_luts(options=options)
    soft_by_display = compress_luts(options=options)
    luts = lut_files(by_display, compress_by_display=soft_by_display, options=options)
    cs = spaces.scene_colorspaces() + thin_film_colorspaces(luts, inline=inline, options=options)
    film_spaces, film_named, film_luts = film_parts(
        films, inline=inline, taken=[c["name"] for c in cs]
    )
    cs += film_spaces + spaces.display_colorspaces()
    luts.update(film_luts)
    views, displays = display_views(
        by_display,
        soft_by_display,
        luts,
        inline=inline,
        knobs=(compress_map.knob_text(threshold), compress_map.knob_text(limit)),
    )
    return ConfigData(
        name=CONFIG_NAME,
        description=(
            "Thin-film interference colours (Smits & Meyer 1990, \"Newton's "
            "Colors\") with the paper's constant-lightness gamut clip. Reference: "
            "CIE-XYZ-D65; scene-linear: Linear Rec.709 (sRGB). Generated by "
            "ocio-thinfilm (`ocio-thinfilm bake`); do not edit by hand."
        ),
        roles=dict(ROLES),
        colorspaces=cs,
        view_transforms=views,
        displays=displays,
        file_rules=file_rules(),
        luts=luts,
        named_transforms=named_transforms(
            by_display, inline=inline, luts=luts, compress_by_display=soft_by_display
        )
        + film_named,
    )


def thin_film_colorspaces(
    luts: dict[str, ocio_ops.Transform],
    *,
    inline: bool = False,
    options: MapOptions | None = None,
) -> list[dict[str, Any]]:
    """Return the thin-film input colour spaces of the registry as data.

    Parameters
    ----------
    luts : dict
        The LUT files (:func:`lut_files`).
    inline : bool, optional
        Put the tables into the transforms (``True``) or refer to their files.
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`; here the
        table sizes, which the descriptions state); ``None`` (default) for the
        defaults.

    Returns
    -------
    list of dict
        Keyword arguments of :func:`ocio_thinfilm.config.factories.colorspace_factory`.
    """
    options = as_options(options)
    cs = []
    for space in registry.THIN_FILM_LIST:
        table = tables.thin_film_table(
            space, film_size=options.film_size, morpho_size=options.morpho_size
        )
        if space.table == "film":
            encoding = (
                "Pixel value (all three channels equal) = optical thickness t' = "
                "n t cos(theta_t) in micrometres; beyond 100 um the incoherent grey, "
                "negative values black."
            )
        else:
            encoding = (
                "Pixel value (all three channels equal) = cos(theta), the facing "
                "ratio N.V of the viewing direction; clamped to [0, 1] (0 = grazing, "
                "1 = normal incidence)."
            )
        cs.append(
            dict(
                name=space.name,
                family="Thin Film",
                encoding="scene-linear",
                categories=["file-io"],
                description=f"{table.description} {encoding}",
                to_reference=lut_reference(named_lut(space.lut_stem), luts, inline),
            )
        )
    return cs


def display_views(
    luts_by_display: dict,
    compress_by_display: dict,
    luts: dict[str, ocio_ops.Transform],
    *,
    inline: bool = False,
    knobs: tuple[str, str] = ("", ""),
) -> tuple[list[dict[str, Any]], dict[str, list[dict[str, Any]]]]:
    """Return the view transforms and each display's views as data.

    The default view transform links the two reference spaces when a conversion crosses
    them without a view (e.g. display space -> scene space): an identity, as
    "Un-tone-mapped" in the ACES configs (inverting the clip is meaningless). Then one
    view transform per display and view of the registry (:func:`view_parts`); the raw
    view shows the ``Raw`` colour space.

    Parameters
    ----------
    luts_by_display, compress_by_display : dict
        SDR display name -> its ClipLUT (:func:`clip_luts`) and CompressLUT
        (:func:`compress_luts`).
    luts : dict
        The LUT files (:func:`lut_files`).
    inline : bool, optional
        Put the LUTs into the transforms (``True``) or refer to their files.
    knobs : tuple of str, optional
        The compression's threshold and limit as its description states them
        (:meth:`ocio_thinfilm.registry.View.describe`).

    Returns
    -------
    view_transforms : list of dict
        For :func:`ocio_thinfilm.config.factories.view_transform_factory`.
    displays : dict
        Display name -> its views (dicts of ``name`` and ``view_transform`` and
        ``display_colorspace``, or ``name`` and ``colorspace``).
    """
    vts: list[dict[str, Any]] = [
        dict(
            name="Un-tone-mapped",
            family="Utility",
            description="Identity between the scene and display reference "
            "spaces (both CIE-XYZ-D65): no tone mapping, no "
            "gamut mapping. Used for conversions between scene "
            "and display colour spaces.",
            from_reference=ocio_ops.group([ocio_ops.matrix()]),
        )
    ]
    displays = {}
    for entry in registry.ALL_DISPLAY_LIST:
        views = []
        for view in registry.VIEW_LIST:
            if view.raw:
                views.append(dict(name=view.name, colorspace=registry.RAW_SPACE))
                continue
            vt = f"{view.name} - {entry.name}"
            vts.append(
                dict(
                    name=vt,
                    family="Thin Film",
                    description=f"{view.describe(*knobs)} Display: {entry.name}.",
                    from_reference=view_parts(
                        entry,
                        view,
                        lut=luts_by_display[entry.gamut.name],
                        luts=luts,
                        inline=inline,
                        compress=compress_by_display[entry.gamut.name],
                    ),
                )
            )
            views.append(
                dict(name=view.name, view_transform=vt, display_colorspace=entry.colorspace)
            )
        displays[entry.name] = views
    return vts, displays


def file_rules() -> list[dict[str, str]]:
    """Return the file rules: EXR scene-linear, PNG and JPEG the texture space.

    Returns
    -------
    list of dict
        ``name``, ``colorspace``, ``pattern``, ``extension``; the ``Default`` rule only
        its colour space.
    """
    return [
        dict(
            name="OpenEXR", colorspace=ROLES["scene_linear"], pattern="*", extension="[eE][xX][rR]"
        ),
        dict(name="PNG", colorspace=registry.TEXTURE_SPACE, pattern="*", extension="[pP][nN][gG]"),
        dict(name="JPEG", colorspace=registry.TEXTURE_SPACE, pattern="*", extension="[jJ][pP][gG]"),
        dict(name="Default", colorspace=ROLES["default"]),
    ]


#: LUT file stem of a user's film: this prefix and its key (file-name safe).
FILM_LUT_PREFIX = "ThinFilm_User_"


def film_lut_stem(film: Any) -> str:
    """Return the config's LUT file stem of a user's film.

    The stem is :data:`FILM_LUT_PREFIX` and the film's key with every character but
    letters, digits and ``_`` as ``_``.

    Parameters
    ----------
    film : Film
        A :class:`ocio_thinfilm.physics.films.Film`.

    Returns
    -------
    str
        E.g. ``ThinFilm_User_OilOnWater``.
    """
    import re

    return FILM_LUT_PREFIX + re.sub(r"[^A-Za-z0-9_]", "_", film.key)


def film_parts(
    films: Sequence[Any], *, inline: bool = False, taken: Sequence[str] = ()
) -> tuple[list[dict], list[dict], dict[str, ocio_ops.Transform]]:
    """Users' films as config data: (colour spaces, named transforms, LUT files).

    Each :class:`~ocio_thinfilm.physics.films.Film` gives an input colour space named
    ``film.name`` (pixel value = physical thickness of its varying layer in um, all
    channels equal -> CIE-XYZ-D65 through its table,
    :func:`ocio_thinfilm.lut.film_tables.user_film_table`), the named transform
    ``TABLE_NAMED_TRANSFORM`` of it and its CLF file.

    Parameters
    ----------
    films : sequence of Film
        The films.
    inline : bool, optional
        Put the tables into the transforms instead of FileTransforms to their files.
    taken : sequence of str, optional
        The config's colour space names, which the films' names must not repeat
        (:func:`ocio_thinfilm.physics.films.check_names`).

    Returns
    -------
    colorspaces : list of dict
        For :func:`ocio_thinfilm.config.factories.colorspace_factory`.
    named_transforms : list of dict
        For :func:`ocio_thinfilm.config.factories.named_transform_factory`.
    luts : dict
        CLF file name -> GroupTransform.
    """
    from ocio_thinfilm.physics.films import check_names

    films = list(films)
    check_names(films, taken)
    stems = _film_stems(films)
    spaces, named, luts = [], [], {}
    for film, stem in zip(films, stems, strict=True):
        table = film_tables.user_film_table(film)
        filename = named_lut(stem)
        luts[filename] = table.transform()
        reference = lut_reference(filename, luts, inline)
        spaces.append(_film_space(film, table.description, reference))
        named.append(
            dict(
                name=TABLE_NAMED_TRANSFORM.format(space=film.name),
                family="Thin Film",
                categories=["thin-film"],
                encoding="scene-linear",
                description=(
                    f"The {film.name} table on its own: physical thickness of the "
                    f"{film.varying.name} layer in um in (all channels equal), CIE XYZ "
                    "(D65, perfect reflector Y = 1) out."
                ),
                transform=lut_reference(filename, luts, inline),
            )
        )
    return spaces, named, luts


def _film_stems(films: list[Any]) -> list[str]:
    """Return the films' LUT file stems; refuse two films whose files would collide."""
    from ocio_thinfilm.checks import ParameterError

    stems = [film_lut_stem(f) for f in films]
    first: dict[str, Any] = {}
    for film, stem in zip(films, stems, strict=True):
        other = first.setdefault(stem.casefold(), film)
        if other is not film:
            raise ParameterError(
                "films",
                f" {film.source}: the films {other.key!r} and {film.key!r} would share the "
                f"LUT file {named_lut(stem)} (every character of a key but letters, digits and "
                "_ becomes _): rename one",
            )
    return stems


def _film_space(film: Any, table_description: str, to_reference: Any) -> dict:
    """Return the input colour space of a user's film (pixel value: thickness in um)."""
    lo, hi = film.range_um
    output = (
        "the film's physical reflectance (a perfect reflector is Y = 1)"
        if film.model == "exact"
        else "the paper's normalised Eq. 7/8 reflectance (peak 1)"
    )
    if film.normalise:
        output += ", scaled so that its brightest entry has Y = 1"
    return dict(
        name=film.name,
        family="Thin Film",
        encoding="scene-linear",
        categories=["file-io"],
        description=(
            f"{table_description} Pixel value (all three channels equal) = "
            f"physical thickness of the {film.varying.name} layer in "
            f"micrometres, clamped to [{lo:g}, {hi:g}]. Output: {output}, CIE "
            f"XYZ D65. From {Path(film.source).name}."
        ),
        to_reference=to_reference,
    )
