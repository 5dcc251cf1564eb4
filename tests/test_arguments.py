"""The Python API at its edges: each public function handles the edge or
raises a ValueError naming the parameter; inputs are never modified; reflectances
stay within [0, 1]; the thickness colour spaces give black for negative, -inf and NaN
thickness through OpenColorIO at every optimisation level.

References: colour-science's CIE 1931 tables and D65 white point, the physics of the
two-beam film (cos^2(0) = 1: a zero-thickness film without phase change reflects
everything; a thick film reflects half the illuminant on average), and OCIO's own
``ACES_GamutComp13`` processor applied directly.
"""

from __future__ import annotations

import numpy as np
import pytest

from ocio_thinfilm.cli import main as cli
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.physics import exact, sampling, spectra


def _cmf(wavelength):
    import colour

    return np.asarray(colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"][wavelength])


# --------------------------------------------------------------------------- #
# One wavelength, huge or non-finite counts
# --------------------------------------------------------------------------- #
def test_single_wavelength_is_a_point_evaluation():
    """One sample: XYZ = R(l) cmf(l) / ybar(l) (the perfect reflector has Y = 1; the
    illuminant cancels)."""
    cmf = _cmf(550)
    np.testing.assert_allclose(colorimetry.spectral_weights([550.0])[0], cmf / cmf[1], rtol=1e-6)
    R = np.sin(2 * np.pi * 300.0 / 550.0) ** 2
    np.testing.assert_allclose(
        colorimetry.film_XYZ(300.0, wavelengths=[550.0], band_limited=False),
        R * cmf / cmf[1],
        rtol=1e-6,
    )


@pytest.mark.parametrize(
    "call,name",
    [
        (lambda: colorimetry.film_XYZ(300, step=1000), "step"),
        (lambda: colorimetry.film_XYZ(300, step=0), "step"),
        (lambda: colorimetry.film_XYZ(300, step=np.nan), "step"),
        (lambda: sampling.wavelength_grid(stop=np.inf), "stop"),
        (lambda: sampling.wavelength_grid(start=np.nan), "start"),
        (lambda: sampling.wavelength_grid(step=3e-5), "samples"),  # 14 million > the limit
        (lambda: spectra.multilayer_reflectance(100.0, [500.0], np.inf), "layers"),
        (lambda: spectra.multilayer_reflectance(100.0, [500.0], np.nan), "layers"),
        (lambda: spectra.multilayer_reflectance(100.0, [500.0], 200_000), "layers"),
        (lambda: spectra.multilayer_reflectance(100.0, [500.0], 2.5), "layers"),
        (lambda: exact.airy_reflectance(100.0, [500.0], 1.33, harmonics=np.inf), "harmonics"),
        (lambda: colorimetry.spectral_locus_XYZ(Y=np.nan), "Y"),
        (lambda: colorimetry.spectral_locus_XYZ(Y=-1.0), "Y"),
        (lambda: colorimetry.spectral_locus_XYZ(Y=np.inf), "Y"),
    ],
)
def test_bad_parameters_raise_value_error_naming_them(call, name):
    with pytest.raises(ValueError, match=name):
        call()


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: spectra.optical_thickness(300.0, "1.33"), "n"),
        (lambda: spectra.optical_thickness("300", 1.33), "thickness"),
        (lambda: spectra.two_beam_reflectance(100.0, ["500"]), "wavelengths"),
        (lambda: spectra.two_beam_reflectance(None, [500.0]), "optical_thickness"),
        (lambda: sampling.wavelength_grid(step="5"), "step"),
        (lambda: sampling.wavelength_grid(start=None), "start"),
        (lambda: colorimetry.film_XYZ([100.0], step="5"), "step"),
        (lambda: colorimetry.spectral_locus_XYZ(Y="1"), "Y"),
    ],
)
def test_numbers_of_the_wrong_type_raise_type_error_naming_them(call, name):
    """A string is refused, not parsed (``n='1.33'`` is not a number)."""
    with pytest.raises(TypeError, match=rf"^{name} must be a number"):
        call()


