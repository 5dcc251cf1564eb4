"""The views' map as code: GLSL and DaVinci Resolve DCTL, exact and with live knobs.

Where a host runs code per pixel, the ``Constant-Lightness Clip`` and
``Constant-Lightness Compress`` views need no LUT: the map is a few lines of arithmetic
(Smits & Meyer 1990, Section 3.2). :func:`shader_source` writes the whole view, from an
input colour space to display code values, as one function (and its inverse): the
input's decoding to CIE-XYZ-D65, an HDR display's scale into its SDR gamut (BT.2100
inverse OOTF for HLG, ITU-R BT.2100-2 Table 5), the map along the ray to the grey of the
same luminance (:mod:`ocio_thinfilm.colour.clip`, :mod:`ocio_thinfilm.colour.compress`;
the ACES 1.3 power curve, S-2020-001), and the display's encoding (IEC 61966-2-1 sRGB,
BT.1886, SMPTE ST 2084, BT.2100 HLG).

- **GLSL** (:data:`LANGUAGES` ``"glsl"``): ``vec3 ocio_thinfilm_view(vec3 rgb)``, GLSL 3.30
  and GLSL ES 3.00, no ``#version`` line; the compression's uniforms
  ``ocio_thinfilm_threshold`` and ``ocio_thinfilm_limit``;
- **DCTL** (``"dctl"``): the transform DCTL entry point, ``Threshold`` and ``Limit``
  sliders and an ``Invert`` check box; only DCTL's documented built-ins.

Every constant (matrices, luminance weights, scales) comes from the same registry and
colorimetry the config is built from. The steps, the edge cases and the host contract
in full: docs/shaders.md, *Design notes*.
"""

from __future__ import annotations

from pathlib import Path

from ocio_thinfilm import __version__, registry
from ocio_thinfilm.checks import ParameterError, as_choice
from ocio_thinfilm.colour import compress
from ocio_thinfilm.export import shader_parts
from ocio_thinfilm.export.shader_language import TOKENS
from ocio_thinfilm.io import StrPath, check_output_file, write_text
from ocio_thinfilm.lut.options import MapOptions, as_options

__all__ = [
    "LANGUAGES",
    "SHADER_MAPS",
    "SHADER_VIEWS",
    "SHADER_SOURCES",
    "KNOB_LIMIT_MAX",
    "THRESHOLD_SLIDER",
    "LIMIT_SLIDER",
    "shader_source",
    "export_shader",
]

#: The languages :func:`shader_source` writes.
LANGUAGES = tuple(TOKENS)
#: View kind (:data:`ocio_thinfilm.registry.VIEW_KINDS`) -> whether its map is the soft
#: compression (``True``) or the clip (``False``); ``None`` for the kinds the shaders do
#: not write (the baselines are LUT-free in the config already, the raw view passes data
#: through).
SHADER_MAPS: dict[str, bool | None] = {
    "clip": False,
    "compress": True,
    "clamp": None,
    "aces": None,
    "raw": None,
}
#: The views it writes.
SHADER_VIEWS = tuple(v.name for v in registry.VIEW_LIST if SHADER_MAPS[v.kind] is not None)
#: The input colour spaces it decodes analytically: the reference, the scene-linear
#: spaces and the encoded ones (the thin-film inputs are spectral tables: use
#: ``export view``).
SHADER_SOURCES = (
    (registry.REFERENCE,)
    + registry.SCENE_LINEAR_SPACES
    + registry.ENCODED_SPACES
    + (registry.TEXTURE_SPACE,)
)
#: The largest limit the shaders accept from a host (a larger uniform gives the defaults).
KNOB_LIMIT_MAX = compress.LIMIT_MAX
#: DCTL slider ranges (min, max, step); widened to hold the exported default.
THRESHOLD_SLIDER = (0.05, 0.99, 0.01)
LIMIT_SLIDER = (1.01, 3.0, 0.01)


