"""``ocio-thinfilm bake`` and ``ocio-thinfilm export``: their options and what they run.

``export`` has one sub-command per thing it writes, each with only its options and its
own ``--help``:

- ``export film`` -- the thickness table of a built-in film kind, or a film of a film
  file (``--films FILE --film KEY``), or that film's swatches and spectra as CSV
  (``--swatches``, ``--spectra``);
- ``export material`` -- a film of a film file as a renderer's material: its
  reflectance (and transmittance) over thickness x view angle, float EXRs;
- ``export morpho`` -- the Morpho angle table;
- ``export clip`` -- the constant-lightness clip of a display, a 3D LUT;
- ``export view`` -- a display/view of the config, from one of its colour spaces;
- ``export shader`` -- the same view as GLSL or DCTL code.

Options are parsed and typed by argparse here; the library functions
(:func:`ocio_thinfilm.export.bake.bake`, :func:`ocio_thinfilm.export.merged.bake_into`,
:func:`ocio_thinfilm.export.files.export_lut`,
:func:`ocio_thinfilm.export.view.export_view`,
:func:`ocio_thinfilm.export.shader.export_shader`,
:func:`ocio_thinfilm.export.material.export_material`) check what the values allow.
"""

from __future__ import annotations

import argparse
import sys

from ocio_thinfilm import registry
from ocio_thinfilm.checks import UsageError
from ocio_thinfilm.colour import compress as compress_map
from ocio_thinfilm.export import bake as bake_module
from ocio_thinfilm.export.files import (
    DEFAULT_RANGE,
    DEFAULT_SIZE,
    FORMATS,
    LUT_FORMATS,
    export_lut,
)
from ocio_thinfilm.io import is_stdout
from ocio_thinfilm.lut import clip_lut
from ocio_thinfilm.lut.options import MapOptions

__all__ = ["register"]

#: The compression's knobs: option -> (``dest``, the library default).
_KNOB_OPTIONS = {
    "--compress-threshold": ("compress_threshold", compress_map.THRESHOLD),
    "--compress-limit": ("compress_limit", compress_map.LIMIT),
}


def _map_options(args: argparse.Namespace, limit_max: float | None = None) -> MapOptions:
    """Return the options' knobs as one :class:`~ocio_thinfilm.lut.options.MapOptions`.

    Made here, at the edge: a knob out of range (a limit above ``limit_max`` too, where
    given) is a ParameterError naming the library parameter (the command line names the
    option), raised before any warning. Knobs outside the tested range
    (:func:`ocio_thinfilm.lut.compress_lut.untested_knobs_note`) print one warning line
    on stderr with the accuracy the benchmark found there. ``--clip-size``, where the
    command has it, goes in too.
    """
    from ocio_thinfilm.lut import compress_lut

    threshold, limit = (
        default if getattr(args, dest) is None else getattr(args, dest)
        for dest, default in _KNOB_OPTIONS.values()
    )
    clip_size = getattr(args, "clip_size", None)
    options = MapOptions(
        compress_threshold=threshold,
        compress_limit=limit,
        clip_size=clip_lut.CLIP_SIZE if clip_size is None else clip_size,
    )
    threshold, limit = options.knobs(limit_max=limit_max)
    note = compress_lut.untested_knobs_note(threshold, limit)
    if note is not None:
        command = " ".join(w for w in (args.command, getattr(args, "subcommand", None)) if w)
        print(f"ocio-thinfilm {command}: warning: {note}", file=sys.stderr)
    return options


def _view_options(args: argparse.Namespace, limit_max: float | None = None) -> MapOptions | None:
    """Return the knobs of ``export view|shader``, refused for views other than the compression.

    ``None`` when no knob is given; ``limit_max``: as :func:`_map_options` (the shaders'
    largest limit).
    """
    given = [o for o, (dest, _) in _KNOB_OPTIONS.items() if getattr(args, dest) is not None]
    if not given:
        return None
    view = registry.as_view(args.view) if args.view in registry.VIEWS else None
    if view is None or view.kind != "compress":
        compress_view = registry.view_of_kind("compress").name
        raise UsageError(
            f"{given[0]} applies to 'export view|shader --view \"{compress_view}\"', "
            f"not --view {args.view!r}"
        )
    return _map_options(args, limit_max)


