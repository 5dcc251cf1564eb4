"""Benchmark: throughput of the Constant-Lightness Clip view against the ACES gamut
compression view and a single 65^3 Lut3D, side by side in one run.

Every processor is OCIO's CPU processor at OPTIMIZATION_DEFAULT, one thread,
``applyRGB`` on a float32 RGB image; each is timed REPEATS times in interleaved
rounds (so machine noise hits all of them alike) and the best round counts.

Processors (CIE-XYZ-D65 -> sRGB display code values):

- ``clip``: the baked config's ``sRGB / Constant-Lightness Clip`` view;
- ``aces``: the baked config's ``sRGB / ACES Gamut Compression`` view (it limits
  components to +-1e6 first, so that no input overflows to NaN);
- ``aces bare``: the same view without that guard (matrix, ACES_GamutComp13, clamp,
  sRGB encoding) -- the target is checked against the faster of the two;
- ``lut65``: a single 65^3 tetrahedral Lut3D, nothing else (the practical ceiling);
- ``one-LUT chain``: what the cheapest single-LUT design would cost -- the clip's input
  limit, a matrix, ``XYZ_TO_xyY``, one 65^3 Lut3D and the sRGB encoding (its values are
  a stand-in: only its speed is measured).

Data sets (1024 x 1024 pixels each): uniform XYZ in [0, 1]^3; the rendered oil scene
(Fig. 5, scene-linear XYZ); object colours + monochromatic stimuli (the test sets,
tiled); random XYZ inside ACES AP0 with 0 <= Y <= 1. Prints a table and writes
``reports/bench_gamut_map.json``.

Also measures the views' accuracy against the analytic clip (the accuracy sets: object
and interference colours, monochromatic stimuli 380-700 nm at Y 0.02/0.1/0.3/0.6,
random XYZ inside ACES AP0 with 0 <= Y <= 1; dE2000 p99 / max, |dY|, in-gamut
colours' max) for every display, into the same JSON.

Usage: python benchmarks/bench_gamut_map.py [--size 1024] [--repeats 7] [--no-speed]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/
from benchmarks import _reports  # noqa: E402  (after the path above)

CONFIG = ROOT / "configs" / "thinfilm" / "config.ocio"


def datasets(n):
    from evaluation.colours import object_colours, spectral_colours
    from ocio_thinfilm.colour import colorimetry
    from ocio_thinfilm.render import frames as render

    side = int(np.sqrt(n))
    rng = np.random.default_rng(0)
    uniform = rng.uniform(0.0, 1.0, (n, 3))
    picture, _ = render.render_scene("oil", (side, side), view="Raw")
    oil = picture.xyz.reshape(-1, 3)
    colours = np.concatenate([object_colours(), spectral_colours(0.6)])
    colours = np.resize(colours, (n, 3))
    ap0 = (
        rng.uniform(0.0, 1.0, (2 * n, 3))
        @ np.linalg.inv(colorimetry.matrix_XYZ_to_RGB("ACES2065-1")).T
    )
    ap0 = ap0[(ap0[:, 1] >= 0.0) & (ap0[:, 1] <= 1.0)][:n]
    return {
        "uniform XYZ": uniform,
        "oil scene": oil,
        "object + spectral": colours,
        "random AP0": np.resize(ap0, (n, 3)),
    }


def processors():
    import PyOpenColorIO as ocio

    from ocio_thinfilm.colour import clip
    from ocio_thinfilm.lut import clip_lut, display_transforms, ocio_ops

    cfg = ocio.Config.CreateFromFile(str(CONFIG))

    def view(v):
        return cfg.getProcessor("CIE-XYZ-D65", "sRGB", v, ocio.TRANSFORM_DIR_FORWARD)

    bare = ocio_ops.group(
        [
            display_transforms.display_matrix_transform("sRGB"),
            display_transforms.aces_gamut_compression_transform(),
            ocio_ops.range_(0.0, 1.0),
            display_transforms.display_encoding_transform("sRGB"),
        ]
    )
    g = np.linspace(0.0, 1.0, 65)
    values = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1) ** 0.9
    lut = ocio_ops.lut3d_transform(values)
    one_lut = ocio_ops.group(
        [
            clip_lut.xyz_limit_transform(),
            ocio_ops.matrix(np.eye(3)),
            clip_lut.xyY_forward_transform(),
            ocio_ops.lut3d_transform(values),
            display_transforms.display_encoding_transform("sRGB"),
        ]
    )
    raw = ocio.Config.CreateRaw()
    procs = {
        "clip": view("Constant-Lightness Clip"),
        "aces": view("ACES Gamut Compression"),
        "aces bare": raw.getProcessor(bare),
        "lut65": raw.getProcessor(lut),
        "one-LUT chain": raw.getProcessor(one_lut),
    }
    del clip
    return {
        k: p.getOptimizedCPUProcessor(
            ocio.BIT_DEPTH_F32, ocio.BIT_DEPTH_F32, ocio.OPTIMIZATION_DEFAULT
        )
        for k, p in procs.items()
    }


def measure(size=1024, repeats=7):
    data = {k: np.ascontiguousarray(v, dtype=np.float32) for k, v in datasets(size * size).items()}
    procs = processors()
    best = {(d, p): np.inf for d in data for p in procs}
    for _ in range(repeats):
        for d, pixels in data.items():
            for p, cpu in procs.items():
                work = pixels.copy()
                t0 = time.perf_counter()
                cpu.applyRGB(work)
                best[d, p] = min(best[d, p], time.perf_counter() - t0)
    rows = []
    for d, pixels in data.items():
        mpx = {p: len(pixels) / best[d, p] / 1e6 for p in procs}
        aces = max(mpx["aces"], mpx["aces bare"])
        rows.append(
            dict(
                dataset=d,
                pixels=len(pixels),
                mpix_per_s=mpx,
                clip_over_aces=mpx["clip"] / mpx["aces"],
                clip_over_aces_bare=mpx["clip"] / mpx["aces bare"],
                clip_over_fastest_aces=mpx["clip"] / aces,
                clip_over_lut65=mpx["clip"] / mpx["lut65"],
                one_lut_chain_over_aces=mpx["one-LUT chain"] / mpx["aces"],
            )
        )
    return rows


def accuracy():
    """{display: {set: statistics}} of the baked config's Constant-Lightness Clip views."""
    import PyOpenColorIO as ocio

    from evaluation.colours import gamut_map_sets as _sets
    from evaluation.views import apply_view as _apply_view
    from evaluation.views import decode_display as _decode
    from ocio_thinfilm.colour import clip, colorimetry

    cfg = ocio.Config.CreateFromFile(str(CONFIG))
    out = {}
    for display in clip.DISPLAYS:
        M = colorimetry.matrix_XYZ_to_RGB(display)
        out[display] = {}
        for name, XYZ in _sets().items():
            rgb = _decode(_apply_view(cfg, display, XYZ), display)
            truth = clip.clip_XYZ(XYZ, display)
            got = colorimetry.RGB_to_XYZ(rgb, display)
            de = colorimetry.delta_E2000(truth, got)
            inside = clip.in_gamut(XYZ @ M.T)
            out[display][name] = dict(
                n=len(XYZ),
                mean=float(de.mean()),
                p99=float(np.percentile(de, 99)),
                max=float(de.max()),
                dY_max=float(np.abs(got[:, 1] - truth[:, 1]).max()),
                in_gamut_n=int(inside.sum()),
                in_gamut_max=float(de[inside].max()) if inside.any() else 0.0,
                in_gamut_p99=float(np.percentile(de[inside], 99)) if inside.any() else 0.0,
            )
    return out


