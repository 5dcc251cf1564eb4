"""The constant-lightness parallelepiped clip (paper Section 3.2).

References used: a bisection along the segment from the grey point to the colour
(the gamut is convex and contains its grey, so the furthest in-gamut point of that
segment is found by bisection without any plane algebra), display matrices built
here from colour-science's primaries (``colour.normalised_primary_matrix``), the
geometric definitions of the clip (Smits & Meyer 1990, Section 3.2: in gamut, Y
preserved, on the segment to the grey, idempotent), and the published ACES 1.3
reference gamut compression formula for the OCIO baseline.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from evaluation.truth import colour_science_RGB_to_XYZ
from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry

#: Every SDR display of the registry (a display's name stands for its gamut).
DISPLAYS = registry.DISPLAYS


def reference_matrices(display):
    """(XYZ->RGB, RGB->XYZ, white XYZ) from colour-science's primaries and white
    (Bradford to D65 for a DCI white), computed by evaluation/truth.py."""
    rgb_to_xyz = colour_science_RGB_to_XYZ(display)
    return np.linalg.inv(rgb_to_xyz), rgb_to_xyz, rgb_to_xyz @ np.ones(3)


def reference_clip_XYZ(XYZ, display, iterations=80):
    """Bisection reference: the point of the segment grey -> colour furthest from
    the grey that is still inside the RGB unit cube (grey = white * Y / Y_white).
    Only for finite colours with 0 < Y < Y_white."""
    M, _, white = reference_matrices(display)
    XYZ = np.asarray(XYZ, dtype=np.float64)
    grey = white * (XYZ[:, 1:2] / white[1])
    lo = np.zeros(len(XYZ))
    hi = np.ones(len(XYZ))
    inside_all = np.all((XYZ @ M.T >= 0) & (XYZ @ M.T <= 1), axis=1)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        p = grey + mid[:, None] * (XYZ - grey)
        rgb = p @ M.T
        ok = np.all((rgb >= 0) & (rgb <= 1), axis=1)
        lo = np.where(ok, mid, lo)
        hi = np.where(ok, hi, mid)
    out = grey + lo[:, None] * (XYZ - grey)
    return np.where(inside_all[:, None], XYZ, out)


def random_XYZ(rng, n, scale):
    """A mix of distributions: a box around the gamut, heavy-tailed magnitudes,
    spectral-locus colours at random Y, and locus/white mixtures near the boundary."""
    k = n // 4
    box = rng.uniform(-0.5, 1.5, (k, 3)) * scale
    heavy = rng.standard_normal((k, 3)) * np.exp(rng.uniform(-5, 5, (k, 1))) * scale
    locus = colorimetry.spectral_locus_XYZ(1.0)
    pick = locus[rng.integers(0, len(locus), n - 3 * k)]
    Y = rng.uniform(0.0, 1.2, (n - 3 * k, 1))
    spectral = pick * Y
    mix = rng.uniform(0.0, 1.0, (k, 1))
    white = colorimetry.white_XYZ()
    near = (mix * locus[rng.integers(0, len(locus), k)] + (1 - mix) * white) * rng.uniform(
        0.0, 1.1, (k, 1)
    )
    return np.concatenate([box, heavy, spectral, near])


def in_gamut_rgb(XYZ, display, tol=1e-6):
    M, _, _ = reference_matrices(display)
    rgb = np.asarray(XYZ, dtype=np.float64) @ M.T
    return np.all((rgb >= -tol) & (rgb <= 1 + tol), axis=-1)


# --------------------------------------------------------------------------- #
# The two forms and the reference
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("display", DISPLAYS)
def test_xyz_and_rgb_forms_agree(display):
    """Reference: each other (the paper says the RGB form has identical
    properties): clip_XYZ(X) = RGB_to_XYZ(clip_RGB(XYZ_to_RGB(X))) to 1e-9."""
    rng = np.random.default_rng(1)
    XYZ = random_XYZ(rng, 40_000, 1.0)
    a = clip.clip_XYZ(XYZ, display)
    b = colorimetry.RGB_to_XYZ(
        clip.clip_RGB(colorimetry.XYZ_to_RGB(XYZ, display), display), display
    )
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-9)


@pytest.mark.parametrize("display", DISPLAYS)
def test_clip_matches_bisection_reference(display):
    """Reference: bisection along the grey -> colour segment (no plane algebra)."""
    rng = np.random.default_rng(2)
    XYZ = random_XYZ(rng, 20_000, 1.0)
    _, _, white = reference_matrices(display)
    XYZ = XYZ[(XYZ[:, 1] > 1e-6) & (XYZ[:, 1] < white[1] - 1e-6) & (np.abs(XYZ).max(axis=1) < 1e3)]
    expected = reference_clip_XYZ(XYZ, display)
    np.testing.assert_allclose(clip.clip_XYZ(XYZ, display), expected, rtol=0, atol=1e-9)


def test_spectrum_clipped_like_figure_4():
    """Reference: the paper's Figure 4 test -- the spectral colours at constant
    lightness: every clipped colour keeps its Y, lands on the gamut boundary (some
    channel at 0 or 1) and matches the bisection reference."""
    for Y in (0.05, 0.2, 0.5):
        XYZ = colorimetry.spectral_locus_XYZ(Y)
        out = clip.clip_XYZ(XYZ)
        np.testing.assert_allclose(out[:, 1], Y, rtol=1e-12)
        rgb = colorimetry.XYZ_to_RGB(out)
        on_boundary = np.isclose(rgb, 0, atol=1e-9) | np.isclose(rgb, 1, atol=1e-9)
        assert np.all(on_boundary.any(axis=1))
        np.testing.assert_allclose(out, reference_clip_XYZ(XYZ, "sRGB"), atol=1e-9)


# --------------------------------------------------------------------------- #
# Edge cases
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_in_gamut_unchanged_bit_for_bit(dtype):
    """Reference: the definition -- colours inside the cube come back identical,
    including colours exactly on faces, edges and vertices."""
    rng = np.random.default_rng(3)
    rgb = rng.uniform(0.0, 1.0, (5000, 3)).astype(dtype)
    faces = rng.uniform(0.0, 1.0, (600, 3)).astype(dtype)
    faces[:100, 0] = 0
    faces[100:200, 1] = 1
    faces[200:300, 2] = 0  # faces  # noqa: E702
    faces[300:400, :2] = 1
    faces[400:500, 1:] = 0  # edges  # noqa: E702
    faces[500:, :] = rng.integers(0, 2, (100, 3))  # vertices
    rgb = np.concatenate([rgb, faces])
    out = clip.clip_RGB(rgb)
    assert out.dtype == dtype and np.array_equal(out, rgb)
    # XYZ form: strictly interior colours (exact face colours may round either way
    # through the matrix, and come back within rounding).
    _, rgb_to_xyz, _ = reference_matrices("sRGB")
    XYZ = (rng.uniform(1e-3, 1 - 1e-3, (5000, 3)) @ rgb_to_xyz.T).astype(dtype)
    out = clip.clip_XYZ(XYZ)
    assert out.dtype == dtype and np.array_equal(out, XYZ)
    XYZ_faces = faces.astype(np.float64) @ rgb_to_xyz.T
    np.testing.assert_allclose(clip.clip_XYZ(XYZ_faces), XYZ_faces, atol=1e-12)


@pytest.mark.parametrize("display", DISPLAYS)
def test_non_positive_Y_is_black_and_Y_above_white_is_white(display):
    """Reference: the clip's definition -- Y <= 0 gives black, Y >= Y_white gives
    the display white (RGB = 1), whatever X and Z are."""
    _, rgb_to_xyz, white = reference_matrices(display)
    XYZ = np.array(
        [
            [0.3, 0.0, 0.2],
            [-5.0, 0.0, 7.0],
            [0.2, -0.1, 0.4],
            [1e30, -1e-300, 0.0],
            [white[0], white[1], white[2]],
            [0.1, white[1], 3.0],
            [5.0, 2.0, -1.0],
            [-1e30, 1e30, 1.0],
        ]
    )
    out = clip.clip_XYZ(XYZ, display)
    assert np.all(out[:4] == 0.0)
    np.testing.assert_allclose(out[4:], np.broadcast_to(white, (4, 3)), rtol=1e-12)
    # RGB form: its own luminance Y = (RGB -> XYZ row 2) . RGB decides.
    luminance = rgb_to_xyz[1]
    rgb = np.array(
        [
            [0.0, 0.0, 0.0],
            [-1.0, 0.1, 0.1],
            [0.5, -1.0, 0.5],
            [-1e30, 1.0, 1.0],
            [1.0, 1.0, 1.0],
            [3.0, 1.0, 0.5],
            [1e30, -1.0, 2.0],
            [0.2, 5.0, -3.0],
        ]
    )
    Y = rgb @ luminance
    assert np.all(Y[:4] <= 0) and np.all(Y[4:] >= luminance.sum() * (1 - 1e-15))
    out_rgb = clip.clip_RGB(rgb, display)
    assert np.all(out_rgb[:4] == 0.0)
    np.testing.assert_allclose(out_rgb[4:], 1.0, rtol=1e-12)


def test_nan_stays_nan_without_touching_neighbours():
    """Reference: the same image with the NaN pixels replaced by a finite colour
    (bit-for-bit equal elsewhere), and the pixels clipped one at a time (to
    rounding: a different batch shape may round differently in the matrix product)."""
    rng = np.random.default_rng(4)
    img = rng.uniform(-0.5, 1.5, (6, 7, 3))
    img[2, 3] = [np.nan, 0.3, 0.2]
    img[0, 0] = [0.1, np.nan, np.nan]
    img[5, 6] = np.nan
    nan_px = np.isnan(img).any(axis=-1)
    for fn in (clip.clip_XYZ, clip.clip_RGB):
        out = fn(img)
        assert np.all(np.isnan(out[nan_px]))
        assert not np.isnan(out[~nan_px]).any()
        filled = np.where(nan_px[..., None], 0.25, img)
        np.testing.assert_array_equal(out[~nan_px], fn(filled)[~nan_px])
        single = np.array([fn(p) for p in img[~nan_px]])
        np.testing.assert_allclose(out[~nan_px], single, rtol=0, atol=1e-15)


def test_infinities_and_huge_values_give_finite_in_gamut_colours():
    """Reference: the geometric definition (finite, in gamut, Y kept when
    0 <= Y <= Y_white) and the limit of the clip as the component grows (the
    result for +-Inf equals that for 1e15, 1e30 to 1e-9)."""
    rows = []
    for sign in (1.0, -1.0):
        for axis in (0, 2):
            for big in (np.inf, 1e30, 1e15):
                v = np.array([0.3, 0.4, 0.3])
                v[axis] = sign * big
                rows.append(v)
    XYZ = np.array(rows)
    out = clip.clip_XYZ(XYZ)
    assert np.all(np.isfinite(out))
    assert np.all(in_gamut_rgb(out, "sRGB", 1e-9))
    np.testing.assert_allclose(out[:, 1], 0.4, rtol=1e-12)
    groups = out.reshape(-1, 3, 3)
    np.testing.assert_allclose(groups[:, 0], groups[:, 1], atol=1e-9)
    np.testing.assert_allclose(groups[:, 0], groups[:, 2], atol=1e-9)
    # Y itself infinite: white or black.
    out = clip.clip_XYZ(
        np.array(
            [
                [0.1, np.inf, 0.2],
                [0.1, -np.inf, 0.2],
                [np.inf, np.inf, -np.inf],
                [1e308, 1e308, 1e308],
            ]
        )
    )
    np.testing.assert_allclose(out[[0, 2, 3]], np.broadcast_to(colorimetry.white_XYZ(), (3, 3)))
    assert np.all(out[1] == 0)
    # RGB form: every channel combination of +-Inf / 1e30 with finite Y.
    rgb = np.array(
        [
            [np.inf, 0.5, 0.2],
            [-np.inf, 0.5, 0.9],
            [0.2, 1e30, -1e30],
            [np.inf, -np.inf, 0.5],
            [-1e30, 0.5, 0.5],
        ]
    )
    out = clip.clip_RGB(rgb)
    assert np.all(np.isfinite(out)) and np.all((out >= 0) & (out <= 1))


@pytest.mark.parametrize("display", DISPLAYS)
def test_rays_nearly_parallel_to_a_face(display):
    """Reference: bisection, and the invariants. Colours are built as grey + s*d
    with d inside the constant-Y plane *and* inside a face's plane (d orthogonal to
    both the face normal and the Y axis), plus perturbations of 0, 1e-15, 1e-9 and
    1e-6 out of that plane: the ray to grey runs (almost) parallel to the face --
    the paper's region of severe hue change. No blow-ups, Y kept, in gamut."""
    M, _, white = reference_matrices(display)
    rows = []
    for j in range(3):
        d = np.cross(M[j], [0.0, 1.0, 0.0])
        d /= np.linalg.norm(d)
        for Y in (1e-6, 0.01, 0.3, 0.9, white[1] * (1 - 1e-12)):
            grey = white * Y / white[1]
            for s in (0.5, 3.0, 1e3):
                for sign in (1.0, -1.0):
                    for eps in (0.0, 1e-15, 1e-9, 1e-6):
                        for k in range(3):
                            e = np.zeros(3)
                            e[k] = eps
                            p = grey + sign * s * d + e
                            p[1] = Y
                            rows.append(p)
    XYZ = np.array(rows)
    out = clip.clip_XYZ(XYZ, display)
    assert np.all(np.isfinite(out))
    assert np.all(in_gamut_rgb(out, display, 1e-9))
    np.testing.assert_allclose(out[:, 1], XYZ[:, 1], rtol=1e-12)
    np.testing.assert_allclose(out, reference_clip_XYZ(XYZ, display), atol=1e-9)
    rgb_out = clip.clip_RGB(XYZ @ M.T, display)
    np.testing.assert_allclose(rgb_out, out @ M.T, atol=1e-9)


