"""The parts of the shaders' code, each a function of the language (:mod:`.shader_language`).

Each part is one GLSL or DCTL function of :func:`ocio_thinfilm.export.shader.shader_source`:
the helpers (OCIO's Range, the normalised distance), the input space's decoding to
CIE-XYZ-D65 and its inverse (by the encoded space's log curve,
its kind and numbers, or the texture space's sRGB curve),
the map of the view's kind (the clip or the compression) and its inverse, and the
display's encoding and decoding (sRGB piecewise, BT.1886, SMPTE ST 2084, BT.2100 HLG)
with the HDR scale.
"""

from __future__ import annotations

import math

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.colour import clip, colorimetry, compress, encodings
from ocio_thinfilm.export.shader_language import GLSL, Language, matrix_rows
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.view_transforms import HLG_GAMMA

__all__ = [
    "helpers_code",
    "input_code",
    "map_code",
    "encode_code",
    "display_code",
    "decode_code",
    "unmap_code",
    "undisplay_code",
    "output_code",
]

#: The config's sRGB-encoded texture space (:data:`ocio_thinfilm.registry.TEXTURE_SPACE`):
#: its primaries and the display whose encoding it has (its colour space decodes with the
#: display's curve, then the matrix).
_TEXTURE_PRIMARIES, _TEXTURE_DISPLAY = "Rec.709", "sRGB"


def _pq() -> dict[str, float]:
    """SMPTE ST 2084's constants m_1, m_2, c_1, c_2, c_3 in that order, colour-science's."""
    from colour.models.rgb.transfer_functions.st_2084 import CONSTANTS_ST2084

    return {k: float(v) for k, v in CONSTANTS_ST2084.items()}


def _hlg() -> dict[str, float]:
    """ITU-R BT.2100 HLG OETF's constants a, b, c in that order, colour-science's."""
    from colour.models.rgb.transfer_functions.arib_std_b67 import CONSTANTS_ARIBSTDB67

    return {k: float(v) for k, v in CONSTANTS_ARIBSTDB67.items()}


def helpers_code(L: Language) -> str:
    """Return the helper functions: OCIO's Range, the finite limit, the distance."""
    lim = L.lit(ocio_ops.LIMIT)
    text = f"""
// Components limited to [lo, hi]; NaN and -Inf give lo, +Inf gives hi (OCIO's Range).
{L.qualifier}float ocio_thinfilm_range(float x, float lo, float hi)
{{
    return x > lo ? (x < hi ? x : hi) : lo;
}}

{L.qualifier}float ocio_thinfilm_finite(float x)
{{
    return ocio_thinfilm_range(x, -{lim}, {lim});
}}
"""
    one = L.lit(1.0)
    text += f"""
// A channel's normalised distance along the ray from the grey Y (0 < Y < 1): the
// fraction of the way to the face through black (below Y) or through white (above).
{L.qualifier}float ocio_thinfilm_distance(float c, float Y)
{{
    return c < Y ? (Y - c) / Y : (c - Y) / ({one} - Y);
}}
"""
    if L is GLSL:
        text += """
float ocio_thinfilm_saturate(float x)
{
    return clamp(x, 0.0, 1.0);
}
"""
    return text


def _piecewise_encode(L: Language, encoding: registry.Encoding, v: str) -> str:
    """Return the sRGB-style curve's encoding of the expression ``v`` (linear below 0)."""
    brk, slope = encodings.piecewise(encoding)
    gamma, offset = encoding.gamma, float(encoding.offset or 0.0)
    return (
        f"{v} <= {L.lit(brk)} ? {L.lit(slope)} * {v} : "
        f"{L.lit(1 + offset)} * {L.pow}({v}, {L.lit(1 / gamma)}) - {L.lit(offset)}"
    )


def _piecewise_decode(L: Language, encoding: registry.Encoding, v: str) -> str:
    """Return the sRGB-style curve's decoding of the expression ``v`` (linear below 0)."""
    brk, slope = encodings.piecewise(encoding)
    gamma, offset = encoding.gamma, float(encoding.offset or 0.0)
    return (
        f"{v} <= {L.lit(slope * brk)} ? {v} / {L.lit(slope)} : "
        f"{L.pow}(({v} + {L.lit(offset)}) / {L.lit(1 + offset)}, {L.lit(gamma)})"
    )


