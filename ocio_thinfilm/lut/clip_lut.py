"""The constant-lightness clip (paper Section 3.2) baked into two 3D LUTs, as OCIO transforms.

The clip factors exactly as clip = U o L along the same ray (L only against R, G, B >= 0,
U only against R, G, B <= 1; the analytic ones are
:func:`ocio_thinfilm.colour.clip.clip_black_faces_RGB` and
:func:`~ocio_thinfilm.colour.clip.clip_white_faces_RGB`). Pass 1, L, is a Lut3D over a
projective chromaticity chart (exactly linear in Y, its nodes outside the primaries'
triangle fitted by :mod:`ocio_thinfilm.lut.node_fit`); pass 2, U, a Lut3D over encoded
display RGB whose nodes brighter than white hold U's analytic continuation. Where the
nodes go is :mod:`ocio_thinfilm.lut.grid`, the 16-bit / half-float storage
:mod:`ocio_thinfilm.lut.storage`. The two passes in detail, accuracy, size, load time
and why the layout is so: docs/gamut_map.md, *Design*.

- :func:`clip_lut` / :class:`ClipLUT` -- the baked LUT data of one display and their
  CLF-writable cores; :meth:`ClipLUT.transforms` -- the whole chain;
- :func:`clip_transform` -- CIE-XYZ-D65 -> display-linear RGB, clipped;
- :func:`xyz_limit_transform`, :func:`xyY_forward_transform`,
  :func:`xyY_inverse_transform`, :func:`working_decoding_transform` -- the chain's
  analytic ops.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ocio_thinfilm import cache, registry, reproducible
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import grid, node_fit, ocio_ops, storage
from ocio_thinfilm.lut.display_transforms import (
    display_encoding_transform,
)
from ocio_thinfilm.lut.ocio_ops import (
    group,
    lut1d_transform,
    lut3d_transform,
    transform_id,
)
from ocio_thinfilm.lut.tables import check_size

__all__ = [
    "CLIP_SIZE",
    "WHITE_SIZE",
    "WHITE_SCALE",
    "ClipLUT",
    "clip_lut",
    "clip_transform",
    "white_size",
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
#: The white pass's Lut3D holds code values / WHITE_SCALE: its nodes brighter than
#: white hold U's continuation (code values above 1), capped at WHITE_SCALE.
WHITE_SCALE = 1.25


def white_size(size: int) -> int:
    """Edge of the white pass's Lut3D for a black pass of edge ``size``.

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
    Section 7.3). After the chart matrix of :func:`ocio_thinfilm.lut.grid.black_plan` it gives the
    black pass's Lut3D coordinates (u_a, u_b) and Y directly.

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


def _white_codes(C: np.ndarray, display: str) -> np.ndarray:
    """Return the white pass's stored values at the (N, 3) nodes ``C``.

    U continued above white
    (:func:`~ocio_thinfilm.colour.clip.clip_white_faces_continued_RGB`), in the working
    encoding, / WHITE_SCALE, on the 16-bit grid.
    """
    continued = clip.clip_white_faces_continued_RGB(C, display)
    code = grid.encode(np.clip(continued, 0.0, None), grid.WORKING_ENCODING)
    return storage.q16(code / WHITE_SCALE)


@dataclass(frozen=True, eq=False)
class ClipLUT:
    """The baked constant-lightness clip for one display (see :func:`clip_lut`).

    The clip of Smits & Meyer (1990), Section 3.2, factored as U o L
    (:func:`ocio_thinfilm.colour.clip.clip_black_faces_RGB`,
    :func:`~ocio_thinfilm.colour.clip.clip_white_faces_RGB`). Frozen; its arrays
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
        the nodes of :func:`ocio_thinfilm.lut.grid.white_nodes`: sRGB-encoded code values of U(c)
        (above white: its continuation) / :data:`WHITE_SCALE`, on the 16-bit grid in [0, 1].
    white_shaper : numpy.ndarray
        float64, (:data:`ocio_thinfilm.lut.grid.SHAPER_LENGTH`, 3): the Lut1D over c_i / tops[i] in
        front of ``white``, grid coordinates on the 16-bit grid.
    chart : numpy.ndarray
        float64, (3, 3): the matrix taking CIE XYZ (D65 white at Y = 1) to the
        black pass's chart before ``XYZ_TO_xyY``.
    tops : numpy.ndarray
        float64, (3,): largest display-linear value of each channel the white pass
        covers, just above 1 / (the channel's luminance weight).
    frame : numpy.ndarray
        float64, (2, 2): ``[origin, sign]`` of the stored coordinates
        z = sign (u - origin) (:func:`ocio_thinfilm.lut.storage.face_frame`); the black core's
        matrix maps them back to (u_a, u_b).

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
        """Name of the clip's transforms: ``Constant-Lightness Clip <display>``."""
        return f"{registry.CLIP_VIEW} {self.display}"

    def black_core(self) -> ocio_ops.Transform:
        """CLF-writable black pass: the Lut3D.

        Chart (u_a, u_b, Y) in, the chart coordinates of L(X) and Y out.
        """
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
        """CLF-writable white pass: per-channel shaper, Lut3D, its scale and a clamp.

        Display-linear c_i / tops[i] in (no negative channel), display code values out.
        """
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
        """Return the whole clip as a list of OCIO transforms.

        CIE-XYZ-D65 -> display RGB in [0, 1], sRGB-encoded
        (:data:`ocio_thinfilm.lut.grid.WORKING_ENCODING`); ``black`` / ``white`` replace the
        CLF-writable cores (e.g. by FileTransforms in the config).
        """
        M = colorimetry.matrix_XYZ_to_RGB(self.display)
        to_white = reproducible.matmul(
            reproducible.matmul(np.diag(1.0 / self.tops), M), reproducible.inv3(self.chart)
        )
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


