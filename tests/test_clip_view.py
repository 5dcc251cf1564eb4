"""The constant-lightness clip as a host applies it -- the baked config's
``Constant-Lightness Clip`` views through OCIO's CPU processor, on every display --
against the analytic clip (``clip.clip_XYZ``, the paper's Section 3.2 form).

Sets: (a) object and interference colours (``evaluation.colours.object_colours``: random smooth
reflectances, ColorCheckers, Munsell, thin films, Morpho), (b) monochromatic stimuli
380-700 nm at Y in {0.02, 0.1, 0.3, 0.6}, (c) random XYZ inside ACES AP0 with
0 <= Y <= 1, (e) spectral-line mixtures up to Y = 0.99
(``evaluation.colours.spectral_mixtures``), (d) extremes. The accuracy targets for
(a)-(c) and (e): dE2000 p99 <= 0.5 and max <= 1.5, |dY| <= 1e-3, output in gamut,
in-gamut colours unchanged (dE2000 <= 0.1).
Where a target is not reached the test asserts what is reached and a strict xfail
states the target, so it shows in every run (and turns into a failure once met).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from evaluation.colours import ap0_below_white
from evaluation.views import (
    EXTREME_XYZ,
    OPTIMIZATION_LEVELS,
    apply_view,
    decode_display,
    error_stats,
    view_codes,
)
from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry

ocio = pytest.importorskip("PyOpenColorIO")

#: Every SDR display of the registry.
DISPLAYS = registry.DISPLAYS
VIEW = "Constant-Lightness Clip"


F32_MAX = float(np.finfo(np.float32).max)


@pytest.fixture(scope="module")
def measured(cfg):
    """{(display, set): dict of dE2000 / dY / in-gamut statistics}."""
    out = {}
    for display in DISPLAYS:
        M = colorimetry.matrix_XYZ_to_RGB(display)
        for name, XYZ, code in view_codes(cfg, display, VIEW):
            got = colorimetry.RGB_to_XYZ(decode_display(code, display), display)
            truth = clip.clip_XYZ(XYZ, display)
            out[display, name] = dict(
                error_stats(truth, got, clip.in_gamut(XYZ @ M.T)),
                dY=float(np.abs(got[:, 1] - truth[:, 1]).max()),
                in_gamut=bool(np.all((code >= 0.0) & (code <= 1.0 + TOL))),
            )
    return out


#: Code values may exceed [0, 1] by float32 round-off of the display encodings (OCIO's
#: fast pow at 1.0 gives 1.0000165 through BT.1886; every view, the baselines too).
TOL = 1e-4

#: The accuracy targets for every set: dE2000 p99, max, |dY|, in-gamut colours' max.
TARGET = (0.5, 1.5, 1e-3, 0.1)
#: What the design reaches, per set (same order), measured on these sets: all three
#: displays are within these numbers.
REACHED = {
    "object": (0.5, 1.5, 1e-3, 0.1),
    "monochromatic": (0.5, 1.5, 1e-3, 0.1),
    "ap0": (0.5, 1.6, 1e-3, 0.1),
    "mixtures": (0.5, 1.5, 1e-3, 0.1),
}
#: (display, set) pairs reaching more than REACHED, measured: P3-DCI's spectral mixtures
#: (max dE2000 1.660).
REACHED_BY_DISPLAY = {("P3-DCI", "mixtures"): (0.5, 1.7, 1e-3, 0.1)}
#: (display, set) pairs that miss TARGET (a strict xfail each, so it turns into a
#: failure once met): the dark violet beyond the blue primary (AP0 at Y ~ 0.05, where
#: the interpolant between points on two faces still cuts the triangle's corner a
#: little after the fit of the outside nodes). Keyed by the display whose clip tables
#: a display uses (``Display.gamut``: Rec.1886 Rec.709 has sRGB's, and its misses).
MISSES = {
    ("sRGB", "ap0"): "max dE2000 1.57 (dark violet beyond the blue primary)",
    ("Display P3", "ap0"): "max dE2000 1.504 (dark violet beyond the blue primary)",
    ("P3-DCI", "ap0"): "max dE2000 1.523 (dark violet beyond the blue primary)",
    ("P3-DCI", "mixtures"): "max dE2000 1.660",
}
#: Where one display reaches less than :data:`REACHED` (measured): P3-DCI's clip tables,
#: made as the others' for a gamut whose white is not D65, on the spectral-line mixtures.
REACHED_BY_DISPLAY = {("P3-DCI", "mixtures"): (0.5, 1.7, 1e-3, 0.1)}


def _tables(display):
    """The display whose clip tables ``display`` uses (its own or an earlier one's)."""
    return registry.as_display(display).gamut.name


def _check(m, limits):
    p99, worst, dY, inside = limits
    assert m["in_gamut"]
    assert m["p99"] <= p99
    assert m["max"] <= worst
    assert m["dY"] <= dY
    assert m["inside_max"] <= inside


@pytest.mark.parametrize("display", DISPLAYS)
@pytest.mark.parametrize("name", list(REACHED))
def test_view_against_the_analytic_clip(measured, display, name):
    m = measured[display, name]
    print(
        f"{display:10s} {name:13s} p99 {m['p99']:.3f} max {m['max']:.3f} "
        f"|dY| {m['dY']:.1e} in-gamut max {m['inside_max']:.3f}"
    )
    _check(m, REACHED_BY_DISPLAY.get((_tables(display), name), REACHED[name]))


@pytest.mark.parametrize(
    "display, name",
    [
        pytest.param(
            d,
            n,
            marks=[
                pytest.mark.xfail(
                    strict=True, reason=f"target not reached: {MISSES[_tables(d), n]}"
                )
            ]
            if (_tables(d), n) in MISSES
            else [],
        )
        for d in DISPLAYS
        for n in REACHED
    ],
)
def test_view_target(measured, display, name):
    _check(measured[display, name], TARGET)


@pytest.fixture(scope="module")
def ap0_below(cfg):
    """{display: dE2000 of the view against the analytic clip} on 200,000 random colours
    inside ACES AP0 below white (``ap0_below_white``, ten times the ``ap0`` set)."""
    XYZ = ap0_below_white()
    out = {}
    for display in DISPLAYS:
        got = colorimetry.RGB_to_XYZ(
            decode_display(apply_view(cfg, display, XYZ), display), display
        )
        out[display] = colorimetry.delta_E2000(clip.clip_XYZ(XYZ, display), got)
    return out


#: What the view reaches on ``ap0_below_white`` (max dE2000, per display), measured: the
#: black pass's interpolant cuts the triangle's corners beyond the primaries (dark violet
#: beyond sRGB's and Display P3's blue, imaginary greens beyond Rec.2020's green), where
#: the clip has a kink along the ray from the white point through the primary. A larger
#: black pass is no cure within the size budget (benchmarks/bench_ap0_corners.py: 81^3,
#: 12.5 MB per display, still reaches 1.47 / 1.41 / 1.505); P3-DCI 1.787. Keyed by the
#: display whose tables a display uses (Rec.1886 Rec.709: sRGB's, measured 1.617).
AP0_REACHED = {"sRGB": 1.62, "Display P3": 1.54, "Rec.2020": 1.79, "P3-DCI": 1.80}


@pytest.mark.parametrize("display", DISPLAYS)
def test_ap0_below_white_within_what_the_design_reaches(ap0_below, display):
    de = ap0_below[display]
    print(f"{display}: AP0 below white max {de.max():.3f} p99 {np.percentile(de, 99):.3f}")
    assert _tables(display) in AP0_REACHED, (
        f"AP0_REACHED has no measured bound for the display {_tables(display)!r} (max "
        f"{de.max():.3f} now): add it"
    )
    assert np.percentile(de, 99) <= TARGET[0]
    assert de.max() <= AP0_REACHED[_tables(display)]


@pytest.mark.parametrize(
    "display",
    [
        pytest.param(
            d,
            marks=pytest.mark.xfail(
                strict=True,
                reason=f"target not reached: max dE2000 {AP0_REACHED.get(_tables(d))} (corners "
                "beyond "
                "the primaries; size trade-off in reports/bench_ap0_corners.md)",
            ),
        )
        for d in DISPLAYS
    ],
)
def test_ap0_below_white_target(ap0_below, display):
    """Random AP0 colours below white: max dE2000 <= 1.5 (TARGET) on every display."""
    assert ap0_below[display].max() <= TARGET[1]


# --------------------------------------------------------------------------- #
# (d) extremes, every optimisation level
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("level", OPTIMIZATION_LEVELS)
@pytest.mark.parametrize("display", DISPLAYS)
def test_extremes_finite_and_in_gamut(cfg, display, level):
    out = apply_view(cfg, display, EXTREME_XYZ, getattr(ocio, OPTIMIZATION_LEVELS[level]))
    assert np.all(np.isfinite(out)) and out.min() >= -TOL and out.max() <= 1.0 + TOL
    np.testing.assert_allclose(out[0], 0.0, atol=1e-6)  # black
    # above white: white, to 3e-4 (0.08/255): the pre-clip brings them to Y = 1, and the
    # white pass interpolates the clip's smooth continuation across Y = 1 there
    np.testing.assert_allclose(out[[6, 7, 8]], 1.0, atol=3e-4)


def _finite_probe():
    """Finite values every input space can hold, huge and tiny included."""
    v = np.array(
        [
            0.0,
            1e-40,
            1e-30,
            1e-6,
            0.18,
            0.5,
            1.0,
            4.0,
            100.0,
            1e4,
            1e30,
            F32_MAX,
            -1e-6,
            -0.5,
            -1.0,
            -100.0,
            -1e30,
            -F32_MAX,
        ],
        dtype=np.float32,
    )
    grid = np.stack(np.meshgrid(v, v, v, indexing="ij"), axis=-1).reshape(-1, 3)
    return np.ascontiguousarray(grid)


@pytest.mark.parametrize("level", OPTIMIZATION_LEVELS)
def test_every_processor_of_the_config_is_finite_and_in_range(cfg, level):
    """Finite, in-range output from finite input for every (input space,
    display, view) of the config, at OCIO's NONE, DRAFT and DEFAULT optimisation."""
    probe = _finite_probe()
    spaces = [
        cs.getName()
        for cs in cfg.getColorSpaces()
        if cs.getReferenceSpaceType() == ocio.REFERENCE_SPACE_SCENE and not cs.isData()
    ]
    bad = []
    for src in spaces:
        for display in cfg.getDisplays():
            for view in cfg.getViews(display):
                if view == "Raw":
                    continue
                proc = cfg.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD)
                cpu = proc.getOptimizedCPUProcessor(
                    ocio.BIT_DEPTH_F32,
                    ocio.BIT_DEPTH_F32,
                    getattr(ocio, OPTIMIZATION_LEVELS[level]),
                )
                px = probe.copy()
                cpu.applyRGB(px)
                if not (np.all(np.isfinite(px)) and px.min() >= -TOL and px.max() <= 1.0 + TOL):
                    bad.append((src, display, view, float(np.nanmin(px)), float(np.nanmax(px))))
        cfg.clearProcessorCache()  # hundreds of processors with their LUTs: gigabytes
    assert not bad, bad[:10]


