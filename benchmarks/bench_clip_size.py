"""Benchmark: accuracy / size / load time of the clip's black-faces pass, the shipped
design against a candidate (issue 15's size curve).

- ``shipped``: :class:`ocio_thinfilm.lut.clip_lut.ClipLUT` as the config bakes it, a
  Lut3D over (u_a, u_b, Y^(1/3)) holding L(X) / top in half floats.
- ``chroma``: the candidate. L is homogeneous of degree 1 (L(kX) = k L(X)): it moves
  the chromaticity radially from the white point onto the primaries' triangle and
  keeps Y. So the Lut3D over (u_a, u_b, Y / Y_top) outputs the *chart coordinates* of
  L(X) and Y unchanged -- constant along the Y axis but for the last layer (above
  white: white), exactly linear there, so tetrahedral interpolation is exact along Y
  and in-gamut chromaticities are reproduced exactly -- and OCIO's analytic
  ``xyY -> XYZ`` (XYZ_TO_xyY, inverse) and one matrix give display RGB / top. 16-bit
  integers in the file. Both are followed by the shipped white-faces pass.

Accuracy: the issue's sets (object, monochromatic, AP0) through OCIO's CPU processor
against the analytic clip, dE2000 p99 / max and in-gamut max. Size: the black pass's
CLF text. Load: building a processor from that CLF in a fresh OCIO config (best of 3).

Usage: python benchmarks/bench_clip_size.py [--sizes 33 49 57 65]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def chroma_black_pass(display, size):
    """(ops before the Lut3D, Lut3D values, ops after) of the candidate black pass,
    ending in display-linear RGB / top (the white pass's input)."""
    from ocio_thinfilm.colour import colorimetry
    from ocio_thinfilm.lut import clip_lut as CL
    from ocio_thinfilm.lut import ocio_ops

    ocio = ocio_ops.module()
    P, _ = CL._black_plan(display, size)
    M = colorimetry.matrix_XYZ_to_RGB(display)
    top = CL.clip_lut(display, size).top
    y_top = (size - 1) / (size - 2)  # node size - 2 is Y = 1
    g = np.linspace(0.0, 1.0, size)
    ua, ub = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    S = 1.0 / np.maximum(ub, 1e-9)  # u_b -> 0: ever larger chroma
    XYZ = np.c_[ua * S, np.ones_like(S), S - ua * S - 1.0] @ np.linalg.inv(P).T
    with np.errstate(all="ignore"):
        L = CL.clip_black_faces_RGB(XYZ @ M.T, display) @ np.linalg.inv(M).T @ P.T
    white = P @ np.linalg.inv(M) @ np.ones(3)
    lut = np.zeros((size, size, size, 3))
    lut[..., 0] = (L[:, 0] / L.sum(1)).reshape(size, size)[:, :, None]
    lut[..., 1] = (L[:, 1] / L.sum(1)).reshape(size, size)[:, :, None]
    lut[..., 2] = g
    lut[:, :, -1] = [white[0] / white.sum(), white[1] / white.sum(), g[-2]]
    lut = np.round(np.clip(lut, 0.0, 1.0) * 65535) / 65535
    before = [CL.xyz_limit_transform(), ocio_ops.matrix(P / y_top), CL.xyY_forward_transform()]
    after = [ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_XYZ_TO_xyY,
                                         direction=ocio.TRANSFORM_DIR_INVERSE),
             ocio_ops.matrix(M @ np.linalg.inv(P) * y_top / top)]
    return before, lut, after


def variant(display, size, kind):
    """(whole clip chain CIE-XYZ-D65 -> display-linear RGB, CLF-writable black core)."""
    from ocio_thinfilm.lut import clip_lut as CL
    from ocio_thinfilm.lut import ocio_ops

    shipped = CL.clip_lut(display, size)
    if kind == "shipped":
        core = shipped.black_core()
        ops = shipped.transforms()
    else:
        before, lut, after = chroma_black_pass(display, size)
        core = ocio_ops.group([ocio_ops.lut3d_transform(lut, bitdepth="uint16"),
                               ocio_ops.matrix()])
        ops = before + [core] + after + [shipped.white_core()]
    return ocio_ops.group(ops + [CL.working_decoding_transform()]), core


def accuracy(display, chain):
    sys.path.insert(0, str(ROOT / "tests"))
    from test_gamut_map import _sets

    from ocio_thinfilm.colour import clip, colorimetry
    from ocio_thinfilm.lut.ocio_ops import apply

    M = colorimetry.matrix_XYZ_to_RGB(display)
    out = {}
    for name, XYZ in _sets().items():
        got = colorimetry.RGB_to_XYZ(np.asarray(apply(chain, XYZ), float), display)
        de = colorimetry.delta_E2000(clip.clip_XYZ(XYZ, display), got)
        inside = clip.in_gamut(XYZ @ M.T)
        out[name] = (float(np.percentile(de, 99)), float(de.max()),
                     float(de[inside].max()) if inside.any() else 0.0)
    return out


def load(core):
    import PyOpenColorIO as ocio

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "black.clf"
        core.write("Academy/ASC Common LUT Format", str(path), ocio.Config.CreateRaw())
        best = np.inf
        for _ in range(3):
            ocio.ClearAllCaches()
            t0 = time.perf_counter()
            ocio.Config.CreateRaw().getProcessor(ocio.FileTransform(str(path))) \
                .getDefaultCPUProcessor()
            best = min(best, time.perf_counter() - t0)
        return path.stat().st_size / 1e6, best * 1e3


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--sizes", type=int, nargs="+", default=[33, 49, 57, 65])
    p.add_argument("--displays", nargs="+", default=["sRGB", "Display P3", "Rec.2020"])
    args = p.parse_args(argv)
    print("| display | black pass | size | MB | load ms | object p99 / max | "
          "monochromatic p99 / max | ap0 p99 / max | in-gamut max |")
    print("|---|---|---|---|---|---|---|---|---|")
    for display in args.displays:
        for size in args.sizes:
            for kind in ("shipped", "chroma"):
                chain, core = variant(display, size, kind)
                acc = accuracy(display, chain)
                mb, ms = load(core)
                cells = " | ".join(f"{v[0]:.3f} / {v[1]:.3f}" for v in acc.values())
                print(f"| {display} | {kind} | {size} | {mb:.1f} | {ms:.0f} | {cells} | "
                      f"{max(v[2] for v in acc.values()):.3f} |", flush=True)


if __name__ == "__main__":
    main()