def _unlog(L: Language, c: registry.LogCurve, v: str) -> str:
    """Return the log part's inverse of the expression ``v``.

    ``(2 ** (v * S - O) - lin_offset) / lin_slope`` (S, O: the log side's scale and
    offset in base 2).
    """
    scale = math.log2(c.base) / c.log_slope
    power = f"{L.exp2}({v} * {L.lit(scale)} - {L.lit(c.log_offset * scale)})"
    if c.lin_offset:
        power = f"({power} - {L.lit(c.lin_offset)})"
    if c.lin_slope != 1.0:
        power = f"{power} / {L.lit(c.lin_slope)}"
    return power


def _relog(L: Language, c: registry.LogCurve, v: str) -> str:
    """Return the log part of the expression ``v`` (the inverse of :func:`_unlog`)."""
    scale = math.log2(c.base) / c.log_slope
    inner = v
    if c.lin_slope != 1.0:
        inner = f"{L.lit(c.lin_slope)} * {inner}"
    if c.lin_offset:
        inner = f"{inner} + {L.lit(c.lin_offset)}"
    return f"({L.log2}({inner}) + {L.lit(c.log_offset * scale)}) / {L.lit(scale)}"


def _log_decoding(L: Language, c: registry.LogCurve) -> list[str]:
    """Return the lines decoding ``r``, ``g``, ``b`` from the log curve ``c``.

    Codes limited to those of linear +-1e6, then by the curve's kind
    (:data:`ocio_thinfilm.registry.CURVE_KINDS`): the toe (a line, or the quadratic's
    root) up to the toe's code at the break, the log part above it, and for a mirrored
    curve the negated log part of ``2 black - code`` below the mirrored break.
    """
    lo, hi = c.encode_one(-ocio_ops.LIMIT), c.encode_one(ocio_ops.LIMIT)
    if c.kind == "quadratic-toe":
        root = f"{L.sqrt}({L.max}({{ch}}, {L.lit(0.0)}) / {L.lit(c.toe_slope)})"
        toe = f"{L.lit(c.toe_origin)} + {root}"
    else:
        toe = f"({{ch}} - {L.lit(c.toe_intercept)}) / {L.lit(c.toe_slope)}"
    lines = [f"    // {c.name} codes -> linear"]
    for ch in "rgb":
        value = f"{ch} <= {L.lit(c.toe_break)} ? {toe.format(ch=ch)} : {_unlog(L, c, ch)}"
        if c.kind == "mirrored-log":
            mirror = f"({L.lit(2.0 * c.black)} - {ch})"
            lower = L.lit(2.0 * c.black - c.toe_break)
            value = f"{ch} < {lower} ? -({_unlog(L, c, mirror)}) : ({value})"
        lines.append(
            f"    {ch} = ocio_thinfilm_range({ch}, {L.lit(lo)}, {L.lit(hi)});  {ch} = {value};"
        )
    return lines


def _log_encoding(L: Language, c: registry.LogCurve) -> list[str]:
    """Return the lines encoding ``r``, ``g``, ``b`` with the log curve ``c``.

    The inverse of :func:`_log_decoding`.
    """
    lines = [f"    // linear -> {c.name} codes"]
    for ch in "rgb":
        if c.kind == "quadratic-toe":
            d = f"({ch} - {L.lit(c.toe_origin)})"
            square = f"{L.lit(c.toe_slope)} * {d} * {d}"
            toe = f"({ch} > {L.lit(c.toe_origin)} ? {square} : {L.lit(0.0)})"
        else:
            toe = f"{L.lit(c.toe_slope)} * {ch} + {L.lit(c.toe_intercept)}"
        value = f"{ch} <= {L.lit(c.lin_break)} ? {toe} : {_relog(L, c, ch)}"
        if c.kind == "mirrored-log":
            mirror = f"{L.lit(2.0 * c.black)} - {_relog(L, c, f'(-{ch})')}"
            value = f"{ch} < {L.lit(-c.lin_break)} ? {mirror} : ({value})"
        lines.append(f"    {ch} = {value};")
    return lines


