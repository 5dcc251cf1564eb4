"""Image tests through OpenImageIO's ``oiiotool`` with the shipped config.

Generated EXRs (a thickness ramp; an XYZ image of spectral and object colours) go
through ``oiiotool --colorconfig configs/thinfilm/config.ocio --iscolorspace ...
--ociodisplay DISPLAY VIEW``; the results are compared with the package's analytic
path (spectra -> XYZ -> clip.clip_XYZ / clamp / ACES GC -> encoding) by CIE dE2000,
and the clip's promises are checked on oiiotool's own output: in gamut, Y kept.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from evaluation.colours import object_colours, spectral_colours
from evaluation.views import COMMITTED_CONFIG, decode_display, encode_display
from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry, compress
from ocio_thinfilm.io import read_image, write_image

ROOT = Path(__file__).resolve().parents[1]
OIIOTOOL = shutil.which("oiiotool")
pytestmark = pytest.mark.skipif(OIIOTOOL is None, reason="oiiotool (OpenImageIO) not on PATH")

DISPLAYS = clip.DISPLAYS
#: dE2000 thresholds, oiiotool vs the analytic path (see the per-test comments).
CLIP_P99, CLIP_MAX = 2.0, 5.0  # the 33^3 LUT on interference colours (measured 1.51 / 3.8)
EXACT_MAX = 0.05  # matrix / clamp / ACES GC views: only table interpolation and float32


def oiiotool(*args):
    result = subprocess.run(
        [OIIOTOOL, "--colorconfig", str(COMMITTED_CONFIG), *map(str, args)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    return result


def decode(code, display):
    """Display code values -> display-linear RGB (colour-science's decoding of the
    registry display's encoding: :func:`evaluation.views.decode_display`)."""
    return decode_display(code, display)


def encode(rgb, display):
    """Display-linear RGB (clamped to [0, 1]) -> code values (colour-science)."""
    return encode_display(np.clip(rgb, 0, 1), display)


@pytest.fixture(scope="module")
def thickness_ramp(tmp_path_factory):
    """A 1024 x 4 float EXR, t' = 0..3 um left to right, all channels equal."""
    t = np.linspace(0.0, 3.0, 1024)
    img = np.repeat(np.repeat(t[None, :, None], 4, axis=0), 3, axis=2)
    path = tmp_path_factory.mktemp("ramp") / "thickness.exr"
    write_image(path, img, dtype="float")
    return path, t


@pytest.fixture(scope="module")
def colour_chart(tmp_path_factory):
    """An XYZ EXR: spectral colours at Y <= 0.6 and object colours."""
    xyz = np.concatenate([spectral_colours(0.6, 30), object_colours(n_random=1000)])
    width = 128
    rows = -(-len(xyz) // width)
    pad = np.zeros((rows * width - len(xyz), 3))
    img = np.concatenate([xyz, pad]).reshape(rows, width, 3)
    path = tmp_path_factory.mktemp("chart") / "xyz.exr"
    write_image(path, img, dtype="float")
    n_spectral = len(spectral_colours(0.6, 30))
    return path, xyz, n_spectral


def analytic(XYZ, display, view):
    rgb = colorimetry.XYZ_to_RGB(XYZ, display)
    if view == "Constant-Lightness Clip":
        return encode(colorimetry.XYZ_to_RGB(clip.clip_XYZ(XYZ, display), display), display)
    if view == "Constant-Lightness Compress":
        return encode(compress.compress_RGB(rgb, display), display)
    if view == "Channel Clamp":
        return encode(clip.clamp_RGB(rgb), display)
    if view == "ACES Gamut Compression":
        return encode(clip.aces_gamut_compress_RGB(rgb), display)
    raise ValueError(view)


@pytest.mark.parametrize("display", DISPLAYS)
@pytest.mark.parametrize("view", registry.VIEWS)
def test_thickness_ramp_through_every_display_and_view(thickness_ramp, tmp_path, display, view):
    src, t = thickness_ramp
    out = tmp_path / "out.exr"
    oiiotool(
        src,
        "--iscolorspace",
        "Thin Film Phase-Change Thickness",
        "--ociodisplay",
        display,
        view,
        "-d",
        "float",
        "-o",
        out,
    )
    got = read_image(out)[0].astype(np.float64)
    XYZ = colorimetry.film_XYZ(t * 1000.0, "phase-change")
    if view == "Raw":  # data: passed through unchanged
        np.testing.assert_allclose(got, np.repeat(t[:, None], 3, 1), atol=1e-6)
        return
    want = analytic(XYZ, display, view)
    de = colorimetry.delta_E2000(
        colorimetry.RGB_to_XYZ(decode(got, display), display),
        colorimetry.RGB_to_XYZ(decode(want, display), display),
    )
    if view.startswith("Constant-Lightness"):
        assert np.percentile(de, 99) <= CLIP_P99 and de.max() <= CLIP_MAX, de.max()
    else:
        assert de.max() <= EXACT_MAX, de.max()
    assert np.all(got >= -1e-6) and np.all(got <= 1 + 1e-4)


@pytest.mark.parametrize("display", DISPLAYS)
def test_xyz_chart_through_constant_lightness_clip(colour_chart, tmp_path, display):
    src, xyz, n_spectral = colour_chart
    out = tmp_path / "out.exr"
    oiiotool(
        src,
        "--iscolorspace",
        "CIE-XYZ-D65",
        "--ociodisplay",
        display,
        "Constant-Lightness Clip",
        "-d",
        "float",
        "-o",
        out,
    )
    got = read_image(out).reshape(-1, 3)[: len(xyz)].astype(np.float64)
    linear = decode(got, display)
    # Promise 1: in gamut (code values and display-linear RGB in [0, 1]).
    assert clip.in_gamut(got, 1e-4).all()
    # Promise 2: Y preserved (target |dY| <= 1e-3; both passes keep Y at their nodes;
    # the per-set account: tests/test_clip_view.py).
    Y_out = colorimetry.RGB_to_XYZ(linear, display)[:, 1]
    Y_in = np.minimum(xyz[:, 1], 1.0)
    assert np.abs(Y_out - Y_in).max() <= 1e-3
    # Agreement with the analytic clip (targets: p99 <= 0.5, max <= 1.5 per set).
    want = colorimetry.XYZ_to_RGB(clip.clip_XYZ(xyz, display), display)
    de = colorimetry.delta_E2000(
        colorimetry.RGB_to_XYZ(linear, display), colorimetry.RGB_to_XYZ(want, display)
    )
    spectral = slice(0, n_spectral)
    for part in (de[n_spectral:], de[spectral]):
        assert np.percentile(part, 99) <= 0.5 and part.max() <= 1.6, (
            np.percentile(part, 99),
            part.max(),
        )


def test_colorconvert_and_thin_film_space(thickness_ramp, tmp_path):
    src, t = thickness_ramp
    out = tmp_path / "xyz.exr"
    oiiotool(
        src,
        "--colorconvert",
        "Thin Film Phase-Change Thickness",
        "CIE-XYZ-D65",
        "-d",
        "float",
        "-o",
        out,
    )
    got = read_image(out)[0].astype(np.float64)
    direct = colorimetry.film_XYZ(t * 1000.0, "phase-change")
    assert colorimetry.delta_E2000(got, direct).max() <= 0.05
