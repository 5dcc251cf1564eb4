"""Section 2a: gamut-mapping peers on the same colours (and their speed), and the
saturation ramps through the clip and the compression views."""

from __future__ import annotations

import numpy as np

from evaluation.report import ramps
from evaluation.report.context import Section
from evaluation.report.measure import (
    best_time,
    ocio_apply_speed,
    ocio_cpu,
    stats,
    table,
)
from evaluation.report.peers import oklch_gamut_map_RGB
from ocio_thinfilm.colour import clip, colorimetry, compress
from ocio_thinfilm.lut import ocio_ops, view_transforms

#: The views compared through OCIO: id -> (label in the speed table, view name).
VIEWS = {
    "aces_gamut_compression": ("ACES gamut compression view (OCIO)", "ACES Gamut Compression"),
    "constant_lightness_clip": ("constant-lightness clip view (OCIO)", "Constant-Lightness Clip"),
    "constant_lightness_compress": (
        "constant-lightness compress view (OCIO)",
        "Constant-Lightness Compress",
    ),
}


def _datasets(q):
    """id -> (label, XYZ) of the colour sets."""
    wl = np.arange(380.0, 701.0, 2.0 if q else 1.0)
    t = np.linspace(0.0, 1500.0, 301 if q else 1501)
    return {
        "spectral_locus": ("spectral locus (Y = 0.2)", colorimetry.spectral_locus_XYZ(0.2, wl)),
        "soap_film": ("soap film (Eq. 7, t' 0–1.5 µm)", colorimetry.film_XYZ(t)),
        "film_on_glass": (
            "film on glass (Eq. 8, t' 0–1.5 µm)",
            colorimetry.film_XYZ(t, kind="no-phase-change"),
        ),
        "morpho": (
            "Morpho (Eq. 9+14, 0–89°)",
            colorimetry.morpho_XYZ(np.linspace(0, 89, 90 if q else 357)),
        ),
    }


def _methods(display):
    """id -> (label, fn(rgb), how it runs, fraction of the speed image it is timed on)."""
    return {
        "constant_lightness_clip": (
            "constant-lightness clip",
            lambda rgb: clip.clip_RGB(rgb, display),
            "numpy",
            1,
        ),
        "constant_lightness_compress": (
            "constant-lightness compress (0.8 / 1.3)",
            lambda rgb: compress.compress_RGB(rgb, display),
            "numpy",
            1,
        ),
        "clamp": ("per-channel clamp", clip.clamp_RGB, "numpy", 1),
        "aces": (
            "ACES 1.3 gamut compression (+clamp)",
            lambda rgb: clip.aces_gamut_compress_RGB(rgb).astype(np.float64),
            "clip.aces_gamut_compress_RGB: OCIO processor built per call + numpy clamp",
            1,
        ),
        "oklch": (
            "OKLCh chroma reduction (CSS Color 4)",
            lambda rgb: oklch_gamut_map_RGB(rgb, display),
            "numpy",
            8,
        ),
    }


def _lab(xyz):
    import colour

    return colour.XYZ_to_Lab(xyz, colour.CCS_ILLUMINANTS[colorimetry.DEFAULT_OBSERVER]["D65"])


def _hue_shift_deg(lab1, lab0):
    """Signed hue difference h_ab(lab1) - h_ab(lab0) in degrees, in (-180, 180]."""
    return np.degrees(
        np.angle(
            np.exp(
                1j
                * (np.arctan2(lab1[..., 2], lab1[..., 1]) - np.arctan2(lab0[..., 2], lab0[..., 1]))
            )
        )
    )


