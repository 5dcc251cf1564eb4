"""Precomputed tables (paper Section 2.1) and the 3D LUT of the clip, as OCIO transforms.

Stage 4 of the pipeline. INTERFACE CONTRACT (the renderer and the report use exactly
these names; the implementation is filled in by the LUT/config work):

- ``BUILT``: list of strings, one per table or LUT *computed* in this process
  (e.g. ``"film:phase-change:<size>"``, ``"morpho:<size>"``, ``"clip3d:sRGB:<size>"``);
  cached results are not re-appended. Tests use it to prove a scene builds only
  what it needs.
- ``film_table(kind, ...) -> Table1D`` for ``kind`` in ``("phase-change", "no-phase-change")``:
  pixel value = optical thickness t' = n t cos(theta_t) in micrometres -> exact XYZ.
- ``morpho_table(...) -> Table1D``: pixel value = cos(theta) of the viewing angle
  (facing ratio, N.V) -> exact XYZ of the Morpho multilayer (Eq. 9 + 14).
- ``Table1D``: ``.kind``, ``.values`` (XYZ array), ``.transform()`` (an OCIO transform
  from the pixel encoding, all three channels equal, to CIE-XYZ-D65), ``.lookup(x)``
  (numpy evaluation of the same interpolation).
- ``clip_transform(display, size=...)``: OCIO transform CIE-XYZ-D65 -> display-linear
  RGB, constant-lightness clipped (the 3D LUTs with their charts).
- ``view_transform(display, view)``: OCIO transform CIE-XYZ-D65 -> display-encoded RGB
  for ``view`` in ``VIEWS``.
- ``apply(transform, pixels)``: apply an OCIO transform to a float32 (..., 3) array
  with OCIO's CPU processor; returns a new array.

Design (measured; see ``benchmarks/bench_luts.py``)
---------------------------------------------------
1D tables
    The thickness tables are indexed through a log shaper (OCIO ``LogAffineTransform``,
    CLF ``Log``): ``u = log2(1 + t'/t0) / log2(1 + t'_max/t0)`` with ``t0 = 1 um`` and
    ``t'_max = 100 um``, then a linear ``Lut1D`` of :data:`FILM_SIZE` entries. At
    100 um the band-limited film colour is the incoherent grey (half the
    illuminant), so the LUT's own clamp beyond the range gives the right limit: no
    NaN, no wrap-around; negative thicknesses give black (t' = 0). The Morpho table
    is uniform in cos(theta) over [0, 1] (the clamp gives grazing / normal incidence
    outside).
3D clip LUT (two passes; see the section "3D clip LUT" below)
    The clip factors exactly as U o L (faces through black, then through white,
    along the same constant-Y ray). L is one Lut3D over a projective chart of the
    chromaticity (XYZ_TO_xyY of 0.1 X, Y, 0.1 Z, the primaries' triangle on grid and
    tetrahedral split planes) and Y, exactly linear along Y; it outputs display RGB.
    U is one Lut3D over that RGB, nodes below 1 at display-encoded values, storing
    display code values: in-gamut colours are reproduced exactly and nothing after
    the LUT amplifies its rounding (half-float GPU textures included). Chain:
    Range, matrix, XYZ_TO_xyY, matrix, Lut1D + Lut3D, Lut1D + Lut3D -- fewer and
    cheaper ops than the ACES gamut compression view. Accuracy, speed and the
    rejected designs: ``benchmarks/bench_luts.py`` and reports/report.md.

Added names (beyond the contract): :func:`clip_lut` / :class:`ClipLUT` (the LUT data),
:func:`clip_black_faces_RGB`, :func:`clip_white_faces_RGB`, :func:`view_linear_transform`,
:func:`display_matrix_transform`, :func:`display_encoding_transform`,
:func:`xyz_limit_transform`, :func:`group`, :func:`quantize`, :func:`transform_id`,
``Table1D.rgb(display)`` (per-display clipped variant), ``Table1D.shaper(x)``. The
test colours the tests, benchmarks and report evaluate against live in
:mod:`ocio_thinfilm.evaluation.colours`, outside the shipped path.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field

import numpy as np

from ocio_thinfilm import cache, registry
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import ocio_ops
# Re-exported (the contract above names them); the one implementation is in ocio_ops.
from ocio_thinfilm.lut.ocio_ops import (VENDOR, apply, group, lut1d_transform, lut3d_transform,  # noqa: F401
                       quantize, transform_id)

__all__ = [
    "BUILT",
    "VIEWS",
    "FILM_KINDS",
    "FILM_SIZE",
    "FILM_T0_UM",
    "FILM_TMAX_UM",
    "MORPHO_SIZE",
    "CLIP_SIZE",
    "SPECTRAL_STEP",
    "Table1D",
    "film_table",
    "morpho_table",
    "clip_lut",
    "clip_transform",
    "view_transform",
    "display_matrix_transform",
    "display_encoding_transform",
    "apply",
    "group",
    "xyz_limit_transform",
    "finite_limit_transform",
    "xyY_forward_transform",
    "clip_black_faces_RGB",
    "clip_white_faces_RGB",
    "transform_id",
    "quantize",
]

#: The views of every display (:mod:`.registry`).
VIEWS = registry.VIEWS

#: Tables and LUTs computed in this process (cache hits are not re-appended).
BUILT: list[str] = []

FILM_KINDS = colorimetry.FILM_KINDS
#: Default entries of a thickness table (log-shaped, 0-100 um); max dE2000 <= 0.05.
FILM_SIZE = 8192
#: Log shaper knee t0 and the end of the thickness range, micrometres.
FILM_T0_UM = 1.0
FILM_TMAX_UM = 100.0
#: Default entries of the Morpho angle table (uniform in cos(theta)).
MORPHO_SIZE = 1024
#: Wavelength step (nm) of the spectra behind the tables (band-limited integration).
SPECTRAL_STEP = 5.0

_LOCK = threading.RLock()


# --------------------------------------------------------------------------- #
# 1D tables
# --------------------------------------------------------------------------- #
@dataclass(frozen=True, eq=False)
class Table1D:
    """A 1D table: pixel value (all three channels equal) -> exact XYZ.

    ``kind``: ``"phase-change"``, ``"no-phase-change"`` or ``"morpho"``.
    ``values``: (size, 3) XYZ at the table's nodes. ``encoding``: ``"log"``
    (thickness in um through the log shaper, nodes at ``u = i / (size - 1)``) or
    ``"linear"`` (pixel in [domain_min, domain_max] spread uniformly over the nodes).
    """

    kind: str
    values: np.ndarray
    encoding: str
    domain_min: float
    domain_max: float
    t0: float = 0.0
    description: str = ""
    name: str = ""
    nodes: np.ndarray = field(default=None, repr=False)

    @property
    def size(self) -> int:
        return int(self.values.shape[0])

    # -- numpy path -------------------------------------------------------- #
    def shaper(self, x) -> np.ndarray:
        """Normalised table coordinate u in [0, 1] (clamped) of pixel values ``x``."""
        x = np.nan_to_num(np.asarray(x, dtype=np.float64), nan=0.0)
        if self.encoding == "log":
            t = np.maximum(x, 0.0)
            u = np.log1p(np.minimum(t, 1e30) / self.t0) / np.log1p(self.domain_max / self.t0)
        else:
            u = (x - self.domain_min) / (self.domain_max - self.domain_min)
        return np.clip(u, 0.0, 1.0)

    def lookup(self, x) -> np.ndarray:
        """XYZ for pixel values ``x`` (any shape), by the same linear interpolation
        OCIO applies (returns shape ``x.shape + (3,)``, float64)."""
        u = self.shaper(x) * (self.size - 1)
        i = np.minimum(np.floor(u).astype(np.int64), self.size - 2)
        f = (u - i)[..., None]
        out = self.values[i] * (1.0 - f) + self.values[i + 1] * f
        if self.encoding == "log":  # negative and NaN thickness: black (as through OCIO)
            x = np.asarray(x)
            out[(x < 0) | np.isnan(x)] = 0.0
        return out

    # -- OCIO path --------------------------------------------------------- #
    def shaper_transform(self):
        """OCIO transform: pixel value -> u in [0, 1] (before the LUT's clamp)."""
        ocio = ocio_ops.module()
        if self.encoding == "log":
            t = ocio.LogAffineTransform()
            t.setBase(2.0)
            scale = 1.0 / np.log2(1.0 + self.domain_max / self.t0)
            t.setLogSideSlopeValue([scale] * 3)
            t.setLogSideOffsetValue([0.0] * 3)
            t.setLinSideSlopeValue([1.0 / self.t0] * 3)
            t.setLinSideOffsetValue([1.0] * 3)
            return t
        span = self.domain_max - self.domain_min
        return ocio_ops.matrix(np.eye(3) / span, [-self.domain_min / span] * 3)

    def lut_transform(self):
        return lut1d_transform(self.values)

    def _black_node(self) -> bool:
        """A thickness table whose t' = 0 entry is not black (no phase change: white)
        gets a black node in front of it, so negative, -inf and NaN thicknesses give
        black through OCIO as well (the LUT's clamp lands on that node)."""
        return self.encoding == "log" and bool(np.any(self.values[0] != 0.0))

    def transform(self):
        """OCIO transform from the pixel encoding to CIE-XYZ-D65 (a GroupTransform
        with CLF metadata: shaper, then the Lut1D)."""
        ops = [self.lut_transform()]
        if self._black_node():
            # Nodes i/(n-1) move to (i+1)/n, behind a black node at 0: t' >= 0 is
            # unchanged, t' < 0 (the log goes negative), -inf and NaN give black;
            # only -0.6 nm < t' < 0 blends towards the t' = 0 colour.
            n = self.size
            shaper = self.shaper_transform()
            shaper.setLogSideSlopeValue([v * (n - 1) / n for v in
                                         shaper.getLogSideSlopeValue()])
            shaper.setLogSideOffsetValue([1.0 / n] * 3)
            values = np.vstack([np.zeros((1, 3)), self.values])
            ops = [shaper, lut1d_transform(values)]
        elif self.encoding == "log":
            # Negative thickness: log of (1 + t/t0) < 1 is negative -> clamped to
            # u = 0 by the LUT; t <= -t0 is clamped by OCIO's log to a tiny argument.
            ops.insert(0, self.shaper_transform())
        elif (self.domain_min, self.domain_max) != (0.0, 1.0):
            ops.insert(0, self.shaper_transform())
        return group(ops, name=self.name, id=transform_id("Input", self.name),
                     description=self.description,
                     input_descriptor=self.input_descriptor,
                     output_descriptor="CIE-XYZ-D65 (perfect reflector Y = 1)")

    @property
    def input_descriptor(self) -> str:
        if self.kind == "morpho":
            return "cos(theta): facing ratio N.V, all channels equal"
        return "optical thickness t' = n t cos(theta_t) in micrometres, all channels equal"

    def rgb(self, display: str = "sRGB", clipped: bool = True) -> np.ndarray:
        """Per-display variant: the nodes in display-linear RGB, constant-lightness
        clipped (``clipped=True``) or raw."""
        rgb = colorimetry.XYZ_to_RGB(self.values, display)
        return clip.clip_RGB(rgb, display) if clipped else rgb


def _check_size(size, minimum=2, maximum=1 << 20, what="size"):
    if isinstance(size, bool) or not isinstance(size, (int, np.integer)):
        raise ValueError(f"{what} must be an integer, got {size!r}")
    if not minimum <= size <= maximum:
        raise ValueError(f"{what} must be in [{minimum}, {maximum}], got {size}")
    return int(size)


def _check_positive(name, value):
    value = float(value)
    if not np.isfinite(value) or value <= 0:
        raise ValueError(f"{name} must be a positive finite number, got {value:g}")
    return value


@cache.memoize(maxsize=32)
def _film_table(kind, size, tmax_um, t0_um, step):
    u = np.linspace(0.0, 1.0, size)
    t_um = t0_um * np.expm1(u * np.log1p(tmax_um / t0_um))
    t_um[-1] = tmax_um
    values = colorimetry.film_XYZ(t_um * 1000.0, kind, step=step)
    BUILT.append(f"film:{kind}:{size}")
    name = f"Thin Film {'Phase-Change' if kind == 'phase-change' else 'No-Phase-Change'} Thickness"
    values.setflags(write=False)
    t_um.setflags(write=False)
    return Table1D(kind=kind, values=values, encoding="log", domain_min=0.0,
                   domain_max=float(tmax_um), t0=float(t0_um), nodes=t_um, name=name,
                   description=(f"Smits & Meyer 1990 Eq. {7 if kind == 'phase-change' else 8}: "
                                f"exact XYZ (D65, CIE 1931 2 deg, band-limited {step:g} nm) of a "
                                f"{kind} thin film against optical thickness 0-{tmax_um:g} um; "
                                f"log2 shaper (t0 = {t0_um:g} um), {size}-entry Lut1D."))


def film_table(kind: str = "phase-change", size: int = FILM_SIZE, *,
               max_thickness_um: float = FILM_TMAX_UM, t0_um: float = FILM_T0_UM,
               step: float = SPECTRAL_STEP) -> Table1D:
    """Thickness table of the paper's single film (Eq. 7 / Eq. 8).

    Pixel value = optical thickness t' in micrometres (all channels equal) -> the
    film's exact XYZ, the perfect reflector at Y = 1 under D65. Nodes are log-spaced
    (see the module docstring); beyond ``max_thickness_um`` the table holds its last
    entry, the incoherent grey.
    """
    if kind not in FILM_KINDS:
        raise ValueError(f"film kind must be one of {FILM_KINDS}, got {kind!r}")
    size = _check_size(size)
    tmax = _check_positive("max thickness (um)", max_thickness_um)
    t0 = _check_positive("t0 (um)", t0_um)
    step = _check_positive("spectral step (nm)", step)
    with _LOCK:
        return _film_table(kind, size, tmax, t0, step)


@cache.memoize(maxsize=8)
def _morpho_table(size, step):
    c = np.linspace(0.0, 1.0, size)
    theta = np.degrees(np.arccos(c))
    values = colorimetry.morpho_XYZ(theta, step=step)
    BUILT.append(f"morpho:{size}")
    values.setflags(write=False)
    c.setflags(write=False)
    return Table1D(kind="morpho", values=values, encoding="linear", domain_min=0.0,
                   domain_max=1.0, nodes=c, name="Thin Film Morpho Iridescence",
                   description=(f"Smits & Meyer 1990 Eq. 9 + 14: exact XYZ (D65, CIE 1931 2 deg, "
                                f"band-limited {step:g} nm) of the Morpho wing multilayer against "
                                f"cos(theta) (facing ratio N.V) in [0, 1]; {size}-entry Lut1D."))


def morpho_table(size: int = MORPHO_SIZE, *, step: float = SPECTRAL_STEP) -> Table1D:
    """Angle table of the Morpho multilayer (Eq. 9 + 14): pixel value = cos(theta) of
    the viewing angle (N.V) -> exact XYZ. Values outside [0, 1] are clamped
    (grazing / normal incidence)."""
    size = _check_size(size)
    step = _check_positive("spectral step (nm)", step)
    with _LOCK:
        return _morpho_table(size, step)


# --------------------------------------------------------------------------- #
# 3D clip LUT: the faces through black, then the faces through white
# --------------------------------------------------------------------------- #
# The clip moves a colour along its constant-Y ray towards the grey Y W until it is
# inside all six faces: t = min(t_black, t_white). It therefore factors exactly as
# clip = U o L, L clipping only against R, G, B >= 0 and U only against R, G, B <= 1,
# both along the same ray (paper, Section 3.2; :mod:`ocio_thinfilm.colour.clip`).
#
# Pass 1, L, is homogeneous of degree 1: over a projective chart of the
# chromaticities and Y it is exactly linear along Y, so dark colours keep their
# chromaticity however dark they are, and far-out saturated colours (Y a small
# difference of large RGB values) keep an exact Y axis. The primaries' triangle sits
# on grid and tetrahedral split planes. It outputs display-linear RGB of L(X), which
# has no negative channel any more.
#
# Pass 2, U, works on that RGB directly: every face, the white point and the planes
# R = G, G = B, R = B where the binding face changes are grid or split planes; below
# 1 the grid nodes sit at sRGB-encoded values and the LUT stores sRGB code values, so
# the identity (every in-gamut colour) is reproduced exactly and the display encoding
# costs nothing (sRGB, Display P3) or one analytic op (Rec.2020). No gain follows a
# LUT, so the LUTs' rounding (16-bit files, half-float GPU textures) is never
# amplified. Design notes and measurements: docs/gamut_map.md.
#: Default edge length of both clip LUTs.
CLIP_SIZE = 65
#: The black pass's chart covers these colours (with a uniform grid): the spectral
#: locus 360-780 nm, the ACES AP0 gamut with Y >= 0 and the Z axis (anything else is
#: clamped to the grid's edge and still lands in gamut with its Y).
CHART_COVERS = "spectral locus 360-780 nm, ACES AP0 (Y >= 0) and pure Z"
#: Largest ratio of u_b = Y / S across the primaries' triangle (the chart's bend).
CHART_BEND = 6.0
#: The black pass's Y nodes are Y_top (k / (size - 1)) ** Y_POWER: uniform in
#: Y^(1/3) ~ L*, with node size - 2 at Y = 1 (see :func:`_y_top`).
Y_POWER = 3.0
#: Share of each axis of the white pass spent on [0, 1] (grid nodes at encoded
#: values 1 - (1 - k/n)^WHITE_POWER: denser towards white), the rest growing
#: geometrically from WHITE_FIRST_STEP above 1 up to the brightest black-clipped
#: channel, 1 / min(luminance weight).
WHITE_INSIDE = 32 / 64
WHITE_POWER = 2.0
WHITE_FIRST_STEP = 0.002
#: Entries of the Lut1D shapers in front of each Lut3D.
SHAPER_LENGTH = 32768
#: The white pass works in (and its LUT outputs) the sRGB piecewise encoding: its
#: linear toe keeps the grid and the shaper accurate near black. Displays with
#: another encoding (Rec.2020: BT.1886, a pure power with infinite slope at black)
#: decode it with OCIO's analytic op and encode their own (for sRGB and Display P3
#: the pair cancels in OCIO's optimiser).
WORKING_ENCODING = "sRGB"
#: 16-bit LUT files: values are stored as codes of this maximum.
LUT_CODE_MAX = 65535
#: Components are limited to [0, LIMIT] before the chart (see :func:`xyz_limit_transform`).
LIMIT = 1e6


def xyz_limit_transform():
    """Clamp XYZ to [0, LIMIT] per component before the chart.

    No physical colour has a negative X, Y or Z (the CIE 1931 matching functions are
    non-negative), so this changes only non-physical inputs; it keeps the chart's
    normaliser positive and makes +-Inf finite (Y <= 0 gives black, as in the
    analytic clip).
    """
    return ocio_ops.range_(0.0, LIMIT)


def finite_limit_transform():
    """Clamp every component to [-LIMIT, LIMIT]: +-Inf become finite (and NaN, which
    OCIO's CPU Range sends to the lower bound)."""
    return ocio_ops.range_(-LIMIT, LIMIT)


def xyY_forward_transform():
    ocio = ocio_ops.module()
    return ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_XYZ_TO_xyY)


