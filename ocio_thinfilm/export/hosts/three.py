"""The film in three.js: an ES module that turns a ``MeshPhysicalMaterial`` into the film.

:func:`three_module` writes the module's text. It loads the reflectance table (the
film-as-material EXR, beside the module, with three's ``EXRLoader``) as a linear-filtered,
clamp-to-edge texture without mipmaps, and patches a ``MeshPhysicalMaterial``'s shader
(``onBeforeCompile``) so that its Fresnel term is the table's R at the thickness and the
angle: in the image-based light (Fdez-Agüera 2019, ``computeMultiscattering``) and in
the GGX microfacet BRDF of punctual lights. The thickness is a uniform
(``thinFilmThickness``, µm) or a thickness map (glTF ``KHR_materials_iridescence``'s
convention); a free-standing film's transmittance goes through three.js's transmission
pass. The module checks that three.js's shader chunks still hold the lines it replaces
(written against three.js r187). What it changes, line by line: docs/threejs.md, *What
it changes in three.js*; the table's addressing: its *Design notes*.
"""

from __future__ import annotations

import json
import math
from os import PathLike

from ocio_thinfilm import __version__
from ocio_thinfilm.checks import ParameterError, as_pair
from ocio_thinfilm.export.hosts import table_name, thickness_range

__all__ = [
    "THREE_REVISION",
    "SHADER_DECLARATIONS",
    "SHADER_REPLACEMENTS",
    "SHADER_AT_LIGHTS",
    "SHADER_TRANSMISSION",
    "SHADER_VERTEX",
    "three_module",
]

#: The three.js release whose shader chunks the module patches (and the tests run).
THREE_REVISION = "187"

#: GLSL declared ahead of three.js's physical lighting: the tables, the thickness (a
#: uniform, or a thickness map's G channel mapped to a range), and R (and T) at the shading
#: point's N·V (set in ``main`` before the lights).
SHADER_DECLARATIONS = """uniform sampler2D thinFilmTable;
uniform float thinFilmThickness;
uniform vec2 thinFilmRange;
#ifdef THIN_FILM_THICKNESS_MAP
uniform sampler2D thinFilmThicknessMap;
uniform vec2 thinFilmThicknessRange;
varying vec2 vThinFilmUv;
#endif
float thinFilmD;
vec3 thinFilmR;
vec2 thinFilmTableUv( const in sampler2D table, const in float cosTheta ) {
	float u = ( thinFilmD - thinFilmRange.x ) / ( thinFilmRange.y - thinFilmRange.x );
	vec2 size = vec2( textureSize( table, 0 ) );
	return ( saturate( vec2( u, cosTheta ) ) * ( size - 1.0 ) + 0.5 ) / size;
}
vec3 thinFilmReflectance( const in float cosTheta ) {
	return texture( thinFilmTable, thinFilmTableUv( thinFilmTable, cosTheta ) ).rgb;
}
#ifdef THIN_FILM_TRANSMITTANCE
uniform sampler2D thinFilmTransmittanceTable;
vec3 thinFilmT;
#define THIN_FILM_TRANSMITTED( F, attenuated, light ) ( thinFilmT * ( light ) )
#else
#define THIN_FILM_TRANSMITTED( F, attenuated, light ) ( ( 1.0 - ( F ) ) * ( attenuated ) )
#endif
"""

#: (three.js's line, the film's line) in ``lights_physical_pars_fragment``.
SHADER_REPLACEMENTS = [
    (
        "vec3 F = F_Schlick( f0, f90, dotVH );",
        "vec3 F = thinFilmReflectance( dotVH );",
    ),
    (
        "vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );",
        "vec3 F = thinFilmReflectance( dotVH );",
    ),
    ("vec3 Fr = specularColor;", "vec3 Fr = thinFilmR;"),
    (
        "vec3 FssEss = Fr * fab.x + specularF90 * fab.y;",
        "vec3 FssEss = Fr * ( fab.x + fab.y );",
    ),
]

#: (three.js's line, the film's line) in ``transmission_pars_fragment``: with a
#: transmittance table, what three.js's transmission pass saw behind the film, times T.
SHADER_TRANSMISSION = (
    "return vec4( ( 1.0 - F ) * attenuatedColor,",
    "return vec4( THIN_FILM_TRANSMITTED( F, attenuatedColor, transmittedLight.rgb ),",
)

