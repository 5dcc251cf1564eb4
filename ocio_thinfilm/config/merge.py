"""Add the thin-film spaces and the constant-lightness clip to an existing OCIO config.

The result of ``ocio-thinfilm bake --into CONFIG`` is a new ``Config`` (written by
:mod:`ocio_thinfilm.export.merged`, also as an OCIO archive, ``.ocioz``).
:func:`merge_config` takes such a config (the ACES studio/CG configs OCIO ships built in,
``ocio://...``) and adds, leaving everything else of it as it was:

- the three thin-film input spaces (scene-referred);
- the views ``Constant-Lightness Clip``, ``Constant-Lightness Compress`` and ``ACES
  Gamut Compression`` (and ``Channel Clamp``) on every SDR display whose display colour
  space has a supported gamut's primaries and white, and on every HDR display that is
  one of the registry's, found by running the display colour space's own processor
  (:func:`match_displays`);
- named transforms (the clip per matched gamut, the three tables) and ``luts`` on the
  search path, with the LUT files the additions use.

The conversions come from the config's ``cie_xyz_d65_interchange`` role; the result
must be linear (checked numerically), or the merge is refused. How displays are matched
and why not ``PyOpenColorIO.ConfigMerger``: docs/studio.md.

Public names: :func:`load_base`, :func:`match_displays`, :func:`merge_config`.
"""

from __future__ import annotations

import copy
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ocio_thinfilm import config, registry, reproducible
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.io import StrPath
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.options import MapOptions, as_options

__all__ = [
    "load_base",
    "interchange",
    "colorspace_transform",
    "match_displays",
    "merge_config",
    "MERGED_VIEWS",
    "HOST_OCIO",
    "profile_readers",
]

#: Hosts and the newest config profile their OCIO reads (an older OCIO refuses a newer
#: profile outright): Debian's Blender 3.4 and OCIO tools, and Blender 3.x, are OCIO 2.1;
#: PyPI's bpy 5.0 (Blender 5.0) is 2.4; OpenImageIO 3.2's oiiotool is 2.5; the VFX
#: Reference Platform specifies OCIO 2.4 for CY2025 and 2.5 for CY2026.
HOST_OCIO = (
    ("Blender 3.x / Debian's OCIO 2.1 tools", (2, 1)),
    ("VFX Reference Platform CY2025 / Blender 5.0", (2, 4)),
    ("VFX Reference Platform CY2026 / OpenImageIO 3.2's oiiotool", (2, 5)),
)


def profile_readers(cfg: ocio_ops.Config) -> str:
    """Return one line on who reads the config ``cfg``.

    Its profile, the oldest OCIO that reads it (the profile's own version) and the hosts
    of :data:`HOST_OCIO` that refuse it.

    Parameters
    ----------
    cfg : PyOpenColorIO.Config
        The config.

    Returns
    -------
    str
        The line.

    Examples
    --------
    >>> import PyOpenColorIO as ocio
    >>> cfg = ocio.Config.CreateRaw(); cfg.setMajorVersion(2); cfg.setMinorVersion(1)
    >>> profile_readers(cfg)
    'profile 2.1: read by OCIO 2.1 and newer (every host listed in the docs)'
    """
    version = (cfg.getMajorVersion(), cfg.getMinorVersion())
    line = f"profile {version[0]}.{version[1]}: read by OCIO {version[0]}.{version[1]} and newer"
    refused = [f"{host} (OCIO {v[0]}.{v[1]})" for host, v in HOST_OCIO if v < version]
    return line + (
        f"; not by {', '.join(refused)}" if refused else " (every host listed in the docs)"
    )


#: View kinds added to every matched display, in order (the clamp only where the base has
#: no Un-tone-mapped view).
MERGED_KINDS = ("clip", "compress", "aces", "clamp")
#: Views added to every matched display.
MERGED_VIEWS = tuple(registry.view_of_kind(kind).name for kind in MERGED_KINDS)
#: Minimum profile version: ACES_GamutComp13 and the LUT ops need 2.1.
MIN_PROFILE = (2, 1)
#: Tolerance of the display match, in code values for the white and the grey ramp and in
#: display-linear values for colours (float32 round-off ~1e-6; the nearest other
#: gamut, e.g. P3-D60 against P3-D65, is off by > 1e-2).
MATCH_TOLERANCE = 2e-4


