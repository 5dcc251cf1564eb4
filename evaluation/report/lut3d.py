"""Section 1c: the 3D clip LUT's size, domain/shaper and interpolation."""

from __future__ import annotations

import time

import numpy as np

from evaluation.report.context import Section
from evaluation.report.datasets import (
    INTERFERENCE,
    MIXTURES,
    lut_test_sets,
)
from evaluation.report.measure import (
    default,
    ocio_apply_speed,
    ocio_cpu,
    stats,
    table,
)
from evaluation.report.plots import pareto_plot
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import clip_lut, ocio_ops


def _walk(transform):
    """Yield every leaf transform of (nested) GroupTransforms."""
    import PyOpenColorIO as ocio

    if isinstance(transform, ocio.GroupTransform):
        for child in transform:
            yield from _walk(child)
    else:
        yield transform


def _with_interp(transform, interp):
    """``transform`` with every Lut3D in it set to ``interp``."""
    import PyOpenColorIO as ocio

    for t in _walk(transform):
        if isinstance(t, ocio.Lut3DTransform):
            t.setInterpolation(interp)
    return transform


def _naive_lut_transform(display, size, interp):
    """Baseline: a Lut3D over XYZ / white in [0, 1]^3, no shaper (clamps outside)."""
    import PyOpenColorIO as ocio

    W = colorimetry.white_XYZ(display)
    g = np.linspace(0.0, 1.0, size)
    U = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1)  # [r][g][b] = (X, Y, Z)/W
    rgb = clip.clip_XYZ(U * W, display) @ colorimetry.matrix_XYZ_to_RGB(display).T
    lut = ocio.Lut3DTransform()
    lut.setGridSize(size)
    lut.setInterpolation(interp)
    lut.setData(np.ascontiguousarray(rgb, dtype=np.float32).ravel())
    scale = ocio_ops.matrix(np.diag(1.0 / W))
    return ocio.GroupTransform([scale, lut, ocio.RangeTransform(0.0, 1.0, 0.0, 1.0)])


def _rgb_domain_lut_transform(display, size, interp, lo, hi):
    """Variant: a Lut3D over display-linear RGB in [lo, hi]^3 (affine range shaper)."""
    import PyOpenColorIO as ocio

    M = colorimetry.matrix_XYZ_to_RGB(display)
    g = np.linspace(lo, hi, size)
    U = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1)
    rgb = clip.clip_RGB(U, display)
    lut = ocio.Lut3DTransform()
    lut.setGridSize(size)
    lut.setInterpolation(interp)
    lut.setData(np.ascontiguousarray(rgb, dtype=np.float32).ravel())
    m = np.eye(4)
    m[:3, :3] = M / (hi - lo)
    shaper = ocio.MatrixTransform([float(v) for v in m.ravel()], [-lo / (hi - lo)] * 3 + [0.0])
    return ocio.GroupTransform([shaper, lut, ocio.RangeTransform(0.0, 1.0, 0.0, 1.0)])


