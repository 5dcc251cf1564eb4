"""The three.js film module (:func:`ocio_thinfilm.export.hosts.three.three_module`), run:
a mirror sphere (``MeshPhysicalMaterial``, metalness 1, roughness 0) under a uniform
white environment, orthographic camera, in headless Chromium (WebGL2 on SwiftShader) with
three.js from npm (:func:`evaluation.browser.install_three`). Every pixel away from the
silhouette is held, through three.js's sRGB output, to the exact reflectance at that
pixel's angle: colour-science's transfer matrices (s and p averaged), CIE 1931 2°, D65,
sRGB (:mod:`evaluation.materials`), never the package's own physics. The table the page
loads is written by :mod:`evaluation.materials` in the film-as-material layout.

A second page (:func:`evaluation.three_film.write_flat_site`) draws flat films facing the
camera: a mirror plane whose thickness map is a ramp of G codes across the canvas, held
to the exact colours of those thicknesses, and a free-standing film over a checker,
held to R·L + T·background (three.js's ``NoToneMapping`` and sRGB output; R and T from
colour-science); it also checks that a thickness map range outside the table is refused.

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
        out = browser.run_page(
            chromium, url + "index.html", tmp_path / "profile", "--window-size=400,400"
        )
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


#: The flat films' film: a dyed soap film (n = 1.33 + 0.02i) in air, absorbing, so that its
#: T is not 1 - R (for a clear film it is: a test of T would not tell them apart).
DYED = materials.Stack.single(1.33 + 0.02j)
#: The flat films' page (:func:`evaluation.three_film.write_flat_site`): a thickness map
#: (a ramp of G codes 0-255 over the canvas' columns, mapped to MAP_RANGE) on a mirror
#: plane under a white environment; a bubble (BUBBLE_UM thick, half-width 0.75) over a
#: checker of CHECKER's linear colours, 8 squares a side, under an environment of
#: radiance BUBBLE_L. A smaller canvas: every pixel is checked.
FLAT = 128
MAP_RANGE = (0.25, 0.65)
CODES = [round(i * 255 / (FLAT - 1)) for i in range(FLAT)]
CHECKER = ((0.8, 0.25, 0.05), (0.05, 0.4, 0.9))
SQUARES, BUBBLE_HALF, BUBBLE_UM, BUBBLE_L = 8, 0.75, 0.45, 0.25
#: Pixels this far (in pixels) from a checker or bubble edge are held to the expectation
#: (three.js's transmission pass reads its render target with a bicubic B-spline).
MARGIN = 3


@pytest.fixture(scope="module")
def flat_frames(chromium, three, tmp_path_factory):
    """The flat films' page run once: {"map", "bubble"} frames (bottom row first) and
    the message of the Error a thickness map range outside the table's gave."""
    tmp = tmp_path_factory.mktemp("flat")
    module = three_module(
        "Soap", "Soap_R.exr", RANGE_UM, transmittance_exr="Soap_T.exr", name="Soap bubble"
    )
    scenes = [
        {"kind": "map", "environment": 1.0, "codes": CODES, "thicknessRange": MAP_RANGE},
        {
            "kind": "bubble",
            "environment": BUBBLE_L,
            "squares": SQUARES,
            "checker": CHECKER,
            "bubble": BUBBLE_HALF,
            "thickness": BUBBLE_UM,
        },
    ]
    config = {"size": FLAT, "badRange": [0.1, 0.5], "scenes": scenes}
    three_film.write_flat_site(tmp / "site", three, module, config)
    for quantity, suffix in (("reflectance", "R"), ("transmittance", "T")):
        rgb = materials.table(DYED, RANGE_UM, *TABLE, quantity=quantity)
        materials.write_table(
            tmp / "site" / f"Soap_{suffix}.exr",
            rgb,
            key="Soap",
            quantity=quantity,
            range_um=RANGE_UM,
        )
    with browser.serve(tmp / "site") as url:
        out = browser.run_page(
            chromium, url + "index.html", tmp / "profile", "--window-size=300,300"
        )
    assert "error" not in out, out.get("error")
    frames = [
        np.frombuffer(base64.b64decode(f), np.uint8).reshape(FLAT, FLAT, 4)[:, :, :3]
        for f in out["frames"]
    ]
    return {"map": frames[0], "bubble": frames[1], "badRange": out["badRange"]}


def _encode(linear):
    return colour.cctf_encoding(np.clip(linear, 0.0, 1.0), "sRGB")


