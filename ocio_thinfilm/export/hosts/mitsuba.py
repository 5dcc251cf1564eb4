"""A film as a spectral Mitsuba 3 BSDF: ``thinfilm``, the exact film per sampled wavelength.

Call :func:`register` after ``mi.set_variant(...)`` (a spectral variant; the plugin
subclasses that variant's ``mi.BSDF``); :func:`bsdf` builds a checked scene dict::

    import mitsuba as mi
    mi.set_variant("scalar_spectral")
    import ocio_thinfilm.export.hosts.mitsuba as tfm
    tfm.register()
    plate = {"type": "rectangle", "bsdf": tfm.bsdf("films.toml", "SoapFilm", thickness=0.3)}

At every shading point the film's stack is evaluated exactly at the path's sampled
wavelengths and angle by :func:`ocio_thinfilm.physics.exact.stack_pointwise`. A
free-standing film reflects and transmits (two-sided, choosing reflection with
probability at least :data:`MIN_REFLECTION_PROBABILITY`); a film on a substrate reflects
only. A :class:`FilmSampler` holds the numpy side (no Mitsuba type); JIT variants render
inside :func:`evaluated_mode`. The BSDF's properties and its sampling in full:
docs/mitsuba.md, *Parameters*.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from contextlib import contextmanager
from os import PathLike
from typing import Any

import numpy as np

try:
    import drjit as dr
    import mitsuba as mi
except ImportError as _error:  # pragma: no cover - the message is the point
    raise ImportError(
        'ocio_thinfilm.export.hosts.mitsuba needs Mitsuba 3: pip install "ocio-thinfilm[mitsuba]"'
    ) from _error

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.lut import material_tables
from ocio_thinfilm.physics import exact
from ocio_thinfilm.physics.films import Film, read_films

__all__ = [
    "PLUGIN",
    "WAVELENGTH_RANGE",
    "MIN_REFLECTION_PROBABILITY",
    "FilmSampler",
    "film_token",
    "bsdf",
    "register",
    "evaluated_mode",
]

#: The plugin's name in scenes (``"type": "thinfilm"``).
PLUGIN = "thinfilm"
#: Mitsuba's spectral range (nm): the wavelengths its spectral variants sample.
WAVELENGTH_RANGE = (360.0, 830.0)
#: The least probability with which a free-standing film's reflection is sampled (else
#: mean R / (mean R + mean T)): a bubble reflects ~5 %, and its colours are its reflection.
MIN_REFLECTION_PROBABILITY = 0.25
#: Step (nm) of the grid the materials' indices are held on.
_INDEX_STEP = 0.25
#: Films passed as objects (:func:`film_token`).
_FILMS: dict[str, Film] = {}
_TOKENS = itertools.count()


def film_token(film: Film) -> str:
    """Return a string that names ``film`` in a scene: ``{"type": "thinfilm", "film": token}``.

    Mitsuba's properties hold numbers, strings and plugins, not Python objects; the
    token names the film in this process.

    Parameters
    ----------
    film : Film
        The film (e.g. from :func:`ocio_thinfilm.physics.films.read_films`).

    Returns
    -------
    str
        ``"<object>:<key>:<n>"``.
    """
    if not isinstance(film, Film):
        raise TypeError(f"film must be a Film, got {type(film).__name__}")
    token = f"<object>:{film.key}:{next(_TOKENS)}"
    _FILMS[token] = film
    return token


class FilmSampler:
    """The film's exact R and T at a renderer's samples (numpy; no Mitsuba type).

    Parameters
    ----------
    film : Film
        An exact-model film with a transparent incident medium.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``film``) naming the film and why the plugin cannot render it.
    """

    def __init__(self, film: Film) -> None:
        material_tables.check_film(film)
        if film.model != "exact":
            raise ParameterError(
                "film",
                f" {film.key}: model {film.model!r} is a normalised colour, not a physical"
                ' reflectance; the Mitsuba plugin needs model = "exact"',
            )
        self.film = film
        self.free = material_tables.free_standing(film)
        lo, hi = WAVELENGTH_RANGE
        grid = np.arange(lo, hi + _INDEX_STEP / 2, _INDEX_STEP)
        self._grid = grid
        self._indices = [self._held(m, grid) for m in film.stack]
        layers = len(film.stack) - 2
        self._reverse = self.free and not self._symmetric()
        # no medium absorbs: T = 1 - R (half the recursion's work)
        self._lossless = all(np.all(np.imag(n) == 0) for n in self._indices)
        self._back = (film.thickness_nm[::-1], layers - 1 - film.vary)

    @staticmethod
    def _held(material: Any, grid: np.ndarray) -> np.ndarray | complex:
        """Return the index on ``grid`` (edge values outside the data), or one constant."""
        a, b = material.coverage
        n = material.index(np.clip(grid, a, b))
        return complex(n[0]) if np.all(n == n[0]) else n

    def _symmetric(self) -> bool:
        n = [np.broadcast_to(x, self._grid.shape) for x in self._indices]
        same = all(np.array_equal(p, q) for p, q in zip(n, n[::-1], strict=True))
        return same and self.film.thickness_nm == self.film.thickness_nm[::-1]

    def indices(self, wavelengths: np.ndarray) -> np.ndarray:
        """Return the stack's complex indices at ``wavelengths`` (nm).

        Parameters
        ----------
        wavelengths : numpy.ndarray
            Any shape.

        Returns
        -------
        numpy.ndarray
            Shape ``(media,) + wavelengths.shape``.
        """
        wl = np.asarray(wavelengths, dtype=np.float64)
        out = np.empty((len(self._indices),) + wl.shape, dtype=np.complex128)
        for i, n in enumerate(self._indices):
            if isinstance(n, complex):
                out[i] = n
            else:
                out[i] = np.interp(wl, self._grid, n.real) + 1j * np.interp(wl, self._grid, n.imag)
        return out

    def spectra(
        self,
        wavelengths: np.ndarray,
        cos_theta: np.ndarray,
        thickness_nm: np.ndarray,
    ) -> tuple[np.ndarray, np.ndarray]:
        """Return R and T (T = 0 unless free-standing) at each sample.

        Parameters
        ----------
        wavelengths : numpy.ndarray
            nm, shape ``(4, N)`` or ``(4,)`` (Mitsuba's four wavelengths per sample).
        cos_theta : numpy.ndarray
            cos of the angle of incidence, shape ``(N,)`` or a scalar; negative: from
            the back (the stack reversed).
        thickness_nm : numpy.ndarray
            The varying layer's thickness, nm, broadcasting like ``cos_theta``.

        Returns
        -------
        R, T : numpy.ndarray
            The shape of ``wavelengths``.
        """
        wl = np.asarray(wavelengths, dtype=np.float64)
        c = np.asarray(cos_theta, dtype=np.float64)
        d = np.maximum(np.asarray(thickness_nm, dtype=np.float64), 0.0)
        n = self.indices(wl)
        film = self.film
        R, T = exact.stack_pointwise(
            n,
            film.thickness_nm,
            film.vary,
            d,
            wl,
            np.abs(c),
            transmit=self.free and not self._lossless,
        )
        if self.free and self._lossless:
            T = 1.0 - R
        if self._reverse and np.any(c < 0):
            thick, vary = self._back
            Rb, Tb = exact.stack_pointwise(n[::-1], thick, vary, d, wl, np.abs(c))
            Tb = 1.0 - Rb if self._lossless else Tb
            R = np.where(c < 0, Rb, R)
            T = np.where(c < 0, Tb, T) if T is not None and Tb is not None else None
        return R, (np.zeros_like(R) if T is None else T)


def _load(filename: str, key: str) -> Film:
    """Return film ``key`` of the film file ``filename`` (a one-line error naming ``film``)."""
    films = read_films(filename)
    if key not in films:
        known = ", ".join(sorted(films))
        raise ParameterError("film", f" {key!r} is not in {filename}: it has {known}")
    return films[key]


def _film_from(props: Any) -> Film:
    """Return the Film the properties name (``filename`` + ``film``, or a token)."""
    if not props.has_property("film"):
        raise ParameterError("film", " is missing: give filename and film (a key) or a token")
    key = props["film"]
    if not isinstance(key, str):
        raise TypeError(f"film must be a string, got {type(key).__name__}")
    if key in _FILMS:
        return _FILMS[key]
    if not props.has_property("filename"):
        raise ParameterError("filename", f" is missing: the film file holding film {key!r}")
    return _load(str(props["filename"]), key)


def _check_options(thickness: object, thickness_scale: object, roughness: object) -> None:
    """Refuse a constant thickness < 0, an unknown scale, a rough film (one line each)."""
    if isinstance(thickness, bool) or (
        isinstance(thickness, (int, float)) and not (np.isfinite(thickness) and thickness >= 0)
    ):
        raise ParameterError("thickness", f" must be a finite thickness >= 0 (um), got {thickness}")
    if thickness_scale not in ("um", "range"):
        raise ParameterError(
            "thickness_scale", f' must be "um" or "range", got {thickness_scale!r}'
        )
    if isinstance(roughness, bool) or not isinstance(roughness, (int, float)) or roughness != 0:
        raise ParameterError(
            "roughness", f" must be 0 (the plugin's film is smooth), got {roughness!r}"
        )


def _thickness(props: Any, film: Film) -> tuple[float | Any, float, float]:
    """Return (constant µm or texture, scale, offset): thickness_nm = value * scale + offset."""
    lo, hi = film.range_um
    unit = props["thickness_scale"] if props.has_property("thickness_scale") else "um"
    value = props["thickness"] if props.has_property("thickness") else 0.5 * (lo + hi)
    roughness = props["roughness"] if props.has_property("roughness") else 0.0
    _check_options(value, unit, roughness)
    if isinstance(value, (int, float)):
        return float(value), 1000.0, 0.0
    if not isinstance(value, mi.Texture):
        raise TypeError(f"thickness must be a number (um) or a texture, got {type(value).__name__}")
    if unit == "um":
        return value, 1000.0, 0.0
    return value, (hi - lo) * 1000.0, lo * 1000.0


def bsdf(
    film: Film | str | PathLike,
    key: str | None = None,
    *,
    thickness: float | dict | None = None,
    thickness_scale: str = "um",
    roughness: float = 0.0,
) -> dict:
    """Return the plugin's scene dict for a film, checked here (one-line errors).

    Mitsuba wraps an error raised while it loads a plugin into a multi-line
    ``RuntimeError``; this checks the same things first and raises them as they are.

    Parameters
    ----------
    film : Film or str or os.PathLike
        A :class:`~ocio_thinfilm.physics.films.Film`, or a film file (then ``key``).
    key : str, optional
        The film's key in the film file.
    thickness : float or dict, optional
        The varying layer's thickness in µm, or a Mitsuba texture's dict (see
        ``thickness_scale``); default: the middle of the film's ``range_um``.
    thickness_scale : {"um", "range"}, optional
        A texture's value in µm, or in [0, 1] over the film's ``range_um``.
    roughness : float, optional
        0 only (a smooth film).

    Returns
    -------
    dict
        ``{"type": "thinfilm", ...}`` for ``mi.load_dict``.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``film``, ``key``, ``thickness``, ``thickness_scale``, ``roughness``) naming
        the parameter and what it allows.
    """
    if isinstance(film, Film):
        FilmSampler(film)
        out: dict[str, Any] = {"type": PLUGIN, "film": film_token(film)}
    elif isinstance(film, (str, PathLike)):
        if not isinstance(key, str):
            raise ParameterError("key", f" must name a film of {film}, got {key!r}")
        FilmSampler(_load(str(film), key))
        out = {"type": PLUGIN, "filename": str(film), "film": key}
    else:
        raise TypeError(f"film must be a Film or a film file, got {type(film).__name__}")
    _check_options(0.0 if thickness is None else thickness, thickness_scale, roughness)
    if thickness is not None and not isinstance(thickness, (int, float, dict)):
        raise TypeError(f"thickness must be a number (um) or a texture's dict, got {thickness!r}")
    if thickness is not None:
        out["thickness"] = float(thickness) if isinstance(thickness, (int, float)) else thickness
    if thickness_scale != "um":
        out["thickness_scale"] = thickness_scale
    return out


def _lobes(free: bool, varying: bool) -> tuple[list, Any]:
    """Return the components' flags and their union (``varying``: a textured thickness)."""
    sides = mi.BSDFFlags.FrontSide | (mi.BSDFFlags.BackSide if free else mi.BSDFFlags(0))
    reflection = mi.BSDFFlags.DeltaReflection | sides
    flags = [reflection]
    if free:
        flags.append(mi.BSDFFlags.DeltaTransmission | sides)
    extra = mi.BSDFFlags(0)
    if varying:
        extra = mi.BSDFFlags.SpatiallyVarying
    components = [f | extra for f in flags]
    union = mi.BSDFFlags(0)
    for f in components:
        union = union | f
    return components, union