def test_tiny_and_subnormal_luminance():
    """Reference: the invariants (finite, in gamut, Y kept or black) near black,
    where the grey point is tiny or subnormal and every division is by tiny values."""
    XYZ = np.array(
        [
            [1.0, 1e-300, -1.0],
            [-1e-3, 5e-324, 1e-3],
            [1e-310, 1e-310, -1e-310],
            [0.5, 1e-12, 0.5],
            [-2.0, 1e-200, 2.0],
        ]
    )
    out = clip.clip_XYZ(XYZ)
    assert np.all(np.isfinite(out))
    assert np.all(in_gamut_rgb(out, "sRGB", 1e-9))
    assert np.all(np.abs(out[:, 1] - XYZ[:, 1]) <= 1e-12 * np.abs(XYZ[:, 1]))
    # RGB form: tiny luminance in its own terms (Y = luminance . RGB), so the bound
    # includes the rounding of that dot product.
    _, rgb_to_xyz, _ = reference_matrices("sRGB")
    lum = rgb_to_xyz[1]
    rgb = np.array(
        [
            [1.0, -0.2973, 0.0],
            [1e-300, 1e-300, 1e-300],
            [3e-12, -1e-12, 2e-12],
            [5e-324, 0.0, 0.0],
            [2.0, -0.6, 0.1],
        ]
    )
    out = clip.clip_RGB(rgb)
    assert np.all(np.isfinite(out)) and np.all((out >= 0) & (out <= 1))
    Y_in = rgb @ lum
    bound = 1e-12 * np.abs(Y_in) + 4e-16 * (np.abs(rgb) @ lum)
    assert np.all((np.abs(out @ lum - Y_in) <= bound) | ((Y_in <= 0) & (out == 0).all(axis=1)))


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("fn", [clip.clip_XYZ, clip.clip_RGB])
def test_dtype_and_whole_image_shapes(dtype, fn):
    """Reference: float64 evaluation of the same pixels; dtype and (H, W, 3) shape
    preserved; single pixels and (N, 3) arrays too."""
    rng = np.random.default_rng(5)
    img = rng.uniform(-0.5, 1.5, (48, 64, 3)).astype(dtype)
    out = fn(img)
    assert out.shape == img.shape and out.dtype == dtype
    ref = fn(img.astype(np.float64))
    tol = 1e-6 if dtype == np.float32 else 0.0
    np.testing.assert_allclose(out, ref, rtol=0, atol=tol)
    np.testing.assert_array_equal(fn(img.reshape(-1, 3)).reshape(img.shape), out)
    assert fn(img[0, 0]).shape == (3,)
    with pytest.raises(ValueError, match="last axis"):
        fn(img[..., :2])


