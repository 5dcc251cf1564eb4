"""The RGB-against-spectral comparison (docs/rgb_vs_spectral.md, lut/film_lights.py).

References: colour-science alone: its TMM (``colour.phenomena.thin_film_tmm``, one
wavelength at a time, as tests/test_material.py) for the soap film's spectra on 1 nm,
``sd_to_XYZ`` under the light's spectrum, its sRGB colourspace for the RGB path,
``chromatic_adaptation`` (CAT02) and CIEDE2000 for the differences, and its Ohno (2005)
LED model for the LED. One film (the soap film), one light (F11, a three-band
fluorescent lamp), 2 x 2 points.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

from evaluation.films import n_stack
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.lut import film_lights, material_tables
from ocio_thinfilm.physics import films

ROOT = Path(__file__).resolve().parents[1]
FILM = films.read_films(ROOT / "docs" / "films.toml")["SoapFilm"]
LIGHT = "FL11"
THICKNESS_UM = np.array([0.31, 0.83])
COS_THETA = np.array([0.4, 1.0])
OBSERVER = "CIE 1931 2 Degree Standard Observer"


def _colour_XYZ(spectra, wl, illuminant):
    """colour-science's ``sd_to_XYZ`` (integration) of each spectrum under ``illuminant``
    (an SD), the perfect reflector at Y = 1."""
    import colour

    cmfs = colour.MSDS_CMFS[OBSERVER]
    out = [
        colour.sd_to_XYZ(colour.SpectralDistribution(s, wl), cmfs, illuminant, method="Integration")
        for s in spectra
    ]
    white = colour.sd_to_XYZ(
        colour.SpectralDistribution(np.ones(wl.size), wl), cmfs, illuminant, method="Integration"
    )
    return np.array(out) / 100.0, white / 100.0


@pytest.fixture(scope="module")
def reference():
    """The soap film's reflectance spectra at the 2 x 2 points (colour-science's TMM,
    1 nm) and their XYZ under D65 and F11 by colour-science, rows (cos, thickness)."""
    import colour

    wl = np.arange(380.0, 780.01, 1.0)
    n = n_stack(FILM, wl)
    t = np.tile(THICKNESS_UM, COS_THETA.size)
    theta = np.degrees(np.arccos(np.repeat(COS_THETA, THICKNESS_UM.size)))
    diagonal = np.arange(t.size)
    spectra = np.empty((t.size, wl.size))
    for k, lam in enumerate(wl):
        R, _ = colour.phenomena.thin_film_tmm(n[:, k], t * 1000.0, [lam], theta)
        spectra[:, k] = R[0, diagonal, diagonal, :].mean(axis=-1)
    d65, _ = _colour_XYZ(spectra, wl, colour.SDS_ILLUMINANTS["D65"])
    fl11, white = _colour_XYZ(spectra, wl, colour.SDS_ILLUMINANTS["FL11"])
    shape = (COS_THETA.size, THICKNESS_UM.size, 3)
    return {"D65": d65.reshape(shape), LIGHT: fl11.reshape(shape), "white": white}


def _delta_E_under(a, b, white):
    """CIEDE2000 of two colours under a light with colour-science: both CAT02-adapted from
    the light's white to D65, CIELAB (D65)."""
    import colour

    d65 = colour.CCS_ILLUMINANTS[OBSERVER]["D65"]
    d65_XYZ = colour.xy_to_XYZ(d65)
    lab = [
        colour.XYZ_to_Lab(
            colour.chromatic_adaptation(x, white, d65_XYZ, method="Von Kries", transform="CAT02"),
            d65,
        )
        for x in (a, b)
    ]
    return colour.delta_E(*lab, method="CIE 2000")


def test_the_spectral_truth_is_colour_sciences_integral(reference):
    """``film_light_XYZ`` under F11 and D65 (the film's spectra times the light's spectrum
    with the CIE 1931 CMFs, not adapted) is colour-science's ``sd_to_XYZ`` of the same
    film under the same light; the light's white is colour-science's too."""
    ours = film_lights.film_light_XYZ(FILM, THICKNESS_UM, COS_THETA, ["D65", LIGHT])
    for k, name in enumerate(["D65", LIGHT]):
        np.testing.assert_allclose(ours[k], reference[name], atol=5e-4)
    np.testing.assert_allclose(film_lights.light_white_XYZ(LIGHT), reference["white"], atol=2e-3)


