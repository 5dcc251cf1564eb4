"""What every scene is made of: the tables it declares, the picture it returns, its base class.

:class:`TableSpec` (a table a scene needs, :data:`FILM_TABLE`, :data:`MORPHO_TABLE`),
:class:`Picture` (what a scene hands the renderer), :class:`Scene` (the base class of
the scenes of :mod:`ocio_thinfilm.render.scenes`) and the shading helpers they share.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from ocio_thinfilm.lut import tables
from ocio_thinfilm.physics import spectra

__all__ = [
    "TableSpec",
    "FILM_TABLE",
    "MORPHO_TABLE",
    "Lookup",
    "D65_WHITE",
    "Picture",
    "Scene",
    "pixel_grid",
    "smoothstep",
    "optical_thickness_um",
    "grey",
    "unit",
]


@dataclasses.dataclass(frozen=True)
class TableSpec:
    """A table a scene needs.

    The scenes ask for the tables the OCIO config ships (the tables module's
    defaults), so the renders prove exactly those LUTs.

    Parameters
    ----------
    kind : str
        ``"phase-change"``, ``"no-phase-change"`` or ``"morpho"``.
    range : tuple of float
        The encoding range the table covers: t' in micrometres from 0, or cos(theta)
        in [0, 1] for ``"morpho"``.
    entries : int
        Its number of entries.
    """

    kind: str
    range: tuple[float, float]
    entries: int
    #: A user's film (``kind == "user"``): its colour space in the config (pixel value
    #: = physical thickness of its varying layer, um; an exact film's physical
    #: reflectance), from ``bake --films``.
    space: str = ""

    @property
    def encoding(self) -> str:
        """What the table is indexed with.

        ``"cos(theta)"``, the optical thickness or a user's film's physical thickness.
        """
        if self.kind == "user":
            return f"physical thickness (um) of the film of {self.space!r}"
        return "cos(theta)" if self.kind == "morpho" else "optical thickness t' (um)"


#: Newton's colours of a film with a phase change (soap, oil on water): the shipped
#: thickness table (log-shaped, t' = 0-100 um; the scenes use t' <= 1.5 um).
FILM_TABLE = TableSpec("phase-change", (0.0, tables.FILM_TMAX_UM), tables.FILM_SIZE)
#: The Morpho multilayer against the facing ratio cos(theta) in [0, 1].
MORPHO_TABLE = TableSpec("morpho", (0.0, 1.0), tables.MORPHO_SIZE)

#: Lookup supplied by the renderer: (spec, encoded (H, W)) -> XYZ (H, W, 3).
Lookup = Callable[[TableSpec, np.ndarray], np.ndarray]

#: XYZ of the D65 perfect white (Y = 1).
D65_WHITE = np.array([0.95047, 1.0, 1.08883], np.float32)


@dataclasses.dataclass
class Picture:
    """What a scene hands the renderer.

    Parameters
    ----------
    xyz : numpy.ndarray
        (H, W, 3) float32 scene-linear CIE XYZ (D65, Y = 1 white).
    aovs : dict
        Extra EXR channels, name -> (H, W) float32 (documented in ``aov_docs``).
    aov_docs : dict
        Channel name -> what it holds.
    regions : list of tuple
        ``(x0, x1, view)`` column ranges and the view each is displayed through;
        ``view=None`` means the view chosen on the command line.
    labels : list of tuple, optional
        ``(x, y, text, size)`` captions drawn on the display image.
    attributes : dict, optional
        Metadata for the EXR (exposure, parameters).
    """

    xyz: np.ndarray
    aovs: dict
    aov_docs: dict
    regions: list
    labels: list = dataclasses.field(default_factory=list)
    attributes: dict = dataclasses.field(default_factory=dict)


class Scene:
    """Base class of the scenes: a name, the figure it reproduces, the tables it declares.

    The oil and soap scenes also take a user's film (:meth:`with_film`): its table
    (physical thickness of the film's varying layer at the film's own angle -> its
    physical reflectance) replaces the paper's two-beam film and the scene's own Fresnel
    sheen, so the picture shows the film as reflected.

    Attributes
    ----------
    name : str
        The scene's name (a key of :data:`~ocio_thinfilm.render.scenes.SCENES`).
    figure : str
        The paper's figure it reproduces.
    title : str
        What it shows.
    animation : str
        What changes with the frame number.
    tables : tuple of TableSpec
        The tables its ``lookup`` is called with.
    """

    name = ""
    figure = ""
    title = ""
    animation = ""
    tables: tuple[TableSpec, ...] = ()
    #: A user's film (a :class:`TableSpec` of kind ``"user"``), None: the paper's.
    film: TableSpec | None = None
    #: Whether :meth:`with_film` applies.
    takes_films = False

    def with_film(self, film: TableSpec) -> Scene:
        """Return a copy of this scene rendering the user's ``film``.

        Parameters
        ----------
        film : TableSpec
            The film's table, of kind ``"user"``.

        Returns
        -------
        Scene
            A shallow copy whose :attr:`film` is ``film`` and whose :attr:`tables` are
            ``(film,)``.

        Raises
        ------
        ValueError
            If the scene has no film to replace (only oil and soap do).
        """
        if not self.takes_films:
            raise ValueError(f"the {self.name} scene has no film to replace (oil and soap do)")
        import copy

        scene = copy.copy(self)
        scene.film = film
        scene.tables = (film,)
        return scene

    def render(
        self, width: int, height: int, *, lookup: Lookup, seed: int = 0, frame: int = 1
    ) -> Picture:  # pragma: no cover - abstract
        """Render one frame of the scene in scene-linear CIE XYZ.

        Parameters
        ----------
        width, height : int
            Image size in pixels.
        lookup : callable
            ``lookup(spec, encoded)``: (H, W) encoded values of a table of :attr:`tables`
            -> (H, W, 3) CIE XYZ (the renderer's, e.g.
            :func:`~ocio_thinfilm.render.processors.make_lookup`).
        seed : int, optional
            Noise seed, an integer >= 0 (default 0).
        frame : int, optional
            Frame number, 1 the still (default 1); animated parameters depend on it only.

        Returns
        -------
        Picture
            The picture, its AOVs, column regions, captions and EXR attributes.
        """
        raise NotImplementedError


def pixel_grid(width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """Return the pixel centres as float32 (x in [0, W), y in [0, H)), each (H, W)."""
    y, x = np.meshgrid(
        np.arange(height, dtype=np.float32) + np.float32(0.5),
        np.arange(width, dtype=np.float32) + np.float32(0.5),
        indexing="ij",
    )
    return x, y


def smoothstep(e0: float, e1: float, x: np.ndarray) -> np.ndarray:
    """Return the smooth step from 0 at ``e0`` to 1 at ``e1`` (3t^2 - 2t^3, clamped)."""
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def optical_thickness_um(t_um: np.ndarray, n: float, theta_deg: np.ndarray) -> np.ndarray:
    """Return the table index t' = t n cos(theta_t) in micrometres.

    Paper Eq. 10 form, through the refraction angle; :func:`.spectra.optical_thickness`
    works in nm.
    """
    t_nm = np.asarray(t_um, np.float64) * 1000.0
    return (spectra.optical_thickness(t_nm, n, theta_deg) / 1000.0).astype(np.float32)


def grey(Y: np.ndarray) -> np.ndarray:
    """Return neutral (D65) XYZ of luminance ``Y`` (H, W) -> (H, W, 3)."""
    return np.asarray(Y, np.float32)[..., None] * D65_WHITE


def unit(v: np.ndarray) -> np.ndarray:
    """Return the vectors ``v`` (..., 3) scaled to unit length, float32.

    The length is ``sqrt(x*x + y*y + z*z)`` in that order, elementwise: the same bits
    on every CPU (``np.linalg.norm`` reduces with whatever loop numpy's SIMD level
    picks).
    """
    v = np.asarray(v, np.float32)
    length = np.sqrt(v[..., 0] * v[..., 0] + v[..., 1] * v[..., 1] + v[..., 2] * v[..., 2])
    return v / length[..., None]
