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
3D clip LUT ("factored" domain, the default)
    The clip moves a colour along its constant-Y ray towards the grey until it is
    inside all six faces (t = min over the faces), so it factors exactly as
    ``clip = U o L``: L clips only against the faces through black (R, G, B >= 0), U
    only against those through white, both along the same ray. The parallelepiped is
    centrally symmetric, so ``U = C o L o C`` with ``C(X) = W - X`` (a matrix with
    offset). L is homogeneous of degree 1: in a projective chart of the
    chromaticities (``XYZ_TO_xyY`` of a matrix of XYZ) it is a central projection
    towards the white onto the primaries' triangle and Y is unchanged, so each pass is
    one Lut3D over (chart, Y) with an exactly linear Y axis and the triangle's edges on
    grid / tetrahedral split planes (in-gamut colours exact). Pass 1 uses the chart
    normalised by 0.7 X + Y + Z (positive for XYZ >= 0), its grid covering the
    spectral locus; pass 2 takes W - X, whose X + Y + Z can be <= 0 for saturated
    colours, in a chart normalised by 0.02 X + Y + 0.005 Z, its grid covering the
    complements of the object colours. Both LUTs are stored as 16-bit integers.
    Measured at 38^3 on :func:`object_colours` against the analytic clip (dE2000
    mean / p99 / max): sRGB 0.029 / 0.42 / 1.61, Display P3 0.018 / 0.25 / 1.53,
    Rec.2020 0.008 / 0.10 / 0.64; spectral colours (Y <= 0.6) in gamut with
    |dY| <= 3.1e-5 but coarse chromaticity (p99 9-27).
3D clip LUT ("xy" / "aligned" domains, the previous design)
    Built in CIE xyY (OCIO ``FixedFunction XYZ_TO_xyY``, after a clamp of XYZ to
    [0, 1e6] that only touches non-physical inputs): the LUT's axes are the
    chromaticity (x, y), shaped towards the display white, and the luminance Y,
    shaped towards Y = 1; it outputs the same shaped (x, y, Y) coordinates and the
    inverse shapers and ``xyY -> XYZ`` follow. Only cells that cross the gamut
    boundary carry interpolation error; a final clamp to [0, 1] keeps the result in
    gamut (it moves Y by at most ~2e-3 on spectral colours). "xy" at 33^3 (sRGB):
    dE2000 mean 0.10, p99 1.39, max 4.5; 65^3: p99 0.53, max 2.5 (see
    ``benchmarks/bench_luts.py`` for the other domains).

Added names (beyond the contract): :func:`clip_lut` / :class:`ClipLUT` (the LUT data,
``domain="xy" | "aligned"``), :func:`view_linear_transform`,
:func:`display_matrix_transform`, :func:`display_encoding_transform`,
:func:`xyz_limit_transform`, :func:`group`, :func:`quantize`, :func:`transform_id`,
:func:`object_colours`, :func:`spectral_colours`, ``Table1D.rgb(display)`` (per-display
clipped variant), ``Table1D.shaper(x)``.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from . import clip, colorimetry

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
    "xyY_forward_transform",
    "xyY_inverse_transform",
    "transform_id",
    "quantize",
    "object_colours",
    "spectral_colours",
]

VIEWS = ("Constant-Lightness Clip", "Channel Clamp", "ACES Gamut Compression", "Raw")

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
#: Default edge length of the 3D clip LUTs (two per display in the "factored" domain).
CLIP_SIZE = 38
#: Wavelength step (nm) of the spectra behind the tables (band-limited integration).
SPECTRAL_STEP = 5.0

#: ``urn:aswf:ocio:transformId:1.0:<Vendor>:<Type>:<Name>:1.0`` (OpenColorIO-Config-ACES).
VENDOR = "OCIO-ThinFilm"

_LOCK = threading.RLock()


def transform_id(kind: str, name: str) -> str:
    """Transform ID in the style of the ACES OCIO configs."""
    safe = "".join(c if c.isalnum() else "_" for c in name).strip("_")
    return f"urn:aswf:ocio:transformId:1.0:{VENDOR}:{kind}:{safe}:1.0"


# --------------------------------------------------------------------------- #
# OCIO helpers
# --------------------------------------------------------------------------- #
def _ocio():
    import PyOpenColorIO as ocio

    return ocio


def group(transforms, *, name: str | None = None, description: str | None = None,
          id: str | None = None, input_descriptor: str | None = None,
          output_descriptor: str | None = None):
    """A ``GroupTransform`` of ``transforms`` with CLF-style metadata."""
    ocio = _ocio()
    g = ocio.GroupTransform()
    for t in transforms:
        g.appendTransform(t)
    md = g.getFormatMetadata()
    if name:
        md.setName(name)
    if id:
        md.setID(id)
    if description:
        md.addChildElement("Description", description)
    if input_descriptor:
        md.addChildElement("InputDescriptor", input_descriptor)
    if output_descriptor:
        md.addChildElement("OutputDescriptor", output_descriptor)
    return g


