"""Stability on stiff and extreme cases: one test per row of the report's table
(``evaluation.report.stability_rows``; the row names its test). The rows
are defined once, in ``evaluation.stability`` (the physics and OCIO rows
as ``Row``, the clip's extreme XYZ inputs as ``Case``): the report lists them,
``test_stability_row`` and ``test_xyz_stability_case`` run each one, and the
``..._checks_can_fail`` tests show that each check rejects a wrong value. A row whose
test is ``test_stability_row`` is held by its own check alone; the detailed tests named
by the other rows add what the row does not cover (other kinds, angles, inputs, code
paths), without repeating it.

Every expectation here is independent of the code under test: physical limits
(incoherent average = half the illuminant, total internal reflection R = 1, the
Fresnel reflectance of a bare interface), colour-science's own integration and
transfer-matrix method, mpmath at 50 digits, or the geometry of the unit RGB cube.
"""

from __future__ import annotations

import functools
import warnings

import numpy as np
import pytest

from conftest import fresnel_R
from evaluation import stability
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import clip_lut, ocio_ops
from ocio_thinfilm.physics import exact, sampling, spectra

WL = sampling.wavelength_grid()


@pytest.fixture(scope="module")
def white():
    """The perfect reflector under D65 by colour-science's ``sd_to_XYZ`` (Y = 1)."""
    import colour

    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        xyz = np.asarray(
            colour.sd_to_XYZ(colour.sd_ones(), cmfs, illuminant=colour.SDS_ILLUMINANTS["D65"])
        )
    return xyz / xyz[1]


# --------------------------------------------------------------------------- #
# Thick films, t = 0
# --------------------------------------------------------------------------- #
# The rows of evaluation/stability.py run in test_stability_row below; the tests here
# add what a row does not cover (other kinds, angles, inputs and code paths).
def test_thick_film_tends_to_half_white(white):
    """The row holds the phase-change film; the no-phase-change film tends to the same
    incoherent limit."""
    for t in (1e4, 3e4, 1e5):
        xyz = colorimetry.film_XYZ(t, kind="no-phase-change")
        assert np.all(np.isfinite(xyz))
        assert colorimetry.delta_E2000(xyz, 0.5 * white) < 0.5, t


def test_zero_thickness():
    """Beyond the row's XYZ: Eq. 8's spectrum itself is 1 at every wavelength."""
    r = spectra.two_beam_reflectance(0.0, WL, phase_change=False)
    assert np.array_equal(r, np.ones_like(r))  # cos^2(0) = 1


def test_zero_thickness_exact_film():
    """Beyond the row's normal incidence: a vanishing film on glass is the bare
    interface's Fresnel reflectance at every angle."""
    for theta in (30.0, 60.0, 85.0):
        r = exact.airy_reflectance(0.0, WL, 1.33, theta, n_substrate=1.5)
        assert np.allclose(r, fresnel_R(1.0, 1.5, theta), rtol=0, atol=1e-12)
    assert abs(fresnel_R(1.0, 1.5, 0.0) - 0.04) < 1e-15  # the row's value, by hand


# --------------------------------------------------------------------------- #
# Grazing incidence, total internal reflection
# --------------------------------------------------------------------------- #
def test_grazing_matches_colour_tmm():
    """The row compares the exact film with colour's TMM at 89.9°; the optical
    thickness there is the Eq. 10 form t sqrt(n^2 - sin^2 theta)."""
    t = spectra.optical_thickness(300.0, 1.33, 89.9)
    expected = 300.0 * np.sqrt(1.33**2 - np.sin(np.radians(89.9)) ** 2)
    assert np.isfinite(t) and abs(t - expected) < 1e-9