#: Set in ``main`` ahead of ``lights_fragment_begin`` (three.js's view direction).
SHADER_AT_LIGHTS = """#ifdef THIN_FILM_THICKNESS_MAP
thinFilmD = mix( thinFilmThicknessRange.x, thinFilmThicknessRange.y,
	texture( thinFilmThicknessMap, vThinFilmUv ).g );
#else
thinFilmD = thinFilmThickness;
#endif
float thinFilmCosTheta = dot( normal, isOrthographic
	? vec3( 0.0, 0.0, 1.0 ) : normalize( vViewPosition ) );
thinFilmR = thinFilmReflectance( thinFilmCosTheta );
#ifdef THIN_FILM_TRANSMITTANCE
thinFilmT = texture( thinFilmTransmittanceTable,
	thinFilmTableUv( thinFilmTransmittanceTable, thinFilmCosTheta ) ).rgb;
#endif
#include <lights_fragment_begin>"""

#: The vertex shader's share: the thickness map's uv (the mesh's ``uv``, through the
#: map's ``matrix``: offset, repeat, rotation), as three.js passes its own maps' uvs.
SHADER_VERTEX = (
    (
        "#include <uv_pars_vertex>",
        """#include <uv_pars_vertex>
#ifdef THIN_FILM_THICKNESS_MAP
uniform mat3 thinFilmThicknessMapTransform;
varying vec2 vThinFilmUv;
#endif""",
    ),
    (
        "#include <uv_vertex>",
        """#include <uv_vertex>
#ifdef THIN_FILM_THICKNESS_MAP
vThinFilmUv = ( thinFilmThicknessMapTransform * vec3( uv, 1 ) ).xy;
#endif""",
    ),
)

