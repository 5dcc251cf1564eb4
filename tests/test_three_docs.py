"""The three.js page of docs/glsl.md, run: its ``index.html`` and ``main.js`` read from the
page, three.js from npm (:func:`evaluation.browser.install_three`), a scene of test
colours, served on localhost and opened in headless Chromium (WebGL2 on SwiftShader) at
device pixel ratios 1 and 2. Every pixel of the canvas is held to the double-precision
analytic view (:func:`evaluation.shaders.analytic_view`) of the colour the scene puts
there, as the composer's half-float target holds it.

Skips, with the reason, without Chromium, or where three.js cannot be installed (no npm,
no network).
"""

from __future__ import annotations

import base64
import json
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

from evaluation import browser
from evaluation.colours import gamut_map_sets
from evaluation.shaders import analytic_view, source_values
from ocio_thinfilm import registry
from ocio_thinfilm.colour import compress
from ocio_thinfilm.export import shader

DOC = Path(__file__).resolve().parents[1] / "docs" / "glsl.md"
SOURCE = "Linear Rec.709 (sRGB)"
DISPLAY = "sRGB"
#: 8-bit canvas codes against the analytic view's code values.
TOLERANCE = 2.0 / 255.0
#: The scene: a float texture of COLUMNS x ROWS test colours stretched over the canvas,
#: the window's size (headless Chromium's page is a little smaller than its window).
COLUMNS, ROWS = 32, 16
WINDOW = (512, 400)
#: The knobs readback.js sets through ``viewPass`` after the defaults' frame.
KNOBS = (0.6, 1.5)

_SCENE_JS = """import * as THREE from "three";

const colours = await (await fetch("colours.json")).json();
const texture = new THREE.DataTexture(new Float32Array(colours.rgba), colours.columns,
  colours.rows, THREE.RGBAFormat, THREE.FloatType);
texture.colorSpace = THREE.LinearSRGBColorSpace;
texture.magFilter = texture.minFilter = THREE.NearestFilter;
texture.needsUpdate = true;

const scene = new THREE.Scene();
scene.add(new THREE.Mesh(new THREE.PlaneGeometry(2, 2),
  new THREE.MeshBasicMaterial({ map: texture })));
const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
camera.position.z = 1;
export { scene, camera };
"""

_READBACK_JS = """import { renderer, composer, viewPass } from "./main.js";

const gl = renderer.getContext();
function frame() {
  composer.render();
  const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const px = new Uint8Array(w * h * 4);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
  let bytes = "";
  for (let i = 0; i < px.length; i += 0x8000) {
    bytes += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
  }
  return { width: w, height: h, rgba: btoa(bytes) };
}
const out = { dpr: window.devicePixelRatio, css: [window.innerWidth, window.innerHeight],
              defaults: frame() };
viewPass.uniforms.ocio_thinfilm_threshold.value = __THRESHOLD__;
viewPass.uniforms.ocio_thinfilm_limit.value = __LIMIT__;
out.knobs = frame();
document.getElementById("readback").textContent = JSON.stringify(out);
"""


def _block(name):
    text = DOC.read_text(encoding="utf-8")
    match = re.search(rf"<!-- three\.js:{re.escape(name)} -->\n```\w+\n(.*?)```", text, re.S)
    assert match, f"docs/glsl.md has no block {name}"
    return match.group(1)


@pytest.fixture(scope="module")
def three():
    try:
        return browser.install_three()
    except RuntimeError as error:
        pytest.skip(f"no three.js to run docs/glsl.md's page with: {error}")


