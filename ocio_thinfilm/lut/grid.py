"""Where the baked gamut maps put their LUT nodes: charts, node layouts and shapers.

The clip of Smits & Meyer (1990), Section 3.2, is baked as two Lut3Ds
(:mod:`ocio_thinfilm.lut.clip_lut`) and the soft compression adds one before each
(:mod:`ocio_thinfilm.lut.compress_lut`). Their accuracy is decided here, by where the
grid's nodes and split planes fall relative to the maps' kinks and faces:

- :func:`black_plan` -- the black pass's chromaticity chart (a matrix before
  ``XYZ_TO_xyY``): the display's primaries' triangle on grid and tetrahedral split
  planes, the grid uniform and covering :func:`chart_cover` (:data:`CHART_COVERS`);
- :func:`soft_plan` -- S_b's chart: the three rays where its gradient jumps on grid
  and split lines;
- :func:`white_nodes` -- the white pass's nodes per channel: sRGB-encoded spacing
  below 1 (:data:`WHITE_INSIDE`, :data:`WHITE_POWER`), growing geometrically
  (:func:`grow`, :data:`WHITE_FIRST_STEP`) up to the channel's largest value above;
- :func:`shaper_values` -- the Lut1D shaper that takes a value to its grid coordinate;
- :func:`encode` -- a display encoding in float64 (:data:`WORKING_ENCODING`: the
  encoding the white pass works in).

Design notes and the size/accuracy trade-off: docs/gamut_map.md, docs/compress.md,
reports/bench_clip_size.md.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import cache, registry, reproducible
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.colour import colorimetry, encodings
from ocio_thinfilm.colour.clip import luminance_weights
from ocio_thinfilm.lut.node_fit import cross

__all__ = [
    "CHART_COVERS",
    "CHART_BEND",
    "WHITE_INSIDE",
    "WHITE_POWER",
    "WHITE_FIRST_STEP",
    "SHAPER_LENGTH",
    "WORKING_ENCODING",
    "PLAN_STEPS",
    "grow",
    "chart_cover",
    "black_plan",
    "shaper_values",
    "encode",
    "white_nodes",
    "plan_matrix",
    "chart_coordinates",
    "soft_plan",
]

#: The black pass's chart covers these colours (with a uniform grid): the spectral
#: locus 360-780 nm, the ACES AP0 gamut with Y >= 0 and the Z axis (anything else is
#: clamped to the grid's edge and still lands in gamut with its Y).
CHART_COVERS = "spectral locus 360-780 nm, ACES AP0 (Y >= 0) and pure Z"
#: Largest ratio of u_b = Y / S across the primaries' triangle (the chart's bend).
CHART_BEND = 6.0
#: Share of each axis of the white pass spent on [0, 1] (grid nodes at encoded
#: values 1 - (1 - k/n)^WHITE_POWER: denser towards white), the rest growing
#: geometrically from WHITE_FIRST_STEP above 1 up to the channel's largest value,
#: 1 / (its luminance weight).
WHITE_INSIDE = 0.45
WHITE_POWER = 1.5
WHITE_FIRST_STEP = 0.004
#: Entries of the Lut1D shaper in front of the white pass's Lut3D.
SHAPER_LENGTH = 16384
#: The white pass works in (and its LUT outputs) the sRGB piecewise encoding: its
#: linear toe keeps the grid and the shaper accurate near black. Displays with
#: another encoding (Rec.2020: BT.1886, a pure power with infinite slope at black)
#: decode it with OCIO's analytic op and encode their own (for sRGB and Display P3
#: the pair cancels in OCIO's optimiser).
WORKING_ENCODING = "sRGB"
#: Values of mu tried per sign by :func:`soft_plan`.
PLAN_STEPS = 160


def grow(first: float, length: float, cells: int) -> np.ndarray:
    """``cells`` steps growing geometrically from ``first`` and summing to ``length``."""
    if cells <= 0:
        return np.zeros(0)
    if first * cells >= length:
        return np.full(cells, length / cells)
    lo, hi = 1.0, 64.0
    for _ in range(200):
        q = 0.5 * (lo + hi)
        total = first * (q**cells - 1.0) / (q - 1.0)
        lo, hi = (q, hi) if total < length else (lo, q)
    steps = first * q ** np.arange(cells)
    return steps * (length / steps.sum())


def chart_cover() -> np.ndarray:
    """XYZ (any scale) whose chart the black pass's grid must contain.

    The spectral locus, the corners of ACES AP0 cut at Y = 0 (AP0's blue primary has Y < 0)
    and the Z axis. (The X axis cannot be added in this chart family: imaginary colours
    redder than AP0 are clamped to the chart's edge -- in gamut, Y kept, hue
    approximate.)
    """
    locus = colorimetry.spectral_locus_XYZ(1.0, np.arange(360.0, 781.0))
    ap0 = reproducible.inv3(colorimetry.matrix_XYZ_to_RGB("ACES2065-1")).T  # rows: primaries
    cut = [ap0[a] + ap0[a, 1] / (ap0[a, 1] - ap0[2, 1]) * (ap0[2] - ap0[a]) for a in (0, 1)]
    points = np.concatenate([locus, ap0[:2], np.array(cut), [[0.0, 0.0, 1.0]]])
    return points / np.abs(points).sum(axis=1, keepdims=True)


@cache.memoize(maxsize=16)
def black_plan(display: str, size: int) -> tuple[np.ndarray, int]:
    """Return the black pass's chart: a matrix P.

    ``XYZ_TO_xyY(P XYZ)`` gives the Lut3D's coordinates (u_a, u_b) directly, uniform in a
    chromaticity chart where
    the display's triangle is canonical -- edges c_i = 0 on u_a = const, c_j = 0 on
    u_b = const, c_k = 0 on a diagonal u_a - u_b = const, all through nodes -- and
    Y unchanged (third output).

    With S = lam Y + mu c_j (the normaliser) and u_b = Y / S, u_b is affine in c_j / S;
    u_a = s lam w_i c_i / S + beta. Of the channel assignments and node positions
    that keep S > 0 and the chart of :func:`chart_cover` inside [0, 1]^2, the one
    with the most cells across the triangle is taken. Returns (P, cells across).
    """
    cells = size - 1
    M = colorimetry.matrix_XYZ_to_RGB(display)
    w = luminance_weights(display)
    cover = chart_cover()
    best = None
    for j in range(3):
        for i in range(3):
            if i == j:
                continue
            for n1 in range(cells, 1, -1):
                for n0 in range(1, n1):
                    # u_b = Y / S runs from n0 to n1 across the triangle: the chart
                    # inside the gamut bends like 1 / u_b, so keep n1 / n0 moderate
                    if n1 > CHART_BEND * n0:
                        continue
                    if best is not None and n1 - n0 <= best[0]:
                        continue
                    lam = cells / n1  # u_b = 1/lam = n1/cells where c_j = 0's opposite edge
                    mu = w[j] * cells / n0 - lam * w[j]  # u_b = n0/cells on c_j = 0
                    S_row = lam * np.array([0.0, 1.0, 0.0]) + mu * M[j]
                    S = reproducible.matmul(cover, S_row)
                    if np.any(S <= 1e-9):
                        continue
                    u_b = cover[:, 1] / S
                    if u_b.max() > 1.0 or u_b.min() < 0.0:
                        continue
                    s = np.sign((lam * w[j] + mu) * lam / mu) * (n1 - n0) / cells
                    u_a = s * lam * w[i] * reproducible.matmul(cover, M[i]) / S
                    beta = np.ceil(-u_a.min() * cells - 1e-9) / cells
                    if u_a.max() + beta > 1.0 + 1e-12:
                        continue
                    P = np.array([s * lam * w[i] * M[i] + beta * S_row, [0.0, 1.0, 0.0], S_row])
                    P[2] -= P[0] + P[1]
                    best = (n1 - n0, P)
    if best is None:
        raise ParameterError("size", f" {size} is too small to chart {CHART_COVERS}")
    return best[1], best[0]


def shaper_values(
    nodes: np.ndarray,
    lo: float,
    hi: float,
    along: Callable[[np.ndarray], np.ndarray] | None = None,
) -> np.ndarray:
    """Lut1D entries over [lo, hi] (SHAPER_LENGTH samples).

    The grid coordinate k / (size - 1) of the value, piecewise linear between the ``nodes``
    (in the variable ``along(value)`` when given: e.g. the display encoding).
    """
    x = np.linspace(lo, hi, SHAPER_LENGTH)
    grid = np.linspace(0.0, 1.0, len(nodes))
    if along is not None:
        x, nodes = along(x), along(nodes)
    return np.interp(x, nodes, grid)


def encode(values: npt.ArrayLike, display: str) -> np.ndarray:
    """Display encoding (the curve of the OCIO op the config uses), in float64.

    By :func:`ocio_thinfilm.colour.encodings.encode`, not by OCIO's float32 CPU path:
    these values are quantised into the LUTs (:mod:`ocio_thinfilm.reproducible`).
    """
    return encodings.encode(values, registry.as_display(display, hdr=False).encoding)


def white_nodes(
    size: int,
    display: str,
    inside: float = WHITE_INSIDE,
    graded: int = 0,
    ratio: float = 1.0,
    snap: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Node values of each axis of the white pass, (3, size) display-linear.

    Below 1 at working-encoding code values 1 - g_k with g_k = (1 - k/n)^WHITE_POWER (shared),
    above 1 growing geometrically up to the channel's largest value 1 / w_i (w: the
    display's luminance row; a colour with Y <= 1 and no negative channel has
    c_i <= 1 / w_i). Returns (nodes, tops), tops[i] the last node of axis i.

    Parameters
    ----------
    size : int
        Nodes per axis.
    display : str
        A display of the registry.
    inside : float, optional
        Share of the cells below 1 (default :data:`WHITE_INSIDE`).
    graded : int, optional
        The last ``graded`` gaps g_k below white shrink geometrically by ``ratio``
        instead (cells whose size is proportional to their distance from white: a map
        whose features narrow like 1 - Y towards white, as the compression's identity
        region does, then has as many cells across them at every scale).
    ratio : float, optional
        The geometric ratio of the graded gaps.
    snap : bool, optional
        Put every node but 0, 1 and the top on a sample of the :data:`SHAPER_LENGTH`
        Lut1D over [0, top] (:func:`shaper_values`, linear in the value): the shaper's
        linear interpolation then is exactly the piecewise-linear map between the nodes.

    Examples
    --------
    Four of the eight cells lie below 1, at sRGB code values 1 - (1 - k/4)^1.5:

    >>> nodes, tops = white_nodes(9, "sRGB")
    >>> encode(nodes[1, :5], "sRGB").round(3).tolist(), bool(nodes[1, -1] == tops[1])
    ([0.0, 0.35, 0.646, 0.875, 1.0], True)
    """
    cells = size - 1
    inside_cells = max(2, int(round(cells * inside)))
    gap = (1.0 - np.linspace(0.0, 1.0, inside_cells + 1)) ** WHITE_POWER
    if graded > 0:
        first = inside_cells - graded
        gap[first:inside_cells] = gap[first] * ratio ** np.arange(graded)
        gap[inside_cells] = 0.0
    code = 1.0 - gap
    below = encodings.decode(code, registry.as_display(WORKING_ENCODING, hdr=False).encoding)
    below[0], below[-1] = 0.0, 1.0
    # a little above 1 / w_i: float32 round-off of the matrix in front stays inside
    tops = 1.001 / luminance_weights(display)
    nodes = np.array(
        [
            np.concatenate(
                [
                    below,
                    1.0 + np.cumsum(grow(WHITE_FIRST_STEP, top - 1.0, cells - inside_cells)),
                ]
            )
            for top in tops
        ]
    )
    if snap:
        last = SHAPER_LENGTH - 1
        samples = np.round(nodes / tops[:, None] * last) / last * tops[:, None]
        fixed = (nodes == 0.0) | (nodes == 1.0) | (nodes == nodes[:, -1:])
        nodes = np.where(fixed, nodes, samples)
        if not (np.diff(nodes, axis=1) > 0.0).all():
            raise ParameterError("size", f" {size}: nodes closer than the shaper's samples")
    return nodes, tops


def plan_matrix(
    M: np.ndarray,
    perm: tuple[int, int, int],
    lam_nodes: int,
    mu: float,
    a_nodes: float,
    cells: int,
) -> np.ndarray:
    """Return the chart matrix for channels ``perm`` = (p, q, r).

    u_a = alpha (c_p - c_q) / S + a_0, u_b = Y / S with S = lam Y + mu (c_r - c_q),
    alpha = -mu / lam.
    """
    p, q, r = perm
    lam = cells / lam_nodes
    Y = np.array([0.0, 1.0, 0.0])
    S = lam * Y + mu * (M[r] - M[q])
    v0 = -mu / lam * (M[p] - M[q]) + a_nodes / cells * S
    return np.array([v0, Y, S - v0 - Y])


def chart_coordinates(P: np.ndarray, XYZ: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return the chart coordinates (u_a, u_b) of the (N, 3) ``XYZ`` and the normaliser S.

    The coordinates under the chart matrix ``P`` (``XYZ_TO_xyY`` of ``P XYZ``); the
    normaliser S is (N,).
    """
    c = reproducible.matmul(XYZ, P.T)
    with np.errstate(all="ignore"):
        s = c.sum(axis=1)
        return c[:, :2] / s[:, None], s


@cache.persistent(
    modules=(
        "ocio_thinfilm.lut.grid",
        "ocio_thinfilm.lut.node_fit",
        "ocio_thinfilm.colour.colorimetry",
    )
)
def soft_plan(display: str, size: int) -> np.ndarray:
    """Return S_b's chart: a matrix P.

    ``XYZ_TO_xyY(P XYZ)`` gives its Lut3D's coordinates (u_a, u_b) and Y, with the three rays
    where S_b has a kink on grid and split lines.

    S_b scales by a function of d_black = (Y - min c) / Y, whose gradient jumps where
    the two smallest channels swap: on the rays from the white point where c_p = c_q,
    c_q = c_r and c_p = c_r. With u_a = alpha (c_p - c_q) / S + a_0 and u_b = Y / S,
    S = lam Y + mu (c_r - c_q), the first is u_a = a_0, the second u_b = 1 / lam and the
    third, for alpha = -mu / lam, the diagonal u_a - u_b = const (a split plane of
    tetrahedral interpolation) -- all through the white point's node. Of the charts
    that hold :func:`chart_cover` in [0, 1]^2, the one
    where the display's triangle is largest is taken. Memoised on disk (the search takes
    about 2 s per display).
    """
    cells = size - 1
    M = colorimetry.matrix_XYZ_to_RGB(display)
    cover = chart_cover()
    primaries = reproducible.inv3(M).T
    best = None
    mus = np.geomspace(1e-2, 3.0, PLAN_STEPS)
    for perm in ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)):
        for lam_nodes in range(2, cells - 1):
            for mu in np.concatenate([mus, -mus]):
                P = plan_matrix(M, perm, lam_nodes, mu, 0.0, cells)
                uv, s = chart_coordinates(P, cover)
                if np.any(s <= 1e-9) or uv[:, 1].min() < 0.0 or uv[:, 1].max() > 1.0:
                    continue
                lo, hi = uv[:, 0].min(), uv[:, 0].max()
                a_nodes = np.ceil(-lo * cells - 1e-9)  # white on a node, the cover inside
                if hi + a_nodes / cells > 1.0 or a_nodes > cells:
                    continue
                tri, _ = chart_coordinates(P, primaries)
                area = abs(cross(tri[1] - tri[0], tri[2] - tri[0]))
                if best is None or area > best[0]:
                    best = (area, plan_matrix(M, perm, lam_nodes, mu, a_nodes, cells))
    if best is None:
        raise ParameterError("size", f" {size} is too small for the compression's chart")
    return best[1]
