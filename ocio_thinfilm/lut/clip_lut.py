"""The constant-lightness clip (paper Section 3.2) baked into two 3D LUTs, as OCIO transforms.

The clip moves a colour along its constant-Y ray towards the grey Y W until it is
inside all six faces: t = min(t_black, t_white). It therefore factors exactly as
clip = U o L, L clipping only against R, G, B >= 0 and U only against R, G, B <= 1,
both along the same ray (paper, Section 3.2; :mod:`ocio_thinfilm.colour.clip`).

Pass 1, L, is homogeneous of degree 1 (L(kX) = k L(X)): it moves the chromaticity
radially from the white point onto the primaries' triangle and keeps Y. Its Lut3D
therefore maps chromaticity to chromaticity: over the projective chart (u_a, u_b, Y)
of :func:`_black_plan` (``XYZ_TO_xyY`` of a matrix, the primaries' triangle on grid
and tetrahedral split planes) it outputs the chart coordinates of L(X) and Y itself,
constant along the Y axis and exactly linear in Y, so tetrahedral interpolation is
exact along Y, dark colours keep their chromaticity however dark they are, and
in-gamut chromaticities are nodes' identity. The nodes outside the triangle are not
sampled but fitted to L (:func:`_fit_outside_nodes`), so the interpolant does not cut
the triangle's corners, and stored so that two faces are exactly 0 and none of them
leaves the triangle in 16-bit files or half-float textures (:func:`_face_frame`,
:func:`_halves_inside`). OCIO's analytic xyY -> XYZ and one matrix give display RGB.
Before the LUT, Y is limited to 1 (the pre-clip: a colour at or above white becomes
white in pass 2).

Pass 2, U, works on that RGB (no negative channel, Y <= 1) directly: every face, the
white point and the planes R = G, G = B, R = B where the binding face changes are grid
or split planes; below 1 the grid nodes sit at sRGB-encoded values and the LUT stores
sRGB code values, so the identity (every in-gamut colour) is reproduced exactly and the
display encoding costs nothing (sRGB, Display P3) or one analytic op (Rec.2020). Above
1 each channel's nodes run up to its own largest value, 1 / (its luminance weight).
Nodes brighter than white hold U's analytic continuation (:func:`_white_continuation`)
rather than white, so the cells that straddle Y = 1 interpolate a smooth function:
colours just below white, far outside the gamut, keep their Y. The LUT stores code
values / :data:`WHITE_SCALE`; the one gain after a LUT is that 1.25. Design notes and
measurements: docs/gamut_map.md.

- :func:`clip_lut` / :class:`ClipLUT` -- the baked LUT data of one display and their
  CLF-writable cores; :meth:`ClipLUT.transforms` -- the whole chain;
- :func:`clip_black_faces_RGB` (L), :func:`clip_white_faces_RGB` (U) -- the two
  factors, whose composition is :func:`ocio_thinfilm.colour.clip.clip_RGB`;
- :func:`clip_transform` -- CIE-XYZ-D65 -> display-linear RGB, clipped.

Accuracy against the analytic clip, size, load time, speed and the rejected designs:
``benchmarks/bench_gamut_map.py``, ``benchmarks/bench_clip_size.py``,
``benchmarks/bench_load.py`` and docs/gamut_map.md.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import cache, registry
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.display_transforms import (
    display_encoding_transform,
)
from ocio_thinfilm.lut.ocio_ops import (
    apply,
    group,
    lut1d_transform,
    lut3d_transform,
    transform_id,
)
from ocio_thinfilm.lut.tables import check_size

__all__ = [
    "CLIP_SIZE",
    "WHITE_SIZE",
    "WORKING_ENCODING",
    "ClipLUT",
    "clip_lut",
    "clip_transform",
    "clip_black_faces_RGB",
    "clip_white_faces_RGB",
    "xyz_limit_transform",
    "xyY_forward_transform",
    "xyY_inverse_transform",
    "working_decoding_transform",
]

#: Default edge length of the black-faces Lut3D (the chromaticity chart).
CLIP_SIZE = 65
#: Default edge length of the white-faces Lut3D (with the default CLIP_SIZE; other
#: sizes scale it in proportion, :func:`white_size`). Chosen by
#: ``benchmarks/bench_clip_size.py``: the config's size budget against accuracy.
WHITE_SIZE = 53
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
#: The white pass's Lut3D holds code values / WHITE_SCALE: its nodes brighter than
#: white hold U's continuation (code values above 1), capped at WHITE_SCALE.
WHITE_SCALE = 1.25
#: The fit of the black pass's outside nodes (:func:`_fit_outside_nodes`): samples per
#: cell and axis, weight of the distance to the sampled value, gradient steps.
FIT_DENSITY = 5
FIT_DAMPING = 3.0
FIT_ITERATIONS = 1500
#: Entries of the Lut1D shaper in front of the white pass's Lut3D.
SHAPER_LENGTH = 16384
#: The white pass works in (and its LUT outputs) the sRGB piecewise encoding: its
#: linear toe keeps the grid and the shaper accurate near black. Displays with
#: another encoding (Rec.2020: BT.1886, a pure power with infinite slope at black)
#: decode it with OCIO's analytic op and encode their own (for sRGB and Display P3
#: the pair cancels in OCIO's optimiser).
WORKING_ENCODING = "sRGB"
#: 16-bit LUT files: values are stored as codes of this maximum.
LUT_CODE_MAX = 65535
#: Relative size of max(c) - Y below which a colour counts as neutral (a grey to
#: rounding: the luminance row sums to 1 only to a few ulps).
NEUTRAL_TOLERANCE = 1e-12


def white_size(size: int) -> int:
    """Edge of the white pass's Lut3D for a black pass of edge ``size``:
    :data:`WHITE_SIZE` at :data:`CLIP_SIZE`, in proportion otherwise (at least 7).

    Examples
    --------
    >>> white_size(65), white_size(33), white_size(9)
    (53, 27, 7)
    """
    return max(7, int(round(size * WHITE_SIZE / CLIP_SIZE)))


def xyz_limit_transform() -> ocio_ops.Transform:
    """Clamp XYZ to [0, :data:`~ocio_thinfilm.lut.ocio_ops.LIMIT`] per component before the chart.

    No physical colour has a negative X, Y or Z (the CIE 1931 matching functions are
    non-negative), so this changes only non-physical inputs; it keeps the chart's
    normaliser positive and makes +-Inf finite (Y <= 0 gives black, as in the
    analytic clip).

    Returns
    -------
    PyOpenColorIO.RangeTransform
        A clamp (no scaling) of every channel to [0, 1e6]; the first op of
        :meth:`ClipLUT.transforms`.

    References
    ----------
    Smits & Meyer (1990), Section 3.2 (the clip's defined behaviour at Y <= 0).

    Examples
    --------
    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> apply(xyz_limit_transform(), [[-0.1, 0.5, 2e6]]).tolist()
    [[0.0, 0.5, 1000000.0]]
    """
    return ocio_ops.range_(0.0, ocio_ops.LIMIT)


def xyY_forward_transform() -> ocio_ops.Transform:
    """OCIO's analytic CIE XYZ -> xyY (``FIXED_FUNCTION_XYZ_TO_xyY``).

    ``x = X / (X + Y + Z)``, ``y = Y / (X + Y + Z)``, Y unchanged (CIE 15:2004,
    Section 7.3). After the chart matrix of :func:`_black_plan` it gives the black
    pass's Lut3D coordinates (u_a, u_b) and Y directly.

    Returns
    -------
    PyOpenColorIO.FixedFunctionTransform

    References
    ----------
    CIE 15:2004 Colorimetry, 3rd ed., Section 7.3 (chromaticity coordinates).

    Examples
    --------
    The D65 white (0.95047, 1, 1.08883) has the chromaticity (0.3127, 0.3290):

    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> [round(float(v), 4) for v in apply(xyY_forward_transform(), [0.95047, 1.0, 1.08883])]
    [0.3127, 0.329, 1.0]
    """
    ocio = ocio_ops.module()
    return ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_XYZ_TO_xyY)


def xyY_inverse_transform() -> ocio_ops.Transform:
    """OCIO's analytic xyY -> CIE XYZ (``FIXED_FUNCTION_XYZ_TO_xyY``, inverse).

    ``X = x Y / y``, ``Z = (1 - x - y) Y / y`` (CIE 15:2004, Section 7.3). After the
    black pass's Lut3D (chart coordinates of L(X) and Y) it gives L(X) in the chart's
    coordinates; the black pass's outputs keep ``y`` (u_b) away from 0.

    Returns
    -------
    PyOpenColorIO.FixedFunctionTransform

    Examples
    --------
    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> [round(float(v), 4) for v in apply(xyY_inverse_transform(), [0.3127, 0.3290, 1.0])]
    [0.9505, 1.0, 1.0891]
    """
    ocio = ocio_ops.module()
    return ocio.FixedFunctionTransform(
        ocio.FIXED_FUNCTION_XYZ_TO_xyY, direction=ocio.TRANSFORM_DIR_INVERSE
    )


def _luminance(display):
    """Row w with Y = w . RGB (display-linear, RGB = 1 is Y = 1)."""
    return np.linalg.inv(colorimetry.matrix_XYZ_to_RGB(display))[1]


def clip_black_faces_RGB(RGB: npt.ArrayLike, display: str) -> np.ndarray:
    """L: the clip against the faces R, G, B >= 0 only (float64, (N, 3) display RGB).

    ``Y <= 0`` gives black; otherwise the colour moves towards the grey of its Y until
    its smallest channel is 0 (unchanged when no channel is negative).

    The ray of Smits & Meyer (1990), Section 3.2, against the three faces through
    black: with ``Y = w . RGB`` (``w`` the display's luminance row) and
    ``lo = min(R, G, B) < 0`` the result is ``Y + t (RGB - Y)`` with
    ``t = Y / (Y - lo)``, so its smallest channel is 0 and its luminance is Y.
    Channels may still exceed 1 (that is :func:`clip_white_faces_RGB`'s part).

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB of ``display`` (RGB = 1 its white), last axis 3.
    display : str
        A display of :data:`ocio_thinfilm.registry.DISPLAYS`.

    Returns
    -------
    numpy.ndarray
        float64, shape of ``RGB``. Non-finite inputs give non-finite rows (no
        warning).

    References
    ----------
    Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    In-gamut colours are unchanged; (1.2, 0.5, -0.1) (Y = 0.6055 with the Rec.709
    weights) moves with t = 0.6055 / 0.7055 to (1.116, 0.515, 0), keeping Y; a colour
    with Y <= 0 is black:

    >>> out = clip_black_faces_RGB([[0.5, 0.4, 0.3], [1.2, 0.5, -0.1],
    ...                             [-0.1, -0.2, 0.3]], "sRGB")
    >>> out.round(2).tolist()
    [[0.5, 0.4, 0.3], [1.12, 0.51, 0.0], [0.0, 0.0, 0.0]]
    >>> w = colorimetry.RGB_to_XYZ(np.eye(3), "sRGB")[:, 1]  # luminance weights
    >>> bool(np.isclose(out[1] @ w, np.dot([1.2, 0.5, -0.1], w)))
    True
    """
    rgb = np.asarray(RGB, dtype=np.float64)
    with np.errstate(all="ignore"):  # non-finite inputs give non-finite rows, no warning
        Y = rgb @ _luminance(display)
        lo = rgb.min(axis=-1)
        t = np.where(lo < 0.0, Y / (Y - lo), 1.0)
        out = Y[..., None] + t[..., None] * (rgb - Y[..., None])
    out[Y <= 0.0] = 0.0
    return out


def clip_white_faces_RGB(RGB: npt.ArrayLike, display: str) -> np.ndarray:
    """U = C o L o C with C(c) = 1 - c: the clip against R, G, B <= 1 only.

    C maps the display white to black and the faces R, G, B = 1 to the faces through
    black, and Y(C(c)) = Y_W - Y(c): the ray of :func:`clip_black_faces_RGB` in the
    complement is the paper's ray towards the same grey (Smits & Meyer 1990,
    Section 3.2), so U keeps Y, brings the largest channel of an out-of-gamut colour
    to 1 and gives white for Y >= Y_W. Applied after L, the composition is
    :func:`ocio_thinfilm.colour.clip.clip_RGB`.

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB of ``display``, last axis 3.
    display : str
        A display of :data:`ocio_thinfilm.registry.DISPLAYS` (its white has Y = 1).

    Returns
    -------
    numpy.ndarray
        float64, shape of ``RGB``.

    References
    ----------
    Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    In-gamut colours are unchanged; (1.2, 0.5, 0.1) keeps Y = 0.62 with R = 1
    (the complement (-0.2, 0.5, 0.9) has Y = 0.38, t = 0.38 / 0.58); a colour brighter
    than white is white:

    >>> clip_white_faces_RGB([[0.5, 0.4, 0.3], [1.2, 0.5, 0.1],
    ...                       [1.1, 1.2, 0.9]], "sRGB").round(2).tolist()
    [[0.5, 0.4, 0.3], [1.0, 0.54, 0.28], [1.0, 1.0, 1.0]]
    """
    return 1.0 - clip_black_faces_RGB(1.0 - np.asarray(RGB, dtype=np.float64), display)


def _white_continuation(RGB, display):
    """U of :func:`clip_white_faces_RGB` for Y <= 1, continued analytically above.

    For c >= 0 with Y = w . c <= 1, U(c) = Y + t (c - Y) with t = (1 - Y) / (max c - Y)
    where max c > 1 (else c): the paper's ray (Section 3.2) brought to the face
    through white. The same formula for Y > 1 (t < 0) is its smooth continuation past
    white, which the white pass stores at its nodes brighter than white: the cells that
    straddle Y = 1 then interpolate a smooth function instead of a kink towards white
    (the pre-clip keeps the pass's inputs at Y <= 1). At Y = 1 both give white.

    Examples
    --------
    >>> rgb = np.array([[0.5, 0.4, 0.3], [1.2, 0.5, 0.1], [2.0, 1.0, 0.5]])
    >>> bool(np.allclose(_white_continuation(rgb[:2], "sRGB"),
    ...                  clip_white_faces_RGB(rgb[:2], "sRGB")))
    True
    >>> out = _white_continuation(rgb[2:], "sRGB")  # Y = 1.18: past white
    >>> bool(out[0, 0] == 1.0 and np.all(out[0, 1:] > 1.0))
    True
    """
    rgb = np.asarray(RGB, dtype=np.float64)
    Y = rgb @ _luminance(display)
    top = rgb.max(axis=-1)
    # a neutral colour (max c - Y at rounding level) has every channel as its largest,
    # and the largest always goes to 1: past white a grey goes to white, not to 0 / 0
    # (whose rounding differs between CPUs)
    neutral = top - Y <= NEUTRAL_TOLERANCE * np.maximum(np.abs(top), 1.0)
    with np.errstate(all="ignore"):
        t = np.where((top > 1.0) & ~neutral, (1.0 - Y) / (top - Y), 1.0)
    out = Y[..., None] + t[..., None] * (rgb - Y[..., None])
    return np.where(((top > 1.0) & neutral)[..., None], 1.0, out)


def _white_codes(C: np.ndarray, display: str) -> np.ndarray:
    """The white pass's stored values at the (N, 3) nodes ``C``: U continued above
    white (:func:`_white_continuation`), in the working encoding, / WHITE_SCALE, on the
    16-bit grid."""
    code = _encode(np.clip(_white_continuation(C, display), 0.0, None), WORKING_ENCODING)
    return _q16(code / WHITE_SCALE)


def _grow(first, length, cells):
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


def _chart_cover():
    """XYZ (any scale) whose chart the black pass's grid must contain: the spectral
    locus, the corners of ACES AP0 cut at Y = 0 (AP0's blue primary has Y < 0) and
    the Z axis. (The X axis cannot be added in this chart family: imaginary colours
    redder than AP0 are clamped to the chart's edge -- in gamut, Y kept, hue
    approximate.)"""
    locus = colorimetry.spectral_locus_XYZ(1.0, np.arange(360.0, 781.0))
    ap0 = np.linalg.inv(colorimetry.matrix_XYZ_to_RGB("ACES2065-1")).T  # rows: primaries
    cut = [ap0[a] + ap0[a, 1] / (ap0[a, 1] - ap0[2, 1]) * (ap0[2] - ap0[a]) for a in (0, 1)]
    points = np.concatenate([locus, ap0[:2], np.array(cut), [[0.0, 0.0, 1.0]]])
    return points / np.abs(points).sum(axis=1, keepdims=True)


@cache.memoize(maxsize=16)
def _black_plan(display, size):
    """The black pass's chart: a matrix P such that ``XYZ_TO_xyY(P XYZ)`` gives the
    Lut3D's coordinates (u_a, u_b) directly, uniform in a chromaticity chart where
    the display's triangle is canonical -- edges c_i = 0 on u_a = const, c_j = 0 on
    u_b = const, c_k = 0 on a diagonal u_a - u_b = const, all through nodes -- and
    Y unchanged (third output).

    With S = lam Y + mu c_j (the normaliser) and u_b = Y / S, u_b is affine in c_j / S;
    u_a = s lam w_i c_i / S + beta. Of the channel assignments and node positions
    that keep S > 0 and the chart of :func:`_chart_cover` inside [0, 1]^2, the one
    with the most cells across the triangle is taken. Returns (P, cells across).
    """
    cells = size - 1
    M = colorimetry.matrix_XYZ_to_RGB(display)
    w = _luminance(display)
    cover = _chart_cover()
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
                    S = cover @ S_row
                    if np.any(S <= 1e-9):
                        continue
                    u_b = cover[:, 1] / S
                    if u_b.max() > 1.0 or u_b.min() < 0.0:
                        continue
                    s = np.sign((lam * w[j] + mu) * lam / mu) * (n1 - n0) / cells
                    u_a = s * lam * w[i] * (cover @ M[i]) / S
                    beta = np.ceil(-u_a.min() * cells - 1e-9) / cells
                    if u_a.max() + beta > 1.0 + 1e-12:
                        continue
                    P = np.array([s * lam * w[i] * M[i] + beta * S_row, [0.0, 1.0, 0.0], S_row])
                    P[2] -= P[0] + P[1]
                    best = (n1 - n0, P)
    if best is None:
        raise ValueError(f"clip LUT size {size} is too small to chart {CHART_COVERS}")
    return best[1], best[0]


def _shaper_values(nodes, lo, hi, along=None):
    """Lut1D entries over [lo, hi] (SHAPER_LENGTH samples): the grid coordinate
    k / (size - 1) of the value, piecewise linear between the ``nodes`` (in the
    variable ``along(value)`` when given: e.g. the display encoding)."""
    x = np.linspace(lo, hi, SHAPER_LENGTH)
    grid = np.linspace(0.0, 1.0, len(nodes))
    if along is not None:
        x, nodes = along(x), along(nodes)
    return np.interp(x, nodes, grid)


def _encode(values, display):
    """Display encoding (the OCIO op the config uses), float64 out."""
    a = np.asarray(values, dtype=np.float64)
    flat = np.repeat(a.reshape(-1, 1), 3, axis=1)
    encoded = apply(display_encoding_transform(display), flat)[:, 0]
    return encoded.astype(np.float64).reshape(a.shape)


def _white_nodes(size, display):
    """Node values of each axis of the white pass, (3, size) display-linear: below 1
    at working-encoding code values 1 - (1 - k/n)^WHITE_POWER (shared), above 1
    growing geometrically up to the channel's largest value 1 / w_i (w: the
    display's luminance row; a colour with Y <= 1 and no negative channel has
    c_i <= 1 / w_i). Returns (nodes, tops), tops[i] the last node of axis i."""
    cells = size - 1
    inside = max(2, int(round(cells * WHITE_INSIDE)))
    code = 1.0 - (1.0 - np.linspace(0.0, 1.0, inside + 1)) ** WHITE_POWER
    below = apply(
        ocio_ops.inverse([display_encoding_transform(WORKING_ENCODING)]),
        np.repeat(code[:, None], 3, axis=1),
    )[:, 0].astype(np.float64)
    below[0], below[-1] = 0.0, 1.0
    # a little above 1 / w_i: float32 round-off of the matrix in front stays inside
    tops = 1.001 / _luminance(display)
    nodes = np.array(
        [
            np.concatenate(
                [below, 1.0 + np.cumsum(_grow(WHITE_FIRST_STEP, top - 1.0, cells - inside))]
            )
            for top in tops
        ]
    )
    return nodes, tops


@dataclass(frozen=True, eq=False)
class ClipLUT:
    """The baked constant-lightness clip for one display (see :func:`clip_lut`).

    The clip of Smits & Meyer (1990), Section 3.2, factored as U o L
    (:func:`clip_black_faces_RGB`, :func:`clip_white_faces_RGB`). Frozen; its arrays
    are read-only. Instances come from :func:`clip_lut`.

    Attributes
    ----------
    display : str
        The display (a key of :data:`ocio_thinfilm.registry.DISPLAYS`).
    size : int
        Edge length of the black pass's Lut3D, in [9, 129].
    black : numpy.ndarray
        float64, (size, size, size, 3), index [u_a][u_b][Y]: the chart coordinates
        (u_a, u_b) of L(X), stored as z = sign (u - origin) (``frame``), and Y (constant
        along the Y axis; the identity on Y); half floats rounded to the 16-bit grid in
        [0, 1].
    white : numpy.ndarray
        float64, (n, n, n, 3) with n = :func:`white_size` (size), index [R][G][B] over
        the nodes of :func:`_white_nodes`: sRGB-encoded code values of U(c) (above
        white: its continuation) / :data:`WHITE_SCALE`, on the 16-bit grid in [0, 1].
    white_shaper : numpy.ndarray
        float64, (:data:`SHAPER_LENGTH`, 3): the Lut1D over c_i / tops[i] in front of
        ``white``, grid coordinates on the 16-bit grid.
    chart : numpy.ndarray
        float64, (3, 3): the matrix taking CIE XYZ (D65 white at Y = 1) to the
        black pass's chart before ``XYZ_TO_xyY``.
    tops : numpy.ndarray
        float64, (3,): largest display-linear value of each channel the white pass
        covers, just above 1 / (the channel's luminance weight).
    frame : numpy.ndarray
        float64, (2, 2): ``[origin, sign]`` of the stored coordinates
        z = sign (u - origin) (:func:`_face_frame`); the black core's matrix maps them
        back to (u_a, u_b).

    Examples
    --------
    The chain has eight ops: the XYZ limit, the chart matrix, XYZ_TO_xyY, the
    pre-clip (Y <= 1), the black core, xyY -> XYZ, the matrix to display RGB and the
    white core:

    >>> len(clip_lut("sRGB").transforms())
    8
    """

    display: str
    size: int
    black: np.ndarray
    white: np.ndarray
    white_shaper: np.ndarray
    chart: np.ndarray
    tops: np.ndarray
    frame: np.ndarray

    @property
    def name(self) -> str:
        return f"Constant-Lightness Clip {self.display}"

    def black_core(self) -> ocio_ops.Transform:
        """CLF-writable black pass: the Lut3D; chart (u_a, u_b, Y) in, the chart
        coordinates of L(X) and Y out."""
        name = f"{self.name} Black Faces"
        origin, sign = self.frame
        back = ocio_ops.matrix(np.diag([sign[0], sign[1], 1.0]), offset=(origin[0], origin[1], 0.0))
        return group(
            [lut3d_transform(self.black, bitdepth="uint16"), back],
            name=name,
            id=transform_id("Gamut_Map", name),
            description=(
                f"Smits & Meyer 1990 constant-lightness clip into "
                f"{self.display} (Section 3.2), the part against the "
                "gamut faces through black (R, G, B >= 0): a "
                f"{self.size}^3 tetrahedral Lut3D over a projective "
                "chart of the chromaticity (the primaries' triangle on "
                "grid and split planes) and Y; the map is homogeneous, "
                "so it moves the chromaticity and keeps Y. See "
                "ocio_thinfilm.lut.clip_lut.ClipLUT."
            ),
            input_descriptor=(
                "(u_a, u_b, Y): XYZ_TO_xyY of a matrix of CIE-XYZ-D65, Y limited to [0, 1]"
            ),
            output_descriptor=(
                "(u_a, u_b, Y) of the black-faces clip: its chart coordinates and Y, for xyY_TO_XYZ"
            ),
        )

    def white_core(self) -> ocio_ops.Transform:
        """CLF-writable white pass: per-channel shaper, Lut3D, its scale and a clamp;
        display-linear c_i / tops[i] in (no negative channel), display code values out."""
        name = f"{self.name} White Faces"
        n = self.white.shape[0]
        ops = [
            lut1d_transform(self.white_shaper, bitdepth="uint16"),
            lut3d_transform(self.white, bitdepth="uint16"),
            ocio_ops.matrix(np.eye(3) * WHITE_SCALE),
            ocio_ops.range_(0.0, 1.0),
        ]
        return group(
            ops,
            name=name,
            id=transform_id("Gamut_Map", name),
            description=(
                f"Smits & Meyer 1990 constant-lightness clip into "
                f"{self.display} (Section 3.2), the part against the "
                "gamut faces through white (R, G, B <= 1), followed "
                f"by the sRGB encoding: a {n}^3 tetrahedral "
                "Lut3D over display RGB whose nodes below 1 sit at "
                "sRGB-encoded values, so in-gamut colours are "
                "reproduced exactly; nodes above white hold the "
                "clip's continuation. See ocio_thinfilm.lut.clip_lut.ClipLUT."
            ),
            input_descriptor=f"{self.display} display-linear RGB, each channel "
            "divided by 1.001 / its luminance weight, no "
            "negative channel, Y <= 1",
            output_descriptor=f"{self.display} display RGB, clipped, sRGB-encoded "
            "(IEC 61966-2-1 piecewise curve)",
        )

    def transforms(
        self, black: ocio_ops.Transform | None = None, white: ocio_ops.Transform | None = None
    ) -> list[ocio_ops.Transform]:
        """The whole clip as a list of OCIO transforms, CIE-XYZ-D65 -> display RGB in
        [0, 1], sRGB-encoded (:data:`WORKING_ENCODING`); ``black`` / ``white`` replace
        the CLF-writable cores (e.g. by FileTransforms in the config)."""
        M = colorimetry.matrix_XYZ_to_RGB(self.display)
        to_white = np.diag(1.0 / self.tops) @ M @ np.linalg.inv(self.chart)
        return [
            xyz_limit_transform(),
            ocio_ops.matrix(self.chart),
            xyY_forward_transform(),
            ocio_ops.range_(0.0, 1.0),  # the pre-clip: Y <= 1 (the chart is in [0, 1]^2)
            self.black_core() if black is None else black,
            xyY_inverse_transform(),
            ocio_ops.matrix(to_white),
            self.white_core() if white is None else white,
        ]


def _chart_to_XYZ(P, ua, ub):
    """XYZ at Y = 1 of the chart points (u_a, u_b) of ``P`` (u_b = Y / S -> 0: ever
    larger chroma)."""
    S = 1.0 / np.maximum(ub, 1e-9)
    return np.c_[ua * S, np.ones_like(S), S - ua * S - 1.0] @ np.linalg.inv(P).T


def _black_map(display, P, ua, ub):
    """L in the chart: chart coordinates (N, 2) of L(X) for the chart points (u_a, u_b),
    and whether each point is inside the gamut (L leaves it where it is)."""
    M = colorimetry.matrix_XYZ_to_RGB(display)
    with np.errstate(all="ignore"):
        rgb = _chart_to_XYZ(P, ua, ub) @ M.T
        chart = clip_black_faces_RGB(rgb, display) @ np.linalg.inv(M).T @ P.T
        uv = chart[:, :2] / chart.sum(axis=1, keepdims=True)
    # nodes on the triangle's edges count as inside (float64 round-off of their zero)
    return uv, rgb.min(axis=1) >= -1e-9 * np.abs(rgb).max(axis=1)


def _cross(a, b):
    """z component of the cross product of 2D vectors (last axis 2)."""
    a, b = np.asarray(a), np.asarray(b)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _chart_triangle(display, P):
    """The display's primaries in the chart of ``P``: the triangle's vertices (3, 2)."""
    primaries = np.linalg.inv(colorimetry.matrix_XYZ_to_RGB(display)).T @ P.T
    return primaries[:, :2] / primaries.sum(axis=1, keepdims=True)


def _convex_hull(points):
    """Vertices of the convex hull of 2D ``points``, counter-clockwise (Andrew's
    monotone chain)."""
    pts = sorted(map(tuple, np.asarray(points, dtype=np.float64)))

    def half(seq):
        out: list[tuple[float, ...]] = []
        for p in seq:
            while (
                len(out) >= 2
                and _cross(np.subtract(out[-1], out[-2]), np.subtract(p, out[-2])) <= 0
            ):
                out.pop()
            out.append(p)
        return out[:-1]

    return np.array(half(pts) + half(pts[::-1]))


def _inside_convex(points, hull):
    """Whether each of ``points`` (N, 2) lies inside the counter-clockwise ``hull``."""
    inside = np.ones(len(points), dtype=bool)
    for a, b in zip(hull, np.roll(hull, -1, axis=0), strict=True):
        inside &= _cross(b - a, points - a) >= 0.0
    return inside


def _project_triangle(p, V):
    """The nearest points of the triangle V (3, 2) to the points ``p`` (N, 2)."""
    lam = np.linalg.solve(np.array([V[1] - V[0], V[2] - V[0]]).T, (p - V[0]).T).T
    inside = (lam >= 0.0).all(axis=1) & (lam.sum(axis=1) <= 1.0)
    best, dist = None, None
    for a, b in ((0, 1), (1, 2), (2, 0)):
        e = V[b] - V[a]
        q = V[a] + np.clip((p - V[a]) @ e / (e @ e), 0.0, 1.0)[:, None] * e
        d = ((p - q) ** 2).sum(axis=1)
        if best is None:
            best, dist = q, d
        else:
            assert best is not None and dist is not None
            nearer = d < dist
            best[nearer], dist[nearer] = q[nearer], d[nearer]
    return np.where(inside[:, None], p, best)


def _fit_outside_nodes(display, P, size, exact, inside):
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
    V = _chart_triangle(display, P)
    # real colours only: inside the spectral locus (imaginary ones, e.g. AP0's corners,
    # would pull the nodes away from the monochromatic colours on the locus)
    real = colorimetry.spectral_locus_XYZ(1.0, np.arange(360.0, 781.0)) @ P.T
    hull = _convex_hull(real[:, :2] / real.sum(axis=1, keepdims=True))
    m = (n - 1) * FIT_DENSITY
    s = (np.arange(m) + 0.5) / m
    sa, sb = (a.ravel() for a in np.meshgrid(s, s, indexing="ij"))
    target, inside_s = _black_map(display, P, sa, sb)
    keep = ~inside_s & _inside_convex(np.c_[sa, sb], hull)
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
        return _uv(_chart_to_XYZ(P, a, b))

    h = 1e-6
    a, b = target[:, 0], target[:, 1]
    J = np.stack([uv(a + h, b) - uv(a - h, b), uv(a, b + h) - uv(a, b - h)], axis=-1) / (2 * h)
    metric = np.einsum("nki,nkj->nij", J, J)
    metric /= np.median(np.trace(metric, axis1=1, axis2=2))
    free = ~inside
    values = exact.copy()

    def interpolate(v):
        return np.einsum("nk,nkc->nc", weight, v[corner])

    def adjoint(r):
        out = np.zeros((n * n, 2))
        for k in range(3):
            for c in range(2):
                out[:, c] += np.bincount(corner[:, k], weight[:, k] * r[:, c], minlength=n * n)
        return out

    # step 1 / L: L bounds the gradient's Lipschitz constant (each sample's weights sum
    # to 1 and a node holds at most 6 cells of FIT_DENSITY^2 samples)
    lipschitz = 6 * FIT_DENSITY**2 * np.linalg.eigvalsh(metric).max() + FIT_DAMPING
    x_k = z = exact[free]
    t = 1.0
    for _ in range(FIT_ITERATIONS):
        values[free] = z
        r = np.einsum("nij,nj->ni", metric, interpolate(values) - target)
        grad = adjoint(r)[free] + FIT_DAMPING * (z - exact[free])
        x_next = _project_triangle(z - grad / lipschitz, V)
        t_next = 0.5 * (1.0 + np.sqrt(1.0 + 4.0 * t * t))
        z = x_next + (t - 1.0) / t_next * (x_next - x_k)
        x_k, t = x_next, t_next
    values[free] = x_k
    return values


def _uv(XYZ):
    """CIE 1976 u', v' of XYZ (N, 3)."""
    d = XYZ[:, 0] + 15.0 * XYZ[:, 1] + 3.0 * XYZ[:, 2]
    return np.c_[4.0 * XYZ[:, 0] / d, 9.0 * XYZ[:, 1] / d]


def _face_frame(V):
    """The black pass's stored coordinates z = sign * (u - origin) per chart axis: 0 on
    the face lying on u_a = const (resp. u_b = const) and >= 0 on the triangle, so a
    point of those faces is stored as 0 exactly, in 16-bit codes and half floats alike.
    Returns (origin (2,), sign (2,))."""
    origin, sign = np.zeros(2), np.ones(2)
    for axis in (0, 1):
        for a, b in ((0, 1), (1, 2), (2, 0)):
            if abs(V[a, axis] - V[b, axis]) < 1e-12:
                origin[axis] = V[a, axis]
                sign[axis] = 1.0 if V[:, axis].max() > origin[axis] + 1e-12 else -1.0
    return origin, sign


def _halves_inside(z, Vz, margin=2.0 * 0.5 / LUT_CODE_MAX):
    """Points ``z`` (N, 2) of the triangle ``Vz`` (3, 2), in the stored coordinates of
    :func:`_face_frame`, as the nearest pairs of half floats that stay in it: on the two
    faces z = 0 exactly, and ``margin`` inside the third (its points are not half
    floats; the 16-bit codes of the file sit within 7.6e-6 of the half floats).

    So the CPU (16-bit values) and a host that uploads half floats (Blender's viewport)
    see the same points of the faces, and none outside the gamut, whose negative
    channel the white pass would clamp (changing Y).
    """
    h = z.astype(np.float16)
    steps = [h]
    for direction in (np.inf, -np.inf):
        x = h
        for _ in range(2):
            x = np.nextafter(x, np.float16(direction))
            steps.append(x)
    grid = np.stack([s.astype(np.float64) for s in steps], axis=1)  # (N, 5, 2)
    cand = np.stack(np.broadcast_arrays(grid[:, :, None, 0], grid[:, None, :, 1]), axis=-1)
    cand = cand.reshape(len(z), -1, 2)
    ok = (cand >= 0.0).all(axis=-1)
    # the third face: the edge of Vz that lies on neither axis
    for a, b, c in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        e = Vz[b] - Vz[a]
        if abs(e[0]) > 1e-12 and abs(e[1]) > 1e-12:
            normal = np.array([-e[1], e[0]]) / np.hypot(*e)
            normal *= np.sign(normal @ (Vz[c] - Vz[a]))
            ok &= (cand - Vz[a]) @ normal >= margin
    dist = ((cand - z[:, None]) ** 2).sum(axis=-1)
    dist[~ok] = np.inf
    best = cand[np.arange(len(z)), dist.argmin(axis=1)]
    return np.where(np.isfinite(dist.min(axis=1))[:, None], best, h.astype(np.float64))


def _q16(values):
    """``values`` clipped to [0, 1] and rounded to the 16-bit grid."""
    # + 0.0: no negative zero, whose sign (and so the file's text) depends on the CPU
    return np.round(np.clip(values, 0.0, 1.0) * LUT_CODE_MAX) / LUT_CODE_MAX + 0.0


@cache.persistent(modules=("ocio_thinfilm.lut.clip_lut", "ocio_thinfilm.colour.colorimetry"))
def _black_nodes(display, size):
    """The black pass's (u_a, u_b) node values as stored, (size * size + 2, 2): the
    nodes' z = sign (u - origin) (L at the nodes, the outside ones fitted and rounded
    to half floats inside the triangle), then the rows origin and sign of
    :func:`_face_frame`. Memoised on disk (the fit takes seconds per display; the key
    covers this module's and the colorimetry's source and colour-science's version)."""
    P, _ = _black_plan(display, size)
    g = np.linspace(0.0, 1.0, size)
    ua, ub = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    uv, inside = _black_map(display, P, ua, ub)
    uv = _fit_outside_nodes(display, P, size, uv, inside)
    # stored as z = sign (u - origin): the faces on u_a / u_b = const at 0 exactly; the
    # outside nodes (on the faces) rounded to half floats inside the triangle, the
    # others (in-gamut identity nodes, on the grid) are half floats already
    V = _chart_triangle(display, P)
    origin, sign = _face_frame(V)
    origin = np.round(origin * (size - 1)) / (size - 1)  # on node lines by construction
    z = (uv - origin) * sign
    z[~inside] = _halves_inside(z[~inside], (V - origin) * sign)
    return np.concatenate([z, [origin], [sign]])


@cache.memoize(maxsize=16)
def _clip_lut(display, size, white_edge):
    P, _ = _black_plan(display, size)
    # black pass: constant along Y, whose output is Y itself
    stored = _black_nodes(display, size)
    z, origin, sign = stored[:-2], stored[-2], stored[-1]
    g = np.linspace(0.0, 1.0, size)
    black = np.empty((size, size, size, 3))
    black[..., :2] = z.reshape(size, size, 1, 2)
    black[..., 2] = g
    # white pass: RGB nodes -> U(c) (continued above white), sRGB-encoded / scale
    nodes, tops = _white_nodes(white_edge, display)
    n = nodes.shape[1]
    C = np.stack(np.meshgrid(*nodes, indexing="ij"), axis=-1).reshape(-1, 3)
    shaper = np.stack(
        [
            _shaper_values(nodes[i], 0.0, tops[i], along=lambda v: _encode(v, WORKING_ENCODING))
            for i in range(3)
        ],
        axis=1,
    )
    # the black pass: half floats first, then the 16-bit grid (see _halves_inside)
    lut = ClipLUT(
        display=display,
        size=size,
        black=_q16(black.astype(np.float16).astype(np.float64)),
        white=_white_codes(C, display).reshape(n, n, n, 3),
        white_shaper=_q16(shaper),
        chart=P,
        tops=tops,
        frame=np.array([origin, sign]),
    )
    for array in (lut.black, lut.white, lut.white_shaper, lut.chart, lut.tops, lut.frame):
        array.setflags(write=False)
    return lut


def clip_lut(
    display: registry.DisplayLike = "sRGB", size: int = CLIP_SIZE, white_edge: int | None = None
) -> ClipLUT:
    """The baked clip LUTs for ``display`` (cached): both passes, from
    :func:`clip_black_faces_RGB` and :func:`clip_white_faces_RGB`, whose composition
    is :func:`ocio_thinfilm.colour.clip.clip_RGB` exactly.

    Parameters
    ----------
    display : str or registry display, optional
        A display of :data:`ocio_thinfilm.registry.DISPLAYS` or its name (default
        ``"sRGB"``).
    size : int, optional
        Edge length of the black pass's Lut3D, an integer in [9, 129] (default
        :data:`CLIP_SIZE`, 65).
    white_edge : int, optional
        Edge length of the white pass's Lut3D, an integer in [7, 129] (default
        :func:`white_size` of ``size``).

    Returns
    -------
    ClipLUT
        Read-only arrays; the same object for repeated calls in a process.

    Raises
    ------
    ValueError
        For an unknown display, a size outside [9, 129] or a white_edge outside
        [7, 129].

    References
    ----------
    Smits & Meyer (1990), Section 3.2.

    Examples
    --------
    For sRGB the smallest luminance weight is 0.0722 (Rec.709 blue), so the white
    pass's blue axis runs to 1.001 / 0.07219 = 13.87:

    >>> lut = clip_lut("sRGB")
    >>> lut.size, lut.black.shape, lut.white.shape, lut.white_shaper.shape
    (65, (65, 65, 65, 3), (53, 53, 53, 3), (16384, 3))
    >>> lut.tops.round(2).tolist()
    [4.71, 1.4, 13.87]
    >>> lut.black.flags.writeable
    False
    """
    name = registry.as_display(display, hdr=False).name
    size = check_size(size, 9, 129, "size")
    white_edge = white_size(size) if white_edge is None else white_edge
    return _clip_lut(name, size, check_size(white_edge, 7, 129, "white_edge"))


def working_decoding_transform() -> ocio_ops.Transform:
    """sRGB code values (the white pass's output) -> display-linear RGB.

    The inverse of :func:`ocio_thinfilm.lut.display_transforms.display_encoding_transform`
    for :data:`WORKING_ENCODING`: the IEC 61966-2-1 sRGB EOTF, ``V / 12.92`` up to
    V = 0.04045 and ``((V + 0.055) / 1.055) ** 2.4`` above.

    Returns
    -------
    PyOpenColorIO.GroupTransform
        An inverse-direction group holding the sRGB encoding.

    References
    ----------
    IEC 61966-2-1:1999, Multimedia systems and equipment -- Colour measurement and
    management -- Default RGB colour space -- sRGB.

    Examples
    --------
    Code 0.5 decodes to (0.555 / 1.055) ** 2.4 = 0.2140, code 0.04045 (the end of
    the linear segment) to 0.04045 / 12.92 = 0.00313:

    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> out = apply(working_decoding_transform(), [[0.0, 0.5, 1.0], [0.04045, 0.04045, 0.04045]])
    >>> out[0].astype(float).round(3).tolist(), round(float(out[1, 0]), 5)
    ([0.0, 0.214, 1.0], 0.00313)
    """
    return ocio_ops.inverse([display_encoding_transform(WORKING_ENCODING)])


def clip_transform(
    display: registry.DisplayLike = "sRGB", size: int = CLIP_SIZE
) -> ocio_ops.Transform:
    """OCIO transform CIE-XYZ-D65 -> display-linear RGB in [0, 1], constant-lightness
    clipped: :meth:`ClipLUT.transforms` (range limit, chart, the black-faces pass, the
    white-faces pass, which ends in display code values), then the display's EOTF.

    Parameters
    ----------
    display : str or registry display
        A display of the registry (``"sRGB"``, ``"Display P3"``, ``"Rec.2020"``).
    size : int
        Edge of both 3D LUTs, in [9, 129].

    Returns
    -------
    PyOpenColorIO.GroupTransform

    References
    ----------
    Smits & Meyer (1990), Section 3.2: the clip moves an out-of-gamut colour at
    constant luminance Y towards the grey of that Y until it is inside the display's
    RGB parallelepiped.

    Examples
    --------
    An 18 % grey of the display white passes through (to the LUTs' accuracy); the
    spectral colour at 520 nm, far outside sRGB, comes out in gamut with its Y = 0.3
    (Y = 0.2126 R + 0.7152 G + 0.0722 B in sRGB):

    >>> import numpy as np
    >>> from ocio_thinfilm.colour import colorimetry
    >>> from ocio_thinfilm.lut.ocio_ops import apply
    >>> grey = 0.18 * np.array([0.95047, 1.0, 1.08883])
    >>> green = colorimetry.spectral_locus_XYZ(0.3, np.array([520.0]))[0]
    >>> grey_rgb, green_rgb = apply(clip_transform("sRGB"), [grey, green])
    >>> [round(float(v), 2) for v in grey_rgb]
    [0.18, 0.18, 0.18]
    >>> bool(green_rgb.min() >= 0.0 and green_rgb.max() <= 1.0)
    True
    >>> round(float(green_rgb @ [0.2126, 0.7152, 0.0722]), 3)
    0.3
    """
    lut = clip_lut(display, size)
    # the clamp only removes float32 round-off of the EOTF (1.0 -> 1.00002 through
    # OCIO's fast pow): the code values are in [0, 1] already
    return group(
        lut.transforms() + [working_decoding_transform(), ocio_ops.range_(0.0, 1.0)],
        name=lut.name,
        id=transform_id("Gamut_Map", lut.name),
    )
