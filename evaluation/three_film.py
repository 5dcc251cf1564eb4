"""A three.js page that draws a mirror sphere with the exported film module, for the test
(tests/test_three_material.py) and the benchmark (benchmarks/bench_three_material.py).

The scene: a unit sphere (``MeshPhysicalMaterial``, metalness 1, roughness 0) under a
uniform white environment (three.js's PMREM of a scene whose background is white), an
orthographic camera over [-1, 1]², sRGB output, no tone mapping. The page renders one
frame per thickness, reads each back (``gl.readPixels``, bottom row first) and writes
JSON into ``<pre id="readback">``. With ``timing`` it then draws the film and three.js's
own iridescence (``iridescence = 1``) once each and ``timing`` more frames of the one the
URL's ``?draw=film|iridescence`` names, each finished by a 1-pixel ``readPixels`` (the
page runs in the browser's virtual time, so the caller times the whole run).
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path

__all__ = ["MODULE", "write_flat_site", "write_site"]

#: The film module's file name in the site.
MODULE = "thinfilm.js"

_INDEX = """<!doctype html>
<html><head><meta charset="utf-8">
<script type="importmap">
{ "imports": { "three": "./node_modules/three/build/three.module.js",
               "three/addons/": "./node_modules/three/examples/jsm/" } }
</script></head>
<body style="margin:0">
<pre id="readback"></pre>
<script type="module" src="page.js"></script>
</body></html>
"""

_PAGE = """import * as THREE from "three";
import { loadThinFilm } from "./__MODULE__";

const SIZE = __SIZE__, THICKNESSES = __THICKNESSES__, TIMING = __TIMING__;
const out = {};
try {
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(SIZE, SIZE);
  document.body.appendChild(renderer.domElement);
  const pmrem = new THREE.PMREMGenerator(renderer);
  const white = new THREE.Scene();
  white.background = new THREE.Color(1, 1, 1);
  const scene = new THREE.Scene();
  scene.environment = pmrem.fromScene(white).texture;
  const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
  camera.position.z = 5;
  const film = await loadThinFilm();
  const material = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: 0 });
  const uniforms = film.apply(material, { thickness: THICKNESSES[0] });
  const sphere = new THREE.Mesh(new THREE.SphereGeometry(1, 512, 256), material);
  scene.add(sphere);
  const gl = renderer.getContext();
  const px = new Uint8Array(SIZE * SIZE * 4);
  function frame() {
    renderer.render(scene, camera);
    gl.readPixels(0, 0, SIZE, SIZE, gl.RGBA, gl.UNSIGNED_BYTE, px);
    let bytes = "";
    for (let i = 0; i < px.length; i += 0x8000) {
      bytes += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
    }
    return btoa(bytes);
  }
  out.size = SIZE;
  out.frames = THICKNESSES.map((t) => { uniforms.thinFilmThickness.value = t; return frame(); });
  if (TIMING) {  // warm both programs up, then draw TIMING frames of ?draw=film|iridescence
    const one = new Uint8Array(4);
    const iridescent = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: 0,
      iridescence: 1, iridescenceIOR: 1.33, iridescenceThicknessRange: [400, 400] });
    const draw = new URLSearchParams(location.search).get("draw");
    const chosen = { film: material, iridescence: iridescent }[draw];
    for (const m of [material, iridescent, chosen]) {
      sphere.material = m;
      renderer.render(scene, camera);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, one);
    }
    for (let i = 0; i < TIMING - 1; i++) {
      renderer.render(scene, camera);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, one);  // the frame is finished
    }
    out.drawn = draw;
  }
} catch (error) {
  out.error = String(error && error.stack || error);
}
document.getElementById("readback").textContent = JSON.stringify(out);
"""


def write_site(
    root: Path,
    three: Path,
    module_text: str,
    size: int,
    thicknesses: Sequence[float],
    timing: int = 0,
) -> None:
    """Lay out the page in ``root`` (which must not exist): ``index.html``, ``page.js``,
    the film module and ``node_modules/three`` (a link to ``three``); the caller puts
    the table EXR beside them."""
    root.mkdir(parents=True)
    (root / "index.html").write_text(_INDEX, encoding="utf-8")
    page = (
        _PAGE.replace("__MODULE__", MODULE)
        .replace("__SIZE__", str(int(size)))
        .replace("__THICKNESSES__", json.dumps([float(t) for t in thicknesses]))
        .replace("__TIMING__", str(int(timing)))
    )
    (root / "page.js").write_text(page, encoding="utf-8")
    (root / MODULE).write_text(module_text, encoding="utf-8")
    (root / "node_modules").mkdir()
    (root / "node_modules" / "three").symlink_to(three, target_is_directory=True)


#: A page of flat films facing an orthographic camera over [-1, 1]², one frame per scene
#: of its JSON configuration, read back as the sphere page's frames. ``map``: a mirror
#: plane (metalness 1, roughness 0) filling the view under a uniform environment of
#: radiance ``environment``, its thickness from a one-row RGBA8 map (``codes``: the G
#: channel per column, as wide as the canvas) over ``thicknessRange``; ``bubble``: a
#: checker (``MeshBasicMaterial``, linear colours ``checker[0]`` and ``[1]``, ``squares``
#: per side, nearest filtering) behind a flat free-standing film (``bubble`` half-width,
#: thickness ``thickness``) that transmits (the module's T table), under a uniform
#: environment; ``shape: "sphere"`` makes the bubble a double-sided sphere of that
#: radius, ``codes`` (with ``mapAxis`` ``"u"`` or ``"v"`` and ``thicknessRange``) gives
#: it a thickness map, ``transmits: false`` keeps it opaque (no T). With ``badRange`` the
#: page records the Error ``applyThinFilm`` throws for that thickness map range. sRGB
#: output, no tone mapping.
_FLAT_PAGE = """import * as THREE from "three";
import { loadThinFilm } from "./__MODULE__";