def quantize(values, decimals: int = 7) -> np.ndarray:
    """Round to ``decimals`` decimal places (and turn -0 into 0) before data go into a
    file: float64 results can differ in the last bits between runs (BLAS reduction
    order, memory alignment); rounded, the written files are byte-reproducible."""
    return np.round(np.asarray(values, dtype=np.float64), decimals) + 0.0


def _matrix(m3=None, offset=(0.0, 0.0, 0.0)):
    ocio = _ocio()
    m = np.eye(4)
    if m3 is not None:
        m[:3, :3] = m3
    return ocio.MatrixTransform([float(v) for v in quantize(m, 12).ravel()],
                                [float(v) for v in quantize(offset, 12)] + [0.0])


def _range(lo, hi):
    ocio = _ocio()
    r = ocio.RangeTransform()
    r.setMinInValue(lo)
    r.setMaxInValue(hi)
    r.setMinOutValue(lo)
    r.setMaxOutValue(hi)
    return r


#: Components are limited to [0, LIMIT] before XYZ -> xyY (see :func:`xyz_limit_transform`).
LIMIT = 1e6


def xyz_limit_transform():
    """Clamp XYZ to [0, LIMIT] per component before ``XYZ_TO_xyY``.

    No physical colour has a negative X, Y or Z (the CIE 1931 matching functions are
    non-negative), so this changes only non-physical inputs, and it keeps
    X + Y + Z >= 0: without it a huge negative component (X + Y + Z < 0 with Y > 0)
    flips the chromaticity to the opposite side (dE2000 ~60 for X = -1e30). +-Inf and
    NaN become finite; Y <= 0 gives black, as in the analytic clip.
    """
    return _range(0.0, LIMIT)


def xyY_forward_transform():
    ocio = _ocio()
    return ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_XYZ_TO_xyY)


def xyY_inverse_transform():
    ocio = _ocio()
    t = ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_XYZ_TO_xyY)
    t.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return t


def apply(transform, pixels) -> np.ndarray:
    """Apply an OCIO transform to a (..., 3) array with OCIO's CPU processor.

    The input is converted to float32 and not modified; returns a new float32 array
    of the same shape.
    """
    ocio = _ocio()
    a = np.asarray(pixels, dtype=np.float32)
    if a.ndim == 0 or a.shape[-1] != 3:
        raise ValueError(f"pixels must have a last axis of length 3, got shape {a.shape}")
    out = np.ascontiguousarray(a.reshape(-1, 3)).copy()
    cpu = ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()
    if out.size:
        cpu.applyRGB(out)
    return out.reshape(a.shape)


# --------------------------------------------------------------------------- #
# 1D tables
# --------------------------------------------------------------------------- #
def lut1d_transform(values):
    """An OCIO Lut1DTransform (linear interpolation) holding ``values`` (N, 3),
    quantised for byte-reproducible files (:func:`quantize`)."""
    ocio = _ocio()
    t = ocio.Lut1DTransform()
    t.setLength(len(values))
    t.setData(np.ascontiguousarray(quantize(values), dtype=np.float32).ravel())
    t.setInterpolation(ocio.INTERP_LINEAR)
    return t


def lut3d_transform(values, *, uint16: bool = False):
    """An OCIO Lut3DTransform (tetrahedral) holding ``values`` (N, N, N, 3), index
    [r][g][b]. ``uint16``: the values already lie on the 16-bit grid and are written
    as 16-bit integers; otherwise they are quantised (:func:`quantize`)."""
    ocio = _ocio()
    t = ocio.Lut3DTransform()
    t.setGridSize(values.shape[0])
    t.setInterpolation(ocio.INTERP_TETRAHEDRAL)
    t.setData(np.ascontiguousarray(values if uint16 else quantize(values),
                                   dtype=np.float32).ravel())
    if uint16:
        t.setFileOutputBitDepth(ocio.BIT_DEPTH_UINT16)
    return t


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
        ocio = _ocio()
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
        return _matrix(np.eye(3) / span, [-self.domain_min / span] * 3)

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


@lru_cache(maxsize=32)
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