_MODULE = """// Thin film __KEY__ for three.js: a MeshPhysicalMaterial whose specular reflectance is
// the film's exact reflectance R(thickness, angle) read from __TABLE__ (and, for a
// free-standing film, whose transmission is its transmittance T, from __TTABLE__)
// (written by ocio-thinfilm __VERSION__; tested with three.js r__REVISION__).
//
//   import { loadThinFilm } from "./__SELF__";
//   const film = await loadThinFilm();                     // the table(s), once
//   const material = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: 0 });
//   const uniforms = film.apply(material, { thickness: __MID__ });  // µm
//   uniforms.thinFilmThickness.value = 0.5;                // later, per frame
//   // or a thickness map (its G channel from thicknessRange[0] to [1], µm):
//   film.apply(material, { thicknessMap: texture, thicknessRange: [__LO__, __HI__] });
//
// Keep the tables beside this file; import maps must name "three" and "three/addons/".
import * as THREE from "three";
import { EXRLoader } from "three/addons/loaders/EXRLoader.js";

// The film's name (as in its tables' ImageDescription) and its key in the film file.
export const FILM = __NAME_JSON__;
export const FILM_KEY = __KEY_JSON__;
// The table's x axis: thickness (µm), first and last column; its y axis: cos(theta),
// node-centred (the first row at 0, the last at 1).
export const THICKNESS_RANGE_UM = [__LO__, __HI__];
// A thickness map's default range (µm): G = 0 and G = 1.
export const THICKNESS_MAP_RANGE_UM = [__MAP_LO__, __MAP_HI__];
export const TABLE_URL = new URL(__TABLE_JSON__, import.meta.url).href;
// The transmittance table (a free-standing film), or null: no transmission.
export const TRANSMITTANCE_URL = __TTABLE_URL__;

const DECLARATIONS = __DECLARATIONS__;
const REPLACEMENTS = __REPLACEMENTS__;
const TRANSMISSION = __TRANSMISSION__;
const AT_LIGHTS = __AT_LIGHTS__;
const VERTEX = __VERTEX__;

function patched(chunk, from, to) {
  if (!chunk.includes(from)) {
    throw new Error(`ocio-thinfilm: three.js r${THREE.REVISION} has no "${from}" in its ` +
      "physical material's shader; this film was written for three.js r__REVISION__");
  }
  return chunk.split(from).join(to);
}

// The film's fragment shader: three.js's physical lighting with the table's R as its
// Fresnel term and (with THIN_FILM_TRANSMITTANCE defined) T as its transmission.
export function thinFilmShader(fragmentShader) {
  let lights = THREE.ShaderChunk.lights_physical_pars_fragment;
  for (const [from, to] of REPLACEMENTS) lights = patched(lights, from, to);
  let shader = patched(fragmentShader, "#include <lights_physical_pars_fragment>",
    DECLARATIONS + lights);
  shader = patched(shader, "#include <transmission_pars_fragment>",
    patched(THREE.ShaderChunk.transmission_pars_fragment, ...TRANSMISSION));
  return patched(shader, "#include <lights_fragment_begin>", AT_LIGHTS);
}

// The film's vertex shader: the thickness map's uv.
export function thinFilmVertexShader(vertexShader) {
  let shader = vertexShader;
  for (const [from, to] of VERTEX) shader = patched(shader, from, to);
  return shader;
}

function checkedRange(thicknessRange) {
  const [lo, hi] = THICKNESS_RANGE_UM;
  const ok = Array.isArray(thicknessRange) && thicknessRange.length === 2 &&
    thicknessRange.every((t) => Number.isFinite(t) && t >= lo && t <= hi);
  if (!ok) {
    throw new Error(`ocio-thinfilm: thicknessRange must be two thicknesses within the ` +
      `table's [${lo}, ${hi}] µm, got ${JSON.stringify(thicknessRange)}`);
  }
  return thicknessRange;
}

// Turn `material` (a MeshPhysicalMaterial) into the film; returns its uniforms.
// thickness: µm (thinFilmThickness.value; clamped to THICKNESS_RANGE_UM), or
// thicknessMap: a texture whose G channel (with the mesh's uv and the map's matrix) maps
// to mix(thicknessRange[0], thicknessRange[1], G) µm, as glTF's KHR_materials_iridescence
// reads iridescenceThicknessTexture; transmittance: the T table (loadThinFilmTable):
// the material transmits what is behind it times T (three.js's transmission with
// transmission = 1, ior = 1, thickness = 0).
export function applyThinFilm(material, table, { thickness = __MID__, thicknessMap = null,
  thicknessRange = THICKNESS_MAP_RANGE_UM, transmittance = null } = {}) {
  if (!material.isMeshPhysicalMaterial) {
    throw new Error("ocio-thinfilm: applyThinFilm needs a THREE.MeshPhysicalMaterial");
  }
  if (thicknessMap !== null && !thicknessMap.isTexture) {
    throw new Error("ocio-thinfilm: thicknessMap must be a THREE.Texture or null");
  }
  if (transmittance !== null && !transmittance.isTexture) {
    throw new Error("ocio-thinfilm: transmittance must be a THREE.Texture (the T table) or null");
  }
  const range = checkedRange(thicknessRange);
  if (thicknessMap) thicknessMap.updateMatrix();
  const uniforms = {
    thinFilmTable: { value: table },
    thinFilmThickness: { value: thickness },
    thinFilmRange: { value: new THREE.Vector2(...THICKNESS_RANGE_UM) },
    thinFilmThicknessMap: { value: thicknessMap },
    thinFilmThicknessRange: { value: new THREE.Vector2(...range) },
    thinFilmThicknessMapTransform: {
      value: thicknessMap ? thicknessMap.matrix : new THREE.Matrix3() },
    thinFilmTransmittanceTable: { value: transmittance },
  };
  const defines = { ...material.defines };
  delete defines.THIN_FILM_THICKNESS_MAP;
  delete defines.THIN_FILM_TRANSMITTANCE;
  if (thicknessMap) defines.THIN_FILM_THICKNESS_MAP = "";
  if (transmittance) {
    defines.THIN_FILM_TRANSMITTANCE = "";
    Object.assign(material, { transmission: 1, ior: 1, thickness: 0 });
  }
  material.defines = defines;
  material.iridescence = 0;
  material.onBeforeCompile = (shader) => {
    Object.assign(shader.uniforms, uniforms);
    shader.vertexShader = thinFilmVertexShader(shader.vertexShader);
    shader.fragmentShader = thinFilmShader(shader.fragmentShader);
  };
  const key = `ocio-thinfilm${thicknessMap ? "-map" : ""}${transmittance ? "-t" : ""}`;
  material.customProgramCacheKey = () => key;
  material.userData.thinFilm = uniforms;
  material.needsUpdate = true;
  return uniforms;
}

// A table as a texture: linear filtering, clamp to edge, no mipmaps, rows by cos(theta).
export async function loadThinFilmTable(url = TABLE_URL, type = THREE.HalfFloatType) {
  const texture = await new EXRLoader().setDataType(type).loadAsync(url);
  texture.colorSpace = THREE.NoColorSpace;
  texture.magFilter = texture.minFilter = THREE.LinearFilter;
  texture.wrapS = texture.wrapT = THREE.ClampToEdgeWrapping;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.needsUpdate = true;
  return texture;
}

// The tables, loaded, with `apply(material, options)` bound to them (options as
// applyThinFilm's; a free-standing film transmits unless `transmittance: null`).
export async function loadThinFilm(url = TABLE_URL, transmittanceUrl = TRANSMITTANCE_URL) {
  const [table, transmittance] = await Promise.all([loadThinFilmTable(url),
    transmittanceUrl ? loadThinFilmTable(transmittanceUrl) : null]);
  return { table, transmittance,
    apply: (material, options) => applyThinFilm(material, table, { transmittance, ...options }) };
}
"""


