"""The MaterialX film document (:func:`ocio_thinfilm.export.hosts.materialx.materialx_document`),
checked with PyPI ``materialx`` (1.39): the document validates against MaterialX's
standard libraries; its GLSL and OSL shader generators write code for the material; the
GLSL compiles (glslang's ``glslangValidator``, and Mesa through moderngl) and, drawn on
Mesa as MaterialX's viewer would (the table bound with clamp-to-edge, linear filtering,
v = 0 at its bottom row; a uniform white lat-long environment), a mirror sphere shows
the exact reflectance at each pixel's angle: colour-science's transfer matrices, CIE
1931 2°, D65, linear sRGB (:mod:`evaluation.materials`), not the package's physics.

A free-standing film's document (the transmittance table too) is drawn under a lat-long
environment of one colour in front of the sphere and another behind it: each pixel is
the exact R times the front colour plus the exact T times the one behind (MaterialX's
GLSL approximates transmission by the environment seen through the surface); a document
whose film node takes its thickness from a ``noise3d`` node validates, generates,
compiles and draws colours of the film (the independent table's, at some thickness).

Skips, with the reason, without ``materialx``, glslang or a headless OpenGL context. The
OSL code is generated, not compiled (no ``oslc`` here).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import xml.etree.ElementTree as ET

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
MATERIAL = "Soap"


#: The free-standing film's documents draw a dyed soap film (n = 1.33 + 0.02i), absorbing,
#: so that its T is not 1 - R (for a clear film it is: a test of T would not tell them
#: apart).
DYED = materials.Stack.single(1.33 + 0.02j)
#: The free-standing film's document: its name, material and the environment's colours
#: in front of the sphere (what its reflection sees) and behind it (what it transmits).
BUBBLE_NAME = "Soap bubble"
BUBBLE = "Soap_bubble"
FRONT, BEHIND = np.array([0.3, 0.35, 0.4]), np.array([0.9, 0.5, 0.15])
#: Pixels whose reflection stays in the front half of the environment (N·V >= 0.8).
FRONT_RADIUS = 0.6


def _document(**kwargs):
    return materialx_document("Soap", "Soap_R.exr", RANGE_UM, size=TABLE, **kwargs)


def _bubble_document():
    return _document(transmittance_exr="Soap_T.exr", name=BUBBLE_NAME)


def _noise_document():
    """The bubble's document with its film node's thickness from a ``noise3d`` node:
    0.45 ± 0.2 µm over the object-space position times 4."""
    doc = ET.fromstring(_bubble_document().split("\n", 1)[1])
    ET.SubElement(doc, "position", name="P", type="vector3")
    scaled = ET.SubElement(doc, "multiply", name="P4", type="vector3")
    ET.SubElement(scaled, "input", name="in1", type="vector3", nodename="P")
    ET.SubElement(scaled, "input", name="in2", type="float", value="4.0")
    noise = ET.SubElement(doc, "noise3d", name="thickness_noise", type="float")
    ET.SubElement(noise, "input", name="position", type="vector3", nodename="P4")
    ET.SubElement(noise, "input", name="amplitude", type="float", value="0.2")
    ET.SubElement(noise, "input", name="pivot", type="float", value="0.45")
    film = doc.find("Soap_bubble")
    ET.SubElement(film, "input", name="thickness", type="float", nodename="thickness_noise")
    return ET.tostring(doc, encoding="unicode")


def _loaded(text=None):
    doc = mx.createDocument()
    mx.readFromXmlString(doc, _document() if text is None else text)
    library = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), library)
    doc.importLibrary(library)
    return doc


def _generate(language, text=None, material=MATERIAL):
    """{stage: source} of the material from MaterialX's ``language`` generator."""
    from MaterialX import PyMaterialXGenShader as gen_shader

    if language == "glsl":
        from MaterialX.PyMaterialXGenGlsl import GlslShaderGenerator as Generator

        stages = {"vert": gen_shader.VERTEX_STAGE, "frag": gen_shader.PIXEL_STAGE}
    else:
        from MaterialX.PyMaterialXGenOsl import OslShaderGenerator as Generator

        stages = {"osl": gen_shader.PIXEL_STAGE}
    doc = _loaded(text)
    generator = Generator.create()
    context = gen_shader.GenContext(generator)
    context.registerSourceCodeSearchPath(mx.getDefaultDataSearchPath())
    shader = generator.generate(material, doc.getChild(material), context)
    return {key: shader.getSourceCode(stage) for key, stage in stages.items()}


#: (document, material): the reflection only, a free-standing film, its thickness by noise.
DOCUMENTS = {
    "reflection": (_document, MATERIAL),
    "bubble": (_bubble_document, BUBBLE),
    "noise": (_noise_document, BUBBLE),
}


