"""Section 1d: analytic per-pixel evaluation against LUT application."""

from __future__ import annotations

import numpy as np

from evaluation.report.context import Section
from evaluation.report.datasets import test_thicknesses
from evaluation.report.measure import (
    best_time,
    default,
    film_XYZ_chunked,
    ocio_apply_speed,
    ocio_cpu,
    stats,
    table,
)
from evaluation.report.plots import pareto_plot
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import clip_lut, ocio_ops, tables


def section(ctx) -> Section:
    """From a thickness image to clipped sRGB by five paths: error and speed of each."""
    q = ctx.quick
    display = "sRGB"
    M = colorimetry.matrix_XYZ_to_RGB(display)
    Minv = np.linalg.inv(M)
    n = 8192 if q else 32768
    ref_step = 0.25
    x_um = test_thicknesses(q, 1.5, n)
    step = default(colorimetry.film_XYZ, "step")
    reference = clip.clip_XYZ(film_XYZ_chunked(x_um * 1000.0, ref_step, True, chunk=512))
    film = tables.film_table("phase-change")
    img = np.repeat(x_um.astype(np.float32)[:, None], 3, axis=1)
    d_size = default(clip_lut.clip_transform, "size")
    big = 65 if d_size < 65 else d_size
    ocio_paths = {
        f"Lut1D + {d_size}³ clip LUT, OCIO (shipped)": ocio_ops.group(
            [film.transform(), clip_lut.clip_transform(display)]
        ),
        f"Lut1D + {big}³ clip LUT, OCIO": ocio_ops.group(
            [film.transform(), clip_lut.clip_transform(display, big)]
        ),
    }
    lut1d_tf = film.transform()
    paths = {
        f"analytic: film_XYZ ({step:g} nm) + clip_RGB, numpy": lambda: clip.clip_RGB(
            colorimetry.film_XYZ(x_um * 1000.0) @ M.T, display
        ),
        "table lookup (numpy) + clip_RGB (numpy)": lambda: clip.clip_RGB(
            film.lookup(x_um) @ M.T, display
        ),
        "Lut1D (OCIO) + clip_RGB (numpy)": lambda: clip.clip_RGB(
            ocio_ops.apply(lut1d_tf, img).astype(np.float64) @ M.T, display
        ),
    }
    for name, tf in ocio_paths.items():
        paths[name] = lambda tf=tf: ocio_ops.apply(tf, img)
    rows, series, raw = [], {}, []
    for name, fn in paths.items():
        out = np.asarray(fn(), dtype=np.float64)
        de = stats(colorimetry.delta_E2000(out @ Minv.T, reference))
        if name in ocio_paths:
            mpix = ocio_apply_speed(ocio_cpu(ocio_paths[name]), img)
        else:
            mpix = n / best_time(fn, repeat=2, min_time=0.05, max_calls=3) / 1e6
        rows.append([name, de["mean"], de["p99"], de["max"], mpix])
        series[name] = [(1.0 / mpix, de["p99"], de["max"], "")]
        raw.append({"path": name, "dE": de, "Mpix_s": mpix})
    shipped = series[list(ocio_paths)[0]][0]
    img_md = pareto_plot(
        ctx,
        "knob_apply.png",
        "Analytic per pixel vs LUT: error vs cost",
        series,
        xlabel="cost (s / Mpixel, one thread)",
        default=(shipped[0], shipped[1], "shipped OCIO path"),
    )
    headline = [{"path": x["path"], "Mpix_s": x["Mpix_s"], "dE_max": x["dE"]["max"]} for x in raw]
    return Section(
        "\n".join(
            [
                "### 1d. Analytic per-pixel evaluation vs LUT application",
                "",
                f"From a thickness image ({n} random t' in 0–1.5 µm) to clipped display-linear "
                "sRGB, "
                "against the analytic clip of a fine reference spectrum "
                f"({ref_step:g} nm band-limited). Throughput per pixel, one thread.",
                "",
                table(["path", "ΔE2000 mean", "p99", "max", "Mpixel/s"], rows),
                "",
                img_md,
            ]
        ),
        {"analytic_vs_lut": raw},
        {"analytic_vs_lut": headline},
    )