def _header(L, lang, source, entry, view, knobs) -> str:
    name = "GLSL" if lang == "glsl" else "DaVinci Resolve DCTL"
    lines = [
        f"// {view}: {source} -> {entry.name} code values, as {name}.",
        f"// Written by ocio-thinfilm {__version__} (ocio-thinfilm export shader): the map of",
        "// the OpenColorIO config's view, computed per pixel instead of from its LUTs.",
        '// Smits & Meyer (1990), "Newton\'s Colors", Section 3.2: colours outside the',
        "// display's RGB parallelepiped move at constant luminance Y towards the grey of",
        "// the same Y.",
    ]
    if knobs is not None:
        t, lim = knobs
        lines += [
            f"// Compression: the ACES 1.3 power curve (power {compress.POWER:g}); colours",
            f"// within threshold (default here {t:g}) of the boundary distance stay, a",
            f"// colour limit (default here {lim:g}) boundary distances out lands on it.",
        ]
    lines += [
        "// Output for every finite input is finite and in [0, 1]; NaN and -Inf components",
        "// count as the lowest value, +Inf as the highest (as the config's view).",
    ]
    if lang == "dctl":
        lines += [
            "// DaVinci Resolve: in the ResolveFX DCTL plugin for the controls; Invert takes",
            "// display code values back to the input space.",
        ]
    if lang == "glsl":
        lines += [
            "// GLSL 3.30 / GLSL ES 3.00 (declare precision highp float); no version directive:",
            "// call vec3 ocio_thinfilm_view(vec3 rgb); vec3 ocio_thinfilm_view_inverse(vec3",
            "// code) takes display code values back to the input space.",
        ]
        if knobs is not None:
            lines += [
                "// Set the uniforms ocio_thinfilm_threshold and ocio_thinfilm_limit; left",
                f"// at 0 or outside 0 < threshold < 1 < limit <= {KNOB_LIMIT_MAX:g} they give "
                "the defaults.",
            ]
    return "\n".join(lines) + "\n"


def shader_source(
    lang: str,
    display: str,
    view: str,
    source: str = registry.REFERENCE,
    *,
    options: MapOptions | None = None,
) -> str:
    """Return the view's map as GLSL or DCTL source code.

    Parameters
    ----------
    lang : str
        ``"glsl"`` or ``"dctl"`` (:data:`LANGUAGES`).
    display : str
        A display of :data:`ocio_thinfilm.registry.ALL_DISPLAYS` (SDR or HDR).
    view : str
        ``"Constant-Lightness Clip"`` or ``"Constant-Lightness Compress"``.
    source : str, optional
        The input colour space (:data:`SHADER_SOURCES`), default ``CIE-XYZ-D65``.
    options : MapOptions, optional
        The knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`; ``None`` for the
        defaults): the compression's threshold and limit are the code's defaults (the
        GLSL's fallback for unset uniforms, the DCTL sliders' defaults), the limit at
        most :data:`KNOB_LIMIT_MAX`. The clip ignores them.

    Returns
    -------
    str
        The source: GLSL defines ``vec3 ocio_thinfilm_view(vec3 rgb)`` and its inverse
        ``vec3 ocio_thinfilm_view_inverse(vec3 code)``, DCTL the ``transform`` entry
        point with an ``Invert`` check box.

    Raises
    ------
    ValueError
        (:class:`~ocio_thinfilm.checks.ParameterError`) naming the parameter.

    Examples
    --------
    >>> text = shader_source("glsl", "sRGB", "Constant-Lightness Compress")
    >>> "uniform float ocio_thinfilm_threshold;" in text, "#version" in text
    (True, False)
    >>> dctl = shader_source("dctl", "Rec.2100-PQ", "Constant-Lightness Clip")
    >>> "DCTLUI_SLIDER_FLOAT" in dctl, "DEFINE_UI_PARAMS(ocio_thinfilm_invert, Invert" in dctl
    (False, True)
    """
    _check_arguments(lang, display, view, source)
    knobs = as_options(options).knobs(limit_max=KNOB_LIMIT_MAX)
    soft = bool(SHADER_MAPS[registry.as_view(view).kind])
    L = TOKENS[lang]
    entry = registry.as_display(display)
    parts = [_header(L, lang, source, entry, view, knobs if soft else None)]
    parts += _declarations(lang, knobs if soft else None)
    parts += [
        shader_parts.helpers_code(L),
        shader_parts.input_code(L, source),
        shader_parts.map_code(L, entry.gamut.name, soft),
        shader_parts.encode_code(L, entry),
        shader_parts.display_code(L, entry, soft),
        shader_parts.decode_code(L, entry),
        shader_parts.unmap_code(L, entry.gamut.name, soft),
        shader_parts.undisplay_code(L, entry, soft),
        shader_parts.output_code(L, source),
    ]
    parts.append(_entry_points(L, lang, knobs if soft else None))
    return "\n".join(p.strip("\n") + "\n" for p in parts)


def _check_arguments(lang, display, view, source):
    """Refuse a language, display, view or input space the shaders do not write."""
    as_choice("lang", lang, LANGUAGES)
    as_choice("display", display, registry.ALL_DISPLAYS)
    as_choice("view", view, SHADER_VIEWS)
    if registry.space_kind(source) == "thin-film":
        raise ParameterError(
            "source",
            f" {source!r} is a spectral table, not a formula: its views are LUTs "
            "(export view); the shaders take one of " + ", ".join(SHADER_SOURCES),
        )
    as_choice("source", source, SHADER_SOURCES)