@pytest.mark.parametrize("which", DOCUMENTS)
def test_the_document_validates(which):
    make, _ = DOCUMENTS[which]
    doc = _loaded(make())
    valid, message = doc.validate()
    assert valid, message
    graph = doc.getChild("NG_Soap" if which == "reflection" else "NG_Soap_bubble")
    image = graph.getNode("reflectance")
    assert image.getInputValue("file") == "Soap_R.exr"
    assert [image.getInputValue(k) for k in ("uaddressmode", "vaddressmode", "filtertype")] == [
        "clamp",
        "clamp",
        "linear",
    ]
    transmittance = graph.getNode("transmittance")
    if which == "reflection":
        assert transmittance is None and graph.getNode("transmission") is None
    else:
        assert transmittance.getInputValue("file") == "Soap_T.exr"
        transmission = graph.getNode("transmission")
        assert transmission.getCategory() == "dielectric_bsdf"
        assert transmission.getInputValue("scatter_mode") == "T"
        assert transmission.getInputValue("ior") == 1.0


def test_the_film_is_a_node_with_a_connectable_thickness():
    doc = _loaded(_noise_document())
    nodedef = doc.getNodeDef("ND_Soap_bubble")
    assert nodedef is not None and nodedef.getNodeString() == "Soap_bubble"
    assert nodedef.getInput("thickness").getType() == "float"
    assert nodedef.getImplementation().getName() == "NG_Soap_bubble"
    film = doc.getNode("SS_Soap_bubble")
    assert film.getInput("thickness").getConnectedNode().getCategory() == "noise3d"


@pytest.mark.parametrize("which", DOCUMENTS)
def test_the_osl_generator_writes_the_material(which):
    make, material = DOCUMENTS[which]
    osl = _generate("osl", make(), material)["osl"]
    assert f"shader {material}" in osl and "Soap_R.exr" in osl
    assert ("Soap_T.exr" in osl) == (which != "reflection")


@pytest.mark.parametrize("which", DOCUMENTS)
def test_the_glsl_compiles_with_glslang(tmp_path, which):
    validator = shutil.which("glslangValidator")
    if validator is None:
        pytest.skip("no glslangValidator (Debian's glslang-tools)")
    make, material = DOCUMENTS[which]
    for suffix, source in _generate("glsl", make(), material).items():
        path = tmp_path / f"{material}.{suffix}"
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


def _environment(front=(1.0, 1.0, 1.0), behind=(1.0, 1.0, 1.0)):
    """A 256 x 128 lat-long environment: ``front`` where MaterialX's lookup (its default
    ``u_envMatrix`` turns x and z about) puts the directions towards the camera (+z,
    longitude u in [0.25, 0.75)), ``behind`` for those away from it."""
    u = (np.arange(256) + 0.5) / 256
    columns = np.where(((u >= 0.25) & (u < 0.75))[:, None], np.array(front), np.array(behind))
    return np.broadcast_to(columns[None], (128, 256, 3))


def _render(ctx, sources, tables, thickness=THICKNESS, environment=None):
    """Draw the sphere; ``tables``: {sampler uniform: (H, W, 3) table, row 0 at cos θ 0}."""
    program = ctx.program(vertex_shader=sources["vert"], fragment_shader=sources["frag"])
    vertices, indices = _sphere()
    vbo, ibo = ctx.buffer(vertices.tobytes()), ctx.buffer(indices.tobytes())
    vao = ctx.vertex_array(
        program, [(vbo, "3f 3f 3f", "i_position", "i_normal", "i_tangent")], index_buffer=ibo
    )
    textures = []
    for table in tables.values():
        height, width = table.shape[:2]
        texture = ctx.texture((width, height), 3, table.astype("f4").tobytes(), dtype="f4")
        texture.filter = (ctx.LINEAR, ctx.LINEAR)
        texture.repeat_x = texture.repeat_y = False
        textures.append(texture)
    pixels = _environment() if environment is None else environment
    env = ctx.texture(
        (pixels.shape[1], pixels.shape[0]), 3, pixels.astype("f4").tobytes(), dtype="f4"
    )
    colour = ctx.texture((SIZE, SIZE), 4, dtype="f4")
    depth = ctx.depth_renderbuffer((SIZE, SIZE))
    fbo = ctx.framebuffer(color_attachments=[colour], depth_attachment=depth)
    try:
        program["u_viewProjectionMatrix"].write(_ortho_view_projection().T.astype("f4").tobytes())
        program["u_viewPosition"].value = (0.0, 0.0, 1.0e4)  # rays all but parallel
        for name in ("SS_Soap_thickness", "SS_Soap_bubble_thickness"):
            if thickness is not None and program.get(name, None) is not None:
                program[name].value = thickness
        env.use(location=0)
        program["u_envRadiance"].value = 0
        for unit, (name, texture) in enumerate(zip(tables, textures, strict=True), start=1):
            texture.use(location=unit)
            program[name].value = unit
        fbo.use()
        fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        ctx.enable(ctx.DEPTH_TEST)
        vao.render()
        out = np.frombuffer(fbo.read(components=4, dtype="f4"), np.float32)
    finally:
        for obj in (vao, vbo, ibo, *textures, env, fbo, colour, depth, program):
            obj.release()
    return out.reshape(SIZE, SIZE, 4)


