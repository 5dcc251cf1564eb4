"""The soft constant-lightness compression: the analytic map (colour.compress) against
an independent ray-marching reference, and the config's ``Constant-Lightness Compress``
views (OCIO's CPU processor) against the analytic map on the clip's test sets.

Independent of the code under test: luminance weights and gamut test from
colour-science's RGB_COLOURSPACES, the boundary found by bisection along the ray, the
ACES 1.3 curve written out from S-2020-001's formula.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from evaluation.colours import half_way_colours, object_colours
from evaluation.truth import colour_science_RGB_to_XYZ
from evaluation.views import (
    OPTIMIZATION_LEVELS,
    apply_view,
    decode_display,
    error_stats,
    view_codes,
)
from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry, compress
from ocio_thinfilm.lut import compress_lut

ocio = pytest.importorskip("PyOpenColorIO")

DISPLAYS = clip.DISPLAYS
VIEW = "Constant-Lightness Compress"


def _weights(display):
    """Luminance weights of ``display`` from colour-science's primaries and white,
    Bradford to D65 for a DCI white (independent of our matrices)."""
    return colour_science_RGB_to_XYZ(display)[1]


def _aces_curve(d, thr, lim, p=1.2):
    """S-2020-001 'compress': thr + (d - thr) / (1 + ((d - thr) / s) ** p) ** (1 / p),
    s = (lim - thr) / (((1 - thr) / (lim - thr)) ** -p - 1) ** (1 / p)."""
    s = (lim - thr) / (((1.0 - thr) / (lim - thr)) ** -p - 1.0) ** (1.0 / p)
    x = d - thr
    with np.errstate(invalid="ignore"):  # x < 0 where d <= thr (not used there)
        return np.where(d > thr, thr + x / (1.0 + (x / s) ** p) ** (1.0 / p), d)


def _ray_distance(rgb, w, steps=80):
    """Normalised boundary distance by bisection: the largest t with grey + t (c - grey)
    inside the unit cube, d = 1 / t."""
    rgb = np.asarray(rgb, dtype=np.float64)
    Y = rgb @ w
    lo, hi = np.zeros(len(rgb)), np.full(len(rgb), 1e6)
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        p = Y[:, None] + mid[:, None] * (rgb - Y[:, None])
        inside = np.all((p >= 0.0) & (p <= 1.0), axis=1)
        lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    return 1.0 / lo


def _random_rgb(display, n=4000, seed=0):
    rng = np.random.default_rng(seed)
    w = _weights(display)
    Y = rng.uniform(0.02, 0.97, n)
    direction = rng.normal(size=(n, 3))
    direction -= (direction @ w)[:, None]  # keeps Y
    grey = np.repeat(Y[:, None], 3, axis=1)
    d = _ray_distance(grey + direction, w)  # distance of grey + direction
    scale = rng.uniform(0.0, 2.0, n) / d  # colours from the grey to 2 boundary distances
    return grey + scale[:, None] * direction


# --------------------------------------------------------------------------- #
# The analytic map
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("display", DISPLAYS)
def test_compress_keeps_Y_on_the_ray_and_follows_the_curve(display):
    w = _weights(display)
    rgb = _random_rgb(display)
    out = compress.compress_RGB(rgb, display)
    Y = rgb @ w
    assert np.abs(out @ w - Y).max() < 1e-12
    assert np.all((out >= 0.0) & (out <= 1.0))
    # on the segment from the colour to its grey: out - grey = k (c - grey), 0 < k <= 1
    k = ((out - Y[:, None]) * (rgb - Y[:, None])).sum(1) / ((rgb - Y[:, None]) ** 2).sum(1)
    assert np.abs(out - Y[:, None] - k[:, None] * (rgb - Y[:, None])).max() < 1e-12
    assert np.all((k > 0.0) & (k <= 1.0 + 1e-12))
    d = _ray_distance(rgb, w)
    expected = np.minimum(_aces_curve(d, compress.THRESHOLD, compress.LIMIT), 1.0)
    np.testing.assert_allclose(_ray_distance(out, w), expected, rtol=1e-9, atol=1e-12)
    inside = d <= compress.THRESHOLD
    assert inside.sum() > 500 and np.array_equal(out[inside], rgb[inside])
    beyond = d >= compress.LIMIT
    assert beyond.sum() > 500
    np.testing.assert_allclose(out[beyond], clip.clip_RGB(rgb[beyond], display), atol=1e-12)


def test_curve_is_smooth_at_the_threshold_and_strictly_increasing_to_the_limit():
    thr, lim = compress.THRESHOLD, compress.LIMIT
    eps = 1e-6
    f = compress.compression_curve
    slope = (f(thr + eps) - f(thr)) / eps
    assert abs(slope - 1.0) < 1e-4  # first derivative continuous (1 on both sides)
    d = np.linspace(thr, lim, 10001)
    assert np.all(np.diff(f(d)) > 0.0)
    assert f(lim) == pytest.approx(1.0, abs=1e-12)
    assert np.all(f(np.array([lim + 0.01, 2.0, 1e6, np.inf])) == 1.0)
    np.testing.assert_allclose(f(d), _aces_curve(d, thr, lim), rtol=1e-13)
    y = np.linspace(0.0, 0.999, 500)
    np.testing.assert_allclose(
        f(compress.compression_curve_inverse(y), clipped=False), y, atol=1e-12
    )


@pytest.mark.parametrize("display", DISPLAYS)
def test_compress_edges(display):
    out = compress.compress_RGB(
        np.array(
            [
                [np.nan, 0.2, 0.3],
                [np.inf, 0.0, 0.0],
                [-0.1, -0.2, -0.3],
                [2.0, 2.0, 2.0],
                [1e300, -1e300, 5.0],
            ]
        ),
        display,
    )
    assert np.isnan(out[0]).all()
    assert np.isfinite(out[1:]).all() and np.all((out[1:] >= 0) & (out[1:] <= 1))
    assert out[2].tolist() == [0.0, 0.0, 0.0] and out[3].tolist() == [1.0, 1.0, 1.0]
    assert compress.compress_RGB(np.float32([[1.2, 0.3, 0.1]]), display).dtype == np.float32


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(threshold=1.0), "threshold"),
        (dict(threshold=0.0), "threshold"),
        (dict(limit=1.0), "limit"),
        (dict(power=-1.0), "power"),
    ],
)
def test_compress_parameters_refused(kwargs, name):
    with pytest.raises(ValueError, match=name):
        compress.compress_RGB([0.5, 0.5, 0.5], **kwargs)


@pytest.mark.parametrize("display", DISPLAYS)
def test_lut_factorisation_is_the_analytic_map(display):
    """U o S_w o L o S_b, each evaluated analytically, is compress_RGB (the LUT chain
    only adds interpolation)."""
    rgb = np.concatenate(
        [_random_rgb(display, seed=2), colorimetry.XYZ_to_RGB(object_colours()[:3000], display)]
    )
    a = compress.soft_black_RGB(rgb, display)
    a = clip.clip_black_faces_RGB(a, display)
    a = compress.soft_white_RGB(a, display)
    a = clip.clip_RGB(a, display)
    np.testing.assert_allclose(a, compress.compress_RGB(rgb, display), atol=1e-9)


@pytest.mark.parametrize("display", DISPLAYS)
def test_white_squeeze_nodes_do_not_depend_on_the_last_ulps(display, monkeypatch):
    """S_w's stored codes are the same whatever the last bits of the luminance row
    (another CPU's dot product), at the nodes past white closest to grey too, where a
    ratio of rounding errors would decide (soft_white_RGB takes the formula's limit
    Y + A (1 - Y) for a grey past white; two machines once differed there by up to 192
    codes)."""
    nodes, tops = compress_lut._squeeze_nodes(compress_lut.SOFT_WHITE_SIZE, display)
    C = np.stack(np.meshgrid(*nodes, indexing="ij"), axis=-1).reshape(-1, 3)
    w0 = clip.luminance_weights(display)
    codes = []
    for k in (0, -2, -1, 1, 2):
        w = w0 * (1.0 + k * np.finfo(float).eps)
        monkeypatch.setattr(clip, "luminance_weights", lambda _d, w=w: w)
        params = (compress.THRESHOLD, compress.LIMIT, compress.POWER)
        codes.append(compress_lut._squeeze_codes(C, display, params, tops))
    # the nodes at stake: past white and grey to a shaper sample (the nodes sit on each
    # channel's own shaper samples, so none is exactly grey)
    grey = (np.ptp(C, axis=1) < 1e-3) & (C.min(axis=1) > 1.0)
    assert grey.any()
    for other in codes[1:]:
        np.testing.assert_array_equal(other, codes[0])


# --------------------------------------------------------------------------- #
# The config's views
# --------------------------------------------------------------------------- #
def _apply(cfg, display, XYZ, view=VIEW, optimization=None):
    return apply_view(cfg, display, XYZ, optimization, view=view)


@pytest.fixture(scope="module")
def measured(cfg):
    out = {}
    for display in DISPLAYS:
        w = _weights(display)
        for name, XYZ, code in view_codes(cfg, display, VIEW):
            rgb = decode_display(code, display)
            truth = compress.compress_XYZ(XYZ, display)
            out[display, name] = dict(
                error_stats(truth, colorimetry.RGB_to_XYZ(rgb, display)),
                dY=float(np.abs(rgb @ w - truth[:, 1]).max()),
            )
    return out


@pytest.mark.parametrize("display", DISPLAYS)
@pytest.mark.parametrize("name", ["object", "monochromatic", "ap0", "mixtures"])
def test_view_against_the_analytic_compression(measured, display, name):
    """The clip's accuracy targets: dE2000 p99 <= 0.5, max <= 1.5, |dY| <= 1e-3."""
    m = measured[display, name]
    assert m["p99"] <= 0.5 and m["max"] <= 1.5 and m["dY"] <= 1e-3, m


@pytest.fixture(scope="module")
def half_way(cfg):
    """{display: (input RGB, its grey Y, the view's output RGB)} for colours at most
    half-way from their grey to the boundary along the ray (``half_way_colours``:
    40,000 per display, found with colour-science's primaries), through the view."""
    out = {}
    for display in DISPLAYS:
        rgb, Y, _ = half_way_colours(display)
        got = decode_display(_apply(cfg, display, colorimetry.RGB_to_XYZ(rgb, display)), display)
        out[display] = rgb, Y, got
    return out


@pytest.mark.parametrize("display", DISPLAYS)
def test_half_way_colours_are_left_alone_by_the_analytic_map(half_way, display):
    """Below the threshold (0.8 boundary distances) the compression returns its input."""
    rgb, _, _ = half_way[display]
    np.testing.assert_array_equal(compress.compress_RGB(rgb, display), rgb)


@pytest.mark.parametrize("display", DISPLAYS)
def test_view_leaves_half_way_colours_alone(half_way, display):
    """Colours at most half-way to the boundary move by at most dE2000 0.1 through the
    view (the target of the clip's in-gamut colours)."""
    rgb, _, got = half_way[display]
    de = colorimetry.delta_E2000(
        colorimetry.RGB_to_XYZ(rgb, display), colorimetry.RGB_to_XYZ(got, display)
    )
    print(f"{display}: half-way colours dE2000 max {de.max():.3f} p99 {np.percentile(de, 99):.3f}")
    assert de.max() <= 0.1


@pytest.mark.parametrize("display", DISPLAYS)
def test_view_puts_half_way_colours_no_further_out(half_way, display):
    """The view never pushes a colour it should leave alone outwards along its ray: the
    output's position along the ray (its projection on the input's direction from the
    grey) is at most 2.5e-4 of linear light beyond the input (the LUTs' 16-bit steps),
    and at most 2 % of the distance beyond it for colours at least 0.01 from their grey."""
    rgb, Y, got = half_way[display]
    v = rgb - Y[:, None]
    dist = np.linalg.norm(v, axis=1)
    beyond = ((got - Y[:, None]) * v).sum(axis=1) / dist - dist
    far = dist >= 0.01
    print(
        f"{display}: beyond the input by at most {beyond.max():.1e} "
        f"({(beyond[far] / dist[far]).max():.2%} of the distance at >= 0.01)"
    )
    assert beyond.max() <= 2.5e-4
    assert (beyond[far] / dist[far]).max() <= 0.02


@pytest.mark.parametrize("level", OPTIMIZATION_LEVELS)
@pytest.mark.parametrize("display", DISPLAYS)
def test_view_finite_and_in_range_at_every_optimisation_level(cfg, display, level):
    big = np.float32(3.0e38)
    px = np.array(
        [
            [big, big, big],
            [-big, big, -big],
            [np.inf, 0, 0],
            [0, -np.inf, 1],
            [1e30, 1e-30, 0],
            [0.2, 0.3, 0.1],
            [0.0, 0.0, 0.0],
            [5.0, 1.0, 0.0],
        ]
    )
    out = _apply(cfg, display, px, optimization=getattr(ocio, OPTIMIZATION_LEVELS[level]))
    # 1e-4: the tolerance of the clip's views (test_clip_view), float32 ops after the LUTs
    assert np.isfinite(out).all() and out.min() >= -1e-4 and out.max() <= 1.0 + 1e-4


def _ramps(display, n=64):
    """Saturation ramps at fixed Y and hue, from the grey to far outside: towards each
    monochromatic colour 450-650 nm, at Y = 0.05, 0.2 and 0.4 -- XYZ (ramps, n, 3) and
    the unclipped normalised distance of each step."""
    w = _weights(display)
    wl = np.arange(450.0, 651.0, 25.0)
    ramps, dist = [], []
    for Y in (0.05, 0.2, 0.4):
        for target in colorimetry.XYZ_to_RGB(colorimetry.spectral_locus_XYZ(Y, wl), display):
            grey = np.full(3, Y)
            d_target = _ray_distance(target[None], w)[0]
            # to 2.1 distances, or to the spectral colour where it is nearer (beyond it
            # the ramp leaves the real colours)
            t = np.linspace(0.0, min(1.6 * compress.LIMIT / d_target, 1.0), n)
            rgb = grey + t[:, None] * (target - grey)
            ramps.append(colorimetry.RGB_to_XYZ(rgb, display))
            dist.append(t * d_target)
    return np.array(ramps), np.array(dist)


@pytest.fixture(scope="module")
def ramp_distances(cfg):
    """{display: (unclipped distance, analytic compress, compress view, clip view)}, the
    output distances along the ramps of :func:`_ramps`."""
    out = {}
    for display in DISPLAYS:
        w = _weights(display)
        ramps, dist = _ramps(display)
        M = colorimetry.matrix_XYZ_to_RGB(display)
        analytic = compress.compress_XYZ(ramps.reshape(-1, 3), display) @ M.T
        views = [
            decode_display(_apply(cfg, display, ramps.reshape(-1, 3), view), display)
            for view in (VIEW, "Constant-Lightness Clip")
        ]
        out[display] = (
            dist,
            *[_ray_distance(rgb, w).reshape(dist.shape) for rgb in [analytic] + views],
        )
    return out


def _rising_steps(dist, out):
    """Steps of ``out`` along each ramp between 0.05 and the limit (minus one step)."""
    rising = (dist > 0.05) & (dist < compress.LIMIT - 0.02)
    return np.diff(out, axis=1)[rising[:, 1:] & rising[:, :-1]]


#: Measured deviations of a display's shipped compression view from the analytic map on
#: the ramps, beyond the 0.03 this file asserts: a package defect, reported, not a
#: tolerance (strict: the test fails once the view is fixed, until the entry goes).
RAMP_DEFECTS = {
    "P3-DCI": "the compress view is 0.048 of a boundary distance from the analytic map "
    "(input distance 1.16; sRGB 0.019, Display P3 0.012, Rec.2020 0.012)",
}


@pytest.mark.parametrize(
    "display",
    [
        pytest.param(d, marks=pytest.mark.xfail(reason=RAMP_DEFECTS[d], strict=True))
        if d in RAMP_DEFECTS
        else d
        for d in DISPLAYS
    ],
)
def test_ramps_compress_rises_where_the_clip_is_flat(ramp_distances, display):
    """Saturation ramps at fixed Y and hue (64 steps from the grey to 2.1 boundary
    distances or the spectral colour): the analytic compression's output distance
    increases strictly up to the limit, the view follows it to within 0.03 of a
    boundary distance (the reached bound, measured 0.012-0.021, near the boundary), and
    the clip view's output is flat (on the boundary, to the clip LUT's 0.023) past it."""
    dist, analytic, view, clip_view = ramp_distances[display]
    assert _rising_steps(dist, analytic).min() > 0.0
    rising = dist < compress.LIMIT
    assert np.abs(clip_view[dist > 1.02] - 1.0).max() < 0.03  # on the boundary (LUT: 0.023)
    worst = np.abs(view - analytic)[rising].max()
    print(f"{display}: the view within {worst:.3f} boundary distances of the analytic map")
    assert worst < 0.03


def test_ramps_compress_view_rises_until_near_the_boundary(ramp_distances):
    """The view's output distance increases strictly along every ramp until the analytic
    output is within 3 % of the boundary (input distance 1.13)."""
    for display in DISPLAYS:
        dist, analytic, view, _ = ramp_distances[display]
        rising = (dist > 0.05) & (analytic < 0.97)
        steps = np.diff(view, axis=1)[rising[:, 1:] & rising[:, :-1]]
        assert steps.min() > 0.0, (display, steps.min())


@pytest.mark.parametrize("display", DISPLAYS)
def test_ramps_compress_view_strictly_increasing_to_the_limit(ramp_distances, display):
    """... and up to the limit (less one step of the 64), as the analytic curve."""
    dist, _, view, _ = ramp_distances[display]
    assert _rising_steps(dist, view).min() > 0.0


def test_documented_accuracy_comes_from_the_benchmark(load_benchmark, marked):
    """docs/compress.md's accuracy table is what benchmarks/bench_compress.py renders from
    reports/bench_compress.json (the shipped edges), and those figures meet the targets
    this file asserts on the baked config."""
    import json

    root = Path(__file__).resolve().parents[1]
    bench = load_benchmark("bench_compress")
    result = json.loads((root / "reports" / "bench_compress.json").read_text())
    doc = (root / "docs" / "compress.md").read_text()
    assert marked(doc, bench.BEGIN, bench.END) == bench.shipped_markdown(result)
    shipped = [
        r
        for r in result["accuracy"]
        if (r["black"], r["white"]) == (compress_lut.SOFT_SIZE, compress_lut.SOFT_WHITE_SIZE)
    ]
    assert len(shipped) == len(DISPLAYS)


@pytest.mark.parametrize("knobs", [(0.8, 1.3), (0.6, 1.5), (0.9, 1.05)])
@pytest.mark.parametrize("display", registry.DISPLAYS)
def test_the_inverse_is_the_preimage_within_the_limit(display, knobs):
    """compress_RGB_inverse: every colour of the unit cube comes back through the map
    (to 1e-12), from at most ``limit`` boundary distances out; a colour inside the limit
    is its own preimage's image's preimage."""
    rng = np.random.default_rng(2)
    cube = rng.uniform(0.0, 1.0, (50000, 3))
    pre = compress.compress_RGB_inverse(cube, display, *knobs)
    assert np.abs(compress.compress_RGB(pre, display, *knobs) - cube).max() <= 1e-12
    d = compress.boundary_distance(pre, display)
    assert np.nanmax(d) <= knobs[1] * (1 + 1e-12)
    # colours inside the limit: the inverse of the map gives them back
    w = clip.luminance_weights(display)
    Y = rng.uniform(0.05, 0.95, 50000)
    direction = rng.normal(size=(50000, 3))
    direction -= (direction @ w)[:, None]  # along a plane of constant Y
    x = Y[:, None] + direction * 0.05
    keep = compress.boundary_distance(x, display) < knobs[1] * 0.999
    back = compress.compress_RGB_inverse(
        compress.compress_RGB(x[keep], display, *knobs), display, *knobs
    )
    assert np.abs(back - x[keep]).max() <= 1e-9
