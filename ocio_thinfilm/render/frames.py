"""``ocio-thinfilm render``: the paper's example scenes through the generated LUTs.

Stage 7 of the pipeline. A render goes through an OCIO config file -- ``--config``,
by default the package's baked ``configs/thinfilm/config.ocio`` (baked first when
missing) -- so it is an end-to-end test of what users load. For each scene
(:mod:`.scenes`) the renderer

1. hands the scene a ``lookup`` that applies, for each table the scene declares, the
   config's thin-film input colour space (pixel encoding -> CIE-XYZ-D65, e.g.
   ``config.getProcessor("Thin Film Morpho Iridescence", "CIE-XYZ-D65")``) with an
   OCIO CPU processor;
2. writes the composited scene-linear picture as an OpenEXR file: CIE XYZ (D65,
   Y = 1 the perfect white) in the R, G, B channels (``oiio:ColorSpace`` names it), plus
   the scene's AOVs (optical thickness, view angle ...) as extra channels;
3. applies the config's display view (``config.getProcessor("CIE-XYZ-D65", display,
   view, ...)``: CIE-XYZ-D65 -> display-encoded RGB) and writes an 8-bit PNG, with
   captions where the scene has them.

Only the colour spaces and views a scene uses become processors (:data:`PROCESSORS`
records them); nothing is computed from the spectra at render time.

Frames: without ``--frames`` a scene is written as ``NAME.exr`` / ``NAME.png``
(frame 1, the still). ``--frames A-B`` writes ``NAME.####.exr`` / ``.png``; every
frame depends only on (scene, frame, seed, size, display, view, config), and a range of
more than one frame is rendered by one child process per frame
(``python -m ocio_thinfilm render SCENE --frames N-N ...``), ``--jobs`` at a time,
exactly what a render farm would run. Output bytes are a function of the arguments.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.render import scenes as scene_module
from ocio_thinfilm.io import UsageError, check_output_file, check_writable, transaction, write_image

__all__ = ["register", "run", "render_scene", "write_frame", "save_frame", "parse_size", "parse_frames", "MAX_SIDE",
           "MAX_PIXELS", "SCENE_CHOICES", "DEFAULT_CONFIG", "PROCESSORS", "ConfigProcessors",
           "load_config", "make_lookup", "display_image", "table_colorspace"]

#: Limits on --size: each side 16..8192 and at most 4096 x 4096 pixels in total.
MIN_SIDE, MAX_SIDE, MAX_PIXELS = 16, 8192, 4096 * 4096
#: Limits on --frames.
MAX_FRAME = 9999
SCENE_CHOICES = tuple(scene_module.SCENES) + ("all",)
DEFAULT_SIZE = (512, 512)
DEFAULT_DISPLAY = "sRGB"
DEFAULT_VIEW = "Constant-Lightness Clip"

#: How the EXR's colour channels are to be read (also written into every EXR).
EXR_COLORSPACE = "CIE-XYZ-D65"
EXR_DOC = ("R,G,B hold scene-linear CIE XYZ (1931 2-degree observer, D65, Y = 1 is the "
           "perfect white under the scene's unit illuminant)")


#: How the PNG is tagged (OpenImageIO colour interop IDs): sRGB gets PNG's sRGB chunk,
#: Display P3 a cICP chunk, Rec.2020 (BT.1886 gamma 2.4) and the Raw view no tag --
#: never a wrong sRGB one.
PNG_COLORSPACE = {d.name: d.png_colorspace for d in registry.DISPLAY_LIST}

#: The EXR ``DateTime`` (fixed, for byte-identical output): Eurographics Workshop on
#: Photosimulation, Realism and Physics in Computer Graphics, Rennes, 11 June 1990.
FIXED_DATETIME = "1990:06:11 00:00:00"


# --------------------------------------------------------------------------- #
# Argument parsing
# --------------------------------------------------------------------------- #
def parse_size(text: str) -> tuple[int, int]:
    """``W`` or ``WxH`` -> (W, H), each side in [16, 8192], W*H <= 4096^2."""
    m = re.fullmatch(r"\s*([+-]?\d+)\s*(?:[xX]\s*([+-]?\d+)\s*)?", str(text))
    if not m:
        raise UsageError(f"--size {text!r}: expected W or WxH in pixels, e.g. 512 or 640x480")
    w = int(m.group(1))
    h = int(m.group(2)) if m.group(2) is not None else w
    for side in (w, h):
        if side < MIN_SIDE or side > MAX_SIDE:
            raise UsageError(f"--size {text}: each side must be between {MIN_SIDE} and "
                             f"{MAX_SIDE} pixels")
    if w * h > MAX_PIXELS:
        raise UsageError(f"--size {text}: at most {MAX_PIXELS} pixels (4096x4096) per image")
    return w, h


def parse_frames(text: str | None) -> list[int] | None:
    """``A-B`` (or ``N``) -> [A, ..., B] with 1 <= A <= B <= 9999; None -> None."""
    if text is None:
        return None
    m = re.fullmatch(r"\s*(\d+)\s*(?:-\s*(\d+)\s*)?", str(text))
    if not m:
        raise UsageError(f"--frames {text!r}: expected A-B (e.g. 1-24) or a single frame N")
    a = int(m.group(1))
    b = int(m.group(2)) if m.group(2) is not None else a
    if not 1 <= a <= b <= MAX_FRAME:
        raise UsageError(f"--frames {text}: need 1 <= A <= B <= {MAX_FRAME}")
    return list(range(a, b + 1))


def _check_display_view(display: str, view: str) -> None:
    if display not in registry.DISPLAYS:
        raise UsageError(f"--display {display!r}: choose from {', '.join(registry.DISPLAYS)}")
    if view not in registry.VIEWS:
        raise UsageError(f"--view {view!r}: choose from {', '.join(registry.VIEWS)}")


# --------------------------------------------------------------------------- #
# The config: tables and views as OCIO processors
# --------------------------------------------------------------------------- #
#: The config a render goes through by default: the package's baked config (baked
#: with ``ocio-thinfilm bake`` first when it is missing).
DEFAULT_CONFIG = Path(__file__).resolve().parents[2] / "configs" / "thinfilm" / "config.ocio"
#: The config's reference, the EXR's colour space: tables go to it, views start at it.
REFERENCE_SPACE = "CIE-XYZ-D65"

#: Processors created from a config in this process, one string per processor
#: (``"colorspace:<name>"``, ``"view:<display>/<view>"``). Tests use it to prove a scene
#: turns only the colour spaces and views it uses into processors.
PROCESSORS: list[str] = []


def table_colorspace(spec: scene_module.TableSpec) -> str:
    """The config's input colour space (pixel value -> CIE-XYZ-D65) of a scene's
    :class:`~.scenes.TableSpec`: the table the config ships for its kind."""
    from ocio_thinfilm.lut import tables

    lo, hi = spec.range
    if spec.kind == "morpho":
        if (lo, hi) != (0.0, 1.0) or spec.entries != tables.MORPHO_SIZE:
            raise ValueError(f"the config's Morpho table covers cos(theta) in [0, 1] with "
                             f"{tables.MORPHO_SIZE} entries, got {spec}")
    elif (lo, hi) != (0.0, tables.FILM_TMAX_UM) or spec.entries != tables.FILM_SIZE:
        raise ValueError(f"the config's thickness tables cover t' in [0, {tables.FILM_TMAX_UM:g}] "
                         f"um with {tables.FILM_SIZE} entries, got {spec}")
    return registry.thin_film_space_for_kind(spec.kind).name


def load_config(path=None):
    """``PyOpenColorIO.Config`` of ``path`` (default :data:`DEFAULT_CONFIG`, baked with
    :func:`.export.bake` first when missing)."""
    import PyOpenColorIO as ocio

    if path is None:
        path = DEFAULT_CONFIG
        if not path.is_file():
            from ocio_thinfilm.export import files as export

            export.bake(path.parent)
    path = Path(path)
    if not path.is_file():
        raise UsageError(f"--config {path}: no such config file")
    try:
        return ocio.Config.CreateFromFile(str(path))
    except Exception as error:  # OCIO's parse errors
        raise UsageError(f"--config {path}: {str(error).splitlines()[0]}") from None


class ConfigProcessors:
    """The OCIO CPU processors a render needs, created from one config on first use
    (and recorded in :data:`PROCESSORS`): ``table(spec)`` for a scene's table (its
    thin-film colour space -> CIE-XYZ-D65), ``view(display, view)`` for a view
    (CIE-XYZ-D65 -> display code values)."""

    def __init__(self, config=None):
        self.config = config if config is not None and not isinstance(config, (str, Path)) \
            else load_config(config)
        self._cpu = {}

    def _processor(self, key, make):
        if key not in self._cpu:
            try:
                self._cpu[key] = make().getDefaultCPUProcessor()
            except Exception as error:  # a missing space / view / LUT file
                raise UsageError(f"config: cannot build {key}: "
                                 f"{str(error).splitlines()[0]}") from None
            PROCESSORS.append(key)
        return self._cpu[key]

    def table(self, spec):
        space = table_colorspace(spec)
        return self._processor(f"colorspace:{space}",
                               lambda: self.config.getProcessor(space, REFERENCE_SPACE))

    def view(self, display: str, view: str):
        import PyOpenColorIO as ocio

        return self._processor(
            f"view:{display}/{view}",
            lambda: self.config.getProcessor(REFERENCE_SPACE, display, view,
                                             ocio.TRANSFORM_DIR_FORWARD))

    def check_display_view(self, display: str, view: str) -> None:
        """UsageError unless the config has ``display`` with ``view``."""
        displays = list(self.config.getDisplays())
        if display not in displays:
            raise UsageError(f"--display {display!r}: the config has {', '.join(displays)}")
        views = list(self.config.getViews(display))
        if view not in views:
            raise UsageError(f"--view {view!r}: the config's display {display} has "
                             f"{', '.join(views)}")


def _apply(cpu, pixels) -> np.ndarray:
    out = np.array(pixels, dtype=np.float32, order="C", copy=True)
    flat = out.reshape(-1, 3)
    if flat.size:
        cpu.applyRGB(flat)
    return flat.reshape(out.shape)


def build_table(spec: scene_module.TableSpec):
    """The tables-module table for a scene's :class:`~.scenes.TableSpec` (computed
    here, not read from a config: for comparisons with what the config holds)."""
    from ocio_thinfilm.lut import tables

    lo, hi = spec.range
    if spec.kind == "morpho":
        if (lo, hi) != (0.0, 1.0):
            raise ValueError(f"the Morpho table covers cos(theta) in [0, 1], got {spec.range}")
        return tables.morpho_table(spec.entries)
    if lo != 0.0:
        raise ValueError(f"thickness tables start at t' = 0, got {spec.range}")
    return tables.film_table(spec.kind, spec.entries, max_thickness_um=hi)


def _as_rgb(values: np.ndarray) -> np.ndarray:
    """(H, W) encoded values -> (H, W, 3) float32 with all three channels equal."""
    v = np.ascontiguousarray(values, dtype=np.float32)
    return np.repeat(v[..., None], 3, axis=-1)


def make_lookup(processors: ConfigProcessors | None = None):
    """A scene ``lookup(spec, encoded)`` that applies the config's colour space of
    each table (pixel encoding -> CIE-XYZ-D65) with OCIO's CPU processor, each built
    once on first use."""
    processors = processors if processors is not None else ConfigProcessors()

    def lookup(spec, encoded):
        return _apply(processors.table(spec), _as_rgb(encoded))

    lookup.processors = processors
    return lookup


def display_image(picture, display: str, view: str,
                  processors: ConfigProcessors | None = None) -> np.ndarray:
    """The display-encoded RGB of a scene's picture (float32, (H, W, 3)), each column
    region through its view (the config's display/view processors)."""
    processors = processors if processors is not None else ConfigProcessors()
    h, w, _ = picture.xyz.shape
    out = np.zeros((h, w, 3), np.float32)
    for x0, x1, region_view in picture.regions:
        cpu = processors.view(display, region_view or view)
        out[:, x0:x1] = _apply(cpu, np.ascontiguousarray(picture.xyz[:, x0:x1]))
    return np.clip(out, 0.0, 1.0)


def draw_labels(rgb: np.ndarray, labels) -> tuple[np.ndarray, bool]:
    """Draw ``(x, y, text, size)`` captions, centred at x, with OpenImageIO's
    ``render_text`` and its bundled font. Returns (image, whether text was drawn)."""
    if not labels:
        return rgb, True
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(oiio.ImageSpec(rgb.shape[1], rgb.shape[0], 3, oiio.FLOAT))
    buf.set_pixels(oiio.ROI(), np.ascontiguousarray(rgb, dtype=np.float32))
    drawn = True
    for x, y, text, size in labels:
        ok = oiio.ImageBufAlgo.render_text(buf, int(x), int(y), text, int(size), "",
                                           (0.92, 0.92, 0.92), "center", "baseline", 0)
        drawn = drawn and bool(ok)
    if not drawn:
        return rgb, False
    return buf.get_pixels(oiio.FLOAT), True


# --------------------------------------------------------------------------- #
# Rendering one frame of one scene
# --------------------------------------------------------------------------- #
def render_scene(name: str, size=DEFAULT_SIZE, *, seed: int = 0, frame: int = 1,
                 display: str = DEFAULT_DISPLAY, view: str = DEFAULT_VIEW, lookup=None,
                 config=None):
    """Render one frame through a config's processors: returns (picture,
    display-encoded RGB float32). ``config``: a :class:`ConfigProcessors`, a
    ``PyOpenColorIO.Config`` or a path (default: :data:`DEFAULT_CONFIG`); a ``lookup``
    from :func:`make_lookup` brings its own."""
    scene = scene_module.get_scene(name)
    width, height = size
    if isinstance(config, ConfigProcessors):
        processors = config
    elif config is None and getattr(lookup, "processors", None) is not None:
        processors = lookup.processors
    else:
        processors = ConfigProcessors(config)
    lookup = lookup or make_lookup(processors)
    picture = scene.render(width, height, lookup=lookup, seed=seed, frame=frame)
    rgb = display_image(picture, display, view, processors)
    rgb, _ = draw_labels(rgb, picture.labels)
    return picture, rgb


def _exr_attributes(scene, picture, *, seed, frame, display, view):
    attrs = {
        "oiio:ColorSpace": EXR_COLORSPACE,
        "ocio_thinfilm:colorspace": EXR_DOC,
        "ocio_thinfilm:scene": f"{scene.name} ({scene.figure}): {scene.title}",
        "ocio_thinfilm:seed": int(seed),
        "ocio_thinfilm:frame": int(frame),
        "ocio_thinfilm:png_view": f"{display} / {view}",
        "ocio_thinfilm:tables": "; ".join(
            f"{t.kind} over {t.encoding} in [{t.range[0]:g}, {t.range[1]:g}], {t.entries} entries"
            for t in scene.tables),
    }
    for channel, doc in picture.aov_docs.items():
        attrs[f"ocio_thinfilm:aov:{channel}"] = doc
    for key, value in picture.attributes.items():
        attrs[f"ocio_thinfilm:{key}"] = float(value) if isinstance(value, (int, float, np.floating)) \
            else str(value)
    return attrs


def frame_paths(name: str, out_dir: Path, frame: int | None) -> list[Path]:
    """The EXR and PNG paths of one frame of one scene."""
    stem = name if frame is None else f"{name}.{frame:04d}"
    return [Path(out_dir) / f"{stem}.exr", Path(out_dir) / f"{stem}.png"]


def save_frame(name: str, picture, rgb, out_dir: Path, *, seed: int, frame: int | None,
               display: str, view: str, tx=None) -> list[Path]:
    """Write a rendered frame as ``NAME[.####].exr`` and ``.png``; returns the paths.

    The pair is one transaction (:mod:`.io`): both files are written aside and checked,
    then renamed together, so a failed EXR never leaves a new PNG beside an old EXR.
    With ``tx`` they join the caller's transaction instead (committed by the caller)."""
    if tx is None:
        with transaction() as own:
            return save_frame(name, picture, rgb, out_dir, seed=seed, frame=frame,
                              display=display, view=view, tx=own)
    scene = scene_module.get_scene(name)
    stem = name if frame is None else f"{name}.{frame:04d}"
    for path in frame_paths(name, out_dir, frame):
        check_output_file(path)
    channels = ["R", "G", "B"] + list(picture.aovs)
    data = np.concatenate([picture.xyz] + [a[..., None] for a in picture.aovs.values()],
                          axis=-1)
    attrs = _exr_attributes(scene, picture, seed=seed, frame=frame or 1, display=display,
                            view=view)
    # ZIPS: lossless, and faster than zip or piz on these pictures. The two files are
    # encoded in parallel (OpenImageIO releases the GIL); each is written atomically.
    attrs["compression"] = "zips"
    # OpenImageIO stamps EXRs with the current time unless told otherwise: a fixed
    # stamp (the paper's conference date) keeps the bytes a function of the arguments.
    attrs["DateTime"] = FIXED_DATETIME
    # R, G, B hold CIE XYZ: the EXR chromaticities of XYZ (white = equal energy E).
    attrs["chromaticities"] = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0 / 3.0, 1.0 / 3.0)
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=2) as pool:
        exr_job = pool.submit(write_image, out_dir / f"{stem}.exr", data,
                              channel_names=channels, dtype="half", attributes=attrs, tx=tx)
        raw_views = {v.name for v in registry.VIEW_LIST if v.raw}
        raw = all((region[2] or view) in raw_views for region in picture.regions)
        png_tag = "data" if raw else PNG_COLORSPACE[display]
        png_job = pool.submit(write_image, out_dir / f"{stem}.png", rgb, dtype="uint8",
                              attributes={"png:compressionLevel": 3,
                                          "oiio:ColorSpace": png_tag}, tx=tx)
        return [exr_job.result(), png_job.result()]


