"""The evaluation's independent truths (evaluation/truth.py) cover the registry exactly.

A new gamut, log curve or display in the registry fails here until evaluation/truth.py
names its truth (the message names the missing key); each truth is then checked
against the package independently: colour-science's colourspace has the primaries and
white of the package's colorimetry matrix, its log functions are the curve's published
model, OCIO's built-in display transform exists.
"""

from __future__ import annotations

import numpy as np
import pytest

from evaluation import truth
from ocio_thinfilm import registry
from ocio_thinfilm.colour import colorimetry, log_curves

D65 = truth.D65


@pytest.mark.parametrize(
    "mapping, names, what",
    [
        ("COLOUR_SCIENCE_GAMUTS", [g.name for g in registry.GAMUT_LIST], "gamut"),
        ("COLOUR_SCIENCE_LOGS", list(registry.LOG_CURVES), "log curve"),
        ("OCIO_DISPLAY_BUILTINS", list(registry.ALL_DISPLAYS), "display"),
        ("HDR_CICP", list(registry.HDR_DISPLAYS), "HDR display"),
    ],
)
def test_each_truth_covers_exactly_the_registrys_entries(mapping, names, what):
    absent, extra = truth.missing(getattr(truth, mapping), names)
    assert not absent, (
        f"evaluation/truth.py {mapping} has no truth for the registry {what}s {absent}"
    )
    assert not extra, f"evaluation/truth.py {mapping} names {what}s the registry has not: {extra}"


def test_the_coverage_check_names_a_missing_key():
    names = [g.name for g in registry.GAMUT_LIST] + ["Adobe RGB"]
    assert truth.missing(truth.COLOUR_SCIENCE_GAMUTS, names) == (["Adobe RGB"], [])


@pytest.mark.parametrize("gamut", registry.GAMUT_LIST, ids=lambda g: g.name)
def test_colour_sciences_colourspace_has_the_gamuts_primaries_and_white(gamut):
    """colour-science's colourspace named by the truth: its normalised primary matrix,
    Bradford-adapted to D65 where its white is another (built here from its primaries
    and white by colour-science), is the package's matrix; its primaries and white are
    those of the colourspace the registry names."""
    import colour

    space = colour.RGB_COLOURSPACES[truth.COLOUR_SCIENCE_GAMUTS[gamut.name]]
    ours = colour.RGB_COLOURSPACES[gamut.colour_science]
    np.testing.assert_allclose(space.primaries, ours.primaries, atol=1e-12)
    np.testing.assert_allclose(space.whitepoint, ours.whitepoint, atol=1e-12)
    rgb_to_xyz = truth.colour_science_RGB_to_XYZ(gamut.name)
    np.testing.assert_allclose(
        colorimetry.matrix_XYZ_to_RGB(gamut.name), np.linalg.inv(rgb_to_xyz), atol=1e-9
    )
    # RGB = 1 is the D65 white of the scene (Y = 1), whatever the gamut's own white
    np.testing.assert_allclose(rgb_to_xyz @ np.ones(3), colour.xy_to_XYZ(D65), atol=1e-12)


def test_every_display_has_a_gamut_with_a_truth():
    for d in registry.ALL_DISPLAY_LIST:
        assert d.colorimetry in truth.COLOUR_SCIENCE_GAMUTS, d.name
        assert truth.colour_science_gamut(d.name) is truth.colour_science_gamut(d.colorimetry)


@pytest.mark.parametrize("curve", registry.LOG_CURVE_LIST, ids=lambda c: c.name)
def test_colour_sciences_log_functions_are_the_curve(curve):
    """The truth's functions exist, are each other's inverse, and encode as the curve's
    published model (``LogCurve.encode_one``, the package's own constants) does."""
    import colour

    entry = truth.COLOUR_SCIENCE_LOGS[curve.name]
    assert callable(getattr(colour.models, entry.encoding))
    assert callable(getattr(colour.models, entry.decoding))
    linear = np.array([0.0, 0.05, 0.18, 1.0, 10.0])  # away from the breaks (gaps ~1e-9)
    codes = truth.log_encoding(linear, curve)
    np.testing.assert_allclose(truth.log_decoding(codes, curve.name), linear, atol=1e-12)
    np.testing.assert_allclose(
        codes, [curve.encode_one(x) for x in linear], rtol=0, atol=1e-12, err_msg=curve.name
    )
    np.testing.assert_allclose(log_curves.encode(curve, linear), codes, rtol=0, atol=1e-12)


@pytest.mark.parametrize("display", registry.ALL_DISPLAY_LIST, ids=lambda d: d.name)
def test_ocios_builtin_display_transform_exists(display):
    ocio = pytest.importorskip("PyOpenColorIO")

    builtins = {name for name, _ in ocio.BuiltinTransformRegistry().getBuiltins()}
    assert truth.OCIO_DISPLAY_BUILTINS[display.name] in builtins
    if display.hdr:  # the package's HDR colour space is built on its built-in
        assert display.builtin == truth.OCIO_DISPLAY_BUILTINS[display.name]
