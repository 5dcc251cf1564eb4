"""The film where assets travel: a binary glTF (``.glb``) of the film on a sample sphere.

:func:`gltf_binary` writes one material on a UV sphere (docs/gltf.md):

- ``KHR_materials_iridescence`` (with ``KHR_materials_ior`` and the base colour /
  metalness), the fallback every viewer draws, its parameters fitted to the film
  (:mod:`ocio_thinfilm.lut.iridescence_fit`); for a free-standing film also
  ``KHR_materials_transmission`` (factor 1, the base colour the tint of the film's T);
- :data:`EXTENSION`, the exact film: its reflectance (and transmittance) table as float
  data in the binary chunk, node-centred, over ``range_um`` x cos theta, and the same
  thickness texture; listed in ``extensionsUsed`` only, so viewers without it fall back;
- a thickness texture (PNG, G channel: the fraction of ``range_um``, like
  ``iridescenceThicknessTexture``): soap-bubble swirls by default.

:func:`plugin_module` is the three.js ``GLTFLoader`` plugin (an ES module) that reads the
extension and draws the exact film. The bytes are the same on every run and CPU: no
dates, JSON written with sorted keys, floats of the mesh and texture through
:func:`ocio_thinfilm.reproducible.snap`, the PNG's deflate stream stored (uncompressed)
so no zlib implementation's choices reach it.
"""

from __future__ import annotations

import json
import struct
import zlib
from typing import Any

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import __version__, reproducible
from ocio_thinfilm.export.hosts import thickness_range
from ocio_thinfilm.export.hosts import three as three_host
from ocio_thinfilm.lut.khr_iridescence import KHRIridescence

__all__ = [
    "EXTENSION",
    "PLUGIN_NAME",
    "swirl_thickness",
    "png_bytes",
    "sphere_mesh",
    "gltf_binary",
    "plugin_module",
]

#: The vendor extension (glTF 2.0, 3.12: ``PREFIX_scope_feature``).
EXTENSION = "OCIO_THINFILM_materials_film"
#: The plugin module's file name.
PLUGIN_NAME = "ocio_thinfilm_gltf.js"
_GLB_MAGIC, _JSON, _BIN = 0x46546C67, 0x4E4F534A, 0x004E4942
_FLOAT, _USHORT, _UINT = 5126, 5123, 5125


def swirl_thickness(size: int = 256) -> np.ndarray:
    """Return a soap bubble's thickness texture: 8-bit fractions of the range, (size, size).

    Thinner towards the top (drainage) with swirling bands; row 0 is the texture's top
    (glTF's v = 0), columns wrap around the sphere.
    """
    u = (np.arange(size) + 0.5) / size
    x, y = np.meshgrid(2.0 * np.pi * u, u)
    swirl = np.sin(3.0 * x + 9.0 * y + 2.0 * np.sin(2.0 * x - 5.0 * y))
    g = 0.25 + 0.55 * y + 0.18 * swirl * np.sin(np.pi * y)
    g = reproducible.snap(np.clip(g, 0.0, 1.0) * 255.0)
    return np.floor(g + 0.5).astype(np.uint8)


def _stored_deflate(data: bytes) -> bytes:
    blocks = [data[i : i + 65535] for i in range(0, len(data), 65535)] or [b""]
    out = bytearray(b"\x78\x01")
    for i, block in enumerate(blocks):
        n = len(block)
        out += bytes([1 if i == len(blocks) - 1 else 0]) + struct.pack("<HH", n, n ^ 0xFFFF)
        out += block
    return bytes(out + struct.pack(">I", zlib.adler32(data)))


def png_bytes(grey: npt.ArrayLike) -> bytes:
    """Return an 8-bit RGB PNG with the (H, W) uint8 values in every channel."""
    g = np.asarray(grey, dtype=np.uint8)
    h, w = g.shape
    rows = np.repeat(g[:, :, None], 3, axis=2).reshape(h, w * 3)
    raw = b"".join(b"\x00" + row.tobytes() for row in rows)

    def chunk(kind: bytes, body: bytes) -> bytes:
        return (
            struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
        )

    header = struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", header)
        + chunk(b"IDAT", _stored_deflate(raw))
        + chunk(b"IEND", b"")
    )