def input_code(L: Language, source: str) -> str:
    """Input colour space -> CIE-XYZ-D65, limited as the config's colour space and view."""
    lines = [f"{L.qualifier}{L.vec3} ocio_thinfilm_input(float r, float g, float b)", "{"]
    kind = registry.space_kind(source)
    if kind == "reference":
        lines.append(
            f"    return {L.make3}(ocio_thinfilm_finite(r), ocio_thinfilm_finite(g), "
            "ocio_thinfilm_finite(b));"
        )
        return "\n".join(lines + ["}", ""])
    if kind == "texture":
        encoding = registry.as_display(_TEXTURE_DISPLAY, hdr=False).encoding
        for ch in "rgb":
            lines.append(f"    {ch} = {_piecewise_decode(L, encoding, ch)};")
        colorimetry_name = _TEXTURE_PRIMARIES
    else:
        space = registry.linear_space_of(source)
        assert space is not None  # shader_source checked the source
        colorimetry_name = space.colorimetry
    encoded = registry.find_encoded(source)
    if encoded is not None:
        lines += _log_decoding(L, encoded.curve)
    for ch in "rgb":
        lines.append(f"    {ch} = ocio_thinfilm_finite({ch});")
    M = reproducible.inv3(colorimetry.matrix_XYZ_to_RGB(colorimetry_name))
    X, Y, Z = matrix_rows(L, M, ("r", "g", "b"))
    lines += [
        f"    float X = ocio_thinfilm_finite({X});",
        f"    float Y = ocio_thinfilm_finite({Y});",
        f"    float Z = ocio_thinfilm_finite({Z});",
        f"    return {L.make3}(X, Y, Z);",
        "}",
        "",
    ]
    return "\n".join(lines)


def map_code(L: Language, gamut: str, soft: bool) -> str:
    """Display-linear RGB of ``gamut`` -> the map (Smits & Meyer 1990, Section 3.2)."""
    w = ", ".join(f"{v:.6f}" for v in clip.luminance_weights(gamut))
    one, zero = L.lit(1.0), L.lit(0.0)
    text = ""
    if soft:
        p = compress.POWER
        text += f"""
// The compressed distance over the distance, threshold < d < limit: the ACES 1.3 power
// curve (S-2020-001, power {p:g}) through (threshold, threshold) with slope 1, reaching
// the boundary (1) at the limit.
{L.qualifier}float ocio_thinfilm_curve_s(float t, float l)
{{
    // the curve's scale: its asymptote is t + s, it reaches 1 at l
    return (l - t) / {L.pow}({L.pow}((l - t) / ({one} - t), {L.lit(p)}) - {one}, {L.lit(1 / p)});
}}

{L.qualifier}float ocio_thinfilm_scale(float d, float t, float l)
{{
    float s = ocio_thinfilm_curve_s(t, l);
    float x = d - t;
    return (t + x / {L.pow}({one} + {L.pow}(x / s, {L.lit(p)}), {L.lit(1 / p)})) / d;
}}
"""
    scale = "d >= l ? {one} / d : ocio_thinfilm_scale(d, t, l)" if soft else "{one} / d"
    knobs = ", float t, float l" if soft else ""
    inside = "t" if soft else one
    on_face = "l" if soft else one
    text += f"""
// Display-linear RGB -> the map: towards the grey of the same luminance Y (R = G = B =
// Y), by the scale k of the normalised distance d to the gamut's faces.
// Y is the colour's luminance (the weights of R, G, B: {w}), the input's CIE Y:
// taken from XYZ, no float32 cancellation between large channels moves it.
{L.qualifier}{L.vec3} ocio_thinfilm_map(float r, float g, float b, float Y{knobs})
{{
    if (!(Y > {zero})) return {L.make3}({zero}, {zero}, {zero});
    if (Y >= {one}) return {L.make3}({one}, {one}, {one});
    float dr = ocio_thinfilm_distance(r, Y);
    float dg = ocio_thinfilm_distance(g, Y);
    float db = ocio_thinfilm_distance(b, Y);
    float d = {L.max}(dr, {L.max}(dg, db));
    if (d <= {inside}) return {L.make3}(r, g, b);
    float k = {scale.format(one=one)};
    float mr = Y + k * (r - Y);
    float mg = Y + k * (g - Y);
    float mb = Y + k * (b - Y);
    if (d >= {on_face}) {{
        // on the boundary: the channels that meet a face are on it exactly
        if (dr == d) mr = r < Y ? {zero} : {one};
        if (dg == d) mg = g < Y ? {zero} : {one};
        if (db == d) mb = b < Y ? {zero} : {one};
    }}
    return {L.make3}({L.saturate}(mr), {L.saturate}(mg), {L.saturate}(mb));
}}
"""
    return text


