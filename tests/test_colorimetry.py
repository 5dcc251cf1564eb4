"""Colorimetry and band-limited integration against independent references.

References used: colour-science's own integrators (``colour.sd_to_XYZ``, methods
"Integration" and "ASTM E308") and conversions (``colour.XYZ_to_RGB`` with derived
matrices), brute-force dense sampling (0.1 nm) for the band-limited integration,
the analytic incoherent averages of each model, and published CIEDE2000 test data
(Sharma, Wu & Dalal 2005).
"""

from __future__ import annotations

import numpy as np
import pytest

from evaluation.truth import COLOUR_SCIENCE_GAMUTS
from ocio_thinfilm import registry
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.physics import exact, sampling, spectra

OBS = "CIE 1931 2 Degree Standard Observer"
D65_XY = np.array([0.3127, 0.3290])


def colour_XYZ(colour, R, wl, observer=OBS, illuminant="D65", method="Integration"):
    """colour-science's integrator on our spectral data, rescaled to Y_white = 1."""
    sd = colour.SpectralDistribution(np.asarray(R, dtype=float), wl)
    return (
        colour.sd_to_XYZ(
            sd, colour.MSDS_CMFS[observer], colour.SDS_ILLUMINANTS[illuminant], method=method
        )
        / 100.0
    )


# --------------------------------------------------------------------------- #
# Spectrum -> XYZ
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("step,tol", [(0.5, 1e-4), (1.0, 1e-4), (5.0, 3e-4), (10.0, 1e-3)])
def test_perfect_reflector_is_the_illuminant_white(colour, step, tol):
    """Reference: colour.sd_to_XYZ of R = 1 with the same CMFs and D65 (Y = 1 by
    construction; X and Z within 1e-4 of colour's independent 1 nm integration, a
    little more on 5 / 10 nm grids where the trapezoid rule itself is coarser)."""
    wl = sampling.wavelength_grid(step=step)
    XYZ = colorimetry.reflectance_to_XYZ(np.ones(wl.size), wl)
    assert XYZ[1] == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(XYZ, colour_XYZ(colour, np.ones(wl.size), wl), atol=tol)
    np.testing.assert_allclose(colour.XYZ_to_xy(XYZ), D65_XY, atol=tol)


@pytest.mark.parametrize("t_opt", [0.0, 150.0, 399.0, 700.0, 1500.0])
@pytest.mark.parametrize("phase_change", [True, False])
def test_film_spectra_match_colour_sd_to_XYZ(colour, t_opt, phase_change):
    """Reference: colour.sd_to_XYZ ("Integration" at 1 nm; "ASTM E308" at 5 nm) on
    exactly the same film spectrum, so only the integrators differ."""
    for step, method, tol in ((1.0, "Integration", 2e-5), (5.0, "ASTM E308", 2e-5)):
        wl = sampling.wavelength_grid(step=step)
        R = spectra.two_beam_reflectance(t_opt, wl, phase_change=phase_change)
        got = colorimetry.reflectance_to_XYZ(R, wl)
        np.testing.assert_allclose(got, colour_XYZ(colour, R, wl, method=method), atol=tol)


def test_film_XYZ_is_the_integral_of_the_model(colour):
    """Reference: colour.sd_to_XYZ of Eq. 7 evaluated with numpy on a 1 nm grid,
    for film_XYZ's pointwise (band_limited=False) path over many thicknesses."""
    wl = sampling.wavelength_grid(step=1.0)
    t = np.array([0.0, 100.0, 250.0, 532.0, 1000.0])
    got = colorimetry.film_XYZ(t, wavelengths=wl, band_limited=False)
    for i, ti in enumerate(t):
        R = np.sin(2 * np.pi * ti / wl) ** 2
        np.testing.assert_allclose(got[i], colour_XYZ(colour, R, wl), atol=2e-5)