def sphere_mesh(
    segments: int = 96, rings: int = 48
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Return a unit UV sphere: float32 positions, normals, texcoords and uint32 indices.

    u runs once around (a seam of duplicated vertices), v from the top (0) to the bottom
    (1), glTF's texture orientation; triangles wind counter-clockwise seen from outside.
    """
    u = np.arange(segments + 1) / segments
    v = np.arange(rings + 1) / rings
    uu, vv = np.meshgrid(u, v)
    phi, theta = 2.0 * np.pi * uu, np.pi * vv
    p = np.stack([-np.cos(phi) * np.sin(theta), np.cos(theta), np.sin(phi) * np.sin(theta)], -1)
    p = reproducible.snap(p).reshape(-1, 3).astype(np.float32)
    uv = np.stack([uu, vv], -1).reshape(-1, 2).astype(np.float32)
    a = (np.arange(rings)[:, None] * (segments + 1) + np.arange(segments)[None, :]).ravel()
    b, c, d = a + segments + 1, a + segments + 2, a + 1
    tris = np.concatenate([np.stack([a, b, d], -1), np.stack([b, c, d], -1)])
    return p, p.copy(), uv, tris.astype(np.uint32).ravel()


class _Buffer:
    """The binary chunk: buffer views, 4-byte aligned."""

    def __init__(self) -> None:
        self.data = bytearray()
        self.views: list[dict[str, Any]] = []

    def add(self, payload: bytes, target: int | None = None) -> int:
        self.data += b"\x00" * (-len(self.data) % 4)
        view: dict[str, Any] = {
            "buffer": 0,
            "byteOffset": len(self.data),
            "byteLength": len(payload),
        }
        if target is not None:
            view["target"] = target
        self.views.append(view)
        self.data += payload
        return len(self.views) - 1


def _accessors(buffer: _Buffer, mesh: tuple[np.ndarray, ...]) -> list[dict[str, Any]]:
    positions, normals, uv, indices = mesh
    out = []
    for array, kind, target in [
        (positions, "VEC3", 34962),
        (normals, "VEC3", 34962),
        (uv, "VEC2", 34962),
    ]:
        view = buffer.add(np.ascontiguousarray(array, "<f4").tobytes(), target)
        acc = {"bufferView": view, "componentType": _FLOAT, "count": len(array), "type": kind}
        out.append(acc)
    out[0]["min"] = [float(x) for x in positions.min(axis=0)]
    out[0]["max"] = [float(x) for x in positions.max(axis=0)]
    small = int(indices.max()) < 65535
    data = indices.astype("<u2" if small else "<u4").tobytes()
    view = buffer.add(data, 34963)
    out.append(
        {
            "bufferView": view,
            "componentType": _USHORT if small else _UINT,
            "count": len(indices),
            "type": "SCALAR",
        }
    )
    return out


def _table_accessor(buffer: _Buffer, table: np.ndarray) -> dict[str, Any]:
    values = np.ascontiguousarray(np.asarray(table, dtype=np.float64).astype("<f4"))
    view = buffer.add(values.tobytes())
    count = values.shape[0] * values.shape[1]
    return {"bufferView": view, "componentType": _FLOAT, "count": count, "type": "VEC3"}


def _material(
    name: str, fallback: KHRIridescence, film: dict[str, Any], texture: int
) -> dict[str, Any]:
    lo_nm, hi_nm = fallback.thickness_nm
    out: dict[str, Any] = {
        "name": name,
        "pbrMetallicRoughness": {
            "baseColorFactor": [*[float(c) for c in fallback.base_colour], 1.0],
            "metallicFactor": float(fallback.metalness),
            "roughnessFactor": 0.0,
        },
        "extensions": {
            "KHR_materials_ior": {"ior": float(fallback.base_ior)},
            "KHR_materials_iridescence": {
                "iridescenceFactor": float(fallback.factor),
                "iridescenceIor": float(fallback.ior),
                "iridescenceThicknessMinimum": float(lo_nm),
                "iridescenceThicknessMaximum": float(hi_nm),
                "iridescenceThicknessTexture": {"index": texture},
            },
            EXTENSION: film,
        },
    }
    if fallback.transmission > 0.0:
        out["extensions"]["KHR_materials_transmission"] = {
            "transmissionFactor": float(fallback.transmission)
        }
    return out


def gltf_binary(
    key: str,
    reflectance: npt.ArrayLike,
    range_um: tuple[float, float],
    fallback: KHRIridescence,
    *,
    transmittance: npt.ArrayLike | None = None,
    thickness: npt.ArrayLike | None = None,
    name: str | None = None,
) -> bytes:
    """Return the ``.glb`` of a film on a sample sphere.

    Parameters
    ----------
    key : str
        The film's key (the material's name unless ``name`` is given).
    reflectance : array_like
        The film's reflectance table, (H, W, 3) linear Rec.709 in texture row order (row
        0 at cos theta = 0), node-centred (:func:`ocio_thinfilm.export.material.material_table`).
    range_um : tuple of float
        The table's thickness axis ``(lo, hi)``.
    fallback : KHRIridescence
        The ``KHR_materials_iridescence`` material
        (:func:`ocio_thinfilm.lut.iridescence_fit.fit_iridescence`).
    transmittance : array_like, optional
        The transmittance table of a free-standing film, like ``reflectance``.
    thickness : array_like, optional
        The thickness texture, (h, w) uint8 fractions of ``range_um`` x 255 (default
        :func:`swirl_thickness`).
    name : str, optional
        The material's name.

    Returns
    -------
    bytes
        The GLB container (glTF 2.0).
    """
    lo, hi = thickness_range(range_um)
    R = np.asarray(reflectance, dtype=np.float64)
    if R.ndim != 3 or R.shape[2] != 3 or min(R.shape[:2]) < 2:
        raise ValueError(f"reflectance must be (H, W, 3) with H, W >= 2, got {R.shape}")
    buffer = _Buffer()
    mesh = _accessors(buffer, sphere_mesh())
    grey = swirl_thickness() if thickness is None else np.asarray(thickness, dtype=np.uint8)
    image = buffer.add(png_bytes(grey))
    accessors = [*mesh, _table_accessor(buffer, R)]
    film: dict[str, Any] = {
        "reflectance": len(accessors) - 1,
        "width": int(R.shape[1]),
        "height": int(R.shape[0]),
        "thicknessRange": [float(lo), float(hi)],
        "thicknessTexture": {"index": 0},
        "colorSpace": "lin_rec709",
        "film": key,
    }
    if transmittance is not None:
        T = np.asarray(transmittance, dtype=np.float64)
        if T.shape != R.shape:
            raise ValueError(f"transmittance must be shaped like reflectance, got {T.shape}")
        accessors.append(_table_accessor(buffer, T))
        film["transmittance"] = len(accessors) - 1
    used = ["KHR_materials_ior", "KHR_materials_iridescence", EXTENSION]
    if fallback.transmission > 0.0:
        used.insert(2, "KHR_materials_transmission")
    document = {
        "asset": {"version": "2.0", "generator": f"ocio-thinfilm {__version__}"},
        "extensionsUsed": used,
        "scene": 0,
        "scenes": [{"name": key, "nodes": [0]}],
        "nodes": [{"name": key, "mesh": 0}],
        "meshes": [
            {
                "name": f"{key} sample sphere",
                "primitives": [
                    {
                        "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                        "indices": 3,
                        "material": 0,
                    }
                ],
            }
        ],
        "materials": [_material(name or key, fallback, film, 0)],
        "textures": [{"sampler": 0, "source": 0}],
        "images": [{"bufferView": image, "mimeType": "image/png", "name": f"{key} thickness"}],
        "samplers": [{"magFilter": 9729, "minFilter": 9729, "wrapS": 10497, "wrapT": 33071}],
        "accessors": accessors,
        "bufferViews": buffer.views,
        "buffers": [{"byteLength": len(buffer.data) + (-len(buffer.data) % 4)}],
    }
    return _container(document, bytes(buffer.data))


def _container(document: dict[str, Any], binary: bytes) -> bytes:
    text = json.dumps(document, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    data = text.encode("utf-8")
    data += b" " * (-len(data) % 4)
    binary += b"\x00" * (-len(binary) % 4)
    total = 12 + 8 + len(data) + 8 + len(binary)
    return b"".join(
        [
            struct.pack("<III", _GLB_MAGIC, 2, total),
            struct.pack("<II", len(data), _JSON),
            data,
            struct.pack("<II", len(binary), _BIN),
            binary,
        ]
    )


_PLUGIN = """// ocio-thinfilm __VERSION__: a three.js GLTFLoader plugin for __EXTENSION__
// (tested with three.js r__REVISION__). It draws the exact film a .glb carries: the
// material's specular reflectance is the film's table R(thickness, angle) and, for a
// free-standing film (a transmittance table), what it transmits of the scene behind it is
// T(thickness, angle) times that (three.js's transmission pass), the thickness read from
// the extension's thickness texture (G channel: the fraction of thicknessRange), in place
// of three.js's KHR_materials_iridescence and KHR_materials_transmission (docs/gltf.md).
// The shader parts are the three.js film module's (ocio-thinfilm's thinfilm.js).
//
//   import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
//   import { ThinFilmGLTFPlugin } from "./__SELF__";
//   const loader = new GLTFLoader().register((parser) => new ThinFilmGLTFPlugin(parser));
//   const gltf = await loader.loadAsync("ThinFilm_User_Soap.glb");
import * as THREE from "three";

