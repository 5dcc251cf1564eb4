"""Section 1a: the spectral step, with and without band-limited integration."""

from __future__ import annotations

import numpy as np

from evaluation.report.context import Section
from evaluation.report.measure import (
    best_time,
    default,
    film_XYZ_chunked,
    fmt,
    stats,
    table,
)
from evaluation.report.plots import pareto_plot
from ocio_thinfilm.colour import colorimetry


def section(ctx) -> Section:
    """Soap-film XYZ at several spectral steps against a fine point-sampled reference."""
    q = ctx.quick
    n = 201 if q else 1001
    thin = np.linspace(0.0, 1500.0, n)  # the soap-film table's range
    thick = np.linspace(1500.0, 10000.0, n)  # thick films, up to t' = 10 um
    t = np.concatenate([thin, thick])
    ref_step = 0.25 if q else 0.05
    reference = film_XYZ_chunked(t, ref_step, False)
    check = film_XYZ_chunked(t, ref_step, True)
    ref_agreement = stats(colorimetry.delta_E2000(reference, check))
    steps = [1.0, 5.0, 20.0] if q else [0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0]
    timing_t = np.linspace(0.0, 10000.0, 256)
    rows, series = [], {"band-limited": [], "point-sampled": []}
    raw = []
    for bl in (True, False):
        for step in steps:
            xyz = film_XYZ_chunked(t, step, bl)
            de = colorimetry.delta_E2000(xyz, reference)
            s_thin, s_all = stats(de[:n]), stats(de)
            cost = (
                best_time(
                    lambda step=step, bl=bl: colorimetry.film_XYZ(
                        timing_t, step=step, band_limited=bl
                    ),
                    repeat=2 if q else 3,
                )
                / timing_t.size
                * 1e6
            )
            label = "band-limited" if bl else "point-sampled"
            rows.append(
                [
                    f"{step:g}",
                    label,
                    s_thin["mean"],
                    s_thin["p99"],
                    s_thin["max"],
                    s_all["mean"],
                    s_all["p99"],
                    s_all["max"],
                    cost,
                ]
            )
            series[label].append((cost, s_all["p99"], s_all["max"], f"{step:g}"))
            raw.append(
                {
                    "step": step,
                    "band_limited": bl,
                    "thin": s_thin,
                    "all": s_all,
                    "us_per_colour": cost,
                }
            )
    d_step = default(colorimetry.film_XYZ, "step")
    d_bl = default(colorimetry.film_XYZ, "band_limited")
    by = {(r["step"], r["band_limited"]): r for r in raw}
    results = {}
    plot_default = None
    d = by.get((d_step, d_bl))
    if d is not None:
        plot_default = (
            d["us_per_colour"],
            d["all"]["p99"],
            f"{d_step:g} nm, {'band-limited' if d_bl else 'point'}",
        )
        results["default_spectral"] = d
    results["spectral_step"] = {
        "reference_step_nm": ref_step,
        "reference_check": ref_agreement,
        "rows": raw,
    }
    img = pareto_plot(
        ctx,
        "knob_spectral_step.png",
        "Spectral step: error vs cost (soap film, t' 0–10 µm)",
        series,
        xlabel="cost per colour (µs, 421-sample grid at 1 nm scale)",
        default=plot_default,
    )
    text = [
        "### 1a. Spectral step, with and without band-limited integration",
        "",
        f"Soap film (Eq. 7) XYZ for {n} optical thicknesses t' in 0–1.5 µm (the table range) "
        f"and {n} in 1.5–10 µm, against a point-sampled reference every {ref_step:g} nm over "
        "360–780 nm. The reference is checked against the band-limited integration at the "
        f"same step: ΔE2000 max {fmt(ref_agreement['max'])} (mean {fmt(ref_agreement['mean'])}). "
        "Cost is the best-of-runs wall time of `film_XYZ` per colour for 256 thicknesses.",
        "",
        table(
            [
                "step (nm)",
                "integration",
                "0–1.5 µm mean",
                "p99",
                "max",
                "0–10 µm mean",
                "p99",
                "max",
                "µs / colour",
            ],
            rows,
        ),
        "",
        f"Default (from `film_XYZ`'s signature): step = {d_step} nm, band_limited = {d_bl}.",
        "",
        img,
    ]
    return Section(
        "\n".join(text), results, {"spectral_step": _headline(ref_step, by, d_step, d_bl)}
    )


def _headline(ref_step, by, d_step, d_bl):
    """The default step's maxima, point sampling at that step, and the coarsest step."""
    d = by.get((d_step, d_bl))
    if d is None:
        return None
    point = by.get((d_step, False))
    coarse = max(step for step, _ in by)
    pair = (by.get((coarse, False)), by.get((coarse, True)))
    return {
        "reference_step_nm": ref_step,
        "default": {"step": d_step, "thin_max": d["thin"]["max"], "all_max": d["all"]["max"]},
        "point_sampled_at_default": None
        if point is None
        else {"thin_max": point["thin"]["max"], "all_max": point["all"]["max"]},
        "coarsest": None
        if None in pair
        else {
            "step": coarse,
            "point_all_max": pair[0]["all"]["max"],
            "band_limited_all_max": pair[1]["all"]["max"],
        },
    }