BEGIN, END = "<!-- bench_gamut_map:begin -->", "<!-- bench_gamut_map:end -->"


def numbers_markdown(result):
    """The measured tables of docs/gamut_map.md, from the benchmark's JSON."""
    out = [
        "| display | set | colours | dE2000 mean | p99 | max | max \\|dY\\| | in-gamut max |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for display, sets in result["accuracy"].items():
        for name, m in sets.items():
            out.append(
                f"| {display} | {name} | {m['n']} | {m['mean']:.3f} | {m['p99']:.3f} | "
                f"{m['max']:.3f} | {m['dY_max']:.1e} | {m['in_gamut_max']:.3f} |"
            )
    if result.get("speed"):
        out += [
            "",
            "| data set | clip | ACES view | ACES bare | 65³ Lut3D | one-LUT chain | "
            "clip / ACES view | clip / ACES bare | clip / Lut3D | one-LUT chain / ACES view |",
            "|---|---|---|---|---|---|---|---|---|---|",
        ]
        for r in result["speed"]:
            m = r["mpix_per_s"]
            out.append(
                f"| {r['dataset']} | {m['clip']:.1f} | {m['aces']:.1f} | "
                f"{m['aces bare']:.1f} | {m['lut65']:.1f} | {m['one-LUT chain']:.1f} | "
                f"{r['clip_over_aces']:.2f}× | {r['clip_over_aces_bare']:.2f}× | "
                f"{r['clip_over_lut65']:.2f}× | {r['one_lut_chain_over_aces']:.2f}× |"
            )
    return "\n".join(out)


TARGETS_BEGIN, TARGETS_END = (
    "<!-- bench_gamut_map:targets:begin -->",
    "<!-- bench_gamut_map:targets:end -->",
)
#: The targets for the clip views against the analytic clip.
TARGETS = {"p99": 0.5, "max": 1.5, "dY_max": 1e-3, "in_gamut_max": 0.1, "speed": 1.0}


def targets_markdown(result):
    """docs/gamut_map.md's account of the targets: what the JSON meets and misses."""
    acc = result["accuracy"]
    met, missed = [], []
    for name in next(iter(acc.values())):
        rows = [acc[d][name] for d in acc]
        for key, label, fmt in (
            ("p99", "p99", ".2f"),
            ("max", "max", ".2f"),
            ("dY_max", "|ΔY|", ".1e"),
        ):
            worst = max(m[key] for m in rows)
            line = f"{name} {label} ≤ {format(worst, fmt)} (target {TARGETS[key]:g})"
            (met if worst <= TARGETS[key] else missed).append(line)
    worst = max(
        m["in_gamut_max"] for by_set in acc.values() for m in by_set.values() if m["in_gamut_n"]
    )
    line = f"in-gamut colours move by ≤ {worst:.2f} ΔE2000 (target {TARGETS['in_gamut_max']:g})"
    (met if worst <= TARGETS["in_gamut_max"] else missed).append(line)
    for r in result.get("speed") or []:
        line = f"speed on {r['dataset']}: {r['clip_over_aces']:.2f}× the ACES view"
        (met if r["clip_over_aces"] >= TARGETS["speed"] else missed).append(line)
    return "\n".join(
        [
            f"- **Met** (worst display): {'; '.join(met)}.",
            f"- **Not met** (worst display): {'; '.join(missed) or 'none'}.",
        ]
    )


STATUS_BEGIN, STATUS_END = (
    "<!-- bench_gamut_map:status:begin -->",
    "<!-- bench_gamut_map:status:end -->",
)


def status_markdown(result):
    """The README's status line of the clip views, its figures from the benchmark's JSON."""
    acc = result["accuracy"]
    every = [m for by_set in acc.values() for m in by_set.values()]
    worst = {name: max(acc[d][name]["max"] for d in acc) for name in next(iter(acc.values()))}
    dY = {name: max(acc[d][name]["dY_max"] for d in acc) for name in worst}
    text = (
        "- The `Constant-Lightness Clip` views: on every display and every test set (object, "
        "monochromatic, random AP0, spectral-line mixtures up to Y = 0.99) within ΔE2000 p99 "
        f"{max(m['p99'] for m in every):.2f} of the analytic clip, in-gamut colours within "
        f"{max(m['in_gamut_max'] for m in every):.2f}, |ΔY| ≤ {max(dY.values()):.1e}, in "
        "gamut, every processor finite at "
        "every OCIO optimisation level; GPU float textures within 2/255 of the CPU, "
        "half-float ones too but near black on the pure-power and PQ displays (up to "
        "3.4/255: tests/test_gpu.py prints what it measures and xfails there)"
    )
    missed = [
        f"max ΔE2000 ≤ 1.5 on {name} ({v:.2f})" for name, v in worst.items() if v > TARGETS["max"]
    ]
    missed += [
        f"|ΔY| ≤ 1e-3 on {name} ({v:.1e})" for name, v in dY.items() if v > TARGETS["dY_max"]
    ]
    oil = [r for r in result.get("speed") or [] if r["dataset"] == "oil scene"]
    if oil and oil[0]["clip_over_aces"] < TARGETS["speed"]:
        missed.append(
            "on a mostly in-gamut rendered scene the view runs at "
            f"{oil[0]['clip_over_aces']:.2f}× the ACES view"
        )
    text += ". Not reached: " + "; ".join(missed) if missed else ""
    text += ". Details and numbers: [docs/gamut_map.md](docs/gamut_map.md)."
    return text


def update_markdown(path, result, update=False):
    """Replace the text between BEGIN and END in ``path`` by :func:`numbers_markdown`,
    and the README's status line by :func:`status_markdown` -- if ``update``; else say
    which would change."""
    _reports.update_section(path, BEGIN, END, numbers_markdown(result), update=update)
    if TARGETS_BEGIN in Path(path).read_text():
        body = targets_markdown(result)
        _reports.update_section(path, TARGETS_BEGIN, TARGETS_END, body, update=update)
    readme = ROOT / "README.md"
    if STATUS_BEGIN in readme.read_text():
        body = status_markdown(result)
        _reports.update_section(readme, STATUS_BEGIN, STATUS_END, body, update=update)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=1024)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--json", default=str(ROOT / "reports" / "bench_gamut_map.json"))
    parser.add_argument("--no-speed", action="store_true", help="accuracy only")
    _reports.add_update_docs(parser)
    args = parser.parse_args(argv)
    acc = accuracy()
    print(f"{'display':11s} {'set':14s} {'p99':>6s} {'max':>6s} {'|dY|':>8s} {'in-gamut max':>13s}")
    for display, sets in acc.items():
        for name, m in sets.items():
            print(
                f"{display:11s} {name:14s} {m['p99']:6.3f} {m['max']:6.3f} {m['dY_max']:8.1e} "
                f"{m['in_gamut_max']:13.3f}"
            )
    result = {"accuracy": acc}
    path = Path(args.json)
    if args.no_speed and path.exists():  # keep the last speed run
        result["speed"] = json.loads(path.read_text()).get("speed")
    if args.no_speed:
        _reports.write_json("gamut_map", result, path=path, indent=2)
        update_markdown(ROOT / "docs" / "gamut_map.md", result, args.update_docs)
        return
    rows = measure(args.size, args.repeats)
    print(
        f"{'data set':20s} {'clip':>7s} {'aces':>7s} {'bare':>7s} {'lut65':>7s}   "
        "clip/aces  clip/bare  clip/lut65   (Mpixel/s, one thread)"
    )
    for r in rows:
        m = r["mpix_per_s"]
        print(
            f"{r['dataset']:20s} {m['clip']:7.1f} {m['aces']:7.1f} {m['aces bare']:7.1f} "
            f"{m['lut65']:7.1f}   {r['clip_over_aces']:9.2f}  {r['clip_over_aces_bare']:9.2f}"
            f"  {r['clip_over_lut65']:10.2f}"
        )
    result["speed"] = rows
    _reports.write_json("gamut_map", result, path=path, indent=2)
    update_markdown(ROOT / "docs" / "gamut_map.md", result, args.update_docs)


if __name__ == "__main__":
    main()