export const EXTENSION = __EXTENSION_JSON__;

const DECLARATIONS = __DECLARATIONS__;
const REPLACEMENTS = __REPLACEMENTS__;
const TRANSMISSION = __TRANSMISSION__;
const AT_LIGHTS = __AT_LIGHTS__;
const VERTEX = __VERTEX__;

function patched(chunk, from, to) {
  if (!chunk.includes(from)) {
    throw new Error(`ocio-thinfilm: three.js r${THREE.REVISION} has no "${from}" in its ` +
      "physical material's shader; this plugin was written for three.js r__REVISION__");
  }
  return chunk.split(from).join(to);
}

// three.js's physical lighting with the table's R as its Fresnel term and (with
// THIN_FILM_TRANSMITTANCE defined) T as its transmission: the film module's shader.
export function thinFilmGLTFShader(fragmentShader) {
  let lights = THREE.ShaderChunk.lights_physical_pars_fragment;
  for (const [from, to] of REPLACEMENTS) lights = patched(lights, from, to);
  let shader = patched(fragmentShader, "#include <lights_physical_pars_fragment>",
    DECLARATIONS + lights);
  shader = patched(shader, "#include <transmission_pars_fragment>",
    patched(THREE.ShaderChunk.transmission_pars_fragment, ...TRANSMISSION));
  return patched(shader, "#include <lights_fragment_begin>", AT_LIGHTS);
}

