"""Spectral models (paper Section 2) against independent references.

References used: the paper's formulas evaluated directly with numpy, mpmath at 50
digits for Eq. 9 next to its 0/0 points, colour-science's transfer-matrix method
(``colour.phenomena.thin_film_tmm`` / ``multilayer_tmm``), a textbook Airy/Fresnel
evaluation in mpmath (``conftest.mp_airy_R``) where colour cannot be used (total
internal reflection, absorbing media at oblique incidence), and energy conservation.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from conftest import colour_multilayer_R, colour_thin_film_R, mp_airy_R
from ocio_thinfilm.physics import exact, sampling, spectra

WL_10 = np.arange(380.0, 781.0, 10.0)


# --------------------------------------------------------------------------- #
# Eq. 7 / 8: two-beam sin^2 / cos^2
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("phase_change", [True, False])
def test_two_beam_is_sin2_cos2(phase_change):
    """Reference: Eq. 7 / 8 evaluated directly, sin^2(2 pi t'/l) and cos^2(2 pi t'/l)."""
    t = np.linspace(0.0, 5000.0, 257)
    wl = sampling.wavelength_grid(step=1.0)
    x = 2.0 * np.pi * t[:, None] / wl[None, :]
    expected = np.sin(x) ** 2 if phase_change else np.cos(x) ** 2
    got = spectra.two_beam_reflectance(t, wl, phase_change=phase_change)
    assert got.shape == (t.size, wl.size)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12)


def test_two_beam_broadcasts_thickness_in_front_of_wavelength():
    """Reference: the scalar evaluation of the same formula, element by element."""
    t = np.array([[0.0, 120.0, 333.3], [1000.0, 1e4, 2.5e4]])
    wl = np.array([400.0, 550.0, 700.0])
    got = spectra.two_beam_reflectance(t, wl)
    assert got.shape == (2, 3, 3)
    for idx in np.ndindex(t.shape):
        for k, w in enumerate(wl):
            assert got[idx + (k,)] == pytest.approx(np.sin(2 * np.pi * t[idx] / w) ** 2, abs=1e-12)


def test_thin_soap_film_is_black_and_quarter_wave_is_bright():
    """Reference: the paper's physics: t -> 0 gives black (Section 2, soap film
    top); t' = lambda/4 gives the peak of Eq. 7."""
    wl = np.array([400.0, 500.0, 600.0])
    assert np.all(spectra.two_beam_reflectance(0.0, wl) == 0.0)
    assert np.all(spectra.two_beam_reflectance(0.0, wl, phase_change=False) == 1.0)
    np.testing.assert_allclose(
        spectra.two_beam_reflectance(125.0, np.array([500.0])), 1.0, atol=1e-15
    )


# --------------------------------------------------------------------------- #
# Optical thickness: Eq. 10 form (refraction) against literal Eq. 11
# --------------------------------------------------------------------------- #
def test_optical_thickness_refraction_form_matches_snell():
    """Reference: Snell's law, theta_t = asin(sin(theta)/n), t' = t n cos(theta_t)."""
    t, n = 400.0, 1.33
    theta = np.array([0.0, 10.0, 30.0, 45.0, 60.0, 75.0, 89.0, 90.0])
    theta_t = np.arcsin(np.sin(np.deg2rad(theta)) / n)
    np.testing.assert_allclose(
        spectra.optical_thickness(t, n, theta), t * n * np.cos(theta_t), rtol=1e-13
    )