def _ocio_speeds(img, display):
    """Mpixel/s through OCIO: the ACES FixedFunction, a Range clamp and the two views
    (display-linear RGB in, sRGB code values out). Returns (label -> speed, view id ->
    speed or None if it failed)."""
    import PyOpenColorIO as ocio

    speeds = {}
    aces = ocio.FixedFunctionTransform(
        ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13, list(clip.ACES_GAMUT_COMP13_PARAMS)
    )
    rng = ocio.RangeTransform(0.0, 1.0, 0.0, 1.0)
    speeds["ACES 1.3 gamut compression (OCIO FixedFunction)"] = ocio_apply_speed(
        ocio_cpu(aces), img
    )
    speeds["per-channel clamp (OCIO Range)"] = ocio_apply_speed(ocio_cpu(rng), img)
    M = colorimetry.matrix_XYZ_to_RGB(display)
    to_xyz = ocio_ops.matrix(np.linalg.inv(M))
    views = {}
    for view_id, (label, view) in VIEWS.items():
        views[view_id] = None
        try:
            group = ocio.GroupTransform([to_xyz, view_transforms.view_transform(display, view)])
            speeds[label] = views[view_id] = ocio_apply_speed(ocio_cpu(group), img)
        except Exception as error:  # noqa: BLE001 -- reported, not hidden
            speeds[f"{label}: failed: {error}"] = float("nan")
    return speeds, views