def _luminance(display):
    """Row w with Y = w . RGB (display-linear, RGB = 1 is Y = 1)."""
    return np.linalg.inv(colorimetry.matrix_XYZ_to_RGB(display))[1]


def clip_black_faces_RGB(RGB, display):
    """L: the clip against the faces R, G, B >= 0 only (float64, (N, 3) display RGB).

    ``Y <= 0`` gives black; otherwise the colour moves towards the grey of its Y until
    its smallest channel is 0 (unchanged when no channel is negative).
    """
    rgb = np.asarray(RGB, dtype=np.float64)
    with np.errstate(all="ignore"):  # non-finite inputs give non-finite rows, no warning
        Y = rgb @ _luminance(display)
        lo = rgb.min(axis=-1)
        t = np.where(lo < 0.0, Y / (Y - lo), 1.0)
        out = Y[..., None] + t[..., None] * (rgb - Y[..., None])
    out[Y <= 0.0] = 0.0
    return out


def clip_white_faces_RGB(RGB, display):
    """U = C o L o C with C(c) = 1 - c: the clip against R, G, B <= 1 only."""
    return 1.0 - clip_black_faces_RGB(1.0 - np.asarray(RGB, dtype=np.float64), display)


def _grow(first, length, cells):
    """``cells`` steps growing geometrically from ``first`` and summing to ``length``."""
    if cells <= 0:
        return np.zeros(0)
    if first * cells >= length:
        return np.full(cells, length / cells)
    lo, hi = 1.0, 64.0
    for _ in range(200):
        q = 0.5 * (lo + hi)
        total = first * (q ** cells - 1.0) / (q - 1.0)
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
                    P = np.array([s * lam * w[i] * M[i] + beta * S_row,
                                  [0.0, 1.0, 0.0],
                                  S_row])
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
    return apply(display_encoding_transform(display), flat)[:, 0].astype(np.float64).reshape(a.shape)