const CONFIG = __CONFIG__;
const SIZE = CONFIG.size;
const out = { frames: [] };
try {
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(SIZE, SIZE);
  renderer.toneMapping = THREE.NoToneMapping;
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  document.body.appendChild(renderer.domElement);
  const pmrem = new THREE.PMREMGenerator(renderer);
  function environment(radiance) {
    const uniform = new THREE.Scene();
    uniform.background = new THREE.Color(radiance, radiance, radiance);
    return pmrem.fromScene(uniform).texture;
  }
  const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
  camera.position.z = 5;
  const film = await loadThinFilm();
  const gl = renderer.getContext();
  const px = new Uint8Array(SIZE * SIZE * 4);
  function frame(scene) {
    renderer.render(scene, camera);
    gl.readPixels(0, 0, SIZE, SIZE, gl.RGBA, gl.UNSIGNED_BYTE, px);
    let bytes = "";
    for (let i = 0; i < px.length; i += 0x8000) {
      bytes += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
    }
    return btoa(bytes);
  }
  if (CONFIG.badRange) {  // a thickness map range outside the table's: refused
    try {
      film.apply(new THREE.MeshPhysicalMaterial(), { thicknessMap: new THREE.Texture(),
        thicknessRange: CONFIG.badRange });
      out.badRange = "accepted";
    } catch (error) {
      out.badRange = error.message;
    }
  }
  function thicknessMap(codes, axis) {  // one row (axis "u") or column ("v") of G codes
    const data = new Uint8Array(codes.length * 4);
    codes.forEach((g, i) => data.set([0, g, 0, 255], 4 * i));
    const along = axis === "v";
    const map = new THREE.DataTexture(data, along ? 1 : codes.length, along ? codes.length : 1);
    map.magFilter = map.minFilter = THREE.LinearFilter;
    map.needsUpdate = true;
    return map;
  }
  for (const spec of CONFIG.scenes) {
    const scene = new THREE.Scene();
    scene.environment = environment(spec.environment);
    if (spec.kind === "map") {
      const map = thicknessMap(spec.codes, "u");
      const material = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: 0 });
      film.apply(material, { thicknessMap: map, thicknessRange: spec.thicknessRange,
        transmittance: null });
      scene.add(new THREE.Mesh(new THREE.PlaneGeometry(2, 2), material));
    } else {
      const n = spec.squares;
      const data = new Float32Array(n * n * 4);
      for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
        data.set([...spec.checker[(i + j) % 2], 1], 4 * (j * n + i));
      }
      const checker = new THREE.DataTexture(data, n, n, THREE.RGBAFormat, THREE.FloatType);
      checker.magFilter = checker.minFilter = THREE.NearestFilter;
      checker.needsUpdate = true;
      const back = new THREE.Mesh(new THREE.PlaneGeometry(2, 2),
        new THREE.MeshBasicMaterial({ map: checker }));
      back.position.z = -1;
      scene.add(back);
      const sphere = spec.shape === "sphere";
      const material = new THREE.MeshPhysicalMaterial({ metalness: 0, roughness: 0,
        side: sphere ? THREE.DoubleSide : THREE.FrontSide });
      const options = spec.codes
        ? { thicknessMap: thicknessMap(spec.codes, spec.mapAxis),
          thicknessRange: spec.thicknessRange }
        : { thickness: spec.thickness };
      if (spec.transmits === false) options.transmittance = null;  // a black-backed mirror
      film.apply(material, options);
      const w = 2 * spec.bubble;
      const geometry = sphere ? new THREE.SphereGeometry(spec.bubble, 256, 128)
        : new THREE.PlaneGeometry(w, w);
      scene.add(new THREE.Mesh(geometry, material));
    }
    out.frames.push(frame(scene));
  }
} catch (error) {
  out.error = String(error && error.stack || error);
}
document.getElementById("readback").textContent = JSON.stringify(out);
"""


def write_flat_site(root: Path, three: Path, module_text: str, config: dict) -> None:
    """Lay out the flat films' page (:data:`_FLAT_PAGE`) in ``root`` (which must not
    exist), with ``config`` (``size``, ``scenes``); the caller puts the tables beside it."""
    root.mkdir(parents=True)
    (root / "index.html").write_text(_INDEX, encoding="utf-8")
    page = _FLAT_PAGE.replace("__MODULE__", MODULE).replace("__CONFIG__", json.dumps(config))
    (root / "page.js").write_text(page, encoding="utf-8")
    (root / MODULE).write_text(module_text, encoding="utf-8")
    (root / "node_modules").mkdir()
    (root / "node_modules" / "three").symlink_to(three, target_is_directory=True)