@pytest.mark.parametrize(
    "observer,illuminant",
    [
        ("CIE 1964 10 Degree Standard Observer", "D65"),
        (OBS, "A"),
        (OBS, "D50"),
        ("CIE 1964 10 Degree Standard Observer", "FL2"),
    ],
)
def test_other_observers_and_illuminants(colour, observer, illuminant):
    """Reference: colour.sd_to_XYZ with the same observer and illuminant."""
    wl = sampling.wavelength_grid(step=1.0)
    white = colorimetry.reflectance_to_XYZ(np.ones(wl.size), wl, observer, illuminant)
    assert white[1] == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(
        white, colour_XYZ(colour, np.ones(wl.size), wl, observer, illuminant), atol=2e-4
    )
    R = spectra.two_beam_reflectance(420.0, wl)
    got = colorimetry.film_XYZ(
        420.0, wavelengths=wl, band_limited=False, observer=observer, illuminant=illuminant
    )
    np.testing.assert_allclose(got, colour_XYZ(colour, R, wl, observer, illuminant), atol=2e-4)
    # ... and it really is different from the default.
    point = colorimetry.film_XYZ(420.0, wavelengths=wl, band_limited=False)
    assert np.abs(got - point).max() > 1e-3


@pytest.mark.parametrize(
    "call,name",
    [
        (
            lambda: colorimetry.spectral_weights(sampling.wavelength_grid(), observer="Martian"),
            "observer",
        ),
        (
            lambda: colorimetry.spectral_weights(sampling.wavelength_grid(), illuminant="D66"),
            "illuminant",
        ),
        (lambda: colorimetry.matrix_XYZ_to_RGB("sRGBish"), "space"),
        (lambda: colorimetry.XYZ_to_RGB([0.2, 0.3, 0.4], "Adobe RGB 9000"), "space"),
        (lambda: colorimetry.film_XYZ(100.0, kind="soapy"), "kind"),
        (lambda: colorimetry.film_XYZ(-1.0), "optical_thickness"),
        (lambda: colorimetry.film_XYZ(100.0, wavelengths=[500.0, 400.0]), "wavelengths"),
        (lambda: colorimetry.film_XYZ(100.0, step=-5.0), "step"),
        (lambda: colorimetry.morpho_XYZ(95.0), "theta"),
        (lambda: colorimetry.morpho_XYZ(10.0, layers=0), "layers"),
        (lambda: colorimetry.morpho_XYZ(10.0, n=0.0), "n"),
    ],
)
def test_bad_names_and_values_raise(call, name):
    """Reference: the package's argument contract (ocio_thinfilm.checks) -- a
    ValueError naming the parameter."""
    with pytest.raises(ValueError, match=name):
        call()


# --------------------------------------------------------------------------- #
# XYZ -> RGB
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("ours,theirs", sorted(COLOUR_SCIENCE_GAMUTS.items()))
def test_rgb_matrices_match_colour(colour, ours, theirs):
    """Reference: colour.XYZ_to_RGB from D65 XYZ (Bradford adaptation where the
    space's white is not D65, as for ACEScg and DCI-P3), with matrices derived from the
    primaries, for every gamut (evaluation/truth.py's colourspace of it). Also the round
    trip and RGB(white) = 1."""
    rng = np.random.default_rng(7)
    XYZ = rng.uniform(-0.2, 1.2, (200, 3))
    cs = colour.RGB_COLOURSPACES[theirs].copy()
    cs.use_derived_transformation_matrices(True)
    expected = colour.XYZ_to_RGB(
        XYZ, cs, illuminant=D65_XY, chromatic_adaptation_transform="Bradford"
    )
    got = colorimetry.XYZ_to_RGB(XYZ, ours)
    np.testing.assert_allclose(got, expected, atol=1e-9)
    np.testing.assert_allclose(colorimetry.RGB_to_XYZ(got, ours), XYZ, atol=1e-12)
    np.testing.assert_allclose(
        colorimetry.XYZ_to_RGB(colorimetry.white_XYZ(ours), ours), 1.0, atol=1e-12
    )


