"""OpenColorIO's GLSL for every view of the baked config against the CPU path.

The shader OCIO generates for each (input space, display, view) is run on Mesa's
software renderer (headless EGL through moderngl, :mod:`evaluation.gpu`), with
the LUT textures uploaded as float32 (``f4``) and as half float (``f2``, what
Blender's viewport uploads: ``RGB16F``, 11 significant bits).  Requirements:

* finite input never gives NaN or +-Inf on the GPU (any magnitude, up to float32 max);
* for inputs of moderate magnitude (every component in [-20, 100] in the input
  space's own encoding) the GPU output is within 2/255 of the CPU output on display
  code values.

The whole module skips, with the reason, when moderngl is missing or no GL context
can be created.  The harness itself is validated first on analytic transforms
(matrix, 3D and 1D LUTs of known functions, uniforms), independently of the config.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import pytest

from evaluation.views import COMMITTED_CONFIG

ocio = pytest.importorskip("PyOpenColorIO")

TOL = 2.0 / 255.0
#: Where the 2/255 target is missed: the bound reached (the test xfails above 2/255).
#: Rec.2020's BT.1886 encoding (a pure 2.4 power) turns a linear 1e-5 near black into
#: 2/255: one extreme input of the compression (sRGB - Texture code (1.19, -2.68, 1.00),
#: beyond the limit, so clipped onto G = 0) reaches 2.10/255 with half-float textures:
#: the CPU puts G at 0 exactly, the GPU 1e-5 above (in a one-off try, rounding the shaper
#: to half floats on the CPU too does not remove it, so it is not the shaper alone).
#: On the PQ displays ST 2084 is steeper still near black (code 0.013 for 0.004 cd/m2):
#: a channel on a gamut face that the CPU puts at 0 and the GPU's half-float textures
#: (the clip's black pass, the compression's squeezes) leave 1e-5 of white (4e-6 of the
#: peak) above it reaches 2.29/255 (P3-D65 PQ clip), 3.10/255 (P3-D65 PQ compression)
#: and 2.37/255 (Rec.2100-PQ compression), 0.002-0.004 cd/m2 of light.
#: All four come from the 3D LUTs' 16-bit codes, which lie up to 7.6e-6 from the half
#: floats the texture holds (no code but 0 and 1 is a half float): a CPU processor with
#: the 3D LUT values rounded to half floats gives the GPU's result to 0.2-0.45/255
#: (measured once). Half-float LUT files (CLF 16f) would meet 2/255 at twice the text
#: (the black pass 9.9 MB per display instead of 4.9 MB: the config past the 39 MB that
#: tests/test_export.py allows; docs/hdr.md).
#: The other pure powers do the same: Rec.1886 Rec.709's clip (2.4, 3.29/255 from
#: Linear Rec.709 and sRGB - Texture), P3-DCI's clip (2.6, 2.24/255 from a thin film)
#: and compression (3.14/255 from ACEScg).
REACHED = {
    ("Rec.2020", "Constant-Lightness Compress", "f2"): 2.2 / 255.0,
    ("Rec.1886 Rec.709", "Constant-Lightness Clip", "f2"): 3.35 / 255.0,
    ("P3-DCI", "Constant-Lightness Clip", "f2"): 2.3 / 255.0,
    ("P3-DCI", "Constant-Lightness Compress", "f2"): 3.2 / 255.0,
    ("P3-D65 PQ", "Constant-Lightness Clip", "f2"): 2.35 / 255.0,
    ("P3-D65 PQ", "Constant-Lightness Compress", "f2"): 3.4 / 255.0,
    ("Rec.2100-PQ", "Constant-Lightness Compress", "f2"): 2.4 / 255.0,
}
MODERATE = (-20.0, 100.0)
SOURCES = [
    "CIE-XYZ-D65",
    "Linear Rec.709 (sRGB)",
    "ACEScg",
    "ACEScct",
    "sRGB - Texture",
    "Thin Film Phase-Change Thickness",
    "Thin Film No-Phase-Change Thickness",
    "Thin Film Morpho Iridescence",
]
THIN_FILM = {s for s in SOURCES if s.startswith("Thin Film")}
DTYPES = ("f4", "f2")
F32_MAX = float(np.finfo(np.float32).max)
PRECISE = ocio.OptimizationFlags(
    int(ocio.OPTIMIZATION_DEFAULT) & ~int(ocio.OPTIMIZATION_FAST_LOG_EXP_POW)
)


@pytest.fixture(scope="module")
def gl():
    """The module's GL context (shared by every test); skip with the reason without one."""
    try:
        import moderngl  # noqa: F401
    except ImportError as exc:
        pytest.skip(f"moderngl is not installed ({exc}): pip install moderngl")
    from evaluation import gpu

    try:
        ctx = gpu.gl_context()
    except RuntimeError as exc:
        pytest.skip(f"no OpenGL context: {exc}")
    yield ctx
    ctx.release()


