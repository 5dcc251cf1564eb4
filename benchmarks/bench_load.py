"""Benchmark: what a view costs a user's whole job, as whole processes, side by side
(the goals for building a processor and for a frame job): the Constant-Lightness Clip
view against the ACES Gamut Compression view of the same display, through ``oiiotool``
(OpenImageIO's, with the OCIO it is built against), one process per job.

- ``small``: a 16 x 16 EXR of CIE-XYZ-D65 -> the display/view -> PNG. Nearly all of it
  is start-up and building the processor (reading the view's LUT files): what a host
  pays whenever it builds a viewer's processor, a farm once per frame.
- ``frame``: the oil scene (Fig. 5, scene-linear XYZ) at 2048 x 2048 -> PNG.

Every job runs ``--repeats`` times in interleaved rounds (machine noise hits all
alike); the median counts. The view's LUT text (MB) is read from the config. Writes
``reports/bench_load.json`` and, with ``--update-docs``, the table in docs/gamut_map.md
between its markers (a test checks the table against the JSON).

Usage: python benchmarks/bench_load.py [--repeats 9] [--frame 2048] [--display sRGB]
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the benchmarks' helpers beside this script
from benchmarks import _reports  # noqa: E402  (after the path above)

CONFIG = ROOT / "configs" / "thinfilm" / "config.ocio"
JSON = ROOT / "reports" / "bench_load.json"
DOC = ROOT / "docs" / "gamut_map.md"
VIEWS = ("Constant-Lightness Clip", "ACES Gamut Compression", "Constant-Lightness Compress")
BEGIN, END = "<!-- bench_load:begin -->", "<!-- bench_load:end -->"
#: The goals: clip / ACES process time.
GOALS = {"small": 1.5, "frame": 1.05}


def _write_exr(path, pixels):
    import OpenImageIO as oiio

    h, w, _ = pixels.shape
    out = oiio.ImageOutput.create(str(path))
    out.open(str(path), oiio.ImageSpec(w, h, 3, oiio.FLOAT))
    ok = out.write_image(np.ascontiguousarray(pixels, dtype=np.float32))
    out.close()
    if not ok:
        raise OSError(f"cannot write {path}")


def _lut_megabytes(display, view):
    """MB of LUT text the view's processor reads (the clip's two CLFs in the config; the
    compression reads those and its own two)."""
    from ocio_thinfilm import registry

    entry = registry.as_display(display)
    stems = {
        "Constant-Lightness Clip": (entry.clip_lut_stem,),
        "Constant-Lightness Compress": (entry.clip_lut_stem, entry.compress_lut_stem),
    }.get(view, ())
    files = [
        CONFIG.parent / "luts" / f"{stem(white)}.clf" for stem in stems for white in (False, True)
    ]
    return sum(f.stat().st_size for f in files) / 1e6


def measure(repeats=9, frame=2048, display="sRGB"):
    from ocio_thinfilm.render import frames as render

    oiiotool = shutil.which("oiiotool")
    if oiiotool is None:
        raise SystemExit("oiiotool not found (PyPI openimageio ships it)")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        rng = np.random.default_rng(0)
        _write_exr(tmp / "small.exr", rng.uniform(0.0, 1.0, (16, 16, 3)))
        picture, _ = render.render_scene("oil", (frame, frame), view="Raw")
        _write_exr(tmp / "frame.exr", picture.xyz.reshape(frame, frame, 3))
        jobs = {
            (job, view): [
                oiiotool,
                "--colorconfig",
                str(CONFIG),
                str(tmp / f"{job}.exr"),
                "--iscolorspace",
                "CIE-XYZ-D65",
                "--ociodisplay",
                display,
                view,
                "-o",
                str(tmp / f"{job}.png"),
            ]
            for job in ("small", "frame")
            for view in VIEWS
        }
        times = {key: [] for key in jobs}
        for k in range(repeats):
            for key, argv in jobs.items():
                t0 = time.perf_counter()
                subprocess.run(argv, check=True, capture_output=True)
                times[key].append(time.perf_counter() - t0)
            print(f"round {k + 1}/{repeats}", flush=True)
    rows = []
    for job in ("small", "frame"):
        med = {v: statistics.median(times[job, v]) for v in VIEWS}
        rows.append(
            dict(
                job=job,
                pixels=16 * 16 if job == "small" else frame * frame,
                median_s=med,
                best_s={v: min(times[job, v]) for v in VIEWS},
                clip_over_aces=med[VIEWS[0]] / med[VIEWS[1]],
                compress_over_aces=med[VIEWS[2]] / med[VIEWS[1]],
                goal=GOALS[job],
            )
        )
    import OpenImageIO as oiio
    import PyOpenColorIO as ocio

    return dict(
        display=display,
        repeats=repeats,
        rows=rows,
        clip_lut_mb=_lut_megabytes(display, VIEWS[0]),
        compress_lut_mb=_lut_megabytes(display, VIEWS[2]),
        versions=dict(ocio=ocio.__version__, oiio=oiio.__version__),
    )


def markdown(result):
    out = [
        f"| job ({result['display']}, oiiotool, median of {result['repeats']}) | clip s | "
        "ACES s | clip / ACES | goal | compress s | compress / ACES |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in result["rows"]:
        name = (
            "16×16 EXR → PNG (start-up + processor)"
            if r["job"] == "small"
            else f"{int(r['pixels'] ** 0.5)}² oil scene → PNG"
        )
        ratio = r["clip_over_aces"]
        out.append(
            f"| {name} | {r['median_s']['Constant-Lightness Clip']:.3f} | "
            f"{r['median_s']['ACES Gamut Compression']:.3f} | {ratio:.2f}× | "
            f"≤ {r['goal']:g}× ({'met' if ratio <= r['goal'] else 'not met'}) | "
            f"{r['median_s']['Constant-Lightness Compress']:.3f} | "
            f"{r['compress_over_aces']:.2f}× |"
        )
    out.append(
        f"\nThe clip view reads {result['clip_lut_mb']:.1f} MB of LUT text, the "
        f"compression view {result['compress_lut_mb']:.1f} MB "
        f"(OCIO {result['versions']['ocio']}, OpenImageIO {result['versions']['oiio']})."
    )
    return "\n".join(out)


def update_doc(result, path=DOC, update=False):
    """docs/gamut_map.md's table from ``result``.

    Written only if ``update``; else says whether it would change.
    """
    _reports.update_section(path, BEGIN, END, markdown(result), update=update)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--repeats", type=int, default=9)
    p.add_argument("--frame", type=int, default=2048)
    p.add_argument("--display", default="sRGB")
    _reports.add_update_docs(p)
    args = p.parse_args(argv)
    result = measure(args.repeats, args.frame, args.display)
    print(markdown(result))
    _reports.write_json("load", result, path=JSON)
    update_doc(result, update=args.update_docs)


if __name__ == "__main__":
    main()
