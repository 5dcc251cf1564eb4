"""Running the exported shaders where no host is installed, and the truth they are held to.

- :func:`analytic_view` -- the double-precision view: the input decoded with
  colour-science's own function of its log curve (evaluation/truth.py names it) and the
  package's colorimetry matrices, components limited to
  +-1e6 as the config does, the analytic map (``colour.clip.clip_XYZ``,
  ``colour.compress.compress_XYZ``) in the display's gamut (for HDR scaled into its
  volume, HLG in scene light through the BT.2100 OOTF written out here), and the display
  encoding by colour-science's transfer functions.
- :class:`GlslView` -- the exported GLSL on the headless Mesa context of
  :mod:`evaluation.gpu`, as GLSL 3.30 or GLSL ES 3.00, float32 in and out.
- :class:`DctlView` -- the exported DCTL compiled as C++ against ``dctl/dctl_host.h``
  (DCTL's built-ins on ``<cmath>`` in single precision) and run over float32 pixels.
- :func:`analytic_inverse_view` -- the view's inverse (code values -> the input space)
  in double precision, the compression's preimage by ``compress_RGB_inverse``.
- :func:`source_values` -- CIE-XYZ-D65 test colours as values of an input space.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import numpy.typing as npt

from evaluation.truth import log_decoding, log_encoding
from evaluation.views import decode_display, encode_display
from ocio_thinfilm import registry
from ocio_thinfilm.colour import colorimetry, compress
from ocio_thinfilm.colour.views import analytic_map
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.view_transforms import HLG_GAMMA

__all__ = [
    "LIMIT",
    "log_encoding",
    "log_decoding",
    "PEAK",
    "WHITE",
    "analytic_display_XYZ",
    "analytic_view",
    "analytic_inverse_view",
    "source_values",
    "GlslView",
    "DctlView",
    "compiler",
    "count_operations",
    "OPERATIONS",
]

#: The config's limit of every component (+-1e6; NaN and -Inf to the lowest).
LIMIT = ocio_ops.LIMIT
#: The HDR displays' reference white and peak, cd/m2 (ITU-R BT.2408; the registry's).
WHITE = registry.HDR_REFERENCE_WHITE
PEAK = 1000.0


#: The config's sRGB-encoded texture space (sRGB curve, Rec.709 primaries).
TEXTURE = registry.TEXTURE_SPACE

_HERE = Path(__file__).resolve().parent / "dctl"


def _limited(values):
    """Components limited to [-LIMIT, LIMIT], NaN to -LIMIT (OCIO's Range)."""
    v = np.asarray(values, dtype=np.float64)
    return np.clip(np.where(np.isnan(v), -LIMIT, v), -LIMIT, LIMIT)


def _to_XYZ(values, source):
    """An input space's values -> CIE-XYZ-D65, limited per stage as the config's spaces."""
    import colour

    if source == registry.REFERENCE:
        return _limited(values)
    v = np.asarray(values, dtype=np.float64)
    if source == TEXTURE:  # sRGB-encoded Rec.709, decoded by colour-science
        with np.errstate(invalid="ignore", over="ignore"):
            rgb = _limited(colour.cctf_decoding(v, function="sRGB"))
        return _limited(colorimetry.RGB_to_XYZ(rgb, "Rec.709"))
    space = registry.linear_space_of(source)
    assert space is not None, source
    encoded = registry.find_encoded(source)
    if encoded is not None:  # decoded by colour-science's function of the curve
        lo, hi = log_encoding([-LIMIT, LIMIT], encoded.curve)
        v = log_decoding(np.clip(np.where(np.isnan(v), lo, v), lo, hi), encoded.curve)
    rgb = _limited(v)
    return _limited(colorimetry.RGB_to_XYZ(rgb, space.colorimetry))


def _hlg_scene_light(XYZ):
    """HLG display light (XYZ, Y = 1 at 203 cd/m2) -> scene light E (the BT.2100 inverse
    OOTF, Table 5, L_B = 0): E = F_D / (L_W Y_S ** (gamma - 1)), Y_S = (Y_D / L_W) **
    (1 / gamma)."""
    Yd = np.maximum(XYZ[:, 1], 0.0) * WHITE
    with np.errstate(all="ignore"):
        to_scene = np.where(Yd > 0, (Yd / PEAK) ** (1.0 / HLG_GAMMA - 1.0) / PEAK, 0.0)
    return XYZ * WHITE * to_scene[:, None]


def analytic_display_XYZ(
    XYZ: npt.ArrayLike,
    display: str,
    view: str,
    threshold: float = compress.THRESHOLD,
    limit: float = compress.LIMIT,
) -> np.ndarray:
    """The analytic view of limited CIE-XYZ-D65 as display light, XYZ with Y = 1 the
    reference white (an HDR display's volume reaches peak / 203).

    PQ: ``k map(X / k)``, k = peak / 203. HLG (ITU-R BT.2100, Table 5, L_B = 0):
    display light F_D = L_W Y_S ** (gamma - 1) E, so a pixel of display luminance Y_D
    has scene light E = F_D / (L_W Y_S ** (gamma - 1)), Y_S = (Y_D / L_W) ** (1 /
    gamma); the map works on E (the signal's volume is the gamut's parallelepiped)."""
    entry = registry.as_display(display)
    gamut = entry.gamut.name
    form = analytic_map(view)
    assert form is not None, view

    def mapping(x):
        return form.xyz(x, gamut, threshold, limit)

    XYZ = np.asarray(XYZ, dtype=np.float64).reshape(-1, 3)
    if not entry.hdr:
        return mapping(XYZ)
    if entry.transfer == "PQ":
        k = entry.peak / WHITE
        return k * mapping(XYZ / k)
    E = mapping(_hlg_scene_light(XYZ))
    return E * (PEAK * np.maximum(E[:, 1:2], 0.0) ** (HLG_GAMMA - 1.0)) / WHITE


def analytic_view(
    values: npt.ArrayLike,
    source: str,
    display: str,
    view: str,
    threshold: float = compress.THRESHOLD,
    limit: float = compress.LIMIT,
) -> np.ndarray:
    """The view's code values in double precision, (N, 3) float64 (the module's truth)."""
    import colour

    entry = registry.as_display(display)
    gamut = entry.gamut.name
    XYZ = _to_XYZ(np.asarray(values, dtype=np.float64).reshape(-1, 3), source)
    if entry.hdr and entry.transfer == "HLG":
        # the code is the OETF of the mapped scene light (the OOTF and its inverse cancel)
        E = analytic_display_XYZ(_hlg_scene_light(XYZ), gamut, view, threshold, limit)
        rgb = np.clip(colorimetry.XYZ_to_RGB(E, gamut), 0.0, 1.0)
        return colour.models.oetf_BT2100_HLG(rgb)
    light = analytic_display_XYZ(XYZ, display, view, threshold, limit)
    rgb = np.clip(colorimetry.XYZ_to_RGB(light, gamut), 0.0, entry.scale)
    if entry.hdr:
        return colour.models.eotf_inverse_ST2084(rgb * WHITE)
    return encode_display(rgb, display)


def analytic_inverse_view(
    codes: npt.ArrayLike,
    source: str,
    display: str,
    view: str,
    threshold: float = compress.THRESHOLD,
    limit: float = compress.LIMIT,
) -> np.ndarray:
    """The view's inverse in double precision: code values (limited to [0, 1]) ->
    values of ``source`` (N, 3), decoded by colour-science, the map's preimage by
    ``colour.compress.compress_RGB_inverse`` (the clip's: the colour itself)."""
    import colour

    entry = registry.as_display(display)
    gamut = entry.gamut.name
    code = np.clip(np.nan_to_num(np.asarray(codes, dtype=np.float64).reshape(-1, 3)), 0.0, 1.0)
    if not entry.hdr:
        rgb = decode_display(code, display)
    elif entry.transfer == "PQ":
        rgb = colour.models.eotf_ST2084(code) / WHITE / (entry.peak / WHITE)
    else:
        rgb = colour.models.oetf_inverse_BT2100_HLG(code)
    rgb = np.clip(rgb, 0.0, 1.0)
    if registry.as_view(view).kind == "compress":  # the clip's preimage is the colour itself
        rgb = compress.compress_RGB_inverse(rgb, gamut, threshold, limit)
    XYZ = colorimetry.RGB_to_XYZ(rgb, gamut)
    if entry.hdr and entry.transfer == "PQ":
        XYZ = XYZ * entry.peak / WHITE
    elif entry.hdr:  # the BT.2100 OOTF, L_B = 0
        XYZ = XYZ * (PEAK * np.maximum(XYZ[:, 1:2], 0.0) ** (HLG_GAMMA - 1.0)) / WHITE
    return source_values(XYZ, source)


def source_values(XYZ: npt.ArrayLike, source: str) -> np.ndarray:
    """CIE-XYZ-D65 -> values of the input space ``source`` (float64, (N, 3)); a log
    space encoded by colour-science's function of its curve."""
    import colour

    XYZ = np.asarray(XYZ, dtype=np.float64).reshape(-1, 3)
    if source == registry.REFERENCE:
        return XYZ
    if source == TEXTURE:
        return colour.cctf_encoding(colorimetry.XYZ_to_RGB(XYZ, "Rec.709"), function="sRGB")
    space = registry.linear_space_of(source)
    assert space is not None, source
    rgb = colorimetry.XYZ_to_RGB(XYZ, space.colorimetry)
    encoded = registry.find_encoded(source)
    return rgb if encoded is None else log_encoding(rgb, encoded.curve)


# --------------------------------------------------------------------------- #
# GLSL on Mesa
# --------------------------------------------------------------------------- #
_VERSIONS = {
    "330": ("#version 330 core", ""),
    "es300": (
        "#version 300 es",
        "precision highp float;\nprecision highp int;\nprecision highp sampler2D;",
    ),
}

_FRAGMENT = """{version}
{precision}
uniform sampler2D thinfilm_input;
out vec4 thinfilm_output;
{shader}
void main()
{{
    vec3 rgb = texelFetch(thinfilm_input, ivec2(gl_FragCoord.xy), 0).rgb;
    thinfilm_output = vec4({function}(rgb), 1.0);
}}
"""

_VERTEX = """{version}
void main()
{{
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}}
"""


class GlslView:
    """An exported GLSL view compiled on the headless context (:mod:`evaluation.gpu`).

    ``version``: ``"330"`` (GLSL 3.30 core) or ``"es300"`` (GLSL ES 3.00 with
    ``precision highp float``); ``function``: the function run on each pixel
    (``ocio_thinfilm_view`` or ``ocio_thinfilm_view_inverse``). Raises RuntimeError
    without a context, and moderngl's error (the compiler's log) for code that does not
    compile.
    """

    def __init__(
        self, shader: str, version: str = "330", ctx=None, function: str = "ocio_thinfilm_view"
    ):
        from evaluation import gpu

        self.ctx = gpu.default_context() if ctx is None else ctx
        head, precision = _VERSIONS[version]
        self.fragment = _FRAGMENT.format(
            version=head, precision=precision, shader=shader, function=function
        )
        self.program = self.ctx.program(
            vertex_shader=_VERTEX.format(version=head), fragment_shader=self.fragment
        )
        self._vao = self.ctx.vertex_array(self.program, [])

    def apply(self, pixels: npt.ArrayLike, threshold=None, limit=None) -> np.ndarray:
        """Run the view on float32 pixels; (N, 3) float32.

        The knobs' uniforms are set to ``threshold`` and ``limit``, or to 0 (unset, as a
        host that does not know them leaves them) when None."""
        for name, value in (("ocio_thinfilm_threshold", threshold), ("ocio_thinfilm_limit", limit)):
            if name in self.program:
                self.program[name].value = 0.0 if value is None else float(value)
        from evaluation.gpu import render_pixels

        return render_pixels(self.ctx, self.program, self._vao, pixels, "thinfilm_input")

    def release(self) -> None:
        self._vao.release()
        self.program.release()


# --------------------------------------------------------------------------- #
# DCTL as C++
# --------------------------------------------------------------------------- #
def compiler() -> str | None:
    """The C++ compiler to build DCTLs with (``$CXX``, else g++ or c++), or None."""
    for name in (os.environ.get("CXX"), "g++", "c++"):
        if name and shutil.which(name):
            return name
    return None


class DctlView:
    """An exported DCTL compiled as C++ (``dctl/dctl_host.h``) into a runner program.

    ``flags``: the compiler's optimisation flags (the tests use ``-O2``: IEEE single
    precision, no fast-math). ``directory``: where to build (a temporary one by default).
    """

    def __init__(self, dctl: str, flags=("-O2",), directory: str | os.PathLike | None = None):
        cxx = compiler()
        if cxx is None:
            raise RuntimeError("no C++ compiler (g++) found")
        self._tmp = None if directory is not None else tempfile.TemporaryDirectory()
        work = Path(directory if directory is not None else self._tmp.name)
        source = work / "view.dctl"
        source.write_text(dctl)
        self.binary = work / "dctl_runner"
        self.knobs = "DCTLUI_SLIDER_FLOAT" in dctl
        cmd = [
            cxx,
            "-std=c++17",
            *flags,
            "-Wall",
            "-Werror",
            "-Wno-unused-parameter",
            "-Wno-unused-variable",
            f"-I{_HERE}",
            f'-DDCTL_FILE="{source}"',
            *(["-DDCTL_KNOBS"] if self.knobs else []),
            str(_HERE / "dctl_runner.cpp"),
            "-o",
            str(self.binary),
        ]
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"the DCTL does not compile as C++:\n{done.stderr}")

    def sliders(self) -> dict:
        """{label: (default, min, max, step)} of the DCTL's DEFINE_UI_PARAMS sliders."""
        if not self.knobs:
            return {}
        out = subprocess.run(
            [str(self.binary), "sliders"], capture_output=True, text=True, check=True
        )
        rows = [line.split() for line in out.stdout.splitlines()]
        return {r[0]: tuple(float(v) for v in r[1:]) for r in rows}

    def apply(
        self, pixels: npt.ArrayLike, threshold=None, limit=None, invert: bool = False
    ) -> np.ndarray:
        """Run ``transform`` on float32 pixels (knobs set when given, the ``Invert`` check
        box when ``invert``); (N, 3) float32."""
        rgb = np.ascontiguousarray(np.asarray(pixels, dtype=np.float32).reshape(-1, 3))
        args = [str(self.binary), str(len(rgb)), f"invert={int(bool(invert))}"]
        if threshold is not None:
            args.append(f"threshold={float(threshold)!r}")
        if limit is not None:
            args.append(f"limit={float(limit)!r}")
        done = subprocess.run(args, input=rgb.tobytes(), capture_output=True, check=True)
        return np.frombuffer(done.stdout, dtype=np.float32).reshape(-1, 3).copy()

    def time(self, pixels: npt.ArrayLike, repeats: int = 5) -> float:
        """Seconds of the fastest of ``repeats`` passes of ``transform`` over the pixels
        (default knobs; timed inside the program, without reading or writing them)."""
        rgb = np.ascontiguousarray(np.asarray(pixels, dtype=np.float32).reshape(-1, 3))
        args = [str(self.binary), "time", str(len(rgb)), str(int(repeats))]
        done = subprocess.run(args, input=rgb.tobytes(), capture_output=True, check=True)
        return float(done.stdout.split()[0])

    def release(self) -> None:
        if self._tmp is not None:
            self._tmp.cleanup()