def _white_nodes(size, display):
    """Node values of every axis of the white pass (display-linear; grid nodes below 1
    at working-encoding code values 1 - (1 - k/n)^WHITE_POWER)."""
    cells = size - 1
    inside = max(2, int(round(cells * WHITE_INSIDE)))
    # the brightest black-clipped channel is 1 / (smallest luminance weight); a power
    # of two above it, so that white (1 / top) is exact in half floats
    top = 2.0 ** np.ceil(np.log2(1.0 / _luminance(display).min()))
    code = 1.0 - (1.0 - np.linspace(0.0, 1.0, inside + 1)) ** WHITE_POWER
    below = apply(ocio_ops.inverse([display_encoding_transform(WORKING_ENCODING)]),
                  np.repeat(code[:, None], 3, axis=1))[:, 0].astype(np.float64)
    below[0], below[-1] = 0.0, 1.0
    above = 1.0 + np.cumsum(_grow(WHITE_FIRST_STEP, top - 1.0, cells - inside))
    return np.concatenate([below, above]), top


def y_shaper_transform():
    """The black pass's third axis: Y^(1/3) (uniform in lightness), chromaticity axes
    unchanged -- an analytic op, exact in float on every GPU (a Lut1D shaper here
    would be stored in half floats by some hosts, placing colours only to 1/30 of a
    cell)."""
    ocio = ocio_ops.module()
    t = ocio.ExponentTransform([1.0, 1.0, Y_POWER, 1.0])
    t.setNegativeStyle(ocio.NEGATIVE_CLAMP)
    t.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return t