@lru_cache(maxsize=8)
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
# 3D clip LUT
# --------------------------------------------------------------------------- #
#: Chromaticity domain of the LUT (covers the spectral locus, x <= 0.735, y <= 0.834).
XY_DOMAIN_MAX = (0.75, 0.85)
#: Clip LUT domains (see :func:`_shaper_parts`) and the default.
CLIP_DOMAINS = ("factored", "xy", "aligned")
CLIP_DOMAIN = "factored"
#: Default shaper exponents / offsets (mirrored moncurve) for the (x, y, 1 - Y) axes.
#: In the "aligned" domain the chromaticity axes stay affine (exponent 1); the
#: "factored" domain has no curve (every axis affine), the values are unused.
SHAPER_GAMMA = {"aligned": (1.0, 1.0, 2.0), "xy": (2.0, 2.0, 2.0), "factored": (1.0, 1.0, 1.0)}
SHAPER_OFFSET = {"aligned": (0.0, 0.0, 0.01), "xy": (0.01, 0.01, 0.01),
                 "factored": (0.0, 0.0, 0.0)}
#: Projective charts of the "factored" domain: the normaliser n . XYZ that
#: ``XYZ_TO_xyY`` divides by (after a matrix), for the pass against the faces through
#: black (inputs XYZ >= 0) and the pass against the faces through white (inputs
#: W - X, which can have X + Y + Z <= 0: the normaliser is mostly Y).
CHART_BLACK = (0.7, 1.0, 1.0)
CHART_WHITE = (0.02, 1.0, 0.005)
#: The factored LUTs are stored as 16-bit integers in the CLF files (half the size of
#: float text); values are rounded to that grid (error <= 7.6e-6 of the LUT range).
LUT_CODE_MAX = 65535
#: The factored clip maps display RGB [SNAP, 1 - SNAP] to [0, 1] before its final clamp:
#: black and white stay exact despite float32 round-off in the second pass's chart.
SNAP = 3e-5


def _white_xy(display):
    W = colorimetry.white_XYZ(display)
    return W[:2] / W.sum()


def _primaries_xy(display):
    P = colorimetry.RGB_to_XYZ(np.eye(3), display)
    return P[:, :2] / P.sum(axis=1, keepdims=True)


#: The canonical triangle the display primaries are sent to in the "aligned" domain:
#: its edges a = 0, b = 1 and a = b are grid planes and tetrahedral split planes.
_CANONICAL = np.array([[0.0, 0.0], [0.0, 1.0], [1.0, 1.0]])


def _locus_xy():
    L = colorimetry.spectral_locus_XYZ(1.0, np.arange(360.0, 781.0))
    return L[:, :2] / L.sum(axis=1, keepdims=True)


def _canonical_grid(primaries, points, cells):
    """The affine map of a 2D chart that sends ``primaries`` (3, 2) to the canonical
    triangle with ``points`` (N, 2) inside a grid of ``cells`` cells per axis, nodes
    every 1/k on both axes (k as large as possible, over the six assignments of
    primaries to corners). Returns (A (2x2), o (2,), k, m_a, m_b) -- the canonical
    coordinate a sits at node m_a + a k -- or None if no k >= 1 fits."""
    import itertools

    best = None
    for perm in itertools.permutations(range(3)):
        sol = np.linalg.solve(np.c_[primaries[list(perm)], np.ones(3)], _CANONICAL)
        A, o = sol[:2].T, sol[2]
        ab = points @ A.T + o
        lo, hi = ab.min(axis=0), ab.max(axis=0)
        k = int(np.floor(cells / float((hi - lo).max())))
        while k > 0:
            ma, mb = int(np.ceil(-lo[0] * k - 1e-9)), int(np.ceil(-lo[1] * k - 1e-9))
            if (cells - ma) / k >= hi[0] and (cells - mb) / k >= hi[1] and ma >= 0 and mb >= 0:
                break
            k -= 1
        if k > 0 and (best is None or k > best[2]):
            best = (A, o, k, ma, mb)
    return best


@lru_cache(maxsize=32)
def _aligned_plan(display, size):
    """Affine chromaticity map of the "aligned" domain for ``display`` and ``size``.

    An affine map of the (x, y) plane sends the display's primaries to the canonical
    triangle (0, 0), (0, 1), (1, 1); the gamut faces R = 0, G = 0, B = 0 (lines
    through pairs of primaries in every constant-Y plane) become the planes a = 0,
    b = 1 and a = b. With nodes at multiples of 1/k on both axes those planes are
    made of grid faces and of the tetrahedral split planes, so no LUT cell straddles
    them. Of the six assignments of primaries to corners, the one giving the most
    nodes per unit (k) while covering the spectral locus is kept.
    Returns (A (2x2), o (2,), k, m_a, m_b): u_a = (a + m_a / k) k / (size - 1).
    """
    best = _canonical_grid(_primaries_xy(display), _locus_xy(), size - 1)
    if best is None:
        raise ValueError(f"clip LUT size {size} is too small for the aligned domain")
    return best


