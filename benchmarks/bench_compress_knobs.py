"""Benchmark: the baked Constant-Lightness Compress view with other knobs (threshold, limit).

The squeezes' LUT layout (``lut.compress_lut``: S_b's chart, S_w's graded nodes) was
chosen for the defaults 0.8 / 1.3. For a grid of knob pairs, each display's view chain
(:func:`ocio_thinfilm.lut.compress_lut.compress_lut` with those knobs, the shipped
edges, through OCIO's CPU processor) is measured against the analytic map
``colour.compress.compress_XYZ(XYZ, display, threshold, limit)`` with the figures the
defaults are held to (``tests/test_compress.py``):

- the clip's test sets (object, monochromatic, AP0, mixtures): dE2000 p99 / max and the
  largest |dY| (targets 0.5 / 1.5 / 1e-3);
- colours the map leaves alone: at most ``min(0.5, 0.625 threshold)`` of the way from
  their grey to the boundary (half-way at the defaults, the same share of the untouched
  region below), 40,000 per display (``evaluation.colours.half_way_colours``): the
  largest dE2000 they move (target 0.1) and how far beyond the input along the ray
  (targets 2.5e-4 of linear light, 2 % of the distance at >= 0.01);
- saturation ramps (towards monochromatic 450-650 nm at Y = 0.05, 0.2, 0.4, 64 steps to
  1.6 limits or the spectral colour): the largest gap between the view's and the
  analytic output distance below the limit (target 0.03) and the smallest step up to the
  limit (target > 0: strictly rising).

A pair meets the targets when every display does. The tested range
(``compress_lut.TESTED_THRESHOLD`` x ``TESTED_LIMIT``) is the rectangle of grid pairs
that all meet them; the figures of the pairs outside it are what
``compress_lut.MEASURED_KNOBS`` holds (the command line's warning quotes them).

Writes reports/bench_compress_knobs.json, reports/bench_compress_knobs.md and the knob
tables of docs/compress.md; prints the tables and the ``MEASURED_KNOBS`` dict.

Usage: python benchmarks/bench_compress_knobs.py [--pairs 0.6:1.5 0.9:1.2 ...]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/
from benchmarks import _reports  # noqa: E402  (after the path above)

DOC = ROOT / "docs" / "compress.md"
JSON = ROOT / "reports" / "bench_compress_knobs.json"
BEGIN, END = "<!-- compress-knobs:begin -->", "<!-- compress-knobs:end -->"
THRESHOLDS = (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 0.99)
LIMITS = (1.01, 1.05, 1.1, 1.2, 1.3, 1.5, 2.0, 3.0, 5.0)
#: Pairs shown one by one in docs/compress.md (the defaults first).
NAMED = ((0.8, 1.3), (0.6, 1.5), (0.9, 1.2), (0.7, 2.0), (0.5, 1.1), (0.95, 1.05))
SETS = ("object", "monochromatic", "ap0", "mixtures")
#: Targets beyond compress_lut.KNOB_TARGETS (tests/test_compress.py).
BEYOND, BEYOND_SHARE, RAMP_GAP = 2.5e-4, 0.02, 0.03


def inside_reach(threshold):
    """How far towards the boundary the colours left alone reach (half-way at 0.8)."""
    return min(0.5, 0.625 * threshold)


def ramps(display, limit, n=64):
    """Display-linear ramps (k, n, 3) from the grey towards monochromatic 450-650 nm at
    Y = 0.05, 0.2, 0.4, to 1.6 limits or the spectral colour, and their input distance."""
    from ocio_thinfilm.colour import colorimetry, compress

    wl = np.arange(450.0, 651.0, 25.0)
    out, dist = [], []
    for Y in (0.05, 0.2, 0.4):
        for target in colorimetry.XYZ_to_RGB(colorimetry.spectral_locus_XYZ(Y, wl), display):
            grey = np.full(3, Y)
            d_target = float(compress.boundary_distance(target, display))
            t = np.linspace(0.0, min(1.6 * limit / d_target, 1.0), n)
            out.append(grey + t[:, None] * (target - grey))
            dist.append(t * d_target)
    return np.array(out), np.array(dist)


def measure(display, threshold, limit, sets):
    """The figures of one display's view with the knobs (module docstring)."""
    from evaluation.colours import half_way_colours
    from ocio_thinfilm.colour import clip, colorimetry, compress
    from ocio_thinfilm.lut import clip_lut, compress_lut, ocio_ops

    soft = compress_lut.compress_lut(display, threshold=threshold, limit=limit)
    chain = ocio_ops.group(soft.transforms() + [clip_lut.working_decoding_transform()])
    to_xyz = np.linalg.inv(colorimetry.matrix_XYZ_to_RGB(display))

    def view(XYZ):
        return ocio_ops.apply(chain, XYZ).astype(np.float64)  # display-linear RGB

    row = {}
    for name in SETS:
        XYZ = sets[name]
        got = view(XYZ) @ to_xyz.T
        truth = compress.compress_XYZ(XYZ, display, threshold, limit)
        de = colorimetry.delta_E2000(truth, got)
        row[name] = dict(
            p99=float(np.percentile(de, 99)),
            max=float(de.max()),
            dY=float(np.abs(got[:, 1] - truth[:, 1]).max()),
        )
    rgb, Y, _ = half_way_colours(display, reach=inside_reach(threshold))
    XYZ = colorimetry.RGB_to_XYZ(rgb, display)
    got = view(XYZ)
    de = colorimetry.delta_E2000(XYZ, got @ to_xyz.T)
    v = rgb - Y[:, None]
    dist = np.linalg.norm(v, axis=1)
    beyond = ((got - Y[:, None]) * v).sum(axis=1) / dist - dist
    far = dist >= 0.01
    row["inside"] = dict(
        max=float(de.max()),
        beyond=float(beyond.max()),
        beyond_share=float((beyond[far] / dist[far]).max()),
    )
    rgb, dist = ramps(display, limit)
    flat = rgb.reshape(-1, 3)
    grey = flat @ clip.luminance_weights(display)
    out = compress._distance(view(colorimetry.RGB_to_XYZ(flat, display)).T, grey)
    analytic = compress._distance(compress.compress_RGB(flat, display, threshold, limit).T, grey)
    out, analytic = out.reshape(dist.shape), analytic.reshape(dist.shape)
    rising = (dist > 0.05) & (dist < limit - 0.02)
    steps = np.diff(out, axis=1)[rising[:, 1:] & rising[:, :-1]]
    row["ramps"] = dict(
        gap=float(np.abs(out - analytic)[dist < limit].max()), step=float(steps.min())
    )
    return row