def _y_top(size):
    """Y of the black pass's last layer: the layer below it is Y = 1 exactly, the last
    holds white, so every colour brighter than the display white by 5 % or more is
    white exactly (Section 3.2: Y >= Y_W gives white)."""
    return ((size - 1) / (size - 2)) ** Y_POWER


@dataclass(frozen=True, eq=False)
class ClipLUT:
    """The baked constant-lightness clip for one display (see :func:`clip_lut`).

    ``black``: (size, size, size, 3) display-linear RGB of L(X) / ``top``, over the
    chart (u_a, u_b, Y^(1/3)) of :func:`_black_plan` (``chart``: its 3x3 matrix),
    rounded to half floats. ``white``: the same shape, display code values of U(c)
    over display RGB (:func:`_white_nodes`), rounded to 16 bits; ``white_shaper``:
    (SHAPER_LENGTH, 3) Lut1D entries (grid coordinates) in front of it;
    """

    display: str
    size: int
    black: np.ndarray
    white: np.ndarray
    white_shaper: np.ndarray
    chart: np.ndarray
    top: float

    @property
    def name(self) -> str:
        return f"Constant-Lightness Clip {self.display}"

    def black_core(self):
        """CLF-writable black pass: the Lut3D; chart in, display-linear RGB / top out."""
        name = f"{self.name} Black Faces"
        return group([lut3d_transform(self.black, bitdepth="half")],
                     name=name, id=transform_id("Gamut_Map", name),
                     description=(f"Smits & Meyer 1990 constant-lightness clip into "
                                  f"{self.display} (Section 3.2), the part against the "
                                  "gamut faces through black (R, G, B >= 0): a "
                                  f"{self.size}^3 tetrahedral Lut3D over a projective "
                                  "chart of the chromaticity (the primaries' triangle on "
                                  "grid and split planes) and Y^(1/3), exactly linear "
                                  "along Y. See ocio_thinfilm.lut.clip_lut.ClipLUT."),
                     input_descriptor=("(u_a, u_b, Y^(1/3)): XYZ_TO_xyY of a matrix of "
                                       "CIE-XYZ-D65, then the cube root of Y"),
                     output_descriptor=(f"{self.display} display-linear RGB of the "
                                        f"black-faces clip, divided by {self.top:g}"))

    def white_core(self):
        """CLF-writable white pass: per-channel shaper and Lut3D; display-linear RGB /
        top in (no negative channel), display code values out."""
        name = f"{self.name} White Faces"
        ops = [lut1d_transform(self.white_shaper, bitdepth="uint16"),
               lut3d_transform(self.white, bitdepth="uint16")]
        return group(ops, name=name, id=transform_id("Gamut_Map", name),
                     description=(f"Smits & Meyer 1990 constant-lightness clip into "
                                  f"{self.display} (Section 3.2), the part against the "
                                  "gamut faces through white (R, G, B <= 1), followed "
                                  f"by the sRGB encoding: a {self.size}^3 tetrahedral "
                                  "Lut3D over display RGB whose nodes below 1 sit at "
                                  "sRGB-encoded values, so in-gamut colours are "
                                  "reproduced exactly. See ocio_thinfilm.lut.clip_lut.ClipLUT."),
                     input_descriptor=f"{self.display} display-linear RGB divided by "
                                      f"{self.top:g}, no negative channel",
                     output_descriptor=f"{self.display} display RGB, clipped, sRGB-encoded "
                                       "(IEC 61966-2-1 piecewise curve)")

    def transforms(self, black=None, white=None):
        """The whole clip as a list of OCIO transforms, CIE-XYZ-D65 -> display RGB in
        [0, 1], sRGB-encoded (:data:`WORKING_ENCODING`); ``black`` / ``white`` replace
        the CLF-writable cores (e.g. by FileTransforms in the config)."""
        return [xyz_limit_transform(), ocio_ops.matrix(self.chart / _y_top(self.size)),
                xyY_forward_transform(),
                y_shaper_transform(),
                self.black_core() if black is None else black,
                self.white_core() if white is None else white]


