"""The soft constant-lightness compression as OCIO transforms.

The compression of :mod:`ocio_thinfilm.colour.compress`: two small LUTs in front of the
clip's two passes, which it reuses as they are. With ``f`` the compression curve
continued past the limit and ``sigma(d) = f(d) / d``, the compression is the clip of a
smooth squeeze, ``compress = clip o S`` with ``S(c) = Y + sigma(D) (c - Y)``, and S
factors as the clip does (:mod:`.clip_lut`), so the chain is ``U o S_w o L o S_b``:
S_b (:func:`ocio_thinfilm.colour.compress.soft_black_RGB`) a Lut3D over its own
chromaticity chart (:func:`ocio_thinfilm.lut.grid.soft_plan`), S_w
(:func:`ocio_thinfilm.colour.compress.soft_white_RGB`) a Lut3D on the clip's white-pass
nodes. Every step keeps Y and moves along the same ray (tested against the analytic map
in ``tests/test_compress.py``). The derivation: docs/compress.md, *Baked*.

This module holds :class:`CompressLUT` (the two LUTs and their OCIO transforms) and
:func:`compress_lut`; the node layouts are in :mod:`ocio_thinfilm.lut.grid`, the 16-bit
storage in :mod:`ocio_thinfilm.lut.storage`. Sizes, accuracy and load time:
``benchmarks/bench_compress.py``, ``benchmarks/bench_load.py`` and docs/compress.md.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ocio_thinfilm import cache, registry, reproducible
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.colour import compress as soft
from ocio_thinfilm.lut import clip_lut, grid, ocio_ops, storage
from ocio_thinfilm.lut.clip_lut import ClipLUT, xyY_forward_transform, xyY_inverse_transform
from ocio_thinfilm.lut.node_fit import chart_to_XYZ
from ocio_thinfilm.lut.ocio_ops import group, lut1d_transform, lut3d_transform, transform_id
from ocio_thinfilm.lut.options import check_clip_size
from ocio_thinfilm.lut.tables import check_size

__all__ = [
    "SOFT_SIZE",
    "SOFT_WHITE_SIZE",
    "SOFT_WHITE_INSIDE",
    "SOFT_WHITE_GRADED",
    "SOFT_WHITE_RATIO",
    "TESTED_THRESHOLD",
    "TESTED_LIMIT",
    "KNOB_TARGETS",
    "MEASURED_KNOBS",
    "knobs_tested",
    "untested_knobs_note",
    "CompressLUT",
    "compress_lut",
]

#: Edge of S_b's Lut3D (over its own chart, :func:`ocio_thinfilm.lut.grid.soft_plan`).
SOFT_SIZE = 49
#: Edge of S_w's Lut3D.
SOFT_WHITE_SIZE = 49
#: S_w's node layout (:func:`ocio_thinfilm.lut.grid.white_nodes`): the share of each axis
#: below 1, and the last cells below white graded geometrically towards it (number and
#: ratio). S_w is the identity where the distance D is below the threshold, a region that
#: narrows like 1 - Y towards white; cells proportional to the distance from white keep
#: as many across it at every scale, so colours near white inside the threshold stay put.
#: Chosen by measurement (docs/compress.md): colours half-way to the boundary move by
#: dE2000 <= 0.07 and the clip's test sets stay within p99 0.5 / max 1.5.
SOFT_WHITE_INSIDE = 0.55
SOFT_WHITE_GRADED = 9
SOFT_WHITE_RATIO = 0.57

#: The tested range of the knobs (threshold, limit), both bounds included: on a grid of
#: pairs inside it (``benchmarks/bench_compress_knobs.py``, docs/compress.md) the baked
#: view keeps the accuracy targets :data:`KNOB_TARGETS` of the defaults against the
#: analytic map on every display.
TESTED_THRESHOLD = (0.3, 0.85)
TESTED_LIMIT = (1.1, 1.5)
#: The defaults' accuracy targets, worst over the displays and the clip's test sets:
#: dE2000 p99 and max, |dY| max against the analytic map; colours below the threshold
#: (at most ``min(0.5, 0.625 threshold)`` of the way to the boundary: half-way at the
#: defaults) moved by at most dE2000 0.1.
KNOB_TARGETS = {"p99": 0.5, "max": 1.5, "dY": 1e-3, "inside": 0.1}
#: From ``benchmarks/bench_compress_knobs.py`` (reports/bench_compress_knobs.json)
#: at the grid's pairs outside the tested range: (threshold, limit) -> (dE2000 p99,
#: dE2000 max, |dY| max, dE2000 max of the colours below the threshold, the targets
#: missed), each the worst over the displays and test sets.
MEASURED_KNOBS: dict[tuple[float, float], tuple[float, float, float, float, str]] = {
    (0.1, 1.01): (5.83, 20.39, 0.064, 0.039, "p99, max, |dY|"),
    (0.1, 1.05): (0.55, 5.38, 0.027, 0.047, "p99, max, |dY|"),
    (0.1, 1.1): (0.48, 1.89, 0.0055, 0.067, "max, |dY|"),
    (0.1, 1.2): (0.45, 1.1, 0.00057, 0.102, "colours left alone"),
    (0.1, 1.3): (0.43, 1.18, 0.00056, 0.134, "colours left alone"),
    (0.1, 1.5): (0.45, 1.21, 0.00041, 0.184, "colours left alone"),
    (0.1, 2.0): (0.45, 0.9, 0.00029, 0.262, "colours left alone"),
    (0.1, 3.0): (0.43, 0.92, 0.00019, 0.319, "colours left alone"),
    (0.1, 5.0): (0.46, 0.92, 0.00012, 0.365, "colours left alone"),
    (0.2, 1.01): (4.71, 19.0, 0.053, 0.041, "p99, max, |dY|"),
    (0.2, 1.05): (0.5, 3.71, 0.019, 0.041, "p99, max, |dY|"),
    (0.2, 1.1): (0.47, 1.43, 0.00096, 0.05, ""),
    (0.2, 1.2): (0.44, 1.25, 0.00058, 0.068, ""),
    (0.2, 1.3): (0.45, 1.04, 0.0005, 0.087, ""),
    (0.2, 1.5): (0.46, 1.31, 0.00034, 0.115, "colours left alone"),
    (0.2, 2.0): (0.44, 0.84, 0.00021, 0.145, "colours left alone"),
    (0.2, 3.0): (0.42, 0.86, 0.00023, 0.176, "colours left alone"),
    (0.2, 5.0): (0.43, 0.87, 0.00013, 0.195, "colours left alone"),
    (0.3, 1.01): (2.66, 14.62, 0.044, 0.038, "p99, max, |dY|"),
    (0.3, 1.05): (0.48, 2.0, 0.0095, 0.038, "max, |dY|"),
    (0.3, 2.0): (0.43, 0.91, 0.00023, 0.088, ""),
    (0.3, 3.0): (0.42, 0.84, 0.00021, 0.105, "colours left alone"),
    (0.3, 5.0): (0.43, 0.85, 0.00011, 0.115, "colours left alone"),
    (0.4, 1.01): (1.59, 14.64, 0.041, 0.037, "p99, max, |dY|"),
    (0.4, 1.05): (0.48, 1.2, 0.0027, 0.037, "|dY|"),
    (0.4, 2.0): (0.43, 0.86, 0.00025, 0.088, ""),
    (0.4, 3.0): (0.43, 0.79, 0.00016, 0.095, ""),
    (0.4, 5.0): (0.42, 0.82, 0.0001, 0.102, "colours left alone"),
    (0.5, 1.01): (0.89, 9.45, 0.031, 0.043, "p99, max, |dY|"),
    (0.5, 1.05): (0.44, 1.21, 0.00051, 0.043, ""),
    (0.5, 2.0): (0.41, 0.86, 0.00024, 0.091, ""),
    (0.5, 3.0): (0.42, 0.8, 0.00015, 0.103, "colours left alone"),
    (0.5, 5.0): (0.41, 0.77, 0.00012, 0.103, "colours left alone, ramps not strictly rising"),
    (0.6, 1.01): (0.5, 4.04, 0.023, 0.035, "p99, max, |dY|"),
    (0.6, 1.05): (0.43, 1.24, 0.00055, 0.035, ""),
    (0.6, 2.0): (0.41, 0.79, 0.00019, 0.091, ""),
    (0.6, 3.0): (0.41, 0.87, 0.00015, 0.103, "colours left alone, ramps not strictly rising"),
    (0.6, 5.0): (0.41, 0.86, 0.00012, 0.103, "colours left alone, ramps not strictly rising"),
    (0.7, 1.01): (0.47, 1.57, 0.0075, 0.037, "max, |dY|"),
    (0.7, 1.05): (0.45, 1.29, 0.00061, 0.037, ""),
    (0.7, 2.0): (0.41, 0.92, 0.00015, 0.104, "colours left alone"),
    (0.7, 3.0): (0.41, 0.81, 0.00014, 0.113, "colours left alone, ramps not strictly rising"),
    (0.7, 5.0): (0.4, 0.77, 0.00014, 0.113, "colours left alone, ramps not strictly rising"),
    (0.8, 1.01): (0.45, 1.45, 0.00045, 0.036, ""),
    (0.8, 1.05): (0.45, 1.24, 0.00048, 0.036, ""),
    (0.8, 2.0): (0.4, 1.08, 0.00014, 0.073, "ramps not strictly rising"),
    (0.8, 3.0): (0.4, 1.04, 0.00014, 0.081, "ramps not strictly rising"),
    (0.8, 5.0): (0.4, 1.01, 0.00014, 0.081, "ramps not strictly rising"),
    (0.85, 1.01): (0.45, 1.4, 0.00047, 0.036, ""),
    (0.85, 1.05): (0.44, 1.45, 0.00038, 0.036, ""),
    (0.85, 2.0): (0.43, 0.89, 0.00015, 0.052, "ramps not strictly rising"),
    (0.85, 3.0): (0.44, 0.82, 0.00015, 0.061, "ramps not strictly rising"),
    (0.85, 5.0): (0.44, 0.81, 0.00015, 0.061, "ramps not strictly rising"),
    (0.9, 1.01): (0.45, 1.36, 0.00056, 0.036, ""),
    (0.9, 1.05): (0.48, 1.05, 0.00039, 0.036, ""),
    (0.9, 1.1): (0.44, 1.14, 0.00026, 0.036, ""),
    (0.9, 1.2): (0.46, 1.4, 0.00018, 0.036, ""),
    (0.9, 1.3): (0.45, 1.33, 0.00014, 0.036, ""),
    (0.9, 1.5): (0.46, 1.47, 0.00014, 0.036, ""),
    (0.9, 2.0): (0.47, 1.4, 0.00015, 0.036, "ramps not strictly rising"),
    (0.9, 3.0): (0.48, 1.38, 0.00015, 0.041, "ramps not strictly rising"),
    (0.9, 5.0): (0.48, 1.36, 0.00015, 0.042, "ramps not strictly rising"),
    (0.95, 1.01): (0.47, 1.28, 0.0005, 0.036, ""),
    (0.95, 1.05): (0.83, 1.79, 0.00026, 0.036, "p99, max"),
    (0.95, 1.1): (0.78, 1.95, 0.00016, 0.036, "p99, max"),
    (0.95, 1.2): (0.75, 1.92, 0.00016, 0.036, "p99, max"),
    (0.95, 1.3): (0.76, 1.9, 0.00014, 0.036, "p99, max, ramps not strictly rising"),
    (0.95, 1.5): (0.76, 1.89, 0.00016, 0.036, "p99, max, ramps not strictly rising"),
    (0.95, 2.0): (0.74, 1.87, 0.00016, 0.036, "p99, max, ramps not strictly rising"),
    (0.95, 3.0): (0.73, 1.86, 0.00014, 0.036, "p99, max, ramps not strictly rising"),
    (0.95, 5.0): (0.73, 1.86, 0.00014, 0.036, "p99, max, ramps not strictly rising"),
    (0.99, 1.01): (1.32, 2.94, 0.00017, 0.036, "p99, max, ramps off the curve"),
    (0.99, 1.05): (1.31, 3.14, 0.00016, 0.036, "p99, max, ramps off the curve"),
    (0.99, 1.1): (
        1.31,
        3.09,
        0.00015,
        0.036,
        "p99, max, ramps off the curve, ramps not strictly rising",
    ),
    (0.99, 1.2): (
        1.31,
        3.1,
        0.00014,
        0.036,
        "p99, max, ramps off the curve, ramps not strictly rising",
    ),
    (0.99, 1.3): (
        1.31,
        3.09,
        0.00013,
        0.036,
        "p99, max, ramps off the curve, ramps not strictly rising",
    ),
    (0.99, 1.5): (
        1.3,
        3.08,
        0.00013,
        0.036,
        "p99, max, ramps off the curve, ramps not strictly rising",
    ),
    (0.99, 2.0): (
        1.3,
        3.08,
        0.00014,
        0.036,
        "p99, max, ramps off the curve, ramps not strictly rising",
    ),
    (0.99, 3.0): (
        1.3,
        3.08,
        0.00014,
        0.036,
        "p99, max, ramps off the curve, ramps not strictly rising",
    ),
    (0.99, 5.0): (
        1.3,
        3.08,
        0.00014,
        0.036,
        "p99, max, ramps off the curve, ramps not strictly rising",
    ),
}


@dataclass(frozen=True, eq=False)
class CompressLUT:
    """The baked compression for one display (see :func:`compress_lut`).

    S_b and S_w, and the display's :class:`~ocio_thinfilm.lut.clip_lut.ClipLUT` they run with.

    Attributes
    ----------
    display : str
    clip : ClipLUT
        The clip's passes (L, U), shared with the Constant-Lightness Clip view.
    black : numpy.ndarray
        (n, n, n, 3) over S_b's chart (u_a, u_b, Y) of ``chart``: the chart coordinates
        of S_b(X) and Y (constant along Y) times
        :func:`~ocio_thinfilm.lut.storage.grid_scale` (n), half floats rounded to the
        16-bit grid.
    white : numpy.ndarray
        (m, m, m, 3) over the nodes of :func:`~ocio_thinfilm.lut.grid.white_nodes`
        (:data:`SOFT_WHITE_INSIDE`, :data:`SOFT_WHITE_GRADED`, :data:`SOFT_WHITE_RATIO`,
        on the shaper's samples): S_w(c) / tops (the clip's white-pass input scale) on
        the 16-bit grid in [0, 1].
    white_shaper : numpy.ndarray
        (SHAPER_LENGTH, 3): the per-channel Lut1D over c_i / tops[i] in front of
        ``white``, piecewise linear in c between nodes.
    chart : numpy.ndarray
        (3, 3): CIE XYZ -> S_b's chart before ``XYZ_TO_xyY``
        (:func:`ocio_thinfilm.lut.grid.soft_plan`).
    parameters : tuple
        (threshold, limit, power) of the curve.
    """

    display: str
    clip: ClipLUT
    black: np.ndarray
    white: np.ndarray
    white_shaper: np.ndarray
    chart: np.ndarray
    parameters: tuple

    @property
    def name(self) -> str:
        """Name of the compression's transforms: ``Constant-Lightness Compress <display>``."""
        return f"{registry.COMPRESS_VIEW} {self.display}"

    def black_core(self) -> ocio_ops.Transform:
        """CLF-writable S_b: chart (u_a, u_b, Y) in and out."""
        name = f"{self.name} Black Faces"
        t, lim = (soft.knob_text(v) for v in self.parameters[:2])
        return group(
            [
                lut3d_transform(self.black, bitdepth="uint16"),
                ocio_ops.matrix(np.eye(3) / storage.grid_scale(self.black.shape[0])),
            ],
            name=name,
            id=transform_id("Gamut_Map", name),
            description=(
                f"Soft constant-lightness compression into {self.display}"
                f" (threshold {t}, limit {lim}), the squeeze by the "
                "distance to the faces through black, before the clip's "
                f"black pass: a {self.black.shape[0]}^3 tetrahedral "
                "Lut3D over its own chromaticity chart, which stores its output "
                "scaled so that the identity is exact in half floats, and the "
                "gain that undoes the scale; keeps Y. See "
                "ocio_thinfilm.lut.compress_lut."
            ),
            input_descriptor="(u_a, u_b, Y): XYZ_TO_xyY of a matrix of "
            "CIE-XYZ-D65, limited to [0, 1]",
            output_descriptor="(u_a, u_b, Y) of the squeezed colour",
        )

    def white_core(self) -> ocio_ops.Transform:
        """CLF-writable S_w: c_i / tops[i] in and out (after the clip's black pass)."""
        name = f"{self.name} White Faces"
        t, lim = (soft.knob_text(v) for v in self.parameters[:2])
        return group(
            [
                lut1d_transform(self.white_shaper, bitdepth="uint16"),
                lut3d_transform(self.white, bitdepth="uint16"),
            ],
            name=name,
            id=transform_id("Gamut_Map", name),
            description=(
                f"Soft constant-lightness compression into {self.display}"
                f" (threshold {t}, limit {lim}), the squeeze by the "
                "distance to the faces through white, before the clip's "
                f"white pass: a {self.white.shape[0]}^3 tetrahedral "
                "Lut3D over display RGB; keeps Y. See "
                "ocio_thinfilm.lut.compress_lut."
            ),
            input_descriptor=f"{self.display} display-linear RGB, each channel "
            "divided by 1.001 / its luminance weight",
            output_descriptor="the same, squeezed",
        )

    def transforms(
        self,
        black: ocio_ops.Transform | None = None,
        white: ocio_ops.Transform | None = None,
        clip_black: ocio_ops.Transform | None = None,
        clip_white: ocio_ops.Transform | None = None,
    ) -> list[ocio_ops.Transform]:
        """CIE-XYZ-D65 -> display RGB in [0, 1], sRGB-encoded.

        The clip's chain with S_b before its black pass and S_w before its white pass; the
        arguments replace the CLF-writable cores (e.g. by FileTransforms in the config).
        """
        ops = self.clip.transforms(clip_black, clip_white)
        # the clip's chain: limit, chart, xyY, pre-clip, L, xyY^-1, matrix, U
        to_clip_chart = reproducible.matmul(self.clip.chart, reproducible.inv3(self.chart))
        return (
            [
                ops[0],
                ocio_ops.matrix(self.chart),
                xyY_forward_transform(),
                ops[3],
                self.black_core() if black is None else black,
                xyY_inverse_transform(),
                ocio_ops.matrix(to_clip_chart),
                xyY_forward_transform(),
                ops[4],
            ]
            + ops[5:7]
            + [self.white_core() if white is None else white, ops[7]]
        )