def section(ctx) -> Section:
    """Four gamut mappings into sRGB: lightness, hue and ΔE2000 kept, and speed."""
    import colour
    import matplotlib.pyplot as plt

    display = "sRGB"
    q = ctx.quick
    M = colorimetry.matrix_XYZ_to_RGB(display)
    Minv = np.linalg.inv(M)
    sets = _datasets(q)
    methods = _methods(display)
    rows, raw, soap = [], {}, {}
    mapped_locus = {}
    for set_id, (set_name, xyz) in sets.items():
        rgb = xyz @ M.T
        outside = ~clip.in_gamut(rgb)
        lab0 = _lab(xyz)
        raw[set_name] = {"fraction_outside": float(outside.mean())}
        for m_name, fn, _, _ in methods.values():
            out = np.asarray(fn(rgb), dtype=np.float64)
            if set_id == "spectral_locus":
                mapped_locus[m_name] = out
            xyz_m = out @ Minv.T
            lab1 = _lab(xyz_m)
            sel = outside
            dL = np.abs(lab1[sel, 0] - lab0[sel, 0])
            c0 = np.hypot(lab0[sel, 1], lab0[sel, 2])
            dh = np.abs(_hue_shift_deg(lab1[sel], lab0[sel]))[c0 > 5.0]
            de = colorimetry.delta_E2000(xyz_m[sel], xyz[sel])
            still_out = float((~clip.in_gamut(out, 1e-6)).mean())
            r = {
                "dL_mean": float(dL.mean()) if dL.size else 0.0,
                "dL_max": float(dL.max()) if dL.size else 0.0,
                "dh_mean": float(dh.mean()) if dh.size else 0.0,
                "dh_max": float(dh.max()) if dh.size else 0.0,
                "dE": stats(de),
                "left_out_of_gamut": still_out,
            }
            raw[set_name][m_name] = r
            if set_id == "soap_film":
                soap[m_name] = {
                    "dL_max": r["dL_max"],
                    "dh_mean": r["dh_mean"],
                    "dE_mean": r["dE"]["mean"],
                }
            rows.append(
                [
                    set_name,
                    f"{100 * outside.mean():.0f} %",
                    m_name,
                    r["dL_mean"],
                    r["dL_max"],
                    r["dh_mean"],
                    r["dh_max"],
                    r["dE"]["mean"],
                    r["dE"]["max"],
                ]
            )
    # Throughput, numpy and OCIO, on one image of interference colours.
    h, w = (256, 512) if q else (1080, 1920)
    img = np.resize(sets["soap_film"][1] @ M.T, (h * w, 3)).astype(np.float32)
    speed = {}
    for m_name, fn, how, fraction in methods.values():
        sub = img[: (h * w) // fraction]
        sec = best_time(lambda fn=fn, sub=sub: fn(sub), repeat=2, min_time=0.05, max_calls=3)
        speed[f"{m_name} ({how})"] = sub.shape[0] / sec / 1e6
    ocio_speed, view_speed = _ocio_speeds(img, display)
    speed.update(ocio_speed)
    ref = speed.get("ACES 1.3 gamut compression (OCIO FixedFunction)")
    srows = [[k, v, (v / ref) if ref else None] for k, v in speed.items()]
    results = {"gamut": {"metrics": raw, "throughput_Mpix_s": speed, "image": [w, h]}}
    headline = {"soap_film_outside": soap, "view_Mpix_s": view_speed}

    # Figure: the spectrum through each method (the paper's Figure 4) + hue shift.
    locus = sets["spectral_locus"][1]
    wl = np.arange(380.0, 701.0, 2.0 if q else 1.0)
    fig, axes = plt.subplots(
        len(methods) + 1,
        1,
        figsize=(8, 5.5),
        sharex=True,
        gridspec_kw={"height_ratios": [1] * len(methods) + [3]},
    )
    # axes has one row more than the methods: the hue-shift plot below
    for ax, (m_name, out) in zip(axes, mapped_locus.items(), strict=False):
        enc = colour.cctf_encoding(np.clip(out, 0, 1), function="sRGB")
        ax.imshow(enc[None, :, :], aspect="auto", extent=(wl[0], wl[-1], 0, 1))
        ax.set_yticks([])
        ax.set_ylabel(m_name, rotation=0, ha="right", va="center", fontsize=7)
    lab0 = _lab(locus)
    for m_name, out in mapped_locus.items():
        axes[-1].plot(wl, _hue_shift_deg(_lab(out @ Minv.T), lab0), label=m_name)
    axes[-1].set_ylabel("hue shift Δh_ab (°)")
    axes[-1].set_xlabel("wavelength (nm), spectral colours at Y = 0.2")
    axes[-1].legend(fontsize=7)
    axes[-1].grid(alpha=0.3)
    fig.suptitle("Gamut mapping of the spectrum into sRGB")
    img_md = ctx.savefig(fig, "peers_gamut_spectrum.png")
    ramp, ramp_rgb = ramps.ramp_table(display)
    ramp_md = ctx.savefig(ramps.plot(ramp, ramp_rgb), "compress_ramps.png")
    results["ramps"] = {
        view: {k: v for k, v in ramp[view].items() if k != "output"} for view in ramps.VIEWS
    }
    text = [
        "### 2a. Gamut mapping peers",
        "",
        "Into sRGB, from the unclipped colour. Statistics over the colours that start outside "
        "the gamut; ΔL* and Δh_ab in CIELAB (D65), Δh only where C*ab > 5. The ACES 1.3 "
        "compression (OCIO `ACES_GamutComp13`, applied to display-linear RGB) is followed by a "
        "clamp; the OKLCh method is the CSS Color 4 binary search (JND 0.02, ε 1e-4) implemented "
        "in `evaluation/report/peers.py` with colour-science's Oklab. Per that spec, colours "
        "whose Oklab L is ≥ 1 map "
        "to white: at Y = 0.2 the deep-blue spectral colours have L > 1 (their S-cone response is "
        "huge), which is what drives its hue and lightness figures on the spectral locus.",
        "",
        table(
            [
                "colours",
                "outside",
                "method",
                "ΔL* mean",
                "ΔL* max",
                "Δh mean (°)",
                "Δh max (°)",
                "ΔE2000 mean",
                "ΔE2000 max",
            ],
            rows,
        ),
        "",
        f"Throughput on a {w}×{h} float32 image of soap-film colours (Mpixel/s, one thread; "
        "ratio to the ACES compression through OCIO in this run). The OKLCh search has no OCIO "
        "equivalent (an iterative, per-pixel search), so only its numpy speed is listed; the "
        "constant-lightness clip runs in OCIO as the shipped 3D LUT (display RGB → XYZ → clip).",
        "",
        table(["method", "Mpixel/s", "× ACES (OCIO)"], srows),
        "",
        img_md,
        "",
        "Saturation ramps at Y = 0.2 from the grey towards monochromatic 450–650 nm (to 2.1 "
        "boundary distances or the spectral colour), through the config's views: the output's "
        "distance to the boundary along the same ray. The compression rises up to its limit "
        "(1.3), the clip is flat past the boundary, ACES 1.3 compresses per channel (not along "
        "the ray; it changes Y).",
        "",
        table(
            [
                "view",
                "strictly rising to the limit",
                "smallest step",
                "spread past the boundary",
                "max |ΔY|",
            ],
            [
                [view, str(r["strictly_rising"]), r["min_step"], r["spread_past_boundary"], r["dY"]]
                for view, r in results["ramps"].items()
            ],
        ),
        "",
        ramp_md,
    ]
    return Section("\n".join(text), results, {"gamut": headline})