def encode_code(L: Language, entry: registry.AnyDisplay) -> str:
    """Display-linear -> code value of one channel (``v`` in [0, 1], or [0, k] for PQ)."""
    one, zero = L.lit(1.0), L.lit(0.0)
    m1, m2, c1, c2, c3 = _pq().values()
    ha, hb, hc = _hlg().values()
    head = f"{L.qualifier}float ocio_thinfilm_encode(float v)\n{{\n"
    if isinstance(entry, registry.HDRDisplay) and entry.transfer == "PQ":
        scale = registry.HDR_REFERENCE_WHITE / 10000.0
        body = (
            f"    // SMPTE ST 2084; v = 1 is the reference white, {registry.HDR_REFERENCE_WHITE:g}"
            " cd/m2\n"
            f"    float p = v > {zero} ? {L.pow}(v * {L.lit(scale)}, {L.lit(m1)}) : {zero};\n"
            f"    return {L.pow}(({L.lit(c1)} + {L.lit(c2)} * p) / ({one} + "
            f"{L.lit(c3)} * p), {L.lit(m2)});\n"
        )
    elif isinstance(entry, registry.HDRDisplay):
        body = (
            "    // ITU-R BT.2100 HLG OETF of the scene light E in [0, 1]\n"
            f"    return v <= {L.lit(1 / 12)} ? {L.sqrt}({L.lit(3.0)} * v) : "
            f"{L.lit(ha)} * {L.log}({L.lit(12.0)} * v - {L.lit(hb)}) + {L.lit(hc)};\n"
        )
    elif entry.encoding.offset is None:
        gamma = entry.encoding.gamma
        body = (
            f"    // ITU-R BT.1886 with a black level of 0: L ** (1 / {gamma:g})\n"
            f"    return v > {zero} ? {L.pow}(v, {L.lit(1 / gamma)}) : {zero};\n"
        )
    else:
        body = (
            f"    // IEC 61966-2-1 piecewise ({encodings.piecewise(entry.encoding)[1]:.6g} L below "
            f"{encodings.piecewise(entry.encoding)[0]:.6g})\n"
            f"    return {_piecewise_encode(L, entry.encoding, 'v')};\n"
        )
    return head + body + "}\n"


def display_code(L: Language, entry: registry.AnyDisplay, soft: bool) -> str:
    """CIE-XYZ-D65 -> code values: the HDR scale, the matrix, the map, the encoding."""
    gamut = entry.gamut.name
    M = colorimetry.matrix_XYZ_to_RGB(gamut)
    knobs, args = (", float t, float l", ", t, l") if soft else ("", "")
    lines = [
        f"{L.qualifier}{L.vec3} ocio_thinfilm_display(float X, float Y, float Z{knobs})",
        "{",
    ]
    scale_out = "v"
    if isinstance(entry, registry.HDRDisplay) and entry.transfer == "PQ":
        k = entry.scale
        lines.append(f"    // the PQ volume is the gamut's parallelepiped scaled by {k:.6g}")
        lines += [f"    {c} = {c} * {L.lit(1 / k)};" for c in "XYZ"]
        scale_out = f"v * {L.lit(k)}"
    elif isinstance(entry, registry.HDRDisplay):
        # BT.2100 Table 5 (L_B = 0): F_D = L_W Y_S ** (gamma - 1) E; the display light of
        # luminance Y_D has scene light E = F_D / (L_W Y_S ** (gamma - 1)), Y_S =
        # (Y_D / L_W) ** (1 / gamma); the map runs on E, the signal's parallelepiped.
        a = registry.HDR_REFERENCE_WHITE / entry.peak
        lines += [
            "    // HLG: the BT.2100 inverse OOTF to scene light E (the signal's volume is",
            f"    // the gamut's parallelepiped in E); peak {entry.peak:g} cd/m2, gamma "
            f"{HLG_GAMMA:g}",
            f"    float f = Y > {L.lit(0.0)} ? {L.lit(a)} * {L.pow}(Y * {L.lit(a)}, "
            f"{L.lit(1 / HLG_GAMMA - 1)}) : {L.lit(0.0)};",
        ]
        lines += [f"    {c} = {c} * f;" for c in "XYZ"]
    R, G, B = matrix_rows(L, M, ("X", "Y", "Z"))
    lines += [
        f"    {L.vec3} m = ocio_thinfilm_map({R},",
        f"        {G},",
        f"        {B}, Y{args});",
    ]
    enc = [f"ocio_thinfilm_encode({scale_out.replace('v', 'm.' + c)})" for c in "xyz"]
    lines += [f"    return {L.make3}({', '.join(enc)});", "}", ""]
    return "\n".join(lines)