def _squeeze_nodes(white_edge: int, display: str) -> tuple[np.ndarray, np.ndarray]:
    """S_w's nodes per axis and the clip's tops.

    By :func:`ocio_thinfilm.lut.grid.white_nodes` with :data:`SOFT_WHITE_INSIDE`,
    :data:`SOFT_WHITE_GRADED`, :data:`SOFT_WHITE_RATIO`, on the shaper's samples.
    """
    return grid.white_nodes(
        white_edge,
        display,
        inside=SOFT_WHITE_INSIDE,
        graded=SOFT_WHITE_GRADED,
        ratio=SOFT_WHITE_RATIO,
        snap=True,
    )


def _squeeze_codes(
    C: np.ndarray, display: str, parameters: tuple[float, float, float], tops: np.ndarray
) -> np.ndarray:
    """S_w's stored values at the (N, 3) nodes ``C``: S_w(c) / tops on the 16-bit grid.

    By :func:`ocio_thinfilm.lut.storage.q16`; not rounded to half floats first, which would
    move the identity nodes near white by up to 3e-4.
    """
    return storage.q16(np.clip(soft.soft_white_RGB(C, display, *parameters), 0.0, tops) / tops)


@cache.memoize(maxsize=16)
def _compress_lut(display, size, white_edge, parameters, clip_size):
    lut = clip_lut.clip_lut(display, clip_size)
    P = grid.soft_plan(display, size)
    M = colorimetry.matrix_XYZ_to_RGB(display)
    g = np.linspace(0.0, 1.0, size)
    ua, ub = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    with np.errstate(all="ignore"):
        rgb = reproducible.matmul(chart_to_XYZ(P, ua, ub), M.T)
        squeezed = soft.soft_black_RGB(rgb, display, *parameters)
        chart = reproducible.matmul(reproducible.matmul(squeezed, reproducible.inv3(M).T), P.T)
        uv = chart[:, :2] / chart.sum(axis=1, keepdims=True)
    uv = np.where(np.isfinite(uv), uv, np.c_[ua, ub])
    black = np.empty((size, size, size, 3))
    black[..., :2] = np.clip(uv, 0.0, 1.0).reshape(size, size, 1, 2)
    black[..., 2] = g
    # stored times grid_scale: the nodes where S_b is the identity (every colour up to
    # the threshold) then hold exact half floats, k / 2^m
    black *= storage.grid_scale(size)
    nodes, tops = _squeeze_nodes(white_edge, display)
    n = nodes.shape[1]
    C = np.stack(np.meshgrid(*nodes, indexing="ij"), axis=-1).reshape(-1, 3)
    # stored linear: with the shaper piecewise linear in c itself, the grid coordinates
    # are affine in c within each cell, so interpolating S_w, which keeps Y (a linear
    # function), keeps Y (stored sRGB-encoded, as the clip's white pass, the encoding's
    # curvature costs |dY|: docs/compress.md). The nodes sit on the shaper's samples
    # (snap=True), so the shaper is exact and the identity nodes are reproduced to the
    # 16-bit step.
    shaper = np.stack([grid.shaper_values(nodes[i], 0.0, tops[i]) for i in range(3)], axis=1)
    out = CompressLUT(
        display=display,
        clip=lut,
        black=storage.half16(black),
        white=_squeeze_codes(C, display, parameters, tops).reshape(n, n, n, 3),
        white_shaper=storage.q16(shaper),
        chart=P,
        parameters=parameters,
    )
    for array in (out.black, out.white, out.white_shaper, out.chart):
        array.setflags(write=False)
    return out


