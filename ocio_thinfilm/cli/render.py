"""``ocio-thinfilm render``: the paper's scenes, each frame through the config's processors.

Without ``--frames`` a scene is written as ``NAME.exr`` / ``NAME.png`` (frame 1, the
still). ``--frames A-B`` writes ``NAME.####.exr`` / ``.png``; a range of more than one
frame is rendered by one child process per frame (``python -m ocio_thinfilm render
SCENE --frames N-N ...``), ``--jobs`` at a time, exactly what a render farm would run.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import re
import subprocess
import sys
import time
from collections.abc import Callable

from ocio_thinfilm import registry
from ocio_thinfilm.checks import UsageError
from ocio_thinfilm.io import check_output_file, check_writable, transaction
from ocio_thinfilm.render import frames as render
from ocio_thinfilm.render import scenes as scene_module
from ocio_thinfilm.render.processors import ConfigProcessors, make_lookup

__all__ = ["register", "run", "size_argument", "frames_argument", "integer_argument"]

MIN_SIDE, MAX_SIDE, MAX_PIXELS = 16, 8192, 4096 * 4096
#: Limits on --size: each side 16..8192 and at most 4096 x 4096 pixels in total; on --frames.
MAX_FRAME = 9999
SCENE_CHOICES = tuple(scene_module.SCENES) + ("all",)


def size_argument(text: str) -> tuple[int, int]:
    """Parse ``--size``: ``W`` or ``WxH`` -> (W, H).

    Parameters
    ----------
    text : str
        ``W`` or ``WxH`` in pixels (spaces allowed), each side in [16, 8192] and
        W * H <= 4096^2.

    Returns
    -------
    tuple of int
        (W, H); ``W`` alone is a square.

    Raises
    ------
    argparse.ArgumentTypeError
        For anything else.

    Examples
    --------
    >>> size_argument("640x480"), size_argument("512")
    ((640, 480), (512, 512))
    """
    m = re.fullmatch(r"\s*([+-]?\d+)\s*(?:[xX]\s*([+-]?\d+)\s*)?", str(text))
    if not m:
        raise argparse.ArgumentTypeError(
            f"{text!r}: expected W or WxH in pixels, e.g. 512 or 640x480"
        )
    w = int(m.group(1))
    h = int(m.group(2)) if m.group(2) is not None else w
    for side in (w, h):
        if side < MIN_SIDE or side > MAX_SIDE:
            raise argparse.ArgumentTypeError(
                f"{text}: each side must be between {MIN_SIDE} and {MAX_SIDE} pixels"
            )
    if w * h > MAX_PIXELS:
        raise argparse.ArgumentTypeError(
            f"{text}: at most {MAX_PIXELS} pixels (4096x4096) per image"
        )
    return w, h


def frames_argument(text: str) -> list[int]:
    """Parse ``--frames``: ``A-B`` (or ``N``) -> [A, ..., B].

    Parameters
    ----------
    text : str
        ``A-B`` or ``N``, with 1 <= A <= B <= 9999.

    Returns
    -------
    list of int
        The frames, in order.

    Raises
    ------
    argparse.ArgumentTypeError
        For anything else.

    Examples
    --------
    >>> frames_argument("3-5"), frames_argument("12")
    ([3, 4, 5], [12])
    """
    m = re.fullmatch(r"\s*(\d+)\s*(?:-\s*(\d+)\s*)?", str(text))
    if not m:
        raise argparse.ArgumentTypeError(f"{text!r}: expected A-B (e.g. 1-24) or a single frame N")
    a = int(m.group(1))
    b = int(m.group(2)) if m.group(2) is not None else a
    if not 1 <= a <= b <= MAX_FRAME:
        raise argparse.ArgumentTypeError(f"{text}: need 1 <= A <= B <= {MAX_FRAME}")
    return list(range(a, b + 1))


def integer_argument(lo: int, hi: int) -> Callable[[str], int]:
    """Return an argparse type that parses an integer in [lo, hi].

    Parameters
    ----------
    lo, hi : int
        The bounds, inclusive.

    Returns
    -------
    callable
        ``parse(text) -> int``; it raises :class:`argparse.ArgumentTypeError` for
        anything but digits (spaces around them allowed) of a value in [lo, hi].

    Examples
    --------
    >>> integer_argument(1, 64)(" 8 ")
    8
    """

    def parse(text: str) -> int:
        if not re.fullmatch(r"\s*\d+\s*", str(text)) or not lo <= int(text) <= hi:
            raise argparse.ArgumentTypeError(f"{text!r}: must be an integer in [{lo}, {hi}]")
        return int(text)

    return parse


def run(args: argparse.Namespace) -> int:
    """Run ``ocio-thinfilm render``: every frame of the chosen scenes through the config.

    The outputs are checked first and committed together; a range of more than one
    frame runs one child process per frame, ``--jobs`` at a time.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options: ``scene`` (or ``"all"``), ``size``, ``frames``, ``out``,
        ``seed``, ``display``, ``view``, ``config``, ``jobs`` and ``quiet``.

    Returns
    -------
    int
        The exit code, 0.

    Raises
    ------
    ParameterError
        Naming ``config``, ``display``, ``view`` or ``out``, for a config, display,
        view or output that cannot be used.
    UsageError
        If a frame's child process failed (its last error line).
    ValueError
        If the output directory cannot be created or written.
    OSError
        If a file cannot be written.
    """
    names = list(scene_module.SCENES) if args.scene == "all" else [args.scene]
    size, frames = args.size, args.frames
    out_dir = check_writable(args.out)
    # the config is read (baked first when the default one is missing) before any
    # frame: --jobs children then find it in place
    film, film_transforms = _user_film(args, names)
    processors = ConfigProcessors(getattr(args, "config", None), films=film_transforms)
    processors.check_display_view(args.display, args.view)

    if frames is not None and len(frames) > 1:
        return _render_frames_in_children(args, frames)

    frame = None if frames is None else frames[0]
    # Every output is checked before anything is rendered, and all of them are
    # committed together at the end: a failure leaves every previous file as it was.
    for name in names:
        for path in render.frame_paths(name, out_dir, frame):
            check_output_file(path, in_new_folder=True)
    lookup = make_lookup(processors)
    messages = []
    with transaction() as tx:
        for name in names:
            start = time.perf_counter()
            paths = render.write_frame(
                name,
                out_dir,
                size,
                seed=args.seed,
                frame=frame,
                display=args.display,
                view=args.view,
                lookup=lookup,
                config=processors,
                tx=tx,
                film=film,
            )
            messages.append(
                f"{name}: wrote {', '.join(str(p) for p in paths)} "
                f"({size[0]}x{size[1]}, {time.perf_counter() - start:.2f} s)"
            )
    if not args.quiet:
        print("\n".join(messages))
    return 0


def _user_film(args, names):
    """Return the table of the user's film of ``--films``/``--film`` for the oil or soap scene.

    The result is (the TableSpec of ``--films``/``--film``, {colour space: transform}), the
    film's table as ``bake --films`` writes it, or (None, {}) without ``--films``.
    """
    films_file, key = getattr(args, "films", None), getattr(args, "film", None)
    if films_file is None:
        if key is not None:
            raise UsageError("--film KEY goes with --films FILE")
        return None, {}
    if any(name not in ("oil", "soap") for name in names):
        raise UsageError("--films applies to the oil and soap scenes")
    from ocio_thinfilm.export.film_files import pick_film
    from ocio_thinfilm.lut import film_tables

    chosen = pick_film(films_file, key)
    table = film_tables.user_film_table(chosen)
    spec = scene_module.TableSpec("user", chosen.range_um, table.size, chosen.name)
    return spec, {chosen.name: table.transform()}


def _child_command(args, frame: int) -> list[str]:
    cmd = [
        sys.executable,
        "-m",
        "ocio_thinfilm",
        "render",
        args.scene,
        "--frames",
        f"{frame}-{frame}",
        "--size",
        "x".join(map(str, args.size)),
        "--out",
        str(args.out),
        "--seed",
        str(args.seed),
        "--display",
        args.display,
        "--view",
        args.view,
    ]
    if getattr(args, "config", None) is not None:
        cmd += ["--config", str(args.config)]
    if getattr(args, "films", None) is not None:
        cmd += ["--films", str(args.films)]
        if args.film is not None:
            cmd += ["--film", args.film]
    return cmd + (["--quiet"] if args.quiet else [])


def _render_frames_in_children(args, frames) -> int:
    """Render one process per frame, ``--jobs`` at a time (what a render farm does)."""
    pending = list(frames)
    running: list[tuple[int, subprocess.Popen]] = []
    failed = None
    env = dict(os.environ)
    while pending or running:
        while pending and len(running) < args.jobs and failed is None:
            frame = pending.pop(0)
            running.append(
                (
                    frame,
                    subprocess.Popen(
                        _child_command(args, frame),
                        stdout=None if not args.quiet else subprocess.DEVNULL,
                        stderr=subprocess.PIPE,
                        text=True,
                        env=env,
                    ),
                )
            )
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


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add the ``render`` command to the ``sub`` parsers.

    Parameters
    ----------
    sub : argparse._SubParsersAction
        The sub-parsers of the ``ocio-thinfilm`` parser.
    """
    p = sub.add_parser(
        "render",
        help="render the paper's example scenes (Figures 4-7) through the LUTs",
        description="Render the paper's example scenes through the generated tables and "
        "OCIO views: a scene-linear EXR (CIE XYZ in R,G,B plus AOV channels) "
        "and a display-encoded PNG per scene.",
    )
    p.add_argument(
        "scene",
        choices=SCENE_CHOICES,
        metavar="SCENE",
        help="scene to render (spectrum = Fig. 4, oil = Fig. 5, soap = Fig. 6, "
        "morpho = Fig. 7) or all of them",
    )
    p.add_argument(
        "--size",
        type=size_argument,
        default=render.DEFAULT_SIZE,
        help="W or WxH in pixels (default 512x512; sides 16-8192, at most 4096x4096 pixels)",
    )
    p.add_argument("--out", default="renders", help="output directory (default ./renders)")
    p.add_argument(
        "--seed",
        type=integer_argument(0, 2**31 - 1),
        default=0,
        help="noise seed, an integer >= 0 (default 0)",
    )
    p.add_argument(
        "--display",
        default=render.DEFAULT_DISPLAY,
        help=f"display of the PNG, one of the config's (the package's: "
        f"{', '.join(registry.DISPLAYS)}; default {render.DEFAULT_DISPLAY})",
    )
    p.add_argument(
        "--view",
        default=render.DEFAULT_VIEW,
        help=f"view of the PNG, one of the display's (the package's: "
        f"{', '.join(registry.VIEWS)}; default {render.DEFAULT_VIEW}); the "
        "spectrum scene shows the first four side by side",
    )
    p.add_argument(
        "--config",
        default=None,
        help="OCIO config whose thin-film input spaces and display views the "
        "render applies: the package's (default: a checkout's configs/"
        "thinfilm/config.ocio, baked first when missing; installed, the "
        "wheel's copy) or one made by bake --into",
    )
    p.add_argument(
        "--frames",
        type=frames_argument,
        default=None,
        help="A-B: render frames A..B as NAME.####.exr/png with the scene's "
        "animation, one process per frame",
    )
    p.add_argument(
        "--jobs",
        type=integer_argument(1, 64),
        default=1,
        help="frame processes to run at once with --frames (default 1)",
    )
    p.add_argument(
        "--films",
        default=None,
        metavar="FILE",
        help="oil, soap: render with a film of this film file (TOML, see docs/films.md) "
        "instead of the paper's: its physical reflectance at its own angle, against the "
        "scene's physical thickness (its colour space from --config if baked there with "
        "--films, else its table computed as bake --films writes it)",
    )
    p.add_argument("--film", default=None, metavar="KEY", help="the film of --films")
    p.add_argument("--quiet", action="store_true", help="print nothing on success")
    p.set_defaults(func=run)