def worst(displays):
    """The worst figures over the displays (and sets)."""
    rows = list(displays.values())
    return dict(
        p99=max(r[s]["p99"] for r in rows for s in SETS),
        max=max(r[s]["max"] for r in rows for s in SETS),
        dY=max(r[s]["dY"] for r in rows for s in SETS),
        inside=max(r["inside"]["max"] for r in rows),
        beyond=max(r["inside"]["beyond"] for r in rows),
        beyond_share=max(r["inside"]["beyond_share"] for r in rows),
        ramp_gap=max(r["ramps"]["gap"] for r in rows),
        ramp_step=min(r["ramps"]["step"] for r in rows),
    )


def failures(w):
    """The targets a pair's worst figures miss (an empty list: it meets them all)."""
    from ocio_thinfilm.lut.compress_lut import KNOB_TARGETS as T

    checks = [
        ("p99", w["p99"] <= T["p99"]),
        ("max", w["max"] <= T["max"]),
        ("|dY|", w["dY"] <= T["dY"]),
        ("colours left alone", w["inside"] <= T["inside"]),
        ("beyond the input", w["beyond"] <= BEYOND and w["beyond_share"] <= BEYOND_SHARE),
        ("ramps off the curve", w["ramp_gap"] < RAMP_GAP),
        ("ramps not strictly rising", w["ramp_step"] > 0.0),
    ]
    return [name for name, ok in checks if not ok]


def run(pairs, progress=print):
    from evaluation.colours import gamut_map_sets
    from ocio_thinfilm.colour import clip
    from ocio_thinfilm.lut import compress_lut

    sets = gamut_map_sets()
    rows = []
    for threshold, limit in pairs:
        start = time.perf_counter()
        displays = {d: measure(d, threshold, limit, sets) for d in clip.DISPLAYS}
        w = worst(displays)
        rows.append(
            dict(
                threshold=threshold,
                limit=limit,
                tested=compress_lut.knobs_tested(threshold, limit),
                fails=failures(w),
                worst=w,
                displays=displays,
            )
        )
        progress(
            f"{threshold:g} / {limit:g}: p99 {w['p99']:.2f} max {w['max']:.2f} "
            f"dY {w['dY']:.1e} inside {w['inside']:.3f} ramps {w['ramp_gap']:.3f} "
            f"{w['ramp_step']:+.4f} {', '.join(rows[-1]['fails']) or 'meets the targets'} "
            f"({time.perf_counter() - start:.1f} s)"
        )
    return dict(
        tested_threshold=list(compress_lut.TESTED_THRESHOLD),
        tested_limit=list(compress_lut.TESTED_LIMIT),
        rows=rows,
    )


def measured_knobs(result):
    """``compress_lut.MEASURED_KNOBS`` from the result: the pairs outside the tested
    range, rounded as the warning prints them, and the targets each misses."""
    return {
        (r["threshold"], r["limit"]): (
            round(r["worst"]["p99"], 2),
            round(r["worst"]["max"], 2),
            float(f"{r['worst']['dY']:.1e}"),
            round(r["worst"]["inside"], 3),
            ", ".join(r["fails"]),
        )
        for r in result["rows"]
        if not r["tested"]
    }


