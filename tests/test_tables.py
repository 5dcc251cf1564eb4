"""Tables and the 3D clip LUT (ocio_thinfilm.lut.tables): accuracy budgets, edge inputs,
the view transforms and the interface contract the renderer and the report use."""

from __future__ import annotations

import numpy as np
import pytest

from evaluation.colours import object_colours, spectral_colours
from evaluation.views import encode_display
from ocio_thinfilm import cache, registry
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import clip_lut, grid, ocio_ops, storage, tables, view_transforms

DISPLAYS = clip.DISPLAYS


@pytest.fixture(scope="module")
def objects():
    return object_colours()


def grey_input(x):
    x = np.asarray(x, dtype=np.float32)
    return np.repeat(x[:, None], 3, axis=1)


# --------------------------------------------------------------------------- #
# Contract
# --------------------------------------------------------------------------- #
def test_views_and_default_tables():
    assert registry.VIEWS == (
        "Constant-Lightness Clip",
        "Constant-Lightness Compress",
        "Channel Clamp",
        "ACES Gamut Compression",
        "Raw",
    )
    table = tables.film_table("phase-change")
    assert table.kind == "phase-change"
    assert table.values.shape == (tables.FILM_SIZE, 3)
    assert tables.morpho_table().kind == "morpho"


def test_each_table_is_computed_once_and_the_store_shows_it():
    cache.clear()
    assert cache.entries("ocio_thinfilm.lut.") == {}
    tables.film_table("no-phase-change", 1000)
    tables.film_table("no-phase-change", 1000)
    tables.morpho_table(300)
    clip_lut.clip_lut("Rec.2020", 11)
    clip_lut.clip_lut("Rec.2020", 11)
    step = tables.SPECTRAL_STEP
    assert cache.entries("ocio_thinfilm.lut.") == {
        "ocio_thinfilm.lut.tables._film_table": (
            ("no-phase-change", 1000, tables.FILM_TMAX_UM, tables.FILM_T0_UM, step),
        ),
        "ocio_thinfilm.lut.tables._morpho_table": ((300, step),),
        "ocio_thinfilm.lut.grid.black_plan": (("Rec.2020", 11),),
        "ocio_thinfilm.lut.clip_lut._black_nodes": (("Rec.2020", 11),),
        "ocio_thinfilm.lut.clip_lut._clip_lut": (("Rec.2020", 11, 9),),
    }
    infos = cache.info()
    assert infos["ocio_thinfilm.lut.tables._film_table"].misses == 1
    assert infos["ocio_thinfilm.lut.tables._film_table"].hits == 1
    assert infos["ocio_thinfilm.lut.clip_lut._clip_lut"].hits == 1


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: tables.film_table("soap"), "^kind must be one of"),
        (lambda: tables.film_table("phase-change", 1), "size"),
        (lambda: tables.film_table("phase-change", max_thickness_um=-1), "^max_thickness_um"),
        (lambda: tables.morpho_table(0), "size"),
        (lambda: clip_lut.clip_transform("CRT"), "display"),
        (lambda: clip_lut.clip_transform("sRGB", 1000), "size"),
        (lambda: view_transforms.view_transform("sRGB", "Filmic"), "view"),
        (lambda: ocio_ops.apply(ocio_ops.group([]), np.zeros((4, 2))), "last axis"),
    ],
)
def test_bad_arguments_raise_value_error(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_apply_returns_new_float32_array_of_same_shape():
    px = np.linspace(0, 1, 24, dtype=np.float64).reshape(2, 4, 3)
    keep = px.copy()
    out = ocio_ops.apply(view_transforms.view_transform("sRGB", "Channel Clamp"), px)
    assert out.shape == px.shape and out.dtype == np.float32
    np.testing.assert_array_equal(px, keep)
    assert ocio_ops.apply(ocio_ops.group([]), np.zeros((0, 3))).shape == (0, 3)


# --------------------------------------------------------------------------- #
# 1D tables: error budget (max dE2000 <= 0.05 over the whole range)
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("kind", colorimetry.FILM_KINDS)
def test_film_table_error_budget_over_whole_range(kind):
    table = tables.film_table(kind)
    # Midpoints between nodes (worst case for linear interpolation) and a dense grid.
    u = (np.arange(table.size - 1) + 0.5) / (table.size - 1)
    t_mid = table.t0 * np.expm1(u * np.log1p(table.domain_max / table.t0))
    t = np.concatenate([t_mid, np.linspace(0.0, 100.0, 20001)])
    direct = colorimetry.film_XYZ(t * 1000.0, kind, step=tables.SPECTRAL_STEP)
    assert colorimetry.delta_E2000(table.lookup(t), direct).max() <= 0.05
    via_ocio = ocio_ops.apply(table.transform(), grey_input(t)).astype(np.float64)
    assert colorimetry.delta_E2000(via_ocio, direct).max() <= 0.05


def test_morpho_table_error_budget():
    table = tables.morpho_table()
    c = np.concatenate(
        [(np.arange(table.size - 1) + 0.5) / (table.size - 1), np.linspace(0, 1, 5001)]
    )
    direct = colorimetry.morpho_XYZ(np.degrees(np.arccos(c)), step=tables.SPECTRAL_STEP)
    assert colorimetry.delta_E2000(table.lookup(c), direct).max() <= 0.05
    via_ocio = ocio_ops.apply(table.transform(), grey_input(c)).astype(np.float64)
    assert colorimetry.delta_E2000(via_ocio, direct).max() <= 0.05


def test_lookup_matches_ocio():
    table = tables.film_table("phase-change")
    t = np.linspace(-1.0, 150.0, 50001)
    np.testing.assert_allclose(
        ocio_ops.apply(table.transform(), grey_input(t)), table.lookup(t), atol=5e-4
    )


def test_film_table_beyond_range_is_incoherent_grey_no_nan_no_wrap():
    table = tables.film_table("phase-change")
    edge = np.array([100.0, 150.0, 1e4, 1e30, np.inf, -0.5, -1e30, -np.inf, np.nan, 0.0])
    out = ocio_ops.apply(table.transform(), grey_input(edge))
    assert np.all(np.isfinite(out))
    grey = 0.5 * colorimetry.white_XYZ("sRGB")  # D65 white: the perfect reflector
    for row in out[:5]:  # thick films: half the illuminant, the incoherent limit
        np.testing.assert_allclose(row, grey, atol=2e-3)
    np.testing.assert_allclose(out[5:], 0.0, atol=1e-5)  # negative, NaN, 0: black
    np.testing.assert_allclose(table.lookup(edge[:5]), np.repeat(grey[None], 5, 0), atol=2e-3)


def test_morpho_out_of_range_clamps():
    table = tables.morpho_table()
    out = ocio_ops.apply(table.transform(), grey_input([-0.5, 0.0, 1.0, 2.0, np.nan]))
    assert np.all(np.isfinite(out))
    np.testing.assert_allclose(out[0], out[1], atol=1e-7)
    np.testing.assert_allclose(out[2], out[3], atol=1e-7)


def test_per_display_rgb_variant_is_clipped():
    table = tables.film_table("phase-change", 2048)
    for display in DISPLAYS:
        rgb = table.rgb(display)
        assert clip.in_gamut(rgb, 1e-12).all()
        np.testing.assert_allclose(
            colorimetry.RGB_to_XYZ(rgb, display)[:, 1],
            np.minimum(table.values[:, 1], 1.0),
            atol=1e-9,
        )


# --------------------------------------------------------------------------- #
# 3D clip LUT
# --------------------------------------------------------------------------- #
#: The targets for object colours (the view, every display): p99 <= 0.5, max <= 1.5
#: dE2000 vs the analytic clip (measured: reports/bench_gamut_map.json;
#: tests/test_clip_view.py covers the other sets).
OBJECT_P99 = 0.5
OBJECT_MAX = 1.5


@pytest.mark.parametrize("display", DISPLAYS)
def test_clip_lut_against_analytic_clip_on_object_colours(display, objects):
    truth = clip.clip_XYZ(objects, display)
    out = ocio_ops.apply(clip_lut.clip_transform(display), objects)
    de = colorimetry.delta_E2000(truth, colorimetry.RGB_to_XYZ(out.astype(np.float64), display))
    assert np.percentile(de, 99) <= OBJECT_P99
    assert de.max() <= OBJECT_MAX
    assert de.mean() <= 0.05


@pytest.mark.parametrize("display", DISPLAYS)
def test_clip_lut_reproduces_interior_colours(display):
    # In gamut the white-faces pass is the identity exactly (its nodes sit at encoded
    # values); what remains is the black-faces pass interpolating Y g(chart) over a
    # projective chart and its half-float storage. Measured: |d| <= 2.4e-3 here.
    rgb = np.random.default_rng(3).uniform(0.2, 0.8, (5000, 3))
    out = ocio_ops.apply(clip_lut.clip_transform(display), colorimetry.RGB_to_XYZ(rgb, display))
    np.testing.assert_allclose(out, rgb, atol=3e-3)


@pytest.mark.parametrize("display", DISPLAYS)
def test_clip_lut_keeps_Y_of_spectral_colours_and_lands_in_gamut(display):
    # The target |dY| <= 1e-3 (both passes keep Y exactly at their nodes: the
    # first is the identity on Y, the second moves along constant Y).
    locus = spectral_colours(0.6)
    out = ocio_ops.apply(clip_lut.clip_transform(display), locus).astype(np.float64)
    assert clip.in_gamut(out).all()
    Y = colorimetry.RGB_to_XYZ(out, display)[:, 1]
    assert np.abs(Y - locus[:, 1]).max() <= 1e-3


def test_clip_lut_edge_inputs_never_nan():
    W = colorimetry.white_XYZ("sRGB")
    edge = np.array(
        [
            [0, 0, 0],
            [-1, -1, -1],
            [-1, 0.5, 0.5],
            [0.5, 0.5, -3],
            2 * W,
            [0.95, 1.5, 1.09],
            [1e30, 1e30, 1e30],
            [1e30, 0.5, 0.5],
            [-1e30, 0.5, 0.5],
            [np.inf, np.inf, np.inf],
            [-np.inf, 0.5, 0.5],
            [np.nan, 0.5, 0.5],
            [np.nan] * 3,
            [0.1, 1e-12, 0.1],
            [0.5, 1.5, 0.5],
        ],
        dtype=np.float32,
    )
    for display in DISPLAYS:
        out = ocio_ops.apply(clip_lut.clip_transform(display), edge)
        assert np.all(np.isfinite(out)), display
        assert clip.in_gamut(out).all()
        np.testing.assert_allclose(out[0], 0.0, atol=1e-6)
        # brighter than the display white -> white (the pre-clip brings Y to 1; the
        # white pass interpolates the clip's continuation across Y = 1: within 2e-3 in
        # linear RGB, 0.13/255 in sRGB code values)
        np.testing.assert_allclose(out[[4, 5, 14]], 1.0, atol=2e-3)


def test_clip_lut_size_is_an_option():
    lut = clip_lut.clip_lut("sRGB", 33)
    assert lut.black.shape == (33, 33, 33, 3)
    assert lut.white.shape == (27, 27, 27, 3)  # white_size(33): in proportion to 53 / 65
    assert clip_lut.clip_lut("sRGB", 33, 33).white.shape == (33, 33, 33, 3)
    with pytest.raises(ValueError, match="white_edge"):
        clip_lut.clip_lut("sRGB", 33, 5)
    out = ocio_ops.apply(
        clip_lut.clip_transform("sRGB", 33),
        colorimetry.RGB_to_XYZ(np.array([[0.5, 0.4, 0.3]]), "sRGB"),
    )
    np.testing.assert_allclose(out, [[0.5, 0.4, 0.3]], atol=3e-3)


def test_black_and_white_passes_compose_to_the_clip():
    """U o L is the Section 3.2 clip (the factorisation the LUTs rely on), checked
    against the paper's XYZ form on random colours far outside every gamut."""
    rng = np.random.default_rng(5)
    rgb = rng.normal(0.4, 1.5, (20000, 3))
    for display in DISPLAYS:
        both = clip.clip_white_faces_RGB(clip.clip_black_faces_RGB(rgb, display), display)
        M = colorimetry.matrix_XYZ_to_RGB(display)
        paper = colorimetry.XYZ_to_RGB(clip.clip_XYZ(rgb @ np.linalg.inv(M).T, display), display)
        np.testing.assert_allclose(both, paper, atol=1e-9)


def _ulp_rows(display):
    """The display's luminance row and four copies a few ulps away: the sums of a dot
    product another CPU (another SIMD width, FMA or not) may compute."""
    w = clip.luminance_weights(display)
    return [w * (1.0 + k * np.finfo(float).eps) for k in (0, -2, -1, 1, 2)]


@pytest.mark.parametrize("display", DISPLAYS)
def test_white_pass_nodes_do_not_depend_on_the_last_ulps(display, monkeypatch):
    """The white pass's stored codes are the same whatever the last bits of the
    luminance row: a grey node past white (every channel 1.004) goes to white, not to a
    0 / 0 that one CPU rounded to white and another to the grey itself (52428 against
    52520 in one node of each white pass, seen between two machines)."""
    nodes, _ = grid.white_nodes(clip_lut.WHITE_SIZE, display)
    C = np.stack(np.meshgrid(*nodes, indexing="ij"), axis=-1).reshape(-1, 3)
    codes = []
    for w in _ulp_rows(display):
        monkeypatch.setattr(clip, "luminance_weights", lambda _d, w=w: w)
        codes.append(clip_lut._white_codes(C, display))
    grey = np.all(C == C[:, :1], axis=1) & (C[:, 0] > 1.0)
    assert grey.any()  # the nodes that were at stake
    np.testing.assert_array_equal(codes[0][grey], 1.0 / clip_lut.WHITE_SCALE)
    for other in codes[1:]:
        np.testing.assert_array_equal(other, codes[0])


def test_lut_files_hold_no_negative_zero():
    """No -0 in the 16-bit LUTs: its sign (and the file's text) depended on the CPU."""
    lut = clip_lut.clip_lut("sRGB")
    for array in (lut.black, lut.white, lut.white_shaper):
        assert not np.signbit(array).any()
    assert not np.signbit(storage.q16(np.array([-0.0, -1e-9, 0.0]))).any()


# --------------------------------------------------------------------------- #
# Views
# --------------------------------------------------------------------------- #
def _encode(rgb, display):
    """Display-linear RGB (clamped) -> code values, by colour-science
    (:func:`evaluation.views.encode_display`)."""
    return encode_display(np.clip(rgb, 0, 1), display)


@pytest.mark.parametrize("display", DISPLAYS)
def test_views_match_the_analytic_paths(display, objects):
    X = objects[::7]
    rgb = colorimetry.XYZ_to_RGB(X, display)
    clamp = ocio_ops.apply(view_transforms.view_transform(display, "Channel Clamp"), X)
    np.testing.assert_allclose(clamp, _encode(clip.clamp_RGB(rgb), display), atol=2e-4)
    gc = ocio_ops.apply(view_transforms.view_transform(display, "ACES Gamut Compression"), X)
    np.testing.assert_allclose(gc, _encode(clip.aces_gamut_compress_RGB(rgb), display), atol=2e-4)
    raw = ocio_ops.apply(view_transforms.view_transform(display, "Raw"), X)
    np.testing.assert_allclose(raw, X.astype(np.float32))
    cl = ocio_ops.apply(view_transforms.view_transform(display, "Constant-Lightness Clip"), X)
    lin = ocio_ops.apply(clip_lut.clip_transform(display), X)
    np.testing.assert_allclose(cl, _encode(lin, display), atol=2e-4)
    assert np.all((cl >= 0) & (cl <= 1 + 1e-4))  # float pow of the encoding at 1.0


def test_scene_linear_one_is_display_white():
    # within a quarter of an 8-bit code (the clip's white is interpolated: the display
    # white is not a node of the black pass's chart; measured 0.15 codes)
    for display in DISPLAYS:
        W = colorimetry.white_XYZ(display)
        for view in registry.VIEWS[:3]:
            out = ocio_ops.apply(view_transforms.view_transform(display, view), W[None])
            np.testing.assert_allclose(out, 1.0, atol=0.25 / 255)