def test_optical_thickness_literal_eq11_differs_away_from_normal():
    """Reference: Eq. 11 as printed (t n cos theta). The two forms agree at normal
    incidence and differ by the documented 34 % at 60 degrees for n = 1.33."""
    t, n = 400.0, 1.33
    assert spectra.optical_thickness(t, n, 0.0) == pytest.approx(t * n, rel=1e-15)
    assert spectra.optical_thickness(t, n, 0.0, mode="literal") == pytest.approx(t * n, rel=1e-15)
    literal = spectra.optical_thickness(t, n, 60.0, mode="literal")
    refraction = spectra.optical_thickness(t, n, 60.0)
    assert literal == pytest.approx(t * n * 0.5, rel=1e-13)
    assert refraction == pytest.approx(t * np.sqrt(n * n - 0.75), rel=1e-13)
    assert 1.0 - literal / refraction == pytest.approx(0.341, abs=1e-3)
    with pytest.raises(ValueError, match="mode"):
        spectra.optical_thickness(t, n, 10.0, mode="sideways")


# --------------------------------------------------------------------------- #
# Eq. 9: Anderson & Richards multilayer
# --------------------------------------------------------------------------- #
def _closed_form_eq9(x, layers):
    """Eq. 9 as printed (without the 1/2), divided by its peak (l+1)^2."""
    return (np.sin((layers + 1) * x) / np.sin(x)) ** 2 / (layers + 1) ** 2


def _multilayer_at_x(x, layers):
    """Our Eq. 9 at x = 2 pi t / lambda for lambda = 500 nm."""
    wl = np.array([500.0])
    return spectra.multilayer_reflectance(x * 500.0 / (2.0 * np.pi), wl, layers)[..., 0]


@pytest.mark.parametrize("layers", [1, 2, 5, 12, 100])
def test_multilayer_matches_closed_form_away_from_poles(layers):
    """Reference: Eq. 9 closed form sin^2((l+1)x) / sin^2 x / (l+1)^2 with numpy,
    where |sin x| > 1e-3 so the closed form itself is well conditioned."""
    x = np.linspace(0.0, 6.0 * np.pi, 20001)
    x = x[np.abs(np.sin(x)) > 1e-3]
    got = _multilayer_at_x(x, layers)
    np.testing.assert_allclose(got, _closed_form_eq9(x, layers), rtol=1e-8, atol=1e-11)


@pytest.mark.parametrize("layers", [1, 12, 100])
@pytest.mark.parametrize("m", [0, 1, 2, 7])
def test_multilayer_exact_and_smooth_at_the_poles(layers, m):
    """Reference: mpmath at 50 digits of the closed form (sin((l+1)x)/sin x)^2/(l+1)^2
    at x = m pi + delta; at delta = 0 the analytic limit 1. Shows no NaN and no
    cancellation spike: naive float64 evaluation of the closed form is checked to
    be far off at 1e-9 (so this test would notice a naive implementation)."""
    import mpmath as mp

    deltas = np.array([0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-7, -1e-7, 1e-5, -1e-5, 1e-3, -1e-3])
    if m == 0:
        deltas = np.abs(deltas)  # thickness >= 0
    t = (m * np.pi + deltas) * 500.0 / (2.0 * np.pi)
    got = spectra.multilayer_reflectance(t, np.array([500.0]), layers)[:, 0]
    assert np.all(np.isfinite(got))
    with mp.workdps(50):
        expected = []
        for ti in t:
            x = 2 * mp.pi * mp.mpf(float(ti)) / 500
            if abs(mp.sin(x)) < mp.mpf(10) ** -30:  # x = m pi up to 50-digit pi
                expected.append(1.0)
            else:
                expected.append(
                    float((mp.sin((layers + 1) * x) / mp.sin(x)) ** 2 / (layers + 1) ** 2)
                )
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-9)
    assert np.all(got <= 1.0 + 1e-12)
    # Monotone towards the peak from both sides: no spike next to the pole.
    assert got[0] == pytest.approx(1.0, abs=1e-12)
    if m > 0:
        naive = _closed_form_eq9(2 * np.pi * t / 500.0, layers)
        assert not np.all(np.abs(naive - np.asarray(expected)) < 1e-9) or layers == 1


