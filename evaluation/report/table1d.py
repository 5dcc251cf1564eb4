"""Section 1b: the 1D thickness table's size and spacing."""

from __future__ import annotations

import time

import numpy as np

from evaluation.report.context import Section
from evaluation.report.datasets import test_thicknesses
from evaluation.report.measure import (
    default,
    fmt,
    ocio_apply_speed,
    ocio_cpu,
    stats,
    table,
)
from evaluation.report.plots import pareto_plot
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.lut import ocio_ops, tables


def section(ctx) -> Section:
    """``tables.film_table`` at several sizes and spacings against direct evaluation."""
    q = ctx.quick
    d_size = default(tables.film_table, "size")
    d_t0 = default(tables.film_table, "t0_um")
    tmax = default(tables.film_table, "max_thickness_um")
    step = default(tables.film_table, "step")
    sizes = [1024, 4096, d_size] if q else sorted({256, 1024, 2048, 4096, 8192, 16384, d_size})
    spacings = {
        f"log, t0 = {d_t0:g} µm (shipped)": d_t0,
        "log, t0 = 0.1 µm": 0.1,
        f"uniform 0–{tmax:g} µm": ("uniform", tmax),
        "uniform 0–1.5 µm (clamps beyond)": ("uniform", 1.5),
    }
    if q:
        spacings = {k: v for k, v in spacings.items() if v != 0.1}
    thin = test_thicknesses(q)  # t' in 0–1.5 um, micrometres
    thick = test_thicknesses(q, tmax, n=thin.size // 4)
    x_um = np.concatenate([thin, thick])
    direct = colorimetry.film_XYZ(x_um * 1000.0, step=step)  # same spectra, no table
    img = np.repeat(x_um[: (65536 if q else 262144)].astype(np.float32)[:, None], 3, axis=1)
    rows, series, raw = [], {}, []
    results = {}
    default_pt = None
    ocio_check = 0.0
    for label, t0 in spacings.items():
        series[label] = []
        uniform = isinstance(t0, tuple)
        for size in sizes:
            t_start = time.perf_counter()
            if uniform:  # uniform nodes, the shipped Table1D class
                nodes = np.linspace(0.0, t0[1], size)
                lut = tables.Table1D(
                    kind="phase-change",
                    values=colorimetry.film_XYZ(nodes * 1000.0, step=step),
                    encoding="linear",
                    domain_min=0.0,
                    domain_max=float(t0[1]),
                    nodes=nodes,
                    name="uniform",
                )
            else:
                lut = tables.film_table("phase-change", size, t0_um=t0)
            bake = time.perf_counter() - t_start
            de = colorimetry.delta_E2000(lut.lookup(x_um), direct)
            s_thin, s_all = stats(de[: thin.size]), stats(de)
            tf = lut.transform()
            mpix = ocio_apply_speed(ocio_cpu(tf), img)
            via = ocio_ops.apply(tf, img[:4096])
            ocio_check = max(
                ocio_check,
                float(
                    np.max(
                        colorimetry.delta_E2000(
                            via.astype(np.float64), lut.lookup(img[:4096, 0].astype(np.float64))
                        )
                    )
                ),
            )
            is_default = not uniform and t0 == d_t0 and size == d_size
            if is_default:
                results["default_table1d"] = {"size": size, "thin": s_thin, "all": s_all}
                default_pt = (1.0 / mpix, s_thin["p99"], f"{size}, log t0 {d_t0:g} µm")
            rows.append(
                [
                    label,
                    size,
                    s_thin["mean"],
                    s_thin["p99"],
                    s_thin["max"],
                    s_all["max"],
                    bake,
                    mpix,
                ]
            )
            series[label].append((1.0 / mpix, s_thin["p99"], s_thin["max"], size))
            raw.append(
                {
                    "spacing": label,
                    "t0_um": t0,
                    "size": size,
                    "thin": s_thin,
                    "all": s_all,
                    "bake_s": bake,
                    "apply_Mpix_s": mpix,
                }
            )
    results["table1d"] = {"rows": raw, "ocio_vs_numpy_dE_max": ocio_check}
    img_md = pareto_plot(
        ctx,
        "knob_table1d.png",
        "1D thickness table: error vs apply cost",
        series,
        xlabel="apply cost through OCIO (µs per Mpixel⁻¹ = s / Mpixel)",
        default=default_pt,
        ylabel="ΔE2000 over t' 0–1.5 µm (p99, max)",
    )
    d = results.get("default_table1d")
    headline = (
        None
        if d is None
        else {"size": d["size"], "thin_max": d["thin"]["max"], "all_max": d["all"]["max"]}
    )
    return Section(
        "\n".join(
            [
                "### 1b. 1D table size and spacing",
                "",
                f"The soap-film thickness table (`tables.film_table`, 0–{tmax:g} µm, linear "
                "interpolation through OCIO's Lut1D behind a log shaper) against direct "
                f"evaluation of the same spectra ({step:g} nm band-limited) at {thin.size} random "
                f"t' in 0–1.5 µm and {thick.size} in 0–{tmax:g} µm: the error is the table's "
                "alone. Bake = first build "
                f"(uncached); apply = OCIO CPU processor on {img.shape[0]} pixels, one thread. "
                f"OCIO path vs the numpy `lookup`: ΔE2000 max {fmt(ocio_check)} (float32).",
                "",
                table(
                    [
                        "spacing",
                        "size",
                        "0–1.5 µm mean",
                        "p99",
                        "max",
                        f"0–{tmax:g} µm max",
                        "bake (s)",
                        "apply Mpixel/s",
                    ],
                    rows,
                ),
                "",
                f"Defaults (from `film_table`'s signature): size {d_size}, t0 = {d_t0:g} µm.",
                "",
                img_md,
            ]
        ),
        results,
        {"table1d": headline},
    )