def _choose(
    R: np.ndarray, T: np.ndarray, c: np.ndarray, has_r: Any, has_t: Any, free: bool, sample1: Any
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Return (reflect, ok, pdf, weight): each sample's lobe, validity, pdf and weight.

    The lobe is chosen by the sample's mean reflectance against its transmittance.
    """
    r, t = R.mean(axis=0), T.mean(axis=0)
    if has_r and has_t:
        p_r = np.divide(r, r + t, out=np.ones_like(r), where=r + t > 0)
        p_r = np.clip(p_r, MIN_REFLECTION_PROBABILITY, 1.0)
    else:
        p_r = np.full_like(r, 1.0 if has_r else 0.0)
    reflect = np.asarray(sample1, dtype=np.float64) < p_r
    ok = (c != 0) & (has_r | has_t) & (free | (c > 0))
    pdf = np.where(reflect, p_r, 1.0 - p_r)
    weight = np.where(reflect, R, T) / np.where(pdf > 0, pdf, 1.0)
    ok = ok & (pdf > 0)
    return reflect, ok, pdf, weight


def _bsdf_class() -> type:
    """Return the plugin's class for the variant that is set (it subclasses its ``mi.BSDF``)."""

    class ThinFilmBSDF(mi.BSDF):
        """The ``thinfilm`` plugin (see the module docstring)."""

        def __init__(self, props: Any) -> None:
            super().__init__(props)
            if not mi.is_spectral:
                raise ParameterError(
                    "variant", f" {mi.variant()} is not spectral: the film needs wavelengths"
                )
            self.sampler = FilmSampler(_film_from(props))
            self.thickness, self.scale, self.offset = _thickness(props, self.sampler.film)
            self.m_components, self.m_flags = _lobes(
                self.sampler.free, isinstance(self.thickness, mi.Texture)
            )

        def _thickness_nm(self, si: Any, active: Any) -> np.ndarray:
            if isinstance(self.thickness, float):
                return np.asarray(self.thickness * 1000.0)
            value = np.asarray(self.thickness.eval_1(si, active), dtype=np.float64)
            return value * self.scale + self.offset

        def sample(self, ctx: Any, si: Any, sample1: Any, sample2: Any, active: Any = True) -> Any:
            cos_i = mi.Frame3f.cos_theta(si.wi)
            c = np.asarray(cos_i, dtype=np.float64)
            R, T = self.sampler.spectra(
                np.asarray(si.wavelengths), c, self._thickness_nm(si, active)
            )
            has_r = ctx.is_enabled(mi.BSDFFlags.DeltaReflection, 0)
            has_t = self.sampler.free and ctx.is_enabled(mi.BSDFFlags.DeltaTransmission, 1)
            reflect, ok, pdf, weight = _choose(R, T, c, has_r, has_t, self.sampler.free, sample1)
            sel = mi.Mask(reflect if reflect.ndim else bool(reflect))
            bs = mi.BSDFSample3f()
            bs.wo = dr.select(sel, mi.reflect(si.wi), -si.wi)
            bs.eta = 1.0
            bs.pdf = mi.Float(np.where(ok, pdf, 0.0) if pdf.ndim else float(ok * pdf))
            bs.sampled_component = dr.select(sel, mi.UInt32(0), mi.UInt32(1))
            bs.sampled_type = dr.select(
                sel,
                mi.UInt32(int(mi.BSDFFlags.DeltaReflection)),
                mi.UInt32(int(mi.BSDFFlags.DeltaTransmission)),
            )
            w = np.where(ok, weight, 0.0)
            return bs, mi.Spectrum(w) if w.ndim > 1 else mi.Spectrum(*w)

        def eval(self, ctx: Any, si: Any, wo: Any, active: Any = True) -> Any:
            return mi.Spectrum(0.0)

        def pdf(self, ctx: Any, si: Any, wo: Any, active: Any = True) -> Any:
            return mi.Float(0.0)

        def eval_pdf(self, ctx: Any, si: Any, wo: Any, active: Any = True) -> Any:
            return mi.Spectrum(0.0), mi.Float(0.0)

        def traverse(self, callback: Any) -> None:
            pass

        def to_string(self) -> str:
            film = self.sampler.film
            return f"ThinFilmBSDF[film={film.key!r}, {film.describe()}]"

    return ThinFilmBSDF


def register() -> None:
    """Register the ``thinfilm`` BSDF for the Mitsuba variant that is set.

    Call it after ``mi.set_variant(...)`` (again after switching variants).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``variant``) when no variant is set or it is not spectral.
    """
    variant = mi.variant()
    if variant is None or "spectral" not in variant:
        raise ParameterError(
            "variant",
            f" must be a spectral Mitsuba variant set first (mi.set_variant), got {variant}",
        )
    cls = _bsdf_class()
    mi.register_bsdf(PLUGIN, lambda props: cls(props))


@contextmanager
def evaluated_mode() -> Iterator[None]:
    """Render JIT variants in Dr.Jit's evaluated mode (what the plugin's numpy needs).

    Mitsuba's JIT variants record loops and virtual calls symbolically; the plugin's
    physics is numpy, which needs each wavefront's values. Inside this context the
    bounce loop and the BSDF calls run evaluated, wavefront by wavefront.

    Yields
    ------
    None
    """
    flags = (dr.JitFlag.SymbolicLoops, dr.JitFlag.SymbolicCalls)
    before = [dr.flag(f) for f in flags]
    try:
        for f in flags:
            dr.set_flag(f, False)
        yield
    finally:
        for f, b in zip(flags, before, strict=True):
            dr.set_flag(f, b)