def _row(result, threshold, limit):
    for r in result["rows"]:
        if (r["threshold"], r["limit"]) == (threshold, limit):
            return r
    return None


def knobs_markdown(result):
    """docs/compress.md's knob tables: the named pairs, then the grid."""
    (t_lo, t_hi), (l_lo, l_hi) = result["tested_threshold"], result["tested_limit"]
    out = [
        "| threshold / limit | tested range | object | monochromatic | AP0 | mixtures | "
        "left alone: dE max | ramps: gap, smallest step | misses |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for t, lim in NAMED:
        r = _row(result, t, lim)
        if r is None:
            continue
        cells = []
        for s in SETS:
            d = {
                k: max(r["displays"][x][s][k] for x in r["displays"]) for k in ("p99", "max", "dY")
            }
            cells.append(f"{d['p99']:.2f} / {d['max']:.2f}, {d['dY']:.1e}")
        w = r["worst"]
        out.append(
            f"| {t:g} / {lim:g} | {'yes' if r['tested'] else 'no'} | "
            + " | ".join(cells)
            + f" | {w['inside']:.3f} | {w['ramp_gap']:.3f}, {w['ramp_step']:+.4f} | "
            + (", ".join(r["fails"]) or "-")
            + " |"
        )
    limits = sorted({r["limit"] for r in result["rows"]})
    thresholds = sorted({r["threshold"] for r in result["rows"]})
    out += [
        "",
        f"Every measured pair, worst dE2000 p99 / max over the displays and sets; **bold**: "
        f"inside the tested range (threshold {t_lo:g}-{t_hi:g}, limit {l_lo:g}-{l_hi:g}); "
        "✗ misses a target (which: reports/bench_compress_knobs.md):",
        "",
        "| threshold \\ limit | " + " | ".join(f"{v:g}" for v in limits) + " |",
        "|---" * (len(limits) + 1) + "|",
    ]
    for t in thresholds:
        cells = []
        for lim in limits:
            r = _row(result, t, lim)
            if r is None:
                cells.append("")
                continue
            text = f"{r['worst']['p99']:.2f} / {r['worst']['max']:.2f}"
            text += " ✗" if r["fails"] else ""
            cells.append(f"**{text}**" if r["tested"] else text)
        out.append(f"| {t:g} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def report_markdown(result):
    lines = [
        "# bench_compress_knobs",
        "",
        "Worst over sRGB, Display P3 and Rec.2020 (module docstring of "
        "benchmarks/bench_compress_knobs.py).",
        "",
        "| threshold | limit | tested | p99 | max | abs(dY) | left alone dE max | beyond | "
        "beyond share | ramp gap | ramp step | misses |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in result["rows"]:
        w = r["worst"]
        lines.append(
            f"| {r['threshold']:g} | {r['limit']:g} | {'yes' if r['tested'] else 'no'} | "
            f"{w['p99']:.2f} | {w['max']:.2f} | {w['dY']:.1e} | {w['inside']:.3f} | "
            f"{w['beyond']:.1e} | {w['beyond_share']:.1%} | {w['ramp_gap']:.3f} | "
            f"{w['ramp_step']:+.4f} | {', '.join(r['fails']) or '-'} |"
        )
    return "\n".join(lines) + "\n"


def update_doc(result, path=DOC, update=False):
    """docs/compress.md's knob tables from ``result``.

    Written only if ``update``; else says whether it would change.
    """
    _reports.update_section(path, BEGIN, END, knobs_markdown(result), update=update)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--pairs",
        nargs="+",
        default=None,
        metavar="T:L",
        help="knob pairs to measure (default: the grid of THRESHOLDS x LIMITS); with "
        "--pairs nothing is written",
    )
    _reports.add_update_docs(parser)
    args = parser.parse_args(argv)
    pairs = (
        [tuple(float(v) for v in p.split(":")) for p in args.pairs]
        if args.pairs
        else [(t, lim) for t in THRESHOLDS for lim in LIMITS]
    )
    result = run(pairs)
    print()
    print(knobs_markdown(result))
    print()
    print("MEASURED_KNOBS = " + repr(measured_knobs(result)))
    inside_fail = [
        (r["threshold"], r["limit"], r["fails"])
        for r in result["rows"]
        if r["tested"] and r["fails"]
    ]
    if inside_fail:
        print(f"pairs inside the tested range that miss a target: {inside_fail}")
    if args.pairs:
        return
    _reports.write_json("compress_knobs", result, path=JSON)
    (ROOT / "reports" / "bench_compress_knobs.md").write_text(report_markdown(result))
    print("wrote reports/bench_compress_knobs.md")
    update_doc(result, update=args.update_docs)


if __name__ == "__main__":
    main()
