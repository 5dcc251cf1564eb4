"""The MaterialX film document (:func:`ocio_thinfilm.export.hosts.materialx.materialx_document`),
checked with PyPI ``materialx`` (1.39): the document validates against MaterialX's
standard libraries; its GLSL and OSL shader generators write code for the material; the
GLSL compiles (glslang's ``glslangValidator``, and Mesa through moderngl) and, drawn on
Mesa as MaterialX's viewer would (the table bound with clamp-to-edge, linear filtering,
v = 0 at its bottom row; a uniform white lat-long environment), a mirror sphere shows
the exact reflectance at each pixel's angle: colour-science's transfer matrices, CIE
1931 2°, D65, linear sRGB (:mod:`evaluation.materials`), not the package's physics.

Skips, with the reason, without ``materialx``, glslang or a headless OpenGL context. The
OSL code is generated, not compiled (no ``oslc`` here).
"""

from __future__ import annotations

import os
import shutil
import subprocess

import numpy as np
import pytest

from evaluation import materials
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.export.hosts.materialx import materialx_document

mx = pytest.importorskip("MaterialX", reason="no PyPI materialx (a test-only dependency)")

#: A soap film (water, n = 1.33) in air, its table over 0.2-0.7 µm.
STACK = materials.SOAP_BUBBLE  # n = 1.33 in air
RANGE_UM = (0.2, 0.7)
TABLE = (128, 128)  # (width: thickness, height: cos θ)
THICKNESS = 0.61
SIZE = 192
RADIUS = 0.9  # away from the silhouette: N·V >= 0.44
#: Linear reflectance, absolute (MaterialX's mirror: 16 importance samples of a GGX lobe
#: of alpha 1e-4; the table's bilinear lookup).
TOLERANCE = 0.005
MATERIAL = "ThinFilm_Soap"


def _document():
    return materialx_document("Soap", "Soap_R.exr", RANGE_UM, size=TABLE)


def _loaded():
    doc = mx.createDocument()
    mx.readFromXmlString(doc, _document())
    library = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), library)
    doc.importLibrary(library)
    return doc


def _generate(language):
    """{stage: source} of the material from MaterialX's ``language`` generator."""
    from MaterialX import PyMaterialXGenShader as gen_shader

    if language == "glsl":
        from MaterialX.PyMaterialXGenGlsl import GlslShaderGenerator as Generator

        stages = {"vert": gen_shader.VERTEX_STAGE, "frag": gen_shader.PIXEL_STAGE}
    else:
        from MaterialX.PyMaterialXGenOsl import OslShaderGenerator as Generator

        stages = {"osl": gen_shader.PIXEL_STAGE}
    doc = _loaded()
    generator = Generator.create()
    context = gen_shader.GenContext(generator)
    context.registerSourceCodeSearchPath(mx.getDefaultDataSearchPath())
    shader = generator.generate(MATERIAL, doc.getChild(MATERIAL), context)
    return {key: shader.getSourceCode(stage) for key, stage in stages.items()}


def test_the_document_validates():
    doc = _loaded()
    valid, message = doc.validate()
    assert valid, message
    image = doc.getChild("NG_ThinFilm_Soap").getNode("table")
    assert image.getInputValue("file") == "Soap_R.exr"
    assert [image.getInputValue(k) for k in ("uaddressmode", "vaddressmode", "filtertype")] == [
        "clamp",
        "clamp",
        "linear",
    ]


def test_the_osl_generator_writes_the_material():
    osl = _generate("osl")["osl"]
    assert f"shader {MATERIAL}" in osl and "Soap_R.exr" in osl


def test_the_glsl_compiles_with_glslang(tmp_path):
    validator = shutil.which("glslangValidator")
    if validator is None:
        pytest.skip("no glslangValidator (Debian's glslang-tools)")
    for suffix, source in _generate("glsl").items():
        path = tmp_path / f"{MATERIAL}.{suffix}"
        path.write_text(source, encoding="utf-8")
        done = subprocess.run([validator, str(path)], capture_output=True, text=True)
        assert done.returncode == 0, done.stdout + done.stderr


def _ortho_view_projection():
    """Camera on +z looking at the origin, [-1, 1]² orthographic, depth 0.1-10."""
    view = np.eye(4)
    view[2, 3] = -5.0
    near, far = 0.1, 10.0
    projection = np.diag([1.0, 1.0, -2.0 / (far - near), 1.0])
    projection[2, 3] = -(far + near) / (far - near)
    return projection @ view


