"""Benchmark: 1D table spacing/size and 3D clip-LUT domain/size, error against bake time.

Run:  python benchmarks/bench_luts.py [--quick] [--displays sRGB "Display P3" Rec.2020]
                                       [--json results.json]

1D tables: max CIE dE2000 of the interpolated table against direct evaluation
(``colorimetry.film_XYZ`` at the same spectral step), at the midpoints between nodes
(the worst case of linear interpolation) and on a dense grid, through numpy
(``Table1D.lookup``) and through OCIO's CPU processor (``Table1D.transform()``).

3D clip LUT: dE2000 of the OCIO transform against the analytic ``clip.clip_XYZ`` on
``object_colours()`` (random smooth reflectances, ColorCheckers, Munsell,
interference colours); on spectral colours at Y <= 0.6 the luminance error and
whether the output is in gamut; bake time (vertex values + OCIO processor) and the
size of the CLF the config would ship.

The shipped design and why it is laid out so: see :func:`options` and docs/gamut_map.md;
this script prints its own measurements (no numbers are typed here).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from benchmarks import _reports  # noqa: E402  (after the path above)
from evaluation.colours import object_colours, spectral_colours  # noqa: E402
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import clip_lut, display_transforms, grid, ocio_ops, tables  # noqa: E402


def grey(x):
    return np.repeat(np.asarray(x, np.float32)[:, None], 3, axis=1)


# --------------------------------------------------------------------------- #
# 1D tables
# --------------------------------------------------------------------------- #
def bench_1d(quick):
    rows = []
    kind = "phase-change"
    uniform_sizes = (1024, 4096, 16384)
    for size in uniform_sizes:
        t0 = time.perf_counter()
        nodes = np.linspace(0.0, 1.5, size)
        table = tables.Table1D(
            kind=kind,
            values=colorimetry.film_XYZ(nodes * 1000.0, kind),
            encoding="linear",
            domain_min=0.0,
            domain_max=1.5,
            nodes=nodes,
            name="uniform",
        )
        bake = time.perf_counter() - t0
        mid = (nodes[:-1] + nodes[1:]) / 2
        direct = colorimetry.film_XYZ(mid * 1000.0, kind)
        de_np = colorimetry.delta_E2000(table.lookup(mid), direct).max()
        de_ocio = colorimetry.delta_E2000(
            ocio_ops.apply(table.transform(), grey(mid)).astype(np.float64), direct
        ).max()
        rows.append(
            dict(
                spacing="uniform 0-1.5 um",
                size=size,
                max_dE_numpy=de_np,
                max_dE_ocio=de_ocio,
                bake_s=bake,
            )
        )
    log_sizes = (2048, 4096, 8192) if quick else (2048, 4096, 8192, 16384, 65536)
    for size in log_sizes:
        t0 = time.perf_counter()
        table = tables.film_table(kind, size)
        bake = time.perf_counter() - t0
        u = (np.arange(size - 1) + 0.5) / (size - 1)
        mid = table.t0 * np.expm1(u * np.log1p(table.domain_max / table.t0))
        direct = colorimetry.film_XYZ(mid * 1000.0, kind)
        de_np = colorimetry.delta_E2000(table.lookup(mid), direct).max()
        de_ocio = colorimetry.delta_E2000(
            ocio_ops.apply(table.transform(), grey(mid)).astype(np.float64), direct
        ).max()
        rows.append(
            dict(
                spacing="log2 shaper t0=1 um, 0-100 um",
                size=size,
                max_dE_numpy=de_np,
                max_dE_ocio=de_ocio,
                bake_s=bake,
            )
        )
    for size in (512, 1024, 4096):
        t0 = time.perf_counter()
        table = tables.morpho_table(size)
        bake = time.perf_counter() - t0
        c = (np.arange(size - 1) + 0.5) / (size - 1)
        direct = colorimetry.morpho_XYZ(np.degrees(np.arccos(c)))
        rows.append(
            dict(
                spacing="Morpho, uniform cos(theta)",
                size=size,
                max_dE_numpy=colorimetry.delta_E2000(table.lookup(c), direct).max(),
                max_dE_ocio=colorimetry.delta_E2000(
                    ocio_ops.apply(table.transform(), grey(c)).astype(np.float64), direct
                ).max(),
                bake_s=bake,
            )
        )
    return rows


# --------------------------------------------------------------------------- #
# 3D clip LUT options
# --------------------------------------------------------------------------- #
def naive_xyz(display, size):
    """Baseline: LUT over XYZ / white in [0, 1]^3, outputs clipped RGB, no shaper."""
    W = colorimetry.white_XYZ(display)
    g = np.linspace(0, 1, size)
    P = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1) * W
    V = colorimetry.XYZ_to_RGB(clip.clip_XYZ(P, display), display)
    return ocio_ops.group(
        [ocio_ops.matrix(np.diag(1 / W)), ocio_ops.lut3d_transform(V), ocio_ops.range_(0, 1)]
    )


def uvY_uniform(display, size):
    """LUT over CIE 1976 u'v'Y (FixedFunction XYZ_TO_uvY), uniform, outputs u'v'Y."""
    import PyOpenColorIO as ocio

    hi = np.array([0.63, 0.6, 1.0])
    g = np.linspace(0, 1, size)
    U = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1)
    c = U * hi
    u, v, Y = c[..., 0], np.maximum(c[..., 1], 1e-9), np.maximum(c[..., 2], 1e-9)
    XYZ = np.stack([Y * 9 * u / (4 * v), Y, Y * (12 - 3 * u - 20 * v) / (4 * v)], -1)
    out = clip.clip_XYZ(XYZ, display)
    s = out[..., 0] + 15 * out[..., 1] + 3 * out[..., 2]
    s = np.where(s == 0, 1.0, s)
    uvY = np.stack([4 * out[..., 0] / s, 9 * out[..., 1] / s, c[..., 2]], -1)
    inside = np.all(out == XYZ, -1)
    uvY[inside] = c[inside]
    uvY[..., 2] = c[..., 2]
    fwd = ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_XYZ_TO_uvY)
    inv = ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_XYZ_TO_uvY)
    inv.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return ocio_ops.group(
        [
            clip_lut.xyz_limit_transform(),
            fwd,
            ocio_ops.matrix(np.diag(1 / hi)),
            ocio_ops.lut3d_transform(uvY / hi),
            ocio_ops.matrix(np.diag(hi)),
            inv,
            display_transforms.display_matrix_transform(display),
            ocio_ops.range_(0, 1),
        ]
    )


def options(quick):
    """The shipped two-pass design at several sizes, and two single-LUT baselines.

    Why the design has two passes and no shapers or gains around its first LUT:
    docs/gamut_map.md, *Why this layout*.
    """
    sizes = (33, 49, 65) if quick else (33, 41, 49, 57, 65)
    return [
        ("naive XYZ/white (baseline)", naive_xyz, (33, 65)),
        ("u'v'Y uniform", uvY_uniform, (33, 65)),
        (
            "two passes: black faces over a chart, white faces over encoded RGB (shipped)",
            lambda d, n: clip_lut.clip_transform(d, n),
            sizes,
        ),
    ]


def clf_size(transform):
    """Bytes of the CLF holding the LUT part of ``transform`` (Lut3D and what is
    CLF-writable around it)."""
    import PyOpenColorIO as ocio

    from ocio_thinfilm.export.files import CLF_WRITER

    writable = ocio_ops.group(
        [t for t in _flatten(transform) if not isinstance(t, ocio.FixedFunctionTransform)]
    )
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "x.clf"
        writable.write(CLF_WRITER, str(path), ocio.Config.CreateRaw())
        return path.stat().st_size


def _flatten(transform):
    import PyOpenColorIO as ocio

    if (
        isinstance(transform, ocio.GroupTransform)
        and transform.getDirection() == ocio.TRANSFORM_DIR_FORWARD
    ):
        for t in transform:
            yield from _flatten(t)
    else:
        yield transform


def bench_3d(displays, quick):
    objects = object_colours()
    locus = spectral_colours(0.6)
    rows = []
    for display in displays:
        truth = clip.clip_XYZ(objects, display)
        for label, build, sizes in options(quick):
            for size in sizes:
                clip_lut._clip_lut.cache_clear()
                grid.black_plan.cache_clear()
                t0 = time.perf_counter()
                transform = build(display, size)
                out = ocio_ops.apply(transform, objects[:1])  # processor built
                bake = time.perf_counter() - t0
                out = ocio_ops.apply(transform, objects).astype(np.float64)
                de = colorimetry.delta_E2000(truth, colorimetry.RGB_to_XYZ(out, display))
                lo = ocio_ops.apply(transform, locus).astype(np.float64)
                Y = colorimetry.RGB_to_XYZ(lo, display)[:, 1]
                de_locus = colorimetry.delta_E2000(
                    clip.clip_XYZ(locus, display), colorimetry.RGB_to_XYZ(lo, display)
                )
                rows.append(
                    dict(
                        display=display,
                        option=label,
                        size=size,
                        mean=de.mean(),
                        p99=np.percentile(de, 99),
                        max=de.max(),
                        locus_dY=np.abs(Y - locus[:, 1]).max(),
                        locus_dY_rel=np.abs(Y / locus[:, 1] - 1).max(),
                        locus_in_gamut=bool(clip.in_gamut(lo, 1e-6).all()),
                        locus_p99=np.percentile(de_locus, 99),
                        bake_s=bake,
                        clf_MB=clf_size(transform) / 1e6,
                    )
                )
                print(_fmt3d(rows[-1]), flush=True)
    return rows


def _fmt3d(r):
    return (
        f"| {r['display']} | {r['option']} | {r['size']} | {r['mean']:.3f} | "
        f"{r['p99']:.3f} | {r['max']:.3f} | {r['locus_dY']:.1e} | "
        f"{r['locus_dY_rel']:.1e} | {'yes' if r['locus_in_gamut'] else 'NO'} | "
        f"{r['locus_p99']:.2f} | "
        f"{r['bake_s']:.2f} | {r['clf_MB']:.2f} |"
    )


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="fewer sizes")
    p.add_argument("--displays", nargs="+", default=["sRGB"], choices=clip.DISPLAYS)
    p.add_argument("--json", default=None, help="where to write the rows (reports/bench_luts.json)")
    args = p.parse_args(argv)

    print("## 1D tables (phase-change film; Morpho), max dE2000 vs direct evaluation\n")
    print("| spacing | entries | max dE numpy | max dE OCIO | bake s |")
    print("|---|---:|---:|---:|---:|")
    colorimetry.film_XYZ(np.zeros(1))  # import colour-science before timing
    rows1 = bench_1d(args.quick)
    for r in rows1:
        print(
            f"| {r['spacing']} | {r['size']} | {r['max_dE_numpy']:.4f} | "
            f"{r['max_dE_ocio']:.4f} | {r['bake_s']:.2f} |"
        )
    print(
        "\n## 3D clip LUT options, dE2000 vs analytic clip on object colours; "
        "spectral colours Y <= 0.6\n"
    )
    print(
        "| display | option | size | mean | p99 | max | locus |dY| | locus |dY|/Y | "
        "locus in gamut | locus p99 dE | bake s | CLF MB |"
    )
    print("|---|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|")
    rows3 = bench_3d(args.displays, args.quick)
    _reports.write_json("luts", {"table1d": rows1, "clip3d": rows3}, path=args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