def _nonfinite_probe():
    """Code values a display colour space can be handed: ordinary, huge (1e30, 3e38,
    float32 max), infinite and NaN, every combination of three."""
    v = np.array(
        [0.0, 0.5, 1.0, -1.0, 1e30, -1e30, 3e38, -3e38, F32_MAX, -F32_MAX, np.inf, -np.inf, np.nan],
        dtype=np.float32,
    )
    return np.ascontiguousarray(np.stack(np.meshgrid(v, v, v, indexing="ij"), -1).reshape(-1, 3))


def _lowest_and_highest(x):
    """``x`` with NaN and -Inf replaced by -float32 max and +Inf by float32 max: the
    config's definition of non-finite input (every input space limits its components
    first, and OCIO's Range sends NaN to the lower bound)."""
    y = np.where(np.isnan(x) | (x == -np.inf), -F32_MAX, x)
    return np.ascontiguousarray(np.where(y == np.inf, F32_MAX, y).astype(np.float32))


def _cpu(proc, level, x):
    cpu = proc.getOptimizedCPUProcessor(
        ocio.BIT_DEPTH_F32, ocio.BIT_DEPTH_F32, getattr(ocio, OPTIMIZATION_LEVELS[level])
    )
    px = np.ascontiguousarray(x, dtype=np.float32).copy()
    cpu.applyRGB(px)
    return px