def _moncurve(gamma, offset, inverse):
    ocio = _ocio()
    curve = ocio.ExponentWithLinearTransform([*map(float, gamma), 1.0],
                                             [*map(float, offset), 0.0])
    curve.setNegativeStyle(ocio.NEGATIVE_MIRROR)
    if inverse:
        curve.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return curve


def _shaper_parts(display, size, domain="aligned", gamma=None, offset=None):
    """Per-axis shaper xyY -> LUT coordinates u in [0, 1]^3 (a list of OCIO
    transforms, CLF-writable: matrices and a mirrored moncurve).

    "aligned": the affine map of :func:`_aligned_plan` on (x, y); Y through
    ``1 - moncurve^-1(1 - Y)`` (grid points towards Y = 1).
    "xy": distance from the display white over [0, 0.75] x [0, 0.85], normalised to
    [-1, 1], through the inverse moncurve (grid points near the white), to [0, 1].
    """
    gamma = SHAPER_GAMMA[domain] if gamma is None else tuple(gamma)
    offset = SHAPER_OFFSET[domain] if offset is None else tuple(offset)
    if domain == "aligned":
        A, o, k, ma, mb = _aligned_plan(display, size)
        s = k / (size - 1)
        M = np.eye(3)
        M[:2, :2] = A * s
        M[2, 2] = -1.0
        ops = [_matrix(M, [(o[0] + ma / k) * s, (o[1] + mb / k) * s, 1.0])]
        ops.append(_moncurve(gamma, offset, True))
        ops.append(_matrix(np.diag([1.0, 1.0, -1.0]), [0.0, 0.0, 1.0]))
        return ops
    if domain != "xy":
        raise ValueError(f"clip LUT domain must be one of {CLIP_DOMAINS}, got {domain!r}")
    xw, yw = _white_xy(display)
    dx = max(xw, XY_DOMAIN_MAX[0] - xw)
    dy = max(yw, XY_DOMAIN_MAX[1] - yw)
    ops = [_matrix(np.diag([1 / dx, 1 / dy, -1.0]), [-xw / dx, -yw / dy, 1.0]),
           _moncurve(gamma, offset, True),
           _matrix(np.diag([0.5, 0.5, -1.0]), [0.5, 0.5, 1.0])]
    return ops


def _inverse(transforms):
    ocio = _ocio()
    g = group(transforms)
    g.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return g


# ---- the "factored" domain ------------------------------------------------- #
# The clip moves a colour along its constant-Y ray towards the grey g W until it is
# inside all six faces: t = min(t_black, t_white), so it factors exactly as
# clip = U o L, L clipping only against R, G, B >= 0 and U only against R, G, B <= 1
# (both along the same ray, towards the same grey). The parallelepiped is centrally
# symmetric: with C(X) = W - X (an exact matrix with offset), U = C o L o C. L is
# homogeneous of degree 1, so in any projective chart of the chromaticities it is a
# 2D map (central projection towards the white onto the primaries' triangle) and Y
# passes through unchanged: each pass is one Lut3D over (chart, Y) whose Y axis is
# exactly linear, with the triangle's edges on grid / tetrahedral split planes.
def _chart_matrix(upper):
    """XYZ -> V with V1 = Y and V0 + V1 + V2 = n . XYZ, n = CHART_WHITE (``upper``,
    applied to W - X) or CHART_BLACK. ``XYZ_TO_xyY`` of V gives the chart (V0/n.X,
    Y/n.X) and Y."""
    n = np.asarray(CHART_WHITE if upper else CHART_BLACK, dtype=np.float64)
    first = np.array([1.0, 0.0, -1.0]) if upper else np.array([1.0, 0.0, 0.0])
    return np.array([first, [0.0, 1.0, 0.0], n - first - np.array([0.0, 1.0, 0.0])])


def _chart(P, XYZ):
    V = np.asarray(XYZ, dtype=np.float64) @ P.T
    return V[..., :2] / V.sum(axis=-1, keepdims=True)


def _clip_black_faces(XYZ, display):
    """L: the clip against the faces R, G, B >= 0 only (float64, Y > 0)."""
    M = colorimetry.matrix_XYZ_to_RGB(display)
    rgb = XYZ @ M.T
    grey = XYZ[:, 1:2] / np.linalg.inv(M)[1].sum()
    neg = rgb < 0
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(neg, grey / np.where(neg, grey - rgb, 1.0), 1.0).min(axis=1, keepdims=True)
    return (grey + t * (rgb - grey)) @ np.linalg.inv(M).T


@colorimetry.persistent(modules=("ocio_thinfilm.tables", "ocio_thinfilm.spectra",
                                 "ocio_thinfilm.colorimetry", "ocio_thinfilm.clip"))
