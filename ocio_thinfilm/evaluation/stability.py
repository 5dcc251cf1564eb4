"""The stability cases of the analytic clip, defined once (tests and report share them).

Each :class:`Case` is an extreme CIE-XYZ-D65 input to :func:`ocio_thinfilm.colour.clip.clip_XYZ`
(sRGB) with the behaviour expected of it and a check of the output. The expectations
are geometric facts of the unit RGB cube (black, white, the boundary point along a
direction from grey), not outputs copied from the code under test.
``tests/test_stability.py`` runs every case (next to its more detailed tests, named
by ``Case.test``); the report's stability table lists them (``report.stability_rows``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from ocio_thinfilm.colour import clip, colorimetry

__all__ = ["Case", "fmt", "limit_along", "xyz_cases"]


def fmt(x, digits: int = 3) -> str:
    """A number as the report prints it (``digits`` significant, exponent outside
    [1e-3, 1e4)); strings pass through, None is a dash."""
    if x is None:
        return "–"
    if isinstance(x, str):
        return x
    if isinstance(x, (int, np.integer)) and not isinstance(x, bool):
        return str(x)
    if not np.isfinite(x):
        return str(x)
    if x == 0:
        return "0"
    if abs(x) >= 1e4 or abs(x) < 1e-3:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}"


@dataclass(frozen=True)
class Case:
    """One stability case: ``name`` (the report's row), ``inputs`` (XYZ, any leading
    shape), ``expected`` (the behaviour, in words), ``check(out) -> (ok, observed)``
    on the clip's output, ``test`` (the test in tests/test_stability.py that covers
    it in detail)."""

    name: str
    inputs: np.ndarray
    expected: str
    check: Callable[[np.ndarray], tuple[bool, str]]
    test: str


def limit_along(M, Minv, W, direction, Y):
    """Independent limit: from the grey of luminance Y, the furthest point along
    ``direction`` projected to constant Y that stays in the unit RGB cube."""
    grey = W * (Y / W[1])
    d = direction - W * (direction[1] / W[1])  # remove the luminance component
    g, dr = grey @ M.T, d @ M.T
    s = np.inf
    for c in range(3):
        if dr[c] > 0:
            s = min(s, (1 - g[c]) / dr[c])
        elif dr[c] < 0:
            s = min(s, -g[c] / dr[c])
    return grey + s * d


def _nan_check():
    alone = clip.clip_XYZ(np.array([[0.2, 0.3, 0.9]]))[0]

    def check(out):
        err = float(np.abs(out[1] - alone).max())
        ok = bool(np.all(np.isnan(out[0])) and err <= 1e-15)
        return ok, f"pixel 0 NaN: {bool(np.all(np.isnan(out[0])))}; pixel 1 vs alone |Δ| {fmt(err)}"
    return check


def _faces_edges():
    vals = [0.0, 0.37, 1.0]
    pts = np.array([[a, b, c] for a in vals for b in vals for c in vals])
    return pts


def _near_parallel(M, Minv):
    lum = Minv[1]
    out = []
    for delta in (1e-15, -1e-15, 1e-12, -1e-12, 1e-9, 1e-6, -1e-6):
        g = 0.4
        # RGB = (g + delta, g + a, g + b) with the same luminance as grey g:
        a = 3.0
        b = -(lum[0] * delta + lum[1] * a) / lum[2]
        out.append([g + delta, g + a, g + b])
    return np.array(out) @ Minv.T


def _near_parallel_check(M, Minv):
    def check(out):
        xyz = _near_parallel(M, Minv)
        rgb = out @ M.T
        ok = bool(np.all(np.isfinite(out)) and rgb.min() > -1e-12 and rgb.max() < 1 + 1e-12
                  and np.allclose(out[:, 1], xyz[:, 1], rtol=1e-9))
        return ok, (f"RGB in [{fmt(float(rgb.min()))}, {fmt(float(rgb.max()), 6)}], "
                    f"max |ΔY| {fmt(float(np.abs(out[:, 1] - xyz[:, 1]).max()))}")
    return check


def xyz_cases(W=None) -> list[Case]:
    """The extreme XYZ inputs of the analytic clip (sRGB); ``W``: the display white
    (default ``colorimetry.white_XYZ("sRGB")``)."""
    W = colorimetry.white_XYZ("sRGB") if W is None else W
    M = colorimetry.matrix_XYZ_to_RGB("sRGB")
    Minv = np.linalg.inv(M)
    grey_dir_limit = limit_along(M, Minv, W, np.array([1.0, 0.0, 0.0]), 0.5)

    def in_gamut_keep_Y(Y):
        def check(out):
            rgb = out @ M.T
            ok = bool(np.all(np.isfinite(out)) and np.all(rgb > -1e-9) and np.all(rgb < 1 + 1e-9)
                      and np.allclose(out[..., 1], Y, rtol=1e-9, atol=1e-12))
            return ok, f"RGB [{', '.join(fmt(float(v), 4) for v in np.ravel(rgb)[:3])}], Y {fmt(float(np.ravel(out)[1]), 6)}"
        return check

    def equals(target, tol, label):
        def check(out):
            err = float(np.max(np.abs(np.asarray(out) - target)))
            return err <= tol, f"{label}: |Δ| {fmt(err)}"
        return check

    cases = [
        ("XYZ negative (−0.1, −0.2, −0.1)", [-0.1, -0.2, -0.1], "black (Y ≤ 0)",
         equals(0.0, 0.0, "black"), "test_xyz_negative_and_zero_give_black"),
        ("XYZ zero", [0.0, 0.0, 0.0], "black", equals(0.0, 0.0, "black"),
         "test_xyz_negative_and_zero_give_black"),
        ("XYZ above white: 2·white and (0.5, 1.5, 0.5)", [2 * W, [0.5, 1.5, 0.5]],
         "white (Y ≥ Y_white)", equals(W, 1e-12, "white"), "test_xyz_above_white_gives_white"),
        ("XYZ (1e30, 0.5, 0.5)", [1e30, 0.5, 0.5],
         "finite, in gamut, Y = 0.5: the boundary point from grey along +X",
         equals(grey_dir_limit, 1e-9, "vs limit"), "test_xyz_huge_and_infinite_components"),
        ("XYZ (+Inf, 0.5, 0.5)", [np.inf, 0.5, 0.5], "same as the 1e30 limit",
         equals(grey_dir_limit, 1e-9, "vs limit"), "test_xyz_huge_and_infinite_components"),
        ("XYZ (−Inf, 0.5, 0.5)", [-np.inf, 0.5, 0.5], "finite, in gamut, Y = 0.5",
         in_gamut_keep_Y(0.5), "test_xyz_huge_and_infinite_components"),
        ("XYZ (0.3, +Inf, 0.3) / (0.3, −Inf, 0.3)", [[0.3, np.inf, 0.3], [0.3, -np.inf, 0.3]],
         "white / black", equals(np.array([W, np.zeros(3)]), 1e-12, "white/black"),
         "test_xyz_infinite_luminance"),
        ("XYZ NaN in one pixel of two", [[np.nan, 0.5, 0.5], [0.2, 0.3, 0.9]],
         "NaN in that pixel only; the other as if clipped alone (≤ 1e-15)",
         _nan_check(), "test_xyz_nan_stays_in_its_pixel"),
        ("XYZ on faces and edges (RGB channels exactly 0 or 1)", _faces_edges() @ Minv.T,
         "unchanged (≤ 1e-12: only the XYZ↔RGB round-off)",
         equals(_faces_edges() @ Minv.T, 1e-12, "moved"), "test_xyz_on_faces_and_edges_unchanged"),
        ("rays nearly parallel to a face (R − grey = ±1e-15…1e-6, G far out)", _near_parallel(M, Minv),
         "finite, in gamut, Y preserved to 1e-9", _near_parallel_check(M, Minv),
         "test_rays_nearly_parallel_to_a_face"),
    ]
    return [Case(name, np.asarray(xyz, dtype=np.float64), expected, check, test)
            for name, xyz, expected, check, test in cases]
