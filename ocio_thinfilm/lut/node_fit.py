"""The clip's black pass as planar geometry, and the fit of its nodes outside the gamut.

The black pass of the baked clip (:mod:`ocio_thinfilm.lut.clip_lut`) is L, the
constant-lightness clip of Smits & Meyer (1990), Section 3.2, against the faces through
black: homogeneous of degree 1, so a map from chromaticity to chromaticity, a 2D map
over the chart of :func:`ocio_thinfilm.lut.grid.black_plan` (the display's primaries a
triangle there). Its nodes inside the triangle hold the identity; sampling L at the
nodes outside makes the interpolant cut the triangle's corners, so those nodes hold the
values that interpolate L best (:func:`fit_outside_nodes`, lattice regression after
Garcia & Gupta 2009, solved by projected FISTA).

- :func:`chart_to_XYZ`, :func:`black_map` -- chart points as XYZ, and L in the chart;
- :func:`chart_triangle` -- the display's primaries in the chart;
- :func:`cross`, :func:`convex_hull`, :func:`inside_convex`, :func:`project_triangle`
  -- planar geometry;
- :func:`uv_1976` -- CIE 1976 u', v' (the fit's metric);
- :func:`fit_outside_nodes` -- the fit, with :data:`FIT_DENSITY`, :data:`FIT_DAMPING`
  and :data:`FIT_ITERATIONS`.

Measurements of the fit against sampled nodes: docs/gamut_map.md ("The outside nodes
are fitted, not sampled").
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import reproducible
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.colour.clip import clip_black_faces_RGB

__all__ = [
    "FIT_DENSITY",
    "FIT_DAMPING",
    "FIT_ITERATIONS",
    "chart_to_XYZ",
    "black_map",
    "chart_triangle",
    "cross",
    "convex_hull",
    "inside_convex",
    "project_triangle",
    "uv_1976",
    "fit_outside_nodes",
]

#: The fit of the black pass's outside nodes (:func:`fit_outside_nodes`): samples per
#: cell and axis, weight of the distance to the sampled value, gradient steps.
FIT_DENSITY = 5
FIT_DAMPING = 3.0
FIT_ITERATIONS = 1500


def chart_to_XYZ(P: np.ndarray, ua: np.ndarray, ub: np.ndarray) -> np.ndarray:
    """XYZ at Y = 1 of the chart points (u_a, u_b) of ``P``.

    u_b = Y / S -> 0: ever larger chroma.
    """
    S = 1.0 / np.maximum(ub, 1e-9)
    return reproducible.matmul(
        np.c_[ua * S, np.ones_like(S), S - ua * S - 1.0], reproducible.inv3(P).T
    )


def black_map(
    display: str, P: np.ndarray, ua: np.ndarray, ub: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """L in the chart: chart coordinates (N, 2) of L(X) for the chart points (u_a, u_b).

    Also whether each point is inside the gamut (L leaves it where it is).
    """
    M = colorimetry.matrix_XYZ_to_RGB(display)
    with np.errstate(all="ignore"):
        rgb = reproducible.matmul(chart_to_XYZ(P, ua, ub), M.T)
        to_chart = reproducible.matmul(reproducible.inv3(M).T, P.T)
        chart = reproducible.matmul(clip_black_faces_RGB(rgb, display), to_chart)
        uv = chart[:, :2] / chart.sum(axis=1, keepdims=True)
    # nodes on the triangle's edges count as inside (float64 round-off of their zero)
    return uv, rgb.min(axis=1) >= -1e-9 * np.abs(rgb).max(axis=1)


def cross(a: npt.ArrayLike, b: npt.ArrayLike) -> np.ndarray:
    """Return the z component of the cross product of 2D vectors (last axis 2)."""
    a, b = np.asarray(a), np.asarray(b)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def chart_triangle(display: str, P: np.ndarray) -> np.ndarray:
    """Return the display's primaries in the chart of ``P``: the triangle's vertices (3, 2)."""
    primaries = reproducible.matmul(
        reproducible.inv3(colorimetry.matrix_XYZ_to_RGB(display)).T, P.T
    )
    return primaries[:, :2] / primaries.sum(axis=1, keepdims=True)


def convex_hull(points: npt.ArrayLike) -> np.ndarray:
    """Vertices of the convex hull of 2D ``points``, counter-clockwise.

    By Andrew's monotone chain.
    """
    pts = sorted(map(tuple, np.asarray(points, dtype=np.float64)))

    def half(seq):
        out: list[tuple[float, ...]] = []
        for p in seq:
            while (
                len(out) >= 2 and cross(np.subtract(out[-1], out[-2]), np.subtract(p, out[-2])) <= 0
            ):
                out.pop()
            out.append(p)
        return out[:-1]

    return np.array(half(pts) + half(pts[::-1]))


def inside_convex(points: np.ndarray, hull: np.ndarray) -> np.ndarray:
    """Whether each of ``points`` (N, 2) lies inside the counter-clockwise ``hull``."""
    inside = np.ones(len(points), dtype=bool)
    for a, b in zip(hull, np.roll(hull, -1, axis=0), strict=True):
        inside &= cross(b - a, points - a) >= 0.0
    return inside


def project_triangle(p: np.ndarray, V: np.ndarray) -> np.ndarray:
    """Return the nearest points of the triangle V (3, 2) to the points ``p`` (N, 2)."""
    # barycentric coordinates by Cramer's rule (elementwise: the same bits on every CPU)
    e1, e2, d = V[1] - V[0], V[2] - V[0], p - V[0]
    det = e1[0] * e2[1] - e1[1] * e2[0]
    lam = np.c_[d[:, 0] * e2[1] - d[:, 1] * e2[0], e1[0] * d[:, 1] - e1[1] * d[:, 0]] / det
    inside = (lam >= 0.0).all(axis=1) & (lam.sum(axis=1) <= 1.0)
    best, dist = None, None
    for a, b in ((0, 1), (1, 2), (2, 0)):
        e = V[b] - V[a]
        along = reproducible.matmul(p - V[a], e) / reproducible.matmul(e, e)
        q = V[a] + np.clip(along, 0.0, 1.0)[:, None] * e
        d = ((p - q) ** 2).sum(axis=1)
        if best is None:
            best, dist = q, d
        else:
            assert best is not None and dist is not None
            nearer = d < dist
            best[nearer], dist[nearer] = q[nearer], d[nearer]
    assert best is not None
    return np.where(inside[:, None], p, best)


def fit_outside_nodes(
    display: str,
    P: np.ndarray,
    size: int,
    exact: np.ndarray,
    inside: np.ndarray,
) -> np.ndarray:
    """Values of the black pass's nodes outside the triangle that interpolate L best.

    Sampling L at the nodes makes the interpolant cut the triangle's corners: near a
    primary, points of two faces are interpolated along a chord inside the gamut (ΔE2000
    up to 1.3 for dark violet beyond sRGB's blue). Instead the outside nodes' values
    minimise the squared error of the interpolant (2D: tetrahedral interpolation of a
    map constant along Y) at :data:`FIT_DENSITY`² points per cell outside the triangle
    and inside the spectral locus, each error weighted by the CIE 1976 u'v' metric, plus
    :data:`FIT_DAMPING` times the squared distance to the sampled value; every value
    constrained to the triangle, so the output stays in gamut and Y exact. Solved by
    projected accelerated gradient descent (FISTA, :data:`FIT_ITERATIONS` steps) from
    the sampled values.

    References
    ----------
    Beck, A. & Teboulle, M. (2009). A fast iterative shrinkage-thresholding algorithm
    for linear inverse problems. SIAM J. Imaging Sciences 2(1), 183-202.
    """
    n = size
    V = chart_triangle(display, P)
    # real colours only: inside the spectral locus (imaginary ones, e.g. AP0's corners,
    # would pull the nodes away from the monochromatic colours on the locus)
    real = reproducible.matmul(colorimetry.spectral_locus_XYZ(1.0, np.arange(360.0, 781.0)), P.T)
    hull = convex_hull(real[:, :2] / real.sum(axis=1, keepdims=True))
    m = (n - 1) * FIT_DENSITY
    s = (np.arange(m) + 0.5) / m
    sa, sb = (a.ravel() for a in np.meshgrid(s, s, indexing="ij"))
    target, inside_s = black_map(display, P, sa, sb)
    keep = ~inside_s & inside_convex(np.c_[sa, sb], hull)
    sa, sb, target = sa[keep], sb[keep], target[keep]
    # the triangle of the 2D interpolation holding each sample, and its weights
    x, y = sa * (n - 1), sb * (n - 1)
    i, j = np.minimum(x.astype(int), n - 2), np.minimum(y.astype(int), n - 2)
    fx, fy = x - i, y - j
    up = fx >= fy
    corner = np.c_[i * n + j, np.where(up, (i + 1) * n + j, i * n + j + 1), (i + 1) * n + j + 1]
    weight = np.c_[np.where(up, 1 - fx, 1 - fy), np.abs(fx - fy), np.where(up, fy, fx)]

    # u'v' metric of each sample's error: J^T J of chart -> u'v' (central differences),
    # normalised by its median trace
    def uv(a, b):
        return uv_1976(chart_to_XYZ(P, a, b))

    h = 1e-6
    a, b = target[:, 0], target[:, 1]
    J = np.stack([uv(a + h, b) - uv(a - h, b), uv(a, b + h) - uv(a, b - h)], axis=-1) / (2 * h)
    # J^T J, written out (no einsum or BLAS: the same bits on every CPU)
    metric = J[:, 0, :, None] * J[:, 0, None, :] + J[:, 1, :, None] * J[:, 1, None, :]
    metric /= np.median(np.trace(metric, axis1=1, axis2=2))
    free = ~inside
    values = exact.copy()

    def interpolate(v):
        corners = v[corner]
        out = weight[:, 0, None] * corners[:, 0] + weight[:, 1, None] * corners[:, 1]
        return out + weight[:, 2, None] * corners[:, 2]

    def adjoint(r):
        out = np.zeros((n * n, 2))
        for k in range(3):
            for c in range(2):
                out[:, c] += np.bincount(corner[:, k], weight[:, k] * r[:, c], minlength=n * n)
        return out

    # step 1 / L: L bounds the gradient's Lipschitz constant (each sample's weights sum
    # to 1 and a node holds at most 6 cells of FIT_DENSITY^2 samples)
    lipschitz = 6 * FIT_DENSITY**2 * _largest_eigenvalue(metric).max() + FIT_DAMPING
    x_k = z = exact[free]
    t = 1.0
    for _ in range(FIT_ITERATIONS):
        values[free] = z
        e = interpolate(values) - target
        r = metric[:, :, 0] * e[:, 0, None] + metric[:, :, 1] * e[:, 1, None]
        grad = adjoint(r)[free] + FIT_DAMPING * (z - exact[free])
        x_next = project_triangle(z - grad / lipschitz, V)
        t_next = 0.5 * (1.0 + np.sqrt(1.0 + 4.0 * t * t))
        z = x_next + (t - 1.0) / t_next * (x_next - x_k)
        x_k, t = x_next, t_next
    values[free] = x_k
    return values


def _largest_eigenvalue(S: np.ndarray) -> np.ndarray:
    """Return the larger eigenvalue of each symmetric 2x2 matrix of ``S`` (N, 2, 2)."""
    half_trace = 0.5 * (S[:, 0, 0] + S[:, 1, 1])
    half_gap = 0.5 * (S[:, 0, 0] - S[:, 1, 1])
    return half_trace + np.sqrt(half_gap * half_gap + S[:, 0, 1] * S[:, 1, 0])


def uv_1976(XYZ: np.ndarray) -> np.ndarray:
    """CIE 1976 u', v' of XYZ (N, 3)."""
    d = XYZ[:, 0] + 15.0 * XYZ[:, 1] + 3.0 * XYZ[:, 2]
    return np.c_[4.0 * XYZ[:, 0] / d, 9.0 * XYZ[:, 1] / d]