def test_the_rgb_path_is_colour_sciences_product_of_rgbs(reference):
    """The RGB path (the D65 table's linear Rec.709 times the light's linear Rec.709) is the
    same product through colour-science's sRGB colourspace (no adaptation); its
    difference from the spectral truth relative to the light's white is colour-science's
    CAT02 + CIEDE2000, several units at some point, and the recovered path (the film file's
    ``illuminant``) is within 0.3 of the truth."""
    import colour

    table = colour.XYZ_to_RGB(reference["D65"], "sRGB", illuminant=None)
    light = colour.XYZ_to_RGB(reference["white"], "sRGB", illuminant=None)
    expected = colour.RGB_to_XYZ(table * light, "sRGB", illuminant=None)
    truth = film_lights.film_light_XYZ(FILM, THICKNESS_UM, COS_THETA, ["D65", LIGHT])
    ours = film_lights.rgb_path_XYZ(colorimetry.XYZ_to_RGB(truth[0]), LIGHT)
    np.testing.assert_allclose(ours, expected, atol=5e-4)
    # the difference relative to the light's white
    dE_ours = film_lights.delta_E_under(ours, truth[1], LIGHT)
    dE_ref = _delta_E_under(expected, reference[LIGHT], reference["white"])
    np.testing.assert_allclose(dE_ours, dE_ref, atol=0.05)
    assert dE_ref.max() > 2.0, dE_ref
    # the recovered path: the film under F11 adapted to D65, un-adapted with the same CAT
    lit = dataclasses.replace(FILM, illuminant=LIGHT)
    table_f11, _ = material_tables.film_angle_XYZ(lit, THICKNESS_UM, COS_THETA)
    A = film_lights.scene_adaptation(LIGHT)
    recovered = table_f11 @ np.linalg.inv(A).T
    assert _delta_E_under(recovered, reference[LIGHT], reference["white"]).max() < 0.3


def test_the_led_is_ohnos_model_at_the_d65_chromaticity():
    """``led_spectrum`` is colour-science's Ohno (2005) three-LED spectrum with the
    module's peaks, widths and ratios, and its white is D65's chromaticity (CCT 6504 K)."""
    import colour

    sd = colour.colorimetry.sd_multi_leds_Ohno2005(
        np.array(film_lights.LED_PEAKS_NM),
        np.array(film_lights.LED_WIDTHS_NM),
        np.array(film_lights.LED_POWER_RATIOS),
    )
    np.testing.assert_allclose(
        film_lights.led_spectrum(sd.wavelengths), sd.values, rtol=1e-7, atol=1e-9
    )
    xy = colour.XYZ_to_xy(colour.sd_to_XYZ(sd, colour.MSDS_CMFS[OBSERVER]))
    np.testing.assert_allclose(xy, colour.CCS_ILLUMINANTS[OBSERVER]["D65"], atol=1e-4)
    np.testing.assert_allclose(film_lights.light_RGB(film_lights.LED_NAME), 1.0, atol=2e-3)
    with pytest.raises(ParameterError, match="^light must be 'RGB-LED-D65' or"):
        film_lights.light_weights([500.0, 600.0], "LED-XX")


def test_the_host_read_is_bilinear_between_nodes():
    """``table_lookup`` returns the nodes at the nodes and the average of four nodes at the
    centre of a cell (the hand-computed bilinear read)."""
    tab = np.arange(12.0).reshape(3, 4, 1)  # cos 0, 0.5, 1; thickness 0, 1, 2, 3 um
    assert film_lights.table_lookup(tab, (0.0, 3.0), 2.0, 0.5)[0] == 6.0
    assert film_lights.table_lookup(tab, (0.0, 3.0), 0.5, 0.25)[0] == (0 + 1 + 4 + 5) / 4
    assert film_lights.table_lookup(tab, (0.0, 3.0), 9.0, 1.0)[0] == 11.0  # clamped


def test_the_documented_table_is_the_benchmarks(load_benchmark, marked):
    """docs/rgb_vs_spectral.md's table is what benchmarks/bench_rgb_vs_spectral.py wrote
    (reports/bench_rgb_vs_spectral.json); the JSON covers every film of docs/films.toml
    under every light, the recovered path is within p95 0.2 / max 1 everywhere (the
    doc's claims), and the RGB path errs by more than 2 (p95) for every film under every
    light but D65."""
    bench = load_benchmark("bench_rgb_vs_spectral")
    result = json.loads((ROOT / "reports" / "bench_rgb_vs_spectral.json").read_text())
    doc = (ROOT / "docs" / "rgb_vs_spectral.md").read_text()
    assert marked(doc, bench.BEGIN, bench.END) == bench.table_markdown(result)
    keys = list(films.read_films(ROOT / "docs" / "films.toml"))
    assert [f["film"] for f in result["films"]] == keys
    for film in result["films"]:
        assert [r["light"] for r in film["lights"]] == list(bench.LIGHTS)
        assert max(r["recovered"][1] for r in film["lights"]) <= 0.2, film["film"]
        assert max(r["recovered"][2] for r in film["lights"]) < 1.0, film["film"]
        assert min(r["rgb_path"][1] for r in film["lights"][1:]) > 2.0, film["film"]
        assert film["lights"][0]["rgb_path"][1] < 0.1, film["film"]
    assert result["led"]["peak_power_ratios"] == list(film_lights.LED_POWER_RATIOS)