def test_srgb_matrix_close_to_the_published_iec_matrix(colour):
    """Reference: the IEC 61966-2-1 matrix colour ships for sRGB (rounded to 4
    decimals): ours is derived from the primaries, so they differ by the rounding."""
    M = colorimetry.matrix_XYZ_to_RGB("sRGB")
    np.testing.assert_allclose(M, colour.RGB_COLOURSPACES["sRGB"].matrix_XYZ_to_RGB, atol=5e-4)


def test_white_is_d65_for_every_display(colour):
    """Reference: colour's D65 chromaticity; Y of the white = 1 (scene white D65 is
    shown at a display's own white, e.g. DCI's, by a Bradford adaptation)."""
    for space in registry.ALL_DISPLAYS + tuple(COLOUR_SCIENCE_GAMUTS):
        w = colorimetry.white_XYZ(space)
        assert w[1] == pytest.approx(1.0, abs=1e-12)
        np.testing.assert_allclose(colour.XYZ_to_xy(w), D65_XY, atol=1e-12)


def test_delta_E2000_matches_published_data(colour):
    """Reference: Sharma, Wu & Dalal (2005) CIEDE2000 test pairs (Lab, D65 white)."""
    pairs = [
        ((50.0, 2.6772, -79.7751), (50.0, 0.0, -82.7485), 2.0425),
        ((50.0, 2.5, 0.0), (73.0, 25.0, -18.0), 27.1492),
        ((60.2574, -34.0099, 36.2677), (60.4626, -34.1751, 39.4387), 1.2644),
    ]
    for lab_a, lab_b, expected in pairs:
        a = colour.Lab_to_XYZ(np.array(lab_a), D65_XY)
        b = colour.Lab_to_XYZ(np.array(lab_b), D65_XY)
        assert colorimetry.delta_E2000(a, b) == pytest.approx(expected, abs=1e-4)


def test_spectral_locus(colour):
    """Reference: colour.wavelength_to_XYZ, rescaled to the requested Y."""
    for Y in (0.05, 0.5, 1.0):
        locus = colorimetry.spectral_locus_XYZ(Y)
        assert locus.shape == (321, 3)
        np.testing.assert_allclose(locus[:, 1], Y, rtol=1e-12)
        ref = colour.wavelength_to_XYZ(np.arange(380.0, 701.0))
        np.testing.assert_allclose(locus, ref * (Y / ref[:, 1:2]), rtol=1e-9, atol=1e-15)


# --------------------------------------------------------------------------- #
# Band-limited integration (thick films)
# --------------------------------------------------------------------------- #
REF_WL = sampling.wavelength_grid(step=0.1)


@pytest.fixture(scope="module")
def thick_scan():
    """t' = 0..100 um every 100 nm: 0.1 nm brute-force reference (dense sampling
    resolves >= 8 samples per fringe even at 100 um) and the 5 nm results."""
    t = np.linspace(0.0, 100_000.0, 1001)
    out = {}
    for kind in ("phase-change", "no-phase-change"):
        ref = colorimetry.film_XYZ(t, kind, wavelengths=REF_WL, band_limited=False)
        band = colorimetry.film_XYZ(t, kind, step=5.0, band_limited=True)
        naive = colorimetry.film_XYZ(t, kind, step=5.0, band_limited=False)
        out[kind] = (colorimetry.delta_E2000(band, ref), colorimetry.delta_E2000(naive, ref))
    return t, out


@pytest.mark.parametrize("kind", ["phase-change", "no-phase-change"])
def test_band_limited_5nm_within_half_a_delta_E_up_to_100um(thick_scan, kind):
    """Reference: brute-force 0.1 nm sampling (independent: no band limiting).
    Target: Delta E2000 <= 0.5 for every t' up to 100 um (the band-limited tables' accuracy)."""
    t, out = thick_scan
    band, _ = out[kind]
    assert band.max() <= 0.5, (band.max(), t[band.argmax()])


