"""Benchmark: the views as code (``export shader``) against the baked views' LUTs.

For each display and the two mapped views (Constant-Lightness Clip and Compress), on
about a million CIE-XYZ-D65 pixels (the four test sets of ``evaluation.colours``,
repeated; an HDR display's scaled into its volume):

- **operations per pixel** of the DCTL, counted by compiling it with a counting float
  type (``evaluation/dctl/dctl_count.h``): adds, multiplies, divides, comparisons,
  min/max, transcendental calls (pow, exp2, log, sqrt), mean over the pixels;
- **CPU throughput**, one thread, side by side in one run: the DCTL compiled as C++
  (``g++ -O2``, the host header of ``evaluation/dctl``), OCIO's default CPU processor of
  the committed config's view (what a host applies), of the config's ``ACES Gamut
  Compression`` view (OCIO's built-in ACES 1.3 gamut compression, for scale), and of a
  single 65^3 Lut3D (tetrahedral): ns per pixel and ratios to the DCTL;
- **GLSL** on the headless Mesa context (llvmpipe, a CPU rasteriser: the ratio says how
  much work each shader is, not how fast a GPU runs it): the exported GLSL against
  OCIO's GLSL of the baked view with its LUT textures (float32), ms per pass of the
  same pixels, upload and read back included for both.

Writes reports/bench_shader.json and reports/bench_shader.md.

Usage: python benchmarks/bench_shader.py [--pixels 1000000] [--repeats 5] [--displays sRGB ...]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/
from benchmarks import _reports  # noqa: E402  (after the path above)

REPORT = ROOT / "reports"
VIEWS = ("Constant-Lightness Clip", "Constant-Lightness Compress")
#: The flags of the second C++ build: vectorised and with fast math, as GPU compilers
#: treat shader arithmetic (it is not checked for NaN and Inf: the timing only).
FAST = ("-O3", "-march=native", "-ffast-math")


def _pixels(n, scale):
    from evaluation.colours import gamut_map_sets

    XYZ = np.concatenate(list(gamut_map_sets().values()))
    reps = -(-n // len(XYZ))
    return np.ascontiguousarray(np.tile(XYZ, (reps, 1))[:n] * scale, dtype=np.float32)


def _best(fn, repeats):
    best = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def _ocio_seconds(processor, pixels, repeats):
    cpu = processor.getDefaultCPUProcessor()
    work = pixels.copy()

    def run():
        work[:] = pixels
        cpu.applyRGB(work)

    return _best(run, repeats)


def _lut3d_processor(size=65):
    import PyOpenColorIO as ocio

    u = np.linspace(0.0, 1.0, size)
    grid = np.stack(np.meshgrid(u, u, u, indexing="ij"), axis=-1)
    lut = ocio.Lut3DTransform(size)
    values = np.sqrt(grid)  # any smooth content; the cost does not depend on it
    for i in range(size):
        for j in range(size):
            for k in range(size):
                r, g, b = values[i, j, k]
                lut.setValue(i, j, k, float(r), float(g), float(b))
    lut.setInterpolation(ocio.INTERP_TETRAHEDRAL)
    return ocio.Config.CreateRaw().getProcessor(lut)


def _gpu_seconds(run, repeats):
    run()  # compile / upload once
    return _best(run, repeats)


def measure(n_pixels, repeats, displays):
    import PyOpenColorIO as ocio

    from evaluation.shaders import DctlView, GlslView, count_operations
    from evaluation.views import COMMITTED_CONFIG
    from ocio_thinfilm import registry
    from ocio_thinfilm.export.shader import shader_source

    cfg = ocio.Config.CreateFromFile(str(COMMITTED_CONFIG))
    fwd = ocio.TRANSFORM_DIR_FORWARD
    lut3d = _lut3d_processor()
    try:
        from evaluation import gpu

        ctx = gpu.default_context()
    except RuntimeError as error:
        print(f"GLSL skipped: {error}")
        ctx = None
    rows = []
    for display in displays:
        scale = registry.as_display(display).scale
        pixels = _pixels(n_pixels, scale)
        per = 1e9 / len(pixels)
        aces = cfg.getProcessor("CIE-XYZ-D65", display, "ACES Gamut Compression", fwd)
        aces_ns = _ocio_seconds(aces, pixels, repeats) * per
        lut_ns = _ocio_seconds(lut3d, pixels, repeats) * per
        for view in VIEWS:
            dctl = shader_source("dctl", display, view)
            ops = count_operations(dctl, pixels[:200000])
            code = DctlView(dctl)
            fast = DctlView(dctl, flags=FAST)
            try:
                dctl_ns = code.time(pixels, repeats) * per
                fast_ns = fast.time(pixels, repeats) * per
            finally:
                code.release()
                fast.release()
            proc = cfg.getProcessor("CIE-XYZ-D65", display, view, fwd)
            view_ns = _ocio_seconds(proc, pixels, repeats) * per
            row = dict(
                display=display,
                view=view,
                ops=ops,
                ops_total=sum(ops.values()),
                dctl_ns=dctl_ns,
                dctl_fast_ns=fast_ns,
                ocio_view_ns=view_ns,
                ocio_aces_ns=aces_ns,
                ocio_lut3d_ns=lut_ns,
            )
            if ctx is not None:
                glsl = GlslView(shader_source("glsl", display, view), ctx=ctx)
                program = gpu.GpuProgram(proc, ctx=ctx)
                try:
                    row["glsl_ms"] = (
                        _gpu_seconds(lambda g=glsl, x=pixels: g.apply(x), repeats) * 1e3
                    )
                    row["ocio_glsl_ms"] = (
                        _gpu_seconds(lambda p=program, x=pixels: p.apply(x), repeats) * 1e3
                    )
                finally:
                    glsl.release()
                    program.release()
            rows.append(row)
            print(_line(row), flush=True)
    return rows


def _line(r):
    text = (
        f"{r['display']:<13} {r['view']:<28} ops {r['ops_total']:6.1f}  DCTL {r['dctl_ns']:6.1f}"
        f" ns (fast math {r['dctl_fast_ns']:5.1f})  OCIO view {r['ocio_view_ns']:6.1f} ns"
        f" ({r['ocio_view_ns'] / r['dctl_ns']:.2f}x)"
        f"  ACES GC {r['ocio_aces_ns']:5.1f}  Lut3D {r['ocio_lut3d_ns']:5.1f}"
    )
    if "glsl_ms" in r:
        text += f"  GLSL {r['glsl_ms']:.1f} ms vs OCIO GLSL {r['ocio_glsl_ms']:.1f} ms"
    return text


def markdown(result):
    rows = result["rows"]
    lines = [
        "# The views as code against the baked views",
        "",
        f"{result['pixels']:,} CIE-XYZ-D65 pixels (the four test sets, repeated; HDR "
        "displays' scaled into their volume), best of "
        f"{result['repeats']} passes, one thread. `python benchmarks/bench_shader.py`.",
        "",
        "Operations per pixel: the DCTL compiled with a counting float type (mean over the"
        " pixels; a clamp counts 2 min/max). CPU: the DCTL compiled as C++ (g++ -O2, and"
        " -O3 -march=native -ffast-math as GPU compilers treat shader arithmetic),"
        " OCIO's default CPU processors (the committed config's view, its ACES Gamut"
        " Compression view, a single 65^3 Lut3D) on the same pixels.",
        "",
        "| display | view | add | mul | div | cmp | min/max | pow/exp/log | DCTL ns/px "
        "| DCTL fast-math ns/px | OCIO view ns/px | OCIO view / DCTL | ACES GC ns/px "
        "| Lut3D ns/px | Lut3D / DCTL |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        o = r["ops"]
        lines.append(
            f"| {r['display']} | {r['view']} | {o['add']:.1f} | {o['multiply']:.1f} | "
            f"{o['divide']:.1f} | {o['compare']:.1f} | {o['min/max']:.1f} | "
            f"{o['transcendental']:.1f} | {r['dctl_ns']:.1f} | {r['dctl_fast_ns']:.1f} | "
            f"{r['ocio_view_ns']:.1f} | "
            f"{r['ocio_view_ns'] / r['dctl_ns']:.2f} | {r['ocio_aces_ns']:.1f} | "
            f"{r['ocio_lut3d_ns']:.1f} | {r['ocio_lut3d_ns'] / r['dctl_ns']:.2f} |"
        )
    if rows and "glsl_ms" in rows[0]:
        lines += [
            "",
            "GLSL on Mesa llvmpipe (a CPU rasteriser; upload and read back included): ms per pass.",
            "",
            "| display | view | exported GLSL ms | OCIO GLSL of the baked view ms | ratio |",
            "|---|---|---|---|---|",
        ]
        for r in rows:
            lines.append(
                f"| {r['display']} | {r['view']} | {r['glsl_ms']:.1f} | "
                f"{r['ocio_glsl_ms']:.1f} | {r['ocio_glsl_ms'] / r['glsl_ms']:.2f} |"
            )
    return "\n".join(lines) + "\n"


def main(argv=None):
    from ocio_thinfilm import registry

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--pixels", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--displays", nargs="+", default=list(registry.ALL_DISPLAYS))
    args = parser.parse_args(argv)
    rows = measure(args.pixels, args.repeats, args.displays)
    result = dict(pixels=args.pixels, repeats=args.repeats, rows=rows)
    REPORT.mkdir(exist_ok=True)
    _reports.write_json("shader", result)
    (REPORT / "bench_shader.md").write_text(markdown(result))
    print(f"wrote {REPORT / 'bench_shader.md'}")


if __name__ == "__main__":
    main()