def test_a_thickness_map_shows_the_exact_colours_of_its_thicknesses(flat_frames):
    thickness = MAP_RANGE[0] + (MAP_RANGE[1] - MAP_RANGE[0]) * np.array(CODES) / 255.0
    exact = _encode(materials.film_rgb(DYED, thickness, 1.0))  # one per column
    error = np.abs(flat_frames["map"] / 255.0 - exact[None]).max(axis=2) * 255.0
    print(f"\nthree.js thickness map: |canvas - exact| (1/255) max {error.max():.2f}")
    assert error.max() <= TOLERANCE
    assert np.ptp(flat_frames["map"][:, :, 1].astype(int), axis=1).max() > 40  # it varies


def test_a_thickness_map_range_outside_the_table_is_refused(flat_frames):
    message = flat_frames["badRange"]
    assert "thicknessRange" in message and "[0.2, 0.7]" in message, message


def _checker():
    """The checker's linear colour at each pixel (bottom row first) and the pixels at
    least MARGIN from its squares' edges."""
    x, y = np.meshgrid(np.arange(FLAT), np.arange(FLAT))
    side = FLAT // SQUARES
    even = ((x // side + y // side) % 2 == 0)[..., None]
    background = np.where(even, np.array(CHECKER[0]), np.array(CHECKER[1]))
    edge = np.minimum(np.minimum(x % side, side - 1 - x % side), y % side)
    away = np.minimum(edge, side - 1 - y % side) >= MARGIN
    return background, away


def test_a_bubble_transmits_the_checker_behind_it_times_t(flat_frames):
    background, away = _checker()
    centres = np.abs((np.arange(FLAT) + 0.5) / FLAT * 2.0 - 1.0)
    reach = np.maximum(centres[None, :], centres[:, None])  # Chebyshev: the square bubble
    inside = (reach < BUBBLE_HALF - 2.0 * MARGIN / FLAT) & away
    outside = (reach > BUBBLE_HALF + 2.0 * MARGIN / FLAT) & away
    r = materials.film_rgb(DYED, BUBBLE_UM, 1.0)
    t = materials.film_rgb(DYED, BUBBLE_UM, 1.0, quantity="transmittance")
    assert np.abs(1.0 - r - t).min() > 0.1  # T is told apart from 1 - R
    codes = flat_frames["bubble"] / 255.0
    error = np.abs(codes - _encode(r * BUBBLE_L + t * background)).max(axis=2) * 255.0
    direct = np.abs(codes - _encode(background)).max(axis=2) * 255.0
    print(
        f"\nthree.js bubble over a checker: |canvas - (R L + T background)| (1/255) max "
        f"{error[inside].max():.2f}; the checker beside it {direct[outside].max():.2f}"
    )
    assert error[inside].max() <= TOLERANCE
    assert direct[outside].max() <= TOLERANCE
    # the film is seen: without its reflection or its tint the pixels would be off
    assert np.abs(codes - _encode(background)).max(axis=2)[inside].max() * 255.0 > 5.0
    _keep_png(flat_frames["bubble"], "threejs_bubble.png")
    _keep_png(flat_frames["map"], "threejs_thickness_map.png")


def _keep_png(rgb, name):
    """Write an RGB frame (bottom row first) as ``name`` into ``OCIO_THINFILM_GALLERY``."""
    folder = os.environ.get("OCIO_THINFILM_GALLERY")
    if folder:
        import OpenImageIO as oiio

        image = oiio.ImageBuf(np.ascontiguousarray(rgb[::-1]))
        assert image.write(str(Path(folder) / name)), oiio.geterror()


def test_the_module_exports_the_film_name_and_loads_t():
    text = three_module(
        "Oil", "Oil_R.exr", (0.0, 2.0), transmittance_exr="out/Oil_T.exr", name="Oil slick"
    )
    assert 'export const FILM = "Oil slick";' in text
    assert 'export const FILM_KEY = "Oil";' in text
    assert 'TRANSMITTANCE_URL = new URL("Oil_T.exr", import.meta.url).href' in text
    assert "TRANSMITTANCE_URL = null" in three_module("Oil", "Oil_R.exr", (0.0, 2.0))


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


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"thickness_map_range_um": (0.1, 0.5)}, "thickness_map_range_um"),
        ({"thickness_map_range_um": (0.3, 1.2)}, "thickness_map_range_um"),
        ({"transmittance_exr": "Soap_T.png"}, "transmittance_exr"),
    ],
)
def test_bad_options_name_the_parameter(kwargs, match):
    with pytest.raises(ParameterError, match=f"^{match}") as error:
        three_module("Soap", "Soap_R.exr", (0.2, 0.7), **kwargs)
    if "thickness_map_range_um" in kwargs:  # names the allowed range
        assert "[0.2, 0.7]" in str(error.value)


def test_a_thickness_map_range_within_the_table_is_the_default():
    text = three_module("Soap", "R.exr", (0.2, 0.7), thickness_map_range_um=(0.3, 0.6))
    assert "THICKNESS_MAP_RANGE_UM = [0.3, 0.6]" in text
