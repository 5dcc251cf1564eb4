"""HDR displays as a host applies them -- the baked config's views through OCIO's CPU
processor -- against the analytic clip (``clip.clip_XYZ``) scaled into the HDR volume.

Convention (docs/hdr.md): CIE XYZ Y = 1 is shown at 203 cd/m2 (ITU-R BT.2408), the
peak is 1000 cd/m2, so a PQ display's volume is its gamut's parallelepiped up to
k = 1000 / 203 and clip_HDR(X) = k clip_SDR(X / k). HLG's volume in display light is
the BT.2100 OOTF of the signal's parallelepiped; the truth is computed here with the
OOTF written out from BT.2100 (Table 5), not with the package's ops. The code values
are decoded with colour-science's ST 2084 / HLG EOTFs.

The sets are the clip's test sets (evaluation.colours.gamut_map_sets), scaled by k.
"""

from __future__ import annotations

import numpy as np
import pytest

from evaluation.views import (
    EXTREME_XYZ,
    OPTIMIZATION_LEVELS,
    apply_view,
    error_stats,
    view_codes,
)
from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry, compress

ocio = pytest.importorskip("PyOpenColorIO")
colour = pytest.importorskip("colour")

#: Tolerance of a code value above 1 or below 0 (float32 rounding).
TOL = 1e-4
VIEW = registry.CLIP_VIEW
#: The views with an analytic map: the clip and the soft compression (the same ray and
#: faces, scale-covariant alike), and their maps of XYZ into an SDR gamut.
MAPPED = {
    registry.CLIP_VIEW: clip.clip_XYZ,
    registry.COMPRESS_VIEW: compress.compress_XYZ,
}
#: Every view but the raw one.
NOT_RAW = [v.name for v in registry.VIEW_LIST if not v.raw]
WHITE = 203.0
PEAK = 1000.0
K = PEAK / WHITE
HDR = registry.HDR_DISPLAYS


def _apply(cfg, display, view, XYZ, optimization=None):
    return apply_view(cfg, display, XYZ, optimization, view=view)


def _nits(display, code):
    """Code values -> display light RGB in cd/m2 (colour-science's EOTFs)."""
    code = np.asarray(code, dtype=np.float64)
    if registry.as_display(display).transfer == "PQ":
        return colour.models.eotf_ST2084(code)
    return colour.models.eotf_BT2100_HLG(code, L_B=0.0, L_W=PEAK)


def _decoded_XYZ(display, code):
    """Code values -> CIE XYZ in units of the reference white (Y = 1 at 203 cd/m2)."""
    return colorimetry.RGB_to_XYZ(
        _nits(display, code) / WHITE, registry.as_display(display).gamut.name
    )


def _truth(display, XYZ, view=VIEW):
    """The analytic map of ``view`` into the display's HDR volume (XYZ, Y = 1 at 203
    cd/m2), and whether each colour is inside that volume."""
    mapping = MAPPED[view]
    gamut = registry.as_display(display).gamut.name
    M = colorimetry.matrix_XYZ_to_RGB(gamut)
    XYZ = np.asarray(XYZ, dtype=np.float64)
    if registry.as_display(display).transfer == "PQ":
        return K * mapping(XYZ / K, gamut), clip.in_gamut(XYZ / K @ M.T)
    # HLG (BT.2100 Table 5, L_B = 0): F_D = L_W Y_S^(gamma - 1) E, gamma = 1.2 at 1000
    # cd/m2; the scene light E in [0, 1] is the signal's volume. A pixel of display
    # luminance Y_D (cd/m2) has Y_S = (Y_D / L_W)^(1 / gamma).
    gamma = 1.2
    Yd = np.maximum(XYZ[:, 1], 0.0) * WHITE
    with np.errstate(all="ignore"):
        to_scene = np.where(Yd > 0, (Yd / PEAK) ** (1.0 / gamma - 1.0) / PEAK, 0.0)
    scene = XYZ * WHITE * to_scene[:, None]
    clipped = mapping(scene, gamut)
    return (clipped * (PEAK * clipped[:, 1:2] ** (gamma - 1.0)) / WHITE, clip.in_gamut(scene @ M.T))