@pytest.mark.parametrize("layers", [1, 3, 12, 100])
def test_multilayer_peak_is_one_and_range(layers):
    """Reference: the Fejer kernel's known extrema: max (l+1)^2 at sin x = 0 (so 1
    after normalisation) and min 0."""
    x = np.linspace(0.0, 4.0 * np.pi, 40001)
    r = _multilayer_at_x(x, layers)
    assert r.max() == pytest.approx(1.0, abs=1e-12)
    assert r.min() >= -1e-12
    assert r[np.argmin(np.abs(x - np.pi))] == pytest.approx(1.0, abs=1e-12)


def test_multilayer_incoherent_average():
    """Reference: the mean of the Fejer kernel over a period is (l+1), so the
    normalised Eq. 9 averages to 1/(l+1)."""
    for layers in (1, 12):
        x = np.linspace(0.0, np.pi, 100001)[:-1]
        assert _multilayer_at_x(x, layers).mean() == pytest.approx(1.0 / (layers + 1), rel=1e-9)


def test_morpho_eq14_and_peak_wavelength():
    """Reference: Eq. 14 evaluated directly; Eq. 9's first-order peak sits where
    sin(2 pi t/lambda) = 0, i.e. lambda = 2 t: 453 nm at normal incidence (t = 226.5
    nm), moving to shorter wavelengths as the angle grows (below 400 nm by 35
    degrees, the paper's "about 400 nm"; it leaves the 360 nm grid near 40 degrees)."""
    theta = np.array([0.0, 10.0, 20.0, 30.0, 35.0])
    th = np.deg2rad(theta)
    eq14 = 150.0 * np.cos(th) + 50.0 * np.sqrt(1.53**2 - np.sin(th) ** 2)
    t = spectra.morpho_layer_thickness(theta)
    np.testing.assert_allclose(t, eq14, rtol=1e-14)
    assert t[0] == pytest.approx(226.5, abs=1e-12)
    wl = sampling.wavelength_grid(360.0, 780.0, 0.1)
    R = spectra.multilayer_reflectance(t, wl, spectra.MORPHO["layers"])
    peaks = wl[np.argmax(R, axis=-1)]
    assert peaks[0] == pytest.approx(453.0, abs=0.1)
    np.testing.assert_allclose(peaks, 2.0 * eq14, atol=0.1)
    assert np.all(np.diff(peaks) < 0)
    assert peaks[-1] < 400.0


# --------------------------------------------------------------------------- #
# Exact physics: Airy and transfer matrices against colour-science
# --------------------------------------------------------------------------- #
THICKNESSES = np.array([0.0, 1.0, 10.0, 100.0, 250.0, 777.0, 2000.0, 10000.0])
ANGLES = np.array([0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.9])


@pytest.mark.parametrize("n_film", [1.2, 1.33, 1.5, 2.4])
@pytest.mark.parametrize("n_substrate", [1.0, 1.5, 3.0])
def test_airy_and_tmm_match_colour_thin_film_tmm(n_film, n_substrate):
    """Reference: colour.phenomena.thin_film_tmm (Byrnes-style TMM), (R_s+R_p)/2,
    over thickness x angle (to 89.9 degrees) x wavelength. max |dR| <= 1e-9."""
    ref = colour_thin_film_R([1.0, n_film, n_substrate], THICKNESSES, WL_10, ANGLES)
    airy = exact.airy_reflectance(
        THICKNESSES[None, :], WL_10, n_film, ANGLES[:, None], n_substrate=n_substrate
    )
    assert airy.shape == ref.shape
    assert np.abs(airy - ref).max() <= 1e-9
    for i, d in enumerate(THICKNESSES):
        tmm = exact.transfer_matrix_reflectance(
            [n_film], [d], WL_10, ANGLES, n_substrate=n_substrate
        )
        assert np.abs(tmm - ref[:, i, :]).max() <= 1e-9


