"""A three.js page that draws glTF films and three.js's own iridescence, for tests/test_gltf.py.

The scene is tests/test_three_material.py's: a unit sphere under a uniform white
environment (three.js's PMREM of a white background), an orthographic camera over
[-1, 1]², sRGB output, no tone mapping. ``cases.json`` lists what to draw, one frame each,
read back bottom row first into ``<pre id="readback">``:

- ``{"kind": "physical", ...}``: a ``MeshPhysicalMaterial`` (roughness 0) with
  three.js's iridescence set by hand (``film_ior``, ``thickness`` nm, ``factor``,
  ``ior``, ``metalness``, ``color`` linear) on a 512 x 256 ``SphereGeometry``;
- ``{"kind": "gltf", "url": ..., "plugin": bool}``: a ``.glb`` through ``GLTFLoader``,
  with or without the ocio-thinfilm plugin;
- ``{"kind": "module", "url": ..., "module": ..., "thickness": µm}``: the ``.glb``'s mesh
  with the three.js film module's ``applyThinFilm`` (its EXR table) instead;
- ``{"kind": "hand", "url": ..., ...}``: the ``.glb``'s mesh with a
  ``MeshPhysicalMaterial`` whose iridescence is set by hand as for ``physical`` (and
  ``transmission``, if given: ``KHR_materials_transmission``'s factor).

A case with ``"checker": [[r, g, b], [r, g, b]]`` (linear) has a checker of those colours
(``squares`` a side, ``MeshBasicMaterial``, nearest filtering) on a plane behind the
sphere filling the view: what a free-standing film transmits.
"""

from __future__ import annotations

import json
from pathlib import Path

__all__ = ["write_site"]

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
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { ThinFilmGLTFPlugin } from "./ocio_thinfilm_gltf.js";

const out = { frames: [] };
try {
  const { size: SIZE, cases } = await (await fetch("cases.json")).json();
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
  async function load(url, plugin) {
    const loader = new GLTFLoader();
    if (plugin) loader.register((parser) => new ThinFilmGLTFPlugin(parser));
    return (await loader.loadAsync(url)).scene;
  }
  function firstMesh(root) {
    let mesh = null;
    root.traverse((o) => { if (o.isMesh && !mesh) mesh = o; });
    return mesh;
  }
  function byHand(c) {
    return new THREE.MeshPhysicalMaterial({ roughness: 0, metalness: c.metalness,
      color: new THREE.Color().setRGB(...c.color, THREE.LinearSRGBColorSpace), ior: c.ior,
      iridescence: c.factor, iridescenceIOR: c.film_ior,
      iridescenceThicknessMinimum: c.thickness, iridescenceThicknessMaximum: c.thickness,
      transmission: c.transmission || 0 });
  }
  function checker(c) {
    const n = c.squares || 8;
    const data = new Float32Array(n * n * 4);
    for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
      data.set([...c.checker[(i + j) % 2], 1], 4 * (j * n + i));
    }
    const texture = new THREE.DataTexture(data, n, n, THREE.RGBAFormat, THREE.FloatType);
    texture.magFilter = texture.minFilter = THREE.NearestFilter;
    texture.needsUpdate = true;
    const back = new THREE.Mesh(new THREE.PlaneGeometry(2, 2),
      new THREE.MeshBasicMaterial({ map: texture }));
    back.position.z = -2;
    return back;
  }
  for (const c of cases) {
    let object;
    if (c.kind === "physical") {
      object = new THREE.Mesh(new THREE.SphereGeometry(1, 512, 256), byHand(c));
    } else if (c.kind === "gltf") {
      object = await load(c.url, c.plugin);
    } else {
      const mesh = firstMesh(await load(c.url, false));
      let material;
      if (c.kind === "module") {
        const film = await (await import("./" + c.module)).loadThinFilm();
        material = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: 0 });
        film.apply(material, { thickness: c.thickness });
      } else {
        material = byHand(c);
      }
      object = new THREE.Mesh(mesh.geometry, material);
      object.matrix.copy(mesh.matrixWorld);
      object.matrixAutoUpdate = false;
    }
    const back = c.checker ? checker(c) : null;
    if (back) scene.add(back);
    scene.add(object);
    out.frames.push(frame());
    scene.remove(object);
    if (back) scene.remove(back);
  }
  out.size = SIZE;
} catch (error) {
  out.error = String(error && error.stack || error);
}
document.getElementById("readback").textContent = JSON.stringify(out);
"""


def write_site(root: Path, three: Path, files: dict[str, bytes], size: int, cases: list) -> None:
    """Lay out the page in ``root`` (which must not exist): ``index.html``, ``page.js``,
    ``cases.json``, the given files (the ``.glb``, the plugin, film modules and tables)
    and ``node_modules/three`` (a link to ``three``)."""
    root.mkdir(parents=True)
    (root / "index.html").write_text(_INDEX, encoding="utf-8")
    (root / "page.js").write_text(_PAGE, encoding="utf-8")
    (root / "cases.json").write_text(json.dumps({"size": size, "cases": cases}), encoding="utf-8")
    for name, data in files.items():
        (root / name).write_bytes(data)
    (root / "node_modules").mkdir()
    (root / "node_modules" / "three").symlink_to(three, target_is_directory=True)