def _add_knob_options(parser: argparse.ArgumentParser, what: str) -> None:
    parser.add_argument(
        "--compress-threshold",
        type=float,
        default=None,
        metavar="T",
        help=f"{what}: the Constant-Lightness Compress view's threshold, the fraction of "
        "the distance to the gamut boundary left untouched, 0 < T < 1 (default "
        f"{compress_map.THRESHOLD:g}; tested range: docs/compress.md)",
    )
    parser.add_argument(
        "--compress-limit",
        type=float,
        default=None,
        metavar="L",
        help=f"{what}: its limit, the boundary distance mapped onto the boundary, L > 1 "
        f"(default {compress_map.LIMIT:g})",
    )


def _run_bake(args: argparse.Namespace) -> int:
    options = _map_options(args)
    if getattr(args, "into", None) or str(args.out).lower().endswith(".ocioz"):
        # --into CONFIG (merge into a studio config) and/or an .ocioz archive
        from ocio_thinfilm.config import merge
        from ocio_thinfilm.export import merged

        if args.into and args.out == bake_module.DEFAULT_CONFIG_DIR:
            raise UsageError("--into needs --out DIR (or FILE.ocioz)")
        if args.luts is not None:
            raise UsageError("--luts goes with a plain bake, not with --into or .ocioz")
        path = (
            merged.bake_into(args.into, args.out, films=args.films, options=options)
            if args.into
            else merged.bake_archive(args.out, films=args.films, options=options)
        )
        print(f"wrote {path}")
        if args.into:  # a merged config has the base config's profile: say who reads it
            import PyOpenColorIO as ocio

            print(merge.profile_readers(ocio.Config.CreateFromFile(str(path))))
        return 0
    path = bake_module.bake(
        args.out, show_progress=not args.quiet, luts=args.luts, films=args.films, options=options
    )
    print(f"wrote {path}" + (f" and {args.luts}" if args.luts is not None else ""))
    return 0


def _run_table(args: argparse.Namespace) -> int:
    """``export film``, ``export morpho``, ``export clip``: one LUT of a table or the clip."""
    path = export_lut(
        args.subcommand,
        args.out,
        fmt=args.format,
        kind=getattr(args, "kind", None) or "phase-change",
        display=args.display,
        index=getattr(args, "index", None),
        value_range=args.range,
        size=args.size,
        show_progress=not args.quiet,
    )
    print(f"wrote {path}", file=sys.stderr if is_stdout(path) else sys.stdout)
    return 0


def _run_film(args: argparse.Namespace) -> int:
    """``export film``: a built-in kind's table, or with ``--films`` a film of that file."""
    tables = [o for o in ("swatches", "spectra", "thickness") if getattr(args, o) is not None]
    if args.films is None:
        if args.film is not None or tables:
            named = f"--film {args.film}" if args.film is not None else f"--{tables[0]}"
            raise UsageError(
                f"--films FILE is missing: {named} applies to a film of a film file "
                "(see docs/films.md)"
            )
        return _run_table(args)
    for option, given in (
        ("--kind", args.kind is not None),
        ("--index", args.index is not None),
        ("--range", args.range is not None),
        ("--display", args.display is not None),
    ):
        if given:
            raise UsageError(f"{option} does not apply to a film of --films (its file says)")
    if tables:
        return _run_film_tables(args)
    from ocio_thinfilm.export.film_files import export_film

    for path in export_film(args.films, args.film, args.out, fmt=args.format, size=args.size):
        print(f"wrote {path}")
    return 0