# ---------------------------------------------------------------------------------------------
# The harness on analytic transforms (cannot pass by accident: each expected value is numpy's)
# ---------------------------------------------------------------------------------------------


def _run(gl, transform, x, dtype="f4"):
    from evaluation import gpu

    proc = ocio.Config.CreateRaw().getProcessor(transform)
    prog = gpu.GpuProgram(proc, ctx=gl)
    try:
        return prog, prog.apply(x, texture_dtype=dtype)
    finally:
        prog.release()


def _lut3d(n, f):
    """A Lut3DTransform holding f(r, g, b) on an n^3 lattice, and the lattice values."""
    t = ocio.Lut3DTransform(gridSize=n)
    t.setInterpolation(ocio.INTERP_TETRAHEDRAL)
    grid = np.linspace(0.0, 1.0, n)
    r, g, b = np.meshgrid(grid, grid, grid, indexing="ij")
    values = np.asarray(f(r, g, b), dtype=np.float32)  # (3, n, n, n)
    for i in range(n):
        for j in range(n):
            for k in range(n):
                t.setValue(i, j, k, *map(float, values[:, i, j, k]))
    return t, values


def test_harness_matrix_and_readback_order(gl):
    """A non-symmetric matrix + offset: checks the pixel order of upload/readback too."""
    m = np.array([[0.9, 0.3, -0.2], [-0.1, 1.2, 0.4], [0.25, -0.5, 0.7]])
    off = np.array([0.01, -0.02, 0.5])
    m44 = np.eye(4)
    m44[:3, :3] = m
    t = ocio.MatrixTransform(m44.ravel().tolist(), np.r_[off, 0.0].tolist())
    x = np.random.default_rng(1).uniform(-2, 3, (1000, 3)).astype(np.float32)  # 4 rows of 256
    _, y = _run(gl, t, x)
    np.testing.assert_allclose(y, x @ m.T + off, atol=2e-6)


@pytest.mark.parametrize("dtype", DTYPES)
def test_harness_lut3d(gl, dtype):
    """A 3D LUT of a known non-symmetric function, float32 vs half-float textures.

    At lattice points the tetrahedral interpolation returns the stored value, so the
    GPU must give exactly f (f4) or float16(f) (f2), which also checks the r/g/b
    axis order of the 3D texture.  Between lattice points an affine f is reproduced
    exactly by any interpolation.
    """
    n = 17

    def affine(r, g, b):
        return (0.2 + 0.5 * r + 0.25 * g + 0.05 * b, 0.9 * g - 0.3 * b + 0.1, 0.4 * r + 0.6 * b)

    def curved(r, g, b):
        return (r * r + 0.1 * g, np.sqrt(g) * (1 - 0.5 * b), np.sin(3 * b) + 0.2 * r)

    grid = np.linspace(0, 1, n)
    r, g, b = (a.ravel() for a in np.meshgrid(grid, grid, grid, indexing="ij"))
    lattice = np.stack([r, g, b], -1).astype(np.float32)

    t, values = _lut3d(n, curved)
    prog, y = _run(gl, t, lattice, dtype)
    assert len(list(prog.shader_desc.get3DTextures())) == 1
    want = values.reshape(3, -1).T
    if dtype == "f2":
        want16 = want.astype(np.float16).astype(np.float32)
        assert np.abs(want16 - want).max() > 1e-5  # the rounding is visible, so the check bites
        np.testing.assert_allclose(y, want16, atol=1e-6)
    else:
        np.testing.assert_allclose(y, want, atol=1e-6)

    t, _ = _lut3d(n, affine)
    x = np.random.default_rng(2).uniform(0, 1, (2000, 3)).astype(np.float32)
    _, y = _run(gl, t, x, dtype)
    exact = np.stack(affine(*x.T), -1)
    err = np.abs(y - exact).max()
    if dtype == "f4":
        assert err < 2e-6
    else:  # half-float lattice values: error of the order of their rounding, no more
        assert 1e-5 < err <= 2.0**-11


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("size,mono", [(1024, True), (1024, False), (20000, False)])
def test_harness_lut1d(gl, dtype, size, mono):
    """1D LUTs: RED (mono) and RGB textures, short (one row) and wide (several rows)."""
    t = ocio.Lut1DTransform(length=size)
    x_grid = np.linspace(0, 1, size)
    if mono:
        vals = np.stack([x_grid**2] * 3, -1)
    else:
        vals = np.stack([x_grid**2, 1 - x_grid, np.sqrt(x_grid)], -1)
    t.setData(vals.astype(np.float32).ravel())
    x = np.random.default_rng(3).uniform(0, 1, (3000, 3)).astype(np.float32)
    prog, y = _run(gl, t, x, dtype)
    (tex,) = list(prog.shader_desc.getTextures())
    desc = ocio.GpuShaderDesc
    channel = desc.TEXTURE_RED_CHANNEL if mono else desc.TEXTURE_RGB_CHANNEL
    assert tex.channel == channel
    assert (tex.height > 1) == (size > prog.shader_desc.getTextureMaxWidth())
    stored = vals.astype(np.float32)
    if dtype == "f2":
        rounded = stored.astype(np.float16).astype(np.float32)
        assert np.abs(rounded - stored).max() > 1e-5  # the rounding is visible, so the check bites
        stored = rounded
    want = np.stack([np.interp(x[:, c], x_grid, stored[:, c]) for c in range(3)], -1)
    np.testing.assert_allclose(y, want, atol=1e-5)
    if not mono:  # and the channels are not mixed up: 1 - g is far from g^2 and sqrt(g)
        assert np.abs(y[:, 1] - (1 - x[:, 1])).max() < 1e-3


