"""Benchmark: the clip view on many random AP0 colours below white, against the black
pass's edge length (size against the largest error).

The largest errors of the ``Constant-Lightness Clip`` view on random colours inside
ACES AP0 lie beyond the display's primaries (dark violet beyond the blue primary,
imaginary greens beyond Rec.2020's green): the black pass's interpolant cuts the
triangle's corners there, where L (Smits & Meyer 1990, Section 3.2, the faces through
black) has a kink along the ray from the white point through the primary. For each
black-pass edge (the white pass at its default 53³) the shipped design
(:class:`ocio_thinfilm.lut.clip_lut.ClipLUT`) is built, both passes written as CLF files
as the config bakes them, and the chain read back from those files is measured through
OCIO's CPU processor against the analytic clip (``colour.clip.clip_XYZ``) on
``evaluation.colours.ap0_below_white`` (200,000 colours): dE2000 p99 / max, and the two
CLFs' text (MB per display; the config holds three displays plus the compression's LUTs
and the tables).

Writes reports/bench_ap0_corners.md and reports/bench_ap0_corners.json.

Usage: python benchmarks/bench_ap0_corners.py [--edges 65 73 81]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/
sys.path.insert(0, str(ROOT / "benchmarks"))
from benchmarks import _reports  # noqa: E402  (after the path above)

DEFAULT_EDGES = (65, 73, 81)
WHITE = 53


def measure(edges, displays):
    from bench_clip_size import chain_from_files

    from evaluation.colours import ap0_below_white
    from ocio_thinfilm.colour import clip, colorimetry
    from ocio_thinfilm.lut import clip_lut
    from ocio_thinfilm.lut.ocio_ops import apply

    XYZ = ap0_below_white()
    rows = []
    for display in displays:
        truth = clip.clip_XYZ(XYZ, display)
        for edge in edges:
            lut = clip_lut.clip_lut(display, edge, WHITE)
            with tempfile.TemporaryDirectory() as tmp:
                chain, size = chain_from_files(lut, tmp)
                got = colorimetry.RGB_to_XYZ(np.asarray(apply(chain, XYZ), float), display)
            de = colorimetry.delta_E2000(truth, got)
            rows.append(
                dict(
                    display=display,
                    black=edge,
                    white=WHITE,
                    MB=size / 1e6,
                    p99=float(np.percentile(de, 99)),
                    max=float(de.max()),
                )
            )
            print(markdown_row(rows[-1]), flush=True)
    return rows


def markdown_row(r):
    return (
        f"| {r['display']} | {r['black']}³ + {r['white']}³ | {r['MB']:.1f} | "
        f"{r['p99']:.3f} | {r['max']:.3f} |"
    )


def markdown(rows, colours):
    lines = [
        "# bench_ap0_corners: the clip view on random AP0 colours below white, by the "
        "black pass's edge",
        "",
        "Written by `python benchmarks/bench_ap0_corners.py`. "
        f"{colours} random colours inside ACES AP0 with 0 <= Y < 1 "
        "(`evaluation.colours.ap0_below_white`), the view's chain read from its CLF files "
        "through OCIO's CPU processor against the analytic clip, dE2000; MB: both passes' "
        "CLF text for one display. Target: max <= 1.5.",
        "",
        "| display | black + white | MB | p99 | max |",
        "|---|---|---|---|---|",
    ]
    lines += [markdown_row(r) for r in rows]
    return "\n".join(lines) + "\n"


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--edges", type=int, nargs="+", default=list(DEFAULT_EDGES))
    p.add_argument("--displays", nargs="+", default=["sRGB", "Display P3", "Rec.2020"])
    args = p.parse_args(argv)
    from evaluation.colours import ap0_below_white

    rows = measure(args.edges, args.displays)
    _reports.write_json("ap0_corners", rows)
    text = markdown(rows, len(ap0_below_white()))
    (ROOT / "reports" / "bench_ap0_corners.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
