"""The three.js film module (:func:`ocio_thinfilm.export.hosts.three.three_module`), run:
a mirror sphere (``MeshPhysicalMaterial``, metalness 1, roughness 0) under a uniform
white environment, orthographic camera, in headless Chromium (WebGL2 on SwiftShader) with
three.js from npm (:func:`evaluation.browser.install_three`). Every pixel away from the
silhouette is held, through three.js's sRGB output, to the exact reflectance at that
pixel's angle: colour-science's transfer matrices (s and p averaged), CIE 1931 2°, D65,
sRGB (:mod:`evaluation.materials`), never the package's own physics. The table the page
loads is written by :mod:`evaluation.materials` in the film-as-material layout.

Skips, with the reason, without Chromium or where three.js cannot be installed.
"""

from __future__ import annotations

import base64
import os
from pathlib import Path

import colour
import numpy as np
import pytest

from evaluation import browser, materials, three_film
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.export.hosts.three import three_module

#: A soap film (water, n = 1.33) in air, its table over 0.2-0.7 µm.
STACK = materials.SOAP_BUBBLE  # n = 1.33 in air
RANGE_UM = (0.2, 0.7)
TABLE = (128, 128)  # (width: thickness, height: cos θ)
THICKNESSES = (0.3, 0.61)
SIZE = 256
#: Away from the silhouette: pixels whose centre is within this radius (N·V >= 0.44).
RADIUS = 0.9
TOLERANCE = 2.0  # 8-bit codes


@pytest.fixture(scope="module")
def three():
    try:
        return browser.install_three()
    except RuntimeError as error:
        pytest.skip(f"no three.js to run the film module with: {error}")


def _exact_codes(thickness, cos_theta):
    """sRGB codes (0-1) of the film's exact reflectance at each cos θ (linear in cos θ
    between 4097 exact values: < 1e-5 off)."""
    grid = np.linspace(0.0, 1.0, 4097)
    exact = materials.film_rgb(STACK, thickness, grid)
    linear = np.stack([np.interp(cos_theta, grid, exact[:, k]) for k in range(3)], axis=1)
    return colour.cctf_encoding(np.clip(linear, 0.0, 1.0), "sRGB")


def test_the_mirror_sphere_shows_the_exact_reflectance(chromium, three, tmp_path):
    site = tmp_path / "site"
    module = three_module("Soap", "Soap_R.exr", RANGE_UM)
    three_film.write_site(site, three, module, SIZE, THICKNESSES)
    rgb = materials.table(STACK, RANGE_UM, *TABLE)
    materials.write_table(
        site / "Soap_R.exr", rgb, key="Soap", quantity="reflectance", range_um=RANGE_UM
    )
    with browser.serve(site) as url:
        dom, stderr, _ = browser.dump_dom(
            chromium, url + "index.html", tmp_path / "profile", "--window-size=400,400"
        )
    out = browser.page_readback(dom, stderr)
    assert "error" not in out, out.get("error")
    centres = (np.arange(SIZE) + 0.5) / SIZE * 2.0 - 1.0
    x, y = np.meshgrid(centres, centres)  # GL's rows: bottom first, as read back
    radius = np.hypot(x, y)
    inside = radius <= RADIUS
    cos_theta = np.sqrt(1.0 - radius[inside] ** 2)
    worst = {}
    for thickness, frame in zip(THICKNESSES, out["frames"], strict=True):
        rgba = np.frombuffer(base64.b64decode(frame), np.uint8).reshape(SIZE, SIZE, 4)
        codes = rgba[inside][:, :3] / 255.0
        error = np.abs(codes - _exact_codes(thickness, cos_theta)).max(axis=1) * 255.0
        worst[thickness] = (round(float(error.max()), 2), round(float(np.percentile(error, 99)), 2))
        assert np.all(rgba[radius > 1.02][:, :3] == 0)  # the background: black
    print(f"\nthree.js {browser.THREE_VERSION}: |canvas - exact| (1/255) max, p99 {worst}")
    assert max(w[0] for w in worst.values()) <= TOLERANCE
    _keep(out["frames"][1], tmp_path)
    # the thickness uniform does change the colours
    frames = [np.frombuffer(base64.b64decode(f), np.uint8) for f in out["frames"]]
    assert np.abs(frames[0].astype(int) - frames[1]).max() > 40


def _keep(frame, tmp_path):
    """Write the frame as ``threejs_soap.png`` (top row first) into tmp_path and, where
    the environment names a gallery directory (``OCIO_THINFILM_GALLERY``), there too."""
    import OpenImageIO as oiio

    rgba = np.frombuffer(base64.b64decode(frame), np.uint8).reshape(SIZE, SIZE, 4)[::-1]
    for folder in [tmp_path, os.environ.get("OCIO_THINFILM_GALLERY")]:
        if folder:
            image = oiio.ImageBuf(np.ascontiguousarray(rgba[:, :, :3]))
            assert image.write(str(Path(folder) / "threejs_soap.png")), oiio.geterror()


def test_the_module_names_its_table_and_range():
    text = three_module("Oil slick", "out/ThinFilm_User_Oil_R.exr", (0.0, 2.0))
    assert 'new URL("ThinFilm_User_Oil_R.exr", import.meta.url)' in text
    assert "THICKNESS_RANGE_UM = [0.0, 2.0]" in text
    assert 'import { EXRLoader } from "three/addons/loaders/EXRLoader.js"' in text


@pytest.mark.parametrize(
    "args, match",
    [
        (("Soap", "Soap_R.exr", (0.5, 0.5)), "range_um"),
        (("Soap", "Soap_R.exr", (-0.1, 1.0)), "range_um"),
        (("Soap", "Soap_R.png", (0.0, 1.0)), "reflectance_exr"),
        (("Soap", 'a"b.exr', (0.0, 1.0)), "reflectance_exr"),
    ],
)
def test_bad_arguments_name_the_parameter(args, match):
    with pytest.raises(ParameterError, match=f"^{match}"):
        three_module(*args)