def test_harness_uniforms(gl):
    """Dynamic transforms put their parameters in uniforms (double, float3, bool, vectors)."""
    gp = ocio.GradingPrimary(ocio.GRADING_LOG)
    gp.saturation = 1.4
    gp.contrast = ocio.GradingRGBM(1.1, 1.0, 0.9, 1.2)
    gp.brightness = ocio.GradingRGBM(0.02, -0.03, 0.01, 0.05)
    curve = ocio.GradingRGBCurve(ocio.GRADING_LOG)
    curve.red = ocio.GradingBSplineCurve([0, 0, 0.3, 0.45, 0.7, 0.6, 1, 1])
    curve.blue = ocio.GradingBSplineCurve([0, 0.05, 0.5, 0.4, 1, 0.95])
    transforms = [
        ocio.ExposureContrastTransform(
            exposure=1.5, contrast=1.2, pivot=0.18, dynamicExposure=True, dynamicContrast=True
        ),
        ocio.GradingPrimaryTransform(gp, ocio.GRADING_LOG, dynamic=True),
        ocio.GradingRGBCurveTransform(curve, ocio.GRADING_LOG, dynamic=True),
    ]
    kinds = set()
    x = np.random.default_rng(4).uniform(0.01, 1, (1500, 3)).astype(np.float32)
    for t in transforms:
        proc = ocio.Config.CreateRaw().getProcessor(t)
        cpu = x.copy()
        proc.getDefaultCPUProcessor().applyRGB(cpu)
        prog, y = _run(gl, t, x)
        kinds |= {u.type for _, u in prog.shader_desc.getUniforms()}
        assert np.abs(cpu - x).max() > 0.1  # the transform does something
        np.testing.assert_allclose(y, cpu, atol=1e-4)
    assert kinds >= {
        ocio.UNIFORM_DOUBLE,
        ocio.UNIFORM_FLOAT3,
        ocio.UNIFORM_BOOL,
        ocio.UNIFORM_VECTOR_FLOAT,
        ocio.UNIFORM_VECTOR_INT,
    }


# ---------------------------------------------------------------------------------------------
# The baked config
# ---------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def config():
    if not COMMITTED_CONFIG.exists():
        pytest.skip(f"{COMMITTED_CONFIG} not built")
    return ocio.Config.CreateFromFile(str(COMMITTED_CONFIG))


def _views():
    cfg = ocio.Config.CreateFromFile(str(COMMITTED_CONFIG))
    return [(d, v) for d in cfg.getDisplays() for v in cfg.getViews(d)]


try:
    VIEWS = _views()
except Exception:  # config missing or unreadable: the config fixture skips
    VIEWS = [("sRGB", "Raw")]


