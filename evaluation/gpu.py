"""Run OpenColorIO's GLSL on a headless OpenGL context (the GPU path the tests check).

OpenColorIO evaluates a processor on the GPU by generating a GLSL function
(``OCIOMain``) plus the textures (LUTs) and uniforms it reads.  Hosts such as
Blender's viewport upload those textures themselves, and Blender uploads them
as half floats (``RGB16F``: 11 significant bits), so a config whose LUT
outputs are amplified afterwards can look fine on the CPU and wrong on screen.
This module reproduces that path on Mesa's software renderer (llvmpipe, via a
headless EGL context from :mod:`moderngl`) so tests can compare the GPU result
with ``Processor.getDefaultCPUProcessor()``.

The upload mirrors OpenColorIO's own ``oglapp``/``glsl.cpp`` helpers: every
3D LUT becomes an RGB 3D texture of ``edgelen**3`` texels, every 1D LUT an R or
RGB texture of ``width x height`` texels, each with the filtering OCIO asks
for (``GL_LINEAR`` unless ``INTERP_NEAREST``) and clamp-to-edge wrapping; every
uniform is set from its getter.  ``texture_dtype="f4"`` uploads float32
(``R32F``/``RGB32F``), ``"f2"`` uploads half floats (``R16F``/``RGB16F``): the
float32 values are rounded to float16 (round to nearest even, overflow to
infinity, as a GL driver converting ``GL_FLOAT`` data to a 16F texture does)
before upload.

Only 2D textures are used for 1D LUTs (``GpuShaderDesc.setAllowTexture1D(False)``,
OCIO then lays a 1D LUT out as a 2D texture, ``height`` 1 for short LUTs),
because moderngl has no 1D textures.  Linear filtering along a 1-texel-high 2D
texture sampled at the texel centre row is the same arithmetic as a 1D texture.

Examples
--------
>>> import PyOpenColorIO as ocio                                  # doctest: +SKIP
>>> cfg = ocio.Config.CreateFromFile("configs/thinfilm/config.ocio")  # doctest: +SKIP
>>> proc = cfg.getProcessor("ACEScg", "sRGB", "Raw",
...                         ocio.TRANSFORM_DIR_FORWARD)           # doctest: +SKIP
>>> apply_gpu(proc, [[0.18, 0.18, 0.18]], texture_dtype="f2")     # doctest: +SKIP
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

__all__ = [
    "gl_context",
    "default_context",
    "GpuProgram",
    "apply_gpu",
    "render_pixels",
    "supported_languages",
]

#: Name of the input-pixel sampler in the wrapper shader (kept out of OCIO's
#: resource prefix so it cannot collide with OCIO's samplers or uniforms).
_INPUT_SAMPLER = "thinfilm_gpu_input"

#: Width of the input/output images that hold the pixel list.
_ROW = 256

_VERTEX_SHADER = """
{version}
void main()
{{
    // One triangle covering the viewport; no vertex buffer needed.
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}}
"""

_FRAGMENT_HEAD = """
{version}
{precision}
uniform sampler2D {input};
out vec4 thinfilm_gpu_output;
"""

_FRAGMENT_MAIN = """
void main()
{{
    vec4 color = texelFetch({input}, ivec2(gl_FragCoord.xy), 0);
    thinfilm_gpu_output = {function}(color);
}}
"""


def _languages():
    import PyOpenColorIO as ocio

    return {
        ocio.GPU_LANGUAGE_GLSL_1_3: ("#version 130", ""),
        ocio.GPU_LANGUAGE_GLSL_4_0: ("#version 400 core", ""),
        # ES defaults samplers to lowp: Mesa then samples at reduced precision.
        ocio.GPU_LANGUAGE_GLSL_ES_3_0: (
            "#version 300 es",
            "precision highp float;\nprecision highp int;\n"
            "precision highp sampler2D;\nprecision highp sampler3D;",
        ),
    }


def supported_languages():
    """Map the OCIO GPU languages this module can run to their GLSL headers.

    Returns
    -------
    dict
        ``{PyOpenColorIO.GpuLanguage: (version_line, precision_lines)}``.
        GLSL 1.2 is absent: it has neither ``texelFetch`` nor ``out``.
    """
    return dict(_languages())


_CONTEXT = None
_CONTEXT_ERROR = None


def gl_context(require=330):
    """Create a headless OpenGL context (EGL backend, no window, no display).

    ``EGL_PLATFORM=surfaceless`` is set when the variable is unset, so Mesa
    picks its surfaceless platform instead of probing for X11/Wayland.  On a
    machine without a GPU this is Mesa's llvmpipe software renderer (Debian
    packages ``libegl1 libegl-mesa0 libgl1-mesa-dri libgbm1``).

    Parameters
    ----------
    require : int, optional
        Minimum OpenGL version (``330`` = 3.3 core); float textures,
        ``texelFetch`` and 3D textures all need 3.x.

    Returns
    -------
    moderngl.Context
        A new standalone context.  Release it with ``ctx.release()``.

    Raises
    ------
    RuntimeError
        With the reason, when moderngl is not installed or no context can be
        created (missing EGL/Mesa libraries, version too low, ...).
    """
    try:
        import moderngl
    except ImportError as exc:  # pragma: no cover - depends on the machine
        raise RuntimeError(f"moderngl is not installed ({exc}); pip install moderngl") from exc
    os.environ.setdefault("EGL_PLATFORM", "surfaceless")
    try:
        ctx = moderngl.create_standalone_context(backend="egl", require=require)
    except Exception as exc:  # moderngl raises plain Exception subclasses
        raise RuntimeError(
            "no headless OpenGL context could be created with moderngl's EGL backend "
            f"(EGL_PLATFORM={os.environ.get('EGL_PLATFORM')}): {type(exc).__name__}: {exc}. "
            "On Debian install libegl1 libegl-mesa0 libgl1-mesa-dri libgbm1."
        ) from exc
    return ctx


def default_context():
    """Return a process-wide context, created on first use by :func:`gl_context`.

    Returns
    -------
    moderngl.Context

    Raises
    ------
    RuntimeError
        As :func:`gl_context`; the failure is remembered and re-raised.
    """
    global _CONTEXT, _CONTEXT_ERROR
    if _CONTEXT is None:
        if _CONTEXT_ERROR is not None:
            raise RuntimeError(_CONTEXT_ERROR)
        try:
            _CONTEXT = gl_context()
        except RuntimeError as exc:
            _CONTEXT_ERROR = str(exc)
            raise
    return _CONTEXT


def _texture_bytes(values, texture_dtype):
    values = np.ascontiguousarray(values, dtype=np.float32)
    if texture_dtype == "f4":
        return values.tobytes()
    with np.errstate(over="ignore"):
        return values.astype(np.float16).tobytes()


@dataclass
class GpuProgram:
    """OCIO's shader for one processor, compiled once, run on many pixel sets.

    Parameters
    ----------
    processor : PyOpenColorIO.Processor or PyOpenColorIO.GPUProcessor
        The transform; a ``Processor`` is turned into its default GPU
        processor.
    ctx : moderngl.Context, optional
        The context; :func:`default_context` when omitted.
    language : PyOpenColorIO.GpuLanguage, optional
        The GLSL dialect OCIO generates; ``GPU_LANGUAGE_GLSL_4_0`` by default
        (Mesa's llvmpipe runs 4.5 core).  See :func:`supported_languages`.
    resource_prefix : str, optional
        OCIO's prefix for texture and uniform names.

    Attributes
    ----------
    shader_desc : PyOpenColorIO.GpuShaderDesc
        The extracted shader description.
    fragment_source : str
        The full fragment shader compiled (wrapper + OCIO's text).
    """

    processor: object
    ctx: object = None
    language: object = None
    resource_prefix: str = "ocio_"
    shader_desc: object = field(init=False, repr=False)
    fragment_source: str = field(init=False, repr=False)

    def __post_init__(self):
        import PyOpenColorIO as ocio

        if self.ctx is None:
            self.ctx = default_context()
        if self.language is None:
            self.language = ocio.GPU_LANGUAGE_GLSL_4_0
        headers = _languages()
        if self.language not in headers:
            raise ValueError(
                f"unsupported GPU language {self.language}; use one of {list(headers)}"
            )
        version, precision = headers[self.language]

        gpu = self.processor
        if hasattr(gpu, "getDefaultGPUProcessor"):
            gpu = gpu.getDefaultGPUProcessor()
        desc = ocio.GpuShaderDesc.CreateShaderDesc(
            language=self.language, functionName="OCIOMain", resourcePrefix=self.resource_prefix
        )
        desc.setAllowTexture1D(False)  # moderngl has no 1D textures: OCIO lays 1D LUTs out in 2D
        gpu.extractGpuShaderInfo(desc)
        self.shader_desc = desc

        self.fragment_source = (
            _FRAGMENT_HEAD.format(version=version, precision=precision, input=_INPUT_SAMPLER)
            + desc.getShaderText()
            + _FRAGMENT_MAIN.format(input=_INPUT_SAMPLER, function=desc.getFunctionName())
        )
        vertex = _VERTEX_SHADER.format(version=version)
        self.program = self.ctx.program(vertex_shader=vertex, fragment_shader=self.fragment_source)
        self._vao = self.ctx.vertex_array(self.program, [])
        self._set_uniforms()
        self._luts = {}  # texture_dtype -> [(texture, unit)]

    # -- resources ---------------------------------------------------------------------------

    def _set_uniforms(self):
        import PyOpenColorIO as ocio

        for name, data in self.shader_desc.getUniforms():
            uniform = self.program.get(name, None)
            if uniform is None:  # declared but optimised out by the GLSL compiler
                continue
            kind = data.type
            if kind == ocio.UNIFORM_DOUBLE:
                uniform.value = float(data.getDouble())
            elif kind == ocio.UNIFORM_BOOL:
                uniform.value = bool(data.getBool())
            elif kind == ocio.UNIFORM_FLOAT3:
                uniform.value = tuple(float(v) for v in data.getFloat3())
            elif kind in (ocio.UNIFORM_VECTOR_FLOAT, ocio.UNIFORM_VECTOR_INT):
                if kind == ocio.UNIFORM_VECTOR_FLOAT:
                    values = np.asarray(data.getVectorFloat(), dtype=np.float32)
                else:
                    values = np.asarray(data.getVectorInt(), dtype=np.int32)
                # OCIO declares arrays at their maximum size; the getter returns the used part.
                length = max(getattr(uniform, "array_length", 1), values.size)
                padded = np.zeros(length, dtype=values.dtype)
                padded[: values.size] = values
                uniform.write(padded.tobytes())
            else:
                raise ValueError(f"uniform {name!r} has unsupported type {kind}")

    def _upload_luts(self, texture_dtype):
        import moderngl
        import PyOpenColorIO as ocio

        if texture_dtype in self._luts:
            return self._luts[texture_dtype]
        textures = []
        unit = 1  # unit 0 is the input image

        def bind(texture, sampler, interpolation):
            nonlocal unit
            nearest = interpolation == ocio.INTERP_NEAREST
            mode = moderngl.NEAREST if nearest else moderngl.LINEAR
            texture.filter = (mode, mode)
            texture.repeat_x = texture.repeat_y = False  # clamp to edge
            if hasattr(texture, "repeat_z"):
                texture.repeat_z = False
            textures.append((texture, unit, sampler))
            unit += 1

        for lut in self.shader_desc.get3DTextures():
            n = lut.edgeLen
            data = _texture_bytes(lut.getValues(), texture_dtype)
            tex = self.ctx.texture3d((n, n, n), 3, data, dtype=texture_dtype)
            bind(tex, lut.samplerName, lut.interpolation)

        for lut in self.shader_desc.getTextures():
            if lut.dimensions != ocio.GpuShaderDesc.TEXTURE_2D:
                raise NotImplementedError(
                    f"{lut.textureName}: 1D textures are not supported by moderngl"
                )
            channels = 1 if lut.channel == ocio.GpuShaderDesc.TEXTURE_RED_CHANNEL else 3
            width, height = lut.width, max(lut.height, 1)
            data = _texture_bytes(lut.getValues(), texture_dtype)
            tex = self.ctx.texture((width, height), channels, data, dtype=texture_dtype)
            bind(tex, lut.samplerName, lut.interpolation)

        self._luts[texture_dtype] = textures
        return textures

    # -- evaluation --------------------------------------------------------------------------

    def apply(self, pixels, *, texture_dtype="f4"):
        """Evaluate the shader on RGB pixels.

        Parameters
        ----------
        pixels : array_like, shape (..., 3)
            Input RGB values; cast to float32 (non-finite values pass through).
        texture_dtype : {"f4", "f2"}
            LUT texture upload format: float32 or half float.

        Returns
        -------
        numpy.ndarray, shape (N, 3), float32
            ``OCIOMain`` of every pixel, read back from a float32 framebuffer.
        """
        if texture_dtype not in ("f4", "f2"):
            raise ValueError(f"texture_dtype must be 'f4' or 'f2', not {texture_dtype!r}")
        textures = self._upload_luts(texture_dtype)

        def bind():
            for texture, unit, sampler in textures:
                texture.use(location=unit)
                if sampler in self.program:
                    self.program[sampler].value = unit

        return render_pixels(self.ctx, self.program, self._vao, pixels, _INPUT_SAMPLER, bind)

    def release(self):
        """Free the program and its textures."""
        for textures in self._luts.values():
            for texture, _unit, _sampler in textures:
                texture.release()
        self._luts.clear()
        self._vao.release()
        self.program.release()


def render_pixels(ctx, program, vao, pixels, sampler, bind=None):
    """Draw ``program`` once over a float32 image of the pixels and read it back.

    The pixels (RGB, any shape ``(..., 3)``, cast to float32, non-finite values kept)
    are laid out in rows of at most 256 as an RGBA32F texture on unit 0, bound to the
    uniform ``sampler``; ``bind()`` binds whatever else the program reads; the program
    draws one full-viewport triangle (``vao``) into a float32 framebuffer.

    Returns
    -------
    numpy.ndarray, shape (N, 3), float32
    """
    rgb = np.asarray(pixels, dtype=np.float32).reshape(-1, 3)
    n = rgb.shape[0]
    if n == 0:
        return np.zeros((0, 3), np.float32)
    width = min(n, _ROW)
    height = -(-n // width)
    rgba = np.zeros((height * width, 4), np.float32)
    rgba[:n, :3] = rgb
    rgba[:, 3] = 1.0
    src = ctx.texture((width, height), 4, rgba.tobytes(), dtype="f4")
    src.filter = (ctx.NEAREST, ctx.NEAREST)
    dst = ctx.texture((width, height), 4, dtype="f4")
    fbo = ctx.framebuffer(color_attachments=[dst])
    try:
        src.use(location=0)
        if sampler in program:
            program[sampler].value = 0
        if bind is not None:
            bind()
        fbo.use()
        fbo.viewport = (0, 0, width, height)
        vao.render(mode=ctx.TRIANGLES, vertices=3)
        out = np.frombuffer(fbo.read(components=4, dtype="f4"), dtype=np.float32)
    finally:
        fbo.release()
        dst.release()
        src.release()
    return out.reshape(-1, 4)[:n, :3].copy()


def apply_gpu(processor, pixels, *, texture_dtype="f4", language=None, ctx=None):
    """Apply an OCIO processor to pixels with its generated GLSL.

    Parameters
    ----------
    processor : PyOpenColorIO.Processor
        The transform (``config.getProcessor(...)``).
    pixels : array_like, shape (..., 3)
        Input RGB values.
    texture_dtype : {"f4", "f2"}
        LUT textures uploaded as float32 or as half float (what Blender's
        viewport does).
    language : PyOpenColorIO.GpuLanguage, optional
        GLSL dialect; ``GPU_LANGUAGE_GLSL_4_0`` by default.
    ctx : moderngl.Context, optional
        GL context; :func:`default_context` by default.

    Returns
    -------
    numpy.ndarray, shape (N, 3), float32

    Raises
    ------
    RuntimeError
        When no GL context can be created (see :func:`gl_context`).
    """
    program = GpuProgram(processor, ctx=ctx, language=language)
    try:
        return program.apply(pixels, texture_dtype=texture_dtype)
    finally:
        program.release()