@pytest.mark.parametrize("kind", ["phase-change", "no-phase-change"])
def test_naive_5nm_sampling_fails_on_thick_films(thick_scan, kind):
    """Reference: the same 0.1 nm truth. Naive point sampling at 5 nm aliases: false
    colours far above any visible threshold (the test the band limiting exists for)."""
    t, out = thick_scan
    _, naive = out[kind]
    assert naive[-1] > 5.0  # at t' = 100 um
    assert naive.max() > 10.0
    assert np.mean(naive[t > 20_000] > 1.0) > 0.5


def test_reference_grid_has_converged():
    """Reference: 0.05 nm sampling; the 0.1 nm reference is converged at 100 um."""
    t = np.array([60_000.0, 99_000.0, 100_000.0])
    fine = colorimetry.film_XYZ(
        t, wavelengths=sampling.wavelength_grid(step=0.05), band_limited=False
    )
    ref = colorimetry.film_XYZ(t, wavelengths=REF_WL, band_limited=False)
    assert colorimetry.delta_E2000(fine, ref).max() < 0.01


def test_thick_two_beam_film_is_neutral_grey(colour):
    """Reference: the incoherent average of Eq. 7 / 8 is 1/2: XYZ -> half of
    colour's D65 white."""
    white = colour_XYZ(colour, np.ones(REF_WL.size), REF_WL)
    for kind in ("phase-change", "no-phase-change"):
        XYZ = colorimetry.film_XYZ(np.array([2e5, 5e5, 1e6]), kind)
        np.testing.assert_allclose(XYZ, np.broadcast_to(0.5 * white, XYZ.shape), atol=2e-3)
        assert colorimetry.delta_E2000(XYZ, 0.5 * white).max() < 0.3


def test_band_limited_multilayer_tends_to_incoherent_average():
    """Reference: the mean of the normalised Fejer kernel, 1/(l+1) of the white."""
    wl = sampling.wavelength_grid(step=5.0)
    white = colorimetry.reflectance_to_XYZ(np.ones(wl.size), wl)
    for layers in (1, 5, 12):
        R = spectra.multilayer_reflectance(np.array([1e5, 3e5]), wl, layers, band_limited=True)
        XYZ = colorimetry.reflectance_to_XYZ(R, wl)
        expected = white / (layers + 1)
        assert colorimetry.delta_E2000(XYZ, expected).max() < 0.5
        np.testing.assert_allclose(XYZ, np.broadcast_to(expected, XYZ.shape), rtol=0.02)


def _incoherent_airy(n1, n2, theta):
    """Thick-film (incoherent) reflectance from intensities only, textbook form:
    R = R01 + T01^2 R12 / (1 - R01 R12) per polarisation (lossless: T01 = 1 - R01)."""
    th0 = np.deg2rad(theta)
    c0 = np.cos(th0)
    c1 = np.sqrt(1 - (np.sin(th0) / n1) ** 2)
    c2 = np.sqrt(1 - (np.sin(th0) / n2) ** 2)
    rs01 = (c0 - n1 * c1) / (c0 + n1 * c1)
    rp01 = (n1 * c0 - c1) / (n1 * c0 + c1)
    rs12 = (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2)
    rp12 = (n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2)
    total = 0.0
    for r01, r12 in ((rs01, rs12), (rp01, rp12)):
        R01, R12 = r01**2, r12**2
        total += 0.5 * (R01 + (1 - R01) ** 2 * R12 / (1 - R01 * R12))
    return total