def _extremes():
    """Every combination of negative, above-white and huge values up to float32 max."""
    v = np.array(
        [-F32_MAX, -1e30, -1e4, -100, -20, -1, 0, 0.5, 1, 20, 100, 1e4, 1e30, F32_MAX],
        dtype=np.float32,
    )
    return np.stack(np.meshgrid(v, v, v, indexing="ij"), -1).reshape(-1, 3)


def _inputs(cfg, src):
    """Test pixels in ``src``'s own encoding (float32, (N, 3))."""
    parts = []
    if src in THIN_FILM:
        # Pixel value = optical thickness in um (Morpho: cos(theta)); XYZ cannot be
        # converted into these spaces.  Grey sweeps through the whole colourful range
        # (these are the saturated colours), plus independent channels (the Lut1D
        # applies per channel).
        top = 1.2 if "Morpho" in src else 110.0
        sweep = np.r_[np.linspace(-0.2, top, 2500), np.geomspace(1e-3, top, 500)]
        parts.append(np.repeat(sweep[:, None], 3, 1))
        parts.append(np.random.default_rng(5).uniform(-0.1, top, (500, 3)))
    else:
        g = np.linspace(-0.25, 1.5, 9)
        parts.append(np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3))
        # XYZ: a grid (in-gamut and imaginary colours) and monochromatic stimuli
        # 380-700 nm at four luminances, converted into src on the CPU.
        from ocio_thinfilm.colour.colorimetry import spectral_locus_XYZ

        gx = np.linspace(0.0, 1.2, 6)
        xyz = [np.stack(np.meshgrid(gx, gx, gx, indexing="ij"), -1).reshape(-1, 3)]
        xyz += [spectral_locus_XYZ(Y) for Y in (0.02, 0.1, 0.3, 0.6)]
        xyz = np.concatenate(xyz).astype(np.float32)
        cfg.getProcessor("CIE-XYZ-D65", src).getDefaultCPUProcessor().applyRGB(xyz)
        parts.append(xyz)
    parts.append(_extremes())
    return np.concatenate([np.asarray(p, np.float32) for p in parts])


def _within(a):
    return np.all((a >= MODERATE[0]) & (a <= MODERATE[1]), axis=1)


def _moderate(cfg, src, x):
    """Pixels of moderate magnitude: every component in MODERATE both as encoded in
    ``src`` and as scene-linear CIE XYZ (ACEScct codes above ~7.9 overflow float32)."""
    xyz = x.copy()
    cfg.getProcessor(src, "CIE-XYZ-D65").getDefaultCPUProcessor().applyRGB(xyz)
    with np.errstate(invalid="ignore"):
        return _within(x) & _within(xyz)


@dataclass
class Case:
    x: np.ndarray  # inputs (N, 3)
    moderate: np.ndarray  # (N,) bool
    cpu: np.ndarray  # getDefaultCPUProcessor()
    precise: np.ndarray  # getOptimizedCPUProcessor(PRECISE)
    gpu: dict  # texture dtype -> (N, 3)


def _diffs(case, dtype):
    """(max |GPU - default CPU|, max over pixels of |GPU - nearer CPU path|) on moderate pixels.

    The nearer of OCIO's default CPU processor and the one without fast log/exp/pow:
    the default's pow approximation alone moves some near-black Rec.1886 codes by >2/255.
    """
    m = case.moderate
    if not m.any():
        return 0.0, 0.0
    g = case.gpu[dtype][m]
    d_default = np.abs(g - case.cpu[m]).max(axis=1)
    d_precise = np.abs(g - case.precise[m]).max(axis=1)
    return float(d_default.max()), float(np.minimum(d_default, d_precise).max())


class Results:
    """CPU and GPU outputs per (display, view, source), computed once per module."""

    def __init__(self, ctx, cfg):
        self.ctx, self.cfg = ctx, cfg
        self.inputs = {}
        self.moderate = {}
        self.cache = {}
        self.seconds = 0.0

    def get(self, display, view, src):
        key = (display, view, src)
        if key not in self.cache:
            from evaluation import gpu

            t0 = time.perf_counter()
            if src not in self.inputs:
                self.inputs[src] = x = _inputs(self.cfg, src)
                self.moderate[src] = _moderate(self.cfg, src, x)
            x = self.inputs[src]
            proc = self.cfg.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD)
            cpu = x.copy()
            proc.getDefaultCPUProcessor().applyRGB(cpu)
            # OCIO's default CPU processor uses fast approximations of log/exp/pow
            # (OPTIMIZATION_FAST_LOG_EXP_POW, ~1e-5 relative); the GLSL uses the GPU's own.
            precise = x.copy()
            proc.getOptimizedCPUProcessor(PRECISE).applyRGB(precise)
            prog = gpu.GpuProgram(proc, ctx=self.ctx)
            try:
                out = {dt: prog.apply(x, texture_dtype=dt) for dt in DTYPES}
            finally:
                prog.release()
            self.cache[key] = Case(x, self.moderate[src], cpu, precise, out)
            self.seconds += time.perf_counter() - t0
        return self.cache[key]