def three_module(
    key: str,
    reflectance_exr: str | PathLike[str],
    range_um: tuple[float, float],
    *,
    transmittance_exr: str | PathLike[str] | None = None,
    name: str | None = None,
    thickness_map_range_um: tuple[float, float] | None = None,
    module_name: str = "thinfilm.js",
) -> str:
    """Return the ES module (text) that makes a three.js ``MeshPhysicalMaterial`` the film.

    Parameters
    ----------
    key : str
        The film's key in its film file (the module's ``FILM_KEY`` export).
    reflectance_exr : str or os.PathLike
        The reflectance table; the module loads its file name from beside itself.
    range_um : tuple of float
        The table's thickness axis ``(lo, hi)`` in µm (the film's ``range_um``).
    transmittance_exr : str or os.PathLike, optional
        The transmittance table of a free-standing film: the module loads it too and the
        material transmits what is behind it times T. None: no transmission.
    name : str, optional
        The film's name (``TableFiles.name``, as in the tables' ImageDescription): the
        module's ``FILM`` export. Default ``key``.
    thickness_map_range_um : tuple of float, optional
        A thickness map's default ``thicknessRange`` (µm at G = 0 and G = 1), within
        ``range_um``. Default ``range_um``.
    module_name : str, optional
        The module's own file name, for the usage lines in its header.

    Returns
    -------
    str
        The module: exports ``loadThinFilm``, ``loadThinFilmTable``, ``applyThinFilm``,
        ``thinFilmShader``, ``thinFilmVertexShader``, ``FILM``, ``FILM_KEY``,
        ``THICKNESS_RANGE_UM``, ``THICKNESS_MAP_RANGE_UM``, ``TABLE_URL`` and
        ``TRANSMITTANCE_URL``.

    Raises
    ------
    ParameterError
        For a thickness range that is not ``0 <= lo < hi``, a table that is not an EXR or
        a thickness map range outside ``range_um``.

    Examples
    --------
    >>> text = three_module("Soap", "ThinFilm_User_Soap_R.exr", (0.0, 1.0))
    >>> "ThinFilm_User_Soap_R.exr" in text and "applyThinFilm" in text
    True
    """
    if not isinstance(key, str) or not key:
        raise TypeError(f"key must be a non-empty string, got {key!r}")
    name = key if name is None else name
    if not isinstance(name, str) or not name:
        raise TypeError(f"name must be a non-empty string, got {name!r}")
    table = table_name("reflectance_exr", reflectance_exr)
    t_table = None
    if transmittance_exr is not None:
        t_table = table_name("transmittance_exr", transmittance_exr)
    lo, hi = thickness_range(range_um)
    map_lo, map_hi = _map_range(thickness_map_range_um, (lo, hi))
    fields = {
        "__KEY_JSON__": json.dumps(key),
        "__NAME_JSON__": json.dumps(name),
        "__TABLE_JSON__": json.dumps(table),
        "__TTABLE_URL__": "null"
        if t_table is None
        else f"new URL({json.dumps(t_table)}, import.meta.url).href",
        "__DECLARATIONS__": json.dumps(SHADER_DECLARATIONS),
        "__REPLACEMENTS__": json.dumps(SHADER_REPLACEMENTS, indent=2),
        "__TRANSMISSION__": json.dumps(SHADER_TRANSMISSION),
        "__AT_LIGHTS__": json.dumps(SHADER_AT_LIGHTS),
        "__VERTEX__": json.dumps(SHADER_VERTEX, indent=2),
        "__KEY__": name.replace("\n", " "),
        "__TTABLE__": "none" if t_table is None else t_table,
        "__TABLE__": table,
        "__SELF__": module_name,
        "__VERSION__": __version__,
        "__REVISION__": THREE_REVISION,
        "__MID__": repr(round((lo + hi) / 2, 6)),
        "__MAP_LO__": repr(map_lo),
        "__MAP_HI__": repr(map_hi),
        "__LO__": repr(lo),
        "__HI__": repr(hi),
    }
    text = _MODULE
    for field, value in fields.items():
        text = text.replace(field, value)
    return text


def _map_range(
    thickness_map_range_um: object, table_range: tuple[float, float]
) -> tuple[float, float]:
    """Return the thickness map's range, checked against the table's (default: the table's)."""
    if thickness_map_range_um is None:
        return table_range
    lo, hi = as_pair("thickness_map_range_um", thickness_map_range_um)
    t_lo, t_hi = table_range
    if not all(math.isfinite(t) and t_lo <= t <= t_hi for t in (lo, hi)):
        raise ParameterError(
            "thickness_map_range_um",
            f" must lie within the table's range_um [{t_lo:g}, {t_hi:g}] um, got ({lo:g}, {hi:g})",
        )
    return lo, hi
