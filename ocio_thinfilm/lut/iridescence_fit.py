"""The ``KHR_materials_iridescence`` material that looks most like an exact film.

glTF viewers draw one film model (:mod:`ocio_thinfilm.lut.khr_iridescence`: three.js's
Belcour & Barla port); :func:`fit_iridescence` chooses its parameters -- the film's
``iridescenceIor``, ``iridescenceThicknessMinimum`` / ``Maximum`` (the thickness
texture's value ``g`` is the exact film's thickness ``lo + g (hi - lo)`` of its
``range_um``), ``iridescenceFactor`` and the base (``KHR_materials_ior`` for a dielectric
substrate; the base colour at metalness 1 for an absorbing one) -- for the least mean
CIE Delta E 2000 between what the viewer shows on a mirror and the exact film's
reflectance, over thickness x cos theta. For a free-standing film (a transmittance
table) :func:`fit_transmission` adds ``KHR_materials_transmission``: factor 1 and the
base colour that tints the transmitted light most like the film's T.

The search is coarse to fine and deterministic: a grid of film indices and optical
thickness scales around the exact film's own, then a compass search (each parameter
stepped up and down, the steps halved when nothing improves) from the best starts; the
result is rounded (indices to 1e-3, thicknesses to 0.1 nm, factor and colours to 1e-4)
so that last-bit differences between CPUs do not reach the stored parameters.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.lut.khr_iridescence import (
    DEFAULT_IRIDESCENCE,
    KHRIridescence,
    mirror_reflectance,
    mirror_transmittance,
)
from ocio_thinfilm.physics.films import Film

__all__ = [
    "METAL_K",
    "IridescenceTarget",
    "metal_substrate",
    "target_from_table",
    "unfitted",
    "fallback_errors",
    "fit_iridescence",
    "fit_transmission",
    "scene_errors",
]

#: A substrate whose extinction coefficient at 550 nm exceeds this is a metal (the
#: fallback's base is then metalness 1 with a fitted base colour).
METAL_K = 0.1
#: Film indices of the coarse grid.
_COARSE_IOR = (1.2, 1.33, 1.45, 1.6, 1.8, 2.0, 2.3, 2.6)
#: Optical thickness scales of the coarse grid (1: the exact film's n d).
_COARSE_SCALE = (0.85, 0.93, 1.0, 1.07, 1.15)
#: Bounds of the fitted parameters.
_IOR_BOUNDS = (1.0, 3.0)
#: Compass-search halvings of the steps.
_HALVINGS = 7


@dataclass(frozen=True)
class IridescenceTarget:
    """An exact film to fit: its reflectance at points of the thickness texture x cos theta.

    ``g``, ``cos_theta``: 1-D points (``g`` the thickness texture's value, the fraction of
    the film's ``range_um``); ``XYZ``: the exact reflectance there (D65 white at Y = 1),
    shape ``(len(g), 3)``; ``range_nm``: the film's thickness range; ``film_index``: the
    varying layer's real index at 550 nm; ``substrate``: the complex index of the medium
    under it at 550 nm; ``base_rgb``: the exact film's linear Rec.709 reflectance at the
    thinnest thickness at normal incidence (the metal's colour without the film).
    """

    g: np.ndarray
    cos_theta: np.ndarray
    XYZ: np.ndarray
    range_nm: tuple[float, float]
    film_index: float
    substrate: complex
    base_rgb: tuple[float, float, float]
    transmittance: np.ndarray | None = None


def metal_substrate(film: Film) -> bool:
    """Return whether the film's substrate (the last medium of its stack) absorbs like a metal."""
    below = film.stack[-1]
    return bool(abs(complex(below.index(np.array([550.0]))[0]).imag) > METAL_K)


def target_from_table(
    film: Film,
    reflectance: npt.ArrayLike,
    range_um: tuple[float, float],
    columns: int,
    rows: int,
    transmittance: npt.ArrayLike | None = None,
) -> IridescenceTarget:
    """Return a fitting target: ``columns`` x ``rows`` nodes of a material table.

    Parameters
    ----------
    film : Film
        The film the table is of.
    reflectance : array_like
        The table's reflectance, (H, W, 3) linear Rec.709 in texture row order (row 0 at
        cos theta = 0; :func:`ocio_thinfilm.export.material.material_table`), node-centred.
    range_um : tuple of float
        The table's thickness axis.
    columns, rows : int
        Nodes taken along thickness and cos theta (evenly spaced, both ends included).
    transmittance : array_like, optional
        A free-standing film's transmittance table, like ``reflectance``.

    Returns
    -------
    IridescenceTarget
    """
    table = np.asarray(reflectance, dtype=np.float64)
    h, w = table.shape[:2]
    ci = np.unique(np.round(np.linspace(0, w - 1, min(columns, w))).astype(int))
    ri = np.unique(np.round(np.linspace(0, h - 1, min(rows, h))).astype(int))
    rr, cc = np.meshgrid(ri, ci, indexing="ij")
    rgb = table[rr.ravel(), cc.ravel()]
    wl = np.array([550.0])
    lo, hi = range_um
    t_rgb = None
    if transmittance is not None:
        t_rgb = np.asarray(transmittance, dtype=np.float64)[rr.ravel(), cc.ravel()]
    return IridescenceTarget(
        g=cc.ravel() / (w - 1),
        cos_theta=rr.ravel() / (h - 1),
        XYZ=colorimetry.RGB_to_XYZ(rgb, "Rec.709"),
        range_nm=(lo * 1000.0, hi * 1000.0),
        film_index=float(film.varying.index(wl)[0].real),
        substrate=complex(film.stack[-1].index(wl)[0]),
        base_rgb=tuple(float(v) for v in np.clip(table[h - 1, 0], 0.0, 1.0)),  # type: ignore[arg-type]
        transmittance=t_rgb,
    )


def unfitted(target: IridescenceTarget) -> KHRIridescence:
    """Return the extension's defaults on the base a writer sets without fitting.

    ``iridescenceIor`` 1.3, 100-400 nm, factor 1; a dielectric substrate: glTF's default
    ior 1.5, black base colour; a metal: metalness 1 with the exact film's colour at its
    thinnest, head-on, as base colour.
    """
    if abs(target.substrate.imag) > METAL_K:
        return replace(DEFAULT_IRIDESCENCE, metalness=1.0, base_colour=target.base_rgb)
    return DEFAULT_IRIDESCENCE


def _lab(XYZ: np.ndarray) -> np.ndarray:
    import colour

    d65 = colour.CCS_ILLUMINANTS[colorimetry.DEFAULT_OBSERVER]["D65"]
    return colour.XYZ_to_Lab(XYZ, d65)


def _errors(model: KHRIridescence, target: IridescenceTarget, lab: np.ndarray) -> np.ndarray:
    from colour.difference import delta_E_CIE2000

    rgb = mirror_reflectance(model, target.g, target.cos_theta)
    return delta_E_CIE2000(_lab(colorimetry.RGB_to_XYZ(rgb, "Rec.709")), lab)


def fallback_errors(model: KHRIridescence, target: IridescenceTarget) -> np.ndarray:
    """Return Delta E 2000 between the viewer's mirror and the exact film at each point.

    The viewer's mirror is :func:`~ocio_thinfilm.lut.khr_iridescence.mirror_reflectance`.

    The same as :func:`ocio_thinfilm.colour.colorimetry.delta_E2000` of the two XYZ (CIELAB
    with the D65 white, CIEDE2000).
    """
    return _errors(model, target, _lab(target.XYZ))


def _vector(model: KHRIridescence, metal: bool) -> np.ndarray:
    base = list(model.base_colour) if metal else [model.base_ior]
    return np.array([model.ior, *model.thickness_nm, model.factor, *base])


def _model(p: np.ndarray, metal: bool) -> KHRIridescence:
    p = _clamp(p, metal)
    if metal:
        colour = (float(p[4]), float(p[5]), float(p[6]))
        return KHRIridescence(
            float(p[0]), (float(p[1]), float(p[2])), float(p[3]), 1.5, 1.0, colour
        )
    return KHRIridescence(float(p[0]), (float(p[1]), float(p[2])), float(p[3]), float(p[4]))


def _clamp(p: np.ndarray, metal: bool) -> np.ndarray:
    lo = np.array([_IOR_BOUNDS[0], 0.0, 0.0, 0.0] + ([0.0] * 3 if metal else [1.0]))
    hi = np.array([_IOR_BOUNDS[1], 1e5, 1e5, 1.0] + ([1.0] * 3 if metal else [3.0]))
    return np.clip(p, lo, hi)


def _round(p: np.ndarray, metal: bool) -> np.ndarray:
    digits = [3, 1, 1, 4] + ([4] * 3 if metal else [3])
    return np.array([round(float(v), d) for v, d in zip(_clamp(p, metal), digits, strict=True)])


def _compass(
    cost: Callable[[np.ndarray], float], start: np.ndarray, steps: np.ndarray, halvings: int
) -> tuple[np.ndarray, float]:
    best, best_cost = start, cost(start)
    for _ in range(halvings):
        improved = True
        while improved:
            improved = False
            for i in range(best.size):
                for sign in (1.0, -1.0):
                    trial = best.copy()
                    trial[i] += sign * steps[i]
                    c = cost(trial)
                    if c < best_cost:
                        best, best_cost, improved = trial, c, True
        steps = steps / 2.0
    return best, best_cost


def _starts(target: IridescenceTarget, metal: bool) -> list[np.ndarray]:
    lo, hi = target.range_nm
    base = list(target.base_rgb) if metal else [max(1.0, target.substrate.real)]
    starts = []
    for ior in _COARSE_IOR:
        for scale in _COARSE_SCALE:
            k = scale * target.film_index / ior
            starts.append(np.array([ior, lo * k, hi * k, 1.0, *base]))
    return starts


def fit_iridescence(
    target: IridescenceTarget, keep: int = 2, halvings: int = _HALVINGS
) -> KHRIridescence:
    """Return the ``KHR_materials_iridescence`` material closest to an exact film.

    Parameters
    ----------
    target : IridescenceTarget
        The exact film's reflectance (:func:`target_from_table`).
    keep : int, optional
        Coarse-grid starts refined by the compass search (default 2).
    halvings : int, optional
        Times the compass search halves its steps (default 7: steps down to 1/128 of
        the first, 0.0006 in the index and 0.03 % of the thickness range).

    Returns
    -------
    KHRIridescence
        The least mean Delta E 2000 (:func:`fallback_errors`) found, parameters rounded;
        never worse than :func:`unfitted` (also a start).
    """
    metal = abs(target.substrate.imag) > METAL_K
    lab = _lab(target.XYZ)

    def cost(p: np.ndarray) -> float:
        return float(np.mean(_errors(_model(p, metal), target, lab)))

    starts = [_round(s, metal) for s in _starts(target, metal)]
    lo, hi = target.range_nm
    span = max(hi - lo, 10.0)
    steps = np.array([0.08, 0.04 * span, 0.04 * span, 0.1] + ([0.05] * 3 if metal else [0.08]))
    results = [_compass(cost, s, steps, halvings) for s in sorted(starts, key=cost)[:keep]]
    default = _vector(unfitted(target), metal)
    results.append((default, cost(default)))
    best = min(results, key=lambda r: r[1])[0]
    return fit_transmission(_model(_round(best, metal), metal), target)


def fit_transmission(model: KHRIridescence, target: IridescenceTarget) -> KHRIridescence:
    """Return ``model`` transmitting like a free-standing film (unchanged without T).

    three.js (and glTF's ``KHR_materials_transmission``) transmits the background times
    ``transmission (1 - F) base_colour`` (:func:`mirror_transmittance`), ``F`` the base's
    Schlick Fresnel, whatever the iridescence; the transmitted light replaces the diffuse
    lobe. So: ``transmission`` 1 (less would bring back a diffuse lobe of the base colour),
    metalness 0, and the base colour, per channel, the least-squares tint ``c`` of
    ``(1 - F) c`` against the film's T over the target's points (clamped to [0, 1],
    rounded to 1e-4). The reflection is untouched: a dielectric's specular lobe does not
    depend on the base colour.

    Parameters
    ----------
    model : KHRIridescence
        The fitted reflection (:func:`fit_iridescence`), a dielectric base.
    target : IridescenceTarget
        With ``transmittance`` (:func:`target_from_table`).

    Returns
    -------
    KHRIridescence
    """
    if target.transmittance is None or model.metalness > 0.0:
        return model
    clear = replace(model, transmission=1.0, base_colour=(1.0, 1.0, 1.0))
    w = mirror_transmittance(clear, target.cos_theta)
    tint = np.sum(w * target.transmittance, axis=0) / np.maximum(np.sum(w * w, axis=0), 1e-12)
    colour = tuple(round(float(v), 4) for v in np.clip(tint, 0.0, 1.0))
    return replace(clear, base_colour=colour)  # type: ignore[arg-type]


def scene_errors(
    model: KHRIridescence, target: IridescenceTarget, background: npt.ArrayLike
) -> np.ndarray:
    """Return Delta E 2000 of what a viewer shows of a film over a uniform background.

    The viewer's mirror under a uniform white environment of radiance 1 in front of a
    background of linear Rec.709 colour ``background``: ``R + T b``
    (:func:`mirror_reflectance`, :func:`mirror_transmittance`) against the exact film's
    ``R + T b`` (``T`` 0 for a film without ``transmittance``); CIELAB with the D65 white
    at Y = 1.
    """
    b = np.asarray(background, dtype=np.float64)
    shown = mirror_reflectance(model, target.g, target.cos_theta)
    shown = shown + mirror_transmittance(model, target.cos_theta) * b
    exact = colorimetry.RGB_to_XYZ(
        np.zeros(3) if target.transmittance is None else target.transmittance * b, "Rec.709"
    )
    from colour.difference import delta_E_CIE2000

    lab = _lab(target.XYZ + exact)
    return delta_E_CIE2000(_lab(colorimetry.RGB_to_XYZ(shown, "Rec.709")), lab)