def _measured(cfg):
    """{(view, display, set): statistics} of the mapped views on the sets scaled by k."""
    out = {}
    for view, display in [(v, d) for v in MAPPED for d in HDR]:
        gamut = registry.as_display(display).gamut.name
        M = colorimetry.matrix_XYZ_to_RGB(gamut)
        for name, XYZ, code in view_codes(cfg, display, view, scale=K):
            got = _decoded_XYZ(display, code)
            truth, inside = _truth(display, XYZ, view)
            L, L_true = got[:, 1] * WHITE, XYZ[:, 1] * WHITE  # cd/m2
            rel = np.abs(L - L_true) / np.maximum(L_true, FLOOR)
            out[view, display, name] = dict(
                # dE2000 relative to the peak white (the HDR volume scaled back into SDR
                # units, as the SDR tests compare relative to their white)
                error_stats(truth / K, got / K, inside),
                rel_inside=float(rel[inside].max()) if inside.any() else 0.0,
                rel_outside=float(rel[~inside].max()) if (~inside).any() else 0.0,
                in_range=bool(np.all((code >= 0.0) & (code <= 1.0 + TOL))),
                in_volume=bool(
                    np.all(got @ M.T <= K * (1 + 1e-3) + 1e-6) and np.all(got @ M.T >= -1e-6)
                ),
            )
    return out


#: Relative luminance errors are taken against max(L, FLOOR) cd/m2: near black (Y of
#: 1e-3 to 2e-3 of the SDR LUTs after the scale by 1 / k, 1-2 cd/m2) their 16-bit codes
#: (1.5e-5 of an sRGB code) dominate: in-gamut object colours at 1 cd/m2 reach 1.1e-3
#: relative; below the floor the error is absolute, under 2e-3 cd/m2.
FLOOR = 2.0
#: The accuracy targets: dE2000 p99, max, relative luminance error, in-gamut dE2000.
TARGET = (0.5, 1.5, 1e-3, 0.1)
#: Out-of-gamut colours: the SDR clip LUTs' |dY| (<= 1e-3 absolute, the clip's
#: target), scaled, is a relative error up to 3.2e-3 on spectral-line mixtures
#: (|dY| 3.3e-4 at Y ~ 0.1); the relative target is met by in-gamut colours only.
REACHED_OUTSIDE = 4e-3


#: What the compression reaches against its analytic map (the same as its SDR LUTs on
#: Rec.2020 / P3 for PQ; HLG moves the colours in the LUTs' cells a little): dE2000 max
#: per set (0.72 / 0.50 / 0.74 / 0.92 at most), and its luminance error relative to 203 Y
#: (its LUTs' |dY|, scaled: up to 1.8e-3 on Rec.2100-HLG out-of-gamut object colours).
COMPRESS_MAX = {"object": 0.8, "monochromatic": 0.6, "ap0": 0.8, "mixtures": 1.0}
COMPRESS_REL = 2e-3


@pytest.mark.parametrize("view", list(MAPPED))
@pytest.mark.parametrize("display", HDR)
@pytest.mark.parametrize("name", ["object", "monochromatic", "ap0", "mixtures"])
def test_hdr_view_against_the_scaled_analytic_map(measured, view, display, name):
    m = measured[view, display, name]
    print(
        f"{view:28s} {display:12s} {name:13s} p99 {m['p99']:.3f} max {m['max']:.3f} "
        f"rel L in {m['rel_inside']:.1e} out {m['rel_outside']:.1e} "
        f"in-gamut max {m['inside_max']:.3f}"
    )
    p99, worst, rel, inside = TARGET
    assert m["in_range"] and m["in_volume"]
    assert m["p99"] <= p99
    if view == VIEW:
        # the SDR Rec.2020 / P3 clip's AP0 figures (dark violet beyond the blue primary)
        assert m["max"] <= (1.6 if name == "ap0" else worst)
        assert m["rel_inside"] <= rel
        assert m["inside_max"] <= inside
        assert m["rel_outside"] <= REACHED_OUTSIDE
    else:  # in-gamut colours near the faces move too: no 'unchanged' bound here
        assert m["max"] <= COMPRESS_MAX[name]
        assert max(m["rel_inside"], m["rel_outside"]) <= COMPRESS_REL