def _white_pass_cover(display):
    """Inputs W - L(X) of the second pass that lie outside the gamut, for the object
    colours of :func:`object_colours` (some are brighter than the reflector in one
    component, e.g. Munsell renotation colours, so W - L(X) leaves the locus).

    Memoised on disk: it needs the whole test set (and colour-science's import), but
    only to size the second pass's grid, so a render should not pay for it."""
    M = colorimetry.matrix_XYZ_to_RGB(display)
    X = object_colours()
    X = X[X[:, 1] > 1e-6]
    comp = colorimetry.white_XYZ(display) - _clip_black_faces(X, display)
    rgb = comp @ M.T
    return comp[(comp[:, 1] > 1e-6) & (rgb < 0).any(axis=1)]


@lru_cache(maxsize=32)
def _factored_plan(display, size, upper):
    """Chart and grid of one pass of the "factored" domain.

    The chart (``_chart_matrix``) then an affine map send the display's primaries to
    the canonical triangle (0, 0), (0, 1), (1, 1) (edges a = 0, b = 1, a = b: grid and
    tetrahedral split planes, nodes every 1/k); the grid covers the spectral locus
    (first pass) or the second pass's inputs (:func:`_white_pass_cover`).
    Returns (P, A, o, k, m_a, m_b, white): u = (A chart + o + m / k) k / (size - 1);
    ``white`` is the display white in canonical coordinates.
    """
    P = _chart_matrix(upper)
    M = colorimetry.matrix_XYZ_to_RGB(display)
    prim = _chart(P, np.linalg.inv(M).T)
    if upper:
        cover = _chart(P, _white_pass_cover(display))
    else:
        cover = _chart(P, colorimetry.spectral_locus_XYZ(1.0, np.arange(360.0, 781.0)))
    best = _canonical_grid(prim, np.vstack([cover, prim]), size - 1)
    if best is None:
        raise ValueError(f"clip LUT size {size} is too small for the factored domain")
    A, o, k, ma, mb = best
    white = _chart(P, colorimetry.white_XYZ(display)[None])[0] @ A.T + o
    return P, A, o, k, ma, mb, white


def _factored_shaper(display, size, upper):
    P, A, o, k, ma, mb, _ = _factored_plan(display, size, upper)
    s = k / (size - 1)
    S = np.eye(3)
    S[:2, :2] = A * s
    return [_matrix(S, [(o[0] + ma / k) * s, (o[1] + mb / k) * s, 0.0])]


def _factored_vertices(display, size, upper):
    """LUT values of one pass: central projection towards the white onto the
    canonical triangle, computed in the canonical plane itself (so nodes whose chart
    point has Y <= 0 get the continuation, not a guess); identity inside; Y axis
    identity; rounded to the 16-bit grid of the CLF file."""
    P, A, o, k, ma, mb, white = _factored_plan(display, size, upper)
    s = k / (size - 1)
    g = np.linspace(0.0, 1.0, size)
    U = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1)
    m = np.array([ma, mb]) / k
    ab = U[..., :2] / s - m

    def inside_measure(p):  # >= 0 inside, one per edge: a = 0, b = 1, a = b
        return np.stack([p[..., 0], 1.0 - p[..., 1], p[..., 1] - p[..., 0]], axis=-1)

    fp, fw = inside_measure(ab), inside_measure(white)
    neg = fp < 0
    t = np.where(neg, fw / np.where(neg, fw - fp, 1.0), 1.0).min(axis=-1, keepdims=True)
    out = U.copy()
    out[..., :2] = (white + t * (ab - white) + m) * s
    inside = ~neg.any(axis=-1)
    out[inside] = U[inside]
    out[..., 2] = U[..., 2]
    # Stored as codes c = out * q (size - 1) / LUT_CODE_MAX on the 16-bit grid, with q
    # the largest integer with q (size - 1) <= LUT_CODE_MAX: the identity nodes
    # i / (size - 1) become the exact codes i q, so in-gamut colours (and the white,
    # and black) stay exact; :func:`_factored_code_scale` undoes the scale.
    q = LUT_CODE_MAX // (size - 1)
    return np.round(out * (q * (size - 1))) / LUT_CODE_MAX


def _factored_code_scale(size):
    """Matrix after a factored Lut3D: LUT codes -> LUT coordinates (all three axes)."""
    q = LUT_CODE_MAX // (size - 1)
    return _matrix(np.eye(3) * (LUT_CODE_MAX / (q * (size - 1))))


