"""``ocio-thinfilm bake`` and ``ocio-thinfilm export``: their options and what they run.

Options are parsed and typed by argparse here; the library functions
(:func:`ocio_thinfilm.export.bake.bake`, :func:`ocio_thinfilm.export.merged.bake_into`,
:func:`ocio_thinfilm.export.files.export_lut`,
:func:`ocio_thinfilm.export.view.export_view`) check what the values allow.
"""

from __future__ import annotations

import argparse
import sys

from ocio_thinfilm import registry
from ocio_thinfilm.checks import UsageError
from ocio_thinfilm.colour import compress as compress_map
from ocio_thinfilm.export import bake as bake_module
from ocio_thinfilm.export.files import FORMATS, export_lut
from ocio_thinfilm.io import is_stdout
from ocio_thinfilm.lut import clip_lut

__all__ = ["register"]

#: The compression's knobs: option -> (``dest``, the library default).
_KNOB_OPTIONS = {
    "--compress-threshold": ("compress_threshold", compress_map.THRESHOLD),
    "--compress-limit": ("compress_limit", compress_map.LIMIT),
}


def _compress_knobs(args) -> dict[str, float]:
    """Return the knobs as the library's keyword arguments, checked, and warn if untested.

    A knob out of range is a ParameterError naming the library parameter (the command
    line names the option). Knobs outside the tested range
    (:func:`ocio_thinfilm.lut.compress_lut.untested_knobs_note`) print one warning line
    on stderr with the accuracy measured there.
    """
    from ocio_thinfilm.lut import compress_lut

    names = tuple(dest for dest, _ in _KNOB_OPTIONS.values())
    given = [
        default if getattr(args, dest) is None else getattr(args, dest)
        for dest, default in _KNOB_OPTIONS.values()
    ]
    threshold, limit = compress_map.check_knobs(*given, names=(names[0], names[1]))
    note = compress_lut.untested_knobs_note(threshold, limit)
    if note is not None:
        print(f"ocio-thinfilm {args.command}: warning: {note}", file=sys.stderr)
    return dict(zip(names, (threshold, limit), strict=True))


def _knobs_given(args) -> list[str]:
    return [
        option for option, (dest, _) in _KNOB_OPTIONS.items() if getattr(args, dest) is not None
    ]


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


def _run_bake(args) -> int:
    knobs = _compress_knobs(args)
    if getattr(args, "into", None) or str(args.out).lower().endswith(".ocioz"):
        # --into CONFIG (merge into a studio config) and/or an .ocioz archive
        from ocio_thinfilm.config import merge
        from ocio_thinfilm.export import merged

        if args.into and args.out == bake_module.DEFAULT_CONFIG_DIR:
            raise UsageError("--into needs --out DIR (or FILE.ocioz)")
        if args.luts is not None:
            raise UsageError("--luts goes with a plain bake, not with --into or .ocioz")
        clip_size = bake_module.check_clip_size(args.clip_size)
        path = (
            merged.bake_into(args.into, args.out, clip_size=clip_size, films=args.films, **knobs)
            if args.into
            else merged.bake_archive(args.out, clip_size=clip_size, films=args.films, **knobs)
        )
        print(f"wrote {path}")
        if args.into:  # a merged config has the base config's profile: say who reads it
            import PyOpenColorIO as ocio

            print(merge.profile_readers(ocio.Config.CreateFromFile(str(path))))
        return 0
    path = bake_module.bake(
        args.out,
        clip_size=args.clip_size,
        show_progress=not args.quiet,
        luts=args.luts,
        films=args.films,
        **knobs,
    )
    print(f"wrote {path}" + (f" and {args.luts}" if args.luts is not None else ""))
    return 0


def _run_shader(args) -> int:
    """``export shader``: the view's map as GLSL or DCTL."""
    from ocio_thinfilm.export import shader, view

    for option, given in (
        ("--kind", args.kind != "phase-change"),
        ("--index", args.index is not None),
        ("--range", args.range is not None),
        ("--size", args.size is not None),
        ("--format", args.format is not None),
        ("--resolve-shaper", args.resolve_shaper),
        ("--films", args.films is not None),
        ("--film", args.film is not None),
    ):
        if given:
            raise UsageError(f"{option} does not apply to 'export shader' (code, not a LUT)")
    if args.lang is None:
        raise UsageError(f"--lang is needed for 'export shader': {' or '.join(shader.LANGUAGES)}")
    source = registry.REFERENCE if args.source is None else args.source
    out = args.out
    if out is None and args.display is not None and args.view is not None:
        out = f"{view.set_name(source, args.display, args.view)}.{args.lang}"
    threshold, limit = (
        default if getattr(args, dest) is None else getattr(args, dest)
        for dest, default in _KNOB_OPTIONS.values()
    )
    path = shader.export_shader(
        # without --display or --view the library refuses before it writes anything
        out if out is not None else "ocio_thinfilm_view",
        args.lang,
        args.display,
        args.view,
        source,
        threshold=threshold,
        limit=limit,
    )
    print(f"wrote {path}")
    return 0