@pytest.mark.parametrize("n1,n2,theta", [(1.5, 1.0, 0.0), (1.33, 1.0, 45.0), (2.0, 1.5, 30.0)])
def test_band_limited_airy_thick_film_is_incoherent(n1, n2, theta):
    """Reference: the textbook incoherent sum of intensities (no phases at all)."""
    wl = sampling.wavelength_grid(step=5.0)
    white = colorimetry.reflectance_to_XYZ(np.ones(wl.size), wl)
    R = exact.airy_reflectance(
        np.array([2e5, 5e5]), wl, n1, theta, n_substrate=n2, band_limited=True
    )
    XYZ = colorimetry.reflectance_to_XYZ(R, wl)
    expected = _incoherent_airy(n1, n2, theta) * white
    assert colorimetry.delta_E2000(XYZ, expected).max() < 0.5
    np.testing.assert_allclose(XYZ, np.broadcast_to(expected, XYZ.shape), rtol=0.02)


def test_band_limited_airy_matches_dense_reference():
    """Reference: pointwise Airy on the 0.1 nm grid (brute force), t up to 30 um."""
    d = np.array([100.0, 1000.0, 5000.0, 12_345.0, 30_000.0])
    wl5 = sampling.wavelength_grid(step=5.0)
    dense = colorimetry.reflectance_to_XYZ(exact.airy_reflectance(d, REF_WL, 1.4), REF_WL)
    band = colorimetry.reflectance_to_XYZ(
        exact.airy_reflectance(d, wl5, 1.4, band_limited=True), wl5
    )
    naive = colorimetry.reflectance_to_XYZ(exact.airy_reflectance(d, wl5, 1.4), wl5)
    assert colorimetry.delta_E2000(band, dense).max() <= 0.5
    assert colorimetry.delta_E2000(naive, dense).max() > 1.0


# --------------------------------------------------------------------------- #
# Morpho colour
# --------------------------------------------------------------------------- #
def test_morpho_colour_is_blue_and_matches_colour(colour):
    """Reference: colour.sd_to_XYZ of Eq. 9 with the Eq. 14 thickness evaluated with
    numpy (closed form, 1 nm, its analytic limit at the pole); at normal incidence
    the colour is blue (x, y small)."""
    wl = sampling.wavelength_grid(step=1.0)
    got = colorimetry.morpho_XYZ(np.array([0.0, 20.0]), wavelengths=wl, band_limited=False)
    for i, theta in enumerate((0.0, 20.0)):
        th = np.deg2rad(theta)
        t = 150.0 * np.cos(th) + 50.0 * np.sqrt(1.53**2 - np.sin(th) ** 2)
        x = 2 * np.pi * t / wl
        with np.errstate(all="ignore"):
            R = (np.sin(13 * x) / np.sin(x)) ** 2 / 169.0
        # The closed form is 0/0 at 453 nm (x = pi) for theta = 0: analytic limit 1.
        R = np.where(np.abs(np.sin(x)) < 1e-9, 1.0, R)
        np.testing.assert_allclose(got[i], colour_XYZ(colour, R, wl), atol=2e-5)
    xy = colour.XYZ_to_xy(got[0])
    assert xy[0] < 0.2 and xy[1] < 0.15


@pytest.mark.parametrize("space", sorted(registry.RGB_COLORIMETRY))
def test_matrices_are_colour_sciences(space):
    # computed without BLAS or LAPACK (the same bits on every CPU): colour-science's
    # normalised primary matrix and Bradford adaptation, to rounding
    import colour

    cs = colour.RGB_COLOURSPACES[COLOUR_SCIENCE_GAMUTS[space]]  # the independent name
    reference = np.linalg.inv(colour.normalised_primary_matrix(cs.primaries, cs.whitepoint))
    d65 = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    if not np.allclose(cs.whitepoint, d65, atol=1e-4):
        reference = reference @ colour.adaptation.matrix_chromatic_adaptation_VonKries(
            colour.xy_to_XYZ(d65), colour.xy_to_XYZ(cs.whitepoint), transform="Bradford"
        )
    M = colorimetry.matrix_XYZ_to_RGB(space)
    np.testing.assert_allclose(M, reference, rtol=0, atol=1e-14)