def test_airy_matches_colour_doctest_value():
    """Reference: colour's own doctest, R = 0.1215919 for air|1.5|air, 250 nm, 555 nm."""
    R = exact.airy_reflectance(250.0, np.array([555.0]), 1.5)
    assert R[0] == pytest.approx(0.1215919, abs=1e-7)


@pytest.mark.parametrize("n_substrate", [1.5 + 0.3j, 0.2 + 3.0j, 2.0 + 0.01j])
def test_complex_substrate_normal_incidence_matches_colour(n_substrate):
    """Reference: colour's thin_film_tmm with an absorbing substrate at normal
    incidence (where colour's real-angle Snell law is exact)."""
    ref = colour_thin_film_R([1.0, 1.38, n_substrate], THICKNESSES, WL_10, [0.0])
    airy = exact.airy_reflectance(THICKNESSES, WL_10, 1.38, 0.0, n_substrate=n_substrate)
    assert np.abs(airy - ref[0]).max() <= 1e-9
    tmm = np.stack(
        [
            exact.transfer_matrix_reflectance([1.38], [d], WL_10, 0.0, n_substrate=n_substrate)
            for d in THICKNESSES
        ]
    )
    assert np.abs(tmm - ref[0]).max() <= 1e-9


# colour 0.4.7's snell_law takes np.real of the indices and
# polarised_light_magnitude_elements casts the angles to float, so for absorbing
# media at oblique incidence and under total internal reflection it is not a valid
# oracle (NaN or the wrong refraction angle). There we use the mpmath textbook
# evaluation instead.
MP_CASES = [
    # n0, n1, n2, theta: absorbing substrate / film at oblique incidence
    (1.0, 1.38, 1.5 + 0.3j, 45.0),
    (1.0, 2.0, 0.2 + 3.0j, 70.0),
    (1.0, 1.5 + 0.05j, 1.0, 30.0),
    # frustrated TIR: glass | air gap | glass above the critical angle (41.8 deg)
    (1.5, 1.0, 1.5, 60.0),
    # TIR at the second interface only
    (1.5, 1.6, 1.0, 60.0),
    # near-grazing incidence
    (1.0, 1.33, 1.0, 89.99),
    (1.0, 1.0, 1.5, 89.99),
]


@pytest.mark.parametrize("n0,n1,n2,theta", MP_CASES)
def test_airy_and_tmm_match_mpmath_textbook(n0, n1, n2, theta):
    """Reference: Born & Wolf Airy/Fresnel formulas in 40-digit mpmath (conftest)."""
    d = np.array([0.0, 5.0, 50.0, 200.0, 1000.0])
    wl = np.array([380.0, 450.0, 555.0, 700.0])
    expected = np.array([[mp_airy_R(n0, n1, n2, di, w, theta) for w in wl] for di in d])
    airy = exact.airy_reflectance(d, wl, n1, theta, n_incident=n0, n_substrate=n2)
    tmm = np.stack(
        [
            exact.transfer_matrix_reflectance([n1], [di], wl, theta, n_incident=n0, n_substrate=n2)
            for di in d
        ]
    )
    np.testing.assert_allclose(airy, expected, rtol=0, atol=1e-9)
    np.testing.assert_allclose(tmm, expected, rtol=0, atol=1e-9)


@pytest.mark.parametrize(
    "n0,n1,n2,theta", [(1.5, 1.0, 1.0, 60.0), (1.5, 1.33, 1.0, 70.0), (1.5, 1.6, 1.0, 60.0)]
)
def test_lossless_total_internal_reflection_is_total(n0, n1, n2, theta):
    """Reference: energy conservation. Lossless media, and the substrate cannot carry
    a propagating wave (n2 < n0 sin theta), so nothing is transmitted or absorbed:
    R = 1 exactly, for every thickness and wavelength."""
    assert n2 <= n0 * np.sin(np.deg2rad(theta))
    d = np.array([0.0, 3.0, 80.0, 400.0, 5000.0])
    airy = exact.airy_reflectance(d, WL_10, n1, theta, n_incident=n0, n_substrate=n2)
    np.testing.assert_allclose(airy, 1.0, rtol=0, atol=1e-12)
    for di in d:
        tmm = exact.transfer_matrix_reflectance(
            [n1], [di], WL_10, theta, n_incident=n0, n_substrate=n2
        )
        np.testing.assert_allclose(tmm, 1.0, rtol=0, atol=1e-12)