#: The columns :func:`count_operations` returns, per pixel.
OPERATIONS = ("add", "multiply", "divide", "compare", "min/max", "transcendental")


def count_operations(dctl: str, pixels: npt.ArrayLike) -> dict:
    """Mean float operations per pixel of a transform DCTL over ``pixels``.

    The DCTL is compiled with ``float`` as a counting type (``dctl/dctl_count.h``):
    adds and subtractions, multiplies, divides, comparisons, min/max (a clamp counts 2)
    and transcendental calls (pow, exp2, log, sqrt), averaged over the pixels (the map
    branches: colours inside the threshold take the short way).
    """
    cxx = compiler()
    if cxx is None:
        raise RuntimeError("no C++ compiler (g++) found")
    rgb = np.ascontiguousarray(np.asarray(pixels, dtype=np.float32).reshape(-1, 3))
    with tempfile.TemporaryDirectory() as work:
        source = Path(work) / "view.dctl"
        source.write_text(dctl)
        binary = Path(work) / "dctl_count"
        cmd = [
            cxx,
            "-std=c++17",
            "-O1",
            f"-I{_HERE}",
            f'-DDCTL_FILE="{source}"',
            str(_HERE / "dctl_count.cpp"),
            "-o",
            str(binary),
        ]
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"the counting build failed:\n{done.stderr}")
        out = subprocess.run(
            [str(binary), str(len(rgb))], input=rgb.tobytes(), capture_output=True, check=True
        )
    return dict(zip(OPERATIONS, (float(v) for v in out.stdout.split()), strict=True))