def write_frame(name: str, out_dir: Path, size, *, seed: int, frame: int | None,
                display: str, view: str, lookup=None, config=None, tx=None) -> list[Path]:
    """Render and write ``NAME[.####].exr`` and ``.png``; returns the paths."""
    picture, rgb = render_scene(name, size, seed=seed, frame=frame or 1, display=display,
                                view=view, lookup=lookup, config=config)
    return save_frame(name, picture, rgb, out_dir, seed=seed, frame=frame, display=display,
                      view=view, tx=tx)


# --------------------------------------------------------------------------- #
# The command
# --------------------------------------------------------------------------- #
def _parse_int(option, text, lo, hi) -> int:
    if not re.fullmatch(r"\s*\d+\s*", str(text)) or not lo <= int(text) <= hi:
        raise UsageError(f"{option} {text!r}: must be an integer in [{lo}, {hi}]")
    return int(text)


def run(args) -> int:
    if args.scene != "all" and args.scene not in scene_module.SCENES:
        raise UsageError(f"unknown scene {args.scene!r}: choose from {', '.join(SCENE_CHOICES)}")
    names = list(scene_module.SCENES) if args.scene == "all" else [args.scene]
    size = parse_size(args.size)
    frames = parse_frames(args.frames)
    _check_display_view(args.display, args.view)
    args.seed = _parse_int("--seed", args.seed, 0, 2**31 - 1)
    args.jobs = _parse_int("--jobs", args.jobs, 1, 64)
    out_dir = check_writable(args.out)
    # the config is read (baked first when the default one is missing) before any
    # frame: --jobs children then find it in place
    processors = ConfigProcessors(getattr(args, "config", None))
    processors.check_display_view(args.display, args.view)

    if frames is not None and len(frames) > 1:
        return _render_frames_in_children(args, frames)

    frame = None if frames is None else frames[0]
    # Every output is checked before anything is rendered, and all of them are
    # committed together at the end: a failure leaves every previous file as it was.
    for name in names:
        for path in frame_paths(name, out_dir, frame):
            check_output_file(path)
    lookup = make_lookup(processors)
    messages = []
    with transaction() as tx:
        for name in names:
            start = time.perf_counter()
            paths = write_frame(name, out_dir, size, seed=args.seed, frame=frame,
                                display=args.display, view=args.view, lookup=lookup,
                                config=processors, tx=tx)
            messages.append(f"{name}: wrote {', '.join(str(p) for p in paths)} "
                            f"({size[0]}x{size[1]}, {time.perf_counter() - start:.2f} s)")
    if not args.quiet:
        print("\n".join(messages))
    return 0