def test_frustrated_tir_limits():
    """Reference: physics of frustrated TIR (glass | air gap | glass, 60 degrees):
    no gap -> no interface (R = 0); a gap many decay lengths thick -> R -> 1;
    in between R rises monotonically."""
    d = np.array([0.0, 10.0, 50.0, 100.0, 200.0, 400.0, 2000.0])
    R = exact.airy_reflectance(d, np.array([550.0]), 1.0, 60.0, n_incident=1.5, n_substrate=1.5)[
        :, 0
    ]
    assert R[0] == pytest.approx(0.0, abs=1e-15)
    assert R[-1] == pytest.approx(1.0, abs=1e-9)
    assert np.all(np.diff(R) > 0)


@pytest.mark.parametrize(
    "stack",
    [
        ([1.5, 2.0, 1.38], [100.0, 230.0, 50.0], 1.52),
        ([2.3, 1.38, 2.3, 1.38], [60.0, 100.0, 60.0, 100.0], 1.0),
        ([1.33, 1.7, 1.2, 2.1, 1.45], [1000.0, 12.5, 333.0, 80.0, 0.0], 3.5),
    ],
)
def test_tmm_multilayer_matches_colour(stack):
    """Reference: colour.phenomena.multilayer_tmm for 3-5 layer stacks, all angles."""
    n_layers, d, ns = stack
    ref = colour_multilayer_R([1.0, *n_layers, ns], d, WL_10, ANGLES)
    got = exact.transfer_matrix_reflectance(n_layers, d, WL_10, ANGLES, n_substrate=ns)
    assert got.shape == ref.shape
    assert np.abs(got - ref).max() <= 1e-9


def test_tmm_periodic_stack_matches_eq9_peak_position():
    """Reference: a quarter-wave high/low stack reflects most at its design
    wavelength (textbook Bragg mirror), and its R approaches 1 as layers are added."""
    design = 550.0
    nh, nl = 2.3, 1.38
    wl = np.array([450.0, 550.0, 650.0])
    Rs = []
    for pairs in (2, 4, 8):
        n_layers = [nh, nl] * pairs
        d = [design / (4 * nh), design / (4 * nl)] * pairs
        R = exact.transfer_matrix_reflectance(n_layers, d, wl, 0.0, n_substrate=1.52)
        assert R[1] == R.max()
        Rs.append(R[1])
    assert Rs[0] < Rs[1] < Rs[2] and Rs[2] > 0.99


