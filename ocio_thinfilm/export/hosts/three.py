"""The film in three.js: an ES module that turns a ``MeshPhysicalMaterial`` into the film.

:func:`three_module` writes the module's text. It loads the reflectance table (the
film-as-material EXR, loaded from beside the module with three's ``EXRLoader``) as a
linear-filtered, clamp-to-edge texture without mipmaps, and patches a
``MeshPhysicalMaterial``'s shader (``onBeforeCompile``) so that its specular reflectance
is the table's R at the thickness (a uniform, µm) and the angle:

- image-based light: three.js's single- and multiple-scattering terms (Fdez-Agüera 2019,
  ``computeMultiscattering``) take ``F = R(thickness, N·V)`` for the Fresnel term,
  ``F · (f_a + f_b)`` in place of Schlick's ``F0 · f_a + F90 · f_b`` of the DFG table; a
  mirror (roughness 0) under a uniform environment of radiance L shows ``R · L``;
- punctual lights: the GGX microfacet BRDF takes ``F = R(thickness, V·H)``, the
  Fresnel of the microfacet's angle, in place of Schlick's;
- the light the film does not reflect reaches the base colour's diffuse lobe as before
  (three.js's energy conservation, ``1 - F``): a film whose substrate is in its stack
  (anodised titanium, a bubble) wants ``metalness = 1`` or a black ``color``.

Textures are addressed as OpenGL does (v = 0 at the texture's first row) and
``EXRLoader`` puts the file's last scanline first, so the table's y axis is cos θ
ascending. The axes are node-centred (sample ``i`` of ``N`` at fraction ``i / (N - 1)``):
the shader reads fraction ``f`` at ``(f (N - 1) + 0.5) / N`` with ``textureSize``, so normal
and grazing incidence and both ends of the thickness range are table values.
The module checks that three.js's shader chunks still hold the lines it replaces and
throws an Error naming the three.js revision where they do not (written against three.js
r187). Area lights (LTC) and iridescence are left as three.js has them: keep
``iridescence = 0``.
"""

from __future__ import annotations

import json
from os import PathLike

from ocio_thinfilm import __version__
from ocio_thinfilm.export.hosts import table_name, thickness_range

__all__ = ["THREE_REVISION", "three_module"]

#: The three.js release whose shader chunks the module patches (and the tests run).
THREE_REVISION = "187"

#: GLSL declared ahead of three.js's physical lighting: the table, the thickness and
#: R at the shading point's N·V (set in ``main`` before the lights).
_DECLARATIONS = """uniform sampler2D thinFilmTable;
uniform float thinFilmThickness;
uniform vec2 thinFilmRange;
vec3 thinFilmR;
vec3 thinFilmReflectance( const in float cosTheta ) {
	float u = ( thinFilmThickness - thinFilmRange.x ) / ( thinFilmRange.y - thinFilmRange.x );
	vec2 size = vec2( textureSize( thinFilmTable, 0 ) );
	vec2 uv = ( saturate( vec2( u, cosTheta ) ) * ( size - 1.0 ) + 0.5 ) / size;
	return texture( thinFilmTable, uv ).rgb;
}
"""