def load_base(source: StrPath) -> ocio_ops.Config:
    """Load the base config from a file or an ``ocio://`` URI, with one-line errors.

    Parameters
    ----------
    source : str or os.PathLike
        A config file, or a built-in config's URI (e.g.
        ``ocio://studio-config-latest``).

    Returns
    -------
    PyOpenColorIO.Config

    Raises
    ------
    ParameterError
        Naming ``source``: no such file, or OCIO cannot load it (the first line of
        OCIO's message).
    """
    ocio = ocio_ops.module()
    text = str(source)
    if not text.startswith("ocio://") and not Path(text).is_file():
        raise ParameterError("source", f" {text}: no such config file (or ocio:// URI)")
    try:
        return ocio.Config.CreateFromFile(text)
    except ocio.Exception as error:
        raise ParameterError("source", f" {text}: {str(error).splitlines()[0]}") from None


def colorspace_transform(cs: Any, to_reference: bool) -> ocio_ops.Transform | None:
    """Return a colour space's transform to (or from) its reference.

    The transform of the other direction is inverted when the colour space has only
    that one.

    Parameters
    ----------
    cs : PyOpenColorIO.ColorSpace
        The colour space.
    to_reference : bool
        ``True`` for the transform to the reference, ``False`` for the one from it.

    Returns
    -------
    PyOpenColorIO.Transform or None
        The transform, ``None`` for an identity (no transform either way).
    """
    ocio = ocio_ops.module()
    want, other = (
        (ocio.COLORSPACE_DIR_TO_REFERENCE, ocio.COLORSPACE_DIR_FROM_REFERENCE)
        if to_reference
        else (ocio.COLORSPACE_DIR_FROM_REFERENCE, ocio.COLORSPACE_DIR_TO_REFERENCE)
    )
    t = cs.getTransform(want)
    if t is not None:
        return t
    t = cs.getTransform(other)
    if t is None:
        return None
    return ocio_ops.inverse([t])


