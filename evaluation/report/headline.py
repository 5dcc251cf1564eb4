"""The headline of the report: one line per section, built from the facts each section
stored under an explicit id in ``report.json["headline"]`` (see :class:`.context.Section`).

Each ``_<id>`` function formats one section's facts; a section without facts (None)
gives no line. :func:`headline_lines` works from ``report.json`` alone.
"""

from __future__ import annotations

from evaluation.report.measure import fmt

__all__ = ["headline_lines"]


def _machine(m):
    return [
        f"- Machine: {m.get('cpu')}, {m.get('cores')} usable cores, "
        f"{m.get('memory_GiB', '?')} GiB; Python {m.get('python')}, OCIO "
        f"{m.get('OpenColorIO')}, OIIO {m.get('OpenImageIO')}, colour {m.get('colour-science')}."
    ]


def _spectral_step(s):
    d = s["default"]
    text = (
        f"- Spectral step, soap film against a {s['reference_step_nm']:g} nm reference "
        f"(ΔE2000 max over t' 0–1.5 µm / 0–10 µm): default {d['step']:g} nm band-limited "
        f"{fmt(d['thin_max'])} / {fmt(d['all_max'])}"
    )
    pt = s.get("point_sampled_at_default")
    if pt:
        text += f"; point-sampled at {d['step']:g} nm {fmt(pt['thin_max'])} / {fmt(pt['all_max'])}"
    c = s.get("coarsest")
    if c:
        text += (
            f"; at {c['step']:g} nm point sampling aliases to {fmt(c['point_all_max'])}"
            f" where band-limiting gives {fmt(c['band_limited_all_max'])}"
        )
    return [text + "."]


def _table1d(t):
    return [
        f"- 1D thickness table (default {t['size']} entries, log spacing): ΔE2000 max "
        f"{fmt(t['thin_max'])} over t' 0–1.5 µm, {fmt(t['all_max'])} over its whole range."
    ]


def _lut3d(s):
    a, b, big = s["interference"], s["mixtures"], s.get("larger")
    return [
        f"- 3D clip LUT (default {s['size']}³, {s['domain']}, tetrahedral) against the "
        f"analytic clip: interference colours ΔE2000 mean {fmt(a['mean'])} / p99 "
        f"{fmt(a['p99'])} / max {fmt(a['max'])}; spectral mixtures p99 {fmt(b['p99'])} / max "
        f"{fmt(b['max'])}"
        + (
            f"; {big['size']}³ gives p99 {fmt(big['p99'])} / max {fmt(big['max'])} at "
            f"{fmt(big['apply_Mpix_s'])} vs {fmt(s['apply_Mpix_s'])} Mpixel/s."
            if big
            else "."
        )
    ]


def _analytic_vs_lut(paths):
    return [
        "- Thickness image → clipped RGB, one thread: "
        + "; ".join(
            f"{x['path']}: {fmt(x['Mpix_s'])} Mpixel/s, ΔE2000 max {fmt(x['dE_max'])}"
            for x in paths
        )
        + "."
    ]


def _gamut(g):
    out = []
    soap = g.get("soap_film_outside")
    if soap:
        out.append(
            "- Gamut mapping of the soap-film colours outside sRGB (ΔL* max / Δh mean / "
            "ΔE2000 mean from the unclipped colour): "
            + "; ".join(
                f"{k}: {fmt(v['dL_max'])} / {fmt(v['dh_mean'])}° / {fmt(v['dE_mean'])}"
                for k, v in soap.items()
            )
            + "."
        )
    views = g.get("view_Mpix_s") or {}
    ref, lut = views.get("aces_gamut_compression"), views.get("constant_lightness_clip")
    if ref and lut:
        out.append(
            f"- Through OCIO the Constant-Lightness Clip view runs at "
            f"{fmt(lut / ref)}× the speed of the ACES Gamut Compression view in "
            "the same run (soap-film colours; three more data sets in "
            "benchmarks/bench_gamut_map.py)."
        )
    return out


def _gaussian_fit(g):
    a, w = g["all"], g["worst_band"]
    return [
        f"- Belcour & Barla Gaussian-fit CMFs (MaterialX, glTF) vs exact integration, OPD "
        f"0–10 µm: ΔE2000 mean {fmt(a['belcour_barla_mean'])}, max "
        f"{fmt(a['belcour_barla_max'])} (worst band {w['opd_um'][0]:g}–"
        f"{w['opd_um'][1]:g} µm, mean {fmt(w['belcour_barla_mean'])}); ours "
        f"(default step) max {fmt(a['ours_max'])}."
    ]


def _tmm(t):
    return [
        f"- Closed-form Airy film vs colour-science TMM: max |ΔR| "
        f"{fmt(t['single_film_max_abs_dR'])}, {fmt(t['airy_speedup_vs_colour'])}× faster; "
        f"multilayer max |ΔR| {fmt(t['multilayer_max_abs_dR'])}."
    ]


def _films(f):
    return [
        f"- Users' films (exact stack model): tables of {f['size']} entries within ΔE2000 "
        f"max {fmt(f['dE_max'])} of colour-science's transfer-matrix method; the Airy sum "
        f"{fmt(f['transfer_matrix_over_airy'])}× faster than the transfer-matrix recursion "
        f"for one film."
    ]


def _stability(s):
    bad = s["not_as_expected"]
    return [
        f"- Stability: {s['rows'] - len(bad)} of {s['rows']} extreme cases as expected"
        + (f"; not: {'; '.join(bad)}." if bad else ".")
    ]


def _throughput(t):
    w, h = t["image"]
    c1 = t["copy_1_Mpix_s"]
    return [
        f"- {w}×{h} image, {t['view']} view: "
        f"{fmt(t['ocio_1_Mpix_s'])} Mpixel/s on one thread (OCIO), {fmt(t['oiio_all_Mpix_s'])} on "
        f"all {t['threads']} threads (OIIO), against a memory copy at {fmt(c1)} "
        f"Mpixel/s: {fmt(t['ocio_1_Mpix_s'] / c1 * 100)} % of the bandwidth bound."
    ]


#: Headline id -> its line(s), in the order they are printed.
LINES = {
    "machine": _machine,
    "spectral_step": _spectral_step,
    "table1d": _table1d,
    "lut3d": _lut3d,
    "analytic_vs_lut": _analytic_vs_lut,
    "gamut": _gamut,
    "gaussian_fit": _gaussian_fit,
    "tmm": _tmm,
    "films": _films,
    "stability": _stability,
    "throughput": _throughput,
}


def headline_lines(facts: dict) -> list[str]:
    """The headline's markdown lines.

    Parameters
    ----------
    facts : dict
        ``report.json["headline"]``: headline id -> that section's facts (or None).

    Returns
    -------
    list of str
        One bullet per section with facts, in the order of :data:`LINES`.
    """
    out = []
    for key, lines in LINES.items():
        if facts.get(key):
            out += lines(facts[key])
    return out