@pytest.mark.parametrize("theta", [45.0, 60.0, 89.9])
def test_total_internal_reflection(theta):
    # glass 1.5 -> film 1.0 -> medium 1.0: beyond asin(1/1.5) = 41.8 degrees nothing
    # propagates past the first interface, whatever the film's thickness.
    d = np.array([0.0, 10.0, 300.0, 3000.0])
    r = exact.airy_reflectance(d, WL, 1.0, theta, n_incident=1.5)
    rb = exact.airy_reflectance(d, WL, 1.0, theta, n_incident=1.5, band_limited=True)
    rt = exact.transfer_matrix_reflectance([1.0], [300.0], WL, theta, n_incident=1.5)
    for x in (r, rb, rt):
        assert np.all(np.isfinite(x))
        assert np.abs(x - 1.0).max() < 1e-12


def test_frustrated_tir():
    gaps = np.array([10.0, 100.0, 300.0, 1000.0, 3000.0])
    r = exact.airy_reflectance(gaps, WL, 1.0, 60.0, n_incident=1.5, n_substrate=1.5)
    t = np.stack(
        [
            exact.transfer_matrix_reflectance([1.0], [g], WL, 60.0, n_incident=1.5, n_substrate=1.5)
            for g in gaps
        ]
    )
    assert np.abs(r - t).max() < 1e-9  # two different algorithms agree
    assert np.all(np.diff(r, axis=0) > 0)  # the tunnelling falls with the gap
    assert r[0].max() < 0.2 and abs(r[-1].mean() - 1.0) < 1e-6
    assert np.all((r >= 0) & (r <= 1 + 1e-12))


# --------------------------------------------------------------------------- #
# Eq. 9 near its singular points
# --------------------------------------------------------------------------- #
def test_eq9_near_singular_points():
    """The row holds the point values against mpmath; band-limited and thick, Eq. 9
    stays finite and within [0, 1]."""
    r = spectra.multilayer_reflectance(np.array([226.5, 1e4, 1e5]), WL, 100, band_limited=True)
    assert np.all(np.isfinite(r)) and r.min() >= -1e-12 and r.max() <= 1 + 1e-12


# --------------------------------------------------------------------------- #
# float32 vs float64
# --------------------------------------------------------------------------- #
def test_float32_vs_float64():
    """The row holds clip_RGB and film_XYZ; clip_XYZ keeps float32 too, and float64 in
    gives float64 out."""
    rgb = np.random.default_rng(5).uniform(-2, 3, (10000, 3))
    assert clip.clip_RGB(rgb).dtype == np.float64
    x32 = clip.clip_XYZ((rgb @ np.linalg.inv(colorimetry.matrix_XYZ_to_RGB()).T).astype(np.float32))
    assert x32.dtype == np.float32


# --------------------------------------------------------------------------- #
# XYZ inputs to the clip
# --------------------------------------------------------------------------- #
M = colorimetry.matrix_XYZ_to_RGB("sRGB")
MINV = np.linalg.inv(M)
W = MINV @ np.ones(3)  # display white: RGB = 1


def _in_gamut(xyz, tol=1e-9):
    rgb = np.asarray(xyz, dtype=np.float64) @ M.T
    return np.all(np.isfinite(rgb)) and rgb.min() >= -tol and rgb.max() <= 1 + tol


def test_xyz_negative_and_zero_give_black():
    for xyz in ([-0.1, -0.2, -0.1], [0.0, 0.0, 0.0], [0.5, -1e-12, 0.5], [5.0, -0.1, 5.0]):
        assert np.array_equal(clip.clip_XYZ(np.array(xyz)), np.zeros(3))
    assert np.array_equal(clip.clip_RGB(np.array([-0.1, -0.1, -0.1])), np.zeros(3))


def test_xyz_above_white_gives_white():
    for xyz in (2 * W, [0.5, 1.5, 0.5], [0.0, 1.0 + 1e-9, 0.0], W):
        assert np.allclose(clip.clip_XYZ(np.array(xyz, dtype=float)), W, atol=1e-12)
    assert np.array_equal(clip.clip_RGB(np.array([2.0, 2.0, 2.0])), np.ones(3))