def decode_code(L: Language, entry: registry.AnyDisplay) -> str:
    """Code value -> display-linear of one channel (the inverse of :func:`encode_code`).

    Code values are limited to [0, 1] first (NaN to 0); PQ gives units of the reference
    white (203 cd/m2), HLG the scene light E in [0, 1].
    """
    one, zero = L.lit(1.0), L.lit(0.0)
    m1, m2, c1, c2, c3 = _pq().values()
    ha, hb, hc = _hlg().values()
    head = (
        f"{L.qualifier}float ocio_thinfilm_decode(float v)\n{{\n"
        f"    v = ocio_thinfilm_range(v, {zero}, {one});\n"
    )
    if isinstance(entry, registry.HDRDisplay) and entry.transfer == "PQ":
        scale = 10000.0 / registry.HDR_REFERENCE_WHITE
        body = (
            "    // SMPTE ST 2084 EOTF, in units of the reference white. With p = v ** (1 / m2)\n"
            "    // = exp(x), q = 1 - p: (p - c1) / (c2 - c3 p) = (1 - c1 - q) / (c2 - c3 + c3 q)\n"
            "    // does not cancel near the peak (q from its series where x is small).\n"
            f"    if (!(v > {zero})) return {zero};\n"
            f"    float x = {L.log}(v) * {L.lit(1 / m2)};\n"
            f"    float q = x > {L.lit(-0.05)} ? -x * ({one} + x * ({L.lit(0.5)} + x * "
            f"({L.lit(1 / 6)} + x * {L.lit(1 / 24)}))) : {one} - {L.exp}(x);\n"
            f"    float n = {L.max}({L.lit(1 - c1)} - q, {zero}) / ({L.lit(c2 - c3)} + "
            f"{L.lit(c3)} * q);\n"
            f"    return n > {zero} ? {L.lit(scale)} * {L.pow}(n, {L.lit(1 / m1)}) : {zero};\n"
        )
    elif isinstance(entry, registry.HDRDisplay):
        body = (
            "    // the inverse of the BT.2100 HLG OETF: scene light E in [0, 1]\n"
            f"    return v <= {L.lit(0.5)} ? v * v / {L.lit(3.0)} : ({L.exp}((v - "
            f"{L.lit(hc)}) / {L.lit(ha)}) + {L.lit(hb)}) / {L.lit(12.0)};\n"
        )
    elif entry.encoding.offset is None:
        gamma = entry.encoding.gamma
        body = (
            f"    // ITU-R BT.1886 with a black level of 0: V ** {gamma:g}\n"
            f"    return {L.pow}(v, {L.lit(gamma)});\n"
        )
    else:
        body = (
            "    // IEC 61966-2-1 piecewise, inverted\n"
            f"    return {_piecewise_decode(L, entry.encoding, 'v')};\n"
        )
    return head + body + "}\n"


def unmap_code(L: Language, gamut: str, soft: bool) -> str:
    """Return the map's inverse on display-linear RGB in [0, 1] (the preimage)."""
    w = clip.luminance_weights(gamut)
    one, zero = L.lit(1.0), L.lit(0.0)
    if not soft:
        return f"""
// The clip's inverse inside the gamut: every colour of the gamut is its own preimage.
{L.qualifier}{L.vec3} ocio_thinfilm_unmap(float r, float g, float b)
{{
    return {L.make3}({L.saturate}(r), {L.saturate}(g), {L.saturate}(b));
}}
"""
    p = compress.POWER
    return f"""
// The compression's inverse: the colour at most limit boundary distances out that the
// map takes to this one (the boundary itself: limit), along the same ray, Y kept.
{L.qualifier}{L.vec3} ocio_thinfilm_unmap(float r, float g, float b, float t, float l)
{{
    r = {L.saturate}(r);
    g = {L.saturate}(g);
    b = {L.saturate}(b);
    float Y = {L.lit(w[0])} * r + {L.lit(w[1])} * g + {L.lit(w[2])} * b;
    if (!(Y > {zero})) return {L.make3}({zero}, {zero}, {zero});
    if (Y >= {one}) return {L.make3}({one}, {one}, {one});
    float d = {L.max}(ocio_thinfilm_distance(r, Y),
        {L.max}(ocio_thinfilm_distance(g, Y), ocio_thinfilm_distance(b, Y)));
    if (d <= t) return {L.make3}(r, g, b);
    float k = l / d;
    if (d < {one}) {{
        float s = ocio_thinfilm_curve_s(t, l);
        float u = d - t;
        k = (t + u / {L.pow}({one} - {L.pow}(u / s, {L.lit(p)}), {L.lit(1 / p)})) / d;
    }}
    return {L.make3}(Y + k * (r - Y), Y + k * (g - Y), Y + k * (b - Y));
}}
"""