def compress_lut(
    display: registry.DisplayLike = "sRGB",
    size: int = SOFT_SIZE,
    white_edge: int = SOFT_WHITE_SIZE,
    threshold: float = soft.THRESHOLD,
    limit: float = soft.LIMIT,
    power: float = soft.POWER,
    clip_size: int = clip_lut.CLIP_SIZE,
) -> CompressLUT:
    """Return the baked compression LUTs for ``display`` (cached).

    Parameters
    ----------
    display : str or registry display
        A display of :data:`ocio_thinfilm.registry.DISPLAYS` or its name.
    size, white_edge : int
        Edges of S_b's and S_w's Lut3Ds, integers in [9, 129] and [7, 129].
    threshold, limit, power : float
        The curve of :func:`ocio_thinfilm.colour.compress.compression_curve`.
    clip_size : int
        Edge of the clip LUTs it runs with (:func:`ocio_thinfilm.lut.clip_lut.clip_lut`).

    Raises
    ------
    ValueError
        For an unknown display, an edge out of range or a bad curve parameter.
    """
    name = registry.as_display(display, hdr=False).gamut.name  # shared tables
    size = check_size(size, 9, 129, "size")
    white_edge = check_size(white_edge, 7, 129, "white_edge")
    soft.compression_curve(0.0, threshold, limit, power)  # validates the parameters
    clip_size = check_clip_size(clip_size)
    return _compress_lut(
        name, size, white_edge, (float(threshold), float(limit), float(power)), clip_size
    )