def _limit_along(direction, Y):
    """The clip's limit for a huge component along ``direction``: the geometry of the
    unit RGB cube (:func:`evaluation.stability.limit_along`)."""
    return stability.limit_along(M, W, np.asarray(direction, float), Y)


def test_xyz_huge_and_infinite_components():
    for axis in range(3):
        if axis == 1:
            continue
        for sign in (1.0, -1.0):
            direction = np.zeros(3)
            direction[axis] = sign
            expected = _limit_along(direction, 0.5)
            for big in (1e30, np.inf):
                x = np.array([0.3, 0.5, 0.3])
                x[axis] = sign * big
                out = clip.clip_XYZ(x)
                assert np.all(np.isfinite(out)) and _in_gamut(out)
                assert abs(out[1] - 0.5) < 1e-12
                assert np.allclose(out, expected, atol=1e-9), (axis, sign, big)
    out = clip.clip_RGB(np.array([np.inf, 0.2, -np.inf]))
    assert np.all(np.isfinite(out)) and out.min() >= 0 and out.max() <= 1


def test_xyz_infinite_luminance():
    out = clip.clip_XYZ(np.array([[0.3, np.inf, 0.3], [0.3, -np.inf, 0.3], [np.inf] * 3]))
    assert np.allclose(out[0], W) and np.array_equal(out[1], np.zeros(3))
    assert np.allclose(out[2], W)


def test_xyz_nan_stays_in_its_pixel():
    good = np.array([0.2, 0.3, 0.9])
    for bad in ([np.nan, 0.5, 0.5], [0.5, np.nan, 0.5], [np.nan] * 3):
        out = clip.clip_XYZ(np.array([bad, good]))
        assert np.all(np.isnan(out[0]))
        assert np.allclose(out[1], clip.clip_XYZ(good), rtol=0, atol=1e-15)
        assert _in_gamut(out[1])
    out = clip.clip_RGB(np.array([[np.nan, 0.5, 0.5], [2.0, 0.1, 0.1]]))
    assert np.all(np.isnan(out[0])) and np.all(np.isfinite(out[1]))


def test_xyz_on_faces_and_edges_unchanged():
    vals = [0.0, 0.37, 1.0]
    rgb = np.array([[a, b, c] for a in vals for b in vals for c in vals])
    assert np.array_equal(clip.clip_RGB(rgb), rgb)  # bit for bit in the RGB form
    xyz = rgb @ MINV.T
    assert np.abs(clip.clip_XYZ(xyz) - xyz).max() < 1e-12  # only XYZ<->RGB round-off


def test_rays_nearly_parallel_to_a_face():
    lum = MINV[1]
    g = 0.4
    rows = []
    for delta in (1e-15, -1e-15, 1e-12, -1e-12, 1e-9, 1e-6, -1e-6, 0.0):
        a = 3.0  # far above the G = 1 face
        b = -(lum[0] * delta + lum[1] * a) / lum[2]  # same luminance as the grey
        rows.append([g + delta, g + a, g + b])
    rgb = np.array(rows)
    xyz = rgb @ MINV.T
    out = clip.clip_XYZ(xyz)
    assert np.all(np.isfinite(out)) and _in_gamut(out, 1e-12)
    assert np.allclose(out[:, 1], xyz[:, 1], rtol=1e-9)
    assert np.abs(out @ M.T - clip.clip_RGB(rgb)).max() < 1e-9  # both forms agree
    # Nearly grazing the R = 1 face from just outside it, grey just below white.
    Y = W[1] * (1 - 1e-12)
    x = np.array([1 + 1e-12, 1.0 - 5e-12, 1.0]) @ MINV.T
    x = x * (Y / x[1])
    out = clip.clip_XYZ(x)
    assert np.all(np.isfinite(out)) and _in_gamut(out, 1e-9)


XYZ_CASES = stability.xyz_cases()