@cache.memoize(maxsize=16)
def _clip_lut(display, size):
    P, _ = _black_plan(display, size)
    top_nodes, top = _white_nodes(size, display)
    M = colorimetry.matrix_XYZ_to_RGB(display)
    # black pass: the chart's nodes -> XYZ -> L(X) in display RGB, / top, half floats
    g = np.linspace(0.0, 1.0, size)
    U = np.stack(np.meshgrid(g, g, _y_top(size) * g ** Y_POWER, indexing="ij"),
                 axis=-1).reshape(-1, 3)
    u_b = np.maximum(U[:, 1], 1e-9)  # u_b = Y / S -> 0: the limit of ever larger chroma
    S = U[:, 2] / u_b
    p = np.c_[U[:, 0] * S, U[:, 2], S - U[:, 0] * S - U[:, 2]]
    XYZ = p @ np.linalg.inv(P).T
    with np.errstate(all="ignore"):
        black = clip_black_faces_RGB(XYZ @ M.T, display)
    black = np.where(np.isfinite(black), black, 0.0)
    black[np.arange(len(U)) % size == size - 1] = 1.0  # the layer above white: white
    black = (np.clip(black, 0.0, top) / top).astype(np.float16).astype(np.float64)
    # white pass: RGB nodes -> U(c), clipped, sRGB-encoded, 16-bit
    Uw = np.stack(np.meshgrid(top_nodes, top_nodes, top_nodes, indexing="ij"),
                  axis=-1).reshape(-1, 3)
    white = np.clip(clip_white_faces_RGB(Uw, display), 0.0, 1.0)
    white = np.round(_encode(white, WORKING_ENCODING).clip(0.0, 1.0) * LUT_CODE_MAX) / LUT_CODE_MAX
    w = _shaper_values(top_nodes, 0.0, top, along=lambda v: _encode(v, WORKING_ENCODING))
    q16 = lambda v: np.round(np.clip(v, 0.0, 1.0) * LUT_CODE_MAX) / LUT_CODE_MAX  # noqa: E731
    lut = ClipLUT(display=display, size=size,
                  black=black.reshape(size, size, size, 3),
                  white=white.reshape(size, size, size, 3),
                  white_shaper=q16(np.repeat(w[:, None], 3, axis=1)),
                  chart=P, top=float(top))
    for array in (lut.black, lut.white, lut.white_shaper, lut.chart):
        array.setflags(write=False)
    BUILT.append(f"clip3d:{display}:{size}")
    return lut