def _colours():
    """COLUMNS x ROWS test colours (the gamut maps' sets, evenly taken), float32 RGB of
    SOURCE, row 0 at the bottom (the texture's first row)."""
    sets = gamut_map_sets().values()
    per = COLUMNS * ROWS // len(sets)
    XYZ = np.concatenate([v[:: len(v) // per][:per] for v in sets])
    return source_values(XYZ, SOURCE).astype(np.float32)


def _site(root, three, main_js):
    """The page's files in ``root``, as a user lays them out, plus the test's scene and
    readback; returns the test colours."""
    root.mkdir()
    index = _block("index.html").replace(
        "</body>",
        '<pre id="readback"></pre>\n<script type="module" src="readback.js"></script>\n</body>',
    )
    (root / "index.html").write_text(index, encoding="utf-8")
    (root / "main.js").write_text(main_js, encoding="utf-8")
    (root / "scene.js").write_text(_SCENE_JS, encoding="utf-8")
    readback = _READBACK_JS.replace("__THRESHOLD__", str(KNOBS[0]))
    (root / "readback.js").write_text(readback.replace("__LIMIT__", str(KNOBS[1])))
    glsl = shader.shader_source("glsl", DISPLAY, registry.COMPRESS_VIEW, SOURCE)
    (root / "thinfilm_view.glsl").write_text(glsl, encoding="utf-8")
    rgb = _colours()
    rgba = np.concatenate([rgb, np.ones((len(rgb), 1), np.float32)], axis=1)
    colours = {"columns": COLUMNS, "rows": ROWS, "rgba": [float(v) for v in rgba.ravel()]}
    (root / "colours.json").write_text(json.dumps(colours))
    (root / "node_modules").mkdir()
    (root / "node_modules" / "three").symlink_to(three, target_is_directory=True)
    return rgb


def _run(chromium, tmp_path, three, dpr, main_js):
    """Serve the page, open it at ``dpr`` and return (readback, test colours)."""
    rgb = _site(tmp_path / "site", three, main_js)
    with browser.serve(tmp_path / "site") as url:
        dom, stderr, _ = browser.dump_dom(
            chromium,
            url + "index.html",
            tmp_path / "profile",
            f"--window-size={WINDOW[0]},{WINDOW[1]}",
            f"--force-device-scale-factor={dpr}",
        )
    return browser.page_readback(dom, stderr), rgb


def _texels(n_pixels, n_texels):
    """The texel under each pixel's centre, as (below, above): they differ only where the
    centre lies on a border between two texels (either may be drawn there)."""
    at = (np.arange(n_pixels) + 0.5) * n_texels / n_pixels
    return (
        np.clip(np.floor(at - 1e-9), 0, n_texels - 1).astype(int),
        np.clip(np.floor(at + 1e-9), 0, n_texels - 1).astype(int),
    )


def _errors(frame, rgb, threshold, limit):
    """|canvas - analytic view| per pixel (H, W), top row last (GL's order), and per
    test colour (its block's worst)."""
    w, h = frame["width"], frame["height"]
    canvas = np.frombuffer(base64.b64decode(frame["rgba"]), np.uint8).reshape(h, w, 4) / 255.0
    held = rgb.astype(np.float16).astype(np.float64)  # the composer's HalfFloatType target
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        truth = analytic_view(held, SOURCE, DISPLAY, registry.COMPRESS_VIEW, threshold, limit)
    candidates = [
        row[:, None] * COLUMNS + column[None, :]
        for row in _texels(h, ROWS)
        for column in _texels(w, COLUMNS)
    ]
    errors = [np.abs(canvas[:, :, :3] - truth[i]).max(axis=2) for i in candidates]
    error = np.minimum.reduce(errors)
    index = candidates[0]
    per_colour = np.zeros(COLUMNS * ROWS)
    np.maximum.at(per_colour, index.ravel(), error.ravel())
    assert np.all(canvas[:, :, 3] == 1.0)
    return error, per_colour


@pytest.mark.parametrize("dpr", [1, 2])
def test_the_three_js_page_draws_the_analytic_view(chromium, three, tmp_path, dpr):
    out, rgb = _run(chromium, tmp_path, three, dpr, _block("main.js"))
    assert out["dpr"] == dpr
    worst = {}
    for key, knobs in [("defaults", (compress.THRESHOLD, compress.LIMIT)), ("knobs", KNOBS)]:
        frame = out[key]
        assert [frame["width"], frame["height"]] == [v * dpr for v in out["css"]]
        error, _ = _errors(frame, rgb, *knobs)
        worst[knobs] = round(float(error.max()) * 255, 3)
    size = f"{out['defaults']['width']}x{out['defaults']['height']}"
    print(
        f"\nthree.js {browser.THREE_VERSION}, DPR {dpr} ({size} pixels): "
        f"max |canvas - analytic| (1/255) by knobs {worst}"
    )
    assert max(worst.values()) <= TOLERANCE * 255
    moved, _ = _errors(out["knobs"], rgb, compress.THRESHOLD, compress.LIMIT)
    assert moved.max() > 10 * TOLERANCE  # the knobs set on viewPass do show


def test_a_target_of_the_css_size_fails_at_dpr_2(chromium, three, tmp_path):
    """The check sees the mistake the page warns of: a render target of the window's CSS
    size holds the scene at half the size on a DPR 2 screen."""
    main_js = _block("main.js")
    right = "new EffectComposer(renderer)"
    assert right in main_js
    wrong = main_js.replace(
        right,
        "new EffectComposer(renderer, new THREE.WebGLRenderTarget(window.innerWidth, "
        "window.innerHeight, { type: THREE.HalfFloatType }))",
    )
    out, rgb = _run(chromium, tmp_path, three, 2, wrong)
    error, per_colour = _errors(out["defaults"], rgb, compress.THRESHOLD, compress.LIMIT)
    off = int((per_colour > TOLERANCE).sum())
    print(
        f"\nCSS-sized target at DPR 2: {off} of {per_colour.size} test colours off by more "
        f"than 2/255 somewhere in their block, {(error > TOLERANCE).mean():.1%} of the "
        f"pixels (worst {error.max() * 255:.0f}/255)"
    )
    assert off > per_colour.size // 4