# --------------------------------------------------------------------------- #
# Bad input
# --------------------------------------------------------------------------- #
WL = np.array([400.0, 500.0, 600.0])
BAD_CALLS = [
    ("thickness", lambda: spectra.optical_thickness(-1.0, 1.33)),
    ("n", lambda: spectra.optical_thickness(100.0, 0.0)),
    ("n", lambda: spectra.optical_thickness(100.0, -1.33)),
    ("theta", lambda: spectra.optical_thickness(100.0, 1.33, -0.1)),
    ("theta", lambda: spectra.optical_thickness(100.0, 1.33, 90.5)),
    ("theta", lambda: spectra.optical_thickness(100.0, 1.33, np.nan)),
    ("optical_thickness", lambda: spectra.two_beam_reflectance(-5.0, WL)),
    ("optical_thickness", lambda: spectra.two_beam_reflectance([10.0, np.inf], WL)),
    ("wavelengths", lambda: spectra.two_beam_reflectance(100.0, [])),
    ("wavelengths", lambda: spectra.two_beam_reflectance(100.0, [500.0, 400.0])),
    ("wavelengths", lambda: spectra.two_beam_reflectance(100.0, [400.0, 400.0, 500.0])),
    ("wavelengths", lambda: spectra.two_beam_reflectance(100.0, [-400.0, 500.0])),
    ("wavelengths", lambda: sampling.check_wavelengths(np.ones((2, 2)))),
    ("step", lambda: sampling.wavelength_grid(step=0.0)),
    ("wavelength range", lambda: sampling.wavelength_grid(700.0, 400.0)),
    ("theta", lambda: spectra.morpho_layer_thickness(91.0)),
    ("d1", lambda: spectra.morpho_layer_thickness(0.0, d1=-1.0)),
    ("d2", lambda: spectra.morpho_layer_thickness(0.0, d2=-1.0)),
    ("n", lambda: spectra.morpho_layer_thickness(0.0, n=0.0)),
    ("thickness", lambda: spectra.multilayer_reflectance(-1.0, WL, 12)),
    ("layers", lambda: spectra.multilayer_reflectance(100.0, WL, 0)),
    ("layers", lambda: spectra.multilayer_reflectance(100.0, WL, -3)),
    ("layers", lambda: spectra.multilayer_reflectance(100.0, WL, 2.5)),
    ("wavelengths", lambda: spectra.multilayer_reflectance(100.0, [600.0, 500.0], 12)),
    ("thickness", lambda: exact.airy_reflectance(-1.0, WL, 1.5)),
    ("n_film", lambda: exact.airy_reflectance(100.0, WL, 0.0)),
    ("n_film", lambda: exact.airy_reflectance(100.0, WL, -0.5 + 1j)),
    ("n_incident", lambda: exact.airy_reflectance(100.0, WL, 1.5, n_incident=-1.0)),
    ("n_substrate", lambda: exact.airy_reflectance(100.0, WL, 1.5, n_substrate=0.0)),
    ("theta", lambda: exact.airy_reflectance(100.0, WL, 1.5, 100.0)),
    ("wavelengths", lambda: exact.airy_reflectance(100.0, [], 1.5)),
    ("harmonics", lambda: exact.airy_reflectance(100.0, WL, 1.5, band_limited=True, harmonics=0)),
    ("thicknesses", lambda: exact.transfer_matrix_reflectance([1.5], [-1.0], WL)),
    ("n_layers", lambda: exact.transfer_matrix_reflectance([0.0], [10.0], WL)),
    ("n_substrate", lambda: exact.transfer_matrix_reflectance([1.5], [10.0], WL, n_substrate=-2.0)),
    ("theta", lambda: exact.transfer_matrix_reflectance([1.5], [10.0], WL, -5.0)),
    ("wavelengths", lambda: exact.transfer_matrix_reflectance([1.5], [10.0], [5.0, 4.0])),
    ("n_layers", lambda: exact.transfer_matrix_reflectance([1.5, 2.0], [10.0], WL)),
]


@pytest.mark.parametrize(
    "name,call", BAD_CALLS, ids=[f"{i}-{c[0]}" for i, c in enumerate(BAD_CALLS)]
)
def test_bad_input_raises_value_error_naming_the_parameter(name, call):
    """Reference: the package's argument contract (ocio_thinfilm.checks) -- a
    ValueError whose message names the parameter."""
    with pytest.raises(ValueError) as info:
        call()
    assert name in str(info.value)