#: (three.js's line, the film's line) in ``lights_physical_pars_fragment``.
_REPLACEMENTS = [
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

#: Set in ``main`` ahead of ``lights_fragment_begin`` (three.js's view direction).
_AT_LIGHTS = """thinFilmR = thinFilmReflectance( dot( normal, isOrthographic
	? vec3( 0.0, 0.0, 1.0 ) : normalize( vViewPosition ) ) );
#include <lights_fragment_begin>"""

_MODULE = """// Thin film __KEY__ for three.js: a MeshPhysicalMaterial whose specular reflectance is
// the film's exact reflectance R(thickness, angle) read from __TABLE__ (written by
// ocio-thinfilm __VERSION__; tested with three.js r__REVISION__).
//
//   import { loadThinFilm } from "./__SELF__";
//   const film = await loadThinFilm();                     // the table, once
//   const material = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: 0 });
//   const uniforms = film.apply(material, { thickness: __MID__ });  // µm
//   uniforms.thinFilmThickness.value = 0.5;                // later, per frame
//
// Keep __TABLE__ beside this file; import maps must name "three" and "three/addons/".
import * as THREE from "three";
import { EXRLoader } from "three/addons/loaders/EXRLoader.js";

export const FILM = __KEY_JSON__;
// The table's x axis: thickness (µm), first and last column; its y axis: cos(theta),
// node-centred (the first row at 0, the last at 1).
export const THICKNESS_RANGE_UM = [__LO__, __HI__];
export const TABLE_URL = new URL(__TABLE_JSON__, import.meta.url).href;

const DECLARATIONS = __DECLARATIONS__;
const REPLACEMENTS = __REPLACEMENTS__;
const AT_LIGHTS = __AT_LIGHTS__;

function patched(chunk, from, to) {
  if (!chunk.includes(from)) {
    throw new Error(`ocio-thinfilm: three.js r${THREE.REVISION} has no "${from}" in its ` +
      "physical material's shader; this film was written for three.js r__REVISION__");
  }
  return chunk.split(from).join(to);
}

// The film's shader: three.js's physical lighting with the table's R as its Fresnel term.
export function thinFilmShader(fragmentShader) {
  let lights = THREE.ShaderChunk.lights_physical_pars_fragment;
  for (const [from, to] of REPLACEMENTS) lights = patched(lights, from, to);
  let shader = patched(fragmentShader, "#include <lights_physical_pars_fragment>",
    DECLARATIONS + lights);
  return patched(shader, "#include <lights_fragment_begin>", AT_LIGHTS);
}

// Turn `material` (a MeshPhysicalMaterial) into the film; returns its uniforms
// (thinFilmThickness.value: the thickness in µm, clamped to THICKNESS_RANGE_UM).
export function applyThinFilm(material, table, { thickness = __MID__ } = {}) {
  if (!material.isMeshPhysicalMaterial) {
    throw new Error("ocio-thinfilm: applyThinFilm needs a THREE.MeshPhysicalMaterial");
  }
  const uniforms = {
    thinFilmTable: { value: table },
    thinFilmThickness: { value: thickness },
    thinFilmRange: { value: new THREE.Vector2(...THICKNESS_RANGE_UM) },
  };
  material.iridescence = 0;
  material.onBeforeCompile = (shader) => {
    Object.assign(shader.uniforms, uniforms);
    shader.fragmentShader = thinFilmShader(shader.fragmentShader);
  };
  material.customProgramCacheKey = () => "ocio-thinfilm";
  material.userData.thinFilm = uniforms;
  material.needsUpdate = true;
  return uniforms;
}

// The table as a texture: linear filtering, clamp to edge, no mipmaps, rows by cos(theta).
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

// The table, loaded, with `apply(material, options)` bound to it.
export async function loadThinFilm(url = TABLE_URL) {
  const table = await loadThinFilmTable(url);
  return { table, apply: (material, options) => applyThinFilm(material, table, options) };
}
"""


def three_module(
    key: str,
    reflectance_exr: str | PathLike[str],
    range_um: tuple[float, float],
    *,
    module_name: str = "thinfilm.js",
) -> str:
    """Return the ES module (text) that makes a three.js ``MeshPhysicalMaterial`` the film.

    Parameters
    ----------
    key : str
        The film's key (shown in the module and its ``FILM`` export).
    reflectance_exr : str or os.PathLike
        The reflectance table; the module loads its file name from beside itself.
    range_um : tuple of float
        The table's thickness axis ``(lo, hi)`` in µm (the film's ``range_um``).
    module_name : str, optional
        The module's own file name, for the usage lines in its header.

    Returns
    -------
    str
        The module: exports ``loadThinFilm``, ``loadThinFilmTable``, ``applyThinFilm``,
        ``thinFilmShader``, ``FILM``, ``THICKNESS_RANGE_UM`` and ``TABLE_URL``.

    Raises
    ------
    ParameterError
        For a thickness range that is not ``0 <= lo < hi`` or a table that is not an EXR.

    Examples
    --------
    >>> text = three_module("Soap", "ThinFilm_User_Soap_R.exr", (0.0, 1.0))
    >>> "ThinFilm_User_Soap_R.exr" in text and "applyThinFilm" in text
    True
    """
    if not isinstance(key, str) or not key:
        raise TypeError(f"key must be a non-empty string, got {key!r}")
    table = table_name("reflectance_exr", reflectance_exr)
    lo, hi = thickness_range(range_um)
    fields = {
        "__KEY_JSON__": json.dumps(key),
        "__TABLE_JSON__": json.dumps(table),
        "__DECLARATIONS__": json.dumps(_DECLARATIONS),
        "__REPLACEMENTS__": json.dumps(_REPLACEMENTS, indent=2),
        "__AT_LIGHTS__": json.dumps(_AT_LIGHTS),
        "__KEY__": key.replace("\n", " "),
        "__TABLE__": table,
        "__SELF__": module_name,
        "__VERSION__": __version__,
        "__REVISION__": THREE_REVISION,
        "__MID__": repr(round((lo + hi) / 2, 6)),
        "__LO__": repr(lo),
        "__HI__": repr(hi),
    }
    text = _MODULE
    for name, value in fields.items():
        text = text.replace(name, value)
    return text
