"""Benchmark: the soft constant-lightness compression -- its defaults, its LUTs' size
against accuracy, and what it does to saturation ramps, beside the clip.

1. Defaults. For (threshold, limit) candidates and each display: the share of the
   display's gamut left untouched (uniform display-linear RGB in the unit cube, and
   object colours inside the gamut), and where the spectral locus (380-700 nm at
   Y = 0.02, 0.1, 0.3, 0.6) and random AP0 colours (0 <= Y <= 1) land: the share
   compressed with shading kept (threshold < d < limit) and the share clipped (d >=
   limit).
2. Size against accuracy. The view's chain (``lut.compress_lut.CompressLUT``) for edge
   pairs of its two squeezes, through OCIO's CPU processor, against the analytic map
   (``colour.compress.compress_XYZ``) on the clip's test sets: dE2000 p99 / max and
   |dY|; MB of the two squeezes' CLF text per display.
3. Ramps. Saturation ramps at fixed Y and hue from the grey to 2.1 boundary distances
   or the spectral colour, whichever is nearer (towards monochromatic 450-650 nm at
   Y = 0.2): output boundary distance against
   input distance through the compress view, the clip view and OCIO's ACES 1.3 gamut
   compression view (its output measured along the same ray), and whether each rises
   strictly up to the limit. Plot: docs/compress_ramps.png (distances, and the ramps
   as colour strips).

Writes reports/bench_compress.json, reports/bench_compress.md and docs/compress.md's
accuracy table (the shipped edges).

Usage: python benchmarks/bench_compress.py [--pairs 41:41 49:41 49:49 57:49]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/
from benchmarks import _reports  # noqa: E402  (after the path above)

DEFAULT_PAIRS = ("33:33", "41:41", "49:41", "49:49", "57:49")
DOC = ROOT / "docs" / "compress.md"
BEGIN, END = "<!-- compress-accuracy:begin -->", "<!-- compress-accuracy:end -->"
CANDIDATES = ((0.75, 1.2), (0.8, 1.2), (0.8, 1.3), (0.85, 1.3), (0.8, 1.5))


def _sets():
    from evaluation.colours import gamut_map_sets

    return gamut_map_sets()


def defaults_table(sets):
    """Per (threshold, limit) and display: shares untouched / compressed / clipped."""
    from ocio_thinfilm.colour import clip, colorimetry
    from ocio_thinfilm.colour.compress import boundary_distance, compress_RGB

    rows = []
    rng = np.random.default_rng(0)
    cube = rng.uniform(0.0, 1.0, (200000, 3))
    for display in clip.DISPLAYS:
        d_cube = boundary_distance(cube, display)
        rgb = {
            name: colorimetry.XYZ_to_RGB(sets[name], display)
            for name in ("object", "monochromatic", "ap0")
        }
        d = {name: boundary_distance(v, display) for name, v in rgb.items()}
        inside_objects = d["object"][d["object"] <= 1.0]
        in_rgb = rgb["object"][d["object"] <= 1.0]
        for thr, lim in CANDIDATES:
            moved = colorimetry.delta_E2000(
                colorimetry.RGB_to_XYZ(compress_RGB(in_rgb, display, thr, lim), display),
                colorimetry.RGB_to_XYZ(in_rgb, display),
            )
            row = dict(
                display=display,
                threshold=thr,
                limit=lim,
                cube_untouched=float(np.nanmean(d_cube <= thr)),
                objects_untouched=float(np.mean(inside_objects <= thr)),
                objects_moved_p99=float(np.percentile(moved, 99)),
                objects_moved_max=float(moved.max()),
            )
            for name in ("monochromatic", "ap0"):
                v = d[name][np.isfinite(d[name])]
                row[f"{name}_shaded"] = float(np.mean((v > 1.0) & (v < lim)))
                row[f"{name}_clipped"] = float(np.mean(v >= lim))
            rows.append(row)
    return rows


def _chain(soft):
    from ocio_thinfilm.lut import clip_lut, ocio_ops

    return ocio_ops.group(soft.transforms() + [clip_lut.working_decoding_transform()])


def _clf_bytes(soft, directory):
    import PyOpenColorIO as ocio

    from ocio_thinfilm.export.files import CLF_WRITER

    total = 0
    for kind, core in (("black", soft.black_core()), ("white", soft.white_core())):
        path = Path(directory) / f"{kind}.clf"
        core.write(CLF_WRITER, str(path), ocio.Config.CreateRaw())
        total += path.stat().st_size
    return total


def accuracy_table(sets, pairs, progress):
    from ocio_thinfilm.colour import clip, colorimetry, compress
    from ocio_thinfilm.lut import compress_lut, ocio_ops

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for display in clip.DISPLAYS:
            M = colorimetry.matrix_XYZ_to_RGB(display)
            for pair in pairs:
                black, white = (int(v) for v in pair.split(":"))
                soft = compress_lut.compress_lut(display, black, white)
                chain = _chain(soft)
                row = dict(
                    display=display, black=black, white=white, mb=_clf_bytes(soft, tmp) / 1e6
                )
                for name, XYZ in sets.items():
                    rgb = ocio_ops.apply(chain, XYZ).astype(np.float64)
                    truth = compress.compress_XYZ(XYZ, display)
                    de = colorimetry.delta_E2000(truth, rgb @ np.linalg.inv(M).T)
                    row[name] = dict(
                        p99=float(np.percentile(de, 99)),
                        max=float(de.max()),
                        dY=float(np.abs((rgb @ np.linalg.inv(M).T)[:, 1] - truth[:, 1]).max()),
                    )
                rows.append(row)
                progress(f"accuracy {display} {pair}: {row['mb']:.2f} MB")
    return rows


def _markdown(defaults, accuracy, ramp):
    lines = [
        "# bench_compress",
        "",
        "## Defaults: shares of each set per (threshold, limit)",
        "",
        "| display | threshold | limit | gamut cube untouched | in-gamut object colours "
        "untouched | their dE2000 moved p99 / max | monochromatic shaded / clipped | "
        "AP0 shaded / clipped |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in defaults:
        lines.append(
            f"| {r['display']} | {r['threshold']} | {r['limit']} | "
            f"{r['cube_untouched']:.1%} | {r['objects_untouched']:.1%} | "
            f"{r['objects_moved_p99']:.2f} / {r['objects_moved_max']:.2f} | "
            f"{r['monochromatic_shaded']:.0%} / {r['monochromatic_clipped']:.0%} | "
            f"{r['ap0_shaded']:.0%} / {r['ap0_clipped']:.0%} |"
        )
    lines += [
        "",
        "## The view's LUTs: size against accuracy (dE2000 p99 / max, |dY| max)",
        "",
        "| display | S_b | S_w | MB | object | monochromatic | AP0 | mixtures |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in accuracy:
        cells = [
            f"{r[s]['p99']:.2f} / {r[s]['max']:.2f}, {r[s]['dY']:.1e}"
            for s in ("object", "monochromatic", "ap0", "mixtures")
        ]
        lines.append(
            f"| {r['display']} | {r['black']} | {r['white']} | {r['mb']:.2f} | "
            + " | ".join(cells)
            + " |"
        )
    lines += [
        "",
        f"## Ramps ({ramp['display']}, Y = 0.2, 450-650 nm)",
        "",
        "| view | strictly rising to the limit | smallest step | spread of output "
        "past the boundary | max abs(dY) |",
        "|---|---|---|---|---|",
    ]
    for view in (
        "Constant-Lightness Compress",
        "Constant-Lightness Clip",
        "ACES Gamut Compression",
    ):
        v = ramp[view]
        lines.append(
            f"| {view} | {v['strictly_rising']} | {v['min_step']:.4f} | "
            f"{v['spread_past_boundary']:.3f} | {v['dY']:.1e} |"
        )
    return "\n".join(lines) + "\n"


def shipped_markdown(result):
    """docs/compress.md's accuracy table: the rows of the shipped edges."""
    from ocio_thinfilm.lut import compress_lut

    out = ["| display | object | monochromatic | AP0 | mixtures |", "|---|---|---|---|---|"]
    for r in result["accuracy"]:
        if (r["black"], r["white"]) != (compress_lut.SOFT_SIZE, compress_lut.SOFT_WHITE_SIZE):
            continue
        out.append(
            f"| {r['display']} | "
            + " | ".join(
                f"{r[s]['p99']:.2f} / {r[s]['max']:.2f}, {r[s]['dY']:.1e}"
                for s in ("object", "monochromatic", "ap0", "mixtures")
            )
            + " |"
        )
    return "\n".join(out)