def _declarations(lang, knobs):
    """Return the knobs' uniforms (GLSL) or sliders (DCTL), and DCTL's Invert box.

    ``knobs``: the compression's (threshold, limit) defaults; ``None`` for the clip.
    """
    parts = []
    if knobs is not None and lang == "glsl":
        parts.append("uniform float ocio_thinfilm_threshold;\nuniform float ocio_thinfilm_limit;\n")
    if knobs is not None and lang == "dctl":
        t, lim = knobs
        t_lo, t_hi, t_step = THRESHOLD_SLIDER
        l_lo, l_hi, l_step = LIMIT_SLIDER
        parts.append(
            "DEFINE_UI_PARAMS(ocio_thinfilm_threshold, Threshold, DCTLUI_SLIDER_FLOAT, "
            f"{t:g}, {min(t_lo, t):g}, {max(t_hi, t):g}, {t_step:g})\n"
            "DEFINE_UI_PARAMS(ocio_thinfilm_limit, Limit, DCTLUI_SLIDER_FLOAT, "
            f"{lim:g}, {min(l_lo, lim):g}, {max(l_hi, lim):g}, {l_step:g})\n"
        )
    if lang == "dctl":
        parts.append("DEFINE_UI_PARAMS(ocio_thinfilm_invert, Invert, DCTLUI_CHECK_BOX, 0)\n")
    return parts


def _knob_lines(L, knobs):
    """Return the entry points' lines reading the knobs, and the extra call arguments.

    A host's value outside the allowed range gives the defaults; none for the clip.
    """
    if knobs is None:
        return [], ""
    t, lim = knobs
    check = (
        f"if (!(t > {L.lit(0.0)} && t < {L.lit(1.0)} && l > {L.lit(1.0)} && "
        f"l <= {L.lit(KNOB_LIMIT_MAX)})) {{ t = {L.lit(t)}; l = {L.lit(lim)}; }}"
    )
    lines = [
        "    float t = ocio_thinfilm_threshold;",
        "    float l = ocio_thinfilm_limit;",
        f"    {check}",
    ]
    return lines, ", t, l"


def _entry_points(L, lang, knobs):
    """Return the entry points: GLSL's view and its inverse, or DCTL's ``transform``."""
    knob_lines, args = _knob_lines(L, knobs)
    unmapped = "ocio_thinfilm_undisplay({}{})"
    if lang == "glsl":
        entry_lines = [
            "vec3 ocio_thinfilm_view(vec3 rgb)",
            "{",
            *knob_lines,
            "    vec3 xyz = ocio_thinfilm_input(rgb.x, rgb.y, rgb.z);",
            f"    return ocio_thinfilm_display(xyz.x, xyz.y, xyz.z{args});",
            "}",
            "",
            "// The view's inverse: display code values -> the input space (for colours",
            "// of the display's volume; codes are limited to [0, 1]).",
            "vec3 ocio_thinfilm_view_inverse(vec3 code)",
            "{",
            *knob_lines,
            f"    vec3 xyz = {unmapped.format('code.x, code.y, code.z', args)};",
            "    return ocio_thinfilm_output(xyz.x, xyz.y, xyz.z);",
            "}",
            "",
        ]
    else:
        entry_lines = [
            "__DEVICE__ float3 transform(int p_Width, int p_Height, int p_X, int p_Y, "
            "float p_R, float p_G, float p_B)",
            "{",
            *knob_lines,
            "    if (ocio_thinfilm_invert) {",
            "        // the view's inverse: display code values -> the input space",
            f"        float3 back = {unmapped.format('p_R, p_G, p_B', args)};",
            "        return ocio_thinfilm_output(back.x, back.y, back.z);",
            "    }",
            "    float3 xyz = ocio_thinfilm_input(p_R, p_G, p_B);",
            f"    return ocio_thinfilm_display(xyz.x, xyz.y, xyz.z{args});",
            "}",
            "",
        ]
    return "\n".join(entry_lines)


def export_shader(
    path: StrPath,
    lang: str,
    display: str,
    view: str,
    source: str = registry.REFERENCE,
    *,
    options: MapOptions | None = None,
) -> Path:
    """Write :func:`shader_source` to ``path`` (written aside, checked, then renamed).

    Parameters
    ----------
    path : str or os.PathLike
        The file to write (``.glsl``, ``.dctl`` or any name); the file named is
        replaced atomically, a directory in its place is refused.
    lang, display, view, source, options
        As :func:`shader_source`.

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        For a bad argument (naming it) or an output path that cannot be written.
    """
    text = shader_source(lang, display, view, source, options=options)
    return write_text(check_output_file(path, "path"), text)