def _run_film_tables(args: argparse.Namespace) -> int:
    """``export film --swatches|--spectra``: a film's colours or spectra as CSV (and PNG)."""
    from ocio_thinfilm.export import swatches
    from ocio_thinfilm.export.film_files import pick_film

    for option in ("out", "format", "size"):
        if getattr(args, option) is not None:
            raise UsageError(
                f"--{option} does not go with --swatches/--spectra (they name their own files)"
            )
    if args.spectra is not None and args.thickness is None:
        raise UsageError("--spectra needs --thickness T [T ...] (um)")
    if args.thickness is not None and args.swatches is None and args.spectra is None:
        raise UsageError("--thickness goes with --swatches or --spectra")
    film = pick_film(args.films, args.film)
    if args.swatches is not None:
        for path in swatches.write_swatches(film, args.swatches, args.thickness):
            print(f"wrote {path}")
    if args.spectra is not None:
        print(f"wrote {swatches.write_spectra(film, args.spectra, args.thickness)}")
    return 0


def _run_material(args: argparse.Namespace) -> int:
    """``export material``: a film's reflectance (and transmittance) tables as EXRs."""
    from ocio_thinfilm.export.film_files import pick_film
    from ocio_thinfilm.export.material import (
        DEFAULT_SPACE,
        export_material,
        gltf_files,
        host_files,
    )

    film = pick_film(args.films, args.film)
    spaces = args.space or [DEFAULT_SPACE]
    hosts = host_files(film, spaces)
    # the .glb carries the first space's tables (glTF's linear Rec.709)
    binaries = gltf_files(film, spaces[0]) if args.gltf else None
    written = export_material(
        film,
        args.out,
        space=spaces,
        size=args.size,
        hosts=hosts,
        gamut=args.gamut,
        binaries=binaries,
        workers=args.jobs,
        show_progress=not args.quiet,
    )
    for path in written:
        print(f"wrote {path}")
    return 0


def _run_view(args: argparse.Namespace) -> int:
    """``export view``: a display/view of the config as one LUT file."""
    from ocio_thinfilm.export.view import export_view

    paths = export_view(
        args.source,
        args.display,
        args.view,
        args.out,
        fmt=args.format,
        size=args.size,
        value_range=args.range,
        shaper=True if args.resolve_shaper else None,
        options=_view_options(args),
    )
    for path in paths:
        print(f"wrote {path}")
    return 0


def _run_shader(args: argparse.Namespace) -> int:
    """``export shader``: the view's map as GLSL or DCTL."""
    from ocio_thinfilm.export import shader, view

    if args.lang is None:
        raise UsageError(f"--lang is needed for 'export shader': {' or '.join(shader.LANGUAGES)}")
    options = _view_options(args, limit_max=shader.KNOB_LIMIT_MAX)
    source = registry.REFERENCE if args.source is None else args.source
    out = args.out
    if out is None and args.display is not None and args.view is not None:
        out = f"{view.set_name(source, args.display, args.view)}.{args.lang}"
    path = shader.export_shader(
        # without --display or --view the library refuses before it writes anything
        out if out is not None else "ocio_thinfilm_view",
        args.lang,
        args.display,
        args.view,
        source,
        options=options,
    )
    print(f"wrote {path}")
    return 0


def _add_bake(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = sub.add_parser(
        "bake",
        help="write the OpenColorIO config folder (config.ocio + luts/*.clf)",
        description="Write the drop-in OCIO config and its CLF LUTs, atomically.",
    )
    p.add_argument(
        "--out",
        default=bake_module.DEFAULT_CONFIG_DIR,
        help=f"config directory to (re)write (default {bake_module.DEFAULT_CONFIG_DIR})",
    )
    p.add_argument(
        "--clip-size",
        type=int,
        default=clip_lut.CLIP_SIZE,
        help=f"edge of the 3D clip LUTs (default {clip_lut.CLIP_SIZE})",
    )
    p.add_argument(
        "--luts",
        default=None,
        metavar="DIR",
        help="also write the standalone LUT set (every table, display and "
        "format) into DIR, e.g. luts",
    )
    p.add_argument(
        "--into",
        default=None,
        metavar="CONFIG",
        help="add the thin-film input spaces, the clip views and named "
        "transforms to CONFIG (a config file or a built-in ocio:// URI, "
        "e.g. ocio://studio-config-latest) and write the result to --out "
        "(see docs/studio.md); --out FILE.ocioz writes an OCIO archive",
    )
    p.add_argument(
        "--films",
        default=None,
        metavar="FILE",
        help="a film file (TOML, see docs/films.md): one more input colour space per "
        "film, 'Thin Film <key>' unless it sets a name (pixel value: physical "
        "thickness of its varying layer in um)",
    )
    _add_knob_options(p, "the config")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_run_bake)