@pytest.fixture(scope="module")
def results(gl, config, request):
    res = Results(gl, config)
    yield res
    # Report the max |GPU - CPU| per view and texture type (code values /255).
    lines = [
        "",
        "GPU vs CPU, max |diff| in /255 code values (vs nearer CPU path, asserted <= 2; "
        f"vs default CPU), inputs within {MODERATE}; {res.seconds:.1f} s of GPU+CPU work:",
    ]
    for display, view in VIEWS:
        cells = []
        for dt in DTYPES:
            worst = [(0.0, 0.0, "")]
            for src in SOURCES:
                if (display, view, src) in res.cache:
                    worst.append((*_diffs(res.cache[(display, view, src)], dt), src))
            d_default = max(w[0] for w in worst)
            d_asserted, where = max((w[1], w[2]) for w in worst)
            cells.append(
                f"{dt} {d_asserted * 255:7.3f} (default CPU {d_default * 255:7.3f})"
                + (f" worst: {where}" if d_asserted > TOL else "")
            )
        lines.append(f"  {display:10s} {view:24s} " + "   ".join(cells))
    capture = request.config.pluginmanager.getplugin("capturemanager")
    if capture is not None:  # show the table without -s
        with capture.global_and_fixture_disabled():
            print("\n".join(lines))
    else:
        print("\n".join(lines))


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("display,view", VIEWS)
def test_gpu_finite(results, display, view, dtype):
    """No NaN/Inf on the GPU from finite input, up to float32 max, any texture type."""
    bad = []
    for src in SOURCES:
        case = results.get(display, view, src)
        x, y = case.x, case.gpu[dtype]
        nonfinite = ~np.isfinite(y).all(axis=1) & np.isfinite(x).all(axis=1)
        if nonfinite.any():
            i = np.flatnonzero(nonfinite)[0]
            bad.append(f"{src}: {nonfinite.sum()} pixels, e.g. {x[i].tolist()} -> {y[i].tolist()}")
    assert not bad, "; ".join(bad)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("display,view", VIEWS)
def test_gpu_matches_cpu(results, display, view, dtype, request):
    """max |GPU - CPU| <= 2/255 on display code values for moderate inputs."""
    worst = {}
    for src in SOURCES:
        d_default, d = _diffs(results.get(display, view, src), dtype)
        worst[src] = d
        print(f"{src}: {d * 255:.3f}/255 (vs default CPU {d_default * 255:.3f})")
    reached = REACHED.get((display, view, dtype))
    over = {s: round(d * 255, 3) for s, d in worst.items() if d > (reached or TOL)}
    assert not over, f"max |GPU - CPU| over {(reached or TOL) * 255:.2f}/255 (in /255): {over}"
    if reached is not None and max(worst.values()) > TOL:
        pytest.xfail(
            f"{display} / {view} with {dtype} textures: "
            f"{max(worst.values()) * 255:.2f}/255 (target 2/255)"
        )


NONFINITE = np.array(
    [
        [np.nan] * 3,
        [np.inf] * 3,
        [-np.inf] * 3,
        [np.nan, 0.5, 0.5],
        [np.inf, 0.5, 0.5],
        [-np.inf, 0.5, 0.5],
        [0.5, np.inf, 0.5],
    ],
    np.float32,
)