@dataclass(frozen=True, eq=False)
class ClipLUT:
    """The baked constant-lightness clip for one display (see :func:`clip_lut`).

    In the "factored" domain ``values`` is the pass against the faces through black
    and ``white_values`` the pass against the faces through white (applied to W - X).
    """

    display: str
    size: int
    values: np.ndarray  # (size, size, size, 3) LUT coordinates out, index [u0][u1][uY]
    domain: str
    gamma: tuple
    offset: tuple
    white_values: np.ndarray | None = None

    @property
    def name(self) -> str:
        return f"Constant-Lightness Clip {self.display}"

    def lut_transform(self, white: bool = False):
        # factored values are already on the 16-bit grid
        return lut3d_transform(self.white_values if white else self.values,
                               uint16=self.domain == "factored")

    def shaper(self, white: bool = False):
        if self.domain == "factored":
            return _factored_shaper(self.display, self.size, white)
        return _shaper_parts(self.display, self.size, self.domain, self.gamma, self.offset)

    def core_transform(self, white: bool = False):
        """CLF-writable part, chart in -> chart out: shaper, Lut3D, inverse shaper.

        "xy" / "aligned": CIE xyY in and out. "factored": the chart of one pass
        (``white`` selects the pass against the faces through white)."""
        if self.domain != "factored":
            return group(self.shaper() + [self.lut_transform(), _inverse(self.shaper())],
                         name=self.name, id=transform_id("Gamut_Map", self.name),
                         description=(f"Smits & Meyer 1990 constant-lightness clip into "
                                      f"{self.display} (Section 3.2), baked as a "
                                      f"{self.size}^3 tetrahedral Lut3D over CIE xyY "
                                      f"({self.domain} domain, see ocio_thinfilm.tables; Y "
                                      "shaped towards 1, exact by construction). "
                                      "Apply after XYZ_TO_xyY and follow with its inverse."),
                         input_descriptor="CIE xyY (D65, Y = 1 at display white)",
                         output_descriptor=f"CIE xyY clipped into the {self.display} gamut")
        faces = "white (R, G, B <= 1)" if white else "black (R, G, B >= 0)"
        n = CHART_WHITE if white else CHART_BLACK
        name = f"{self.name} {'White' if white else 'Black'} Faces"
        chart = (f"XYZ_TO_xyY of a matrix of {'W - XYZ' if white else 'XYZ'} whose "
                 f"components sum to {n[0]:g} X + {n[1]:g} Y + {n[2]:g} Z "
                 "(middle component Y)")
        return group(self.shaper(white) + [self.lut_transform(white),
                                           _factored_code_scale(self.size),
                                           _inverse(self.shaper(white))],
                     name=name, id=transform_id("Gamut_Map", name),
                     description=(f"Smits & Meyer 1990 constant-lightness clip into "
                                  f"{self.display} (Section 3.2), the part against the "
                                  f"gamut faces through {faces}: central projection "
                                  "towards the white onto the primaries' triangle, "
                                  f"baked as a {self.size}^3 tetrahedral Lut3D (triangle "
                                  "edges on grid planes, Y axis exact). The clip is "
                                  "C(U(C(L(X)))) with C(X) = W - X, L the black-faces "
                                  "and U the white-faces part; see "
                                  "ocio_thinfilm.tables.clip_transform."),
                     input_descriptor=f"chart ({chart}) and Y",
                     output_descriptor=f"the same chart, clipped against the faces "
                                       f"through {faces} of the {self.display} gamut")

    def transforms(self, black=None, white=None):
        """The whole clip as a list of OCIO transforms, CIE-XYZ-D65 -> display-linear
        RGB in [0, 1]; ``black`` / ``white`` replace the CLF-writable cores (e.g. by
        FileTransforms in the config)."""
        black = self.core_transform() if black is None else black
        if self.domain != "factored":
            return [xyz_limit_transform(), xyY_forward_transform(), black,
                    xyY_inverse_transform(), display_matrix_transform(self.display),
                    _range(0.0, 1.0)]
        white = self.core_transform(True) if white is None else white
        P1 = _factored_plan(self.display, self.size, False)[0]
        P2 = _factored_plan(self.display, self.size, True)[0]
        W = colorimetry.white_XYZ(self.display)
        M = colorimetry.matrix_XYZ_to_RGB(self.display)
        return [xyz_limit_transform(), _matrix(P1), xyY_forward_transform(), black,
                xyY_inverse_transform(),
                _matrix(-P2 @ np.linalg.inv(P1), P2 @ W),  # chart 1 -> W - X -> chart 2
                xyY_forward_transform(), white, xyY_inverse_transform(),
                # chart 2 -> W - X -> display RGB, and [e, 1 - e] -> [0, 1] so that float32
                # round-off through the second chart (~1e-5) does not leave black or
                # white off by that much (moves any channel by at most e)
                _matrix(-M @ np.linalg.inv(P2) / (1 - 2 * SNAP), (M @ W - SNAP) / (1 - 2 * SNAP)),
                _range(0.0, 1.0)]