def undisplay_code(L: Language, entry: registry.AnyDisplay, soft: bool) -> str:
    """Code values -> CIE-XYZ-D65: the decoding, the map's inverse, the HDR scale."""
    gamut = entry.gamut.name
    Minv = reproducible.inv3(colorimetry.matrix_XYZ_to_RGB(gamut))
    knobs, args = (", float t, float l", ", t, l") if soft else ("", "")
    lines = [
        f"{L.qualifier}{L.vec3} ocio_thinfilm_undisplay(float r, float g, float b{knobs})",
        "{",
    ]
    decoded = [f"ocio_thinfilm_decode({c})" for c in "rgb"]
    pq = isinstance(entry, registry.HDRDisplay) and entry.transfer == "PQ"
    if pq:
        decoded = [f"{d} * {L.lit(1 / entry.scale)}" for d in decoded]
    lines.append(f"    {L.vec3} m = ocio_thinfilm_unmap({', '.join(decoded)}{args});")
    rows = matrix_rows(L, Minv, ("m.x", "m.y", "m.z"))
    if pq:
        rows = [f"{L.lit(entry.scale)} * ({row})" for row in rows]
    lines += [f"    float {c} = {row};" for c, row in zip("XYZ", rows, strict=True)]
    if isinstance(entry, registry.HDRDisplay) and entry.transfer == "HLG":
        # the BT.2100 OOTF: display light F_D = L_W Y_S ** (gamma - 1) E, in units of 203
        a = entry.peak / registry.HDR_REFERENCE_WHITE
        lines += [
            f"    // the BT.2100 OOTF (gamma {HLG_GAMMA:g}) back to display light, Y = 1 at "
            f"{registry.HDR_REFERENCE_WHITE:g} cd/m2",
            f"    float f = Y > {L.lit(0.0)} ? {L.lit(a)} * {L.pow}(Y, {L.lit(HLG_GAMMA - 1)}) "
            f": {L.lit(0.0)};",
            "    X = X * f;",
            "    Y = Y * f;",
            "    Z = Z * f;",
        ]
    lines += [f"    return {L.make3}(X, Y, Z);", "}", ""]
    return "\n".join(lines)


def output_code(L: Language, source: str) -> str:
    """CIE-XYZ-D65 -> the input colour space (the inverse of :func:`input_code`)."""
    lines = [f"{L.qualifier}{L.vec3} ocio_thinfilm_output(float X, float Y, float Z)", "{"]
    kind = registry.space_kind(source)
    if kind == "reference":
        return "\n".join(lines + [f"    return {L.make3}(X, Y, Z);", "}", ""])
    texture = kind == "texture"
    space = None if texture else registry.linear_space_of(source)
    M = colorimetry.matrix_XYZ_to_RGB(_TEXTURE_PRIMARIES if space is None else space.colorimetry)
    R, G, B = matrix_rows(L, M, ("X", "Y", "Z"))
    lines += [f"    float r = {R};", f"    float g = {G};", f"    float b = {B};"]
    if texture:
        encoding = registry.as_display(_TEXTURE_DISPLAY, hdr=False).encoding
        lines += [f"    {ch} = {_piecewise_encode(L, encoding, ch)};" for ch in "rgb"]
    encoded = registry.find_encoded(source)
    if encoded is not None:
        lines += _log_encoding(L, encoded.curve)
    lines += [f"    return {L.make3}(r, g, b);", "}", ""]
    return "\n".join(lines)