@pytest.mark.parametrize("display,view", VIEWS)
def test_gpu_nonfinite_inputs(gl, config, display, view):
    """NaN/+-Inf inputs, every input space: the same result on CPU and GPU.

    Raw passes NaN/+-Inf through unchanged (it is data). Every other view gives finite
    codes, and the GPU (Mesa llvmpipe, OCIO 2.6, f4 and f2 textures) the same codes
    within 2/255 (measured 0.19/255): every input space and every view first limits
    its components to +-1e6 (``ocio_ops.finite_limit_transform`` /
    ``xyz_limit_transform``), where OCIO's Range sends NaN to the lower bound and
    +-Inf to the bounds on both paths. So NaN components count as the lower bound
    (black for an all-NaN pixel), +Inf as 1e6 (white through the clip when Y
    is large); the Thin Film spaces give their table's first entry (black) for NaN.
    """
    from evaluation import gpu

    for src in SOURCES:
        proc = config.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD)
        cpu = NONFINITE.copy()
        proc.getDefaultCPUProcessor().applyRGB(cpu)
        prog = gpu.GpuProgram(proc, ctx=gl)
        try:
            out = {dt: prog.apply(NONFINITE, texture_dtype=dt) for dt in DTYPES}
        finally:
            prog.release()
        same = {dt: bool(np.array_equal(out[dt], cpu, equal_nan=True)) for dt in DTYPES}
        print(
            f"{display} / {view} / {src}: GPU == CPU {same}; CPU {cpu.tolist()}; "
            f"GPU f4 {out['f4'].tolist()}"
        )
        if view == "Raw":
            for y in (cpu, *out.values()):
                np.testing.assert_array_equal(y, NONFINITE)
        else:
            assert np.isfinite(cpu).all(), (src, cpu)
            for dt, y in out.items():
                assert np.abs(y - cpu).max() <= 2 / 255, (src, dt, cpu, y)


def _extreme_xyz():
    """CIE XYZ far outside any gamut: every combination of huge, infinite, NaN and
    ordinary components, and imaginary colours with Y = 0 and a large X or Z."""
    v = np.array(
        [-F32_MAX, -3e38, -1e30, -1e6, -1e4, -1, 0, 1e-6, 0.5, 1, 1e4, 1e6, 1e30, 3e38, F32_MAX]
        + [np.inf, -np.inf, np.nan],
        dtype=np.float32,
    )
    grid = np.stack(np.meshgrid(v, v, v, indexing="ij"), -1).reshape(-1, 3)
    return np.concatenate([grid, Y0_IMAGINARY]).astype(np.float32)


#: Colours with Y = 0 (no light: the clip and the compression give black) and a large X
#: or Z, which the HLG views' inverse OOTF must not turn into light by float32 round-off.
Y0_IMAGINARY = np.array(
    [[1e4, 0, 1], [1e6, 0, 0], [0, 0, 1e6], [-1e6, 0, 0.5], [1e4, 0, 1e4]], np.float32
)
HLG_VIEWS = [(d, v) for d, v in VIEWS if d == "Rec.2100-HLG" and v != "Raw"]


@pytest.mark.parametrize("display,view", HLG_VIEWS)
def test_gpu_hlg_extremes(gl, config, display, view):
    """The HLG views on extreme input: the GPU (f4 and f2 textures) within 2/255 of the
    CPU on every pixel, NaN and +-Inf included, and imaginary colours with Y = 0
    black through the clip and the compression on both (Smits & Meyer 1990, Section
    3.2: Y <= 0 is black). The inputs are limited to +-1e6 first, as on the other
    displays (``ocio_ops.finite_limit_transform``)."""
    from evaluation import gpu

    x = _extreme_xyz()
    worst = {}
    for src in ("CIE-XYZ-D65", "Rec.2100-HLG - Display"):
        proc = config.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD)
        cpu = x.copy()
        proc.getDefaultCPUProcessor().applyRGB(cpu)
        assert np.isfinite(cpu).all(), src
        prog = gpu.GpuProgram(proc, ctx=gl)
        try:
            out = {dt: prog.apply(x, texture_dtype=dt) for dt in DTYPES}
        finally:
            prog.release()
        for dt, y in out.items():
            assert np.isfinite(y).all(), (src, dt)
            d = np.abs(y - cpu).max(axis=1)
            worst[src, dt] = round(float(d.max()) * 255, 3)
            i = int(np.argmax(d))
            assert d[i] <= TOL, (src, dt, x[i].tolist(), cpu[i].tolist(), y[i].tolist())
            if src == "CIE-XYZ-D65" and view.startswith("Constant-Lightness"):
                black = y[-len(Y0_IMAGINARY) :]
                assert np.abs(black).max() <= TOL, (dt, black.tolist())
                assert np.abs(cpu[-len(Y0_IMAGINARY) :]).max() <= TOL
    print(f"{display} / {view}: max |GPU - CPU| (/255) {worst}")