def knobs_tested(threshold: float, limit: float) -> bool:
    """Return whether the knobs lie in the tested range.

    :data:`TESTED_THRESHOLD` and :data:`TESTED_LIMIT`, bounds included.

    Parameters
    ----------
    threshold, limit : float
        The compression's knobs.

    Returns
    -------
    bool

    Examples
    --------
    >>> knobs_tested(0.8, 1.3), knobs_tested(0.95, 1.05)
    (True, False)
    """
    (t_lo, t_hi), (l_lo, l_hi) = TESTED_THRESHOLD, TESTED_LIMIT
    return bool(t_lo <= threshold <= t_hi and l_lo <= limit <= l_hi)


def _knob_distance(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Return the distance between knob pairs, over 10 x threshold and log(limit - 1).

    The scale the view's accuracy changes on: limits 1.05 and 1.1 differ more than 2
    and 3.
    """
    return float(np.hypot(10.0 * (a[0] - b[0]), np.log(a[1] - 1.0) - np.log(b[1] - 1.0)))


def untested_knobs_note(threshold: float, limit: float) -> str | None:
    """Return one line on knobs outside the tested range, with the benchmark's figure.

    ``None`` inside the range (:func:`knobs_tested`). Outside it, the line names the
    tested range and the accuracy the benchmark found at the nearest pair it ran
    (:data:`MEASURED_KNOBS`: the pair itself when it ran it).

    Parameters
    ----------
    threshold, limit : float
        The compression's knobs.

    Returns
    -------
    str or None
    """
    if knobs_tested(threshold, limit):
        return None
    (t_lo, t_hi), (l_lo, l_hi) = TESTED_THRESHOLD, TESTED_LIMIT
    text = (
        f"threshold {soft.knob_text(threshold)} / limit {soft.knob_text(limit)} lie outside "
        f"the tested range (threshold {t_lo:g}-{t_hi:g}, limit {l_lo:g}-{l_hi:g}), where the "
        f"baked view keeps dE2000 p99 <= {KNOB_TARGETS['p99']:g} / max <= "
        f"{KNOB_TARGETS['max']:g} of the analytic map"
    )
    if MEASURED_KNOBS:
        pair = min(MEASURED_KNOBS, key=lambda p: _knob_distance(p, (threshold, limit)))
        p99, worst, dY, inside, misses = MEASURED_KNOBS[pair]
        where = "measured there" if pair == (threshold, limit) else "measured at the nearest pair"
        text += (
            f"; {where}, {pair[0]:g} / {pair[1]:g}: p99 {p99:.2f} / max {worst:.2f}, |dY| "
            f"{dY:.1e}, colours below the threshold moved by up to {inside:.3f}, "
            + (f"missing: {misses}" if misses else "every target met")
            + " (docs/compress.md)"
        )
    return text