@pytest.mark.parametrize("layers", ["3", "many", b"3", None, [3], True])
def test_counts_of_the_wrong_type_raise_type_error_naming_them(layers):
    # a string is refused, not parsed: layers='3' is not a count; nor is a bool
    with pytest.raises(TypeError, match="layers"):
        spectra.multilayer_reflectance(100.0, [500.0], layers)


# --------------------------------------------------------------------------- #
# Reflectances within [0, 1]
# --------------------------------------------------------------------------- #
def test_reflectances_stay_within_0_and_1():
    wl = sampling.wavelength_grid()
    rng = np.random.default_rng(9)
    t = np.concatenate([[0.0, 1e6, 1e9], rng.uniform(0, 1e5, 200)])
    outputs = [
        spectra.multilayer_reflectance(1e6, wl, 1000),
        spectra.multilayer_reflectance(t[:, None], wl, 7, band_limited=True),
        spectra.two_beam_reflectance(t[:, None], wl, band_limited=True),
        spectra.two_beam_reflectance(t[:, None], wl, phase_change=False),
        exact.airy_reflectance(t[:20, None], wl, 1.33, 30.0, band_limited=True),
        exact.transfer_matrix_reflectance([1.5, 1.0, 1.5], [1e5, 3e4, 7e5], wl, 45.0),
    ]
    for R in outputs:
        assert np.all(np.isfinite(R))
        assert R.min() >= 0.0 and R.max() <= 1.0


# --------------------------------------------------------------------------- #
# ACES gamut compression: no NaN from huge components, input untouched
# --------------------------------------------------------------------------- #
def _ocio_aces(rgb):
    import PyOpenColorIO as ocio

    t = ocio.FixedFunctionTransform(
        ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13, list(clip.ACES_GAMUT_COMP13_PARAMS)
    )
    px = np.array(rgb, dtype=np.float32).reshape(-1, 3)
    ocio.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor().applyRGB(px)
    return np.clip(px, 0.0, 1.0)


def test_aces_gamut_compress_huge_components_and_no_mutation():
    huge = np.array(
        [[-1e30, 0.5, 0.5], [-3e38, 0.2, 0.9], [0.4, -1e30, -1e30], [-np.inf, 0.5, 0.5]],
        dtype=np.float32,
    )
    keep = huge.copy()
    out = clip.aces_gamut_compress_RGB(huge)
    assert np.array_equal(huge, keep, equal_nan=True)  # not modified in place
    assert out.dtype == np.float32 and np.all(np.isfinite(out))
    # beyond a distance of 1e6 the compression curve has reached its limit: the same
    # colours with -1e6 * max instead, through OCIO directly
    moderate = np.array(
        [
            [-1e6 * 0.5, 0.5, 0.5],
            [-1e6 * 0.9, 0.2, 0.9],
            [0.4, -1e6 * 0.4, -1e6 * 0.4],
            [-1e6 * 0.5, 0.5, 0.5],
        ]
    )
    np.testing.assert_allclose(out, _ocio_aces(moderate), atol=1e-6)
    # ordinary colours: exactly OCIO's result
    rng = np.random.default_rng(3)
    rgb = rng.uniform(-1.0, 2.0, (1000, 3)).astype(np.float32)
    np.testing.assert_allclose(clip.aces_gamut_compress_RGB(rgb), _ocio_aces(rgb), atol=2e-6)


# --------------------------------------------------------------------------- #
# The thickness colour spaces through OCIO: black below zero, at every level
# --------------------------------------------------------------------------- #
@pytest.fixture(scope="module")
def baked_config(tmp_path_factory):
    import PyOpenColorIO as ocio

    out = tmp_path_factory.mktemp("cfg") / "thinfilm"
    assert cli.main(["bake", "--out", str(out), "--quiet", "--clip-size", "9"]) == 0
    ocio.ClearAllCaches()
    return ocio.Config.CreateFromFile(str(out / "config.ocio"))