def _check_display(display):
    if display not in clip.DISPLAYS:
        raise ValueError(f"display must be one of {clip.DISPLAYS}, got {display!r}")
    return display


def clip_lut(display: str = "sRGB", size: int = CLIP_SIZE) -> ClipLUT:
    """The baked clip LUTs for ``display`` (cached): both passes, from
    :func:`clip_black_faces_RGB` and :func:`clip_white_faces_RGB`, whose composition
    is :func:`ocio_thinfilm.colour.clip.clip_RGB` exactly."""
    _check_display(display)
    size = _check_size(size, 9, 129, "clip LUT size")
    with _LOCK:
        return _clip_lut(display, size)


def display_matrix_transform(display: str, inverse: bool = False):
    """CIE-XYZ-D65 -> display-linear RGB (or back) as an OCIO MatrixTransform."""
    M = colorimetry.matrix_XYZ_to_RGB(_check_display(display) if display in clip.DISPLAYS
                                      else display)
    return ocio_ops.matrix(np.linalg.inv(M) if inverse else M)


def working_decoding_transform():
    """sRGB code values (the white pass's output) -> display-linear RGB."""
    return ocio_ops.inverse([display_encoding_transform(WORKING_ENCODING)])


def clip_transform(display: str = "sRGB", size: int = CLIP_SIZE):
    """OCIO transform CIE-XYZ-D65 -> display-linear RGB in [0, 1], constant-lightness
    clipped: :meth:`ClipLUT.transforms` (range limit, chart, the black-faces pass, the
    white-faces pass, which ends in display code values), then the display's EOTF."""
    lut = clip_lut(display, size)
    # the clamp only removes float32 round-off of the EOTF (1.0 -> 1.00002 through
    # OCIO's fast pow): the code values are in [0, 1] already
    return group(lut.transforms() + [working_decoding_transform(), ocio_ops.range_(0.0, 1.0)],
                 name=lut.name, id=transform_id("Gamut_Map", lut.name))