def _clip_vertices(display, size, domain, gamma, offset):
    """Vertex values of the clip LUT (float64), in the LUT's output coordinates.

    xyY <-> XYZ goes through OCIO's own XYZ_TO_xyY, the op the config applies."""
    g = np.linspace(0.0, 1.0, size)
    U = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1)
    shaper = _shaper_parts(display, size, domain, gamma, offset)
    c = apply(_inverse(shaper), U).astype(np.float64)  # xyY at the vertices (OCIO's own)
    c[..., 2] = np.where(U[..., 2] == 0.0, 0.0, np.where(U[..., 2] == 1.0, 1.0, c[..., 2]))
    xyY = c.copy()
    # Y = 0: the limit of the clip as Y -> 0+ (homogeneous), so dark colours keep
    # their chromaticity; y <= 0 is outside every gamut, any tiny value works.
    xyY[..., 2] = np.maximum(xyY[..., 2], 1e-9)
    xyY[..., 1] = np.maximum(xyY[..., 1], 1e-9)
    XYZ = apply(xyY_inverse_transform(), xyY).astype(np.float64)
    clipped = clip.clip_XYZ(XYZ, display)
    inside = np.all(clipped == XYZ, axis=-1)  # the clip returns in-gamut colours unchanged
    out = apply(group([xyY_forward_transform()] + shaper), clipped).astype(np.float64)
    out[inside] = U[inside]  # identity exactly (affine in the grid coordinates)
    out[..., 2] = U[..., 2]  # the clip keeps Y: exact by construction
    return out


@lru_cache(maxsize=16)
def _clip_lut(display, size, domain, gamma, offset):
    white_values = None
    if domain == "factored":
        values = _factored_vertices(display, size, False)
        white_values = _factored_vertices(display, size, True)
        white_values.setflags(write=False)
    else:
        values = _clip_vertices(display, size, domain, gamma, offset)
    values.setflags(write=False)
    BUILT.append(f"clip3d:{display}:{size}")
    return ClipLUT(display=display, size=size, values=values, domain=domain, gamma=gamma,
                   offset=offset, white_values=white_values)


def _check_display(display):
    if display not in clip.DISPLAYS:
        raise ValueError(f"display must be one of {clip.DISPLAYS}, got {display!r}")
    return display


def clip_lut(display: str = "sRGB", size: int = CLIP_SIZE, *, domain: str = CLIP_DOMAIN,
             gamma=None, offset=None) -> ClipLUT:
    """The baked clip LUT for ``display`` (cached): vertex values from
    :func:`ocio_thinfilm.clip.clip_XYZ` on a ``size``^3 grid over shaped CIE xyY."""
    _check_display(display)
    size = _check_size(size, 5, 129, "clip LUT size")
    if domain not in CLIP_DOMAINS:
        raise ValueError(f"clip LUT domain must be one of {CLIP_DOMAINS}, got {domain!r}")
    gamma = tuple(map(float, SHAPER_GAMMA[domain] if gamma is None else gamma))
    offset = tuple(map(float, SHAPER_OFFSET[domain] if offset is None else offset))
    with _LOCK:
        return _clip_lut(display, size, domain, gamma, offset)


def display_matrix_transform(display: str, inverse: bool = False):
    """CIE-XYZ-D65 -> display-linear RGB (or back) as an OCIO MatrixTransform."""
    M = colorimetry.matrix_XYZ_to_RGB(_check_display(display) if display in clip.DISPLAYS
                                      else display)
    return _matrix(np.linalg.inv(M) if inverse else M)


def clip_transform(display: str = "sRGB", size: int = CLIP_SIZE, **kwargs):
    """OCIO transform CIE-XYZ-D65 -> display-linear RGB, constant-lightness clipped.

    Range limit (XYZ clamped to [0, 1e6]: NaN/Inf finite, no chromaticity flip), then
    ("factored") chart matrix, ``XYZ_TO_xyY``, the black-faces LUT (shaper, Lut3D,
    inverse shaper), ``xyY -> XYZ``, the complement W - X into the second chart,
    ``XYZ_TO_xyY``, the white-faces LUT, back, the complement and the display matrix
    in one matrix, a clamp to [0, 1]. ("xy" / "aligned": ``XYZ_TO_xyY``, one LUT,
    ``xyY -> XYZ``, the display matrix, the clamp.)
    """
    lut = clip_lut(display, size, **kwargs)
    return group(lut.transforms(), name=lut.name, id=transform_id("Gamut_Map", lut.name))


#: Display encodings (inverse EOTFs), as in the ACES OCIO configs' display spaces.
DISPLAY_ENCODINGS = {
    "sRGB": ("sRGB piecewise (IEC 61966-2-1)", 2.4, 0.055),
    "Display P3": ("sRGB piecewise (IEC 61966-2-1)", 2.4, 0.055),
    "Rec.2020": ("BT.1886 gamma 2.4", 2.4, None),
}


