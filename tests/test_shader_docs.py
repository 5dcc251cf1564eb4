"""The Matchbox wrapper of docs/matchbox.md, read from the page: compiled and run on Mesa
as GLSL 1.20 and 1.30 around the exported GLSL, held to the analytic view; its XML
sidecar parsed and matched to the shader's uniforms and the DCTL's slider ranges.

Not run in Flame or Baselight (neither is available): docs/matchbox.md says so.
"""

from __future__ import annotations

import re
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from evaluation.colours import gamut_map_sets
from evaluation.shaders import analytic_view, source_values
from ocio_thinfilm.colour import compress
from ocio_thinfilm.export import shader

DOC = Path(__file__).resolve().parents[1] / "docs" / "matchbox.md"
COMPRESS = "Constant-Lightness Compress"
TOLERANCE = 1e-3


def _block(name):
    text = DOC.read_text(encoding="utf-8")
    match = re.search(rf"<!-- matchbox:{re.escape(name)} -->\n```\w+\n(.*?)```", text, re.S)
    assert match, f"docs/matchbox.md has no block {name}"
    return match.group(1)


_VERTEX = """#version 130
void main()
{
    vec2 p = vec2(float((gl_VertexID * 2) % 4), float((gl_VertexID / 2) * 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
"""


def _run(ctx, fragment, pixels, knobs):
    """Draw the Matchbox shader over a float32 texture ``front`` as Flame would feed it."""
    program = ctx.program(vertex_shader=_VERTEX, fragment_shader=fragment)
    n = len(pixels)
    width = 128
    height = -(-n // width)
    rgba = np.zeros((width * height, 4), np.float32)
    rgba[:n, :3] = pixels
    rgba[:, 3] = 0.5
    src = ctx.texture((width, height), 4, rgba.tobytes(), dtype="f4")
    src.filter = (ctx.NEAREST, ctx.NEAREST)
    dst = ctx.texture((width, height), 4, dtype="f4")
    fbo = ctx.framebuffer(color_attachments=[dst])
    vao = ctx.vertex_array(program, [])
    try:
        src.use(location=0)
        program["front"].value = 0
        program["adsk_result_w"].value = float(width)
        program["adsk_result_h"].value = float(height)
        program["ocio_thinfilm_threshold"].value, program["ocio_thinfilm_limit"].value = knobs
        fbo.use()
        fbo.viewport = (0, 0, width, height)
        vao.render(mode=ctx.TRIANGLES, vertices=3)
        out = np.frombuffer(fbo.read(components=4, dtype="f4"), np.float32).reshape(-1, 4)
    finally:
        for obj in (vao, fbo, dst, src, program):
            obj.release()
    return out[:n]


@pytest.mark.parametrize("version", ["120", "130"])
def test_the_matchbox_wrapper_compiles_and_is_the_view(gl, version):
    head = _block("head.glsl")
    assert head.startswith("#version 120\n")
    head = head.replace("#version 120", f"#version {version}", 1)
    view = shader.shader_source("glsl", "sRGB", COMPRESS, "ACEScg")
    fragment = head + view + _block("main.glsl")
    XYZ = np.concatenate(list(gamut_map_sets().values()))
    pixels = source_values(XYZ, "ACEScg").astype(np.float32)
    worst = {}
    for knobs in [(0.0, 0.0), (0.6, 1.5)]:  # unset (the exported defaults), then set
        got = _run(gl, fragment, pixels, knobs)
        truth_knobs = (compress.THRESHOLD, compress.LIMIT) if knobs == (0.0, 0.0) else knobs
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            truth = analytic_view(pixels, "ACEScg", "sRGB", COMPRESS, *truth_knobs)
        worst[knobs] = float(np.abs(got[:, :3] - truth).max())
        assert np.all(got[:, 3] == 0.5)  # the input's alpha passes
    shown = {k: f"{v:.2e}" for k, v in worst.items()}
    print(f"\nMatchbox wrapper, GLSL {version}: max |Mesa - analytic| {shown} code values")
    assert max(worst.values()) <= TOLERANCE


def test_the_matchbox_xml_names_the_shader_s_uniforms():
    root = ET.fromstring(_block("ConstantLightnessCompress.xml"))
    assert root.tag == "ShaderNodePreset"
    uniforms = {u.get("Name"): u for u in root.iter("Uniform")}
    assert set(uniforms) == {"front", "ocio_thinfilm_threshold", "ocio_thinfilm_limit"}
    glsl = _block("head.glsl") + shader.shader_source("glsl", "sRGB", COMPRESS)
    for name in uniforms:
        assert re.search(rf"uniform \w+ {name}\b", glsl), name
    assert uniforms["front"].get("Type") == "sampler2D"
    for name, (lo, hi, step), default in [
        ("ocio_thinfilm_threshold", shader.THRESHOLD_SLIDER, compress.THRESHOLD),
        ("ocio_thinfilm_limit", shader.LIMIT_SLIDER, compress.LIMIT),
    ]:
        u = uniforms[name]
        assert u.get("Type") == "float"
        got = [float(u.get(k)) for k in ("Min", "Max", "Inc", "Default")]
        assert got == pytest.approx([lo, hi, step, default]), name