#: Display encodings (inverse EOTFs), as in the ACES OCIO configs' display spaces.
#: Display -> (description, gamma, offset or None for a pure power) (:mod:`.registry`).
DISPLAY_ENCODINGS = {d.name: d.encoding for d in registry.DISPLAY_LIST}


def display_encoding_transform(display: str):
    """Display-linear RGB -> display code values (the display's inverse EOTF)."""
    ocio = ocio_ops.module()
    _, gamma, offset = DISPLAY_ENCODINGS[_check_display(display)]
    if offset is None:
        t = ocio.ExponentTransform([gamma, gamma, gamma, 1.0])
        t.setNegativeStyle(ocio.NEGATIVE_CLAMP)
    else:
        t = ocio.ExponentWithLinearTransform([gamma] * 3 + [1.0], [offset] * 3 + [0.0])
    t.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return t


def aces_gamut_compression_transform():
    ocio = ocio_ops.module()
    return ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13,
                                       list(clip.ACES_GAMUT_COMP13_PARAMS))


def view_linear_transform(display: str, view: str, size: int = CLIP_SIZE):
    """CIE-XYZ-D65 -> display-linear RGB in [0, 1] for ``view`` (not for Raw)."""
    _check_display(display)
    if view == "Constant-Lightness Clip":
        return clip_transform(display, size)
    # the baselines limit XYZ to +-LIMIT first: +-Inf (and NaN, which OCIO's CPU Range
    # takes to the lower bound) stay finite through the matrices at every
    # optimisation level (OPTIMIZATION_NONE does not compose them, so F32_MAX inputs
    # overflowed to Inf - Inf = NaN)
    if view == "Channel Clamp":
        return group([finite_limit_transform(), display_matrix_transform(display),
                      ocio_ops.range_(0.0, 1.0)])
    if view == "ACES Gamut Compression":
        return group([finite_limit_transform(), display_matrix_transform(display),
                      aces_gamut_compression_transform(), ocio_ops.range_(0.0, 1.0)])
    raise ValueError(f"view must be one of {VIEWS[:3]}, got {view!r}")


def view_transform(display: str, view: str, size: int = CLIP_SIZE):
    """OCIO transform CIE-XYZ-D65 -> display-encoded RGB for ``view`` in :data:`VIEWS`.

    ``Raw`` passes values through unchanged (an empty group). The constant-lightness
    clip's second LUT ends in sRGB code values: decoded, then the display's encoding
    (OCIO's optimiser removes the pair for the sRGB-encoded displays).
    """
    _check_display(display)
    if view not in VIEWS:
        raise ValueError(f"view must be one of {VIEWS}, got {view!r}")
    if view == "Raw":
        return group([])
    if view == "Constant-Lightness Clip":
        lut = clip_lut(display, size)
        return group(lut.transforms() + [working_decoding_transform(),
                                         display_encoding_transform(display)],
                     name=lut.name, id=transform_id("Gamut_Map", lut.name))
    return group([view_linear_transform(display, view, size),
                  display_encoding_transform(display)])