@pytest.mark.parametrize("level", OPTIMIZATION_LEVELS)
def test_display_spaces_as_input_are_finite_at_every_level(cfg, level):
    """Every display colour space (SDR and HDR) as the input of every view of every
    display, converted to CIE-XYZ-D65 and to every other display colour space, at every
    optimisation level: finite output for any input, float32 max and +-Inf included;
    views in the code range [0, 1].

    Non-finite input, defined: a NaN component counts as the lowest value and +-Inf as
    the highest / lowest, so the output equals that of the same pixel with float32
    max in their place (computed here by the same processor on those finite pixels).
    Analytic expectations: an all-NaN or all -Inf pixel is black through every view
    (no light), an all +Inf pixel the view's white at its peak (what a grey 1000 times
    the reference white gives, from CIE-XYZ-D65)."""
    x = _nonfinite_probe()
    substituted = _lowest_and_highest(x)
    nan, neg, pos = (
        np.flatnonzero(np.all(f(x), axis=1))
        for f in (np.isnan, lambda a: a == -np.inf, lambda a: a == np.inf)
    )
    white = np.float32([[0.95047, 1.0, 1.08883]]) * np.float32(1000.0)
    sources = [
        cs.getName()
        for cs in cfg.getColorSpaces()
        if cs.getReferenceSpaceType() == ocio.REFERENCE_SPACE_DISPLAY
    ]
    assert sorted(sources) == sorted(d.colorspace for d in registry.ALL_DISPLAY_LIST)
    raw = [v.name for v in registry.VIEW_LIST if v.raw]
    bad = []
    for src in sources:
        targets = [(d, v) for d in cfg.getDisplays() for v in cfg.getViews(d) if v not in raw]
        # (a conversion of a space to itself is no conversion: OCIO passes it through)
        targets += [(None, dst) for dst in ["CIE-XYZ-D65", *sources] if dst != src]
        for display, view in targets:
            if display is None:
                proc = cfg.getProcessor(src, view)
            else:
                proc = cfg.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD)
            out = _cpu(proc, level, x)
            what = (src, display, view)
            if not np.isfinite(out).all():
                bad.append((*what, "non-finite", x[~np.isfinite(out).all(1)][0].tolist()))
                continue
            if not np.array_equal(out, _cpu(proc, level, substituted)):
                bad.append((*what, "NaN/Inf not the lowest/highest value"))
            if display is None:
                continue
            if out.min() < -TOL or out.max() > 1.0 + TOL:
                bad.append((*what, "out of range", float(out.min()), float(out.max())))
            peak = _cpu(
                cfg.getProcessor("CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD),
                level,
                white,
            )
            if np.abs(out[np.r_[nan, neg]]).max() > 1e-5:
                bad.append((*what, "NaN / -Inf not black", out[nan].tolist()))
            if np.abs(out[pos] - peak).max() > 1e-3:
                bad.append((*what, "+Inf not the peak white", out[pos].tolist(), peak.tolist()))
        cfg.clearProcessorCache()  # hundreds of processors with their LUTs: gigabytes
    assert not bad, bad[:10]


def test_documented_numbers_come_from_the_benchmark(load_benchmark, marked):
    """docs/gamut_map.md's measured tables and the README's status line of the clip
    views are what benchmarks/bench_gamut_map.py renders from
    reports/bench_gamut_map.json (no figure typed by hand)."""
    import json

    root = Path(__file__).resolve().parents[1]
    bench = load_benchmark("bench_gamut_map")
    result = json.loads((root / "reports" / "bench_gamut_map.json").read_text())
    doc = (root / "docs" / "gamut_map.md").read_text()
    assert marked(doc, bench.BEGIN, bench.END) == bench.numbers_markdown(result)
    assert marked(doc, bench.TARGETS_BEGIN, bench.TARGETS_END) == bench.targets_markdown(result)
    readme = (root / "README.md").read_text()
    assert marked(readme, bench.STATUS_BEGIN, bench.STATUS_END) == bench.status_markdown(result)


def test_load_benchmark_table_comes_from_its_json(load_benchmark, marked):
    """docs/gamut_map.md's whole-job costs (clip view against the ACES view, oiiotool
    processes) are what benchmarks/bench_load.py renders from reports/bench_load.json,
    and its ratios are the JSON's timings (not typed by hand)."""
    import json

    root = Path(__file__).resolve().parents[1]
    bench = load_benchmark("bench_load")
    result = json.loads((root / "reports" / "bench_load.json").read_text())
    doc = (root / "docs" / "gamut_map.md").read_text()
    assert marked(doc, bench.BEGIN, bench.END) == bench.markdown(result)
    for row in result["rows"]:
        med = row["median_s"]
        assert row["clip_over_aces"] == pytest.approx(
            med["Constant-Lightness Clip"] / med["ACES Gamut Compression"]
        )
        assert row["compress_over_aces"] == pytest.approx(
            med["Constant-Lightness Compress"] / med["ACES Gamut Compression"]
        )