// The vertex shader: the thickness texture's uv (through its matrix).
export function thinFilmGLTFVertexShader(vertexShader) {
  let shader = vertexShader;
  for (const [from, to] of VERTEX) shader = patched(shader, from, to);
  return shader;
}

// A table (float RGB, row-major, row 0 at cos(theta) = 0) as a half-float texture:
// linear filtering, clamp to edge, no mipmaps.
export function thinFilmTableTexture(values, width, height) {
  const data = new Uint16Array(width * height * 4);
  const one = THREE.DataUtils.toHalfFloat(1);
  for (let i = 0; i < width * height; i++) {
    for (let k = 0; k < 3; k++) data[4 * i + k] = THREE.DataUtils.toHalfFloat(values[3 * i + k]);
    data[4 * i + 3] = one;
  }
  const texture = new THREE.DataTexture(data, width, height, THREE.RGBAFormat,
    THREE.HalfFloatType);
  texture.colorSpace = THREE.NoColorSpace;
  texture.magFilter = texture.minFilter = THREE.LinearFilter;
  texture.wrapS = texture.wrapT = THREE.ClampToEdgeWrapping;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.needsUpdate = true;
  return texture;
}

// Without a thickness texture the film has the top of its range (as KHR's Maximum).
function fullThickness() {
  const texture = new THREE.DataTexture(new Uint8Array([255, 255, 255, 255]), 1, 1);
  texture.needsUpdate = true;
  return texture;
}