def _child_command(args, frame: int) -> list[str]:
    cmd = [sys.executable, "-m", "ocio_thinfilm", "render", args.scene,
           "--frames", f"{frame}-{frame}", "--size", str(args.size), "--out", str(args.out),
           "--seed", str(args.seed), "--display", args.display, "--view", args.view]
    if getattr(args, "config", None) is not None:
        cmd += ["--config", str(args.config)]
    return cmd + (["--quiet"] if args.quiet else [])


def _render_frames_in_children(args, frames) -> int:
    """One process per frame, ``--jobs`` at a time (what a render farm does)."""
    pending = list(frames)
    running: list[tuple[int, subprocess.Popen]] = []
    failed = None
    env = dict(os.environ)
    while pending or running:
        while pending and len(running) < args.jobs and failed is None:
            frame = pending.pop(0)
            running.append((frame, subprocess.Popen(
                _child_command(args, frame), stdout=None if not args.quiet else
                subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)))
        frame, proc = running.pop(0)
        try:
            _, err = proc.communicate()
        except BaseException:  # Ctrl-C / SIGTERM: stop every child, each cleans up
            for _, other in [(frame, proc)] + running:
                with contextlib.suppress(OSError):
                    other.terminate()
            for _, other in [(frame, proc)] + running:
                with contextlib.suppress(Exception):
                    other.wait(timeout=30)
            raise
        if proc.returncode != 0 and failed is None:
            lines = [line for line in (err or "").strip().splitlines() if line.strip()]
            last = lines[-1] if lines else f"exit code {proc.returncode}"
            failed = f"frame {frame}: {last.split('error: ', 1)[-1]}"
            pending.clear()
    if failed:
        raise UsageError(failed)
    return 0