def _vt_from_scene(vt):
    ocio = ocio_ops.module()
    t = vt.getTransform(ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
    if t is not None:
        return t
    t = vt.getTransform(ocio.VIEWTRANSFORM_DIR_TO_REFERENCE)
    return ocio_ops.inverse([t])


def _apply(cfg, transform, values):
    return ocio_ops.apply(transform, values, config=cfg).astype(np.float64)


def interchange(cfg: ocio_ops.Config) -> tuple[ocio_ops.Transform, ocio_ops.Transform]:
    """Return ``cfg``'s conversions between its references and CIE-XYZ-D65.

    From its ``cie_xyz_d65_interchange`` role (see the module docstring).

    Parameters
    ----------
    cfg : PyOpenColorIO.Config
        The config.

    Returns
    -------
    tuple of PyOpenColorIO.GroupTransform
        (scene reference -> CIE-XYZ-D65, CIE-XYZ-D65 -> display reference).

    Raises
    ------
    ValueError
        If the config has no ``cie_xyz_d65_interchange`` role, no view transform that
        reaches it (or no view transform at all), or a conversion that is not linear
        (checked numerically).
    """
    ocio = ocio_ops.module()
    roles = dict(cfg.getRoles())
    name = roles.get("cie_xyz_d65_interchange")
    cs = cfg.getColorSpace(name) if name else None
    if cs is None:
        raise ValueError(
            "the config has no cie_xyz_d65_interchange role (needed to place CIE-XYZ-D65 in it)"
        )
    if cs.getReferenceSpaceType() == ocio.REFERENCE_SPACE_DISPLAY:
        vt_name = cfg.getDefaultViewTransformName() or (
            next(iter(cfg.getViewTransformNames()), None)
        )
        vt = cfg.getViewTransform(vt_name) if vt_name else None
        if vt is None or vt.getReferenceSpaceType() != ocio.REFERENCE_SPACE_SCENE:
            raise ValueError(
                f"the cie_xyz_d65_interchange space {name!r} is "
                "display-referred and the config has no scene-referred "
                "default view transform to reach it"
            )
        scene_to_xyz = ocio_ops.group(
            [_vt_from_scene(vt), colorspace_transform(cs, to_reference=False)]
        )
        xyz_to_display = ocio_ops.group([colorspace_transform(cs, to_reference=True)])
    else:
        scene_to_xyz = ocio_ops.group([colorspace_transform(cs, to_reference=False)])
        vt_name = cfg.getDefaultViewTransformName() or (
            next(iter(cfg.getViewTransformNames()), None)
        )
        if not vt_name:
            raise ValueError("the config has no view transform: no display reference")
        xyz_to_display = ocio_ops.group(
            [
                colorspace_transform(cs, to_reference=True),
                _vt_from_scene(cfg.getViewTransform(vt_name)),
            ]
        )
    # it must be a colorimetric (linear) conversion, not a tone scale
    rng = np.random.default_rng(1)
    a, b = rng.uniform(0.0, 1.0, (2, 64, 3))
    for t in (scene_to_xyz, xyz_to_display):
        fa, fb, fab = (_apply(cfg, t, v) for v in (a, b, 0.5 * a + 0.25 * b))
        if not np.allclose(fab, 0.5 * fa + 0.25 * fb, atol=1e-5):
            raise ValueError(
                f"the config's conversion to cie_xyz_d65_interchange ({name!r}) "
                "is not linear: cannot place CIE-XYZ-D65 in it"
            )
    return scene_to_xyz, xyz_to_display


def _display_colorspace(cfg, display):
    """Return the display colour space of ``display``: the one its views use.

    The colour space named like the display for ``<USE_DISPLAY_NAME>``; ``None`` if no
    view uses a display-referred colour space that is not data.
    """
    ocio = ocio_ops.module()
    for view in cfg.getViews(display):
        name = cfg.getDisplayViewColorSpaceName(display, view)
        if name == "<USE_DISPLAY_NAME>":
            name = display
        cs = cfg.getColorSpace(name)
        if (
            cs is not None
            and not cs.isData()
            and cs.getReferenceSpaceType() == ocio.REFERENCE_SPACE_DISPLAY
        ):
            return cs
    return None


def _match_gamut(cfg, xyz_to_display, cs):
    """Return the clip display whose primaries and white ``cs`` has, or None.

    SDR, any per-channel encoding with white at code 1. XYZ of in-gamut RGB of the
    candidate gamut goes through the colour space's own processor; a grey ramp gives
    the encoding curve, and every colour must come out as that curve applied per
    channel.
    """
    if cs.getEncoding() in ("hdr-video", "edr-video"):
        return None
    transform = ocio_ops.group([xyz_to_display, colorspace_transform(cs, to_reference=False)])
    ramp = np.linspace(0.0, 1.0, 257)
    rng = np.random.default_rng(7)
    # colours whose channels sit on the ramp's nodes: primaries, secondaries, random
    index = np.vstack(
        [
            np.eye(3, dtype=int) * 256,
            np.eye(3, dtype=int) * 128,
            256 - np.eye(3, dtype=int) * 256,
            rng.integers(0, 257, (200, 3)),
        ]
    )
    rgb = ramp[index]
    for display in clip.DISPLAYS:
        to_rgb = reproducible.inv3(colorimetry.matrix_XYZ_to_RGB(display)).T
        try:
            grey = _apply(
                cfg, transform, reproducible.matmul(np.repeat(ramp[:, None], 3, 1), to_rgb)
            )
            codes = _apply(cfg, transform, reproducible.matmul(rgb, to_rgb))
        except Exception:  # noqa: BLE001 -- a colour space that cannot process: no match
            return None
        curve = grey[:, 1]
        if (
            np.abs(grey - curve[:, None]).max() > MATCH_TOLERANCE
            or abs(curve[-1] - 1.0) > MATCH_TOLERANCE
            or abs(curve[0]) > MATCH_TOLERANCE
            or np.any(np.diff(curve) <= 0)
        ):
            continue
        # compared display-linear (through the curve's inverse, exact at the nodes):
        # a steep encoding near black would magnify float round-off of a zero channel
        linear = np.interp(codes, curve, ramp)
        if np.abs(linear - rgb).max() <= MATCH_TOLERANCE:
            return display
    return None


def _hdr_nits(transfer, code):
    """Return the absolute display light in cd/m2 of HDR code values.

    colour-science's ST 2084 EOTF, or the BT.2100 HLG EOTF for a 1000 cd/m2 peak with
    black at 0.
    """
    import colour

    code = np.asarray(code, dtype=np.float64)
    if transfer == "PQ":
        return colour.models.eotf_ST2084(code)
    return colour.models.eotf_BT2100_HLG(code, L_B=0.0, L_W=1000.0)


def _match_hdr(cfg, xyz_to_display, cs):
    """Return the registry's HDR display that ``cs`` encodes for, or None.

    As (HDR display of the registry, cd/m2 per unit of ``cfg``'s display reference),
    for the display whose primaries, white and encoding ``cs`` has: in-gamut RGB of the
    candidate gamut up to the peak goes through the colour space's own processor and,
    decoded with the candidate's EOTF, must be that RGB times one luminance per unit
    (from the white).
    """
    transform = ocio_ops.group([xyz_to_display, colorspace_transform(cs, to_reference=False)])
    rng = np.random.default_rng(7)
    rgb = np.vstack(
        [
            np.eye(3),
            1.0 - np.eye(3),
            np.ones((1, 3)),
            np.linspace(0.05, 1, 8)[:, None] * np.ones(3),
            rng.uniform(0.0, 1.0, (200, 3)),
        ]
    )
    for entry in registry.HDR_DISPLAY_LIST:
        to_xyz = reproducible.inv3(colorimetry.matrix_XYZ_to_RGB(entry.colorimetry)).T
        try:
            white = _apply(cfg, transform, reproducible.matmul(np.ones((1, 3)), to_xyz))
            # to 1e-3 cd/m2: float32 round-off of the base's ops (100 -> 99.99997)
            unit = round(float(_hdr_nits(entry.transfer, white)[0, 1]), 3)
            if not (np.isfinite(unit) and 1.0 <= unit <= entry.peak):
                continue
            scale = entry.peak / unit  # test colours up to the peak
            nits = _hdr_nits(
                entry.transfer, _apply(cfg, transform, reproducible.matmul(rgb * scale, to_xyz))
            )
        except Exception:  # noqa: BLE001 -- a colour space that cannot process: no match
            return None
        if np.allclose(nits / unit, rgb * scale, rtol=2e-3, atol=5e-4 * scale):
            return entry.name, unit
    return None


def _matches(cfg):
    """Return the displays of ``cfg`` the clip supports, and the HDR ones' units.

    As ({display: (display colour space name, clip display or HDR display)},
    {display: cd/m2 per display-reference unit} for the HDR ones).
    """
    _, xyz_to_display = interchange(cfg)
    found, units = {}, {}
    for display in cfg.getDisplays():
        cs = _display_colorspace(cfg, display)
        if cs is None:
            continue
        if cs.getEncoding() in ("hdr-video", "edr-video") or cs.getEncoding() == "":
            hdr = _match_hdr(cfg, xyz_to_display, cs)
            if hdr is not None:
                found[display] = (cs.getName(), hdr[0])
                units[display] = hdr[1]
                continue
        gamut = _match_gamut(cfg, xyz_to_display, cs)
        if gamut is not None:
            found[display] = (cs.getName(), gamut)
    return found, units


def match_displays(cfg: ocio_ops.Config) -> dict[str, tuple[str, str]]:
    """Return the displays of ``cfg`` that the clip supports.

    Found by running each display colour space's own processor on test colours (see
    the module docstring), whatever its name and encoding.

    Parameters
    ----------
    cfg : PyOpenColorIO.Config
        The config.

    Returns
    -------
    dict
        {display of ``cfg``: (its display colour space name, clip display)}; the clip
        display of an SDR display is one of :data:`ocio_thinfilm.registry.DISPLAYS`,
        of an HDR display one of :data:`ocio_thinfilm.registry.HDR_DISPLAYS`.

    Raises
    ------
    ValueError
        As :func:`interchange`.
    """
    return _matches(cfg)[0]


def merge_config(
    base: ocio_ops.Config,
    *,
    films: Sequence[Any] = (),
    options: MapOptions | None = None,
) -> tuple[ocio_ops.Config, dict[str, ocio_ops.Transform], dict[str, tuple[str, str]]]:
    """Return ``base`` plus the additions (module docstring) as a new config.

    The result is not validated here (its LUT files are not written yet:
    :func:`ocio_thinfilm.export.merged.write_merged` writes and validates it). An HDR
    display whose luminance unit differs from that of the first display matched to
    the same target is left alone.

    Parameters
    ----------
    base : PyOpenColorIO.Config
        The config to extend (:func:`load_base`); it is not changed (a deep copy is
        extended). Its profile must be 2.1 or newer.
    films : sequence of Film, optional
        Users' films (:class:`ocio_thinfilm.physics.films.Film`): an input colour space
        and a named transform each, as the built-in thin-film spaces.
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`); ``None``
        (default) for the defaults.

    Returns
    -------
    config : PyOpenColorIO.Config
        The merged config; ``luts`` is added to its search path.
    luts : dict
        {LUT file name: GroupTransform} of the files it needs in ``luts/``.
    matches : dict
        {display: (display colour space name, clip display)} of the displays given the
        views (:func:`match_displays`).

    Raises
    ------
    ValueError
        If the profile is older than 2.1, the conversions cannot be found
        (:func:`interchange`), no display matches, or a colour space, view transform,
        named transform or view to add already exists (merged before?).
    """
    options = as_options(options)
    _check_profile(base)
    conversions = interchange(base)
    matches, unit_of, views_for = _merge_targets(base)
    gamut_entries = [d for d in registry.DISPLAY_LIST if d in {t.gamut for t in views_for}]
    if films:
        _check_film_names(base, films)
    data = config.config_data(films=films, options=options)
    maps = (config.clip_luts(options=options), config.compress_luts(options=options))
    film_names = [f.name for f in films]
    cfg = copy.deepcopy(base)
    _add_input_spaces(cfg, data, film_names, conversions[0])
    _add_view_transforms(cfg, data, views_for, unit_of, maps, conversions)
    _add_display_views(cfg, base, matches)
    _add_named_transforms(cfg, data, [g.name for g in gamut_entries], film_names, maps)
    _finish(cfg, base)
    names = [config.named_lut(s.lut_stem) for s in registry.THIN_FILM_LIST]
    names += [config.named_lut(config.film_lut_stem(f)) for f in films]
    names += [
        config.named_lut(stem(w))
        for g in gamut_entries
        for stem in (g.clip_lut_stem, g.compress_lut_stem)
        for w in (False, True)
    ]
    return cfg, {name: data.luts[name] for name in names}, matches


def _check_profile(base):
    """Refuse a base config whose profile is older than :data:`MIN_PROFILE`."""
    version = (base.getMajorVersion(), base.getMinorVersion())
    if version < MIN_PROFILE:
        raise ValueError(
            f"the config's profile version {version[0]}.{version[1]} is below "
            f"{MIN_PROFILE[0]}.{MIN_PROFILE[1]} (needed by the clip's LUT ops)"
        )


def _merge_targets(base):
    """Return the matched displays, the HDR targets' luminance units and the targets.

    ``(matches, unit_of, views_for)``: one view transform per target; an HDR display of
    another luminance unit than the first one matched to the same target is dropped
    from ``matches`` (left alone).
    """
    matches, units = _matches(base)
    if not matches:
        raise ValueError(
            "the config has no SDR display with the primaries and white of "
            f"{', '.join(clip.DISPLAYS)} (or Rec.709)"
        )
    targets = {g for _, g in matches.values()}
    unit_of: dict[str, float] = {}
    for display, (_, target) in list(matches.items()):
        if display in units:
            if unit_of.setdefault(target, units[display]) != units[display]:
                del matches[display]
    views_for = [d for d in registry.ALL_DISPLAY_LIST if d.name in targets]
    return matches, unit_of, views_for


def _check_film_names(base, films):
    """Refuse films named as a colour space, alias or named transform of ``base``.

    Inactive colour spaces included.
    """
    from ocio_thinfilm.physics.films import check_names

    ocio = ocio_ops.module()
    spaces = base.getColorSpaces(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL)
    check_names(
        films,
        [n for cs in spaces for n in [cs.getName(), *cs.getAliases()]]
        + list(base.getNamedTransformNames()),
    )


def _refuse_taken(cfg, name):
    """Refuse to add ``name`` where ``cfg`` has a colour space, view or named transform."""
    if (
        cfg.getColorSpace(name) is not None
        or cfg.getViewTransform(name) is not None
        or cfg.getNamedTransform(name) is not None
    ):
        raise ValueError(f"the config already has {name!r} (merged before?)")


def _add_input_spaces(cfg, data, film_names, scene_to_xyz):
    """Add the input spaces: table -> CIE-XYZ-D65 -> the config's scene reference."""
    for spec in data.colorspaces:
        if spec["name"] not in registry.THIN_FILM_SPACES and spec["name"] not in film_names:
            continue
        _refuse_taken(cfg, spec["name"])
        spec = dict(
            spec,
            to_reference=ocio_ops.group([spec["to_reference"], ocio_ops.inverse([scene_to_xyz])]),
        )
        cfg.addColorSpace(config.colorspace_factory(**spec))


def _add_view_transforms(cfg, data, views_for, unit_of, maps, conversions):
    """Add one view transform per target and merged view.

    Scene reference -> CIE-XYZ-D65 -> the view -> display reference.
    """
    scene_to_xyz, xyz_to_display = conversions
    by_display, soft_by_display = maps
    described = {vt["name"]: vt for vt in data.view_transforms}
    for target in views_for:
        gamut = target.gamut.name
        # HDR: the project's display reference has Y = 1 at 203 cd/m2, the base's
        # unit_of[target] cd/m2 (100 in the ACES configs)
        to_base = (
            [ocio_ops.matrix(np.eye(3) * registry.HDR_REFERENCE_WHITE / unit_of[target.name])]
            if target.name in unit_of
            else []
        )
        for view in MERGED_VIEWS:
            spec = described[f"{view} - {target.name}"]
            _refuse_taken(cfg, spec["name"])
            parts = config.view_parts(
                target, view, lut=by_display[gamut], luts=data.luts, compress=soft_by_display[gamut]
            )
            cfg.addViewTransform(
                config.view_transform_factory(
                    name=spec["name"],
                    family=spec["family"],
                    description=spec["description"],
                    from_reference=ocio_ops.group(
                        [scene_to_xyz, parts] + to_base + [xyz_to_display]
                    ),
                )
            )


def _add_display_views(cfg, base, matches):
    """Add the merged views to the matched displays, and to the active views."""
    added_views = []
    for display, (cs_name, gamut) in matches.items():
        views = list(base.getViews(display))
        for kind, view in zip(MERGED_KINDS, MERGED_VIEWS, strict=True):
            if view in views:
                raise ValueError(f"display {display!r} already has a view {view!r}")
            if kind == "clamp" and "Un-tone-mapped" in views:
                continue  # the base's colorimetric view is that baseline already
            cfg.addDisplayView(display, view, f"{view} - {gamut}", cs_name, "", "", "")
            if view not in added_views:
                added_views.append(view)
    active = list(base.getActiveViews())
    if active:
        cfg.setActiveViews(", ".join(active + [v for v in added_views if v not in active]))


def _add_named_transforms(cfg, data, gamuts, film_names, maps):
    """Add the named transforms: the clip and compression per gamut, and the tables."""
    by_display, soft_by_display = maps
    film_named = [
        nt
        for nt in data.named_transforms
        if nt["name"] in {config.TABLE_NAMED_TRANSFORM.format(space=n) for n in film_names}
    ]
    for spec in (
        config.named_transforms(
            {g: by_display[g] for g in gamuts},
            compress_by_display={g: soft_by_display[g] for g in gamuts},
        )
        + film_named
    ):
        _refuse_taken(cfg, spec["name"])
        cfg.addNamedTransform(config.named_transform_factory(**spec))


def _finish(cfg, base):
    """Put ``luts`` on the search path and say in the description what was added."""
    paths = list(cfg.getSearchPaths())
    if config.LUT_DIRECTORY not in paths:
        cfg.addSearchPath(config.LUT_DIRECTORY)
    cfg.setDescription(
        (base.getDescription().rstrip() + "\n\n" if base.getDescription() else "")
        + "Extended by ocio-thinfilm (`ocio-thinfilm bake --into`): "
        "thin-film input spaces, the constant-lightness clip views and "
        "named transforms."
    )