def display_encoding_transform(display: str):
    """Display-linear RGB -> display code values (the display's inverse EOTF)."""
    ocio = _ocio()
    _, gamma, offset = DISPLAY_ENCODINGS[_check_display(display)]
    if offset is None:
        t = ocio.ExponentTransform([gamma, gamma, gamma, 1.0])
        t.setNegativeStyle(ocio.NEGATIVE_CLAMP)
    else:
        t = ocio.ExponentWithLinearTransform([gamma] * 3 + [1.0], [offset] * 3 + [0.0])
    t.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return t


def aces_gamut_compression_transform():
    ocio = _ocio()
    return ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13,
                                       list(clip.ACES_GAMUT_COMP13_PARAMS))


def view_linear_transform(display: str, view: str, size: int = CLIP_SIZE):
    """CIE-XYZ-D65 -> display-linear RGB in [0, 1] for ``view`` (not for Raw)."""
    _check_display(display)
    if view == "Constant-Lightness Clip":
        return clip_transform(display, size)
    if view == "Channel Clamp":
        return group([display_matrix_transform(display), _range(0.0, 1.0)])
    if view == "ACES Gamut Compression":
        return group([display_matrix_transform(display), aces_gamut_compression_transform(),
                      _range(0.0, 1.0)])
    raise ValueError(f"view must be one of {VIEWS[:3]}, got {view!r}")


def view_transform(display: str, view: str, size: int = CLIP_SIZE):
    """OCIO transform CIE-XYZ-D65 -> display-encoded RGB for ``view`` in :data:`VIEWS`.

    ``Raw`` passes values through unchanged (an empty group).
    """
    _check_display(display)
    if view not in VIEWS:
        raise ValueError(f"view must be one of {VIEWS}, got {view!r}")
    if view == "Raw":
        return group([])
    return group([view_linear_transform(display, view, size),
                  display_encoding_transform(display)])


# --------------------------------------------------------------------------- #
# Test colours (shared by the tests, the benchmark and the report)
# --------------------------------------------------------------------------- #
def object_colours(seed: int = 0, n_random: int = 4000) -> np.ndarray:
    """A set of object colours (CIE-XYZ-D65, reflectances under D65, Y <= 1):

    ``n_random`` random smooth reflectance spectra (three Gaussian bumps on a
    random base, clipped to [0, 1], scaled), the ColorChecker sets of colour-science,
    the measured ("real") Munsell renotation colours, and the interference colours of
    the two film kinds (0-3 um, 3000 each) and of the Morpho multilayer (500 angles).
    """
    import colour
    from colour.notation.datasets.munsell import MUNSELL_COLOURS_REAL

    rng = np.random.default_rng(seed)
    wl = np.arange(360.0, 781.0, 5.0)
    R = np.zeros((n_random, wl.size))
    for _ in range(3):
        centre = rng.uniform(380, 720, n_random)[:, None]
        width = rng.uniform(10, 120, n_random)[:, None]
        amplitude = rng.uniform(-1, 1.2, n_random)[:, None]
        R += amplitude * np.exp(-0.5 * ((wl - centre) / width) ** 2)
    R = np.clip(R + rng.uniform(0, 0.6, n_random)[:, None], 0, 1)
    R *= rng.uniform(0.05, 1, n_random)[:, None]
    random_XYZ = colorimetry.reflectance_to_XYZ(R, wl)
    shape = colour.SpectralShape(360, 780, 5)
    checker = []
    for name in sorted(colour.SDS_COLOURCHECKERS):
        for sd in colour.SDS_COLOURCHECKERS[name].values():
            checker.append(colour.sd_to_XYZ(sd.copy().align(shape),
                                            illuminant=colour.SDS_ILLUMINANTS["D65"]) / 100)
    munsell = np.array([v[1] for v in MUNSELL_COLOURS_REAL], dtype=np.float64)
    munsell[:, 2] /= 100.0
    munsell = colour.xyY_to_XYZ(munsell[munsell[:, 2] <= 1.0])
    t = np.linspace(0.0, 3000.0, 3000)
    films = np.concatenate([colorimetry.film_XYZ(t, "phase-change"),
                            colorimetry.film_XYZ(t, "no-phase-change"),
                            colorimetry.morpho_XYZ(np.linspace(0.0, 89.0, 500))])
    return np.concatenate([random_XYZ, np.array(checker), munsell, films])


def spectral_colours(max_Y: float = 0.6, levels: int = 60) -> np.ndarray:
    """Monochromatic colours 380-700 nm at ``levels`` luminances in (0, max_Y]."""
    Ys = np.linspace(max_Y / levels, max_Y, levels)
    return np.concatenate([colorimetry.spectral_locus_XYZ(Y) for Y in Ys])