@pytest.mark.parametrize("case", XYZ_CASES, ids=[c.name for c in XYZ_CASES])
def test_xyz_stability_case(case):
    """Each shared case (the rows of the report's table) through the analytic clip."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ok, observed = case.check(clip.clip_XYZ(case.inputs))
    assert ok, f"{case.name}: expected {case.expected}; observed {observed}"


def test_xyz_stability_cases_name_their_tests():
    """Every shared case names a detailed test of this module, and the list is not empty."""
    assert len(XYZ_CASES) >= 10
    for case in XYZ_CASES:
        assert callable(globals().get(case.test)), case.test


def test_xyz_stability_case_checks_can_fail():
    """The checks reject a wrong output (a check that always passed would be no test)."""
    for case in XYZ_CASES:
        wrong = np.full_like(case.inputs, 0.123)
        ok, _ = case.check(wrong)
        assert not ok, case.name


# --------------------------------------------------------------------------- #
# The shared physics and OCIO rows (the report's table)
# --------------------------------------------------------------------------- #
ROWS = stability.physics_rows() + stability.ocio_clip_rows()


@functools.cache
def _measured(index):
    """``ROWS[index].measure()``, once per session (the check-can-fail test reuses it)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ROWS[index].measure()


@pytest.mark.parametrize("index", range(len(ROWS)), ids=[r.name for r in ROWS])
def test_stability_row(index):
    """Each shared row: the code under test meets the row's expectation."""
    row = ROWS[index]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ok, observed = row.check(_measured(index))
    assert ok, f"{row.name}: expected {row.expected}; observed {observed}"


def test_stability_rows_name_their_tests():
    """Every shared row names a detailed test of this module; names are unique."""
    assert len(ROWS) >= 17
    assert len({r.name for r in ROWS}) == len(ROWS)
    for row in ROWS:
        assert callable(globals().get(row.test)), row.test


@pytest.mark.parametrize("index", range(len(ROWS)), ids=[r.name for r in ROWS])
def test_stability_row_checks_can_fail(index):
    """The checks reject a wrong measurement (every value NaN, same shapes and dtypes):
    a check that always passed would be no test."""
    row = ROWS[index]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ok, observed = row.check(stability.poisoned(_measured(index)))
    assert not ok, f"{row.name}: passed on NaN ({observed})"


# --------------------------------------------------------------------------- #
# The same extremes through the shipped OCIO clip transform (the 3D LUT path)
# --------------------------------------------------------------------------- #
@pytest.fixture(scope="module")
def ocio_clip():
    tf = clip_lut.clip_transform("sRGB")
    return lambda x: ocio_ops.apply(tf, np.asarray(x, dtype=np.float64)).astype(np.float64)


def _ocio_limit_check(ocio_clip, sign):
    x = np.array([[sign * 1e30, 0.5, 0.5], [sign * np.inf, 0.5, 0.5]])
    out = ocio_clip(x)
    assert np.all(np.isfinite(out)) and out.min() >= 0 and out.max() <= 1
    expected = _limit_along(np.array([sign, 0.0, 0.0]), 0.5)  # geometry, not the clip code
    de = colorimetry.delta_E2000(out @ MINV.T, np.broadcast_to(expected, out.shape))
    assert de.max() < 5, de


def test_ocio_clip_negative_infinite_component(ocio_clip):
    """-Inf / -1e30 X: clip_lut.xyz_limit_transform keeps X+Y+Z >= 0 before XYZ_TO_xyY, so
    the chromaticity does not flip to the +X side (it did, dE2000 ~60, before that)."""
    _ocio_limit_check(ocio_clip, -1.0)


def test_ocio_clip_nan_is_finite(ocio_clip):
    """Beyond the row's single NaN components: an all-NaN pixel and NaN in Z."""
    out = ocio_clip([[np.nan] * 3, [0.5, 0.5, np.nan]])
    assert np.all(np.isfinite(out)) and out.min() >= 0 and out.max() <= 1
