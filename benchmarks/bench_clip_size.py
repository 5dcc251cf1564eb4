"""Benchmark: accuracy / size / load time of the Constant-Lightness Clip LUTs against
their edge lengths (the config's size budget against accuracy).

For each display and each (black-pass edge, white-pass edge) pair the shipped design
(:class:`ocio_thinfilm.lut.clip_lut.ClipLUT`) is built, both passes are written as CLF
files exactly as the config bakes them, and the whole view chain is read back from
those files:

- MB: the two CLFs' text (what a host parses before the first pixel);
- load ms: building a CPU processor of the chain from the files in a fresh OCIO
  config (best of 3, OCIO's caches cleared);
- accuracy: the chain through OCIO's CPU processor against the analytic clip
  (``colour.clip.clip_XYZ``) on the test sets of ``tests/test_clip_view.py`` (object,
  monochromatic, random AP0, spectral-line mixtures), dE2000 p99 / max, the largest
  |dY|, and the largest dE2000 of in-gamut colours.

Config size: three displays' clip LUTs plus the thin-film tables (about 0.7 MB); the
budget is 25 MB. Also measured: what building a processor costs per text format (one
65³ Lut3D of random values as 8-bit, 16-bit and half-float CLF, each in a fresh
process), and the plain ACEScct -> sRGB ``.cube`` of ``luts/`` at several edge lengths
(size against ΔE2000 on object colours inside AP1, applied by OCIO), the budget of
``luts/`` against accuracy. Writes reports/bench_clip_size.md and
reports/bench_clip_size.json.

Usage: python benchmarks/bench_clip_size.py [--pairs 49:41 57:45 65:53 65:57 73:53]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/
from benchmarks import _reports  # noqa: E402  (after the path above)

DEFAULT_PAIRS = ("49:41", "57:45", "65:49", "65:53", "65:57", "73:53")


def chain_from_files(lut, directory):
    """The view's clip chain with both passes read from CLF files in ``directory``
    (as the config references them); returns (transform, bytes of the two files)."""
    import PyOpenColorIO as ocio

    from ocio_thinfilm.export.files import CLF_WRITER
    from ocio_thinfilm.lut import clip_lut as CL
    from ocio_thinfilm.lut import ocio_ops

    paths = []
    for kind, core in (("black", lut.black_core()), ("white", lut.white_core())):
        path = Path(directory) / f"{kind}.clf"
        core.write(CLF_WRITER, str(path), ocio.Config.CreateRaw())
        paths.append(path)
    cores = [ocio.FileTransform(str(p), interpolation=ocio.INTERP_BEST) for p in paths]
    chain = ocio_ops.group(lut.transforms(*cores) + [CL.working_decoding_transform()])
    return chain, sum(p.stat().st_size for p in paths)


def load_ms(chain):
    import PyOpenColorIO as ocio

    best = np.inf
    for _ in range(3):
        ocio.ClearAllCaches()
        t0 = time.perf_counter()
        ocio.Config.CreateRaw().getProcessor(chain).getDefaultCPUProcessor()
        best = min(best, time.perf_counter() - t0)
    return best * 1e3


def accuracy(display, chain, sets):
    from ocio_thinfilm.colour import clip, colorimetry
    from ocio_thinfilm.lut.ocio_ops import apply

    M = colorimetry.matrix_XYZ_to_RGB(display)
    out = {}
    for name, XYZ in sets.items():
        got = colorimetry.RGB_to_XYZ(np.asarray(apply(chain, XYZ), float), display)
        truth = clip.clip_XYZ(XYZ, display)
        de = colorimetry.delta_E2000(truth, got)
        inside = clip.in_gamut(XYZ @ M.T)
        out[name] = dict(
            p99=float(np.percentile(de, 99)),
            max=float(de.max()),
            dY=float(np.abs(got[:, 1] - truth[:, 1]).max()),
            inside_max=float(de[inside].max()) if inside.any() else 0.0,
        )
    return out


def measure(pairs, displays):
    from evaluation.colours import gamut_map_sets as _sets
    from ocio_thinfilm.lut import clip_lut as CL

    sets = _sets()
    rows = []
    for black, white in pairs:
        for display in displays:
            lut = CL.clip_lut(display, black, white)
            with tempfile.TemporaryDirectory() as tmp:
                chain, size = chain_from_files(lut, tmp)
                rows.append(
                    dict(
                        display=display,
                        black=black,
                        white=white,
                        MB=size / 1e6,
                        load_ms=load_ms(chain),
                        accuracy=accuracy(display, chain, sets),
                    )
                )
            print(markdown_row(rows[-1]), flush=True)
    return rows


def parse_cost():
    """{bit depth: (MB, ms)}: building a processor from one 65³ Lut3D CLF in a fresh
    process (best of 3), by how the values are written."""
    import subprocess

    import PyOpenColorIO as ocio

    from ocio_thinfilm.export.files import CLF_WRITER

    values = np.random.default_rng(0).integers(0, 256, (65, 65, 65, 3)) / 255.0
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, depth in (
            ("8-bit", ocio.BIT_DEPTH_UINT8),
            ("16-bit", ocio.BIT_DEPTH_UINT16),
            ("half float", ocio.BIT_DEPTH_F16),
        ):
            lut = ocio.Lut3DTransform()
            lut.setGridSize(65)
            lut.setData(np.ascontiguousarray(values, np.float32).ravel())
            lut.setFileOutputBitDepth(depth)
            group = ocio.GroupTransform()
            group.appendTransform(lut)
            path = Path(tmp) / f"{name}.clf"
            group.write(CLF_WRITER, str(path), ocio.Config.CreateRaw())
            code = (
                "import time, PyOpenColorIO as o; t = time.perf_counter(); "
                f"o.Config.CreateRaw().getProcessor(o.FileTransform({str(path)!r})); "
                "print(time.perf_counter() - t)"
            )
            ms = min(
                float(
                    subprocess.run(
                        [sys.executable, "-c", code], capture_output=True, text=True, check=True
                    ).stdout
                )
                for _ in range(3)
            )
            out[name] = (path.stat().st_size / 1e6, ms * 1e3)
    return out


def plain_cube_curve(sizes):
    """{edge: (MB, p99, max)}: the plain ACEScct -> sRGB .cube of ``luts/`` baked at
    each edge, applied by OCIO, against the analytic clip on object colours inside AP1
    (as tests/test_export_view.py measures it)."""
    import colour

    from evaluation.views import apply_lut_files, colour_science_rgb, decode_display
    from ocio_thinfilm.colour import clip, colorimetry

    def delta_E(code, XYZ, display):
        got = colorimetry.RGB_to_XYZ(decode_display(code, display), display)
        expected = colorimetry.RGB_to_XYZ(
            clip.clip_RGB(colorimetry.XYZ_to_RGB(XYZ, display), display), display
        )
        return colorimetry.delta_E2000(got, expected)

    from evaluation.colours import object_colours
    from ocio_thinfilm.export.view import export_view

    XYZ = object_colours()
    acescg = colour_science_rgb(XYZ, "ACEScg")
    keep = (acescg >= 0).all(axis=1)
    XYZ, cct = XYZ[keep], colour.models.log_encoding_ACEScct(acescg[keep])
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for n in sizes:
            path = Path(tmp) / f"plain{n}.cube"
            export_view("ACEScct", "sRGB", "Constant-Lightness Clip", path, size=n)
            dE = delta_E(apply_lut_files([path], cct), XYZ, "sRGB")
            p99, worst = np.percentile(dE, 99), dE.max()
            out[n] = (path.stat().st_size / 1e6, float(p99), float(worst))
            print(
                f"plain .cube {n}^3: {out[n][0]:.1f} MB, p99 {p99:.2f} / max {worst:.2f}",
                flush=True,
            )
    return out


def markdown_row(r):
    cells = " | ".join(f"{m['p99']:.2f} / {m['max']:.2f}" for m in r["accuracy"].values())
    dY = max(m["dY"] for m in r["accuracy"].values())
    inside = max(m["inside_max"] for m in r["accuracy"].values())
    return (
        f"| {r['display']} | {r['black']}³ + {r['white']}³ | {r['MB']:.1f} | "
        f"{r['load_ms']:.0f} | {cells} | {dY:.1e} | {inside:.3f} |"
    )


def extras_markdown(parse, cubes):
    lines = [
        "",
        "Building a processor from one 65³ Lut3D CLF (random values, fresh process, "
        "best of 3): "
        + "; ".join(f"{name} {mb:.1f} MB, {ms:.0f} ms" for name, (mb, ms) in parse.items())
        + ".",
        "",
        "The plain ACEScct → sRGB `.cube` of `luts/` by edge length (object colours "
        "inside AP1, applied by OCIO, ΔE2000 p99 / max; three displays' files make "
        "`luts/`): "
        + "; ".join(f"{n}³ {mb:.1f} MB, {p99:.2f} / {mx:.2f}" for n, (mb, p99, mx) in cubes.items())
        + ".",
    ]
    return "\n".join(lines) + "\n"


def markdown(rows, sets, ocio_version):
    head = (
        "| display | black + white | MB | load ms | "
        + " | ".join(f"{s} p99 / max" for s in sets)
        + " | max \\|dY\\| | in-gamut max |"
    )
    lines = [
        "# bench_clip_size: the clip LUTs' accuracy, size and load time by edge length",
        "",
        f"Written by `python benchmarks/bench_clip_size.py` (OCIO {ocio_version}). "
        "MB: both passes' CLF text for one display (the config holds three, plus "
        "0.7 MB of thin-film tables; budget 25 MB); load ms: a CPU processor of the "
        "chain built from those files; accuracy: dE2000 against the analytic clip.",
        "",
        head,
        "|" + "---|" * (6 + len(sets)),
    ]
    lines += [markdown_row(r) for r in rows]
    config_mb = {}
    for r in rows:
        config_mb.setdefault((r["black"], r["white"]), 0.0)
        config_mb[r["black"], r["white"]] += r["MB"]
    lines += [
        "",
        "Config size (three displays' clip LUTs + 0.7 MB of tables): "
        + "; ".join(f"{b}³ + {w}³: {mb + 0.7:.1f} MB" for (b, w), mb in config_mb.items())
        + ".",
    ]
    return "\n".join(lines) + "\n"


def main(argv=None):
    import PyOpenColorIO as ocio

    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument(
        "--pairs",
        nargs="+",
        default=list(DEFAULT_PAIRS),
        help="BLACK:WHITE edge pairs (default: %(default)s)",
    )
    p.add_argument("--displays", nargs="+", default=["sRGB", "Display P3", "Rec.2020"])
    p.add_argument(
        "--cube-sizes",
        type=int,
        nargs="+",
        default=[49, 55, 65],
        help="edges of the plain display .cube to measure (default: %(default)s)",
    )
    args = p.parse_args(argv)
    pairs = []
    for pair in args.pairs:
        try:
            black, white = (int(v) for v in pair.split(":"))
        except ValueError:
            p.error(f"--pairs: expected BLACK:WHITE integers, got {pair!r}")
        pairs.append((black, white))
    rows = measure(pairs, args.displays)
    parse, cubes = parse_cost(), plain_cube_curve(args.cube_sizes)
    sets = list(rows[0]["accuracy"])
    _reports.write_json(
        "clip_size",
        {
            "ocio": ocio.__version__,
            "rows": rows,
            "parse_cost": parse,
            "plain_cube": {str(n): v for n, v in cubes.items()},
        },
    )
    (ROOT / "reports" / "bench_clip_size.md").write_text(
        markdown(rows, sets, ocio.__version__) + extras_markdown(parse, cubes)
    )
    print(f"wrote {ROOT / 'reports' / 'bench_clip_size.md'}")


if __name__ == "__main__":
    main()