def _pixels(radius_limit):
    """The pixel mask within ``radius_limit`` of the centre (GL's rows) and each
    pixel's cos θ."""
    centres = (np.arange(SIZE) + 0.5) / SIZE * 2.0 - 1.0
    x, y = np.meshgrid(centres, centres)
    radius = np.hypot(x, y)
    inside = radius <= radius_limit
    return inside, np.sqrt(1.0 - radius[inside] ** 2), radius


def _exact(thickness, cos, quantity="reflectance", stack=STACK):
    grid = np.linspace(0.0, 1.0, 4097)
    exact = materials.film_rgb(stack, thickness, grid, quantity=quantity)
    return np.stack([np.interp(cos, grid, exact[:, k]) for k in range(3)], axis=1)


def test_the_glsl_draws_the_exact_reflectance_on_mesa(gl):
    sources = _generate("glsl")
    table = materials.table(STACK, RANGE_UM, *TABLE)  # row 0: cos θ near 0
    image = _render(gl, sources, {"reflectance_file": table})
    inside, cos, radius = _pixels(RADIUS)
    truth = _exact(THICKNESS, cos)
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


def _bubble_tables():
    return {
        "reflectance_file": materials.table(DYED, RANGE_UM, *TABLE),
        "transmittance_file": materials.table(DYED, RANGE_UM, *TABLE, quantity="transmittance"),
    }


def test_the_glsl_draws_the_bubble_s_reflection_and_transmission_on_mesa(gl):
    sources = _generate("glsl", _bubble_document(), BUBBLE)
    image = _render(gl, sources, _bubble_tables(), environment=_environment(FRONT, BEHIND))
    inside, cos, radius = _pixels(FRONT_RADIUS)
    r = np.maximum(_exact(THICKNESS, cos, stack=DYED), 0.0)  # the BSDFs clamp negatives
    t = np.maximum(_exact(THICKNESS, cos, "transmittance", DYED), 0.0)
    assert np.abs(1.0 - r - t).min() > 0.1  # T is told apart from 1 - R
    error = np.abs(image[inside][:, :3] - (r * FRONT + t * BEHIND)).max(axis=1)
    print(
        f"\nMaterialX {mx.__version__} GLSL on Mesa, a bubble: |render - (R front + T "
        f"behind)| linear max {error.max():.5f}, p99 {np.percentile(error, 99):.5f}"
    )
    assert np.all(image[radius > 1.02] == 0.0)
    assert error.max() <= TOLERANCE
    # without the transmission the pixels would be far off
    assert np.abs(image[inside][:, :3] - r * FRONT).max() > 0.3


def test_a_noise_driven_thickness_draws_the_film_s_colours_on_mesa(gl):
    sources = _generate("glsl", _noise_document(), BUBBLE)
    tables = _bubble_tables()
    image = _render(gl, sources, tables, thickness=None, environment=_environment(FRONT, BEHIND))
    inside, cos, _ = _pixels(FRONT_RADIUS)
    drawn = image[inside][:, :3]
    assert np.all(np.isfinite(image))
    # the film's colours at each pixel's cos θ, at every thickness the bilinear table
    # holds (its columns and three points between each pair)
    rows = cos * (TABLE[1] - 1)
    j, w = np.minimum(rows.astype(int), TABLE[1] - 2), (rows % 1.0)[:, None, None]
    colours = [
        np.maximum(tables[name][j] * (1 - w) + tables[name][j + 1] * w, 0.0)
        for name in ("reflectance_file", "transmittance_file")
    ]
    film = colours[0] * FRONT + colours[1] * BEHIND  # (pixels, columns, 3)
    steps = np.linspace(0.0, 1.0, 4, endpoint=False)[None, :, None, None]
    dense = film[:, :-1, None] * (1 - steps[..., 0, :]) + film[:, 1:, None] * steps[..., 0, :]
    dense = dense.reshape(len(drawn), -1, 3)
    nearest = np.abs(dense - drawn[:, None]).max(axis=2).min(axis=1)
    spread = np.ptp(drawn, axis=0).max()
    print(
        f"\nMaterialX noise3d thickness on Mesa: |render - nearest film colour| max "
        f"{nearest.max():.4f}; colours spread {spread:.3f}"
    )
    assert nearest.max() <= TOLERANCE
    assert spread > 0.05  # the noise does vary the thickness


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"range_um": (1.0, 0.5)}, "range_um"),
        ({"reflectance_exr": "Soap_R.tif"}, "reflectance_exr"),
        ({"space": "sRGB"}, "space"),
        ({"size": (1, 64)}, "size"),
        ({"size": (64,)}, "size"),
        ({"transmittance_exr": "Soap_T.tif"}, "transmittance_exr"),
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


def test_the_names_come_from_the_film_s_name():
    text = materialx_document("Oil", "Oil_R.exr", (0.0, 1.0), size=(64, 32), name="Oil slick 2")
    for element in (
        '<nodedef name="ND_Oil_slick_2" node="Oil_slick_2"',
        '<nodegraph name="NG_Oil_slick_2" nodedef="ND_Oil_slick_2">',
        '<Oil_slick_2 name="SS_Oil_slick_2" type="surfaceshader"',
        '<surfacematerial name="Oil_slick_2" type="material">',
    ):
        assert element in text, element
