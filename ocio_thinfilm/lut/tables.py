"""Thin-film tables (paper Section 2.1): pixel value -> exact CIE XYZ, as OCIO transforms.

The paper precomputes each film's colour against thickness once and looks it up per
pixel; here a table is a :class:`Table1D` -- XYZ at its nodes, the numpy lookup and the
same lookup as an OCIO transform (shaper + ``Lut1D``), which the config ships as CLF.

- :func:`film_table` -- the single film of Eq. 7 / Eq. 8 against optical thickness
  t' = n t cos(theta_t) in micrometres, through a log shaper
  ``u = log2(1 + t'/t0) / log2(1 + t'_max/t0)`` (``t0 = 1 um``, ``t'_max = 100 um``):
  at 100 um the band-limited colour is the incoherent grey (half the illuminant), so
  the LUT's clamp beyond the range gives the right limit; negative thickness, -inf and
  NaN give black.
- :func:`morpho_table` -- the Morpho multilayer (Eq. 9 + 14) against cos(theta),
  uniform over [0, 1] (the clamp gives grazing / normal incidence outside).
- :func:`thin_film_table` -- the table behind one of the registry's thin-film input
  spaces (:data:`ocio_thinfilm.registry.THIN_FILM_LIST`).

Accuracy against table size: ``benchmarks/bench_luts.py`` and reports/report.md.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import cache, registry
from ocio_thinfilm.checks import as_choice, as_count, as_positive
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.ocio_ops import group, lut1d_transform, transform_id

__all__ = [
    "FILM_KINDS",
    "FILM_SIZE",
    "FILM_T0_UM",
    "FILM_TMAX_UM",
    "MORPHO_SIZE",
    "SPECTRAL_STEP",
    "Table1D",
    "film_table",
    "morpho_table",
    "thin_film_table",
    "check_size",
]

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
    nodes: np.ndarray | None = field(default=None, repr=False)
    #: What the pixel value is, if not the built-in tables' (a user's film).
    pixel: str = ""

    @property
    def size(self) -> int:
        """Number of nodes of the table (the rows of ``values``)."""
        return int(self.values.shape[0])

    # -- numpy path -------------------------------------------------------- #
    def shaper(self, x: npt.ArrayLike) -> np.ndarray:
        """Normalised table coordinate u in [0, 1] (clamped) of pixel values ``x``."""
        x = np.nan_to_num(np.asarray(x, dtype=np.float64), nan=0.0)
        if self.encoding == "log":
            t = np.maximum(x, 0.0)
            u = np.log1p(np.minimum(t, 1e30) / self.t0) / np.log1p(self.domain_max / self.t0)
        else:
            u = (x - self.domain_min) / (self.domain_max - self.domain_min)
        return np.clip(u, 0.0, 1.0)

    def lookup(self, x: npt.ArrayLike) -> np.ndarray:
        """XYZ for pixel values ``x`` (any shape), by the same linear interpolation OCIO applies.

        Returns shape ``x.shape + (3,)``, float64.
        """
        u = self.shaper(x) * (self.size - 1)
        i = np.minimum(np.floor(u).astype(np.int64), self.size - 2)
        f = (u - i)[..., None]
        out = self.values[i] * (1.0 - f) + self.values[i + 1] * f
        if self.encoding == "log":  # negative and NaN thickness: black (as through OCIO)
            x = np.asarray(x)
            out[(x < 0) | np.isnan(x)] = 0.0
        return out

    # -- OCIO path --------------------------------------------------------- #
    def shaper_transform(self) -> ocio_ops.Transform:
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

    def lut_transform(self) -> ocio_ops.Transform:
        """Return the Lut1D of the table's nodes alone (no shaper).

        Returns
        -------
        PyOpenColorIO.Lut1DTransform
            :func:`~ocio_thinfilm.lut.ocio_ops.lut1d_transform` of ``values``.
        """
        return lut1d_transform(self.values)

    def _black_node(self) -> bool:
        """Return whether the table gets a black node in front of it.

        A thickness table whose t' = 0 entry is not black (no phase change: white)
        gets a black node in front of it, so negative, -inf and NaN thicknesses give
        black through OCIO as well (the LUT's clamp lands on that node).
        """
        return self.encoding == "log" and bool(np.any(self.values[0] != 0.0))

    def transform(self) -> ocio_ops.Transform:
        """OCIO transform from the pixel encoding to CIE-XYZ-D65.

        A GroupTransform with CLF metadata: shaper, then the Lut1D.
        """
        ops = [self.lut_transform()]
        if self._black_node():
            # Nodes i/(n-1) move to (i+1)/n, behind a black node at 0: t' >= 0 is
            # unchanged, t' < 0 (the log goes negative), -inf and NaN give black;
            # only -0.6 nm < t' < 0 blends towards the t' = 0 colour.
            n = self.size
            shaper = self.shaper_transform()
            shaper.setLogSideSlopeValue([v * (n - 1) / n for v in shaper.getLogSideSlopeValue()])
            shaper.setLogSideOffsetValue([1.0 / n] * 3)
            values = np.vstack([np.zeros((1, 3)), self.values])
            ops = [shaper, lut1d_transform(values)]
        elif self.encoding == "log":
            # Negative thickness: log of (1 + t/t0) < 1 is negative -> clamped to
            # u = 0 by the LUT; t <= -t0 is clamped by OCIO's log to a tiny argument.
            ops.insert(0, self.shaper_transform())
        elif (self.domain_min, self.domain_max) != (0.0, 1.0):
            ops.insert(0, self.shaper_transform())
        return group(
            ops,
            name=self.name,
            id=transform_id("Input", self.name),
            description=self.description,
            input_descriptor=self.input_descriptor,
            output_descriptor="CIE-XYZ-D65 (perfect reflector Y = 1)",
        )

    @property
    def input_descriptor(self) -> str:
        """CLF input descriptor: what the pixel values are (cos(theta) or thickness)."""
        if self.pixel:
            return self.pixel
        if self.kind == "morpho":
            return "cos(theta): facing ratio N.V, all channels equal"
        return "optical thickness t' = n t cos(theta_t) in micrometres, all channels equal"

    def rgb(self, display: str = "sRGB", clipped: bool = True) -> np.ndarray:
        """Per-display variant: the nodes in display-linear RGB.

        Constant-lightness clipped (``clipped=True``) or raw.
        """
        rgb = colorimetry.XYZ_to_RGB(self.values, display)
        return clip.clip_RGB(rgb, display) if clipped else rgb


def check_size(size: int, minimum: int = 2, maximum: int = 1 << 20, what: str = "size") -> int:
    """Return ``size`` as an int if it is an integer in [minimum, maximum].

    A TypeError naming ``what`` for what is not a number (``"65"`` is not parsed); a
    :class:`~ocio_thinfilm.checks.ParameterError` otherwise.
    """
    return as_count(what, size, minimum, maximum)


@cache.memoize(maxsize=32)
def _film_table(kind, size, tmax_um, t0_um, step):
    u = np.linspace(0.0, 1.0, size)
    t_um = t0_um * np.expm1(u * np.log1p(tmax_um / t0_um))
    t_um[-1] = tmax_um
    values = colorimetry.film_XYZ(t_um * 1000.0, kind, step=step)
    name = f"Thin Film {'Phase-Change' if kind == 'phase-change' else 'No-Phase-Change'} Thickness"
    values.setflags(write=False)
    t_um.setflags(write=False)
    return Table1D(
        kind=kind,
        values=values,
        encoding="log",
        domain_min=0.0,
        domain_max=float(tmax_um),
        t0=float(t0_um),
        nodes=t_um,
        name=name,
        description=(
            f"Smits & Meyer 1990 Eq. {7 if kind == 'phase-change' else 8}: "
            f"exact XYZ (D65, CIE 1931 2 deg, band-limited {step:g} nm) of a "
            f"{kind} thin film against optical thickness 0-{tmax_um:g} um; "
            f"log2 shaper (t0 = {t0_um:g} um), {size}-entry Lut1D."
        ),
    )


def film_table(
    kind: str = "phase-change",
    size: int = FILM_SIZE,
    *,
    max_thickness_um: float = FILM_TMAX_UM,
    t0_um: float = FILM_T0_UM,
    step: float = SPECTRAL_STEP,
) -> Table1D:
    """Thickness table of the paper's single film (Eq. 7 / Eq. 8).

    Pixel value = optical thickness t' in micrometres (all channels equal) -> the
    film's exact XYZ, the perfect reflector at Y = 1 under D65. Nodes are log-spaced
    (see the module docstring); beyond ``max_thickness_um`` the table holds its last
    entry, the incoherent grey.

    Parameters
    ----------
    kind : {"phase-change", "no-phase-change"}
        Eq. 7 (a soap film in air: one reflection changes phase) or Eq. 8.
    size : int
        Entries of the Lut1D, in [2, 2**20].
    max_thickness_um, t0_um : float
        End of the thickness range and knee of the log shaper, micrometres.
    step : float
        Wavelength step (nm) of the band-limited integration
        (:func:`ocio_thinfilm.colour.colorimetry.film_XYZ`).

    Returns
    -------
    Table1D
        Cached: equal arguments return the same (read-only) table.

    References
    ----------
    Smits, B. E., & Meyer, G. W. (1990). Newton's Colors: Simulating Interference
    Phenomena in Realistic Image Synthesis. Eurographics Workshop on Photosimulation,
    Realism and Physics in Computer Graphics. Section 2.1, Eq. 7 and 8.

    Examples
    --------
    A soap film thinner than any wavelength is black (sin^2 0 = 0); a thick one is
    the incoherent average, half the D65 white (0.9505, 1, 1.0888):

    >>> table = film_table("phase-change")
    >>> table.lookup([0.0, 100.0]).round(3).tolist()
    [[0.0, 0.0, 0.0], [0.475, 0.5, 0.544]]

    Without the phase change, zero thickness reflects all of the light (cos^2 0 = 1):

    >>> film_table("no-phase-change").lookup(0.0).round(3).tolist()
    [0.95, 1.0, 1.089]
    """
    kind = as_choice("kind", kind, FILM_KINDS)
    size = check_size(size)
    tmax = as_positive("max_thickness_um", max_thickness_um)
    t0 = as_positive("t0_um", t0_um)
    step = as_positive("step", step)
    return _film_table(kind, size, tmax, t0, step)


@cache.memoize(maxsize=8)
def _morpho_table(size, step):
    c = np.linspace(0.0, 1.0, size)
    theta = np.degrees(np.arccos(c))
    values = colorimetry.morpho_XYZ(theta, step=step)
    values.setflags(write=False)
    c.setflags(write=False)
    return Table1D(
        kind="morpho",
        values=values,
        encoding="linear",
        domain_min=0.0,
        domain_max=1.0,
        nodes=c,
        name="Thin Film Morpho Iridescence",
        description=(
            f"Smits & Meyer 1990 Eq. 9 + 14: exact XYZ (D65, CIE 1931 2 deg, "
            f"band-limited {step:g} nm) of the Morpho wing multilayer against "
            f"cos(theta) (facing ratio N.V) in [0, 1]; {size}-entry Lut1D."
        ),
    )


def morpho_table(size: int = MORPHO_SIZE, *, step: float = SPECTRAL_STEP) -> Table1D:
    """Angle table of the Morpho multilayer (Eq. 9 + 14).

    Pixel value = cos(theta) of the viewing angle (N.V) -> exact XYZ. Values outside [0, 1]
    are clamped (grazing / normal incidence).

    Parameters
    ----------
    size : int
        Entries of the Lut1D (uniform in cos(theta) over [0, 1]), in [2, 2**20].
    step : float
        Wavelength step (nm) of the band-limited integration.

    Returns
    -------
    Table1D
        Cached: equal arguments return the same (read-only) table.

    Examples
    --------
    Seen face on, the wing is blue-violet (Eq. 9 peaks near 453 nm at normal
    incidence: chromaticity x well below the white's 0.313):

    >>> X, Y, Z = morpho_table().lookup(1.0)
    >>> bool(X / (X + Y + Z) < 0.2)
    True
    """
    size = check_size(size)
    step = as_positive("step", step)
    return _morpho_table(size, step)


def thin_film_table(
    space: registry.ThinFilmSpace, *, film_size: int = FILM_SIZE, morpho_size: int = MORPHO_SIZE
) -> Table1D:
    """Return the table behind a thin-film input space of the registry.

    The space is a :class:`ocio_thinfilm.registry.ThinFilmSpace`: :func:`film_table` or
    :func:`morpho_table` as its ``table`` field says, with its arguments.
    """
    if space.table == "film":
        # the registry checks that a film space's args are (kind,): mypy cannot see it
        return film_table(*space.args, size=film_size)  # type: ignore[misc]
    if space.table == "morpho":
        return morpho_table(size=morpho_size)
    raise ValueError(f"thin-film space {space.name!r}: unknown table {space.table!r}")