def _run_export(args) -> int:
    given = _knobs_given(args)
    if given and (args.table not in ("view", "shader") or args.view != registry.COMPRESS_VIEW):
        what = (
            f"'export {args.table}'"
            if args.table not in ("view", "shader")
            else f"--view {args.view!r}"
        )
        raise UsageError(
            f"{given[0]} applies to 'export view|shader --view \"{registry.COMPRESS_VIEW}\"', "
            f"not {what}"
        )
    if args.table == "shader":
        return _run_shader(args)
    if args.lang is not None:
        raise UsageError(f"--lang applies to 'export shader', not {args.table!r}")
    if args.table == "view":
        from ocio_thinfilm.export.view import export_view

        knobs = _compress_knobs(args) if given else {}

        paths = export_view(
            args.source,
            args.display,
            args.view,
            args.out,
            fmt=args.format,
            size=args.size,
            value_range=args.range,
            shaper=True if args.resolve_shaper else None,
            **knobs,
        )
        for path in paths:
            print(f"wrote {path}")
        return 0
    if args.resolve_shaper:
        raise UsageError(f"--resolve-shaper applies to 'export view', not {args.table!r}")
    if args.films is not None or args.film is not None:
        if args.table != "film" or args.films is None:
            raise UsageError("--films FILE (with --film KEY) goes with 'export film'")
        for option, value in (
            ("--kind", args.kind != "phase-change"),
            ("--index", args.index),
            ("--range", args.range),
            ("--display", args.display),
        ):
            if value:
                raise UsageError(f"{option} does not apply to a film of --films (its file says)")
        from ocio_thinfilm.export.film_files import export_film

        for path in export_film(args.films, args.film, args.out, fmt=args.format, size=args.size):
            print(f"wrote {path}")
        return 0
    path = export_lut(
        args.table,
        args.out,
        fmt=args.format,
        kind=args.kind,
        display=args.display,
        index=args.index,
        value_range=args.range,
        size=args.size,
        show_progress=not args.quiet,
    )
    print(f"wrote {path}", file=sys.stderr if is_stdout(path) else sys.stdout)
    return 0


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add the ``bake`` and ``export`` commands to the ``sub`` parsers.

    Parameters
    ----------
    sub : argparse._SubParsersAction
        The sub-parsers of the ``ocio-thinfilm`` parser.
    """
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

    e = sub.add_parser(
        "export",
        help="write one table or clip LUT as a standalone file (CLF, .cube, .spi1d/.spi3d, .csp)",
        description="Write one LUT with OpenColorIO's writers. Film/Morpho "
        "tables are 1D (clf, cube, spi1d); the clip is 3D (clf, "
        "cube, csp; spi3d only over --range 0 1). Every file "
        "takes the value itself: its domain is in the file.",
    )
    e.add_argument(
        "table",
        metavar="TABLE",
        help="film (thickness table), morpho (angle table), clip (the "
        "constant-lightness clip), view (a display/view of the config "
        "from --from SPACE: display code values; cube, csp, clf, ctf, "
        "spi3d, or spi1d for thin-film inputs) or shader (the same view as "
        "code, --lang glsl or dctl: the Constant-Lightness Clip and Compress "
        "views computed per pixel, no LUT)",
    )
    e.add_argument(
        "--kind",
        default="phase-change",
        help="film kind: phase-change (soap film) or no-phase-change",
    )
    e.add_argument(
        "--display",
        default=None,
        help=f"display gamut ({', '.join(registry.DISPLAYS)}): clip into it "
        "(required for clip; for tables gives clipped display-linear RGB "
        "instead of XYZ); for view any display of the config "
        f"({', '.join(registry.HDR_DISPLAYS)} too)",
    )
    e.add_argument(
        "--index",
        type=float,
        default=None,
        help="film refractive index n: input becomes physical thickness t "
        "(t' = n t, normal incidence)",
    )
    e.add_argument(
        "--range",
        nargs=2,
        type=float,
        metavar=("MIN", "MAX"),
        default=None,
        help="input range: thickness in um (film, default 0 1.5), cos(theta) "
        "(morpho, default 0 1), display-linear RGB per channel (clip, "
        "default -0.5 1.5)",
    )
    e.add_argument(
        "--size",
        type=int,
        default=None,
        help="entries (1D) or grid edge (3D); defaults 4096 / 1024 / 33",
    )
    e.add_argument(
        "--format",
        default=None,
        help=f"{', '.join(FORMATS)} (default: from --out's extension, else clf)",
    )
    e.add_argument(
        "--out",
        "-o",
        default=None,
        help="file to write (default: a name from the options, in the current directory)",
    )
    e.add_argument(
        "--from",
        dest="source",
        default=None,
        metavar="SPACE",
        help="view: input colour space of the config (e.g. ACEScct, ACEScg, "
        "'Linear Rec.709 (sRGB)', a thin-film space)",
    )
    e.add_argument(
        "--view", default=None, help="view: the display's view (e.g. 'Constant-Lightness Clip')"
    )
    e.add_argument(
        "--resolve-shaper",
        action="store_true",
        help="view, .cube: DaVinci Resolve's form, a 1D shaper and the 3D LUT in "
        "one file (most other readers ignore the shaper); the default for "
        "ACEScct input is a plain 3D LUT over 0..1 that every reader applies "
        "alike",
    )
    e.add_argument(
        "--films",
        default=None,
        metavar="FILE",
        help="film: a film file (TOML, see docs/films.md); with --film KEY writes that "
        "film's table in every 1D format (clf, cube, spi1d) and as an EXR ramp "
        "(thickness along x) into --out DIR, or one of them to --out FILE",
    )
    e.add_argument("--film", default=None, metavar="KEY", help="film: the film of --films")
    e.add_argument(
        "--lang",
        default=None,
        metavar="LANG",
        help="shader: glsl (a function vec3 ocio_thinfilm_view(vec3), GLSL 3.30 / ES "
        "3.00) or dctl (a DaVinci Resolve transform DCTL)",
    )
    _add_knob_options(e, "view and shader (there: the knobs' defaults)")
    e.add_argument("--quiet", action="store_true", help="no progress bar")
    e.set_defaults(func=_run_export)