def test_bad_display_name():
    """Reference: the package's argument contract (ocio_thinfilm.checks) -- a
    ValueError naming the parameter."""
    with pytest.raises(ValueError, match="display"):
        clip.clip_XYZ(np.zeros(3), "CRT-1990")
    with pytest.raises(ValueError, match="display"):
        clip.clip_RGB(np.zeros(3), "CRT-1990")


# --------------------------------------------------------------------------- #
# Property tests: >= 1e5 random XYZ inputs in total (1e4 per example)
# --------------------------------------------------------------------------- #
def _grey(XYZ, display):
    _, _, white = reference_matrices(display)
    return white * (np.clip(XYZ[:, 1:2], 0, white[1]) / white[1])


@settings(max_examples=12)
@given(
    seed=st.integers(0, 2**32 - 1),
    scale=st.sampled_from([0.01, 0.3, 1.0, 3.0, 1e3, 1e8]),
    display=st.sampled_from(DISPLAYS),
)
def test_clip_properties(seed, scale, display):
    """Reference: the clip's definitions (Section 3.2), checked with matrices built here from
    colour's primaries: output in the gamut (1e-6), Y preserved for 0 <= Y <= Y_white,
    idempotent, identity inside the gamut, and the output on the segment from the
    input to its grey (same direction, not beyond the input)."""
    rng = np.random.default_rng(seed)
    XYZ = random_XYZ(rng, 10_000, scale)
    _, _, white = reference_matrices(display)
    out = clip.clip_XYZ(XYZ, display)
    assert np.all(np.isfinite(out))
    assert np.all(in_gamut_rgb(out, display, 1e-6))
    Y = XYZ[:, 1]
    keep = (Y >= 0) & (Y <= white[1])
    np.testing.assert_allclose(out[keep, 1], Y[keep], rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(clip.clip_XYZ(out, display), out, rtol=0, atol=1e-12)
    inside = in_gamut_rgb(XYZ, display, 0.0)
    assert np.array_equal(out[inside], XYZ[inside])
    # On the segment grey -> input: out - grey = t (input - grey) with 0 <= t <= 1.
    sel = keep & ~inside & (Y > 0) & (Y < white[1])
    grey = _grey(XYZ[sel], display)
    v = XYZ[sel] - grey
    w = out[sel] - grey
    vv = np.einsum("ij,ij->i", v, v)
    t = np.einsum("ij,ij->i", w, v) / vv
    assert np.all(t >= -1e-12) and np.all(t <= 1 + 1e-12)
    resid = np.linalg.norm(w - t[:, None] * v, axis=1)
    assert np.all(resid <= 1e-9 * np.maximum(1.0, np.sqrt(vv)))
    # The RGB form has the same properties on the same data.
    M, _, _ = reference_matrices(display)
    rgb_out = clip.clip_RGB(XYZ @ M.T, display)
    assert np.all((rgb_out >= -1e-6) & (rgb_out <= 1 + 1e-6))
    np.testing.assert_allclose(clip.clip_RGB(rgb_out, display), rgb_out, atol=1e-12)


@settings(max_examples=4)
@given(seed=st.integers(0, 2**32 - 1), display=st.sampled_from(DISPLAYS))
def test_clip_properties_on_spectral_locus(seed, display):
    """Reference: as above, for monochromatic colours (the worst case, paper
    Figure 4) at random Y including 0 and the white's Y: 321 x 40 per example."""
    rng = np.random.default_rng(seed)
    _, _, white = reference_matrices(display)
    Ys = np.concatenate([[0.0, white[1]], rng.uniform(0, white[1], 38)])
    XYZ = np.concatenate([colorimetry.spectral_locus_XYZ(Y) for Y in Ys])
    out = clip.clip_XYZ(XYZ, display)
    assert np.all(in_gamut_rgb(out, display, 1e-6))
    np.testing.assert_allclose(out[:, 1], XYZ[:, 1], rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(clip.clip_XYZ(out, display), out, atol=1e-12)
    mid = (XYZ[:, 1] > 0) & (XYZ[:, 1] < white[1])
    np.testing.assert_allclose(out[mid], reference_clip_XYZ(XYZ[mid], display), atol=1e-9)


# --------------------------------------------------------------------------- #
# Baselines
# --------------------------------------------------------------------------- #
def test_clamp_baseline():
    """Reference: numpy's per-channel definition; it does not keep Y (that is what
    the constant-lightness clip is for)."""
    rgb = np.array([[1.5, -0.2, 0.3], [0.2, 0.3, 0.4], [np.nan, 0.1, 2.0]])
    out = clip.clamp_RGB(rgb)
    np.testing.assert_array_equal(out[:2], [[1.0, 0.0, 0.3], [0.2, 0.3, 0.4]])
    assert np.isnan(out[2, 0]) and out[2, 2] == 1.0
    luminance = colorimetry.RGB_to_XYZ(np.eye(3))[:, 1]
    assert abs(out[0] @ luminance - rgb[0] @ luminance) > 0.03


def _aces_reference(rgb, params=clip.ACES_GAMUT_COMP13_PARAMS):
    """The ACES 1.3 reference gamut compression (Academy LMT, 'parabolic'
    power-curve form) written out from its published CTL."""
    lim = np.array(params[:3])
    thr = np.array(params[3:6])
    pwr = params[6]
    scale = (lim - thr) / np.power(np.power((1.0 - thr) / (lim - thr), -pwr) - 1.0, 1.0 / pwr)
    ach = rgb.max(axis=-1, keepdims=True)
    with np.errstate(divide="ignore", invalid="ignore"):
        dist = np.where(ach == 0, 0.0, (ach - rgb) / np.abs(ach))
    nd = (dist - thr) / scale
    cdist = np.where(
        dist < thr, dist, thr + scale * nd / np.power(1.0 + np.power(np.abs(nd), pwr), 1.0 / pwr)
    )
    return ach - cdist * np.abs(ach)


def test_aces_gamut_compress_baseline():
    """Reference: the ACES 1.3 gamut compression formula in numpy; OCIO's
    FixedFunction ACES_GamutComp13 (float32) then the clamp must match it."""
    rng = np.random.default_rng(6)
    rgb = np.concatenate(
        [
            rng.uniform(-0.3, 1.2, (2000, 3)),
            colorimetry.XYZ_to_RGB(colorimetry.spectral_locus_XYZ(0.3)),
        ]
    )
    out = clip.aces_gamut_compress_RGB(rgb)
    assert out.shape == rgb.shape and out.dtype == np.float32
    expected = np.clip(_aces_reference(rgb), 0.0, 1.0)
    np.testing.assert_allclose(out, expected, atol=2e-5)
    # Colours well inside the gamut (all distances below the thresholds) pass through.
    inner = np.array([[0.5, 0.45, 0.48], [0.9, 0.8, 0.85]])
    np.testing.assert_allclose(clip.aces_gamut_compress_RGB(inner), inner, atol=1e-6)
    # It holds max(RGB) (not Y) where nothing is clamped.
    q = np.array([[0.8, -0.05, 0.3]])
    assert clip.aces_gamut_compress_RGB(q)[0, 0] == pytest.approx(0.8, abs=1e-6)
    assert clip.aces_gamut_compress_RGB(q)[0, 1] >= 0.0