def test_range_messages_state_the_allowed_range():
    """Reference: the package's argument contract (ocio_thinfilm.checks) -- the
    message gives the allowed range."""
    with pytest.raises(ValueError, match=r"theta.*\[0, 90\]"):
        spectra.optical_thickness(1.0, 1.33, 95.0)
    with pytest.raises(ValueError, match=r"thickness.*>= 0"):
        spectra.multilayer_reflectance(-1.0, WL, 12)
    with pytest.raises(ValueError, match=r"n.*> 0"):
        spectra.optical_thickness(1.0, 0.0)
    with pytest.raises(ValueError, match=r"layers.*\[1, 100000\]"):
        spectra.multilayer_reflectance(1.0, WL, 0)


# --------------------------------------------------------------------------- #
# Valid input never gives NaN (property test)
# --------------------------------------------------------------------------- #
@given(
    seed=st.integers(0, 2**32 - 1),
    t_scale=st.sampled_from([0.0, 1.0, 100.0, 1e4, 1e5]),
    n=st.one_of(st.sampled_from([1.0, 1.5, 0.5]), st.floats(0.05, 4.0)),
    n_sub=st.one_of(st.sampled_from([1.0, 1.5]), st.floats(0.05, 4.0)),
    n_inc=st.sampled_from([1.0, 1.33, 1.5]),
    theta=st.one_of(st.sampled_from([0.0, 90.0, 89.999999]), st.floats(0.0, 90.0)),
    band_limited=st.booleans(),
    step=st.sampled_from([0.5, 5.0, 10.0]),
)
def test_valid_input_never_nan(seed, t_scale, n, n_sub, n_inc, theta, band_limited, step):
    """Reference: physical bounds -- every model gives a finite R in [0, 1] for any
    valid thickness, index, angle (0 and 90 included) and wavelength grid."""
    rng = np.random.default_rng(seed)
    t = rng.uniform(0.0, 1.0, 64) * t_scale
    t[0] = 0.0
    wl = sampling.wavelength_grid(360.0, 780.0, step)
    results = [
        spectra.optical_thickness(t, n, theta),
        spectra.optical_thickness(t, n, theta, mode="literal"),
        spectra.two_beam_reflectance(t, wl, band_limited=band_limited),
        spectra.two_beam_reflectance(t, wl, phase_change=False, band_limited=band_limited),
        spectra.multilayer_reflectance(t, wl, 12, band_limited=band_limited),
        spectra.multilayer_reflectance(
            spectra.morpho_layer_thickness(theta), wl, 100, band_limited=band_limited
        ),
        exact.airy_reflectance(
            t[:8], wl, n, theta, n_incident=n_inc, n_substrate=n_sub, band_limited=band_limited
        ),
        exact.transfer_matrix_reflectance(
            [n, n_sub], t[1:3], wl, theta, n_incident=n_inc, n_substrate=n_inc
        ),
    ]
    for k, r in enumerate(results):
        assert np.all(np.isfinite(r)), k
        if k >= 2:
            assert r.min() >= -1e-9 and r.max() <= 1.0 + 1e-9, k


@pytest.mark.parametrize("n1,n2", [(1.33, 1.0), (1.0, 1.5), (1.5, 1.2), (1.0, 1.0)])
def test_exact_grazing_incidence_is_the_limit(n1, n2):
    """Reference: the limit theta -> 90 degrees, taken numerically from the mpmath
    textbook evaluation at 90 - 1e-7 degrees (R -> 1 wherever there is an interface;
    R = 0 for an index-matched stack; and the film drops out where it is absent: d = 0)."""
    d = np.array([0.0, 5.0, 100.0, 1000.0])
    wl = np.array([400.0, 600.0])
    expected = np.array([[mp_airy_R(1.0, n1, n2, di, w, 90.0 - 1e-7) for w in wl] for di in d])
    airy = exact.airy_reflectance(d, wl, n1, 90.0, n_substrate=n2)
    tmm = np.stack(
        [exact.transfer_matrix_reflectance([n1], [di], wl, 90.0, n_substrate=n2) for di in d]
    )
    np.testing.assert_allclose(airy, expected, atol=1e-5)
    np.testing.assert_allclose(tmm, expected, atol=1e-5)