def section(ctx) -> Section:
    """The clip baked into Lut3Ds of several kinds against the analytic ``clip_XYZ``."""
    import PyOpenColorIO as ocio

    q = ctx.quick
    display = "sRGB"
    M = colorimetry.matrix_XYZ_to_RGB(display)
    Minv = np.linalg.inv(M)
    d_size = default(clip_lut.clip_transform, "size")
    sizes = sorted({17, d_size}) if q else sorted({17, 33, 65, d_size})
    sets = lut_test_sets(q)
    refs = {k: clip.clip_XYZ(v, display) for k, v in sets.items()}
    allx = np.concatenate(list(sets.values()))
    rgb_int = sets[INTERFERENCE] @ M.T
    lo = float(np.floor(rgb_int.min() * 4) / 4)
    hi = float(np.ceil(rgb_int.max() * 4) / 4)
    h, w = (256, 256) if q else (512, 1024)
    img = np.resize(allx, (h * w, 3)).astype(np.float32)
    interps = {"tetrahedral": ocio.INTERP_TETRAHEDRAL, "linear": ocio.INTERP_LINEAR}
    shipped = "two passes (shipped)"
    domains = {shipped: lambda size, it: _with_interp(clip_lut.clip_transform(display, size), it)}
    domains.update(
        {
            f"display RGB [{lo:g}, {hi:g}]³, affine": lambda size, it: _rgb_domain_lut_transform(
                display, size, it, lo, hi
            ),
            "XYZ/white [0, 1], no shaper": lambda size, it: _naive_lut_transform(display, size, it),
        }
    )
    rows, series, raw = [], {}, []
    results = {}
    default_pt = None
    for d_name, make in domains.items():
        for i_name, interp in interps.items():
            key = f"{d_name}, {i_name}"
            series[key] = []
            for size in sizes:
                t_start = time.perf_counter()
                try:
                    tf = make(size, interp)
                except ValueError as error:  # e.g. a size the domain does not support
                    rows.append([d_name, i_name, size] + ["–"] * 6 + [f"n/a: {error}", "–"])
                    continue
                bake = time.perf_counter() - t_start
                st = {}
                for s_name, xyz in sets.items():
                    out = ocio_ops.apply(tf, xyz).astype(np.float64) @ Minv.T
                    st[s_name] = stats(colorimetry.delta_E2000(out, refs[s_name]))
                mpix = ocio_apply_speed(ocio_cpu(tf), img)
                a, b = st[INTERFERENCE], st[MIXTURES]
                rows.append(
                    [
                        d_name,
                        i_name,
                        size,
                        a["mean"],
                        a["p99"],
                        a["max"],
                        b["mean"],
                        b["p99"],
                        b["max"],
                        bake,
                        mpix,
                    ]
                )
                series[key].append((1.0 / mpix, a["p99"], a["max"], size))
                raw.append(
                    {
                        "domain": d_name,
                        "interp": i_name,
                        "size": size,
                        "stats": st,
                        "bake_s": bake,
                        "apply_Mpix_s": mpix,
                    }
                )
                if d_name == shipped and i_name == "tetrahedral" and size == d_size:
                    default_pt = (1.0 / mpix, a["p99"], f"two {size}³ LUTs, tetrahedral")
                    results["default_lut3d"] = raw[-1]
    results["lut3d"] = {"rows": raw, "rgb_domain": [lo, hi]}
    img_md = pareto_plot(
        ctx,
        "knob_lut3d.png",
        "3D clip LUT: error vs apply cost (interference colours)",
        series,
        xlabel="apply cost through OCIO (s / Mpixel, one thread)",
        default=default_pt,
    )
    n_int = sets[INTERFERENCE].shape[0]
    n_real = sets[MIXTURES].shape[0]
    return Section(
        "\n".join(
            [
                "### 1c. 3D LUT size, domain/shaper and interpolation",
                "",
                "The constant-lightness clip into sRGB baked into a Lut3D, applied through OCIO "
                "(float32), against the analytic `clip_XYZ` (float64). Test colours: "
                f"{n_int} interference colours (soap film, film on glass, Morpho) and {n_real} "
                "spectral mixtures (random mixtures of up to three spectral colours at Y "
                "0.01–0.99: extreme inputs, most of them outside the object-colour solid and far "
                "outside sRGB). Domains: the shipped `clip_lut.clip_transform` (the faces "
                "through black "
                "over a projective chromaticity chart and Y, then the faces through white over "
                "encoded display RGB; see `clip_lut.ClipLUT`); "
                "display-linear RGB over the box that holds the interference colours, with an "
                "affine "
                "shaper (spectral mixtures beyond it are clamped by the LUT); "
                "and the naive XYZ/white cube without shaper. Bake = building the transform "
                "(the shipped LUT's vertex computation is cached per size, so only its first "
                f"interpolation row pays it); apply = OCIO CPU, one thread, {w}×{h} pixels.",
                "",
                table(
                    [
                        "domain",
                        "interp",
                        "size",
                        "interf. mean",
                        "p99",
                        "max",
                        "mixtures mean",
                        "p99",
                        "max",
                        "bake (s)",
                        "Mpixel/s",
                    ],
                    rows,
                ),
                "",
                f"Default (from the signature of `clip_transform`): two {d_size}³ LUTs, "
                "tetrahedral.",
                "",
                img_md,
            ]
        ),
        results,
        {"lut3d": _headline(results.get("default_lut3d"), raw)},
    )


def _headline(d, raw):
    """The shipped default's errors and speed, and the largest tetrahedral size above it."""
    if d is None:
        return None
    a, b = d["stats"][INTERFERENCE], d["stats"][MIXTURES]
    larger = [
        r
        for r in raw
        if r["interp"] == "tetrahedral" and r["domain"] == d["domain"] and r["size"] > d["size"]
    ]
    best = larger[-1] if larger else None
    return {
        "size": d["size"],
        "domain": d["domain"],
        "apply_Mpix_s": d["apply_Mpix_s"],
        "interference": {"mean": a["mean"], "p99": a["p99"], "max": a["max"]},
        "mixtures": {"p99": b["p99"], "max": b["max"]},
        "larger": None
        if best is None
        else {
            "size": best["size"],
            "p99": best["stats"][INTERFERENCE]["p99"],
            "max": best["stats"][INTERFERENCE]["max"],
            "apply_Mpix_s": best["apply_Mpix_s"],
        },
    }