@cache.persistent(
    modules=(
        "ocio_thinfilm.lut.grid",
        "ocio_thinfilm.lut.node_fit",
        "ocio_thinfilm.lut.storage",
        "ocio_thinfilm.colour.clip",
        "ocio_thinfilm.colour.colorimetry",
    )
)
def _black_nodes(display, size):
    """Return the black pass's (u_a, u_b) node values as stored, (size * size + 2, 2).

    The nodes' z = sign (u - origin) (L at the nodes, the outside ones fitted and rounded
    to half floats inside the triangle), then the rows origin and sign of
    :func:`~ocio_thinfilm.lut.storage.face_frame`. Memoised on disk (the fit takes
    seconds per display; the key covers the source of the modules that make it and
    colour-science's version).
    """
    P, _ = grid.black_plan(display, size)
    g = np.linspace(0.0, 1.0, size)
    ua, ub = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    uv, inside = node_fit.black_map(display, P, ua, ub)
    uv = node_fit.fit_outside_nodes(display, P, size, uv, inside)
    # stored as z = sign (u - origin): the faces on u_a / u_b = const at 0 exactly; the
    # outside nodes (on the faces) rounded to half floats inside the triangle, the
    # others (in-gamut identity nodes, on the grid) are half floats already
    V = node_fit.chart_triangle(display, P)
    origin, sign = storage.face_frame(V)
    origin = np.round(origin * (size - 1)) / (size - 1)  # on node lines by construction
    z = (uv - origin) * sign
    z[~inside] = storage.halves_inside(z[~inside], (V - origin) * sign)
    return np.concatenate([z, [origin], [sign]])


@cache.memoize(maxsize=16)
def _clip_lut(display, size, white_edge):
    P, _ = grid.black_plan(display, size)
    # black pass: constant along Y, whose output is Y itself
    stored = _black_nodes(display, size)
    z, origin, sign = stored[:-2], stored[-2], stored[-1]
    g = np.linspace(0.0, 1.0, size)
    black = np.empty((size, size, size, 3))
    black[..., :2] = z.reshape(size, size, 1, 2)
    black[..., 2] = g
    # white pass: RGB nodes -> U(c) (continued above white), sRGB-encoded / scale
    nodes, tops = grid.white_nodes(white_edge, display)
    n = nodes.shape[1]
    C = np.stack(np.meshgrid(*nodes, indexing="ij"), axis=-1).reshape(-1, 3)
    shaper = np.stack(
        [
            grid.shaper_values(
                nodes[i], 0.0, tops[i], along=lambda v: grid.encode(v, grid.WORKING_ENCODING)
            )
            for i in range(3)
        ],
        axis=1,
    )
    # the black pass: half floats first, then the 16-bit grid (see storage.halves_inside)
    lut = ClipLUT(
        display=display,
        size=size,
        black=storage.half16(black),
        white=_white_codes(C, display).reshape(n, n, n, 3),
        white_shaper=storage.q16(shaper),
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
    """Return the baked clip LUTs for ``display`` (cached).

    Both passes, from :func:`ocio_thinfilm.colour.clip.clip_black_faces_RGB` and
    :func:`~ocio_thinfilm.colour.clip.clip_white_faces_RGB`, whose composition
    is :func:`ocio_thinfilm.colour.clip.clip_RGB` exactly.

    Parameters
    ----------
    display : str or registry display, optional
        A display of :data:`ocio_thinfilm.registry.DISPLAYS` or its name (default
        ``"sRGB"``); a display with another's gamut gets that display's tables.
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
    name = registry.as_display(display, hdr=False).gamut.name  # shared tables
    size = check_size(size, 9, 129, "size")
    white_edge = white_size(size) if white_edge is None else white_edge
    return _clip_lut(name, size, check_size(white_edge, 7, 129, "white_edge"))


def working_decoding_transform() -> ocio_ops.Transform:
    """Return the transform from sRGB code values (the white pass's output) to display-linear RGB.

    The inverse of :func:`ocio_thinfilm.lut.display_transforms.display_encoding_transform`
    for :data:`ocio_thinfilm.lut.grid.WORKING_ENCODING`: the IEC 61966-2-1 sRGB EOTF, ``V / 12.92``
    up to V = 0.04045 and ``((V + 0.055) / 1.055) ** 2.4`` above.

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
    return ocio_ops.inverse([display_encoding_transform(grid.WORKING_ENCODING)])


def clip_transform(
    display: registry.DisplayLike = "sRGB", size: int = CLIP_SIZE
) -> ocio_ops.Transform:
    """OCIO transform CIE-XYZ-D65 -> display-linear RGB in [0, 1], constant-lightness clipped.

    :meth:`ClipLUT.transforms` (range limit, chart, the black-faces pass, the
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
