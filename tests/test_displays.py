"""The broadcast and cinema displays, checked against OCIO's built-ins and colour-science.

``Rec.1886 Rec.709`` (the BT.1886 reference monitor) has sRGB's gamut and shares its
clip tables; ``P3-DCI`` (the DCI projector: P3 primaries, DCI white, gamma 2.6) has a
gamut of its own. Each display colour space is compared with OCIO's built-in display
transform of the same name; each view's light is decoded by colour-science.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from evaluation import truth
from evaluation.views import COMMITTED_CONFIG, apply_view, colour_science_rgb, decode_display
from ocio_thinfilm import registry

ROOT = Path(__file__).resolve().parent.parent
D65 = (0.3127, 0.3290)


@pytest.fixture(scope="module")
def cfg():
    ocio = pytest.importorskip("PyOpenColorIO")
    return ocio.Config.CreateFromFile(str(COMMITTED_CONFIG))


def _in_gamut_XYZ(gamut: str, n: int = 2000) -> tuple[np.ndarray, np.ndarray]:
    """Random display-linear RGB in [0, 1] and its CIE-XYZ-D65, by colour-science
    (Bradford from the gamut's white to D65, as OCIO's ``-BFD`` transforms); ``gamut``
    a gamut or display name (evaluation/truth.py's colourspace)."""
    rgb = np.random.default_rng(11).uniform(0.0, 1.0, (n, 3))
    # the matrix derived from the primaries and white, as OCIO's built-ins (colour-science's
    # sRGB colourspace carries IEC 61966-2-1's rounded matrix, 1.7e-4 off)
    return rgb, rgb @ truth.colour_science_RGB_to_XYZ(gamut).T


@pytest.mark.parametrize("display", registry.ALL_DISPLAY_LIST, ids=lambda d: d.name)
def test_the_display_colour_space_is_ocios_builtin(cfg, display):
    """CIE-XYZ-D65 -> code values: every display colour space equals OCIO's built-in
    display transform of evaluation/truth.py (float32 round-off; an HDR one's input
    scaled from Y = 1 at the reference white to Y = 1 at OCIO's 100 cd/m2, its codes
    clamped to [0, 1]), and an SDR one decodes (colour-science) to the RGB."""
    import PyOpenColorIO as ocio

    from evaluation.views import apply_processor

    builtin = truth.OCIO_DISPLAY_BUILTINS[display.name]
    rgb, XYZ = _in_gamut_XYZ(display.colorimetry)
    XYZ = XYZ * display.scale  # up to an HDR display's peak white
    ours = apply_processor(cfg.getProcessor(registry.REFERENCE, display.colorspace), XYZ)
    unit = registry.HDR_REFERENCE_WHITE / registry.OCIO_XYZ_UNIT if display.hdr else 1.0
    theirs = apply_processor(
        ocio.Config.CreateRaw().getProcessor(ocio.BuiltinTransform(builtin)), XYZ * unit
    )
    if display.hdr:  # our HDR codes end in a clamp to [0, 1] (HLG's inverse OOTF lifts
        # saturated blues to 1.056); float32 round-off of the steep PQ: measured 1.6e-5
        np.testing.assert_allclose(ours, np.clip(theirs, 0.0, 1.0), atol=3e-5)
    else:
        np.testing.assert_allclose(ours, theirs, atol=2e-6)
    if not display.hdr:
        np.testing.assert_allclose(decode_display(ours, display.name), rgb, atol=2e-5)


def test_rec1886_shares_srgbs_tables_and_shows_the_same_light(cfg):
    """Rec.1886 Rec.709 has no LUT files of its own and every view shows the light of
    sRGB's view (each decoded by colour-science's EOTF of its display)."""
    entry = registry.as_display("Rec.1886 Rec.709")
    assert entry.gamut is registry.as_display("sRGB")
    assert "Rec1886Rec709" not in " ".join(
        p.name for p in (COMMITTED_CONFIG.parent / "luts").iterdir()
    )
    rng = np.random.default_rng(5)
    XYZ = np.vstack([rng.uniform(-0.1, 1.3, (3000, 3)), np.eye(3), [[0.95, 1.0, 1.09]]])
    for view in registry.VIEWS[:-1]:
        srgb = decode_display(apply_view(cfg, "sRGB", XYZ, view=view), "sRGB")
        bt1886 = decode_display(apply_view(cfg, entry.name, XYZ, view=view), entry.name)
        # the same light to float32 round-off through two different encodings
        np.testing.assert_allclose(bt1886, srgb, atol=5e-5, err_msg=view)


def test_p3dci_clip_keeps_in_gamut_colours_and_lightness(cfg):
    """The P3-DCI clip view, decoded by colour-science (gamma 2.6) and taken to XYZ by
    colour-science's DCI-P3 (Bradford to D65): colours inside the DCI gamut come back
    as they went in; colours outside come back in gamut at their luminance."""
    import colour

    space = truth.colour_science_gamut("P3-DCI")
    rgb, XYZ = _in_gamut_XYZ("P3-DCI", 500)
    inside = rgb * 0.98 + 0.01
    XYZ_in = colour.RGB_to_XYZ(
        inside, space, np.array(D65), chromatic_adaptation_transform="Bradford"
    )
    codes = apply_view(cfg, "P3-DCI", XYZ_in)
    np.testing.assert_allclose(decode_display(codes, "P3-DCI"), inside, atol=2e-3)
    # the spectral locus at half luminance: far outside, clipped at constant Y
    import colour.colorimetry

    cmfs = (
        colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
        .copy()
        .align(colour.SpectralShape(420, 680, 5))
    )
    locus = cmfs.values / cmfs.values[:, 1:2] * 0.2
    out = decode_display(apply_view(cfg, "P3-DCI", locus), "P3-DCI")
    assert out.min() >= 0.0 and out.max() <= 1.0
    back = colour.RGB_to_XYZ(out, space, np.array(D65), chromatic_adaptation_transform="Bradford")
    np.testing.assert_allclose(back[:, 1], 0.2, atol=2e-3)
    assert np.abs(colour_science_rgb(locus, space.name) - out).max() > 0.1  # it was moved


def test_config_growth_is_one_set_of_tables_per_gamut():
    """The committed config holds four clip/compression files per gamut, none per
    display that shares a gamut (docs/gamut_map.md gives the sizes)."""
    luts = COMMITTED_CONFIG.parent / "luts"
    for display in registry.DISPLAY_LIST:
        own = sorted(p.name for p in luts.glob(f"ConstantLightness*_{display.lut_stem}_*.clf"))
        assert len(own) == (4 if display.gamut is display else 0), display.name
    text = (ROOT / "docs" / "gamut_map.md").read_text()
    for display in registry.GAMUT_DISPLAY_LIST:
        assert f"| {display.name} |" in text, display.name