def _sphere(segments=256, rings=128):
    """A unit UV sphere: interleaved (position, normal, tangent) and triangle indices."""
    theta = np.linspace(0.0, np.pi, rings + 1)[:, None]
    phi = np.linspace(0.0, 2.0 * np.pi, segments + 1)[None, :]
    p = np.stack(
        [np.sin(theta) * np.cos(phi), np.cos(theta) + 0 * phi, np.sin(theta) * np.sin(phi)], -1
    ).reshape(-1, 3)
    tangent = np.stack([-np.sin(phi) + 0 * theta, 0 * theta + 0 * phi, np.cos(phi) + 0 * theta], -1)
    vertices = np.concatenate([p, p, tangent.reshape(-1, 3)], axis=1).astype("f4")
    i = np.arange(rings)[:, None] * (segments + 1) + np.arange(segments)[None, :]
    quads = np.stack([i, i + segments + 1, i + 1, i + 1, i + segments + 1, i + segments + 2], -1)
    return vertices, quads.reshape(-1).astype("i4")


def _render(ctx, sources, table):
    program = ctx.program(vertex_shader=sources["vert"], fragment_shader=sources["frag"])
    vertices, indices = _sphere()
    vbo, ibo = ctx.buffer(vertices.tobytes()), ctx.buffer(indices.tobytes())
    vao = ctx.vertex_array(
        program, [(vbo, "3f 3f 3f", "i_position", "i_normal", "i_tangent")], index_buffer=ibo
    )
    height, width = table.shape[:2]
    texture = ctx.texture((width, height), 3, table.astype("f4").tobytes(), dtype="f4")
    texture.filter = (ctx.LINEAR, ctx.LINEAR)
    texture.repeat_x = texture.repeat_y = False
    env = ctx.texture((8, 4), 3, np.ones((4, 8, 3), "f4").tobytes(), dtype="f4")
    colour = ctx.texture((SIZE, SIZE), 4, dtype="f4")
    depth = ctx.depth_renderbuffer((SIZE, SIZE))
    fbo = ctx.framebuffer(color_attachments=[colour], depth_attachment=depth)
    try:
        program["u_viewProjectionMatrix"].write(_ortho_view_projection().T.astype("f4").tobytes())
        program["u_viewPosition"].value = (0.0, 0.0, 1.0e4)  # rays all but parallel
        program["thickness_u_in"].value = THICKNESS
        texture.use(location=0)
        env.use(location=1)
        program["table_file"].value = 0
        program["u_envRadiance"].value = 1
        fbo.use()
        fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        ctx.enable(ctx.DEPTH_TEST)
        vao.render()
        out = np.frombuffer(fbo.read(components=4, dtype="f4"), np.float32)
    finally:
        for obj in (vao, vbo, ibo, texture, env, fbo, colour, depth, program):
            obj.release()
    return out.reshape(SIZE, SIZE, 4)


def test_the_glsl_draws_the_exact_reflectance_on_mesa(gl):
    sources = _generate("glsl")
    table = materials.table(STACK, RANGE_UM, *TABLE)  # row 0: cos θ near 0
    image = _render(gl, sources, table)
    centres = (np.arange(SIZE) + 0.5) / SIZE * 2.0 - 1.0
    x, y = np.meshgrid(centres, centres)
    radius = np.hypot(x, y)
    inside = radius <= RADIUS
    grid = np.linspace(0.0, 1.0, 4097)
    exact = materials.film_rgb(STACK, THICKNESS, grid)
    cos = np.sqrt(1.0 - radius[inside] ** 2)
    truth = np.stack([np.interp(cos, grid, exact[:, k]) for k in range(3)], axis=1)
    truth = np.maximum(truth, 0.0)  # the GLSL's BSDF clamps negative (out-of-gamut) values
    error = np.abs(image[inside][:, :3] - truth).max(axis=1)
    print(
        f"\nMaterialX {mx.__version__} GLSL on Mesa: |render - exact| linear max "
        f"{error.max():.4f}, p99 {np.percentile(error, 99):.4f}"
    )
    assert np.all(image[radius > 1.02] == 0.0)
    assert error.max() <= TOLERANCE
    gallery = os.environ.get("OCIO_THINFILM_GALLERY")  # a directory for the docs' picture
    if gallery:
        import colour
        import OpenImageIO as oiio

        codes = colour.cctf_encoding(np.clip(image[::-1, :, :3], 0.0, 1.0), "sRGB")
        png = oiio.ImageBuf(np.round(codes * 255.0).astype(np.uint8))
        assert png.write(os.path.join(gallery, "materialx_soap.png")), oiio.geterror()


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"range_um": (1.0, 0.5)}, "range_um"),
        ({"reflectance_exr": "Soap_R.tif"}, "reflectance_exr"),
        ({"space": "sRGB"}, "space"),
        ({"size": (1, 64)}, "size"),
        ({"size": (64,)}, "size"),
    ],
)
def test_bad_arguments_name_the_parameter(kwargs, match):
    args = {
        "key": "Soap",
        "reflectance_exr": "Soap_R.exr",
        "range_um": (0.0, 1.0),
        "size": (64, 32),
        **kwargs,
    }
    with pytest.raises(ParameterError, match=f"^{match}"):
        materialx_document(**args)