@pytest.mark.parametrize(
    "space", ["Thin Film Phase-Change Thickness", "Thin Film No-Phase-Change Thickness"]
)
@pytest.mark.parametrize(
    "level",
    [
        "OPTIMIZATION_NONE",
        "OPTIMIZATION_LOSSLESS",
        "OPTIMIZATION_DEFAULT",
        "OPTIMIZATION_GOOD",
        "OPTIMIZATION_DRAFT",
    ],
)
def test_thickness_spaces_black_below_zero(baked_config, space, level):
    import colour
    import PyOpenColorIO as ocio

    values = np.array([-0.5, -1.0, -1e30, -np.inf, np.nan, np.inf, 1e30, 0.0], dtype=np.float32)
    cpu = baked_config.getProcessor(space, "CIE-XYZ-D65").getOptimizedCPUProcessor(
        ocio.BIT_DEPTH_F32, ocio.BIT_DEPTH_F32, getattr(ocio, level)
    )
    px = np.ascontiguousarray(np.repeat(values[:, None], 3, axis=1))
    cpu.applyRGB(px)
    white = colour.xy_to_XYZ(
        colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    )  # the perfect reflector under D65, Y = 1
    np.testing.assert_allclose(px[:5], 0.0, atol=1e-6)  # negative, -inf, NaN: black
    np.testing.assert_allclose(px[5:7], np.repeat(0.5 * white[None], 2, 0), atol=2e-3)
    at_zero = np.zeros(3) if "No-Phase" not in space else white  # sin^2(0), cos^2(0)
    np.testing.assert_allclose(px[7], at_zero, atol=2e-3)


# --------------------------------------------------------------------------- #
# The SDR display colour spaces' code limit
# --------------------------------------------------------------------------- #
def test_display_code_limit_is_the_code_of_the_input_limit():
    """Reference: colour-science's encoding of each SDR display (IEC 61966-2-1, BT.1886's
    inverse EOTF, a pure power: ``evaluation.views.encode_display``) of display light
    1e6 (ocio_ops.LIMIT, the limit of every scene space's input); the display colour
    space passes codes up to it and clamps beyond, on the way from XYZ and (through
    OCIO's inverse) on the way back."""
    import colour

    from evaluation.views import encode_display
    from ocio_thinfilm import registry
    from ocio_thinfilm.lut import display_transforms, ocio_ops

    limits = {d: display_transforms.code_limit(d) for d in registry.DISPLAYS}
    for display, limit in limits.items():
        expected = float(encode_display(ocio_ops.LIMIT, display))
        assert limit == pytest.approx(expected, rel=1e-12), display
    # pinned: the sRGB display's limit is IEC 61966-2-1's encoding of 1e6
    expected = colour.cctf_encoding(ocio_ops.LIMIT, function="sRGB")
    assert limits["sRGB"] == pytest.approx(expected, rel=1e-12)
    # ordinary codes round-trip unchanged; 1e30 and +Inf become the limit
    t = display_transforms.display_colorspace_transform("sRGB")
    code = np.array([[0.2, 0.5, 1.0], [-0.1, 0.3, 1.5], [1e30, np.inf, 0.0]], np.float32)
    xyz = ocio_ops.apply(ocio_ops.inverse([t]), code)
    assert np.isfinite(xyz).all()
    back = ocio_ops.apply(t, xyz)
    np.testing.assert_allclose(back[:2], code[:2], rtol=1e-4, atol=1e-6)
    np.testing.assert_allclose(back[2, :2], limits["sRGB"], rtol=1e-4)


@pytest.mark.parametrize("display", ["Rec.2100-PQ", "no such display"])
def test_display_code_limit_names_its_parameter(display):
    from ocio_thinfilm.lut import display_transforms

    with pytest.raises(ValueError, match="^display must be one of"):
        display_transforms.code_limit(display)