def _add_lut_options(p: argparse.ArgumentParser, table: str, range_help: str) -> None:
    """Add the options every LUT of ``export film|morpho|clip`` takes to ``p``."""
    low, high = DEFAULT_RANGE[table]
    p.add_argument(
        "--range",
        nargs=2,
        type=float,
        metavar=("MIN", "MAX"),
        default=None,
        help=f"input range: {range_help} (default {low:g} {high:g})",
    )
    p.add_argument(
        "--size",
        type=int,
        default=None,
        help=f"{'grid edge' if table == 'clip' else 'entries'} (default {DEFAULT_SIZE[table]})",
    )
    dims = 3 if table == "clip" else 1
    p.add_argument(
        "--format",
        default=None,
        help=f"{', '.join(f for f in FORMATS if dims in FORMATS[f][2])} (default: from "
        "--out's extension, else clf)",
    )
    p.add_argument(
        "--out",
        "-o",
        default=None,
        help="file to write (default: a name from the options, in the current directory)",
    )
    p.add_argument("--quiet", action="store_true", help="no progress bar")


def _add_export(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    e = sub.add_parser(
        "export",
        help="write one table, clip LUT, view LUT or view shader as a standalone file",
        description="Write one LUT with OpenColorIO's writers, or a view as shader code. "
        "Every LUT takes the value itself: its domain is in the file. "
        "'ocio-thinfilm export TABLE --help' shows each one's options.",
    )
    kinds = e.add_subparsers(
        dest="subcommand",
        metavar="TABLE",
        required=True,
        help="film, morpho, clip, view, shader or material",
    )
    table_display = (
        f"display gamut ({', '.join(registry.DISPLAYS)}): clipped display-linear RGB instead of XYZ"
    )
    _add_film_parser(kinds, table_display)
    _add_morpho_parser(kinds, table_display)
    _add_clip_parser(kinds)
    _add_view_parser(kinds)
    _add_shader_parser(kinds)
    _add_material_parser(kinds)


def _add_film_parser(
    kinds: argparse._SubParsersAction[argparse.ArgumentParser], table_display: str
) -> None:
    """Add ``export film`` and its options to ``kinds``."""
    swatches_count = 25  # ocio_thinfilm.export.swatches.SWATCH_COUNT (imported when run)
    f = kinds.add_parser(
        "film",
        help="a thin-film thickness table (1D), a built-in kind or a film of a film file",
        description="Write the thickness table of a film kind (input: thickness in um), "
        "or with --films FILE --film KEY a film of a film file in every 1D format and "
        "as an EXR ramp, or its swatches (--swatches) or spectra (--spectra).",
    )
    f.add_argument(
        "--kind",
        default=None,
        help="film kind: phase-change (soap film, the default) or no-phase-change",
    )
    f.add_argument(
        "--index",
        type=float,
        default=None,
        help="film refractive index n: input becomes physical thickness t "
        "(t' = n t, normal incidence)",
    )
    f.add_argument("--display", default=None, help=table_display)
    _add_lut_options(f, "film", "thickness in um")
    f.add_argument(
        "--films",
        default=None,
        metavar="FILE",
        help="a film file (TOML, see docs/films.md); with --film KEY writes that "
        "film's table in every 1D format (clf, cube, spi1d) and as an EXR ramp "
        "(thickness along x) into --out DIR, or one of them to --out FILE",
    )
    f.add_argument("--film", default=None, metavar="KEY", help="the film of --films")
    f.add_argument(
        "--swatches",
        default=None,
        metavar="OUT.csv",
        help="with --films: write the film's colours (thickness, sRGB hex, linear sRGB, "
        "XYZ) as a CSV and a labelled PNG sheet beside it (OUT.png), at --thickness or "
        f"{swatches_count} thicknesses over its range",
    )
    f.add_argument(
        "--spectra",
        default=None,
        metavar="OUT.csv",
        help="with --films: write the film's reflectance spectra R(lambda) at --thickness "
        "as a CSV, and its transmittance T(lambda) too for a free-standing film",
    )
    f.add_argument(
        "--thickness",
        nargs="+",
        type=float,
        default=None,
        metavar="T",
        help="physical thicknesses of the film's varying layer in um, for --swatches and --spectra",
    )
    f.set_defaults(func=_run_film)


def _add_morpho_parser(
    kinds: argparse._SubParsersAction[argparse.ArgumentParser], table_display: str
) -> None:
    """Add ``export morpho`` and its options to ``kinds``."""
    m = kinds.add_parser(
        "morpho",
        help="the Morpho angle table (1D, input cos theta)",
        description="Write the Morpho butterfly's angle table (input: cos theta).",
    )
    m.add_argument("--display", default=None, help=table_display)
    _add_lut_options(m, "morpho", "cos(theta)")
    m.set_defaults(func=_run_table)


def _add_clip_parser(kinds: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add ``export clip`` and its options to ``kinds``."""
    c = kinds.add_parser(
        "clip",
        help="the constant-lightness clip into a display gamut (3D)",
        description="Write the constant-lightness clip of display-linear RGB into a "
        "display's gamut as a 3D LUT (clf, cube, csp; spi3d only over --range 0 1).",
    )
    c.add_argument(
        "--display",
        default=None,
        help=f"display gamut to clip into ({', '.join(registry.DISPLAYS)}); required",
    )
    _add_lut_options(c, "clip", "display-linear RGB per channel")
    c.set_defaults(func=_run_table)


def _add_view_parser(kinds: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add ``export view`` and its options to ``kinds``."""
    v = kinds.add_parser(
        "view",
        help="a display/view of the config as one LUT (display code values)",
        description="Write a display/view of the config, from one of its colour spaces, "
        "as one LUT: display code values out.",
    )
    _add_view_options(v)
    v.add_argument(
        "--format",
        default=None,
        help=f"{', '.join(LUT_FORMATS)}; spi1d only for thin-film inputs (default: from "
        "--out's extension)",
    )
    v.add_argument("--size", type=int, default=None, help="entries (1D) or grid edge (3D)")
    v.add_argument(
        "--range",
        nargs=2,
        type=float,
        metavar=("MIN", "MAX"),
        default=None,
        help="thin-film inputs: the input range (thickness in um, cos(theta))",
    )
    v.add_argument(
        "--resolve-shaper",
        action="store_true",
        help=".cube: DaVinci Resolve's form, a 1D shaper and the 3D LUT in "
        "one file (most other readers ignore the shaper); the default for "
        "ACEScct input is a plain 3D LUT over 0..1 that every reader applies "
        "alike",
    )
    _add_knob_options(v, "the view")
    v.set_defaults(func=_run_view)


def _add_shader_parser(kinds: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add ``export shader`` and its options to ``kinds``."""
    s = kinds.add_parser(
        "shader",
        help="a display/view as GLSL or DCTL code (the Clip and Compress views, no LUT)",
        description="Write the Constant-Lightness Clip or Compress view (input decoding, "
        "the map, the display encoding) as GLSL or a DaVinci Resolve DCTL, computed per "
        "pixel: no LUT.",
    )
    s.add_argument(
        "--lang",
        default=None,
        metavar="LANG",
        help="glsl (a function vec3 ocio_thinfilm_view(vec3), GLSL 3.30 / ES "
        "3.00) or dctl (a DaVinci Resolve transform DCTL)",
    )
    _add_view_options(s, default_source=registry.REFERENCE)
    _add_knob_options(s, "the code's defaults (GLSL uniforms, DCTL sliders)")
    s.set_defaults(func=_run_shader)


def _add_material_parser(kinds: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add ``export material`` and its options to ``kinds``."""
    mat = kinds.add_parser(
        "material",
        help="a film of a film file as a view-dependent material: R (and T) over "
        "thickness x cos theta, float EXR",
        description="Write a film's unpolarised reflectance (and, for a free-standing "
        "film, transmittance) over its thickness range (x) and the cosine of the view "
        "angle (y) as float OpenEXR images in a scene-linear space, for renderers "
        "(see docs/materials.md).",
    )
    mat.add_argument(
        "--films", required=True, metavar="FILE", help="a film file (TOML, see docs/films.md)"
    )
    mat.add_argument("--film", default=None, metavar="KEY", help="the film of --films")
    mat.add_argument(
        "--out",
        "-o",
        required=True,
        metavar="DIR",
        help="output directory (created if missing; files this tool did not write are "
        "never replaced)",
    )
    from ocio_thinfilm.export.material import DEFAULT_SPACE, GAMUTS

    mat.add_argument(
        "--space",
        action="append",
        default=None,
        metavar="SPACE",
        help=f"scene-linear space of the RGB ({', '.join(registry.SCENE_LINEAR_SPACES)}; "
        f"default {DEFAULT_SPACE}); repeat it for tables in several spaces in one folder: "
        "the first keeps the plain file names, the others carry the space "
        "(<stem>_LinearRec2020_R.exr), and the Blender script loads the tables of the "
        "scene's working space (docs/blender.md)",
    )
    mat.add_argument(
        "--size",
        default=None,
        metavar="WxH",
        help="texels along thickness x cos theta, e.g. 256x64 (default: measured per film, "
        "docs/materials.md)",
    )
    mat.add_argument(
        "--gamut",
        default=GAMUTS[0],
        choices=GAMUTS,
        help="colours outside the space's gamut: keep their negative channels (default), "
        "or clip them at constant lightness into the space's RGB cube, for renderers that "
        "clamp negative colours (Cycles, MaterialX); clip needs a --space with a display's "
        "primaries (docs/materials.md)",
    )
    mat.add_argument(
        "--gltf",
        action="store_true",
        help="also write <stem>.glb (the film on a sample sphere: the exact tables in the "
        "OCIO_THINFILM_materials_film extension, a fitted KHR_materials_iridescence "
        "fallback) and ocio_thinfilm_gltf.js, the three.js GLTFLoader plugin (docs/gltf.md)",
    )
    mat.add_argument(
        "--jobs",
        "-j",
        type=int,
        default=None,
        metavar="N",
        help="threads that compute the tables, N >= 1 (default: the CPUs this process may "
        "use); the files are the same bytes for any N",
    )
    mat.add_argument("--quiet", action="store_true", help="no progress bar")
    mat.set_defaults(func=_run_material)


def _add_view_options(p: argparse.ArgumentParser, default_source: str | None = None) -> None:
    """Add ``--from``, ``--display``, ``--view`` and ``--out`` of ``export view|shader``."""
    p.add_argument(
        "--from",
        dest="source",
        default=None,
        metavar="SPACE",
        help="input colour space of the config (e.g. ACEScct, ACEScg, "
        "'Linear Rec.709 (sRGB)', a thin-film space)"
        + (f"; default {default_source}" if default_source else ""),
    )
    p.add_argument(
        "--display",
        default=None,
        help=f"any display of the config ({', '.join(registry.DISPLAYS)}, "
        f"{', '.join(registry.HDR_DISPLAYS)})",
    )
    p.add_argument(
        "--view", default=None, help="the display's view (e.g. 'Constant-Lightness Clip')"
    )
    p.add_argument(
        "--out",
        "-o",
        default=None,
        help="file to write (default: a name from the options, in the current directory)",
    )


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add the ``bake`` and ``export`` commands to the ``sub`` parsers.

    Parameters
    ----------
    sub : argparse._SubParsersAction
        The sub-parsers of the ``ocio-thinfilm`` parser.
    """
    _add_bake(sub)
    _add_export(sub)