def update_doc(result, path=DOC, update=False):
    """docs/compress.md's accuracy table from ``result``.

    Written only if ``update``; else says whether it would change.
    """
    _reports.update_section(path, BEGIN, END, shipped_markdown(result), update=update)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--pairs",
        nargs="+",
        default=list(DEFAULT_PAIRS),
        help="edge pairs S_b:S_w of the squeezes' Lut3Ds",
    )
    parser.add_argument(
        "--plot",
        default=None,
        help="where to draw the ramps (default: docs/compress_ramps.png with --update-docs, "
        "else not drawn)",
    )
    _reports.add_update_docs(parser)
    args = parser.parse_args(argv)
    if args.plot is None and args.update_docs:
        args.plot = str(ROOT / "docs" / "compress_ramps.png")

    def progress(text):
        print(text, flush=True)

    sets = _sets()
    defaults = defaults_table(sets)
    progress("defaults measured")
    accuracy = accuracy_table(sets, args.pairs, progress)
    import matplotlib

    matplotlib.use("Agg")
    from evaluation.report import ramps

    ramp, rgb_out = ramps.ramp_table()
    if args.plot:
        ramps.plot(ramp, rgb_out).savefig(args.plot, dpi=110)
        print(f"drew {args.plot}")
    else:
        print("docs/compress_ramps.png not redrawn (--update-docs or --plot PATH draws it)")
    report = dict(
        defaults=defaults,
        accuracy=accuracy,
        ramps={
            k: (
                v if not isinstance(v, dict) else {kk: vv for kk, vv in v.items() if kk != "output"}
            )
            for k, v in ramp.items()
            if k != "input"
        },
    )
    _reports.write_json("compress", report)
    text = _markdown(defaults, accuracy, ramp)
    (ROOT / "reports" / "bench_compress.md").write_text(text)
    print(text)
    print("wrote reports/bench_compress.md")
    update_doc(report, update=args.update_docs)


if __name__ == "__main__":
    main()