def test_hdr_compress_target(measured):
    """The compression into every HDR display: max dE2000 <= 1.5 on every set."""
    assert max(m["max"] for (v, _, _), m in measured.items() if v != VIEW) <= TARGET[1]


@pytest.mark.xfail(
    strict=True,
    reason="target not reached: luminance of out-of-gamut "
    "colours to 1e-3 relative (the SDR LUTs' |dY| <= 1e-3 is absolute)",
)
def test_hdr_relative_luminance_target_outside_the_gamut(measured):
    assert max(m["rel_outside"] for (v, _, _), m in measured.items() if v == VIEW) <= TARGET[2]


@pytest.mark.parametrize("view", list(MAPPED))
@pytest.mark.parametrize("display", HDR)
def test_luminance_is_203_Y(cfg, display, view):
    """Decoding the view's output with the ST 2084 / HLG EOTF gives 203 Y cd/m2 for
    colours the clip keeps (in gamut, Y up to the peak), and the peak white above."""
    gamut = registry.as_display(display).gamut.name
    rng = np.random.default_rng(3)
    rgb = rng.uniform(0.0, 1.0, (4000, 3)) * K
    if registry.as_display(display).transfer == "HLG":
        # inside HLG's volume: the OOTF of the signal's cube
        rgb = rgb / K
        Ys = rgb @ colorimetry.RGB_to_XYZ(np.eye(3), gamut)[:, 1]
        rgb = rgb * (PEAK / WHITE * Ys[:, None] ** 0.2)
    XYZ = colorimetry.RGB_to_XYZ(rgb, gamut)
    code = _apply(cfg, display, view, XYZ)
    L = _decoded_XYZ(display, code)[:, 1] * WHITE
    L_true = XYZ[:, 1] * WHITE
    keep = L_true >= FLOOR
    assert np.abs(L - L_true)[keep].max() / 1.0 <= 1e-3 * L_true[keep].max()
    assert (np.abs(L - L_true) / L_true)[keep].max() <= 1e-3
    if view == VIEW:  # in gamut: unchanged (the compression moves those near the faces)
        np.testing.assert_allclose(_decoded_XYZ(display, code), XYZ, rtol=2e-3, atol=2e-4)
    # grey ramp above the peak: the peak white
    grey = np.outer([1.01 * K, 2 * K, 100.0], colorimetry.white_XYZ())
    out = _nits(display, _apply(cfg, display, view, grey))
    np.testing.assert_allclose(out, PEAK, rtol=1e-3)


@pytest.mark.parametrize("level", OPTIMIZATION_LEVELS)
@pytest.mark.parametrize("display", HDR)
@pytest.mark.parametrize("view", NOT_RAW)
def test_hdr_extremes_finite_and_in_range(cfg, display, view, level):
    with np.errstate(over="ignore"):  # float32 max * k is +Inf: an input too
        x = np.r_[EXTREME_XYZ, EXTREME_XYZ * np.float32(K)]
    out = _apply(cfg, display, view, x, getattr(ocio, OPTIMIZATION_LEVELS[level]))
    assert np.all(np.isfinite(out)) and out.min() >= -TOL and out.max() <= 1.0 + TOL
    assert np.all(_nits(display, out) <= PEAK * (1 + 1e-3))


@pytest.fixture(scope="module")
def measured(cfg):
    return _measured(cfg)