// Make `material` (a MeshPhysicalMaterial) the film: `table` its R texture,
// `transmittance` its T texture or null, the thickness mix(range[0], range[1], G) of
// `thicknessMap` (null: range[1]); with T the material transmits what is behind it times
// T (transmission 1, ior 1, thickness 0, as the film module does).
export function applyThinFilmGLTF(material, table, thicknessMap, thicknessRange,
  transmittance = null) {
  const map = thicknessMap || fullThickness();
  map.updateMatrix();
  const uniforms = {
    thinFilmTable: { value: table },
    thinFilmThickness: { value: thicknessRange[1] },
    thinFilmRange: { value: new THREE.Vector2(...thicknessRange) },
    thinFilmThicknessMap: { value: map },
    thinFilmThicknessRange: { value: new THREE.Vector2(...thicknessRange) },
    thinFilmThicknessMapTransform: { value: map.matrix },
    thinFilmTransmittanceTable: { value: transmittance },
  };
  const defines = { ...material.defines, THIN_FILM_THICKNESS_MAP: "" };
  delete defines.THIN_FILM_TRANSMITTANCE;
  if (transmittance) {
    defines.THIN_FILM_TRANSMITTANCE = "";
    Object.assign(material, { transmission: 1, ior: 1, thickness: 0 });
  }
  material.defines = defines;
  material.iridescence = 0;
  material.onBeforeCompile = (shader) => {
    Object.assign(shader.uniforms, uniforms);
    shader.vertexShader = thinFilmGLTFVertexShader(shader.vertexShader);
    shader.fragmentShader = thinFilmGLTFShader(shader.fragmentShader);
  };
  const key = `ocio-thinfilm-gltf${transmittance ? "-t" : ""}`;
  material.customProgramCacheKey = () => key;
  material.userData.thinFilm = uniforms;
  material.needsUpdate = true;
  return uniforms;
}

export class ThinFilmGLTFPlugin {
  constructor(parser) {
    this.parser = parser;
    this.name = EXTENSION;
  }

  async table(extension, accessor) {
    const values = await this.parser.getDependency("accessor", accessor);
    return thinFilmTableTexture(values.array, extension.width, extension.height);
  }

  async film(materialIndex) {
    const extension = this.parser.json.materials[materialIndex].extensions[EXTENSION];
    const [table, transmittance, map] = await Promise.all([
      this.table(extension, extension.reflectance),
      extension.transmittance === undefined ? null
        : this.table(extension, extension.transmittance),
      extension.thicknessTexture === undefined ? null
        : this.parser.getDependency("texture", extension.thicknessTexture.index),
    ]);
    return { table, transmittance, map, range: extension.thicknessRange };
  }

  async afterRoot(result) {
    const films = new Map();
    const jobs = [];
    for (const scene of result.scenes) {
      scene.traverse((object) => {
        if (!object.isMesh) return;
        for (const material of [].concat(object.material)) {
          const index = this.parser.associations.get(material)?.materials;
          const definition = this.parser.json.materials?.[index];
          if (!definition?.extensions?.[EXTENSION] || !material.isMeshPhysicalMaterial) continue;
          if (!films.has(index)) films.set(index, this.film(index));
          jobs.push(films.get(index).then(({ table, transmittance, map, range }) =>
            applyThinFilmGLTF(material, table, map, range, transmittance)));
        }
      });
    }
    await Promise.all(jobs);
  }
}
"""


def plugin_module(module_name: str = PLUGIN_NAME) -> str:
    """Return the three.js ``GLTFLoader`` plugin (ES module text) for :data:`EXTENSION`.

    It exports ``ThinFilmGLTFPlugin`` (register it with ``GLTFLoader.register``),
    ``applyThinFilmGLTF``, ``thinFilmTableTexture``, ``thinFilmGLTFShader``,
    ``thinFilmGLTFVertexShader`` and ``EXTENSION``; the shader is the three.js film
    module's, its public parts reused as they are (:mod:`ocio_thinfilm.export.hosts.three`:
    R in place of Schlick's Fresnel, T in place of three.js's transmission for a
    free-standing film, the thickness map read through its matrix), the thickness read per
    pixel from the extension's thickness texture.

    Examples
    --------
    >>> "class ThinFilmGLTFPlugin" in plugin_module()
    True
    """
    fields = {
        "__EXTENSION_JSON__": json.dumps(EXTENSION),
        "__DECLARATIONS__": json.dumps(three_host.SHADER_DECLARATIONS),
        "__REPLACEMENTS__": json.dumps(three_host.SHADER_REPLACEMENTS, indent=2),
        "__TRANSMISSION__": json.dumps(three_host.SHADER_TRANSMISSION),
        "__AT_LIGHTS__": json.dumps(three_host.SHADER_AT_LIGHTS),
        "__VERTEX__": json.dumps(three_host.SHADER_VERTEX, indent=2),
        "__EXTENSION__": EXTENSION,
        "__SELF__": module_name,
        "__VERSION__": __version__,
        "__REVISION__": three_host.THREE_REVISION,
    }
    text = _PLUGIN
    for field, value in fields.items():
        text = text.replace(field, value)
    return text
