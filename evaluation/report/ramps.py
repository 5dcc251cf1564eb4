"""Saturation ramps through the views: the compression keeps the shading up to its limit,
the clip is flat past the boundary (shared by ``benchmarks/bench_compress.py`` and the
report's gamut section).

Ramps at fixed Y and hue from the grey towards monochromatic 450-650 nm, to 2.1 boundary
distances or the spectral colour itself where that is nearer, through the baked config's
views; the output's normalised distance to the boundary is measured along the input's
ray (:func:`ocio_thinfilm.colour.compress.boundary_distance`'s formula from the input's
grey: the constant-lightness views keep Y, ACES 1.3 does not).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ocio_thinfilm import registry

ROOT = Path(__file__).resolve().parents[2]
#: The views compared, left to right: the registry's views of these kinds.
VIEWS = tuple(registry.view_of_kind(kind).name for kind in ("compress", "clip", "aces"))


def ramps(display="sRGB", Y=0.2, n=129):
    """Ramps towards monochromatic 450-650 nm at luminance Y: XYZ (k, n, 3), the input
    distance (k, n) and the wavelengths."""
    from ocio_thinfilm.colour import colorimetry, compress
    from ocio_thinfilm.colour.compress import boundary_distance

    wl = np.arange(450.0, 651.0, 25.0)
    out, dist = [], []
    for target in colorimetry.XYZ_to_RGB(colorimetry.spectral_locus_XYZ(Y, wl), display):
        grey = np.full(3, Y)
        d_target = float(boundary_distance(target, display))
        # to 2.1 boundary distances, or to the spectral colour itself where it is nearer
        # (further out the ramp leaves the real colours: yellow 575 nm is at 1.2)
        t = np.linspace(0.0, min(1.6 * compress.LIMIT / d_target, 1.0), n)
        out.append(colorimetry.RGB_to_XYZ(grey + t[:, None] * (target - grey), display))
        dist.append(t * d_target)
    return np.array(out), np.array(dist), wl


def _ray_distance(rgb, grey):
    """Boundary distance of display-linear ``rgb`` measured along its own ray from the
    grey ``grey`` (the views keep Y, ACES does not: its output measured from the input's
    grey)."""
    from ocio_thinfilm.colour.compress import _distance

    return _distance(np.asarray(rgb, dtype=np.float64).T, np.asarray(grey, dtype=np.float64))


def ramp_table(display="sRGB"):
    import PyOpenColorIO as ocio

    from ocio_thinfilm.colour import colorimetry, compress

    cfg = ocio.Config.CreateFromFile(str(ROOT / "configs" / "thinfilm" / "config.ocio"))
    XYZ, dist, wl = ramps(display)
    result = {"display": display, "wavelengths": wl.tolist(), "input": dist.tolist()}
    rgb_out = {}
    for view in VIEWS:
        proc = cfg.getProcessor("CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD)
        dec = cfg.getProcessor(
            cfg.getDisplayViewColorSpaceName(display, view), "CIE-XYZ-D65"
        ).getDefaultCPUProcessor()
        px = np.ascontiguousarray(XYZ.reshape(-1, 3), dtype=np.float32).copy()
        proc.getDefaultCPUProcessor().applyRGB(px)
        rgb_out[view] = px.reshape(XYZ.shape).copy()
        dec.applyRGB(px)  # display code values -> display-referred XYZ
        rgb = colorimetry.XYZ_to_RGB(px.astype(np.float64), display)
        grey = (XYZ.reshape(-1, 3)[:, 1]).astype(np.float64)
        out = _ray_distance(rgb, grey).reshape(dist.shape)
        rising = (dist > 0.05) & (dist < compress.LIMIT - 0.02)
        steps = np.diff(out, axis=1)[rising[:, 1:] & rising[:, :-1]]
        past = dist > 1.02  # (every ramp but 575 nm reaches 1.3)
        result[view] = dict(
            output=out.tolist(),
            min_step=float(steps.min()),
            strictly_rising=bool(steps.min() > 0.0),
            spread_past_boundary=float(np.ptp(out[past])),
            dY=float(np.abs(px[:, 1].reshape(dist.shape) - XYZ[..., 1]).max()),
        )
    return result, rgb_out


def plot(result, rgb_out):
    """The figure: output against input distance per view, and the ramps as strips."""
    import matplotlib.pyplot as plt

    from ocio_thinfilm.colour import compress

    dist = np.array(result["input"])
    fig = plt.figure(figsize=(11, 7.5))
    grid = fig.add_gridspec(2, 3, height_ratios=[2.2, 1.0])
    x = np.linspace(0, 2.1, 400)
    for k, view in enumerate(VIEWS):
        ax = fig.add_subplot(grid[0, k])
        out = np.array(result[view]["output"])
        for i, wl in enumerate(result["wavelengths"]):
            ax.plot(dist[i], out[i], lw=1.2, label=f"{wl:.0f} nm")
        if k == 0:
            ax.plot(x, compress.compression_curve(x), "k--", lw=0.8, label="analytic")
        ax.axvline(1.0, color="0.6", lw=0.6)
        ax.axvline(compress.LIMIT, color="0.6", lw=0.6, ls=":")
        ax.set_title(view, fontsize=10)
        ax.set_xlabel("input distance to the boundary (1 = on it)")
        if k == 0:
            ax.set_ylabel("output distance along the same ray")
            ax.legend(fontsize=7, loc="lower right")
        ax.set_xlim(0, 2.1)
        ax.set_ylim(0, 1.12)
        strip = fig.add_subplot(grid[1, k])
        for i in range(len(result["wavelengths"])):  # each ramp over its own distances
            strip.imshow(
                np.clip(rgb_out[view][i : i + 1], 0, 1),
                aspect="auto",
                interpolation="nearest",
                extent=(0, float(dist[i].max()), i + 1, i),
            )
        strip.set_xlim(0, 2.1)
        strip.set_ylim(len(result["wavelengths"]), 0)
        strip.set_yticks(
            np.arange(len(result["wavelengths"])) + 0.5,
            [f"{w:.0f}" for w in result["wavelengths"]],
            fontsize=7,
        )
        strip.set_xlabel("input distance (ramps from grey, Y = 0.2, sRGB)")
    fig.suptitle(
        "Saturation ramps through the views: the compression keeps the shading "
        "up to the limit, the clip is flat past the boundary",
        fontsize=11,
    )
    fig.tight_layout()
    return fig