def register(sub) -> None:
    p = sub.add_parser(
        "render",
        help="render the paper's example scenes (Figures 4-7) through the LUTs",
        description="Render the paper's example scenes through the generated tables and "
                    "OCIO views: a scene-linear EXR (CIE XYZ in R,G,B plus AOV channels) "
                    "and a display-encoded PNG per scene.")
    p.add_argument("scene", metavar="{" + ",".join(SCENE_CHOICES) + "}",
                   help="scene to render (spectrum = Fig. 4, oil = Fig. 5, soap = Fig. 6, "
                        "morpho = Fig. 7) or all of them")
    p.add_argument("--size", default=f"{DEFAULT_SIZE[0]}x{DEFAULT_SIZE[1]}",
                   help="W or WxH in pixels (default 512x512; sides 16-8192, at most 4096x4096 "
                        "pixels)")
    p.add_argument("--out", default="renders", help="output directory (default ./renders)")
    p.add_argument("--seed", default="0", help="noise seed, an integer >= 0 (default 0)")
    p.add_argument("--display", default=DEFAULT_DISPLAY,
                   help="display of the PNG: sRGB, Display P3 or Rec.2020 (default sRGB)")
    p.add_argument("--view", default=DEFAULT_VIEW,
                   help="view of the PNG (default 'Constant-Lightness Clip'; also 'Channel "
                        "Clamp', 'ACES Gamut Compression', 'Raw'); the spectrum scene always "
                        "shows the first three side by side")
    p.add_argument("--config", default=None,
                   help="OCIO config whose thin-film input spaces and display views the "
                        "render applies (default: the package's configs/thinfilm/"
                        "config.ocio, baked first when missing)")
    p.add_argument("--frames", default=None,
                   help="A-B: render frames A..B as NAME.####.exr/png with the scene's "
                        "animation, one process per frame")
    p.add_argument("--jobs", default="1",
                   help="frame processes to run at once with --frames (default 1)")
    p.add_argument("--quiet", action="store_true", help="print nothing on success")
    p.set_defaults(func=run)
