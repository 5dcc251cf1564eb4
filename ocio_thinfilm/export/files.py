"""``ocio-thinfilm bake`` and ``ocio-thinfilm export``: the config folder and standalone LUTs.

Stage 6 of the pipeline. Every file is written by OpenColorIO's own writers
(``GroupTransform.write`` for CLF, ``Baker`` for .cube / .spi1d / .spi3d / .csp),
atomically (:mod:`.io`), and without timestamps, so equal inputs give equal bytes.

Standalone LUTs (``export``)
----------------------------
Every file takes the value itself as input -- no hand scaling: a host applies it to
the pixel as it is.

- ``film`` / ``morpho``: a 1D table sampled uniformly over ``--range`` (thickness in
  micrometres, or cos(theta) for Morpho). CLF carries the range as a matrix in front
  of the LUT1D, ``.cube`` as ``LUT_1D_INPUT_RANGE``, ``.spi1d`` as ``From MIN MAX``.
  Output: CIE-XYZ-D65, or with ``--display`` the display-linear RGB after the
  constant-lightness clip. ``--index n`` makes the input the physical thickness t
  (t' = n t, normal incidence).
- ``clip``: the constant-lightness clip of one display as a 3D LUT over
  display-linear RGB in ``--range`` (default -0.5..1.5; 0 and 1 fall on grid
  nodes, so in-gamut colours are reproduced exactly). CLF carries the range as a
  matrix, ``.cube`` as an exact affine 1D shaper (``LUT_1D_INPUT_RANGE``) in front of
  the 3D LUT, ``.csp`` as its prelut. ``.spi3d`` has no input domain (it always takes
  0..1), so it is refused unless ``--range 0 1``. Output: clipped display-linear
  RGB. (The config's own clip LUTs work in projective chromaticity charts through
  ``FixedFunction XYZ_TO_xyY`` ops, which these formats cannot hold.)
- ``view`` (:mod:`.export_view`): a whole display/view of the config from any of its
  colour spaces, input the raw pixel values of that space, output display code
  values.

Functions: :func:`export_lut`, :func:`export_set`, :func:`bake`, :func:`register`.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import ocio_ops, tables
from ocio_thinfilm import registry
from ocio_thinfilm.io import (UsageError, atomic_file, check_output_file, claim_directory, is_stdout,
                 transaction)

__all__ = ["FORMATS", "TABLES", "DEFAULT_CONFIG_DIR", "DEFAULT_LUTS_DIR", "export_lut",
           "export_set", "bake", "register"]

#: Format name -> (OCIO writer format, file extension, LUT dimensions it can hold).
FORMATS = {
    "clf": ("Academy/ASC Common LUT Format", "clf", (1, 3)),
    "cube": ("resolve_cube", "cube", (1, 3)),
    "spi1d": ("spi1d", "spi1d", (1,)),
    "spi3d": ("spi3d", "spi3d", (3,)),
    "csp": ("cinespace", "csp", (3,)),
}
TABLES = ("film", "morpho", "clip")
#: Formats with no way to state their input domain: only usable over exactly [0, 1].
NO_DOMAIN = ("spi3d",)
DEFAULT_CONFIG_DIR = "configs/thinfilm"
DEFAULT_LUTS_DIR = "luts"
DEFAULT_SIZE = {"film": 4096, "morpho": 1024, "clip": 33}
MAX_SIZE = {"film": 1 << 20, "morpho": 1 << 20, "clip": 129}
DEFAULT_RANGE = {"film": (0.0, 1.5), "morpho": (0.0, 1.0), "clip": (-0.5, 1.5)}


# --------------------------------------------------------------------------- #
# Validation
# --------------------------------------------------------------------------- #
def _validate(table, kind, display, index, value_range, size, fmt):
    if table not in TABLES:
        raise UsageError(f"unknown table {table!r}; choose from {', '.join(TABLES)}, view")
    if fmt not in FORMATS:
        raise UsageError(f"unknown format {fmt!r}; choose from {', '.join(FORMATS)}")
    dims = 3 if table == "clip" else 1
    if dims not in FORMATS[fmt][2]:
        allowed = [f for f, spec in FORMATS.items() if dims in spec[2]]
        raise UsageError(f"format {fmt} cannot hold a {dims}D LUT; for {table} use "
                         f"{', '.join(allowed)}")
    if display is not None and display not in clip.DISPLAYS:
        raise UsageError(f"unknown display {display!r}; choose from {', '.join(clip.DISPLAYS)}")
    if table == "clip" and display is None:
        raise UsageError("export clip needs --display")
    if kind not in colorimetry.FILM_KINDS:
        raise UsageError(f"unknown film kind {kind!r}; choose from "
                         f"{', '.join(colorimetry.FILM_KINDS)}")
    if index is not None:
        if table != "film":
            raise UsageError("--index applies to film tables only")
        if not (math.isfinite(index) and 1.0 <= index <= 10.0):
            raise UsageError(f"--index must be a refractive index in [1, 10], got {index:g}")
    size = DEFAULT_SIZE[table] if size is None else size
    if not 2 <= size <= MAX_SIZE[table]:
        raise UsageError(f"--size must be in [2, {MAX_SIZE[table]}] for {table}, got {size}")
    lo, hi = DEFAULT_RANGE[table] if value_range is None else value_range
    if not (math.isfinite(lo) and math.isfinite(hi)) or lo >= hi:
        raise UsageError(f"--range must be two finite numbers MIN < MAX, got {lo:g} {hi:g}")
    if table == "film" and lo < 0:
        raise UsageError(f"--range: thickness must not be negative, got {lo:g}")
    if table == "morpho" and (lo < 0 or hi > 1):
        raise UsageError(f"--range: cos(theta) must lie in [0, 1], got {lo:g} {hi:g}")
    if table == "clip" and (lo > 0 or hi < 1):
        raise UsageError(f"--range must contain [0, 1] for clip, got {lo:g} {hi:g}")
    if table == "film" and hi > 1000:
        raise UsageError(f"--range: thickness above 1000 um is the incoherent grey; got {hi:g}")
    if fmt in NO_DOMAIN and (lo, hi) != (0.0, 1.0):
        raise UsageError(f"format {fmt} has no input domain (it always takes 0..1), so it "
                         f"cannot take {table} input over {lo:g}..{hi:g}; use "
                         f"{', '.join(f for f in FORMATS if f not in NO_DOMAIN and dims in FORMATS[f][2])}")
    return size, (float(lo), float(hi))


# --------------------------------------------------------------------------- #
# LUT contents
# --------------------------------------------------------------------------- #
def _stem(table, kind, display, index):
    if table == "film":
        stem = "ThinFilm_" + ("PhaseChange" if kind == "phase-change" else "NoPhaseChange")
        if index is not None:
            stem += f"_n{index:g}"
    elif table == "morpho":
        stem = "ThinFilm_Morpho"
    else:
        stem = "ConstantLightnessClip"
    if display is not None:
        stem += "_" + registry.display(display).lut_stem
    return stem


def lut_contents(table, *, kind="phase-change", display=None, index=None, value_range=None,
                 size=None, progress=None):
    """(values array, LUT transform, metadata dict) for one standalone LUT.

    ``values``: (size, 3) or (size, size, size, 3), on the uniform grid over the
    normalised input p in [0, 1].
    """
    size, (lo, hi) = _validate(table, kind, display, index, value_range, size, "clf")
    x = np.linspace(lo, hi, size)
    if table == "film":
        n = 1.0 if index is None else index
        chunks = np.array_split(x, max(1, size // 8192))
        parts = []
        for chunk in chunks:
            parts.append(colorimetry.film_XYZ(chunk * n * 1000.0, kind,
                                              step=tables.SPECTRAL_STEP))
            if progress:
                progress(len(chunk) / size)
        values = np.concatenate(parts)
        what = ("physical thickness t in um (t' = %g t)" % n if index is not None
                else "optical thickness t' = n t cos(theta_t) in um")
        description = (f"Smits & Meyer 1990 {kind} thin film, {size} entries uniform over "
                       f"{lo:g}-{hi:g} um")
    elif table == "morpho":
        values = colorimetry.morpho_XYZ(np.degrees(np.arccos(np.clip(x, 0.0, 1.0))),
                                        step=tables.SPECTRAL_STEP)
        if progress:
            progress(1.0)
        what = "cos(theta), the facing ratio N.V"
        description = (f"Smits & Meyer 1990 Morpho multilayer (Eq. 9 + 14), {size} entries "
                       f"uniform over cos(theta) {lo:g}-{hi:g}")
    else:
        g = np.stack(np.meshgrid(x, x, x, indexing="ij"), axis=-1)
        values = clip.clip_RGB(g, display)
        if progress:
            progress(1.0)
        what = f"{display} display-linear RGB"
        description = (f"Smits & Meyer 1990 constant-lightness clip into {display} "
                       f"(Section 3.2), {size}^3 tetrahedral LUT3D over display-linear RGB "
                       f"{lo:g}..{hi:g} per channel")
    if table != "clip":
        if display is None:
            output = "CIE-XYZ-D65 (perfect reflector Y = 1), unclipped"
        else:
            values = clip.clip_RGB(colorimetry.XYZ_to_RGB(values, display), display)
            output = f"{display} display-linear RGB, constant-lightness clipped"
            description += f", clipped into {display}"
        lut = ocio_ops.lut1d_transform(values)
    else:
        output = f"{display} display-linear RGB, constant-lightness clipped"
        lut = ocio_ops.lut3d_transform(values)
    meta = dict(name=_stem(table, kind, display, index), input=what, output=output,
                description=description, range=(lo, hi), size=size,
                id=ocio_ops.transform_id("Export", _stem(table, kind, display, index)))
    return values, lut, meta


def _baker_config(lut, lo, hi):
    """A minimal in-memory config for baking ``lut`` over the input domain [lo, hi]:

    - ``input`` (the reference): the raw value -- thickness, cos(theta) or RGB;
    - ``output``: from the reference, the range matrix (x - lo) / (hi - lo) then ``lut``;
    - ``domain``: an affine shaper space, [0, 1] <-> [lo, hi]. Given as the Baker's
      shaper space it makes the writers state the domain in the file: ``.cube``
      ``LUT_1D_INPUT_RANGE lo hi`` (1D) or an exact affine 1D shaper before the 3D LUT,
      ``.spi1d`` ``From lo hi``, ``.csp`` a prelut.
    """
    import PyOpenColorIO as ocio

    span = hi - lo
    config = ocio.Config.CreateRaw()
    config.setVersion(2, 1)
    for name in list(config.getColorSpaceNames()):
        config.removeColorSpace(name)
    ref = ocio.ColorSpace()
    ref.setName("input")
    config.addColorSpace(ref)
    out = ocio.ColorSpace()
    out.setName("output")
    out.setTransform(ocio_ops.group([ocio_ops.matrix(np.eye(3) / span, [-lo / span] * 3), lut]),
                     ocio.COLORSPACE_DIR_FROM_REFERENCE)
    config.addColorSpace(out)
    domain = ocio.ColorSpace()
    domain.setName("domain")
    domain.setTransform(ocio_ops.matrix(np.eye(3) * span, [lo] * 3),
                        ocio.COLORSPACE_DIR_TO_REFERENCE)
    config.addColorSpace(domain)
    config.setRole("scene_linear", "input")
    return config


#: Entries of the affine shaper / prelut that carries a 3D LUT's domain (.cube, .csp).
#: The shaper is a straight line, so any size is exact; 1024 keeps ffmpeg's .csp
#: prelut resampling (it interpolates between knots without dividing by their spacing)
#: within 1/1023 of the grid coordinate.
DOMAIN_SHAPER_SIZE = 1024


def write_lut(path, fmt, values, lut, meta):
    """Write one LUT file with OCIO's writer for ``fmt`` (atomically). Every format
    takes the value itself: the domain ``meta["range"]`` is carried by the file."""
    import PyOpenColorIO as ocio

    writer, ext, _ = FORMATS[fmt]
    path = Path(path)
    lo, hi = meta["range"]
    if fmt in NO_DOMAIN and (lo, hi) != (0.0, 1.0):
        raise UsageError(f"format {fmt} has no input domain; cannot hold {lo:g}..{hi:g}")
    with atomic_file(path) as tmp:
        if fmt == "clf":
            span = hi - lo
            ops = []
            if (lo, hi) != (0.0, 1.0):
                ops.append(ocio_ops.matrix(np.eye(3) / span, [-lo / span] * 3))
            ops.append(lut)
            g = ocio_ops.group(ops, name=meta["name"], id=meta["id"],
                             description=meta["description"],
                             input_descriptor=meta["input"], output_descriptor=meta["output"])
            g.write(writer, str(tmp), ocio.Config.CreateRaw())
        else:
            baker = ocio.Baker()
            baker.setConfig(_baker_config(lut, lo, hi))
            baker.setFormat(writer)
            baker.getFormatMetadata().addChildElement(
                "Description", f"{meta['name']}: input {meta['input']}, {lo:g}..{hi:g} "
                               f"(the value itself); output {meta['output']}")
            baker.setInputSpace("input")
            baker.setTargetSpace("output")
            size = meta["size"]
            baker.setCubeSize(size)  # the 1D writers take their length from the cube size
            if fmt not in NO_DOMAIN:
                baker.setShaperSpace("domain")
                baker.setShaperSize(size if values.ndim == 2 else DOMAIN_SHAPER_SIZE)
            text = baker.bake()
            Path(tmp).write_text(text if text.endswith("\n") else text + "\n")
    return path


def export_lut(table, out=None, *, fmt=None, kind="phase-change", display=None, index=None,
               value_range=None, size=None, show_progress=False) -> Path:
    """Compute and write one standalone LUT; returns the path written."""
    if fmt is None:
        fmt = Path(out).suffix.lstrip(".").lower() if out else "clf"
        if fmt not in FORMATS:
            raise UsageError(f"cannot tell the format from {out!r}; pass --format")
    _validate(table, kind, display, index, value_range, size, fmt)
    if out is None:
        out = Path(_stem(table, kind, display, index) + "." + FORMATS[fmt][1])
    out = check_output_file(out)
    bar = _progress(show_progress, total=1.0, desc=f"export {out.name}")
    try:
        values, lut, meta = lut_contents(table, kind=kind, display=display, index=index,
                                         value_range=value_range, size=size,
                                         progress=bar.update if bar else None)
        write_lut(out, fmt, values, lut, meta)
    finally:
        if bar:
            bar.close()
    return out


def export_set(directory, *, show_progress=False) -> list[Path]:
    """The standalone set shipped in ``luts/``: every table in every format that can
    hold it with its domain, plus the common display LUTs
    (:data:`EXPORT_SET_VIEWS`: ACEScct -> each display's Constant-Lightness Clip as
    a 65^3 .cube), into ``directory``, which must exist."""
    from ocio_thinfilm.export import view as export_view

    jobs = []
    for fmt in FORMATS:
        for kind in colorimetry.FILM_KINDS:
            if 1 in FORMATS[fmt][2]:
                jobs.append(("film", dict(kind=kind), fmt))
        if 1 in FORMATS[fmt][2]:
            jobs.append(("morpho", {}, fmt))
        # (the clip over display-linear RGB, `export clip`, is not shipped: a grid over
        # linear RGB cannot resolve dark saturated colours; the display LUTs below are
        # what to take)
    views = [(source, display, view, fmt) for source, view, fmts in EXPORT_SET_VIEWS
             for display in clip.DISPLAYS for fmt in fmts]
    written = []
    bar = _progress(show_progress, total=len(jobs) + len(views), desc="export luts")
    cache = {}
    for table, kw, fmt in jobs:
        key = (table, tuple(sorted(kw.items())))
        if key not in cache:
            cache[key] = lut_contents(table, **kw)
        values, lut, meta = cache[key]
        path = Path(directory) / f"{meta['name']}.{FORMATS[fmt][1]}"
        write_lut(path, fmt, values, lut, meta)
        written.append(path)
        if bar:
            bar.update(1)
    for source, display, view, fmt in views:
        name = export_view.set_name(source, display, view) + "." + fmt
        written += export_view.export_view(source, display, view, Path(directory) / name,
                                           size=export_view.DEFAULT_VIEW_SIZE)
        if bar:
            bar.update(1)
    if bar:
        bar.close()
    return written


#: Display LUTs in the shipped set: (input space, view, formats), for every display.
EXPORT_SET_VIEWS = (("ACEScct", "Constant-Lightness Clip", ("cube",)),)



def _legacy_config(directory):
    """The files of a config folder baked before the ownership marker existed (e.g.
    the committed ``configs/thinfilm``): ``config.ocio`` saying it was generated by
    ocio-thinfilm, and nothing else but ``luts/*.clf``. None if it is not one."""
    directory = Path(directory)
    cfg = directory / "config.ocio"
    try:
        if "Generated by ocio-thinfilm" not in cfg.read_text(errors="replace")[:4096]:
            return None
    except OSError:
        return None
    owned = {"config.ocio"}
    for entry in directory.iterdir():
        if entry.name == "config.ocio":
            continue
        if entry.name != "luts" or not entry.is_dir() or entry.is_symlink():
            return None
        for lut in entry.iterdir():
            if not (lut.suffix == ".clf" and lut.is_file() and not lut.is_symlink()):
                return None
            owned.add(f"luts/{lut.name}")
    return owned


def _legacy_luts(directory):
    """The files of a standalone LUT set written before the ownership marker existed
    (e.g. the committed ``luts/``): only our LUT names and extensions. None if not."""
    exts = {"." + spec[1] for spec in FORMATS.values()}
    owned = set()
    for entry in Path(directory).iterdir():
        if not (entry.is_file() and not entry.is_symlink() and entry.suffix in exts
                and entry.name.startswith(("ThinFilm_", "ConstantLightnessClip_",
                                           "ACEScct_to_"))):
            return None
        owned.add(entry.name)
    return owned


def _check_staged_clfs(directory, final):
    from ocio_thinfilm.io import _check_xml

    for path in sorted(Path(directory).rglob("*.clf")):
        _check_xml(path, Path(final) / path.relative_to(directory))


def bake(out=DEFAULT_CONFIG_DIR, *, clip_size=tables.CLIP_SIZE, show_progress=False,
         luts=None) -> Path:
    """Write the config folder (config.ocio + luts/*.clf) to ``out`` and, with
    ``luts``, the standalone LUT set (:func:`export_set`) to that directory.

    Both directories must be new, empty, or written by an earlier bake (they then hold
    the marker :data:`.io.MARKER`; files they list are replaced or removed, nothing
    else is touched). Everything is validated, written aside and checked first, then
    committed file by file with ``config.ocio`` last, so a failure (a full disk,
    Ctrl-C) leaves both directories as they were, and a kill leaves each a complete,
    loadable set of files.
    """
    from ocio_thinfilm.config import generate as config

    if isinstance(clip_size, bool) or not 9 <= int(clip_size) <= 129:
        raise UsageError(f"--clip-size must be in [9, 129], got {clip_size}")
    claim = claim_directory(out, option="--out", legacy=_legacy_config, last=("config.ocio",))
    luts_claim = None
    if luts is not None:
        luts_claim = claim_directory(luts, option="--luts", legacy=_legacy_luts)
        a, b = luts_claim.path.resolve(), claim.path.resolve()
        if a == b or a in b.parents or b in a.parents:
            raise UsageError(f"--luts {luts}: must not be, contain or lie inside the --out "
                             f"directory {out}")
    n_files = len(config.THIN_FILM_SPACES) + 2 * len(clip.DISPLAYS) + 1  # 2 clip LUTs each
    bar = _progress(show_progress, total=n_files, desc=f"bake {claim.path}")
    try:
        with transaction() as tx:
            stage = tx.directory(claim)
            try:
                config.write_config(stage, clip_size=int(clip_size),
                                    progress=(lambda name: bar.update(1)) if bar else None)
            except OSError as error:
                raise OSError(f"cannot write {claim.path}: {error.strerror or error}") from None
            except Exception:
                _check_staged_clfs(stage, claim.path)  # a truncated LUT (disk full) says so
                raise
            if luts_claim is not None:
                export_set(tx.directory(luts_claim), show_progress=show_progress)
    finally:
        if bar:
            bar.close()
    _remove_old_leftovers(claim.path, _legacy_config)
    if luts_claim is not None:
        _remove_old_leftovers(luts_claim.path, _legacy_luts)
    return claim.path / "config.ocio"


def _remove_old_leftovers(path, legacy):
    """Earlier versions swapped whole directories through ``.NAME.XXXXXXXX`` and
    ``.NAME.old`` siblings, which a kill could leave behind: remove those that hold
    exactly what a bake writes (nothing else is touched)."""
    import re
    import shutil

    pattern = re.compile(re.escape(f".{path.name}.") + r"(old|[A-Za-z0-9_]{8})")
    try:
        entries = list(path.parent.iterdir())
    except OSError:
        return
    for entry in entries:
        if pattern.fullmatch(entry.name) and entry.is_dir() and not entry.is_symlink():
            try:
                empty = not any(entry.iterdir())
            except OSError:
                continue
            if empty or legacy(entry) is not None:
                shutil.rmtree(entry, ignore_errors=True)


def _progress(show, total, desc):
    if not show:
        return None
    from tqdm import tqdm

    return tqdm(total=total, desc=desc, unit="" if isinstance(total, int) else "",
                leave=False, file=sys.stderr, mininterval=0.2,
                bar_format="{desc}: {percentage:3.0f}%|{bar}| {elapsed}")


# --------------------------------------------------------------------------- #
# CLI
# --------------------------------------------------------------------------- #
def _int(option, text):
    if text is None:
        return None
    try:
        return int(text)
    except ValueError:
        raise UsageError(f"{option} must be an integer, got {text!r}") from None


def _float(option, text):
    if text is None:
        return None
    try:
        return float(text)
    except ValueError:
        raise UsageError(f"{option} must be a number, got {text!r}") from None


def _run_bake(args) -> int:
    if getattr(args, "into", None) or str(args.out).lower().endswith(".ocioz"):
        from ocio_thinfilm.config import merge  # --into CONFIG and/or an .ocioz archive (issue 10)

        if args.into and args.out == DEFAULT_CONFIG_DIR:
            raise UsageError("--into needs --out DIR (or FILE.ocioz)")
        if args.luts is not None:
            raise UsageError("--luts goes with a plain bake, not with --into or .ocioz")
        clip_size = _int("--clip-size", args.clip_size)
        if isinstance(clip_size, bool) or not 9 <= int(clip_size) <= 129:
            raise UsageError(f"--clip-size must be in [9, 129], got {clip_size}")
        path = (merge.bake_into(args.into, args.out, clip_size=clip_size) if args.into
                else merge.bake_archive(args.out, clip_size=clip_size))
        print(f"wrote {path}")
        return 0
    path = bake(args.out, clip_size=_int("--clip-size", args.clip_size),
                show_progress=not args.quiet, luts=args.luts)
    print(f"wrote {path}" + (f" and {args.luts}" if args.luts is not None else ""))
    return 0


def _run_export(args) -> int:
    if args.table == "view":
        from ocio_thinfilm.export import view as export_view

        return export_view.run(args)
    value_range = (None if args.range is None
                   else tuple(_float("--range", v) for v in args.range))
    path = export_lut(args.table, args.out, fmt=args.format, kind=args.kind,
                      display=args.display, index=_float("--index", args.index),
                      value_range=value_range, size=_int("--size", args.size),
                      show_progress=not args.quiet)
    print(f"wrote {path}", file=sys.stderr if is_stdout(path) else sys.stdout)
    return 0


def register(sub) -> None:
    p = sub.add_parser("bake", help="write the OpenColorIO config folder "
                                    "(config.ocio + luts/*.clf)",
                       description="Write the drop-in OCIO config and its CLF LUTs, atomically.")
    p.add_argument("--out", default=DEFAULT_CONFIG_DIR,
                   help=f"config directory to (re)write (default {DEFAULT_CONFIG_DIR})")
    p.add_argument("--clip-size", default=tables.CLIP_SIZE,
                   help=f"edge of the 3D clip LUTs (default {tables.CLIP_SIZE})")
    p.add_argument("--luts", default=None, metavar="DIR",
                   help="also write the standalone LUT set (every table, display and "
                        "format) into DIR, e.g. luts")
    p.add_argument("--into", default=None, metavar="CONFIG",
                   help="add the thin-film input spaces, the clip views and named "
                        "transforms to CONFIG (a config file or a built-in ocio:// URI, "
                        "e.g. ocio://studio-config-latest) and write the result to --out "
                        "(see docs/studio.md); --out FILE.ocioz writes an OCIO archive")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_run_bake)

    e = sub.add_parser("export", help="write one table or clip LUT as a standalone file "
                                      "(CLF, .cube, .spi1d/.spi3d, .csp)",
                       description="Write one LUT with OpenColorIO's writers. Film/Morpho "
                                   "tables are 1D (clf, cube, spi1d); the clip is 3D (clf, "
                                   "cube, csp; spi3d only over --range 0 1). Every file "
                                   "takes the value itself: its domain is in the file.")
    e.add_argument("table", metavar="TABLE",
                   help="film (thickness table), morpho (angle table), clip (the "
                        "constant-lightness clip) or view (a display/view of the config "
                        "from --from SPACE: display code values; cube, csp, clf, ctf, "
                        "spi3d, or spi1d for thin-film inputs)")
    e.add_argument("--kind", default="phase-change",
                   help="film kind: phase-change (soap film) or no-phase-change")
    e.add_argument("--display", default=None,
                   help=f"display gamut ({', '.join(clip.DISPLAYS)}): clip into it "
                        "(required for clip; for tables gives clipped display-linear RGB "
                        "instead of XYZ)")
    e.add_argument("--index", default=None,
                   help="film refractive index n: input becomes physical thickness t "
                        "(t' = n t, normal incidence)")
    e.add_argument("--range", nargs=2, metavar=("MIN", "MAX"), default=None,
                   help="input range: thickness in um (film, default 0 1.5), cos(theta) "
                        "(morpho, default 0 1), display-linear RGB per channel (clip, "
                        "default -0.5 1.5)")
    e.add_argument("--size", default=None,
                   help="entries (1D) or grid edge (3D); defaults 4096 / 1024 / 33")
    e.add_argument("--format", default=None,
                   help=f"{', '.join(FORMATS)} (default: from --out's extension, else clf)")
    e.add_argument("--out", "-o", default=None, help="file to write (default: a name "
                                                     "from the options, in the current "
                                                     "directory)")
    e.add_argument("--from", dest="source", default=None, metavar="SPACE",
                   help="view: input colour space of the config (e.g. ACEScct, ACEScg, "
                        "'Linear Rec.709 (sRGB)', a thin-film space)")
    e.add_argument("--view", default=None,
                   help="view: the display's view (e.g. 'Constant-Lightness Clip')")
    e.add_argument("--quiet", action="store_true", help="no progress bar")
    e.set_defaults(func=_run_export)
