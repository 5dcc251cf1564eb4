"""Fitted 3D tables of the display LUTs: node values by lattice regression.

A display LUT's 3D table sampled at its nodes blends, in every cell that straddles the
gamut boundary, clipped values into colours that need no mapping. Here the nodes are
instead fitted (:func:`ocio_thinfilm.lut.lattice_fit.fit_lattice`, Garcia & Gupta
2009) to the view on colours the file will see (in-gamut colours, object colours,
mixtures of spectral lines), those inside the display's gamut weighted
:data:`INSIDE_WEIGHT` times the others, for tetrahedral and trilinear interpolation at
once. The training set and the target: docs/gamut_map.md, *Design notes*. The samples
come from a fixed seed and the fit sums in a fixed order, so a bake is byte-identical
across runs.

- :func:`fit_view_table` -- the fitted table of a view for a grid over a colour space
  of a config, shape (size, size, size, 3), indexed [r, g, b];
- :func:`training_colours` -- the colours the fit is trained on.
"""

from __future__ import annotations

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry, compress, encodings, log_curves
from ocio_thinfilm.colour.views import analytic_map
from ocio_thinfilm.lut import lattice_fit, ocio_ops

__all__ = [
    "INSIDE_WEIGHT",
    "OBJECT_WEIGHT",
    "SHAPER_OBJECT_WEIGHT",
    "SPREAD_WEIGHT",
    "SAMPLES",
    "fit_view_table",
    "training_colours",
]

#: Weight of the training colours inside the display's gamut (the others weigh 1):
#: the point chosen on the weight curve of ``benchmarks/bench_view_fit.py``.
INSIDE_WEIGHT = 10.0
#: Weight of the object colours outside the gamut: over a grid uniform in the input's
#: code values (the plain ACEScct .cube) 1; over a shaper 3, which lowers the object
#: colours' worst error there (docs/gamut_map.md, *Design notes*).
OBJECT_WEIGHT = 1.0
SHAPER_OBJECT_WEIGHT = 3.0
#: Weight of the spectral-line mixtures (far outside most gamuts).
SPREAD_WEIGHT = 0.3
#: Training colours per family: inside the gamut, object colours, line mixtures.
SAMPLES = (200_000, 200_000, 150_000)
#: Regularisers of :func:`ocio_thinfilm.lut.lattice_fit.fit_lattice`.
PRIOR_WEIGHT = 1e-3
SMOOTHNESS = 0.3
#: Relative residual at which the conjugate gradient stops (tighter changes no code
#: value of the 65^3 ACEScct -> sRGB table by more than its ΔE2000 statistics show).
TOLERANCE = 1e-3
SEED = 20090604
#: Stored values: a node whose fitted correction is below ``SNAP[0]`` keeps the view's
#: value, and values within ``SNAP[1]`` of 0 or 1 are stored as 0 or 1 (far below one
#: 8-bit code; a 65^3 sRGB .cube of 6-decimal values trims to 3.6 MB instead of 7.4).
SNAP = (1e-4, 2e-5)


def training_colours(
    display: registry.DisplayLike, samples: tuple[int, int, int] = SAMPLES, seed: int = SEED
) -> tuple[np.ndarray, np.ndarray]:
    """Return the training colours, CIE-XYZ-D65, and each one's family.

    The families: 0 inside the gamut of ``display``, 1 object colours, 2 spectral-line
    mixtures. None of them is one of the evaluation sets (a separate generator and seed).
    """
    entry = registry.as_display(display)
    gamut = entry.gamut.name if isinstance(entry, registry.HDRDisplay) else entry.name
    scale = float(getattr(entry, "scale", 1.0))
    n_in, n_obj, n_mix = samples
    rng = np.random.default_rng(seed)
    # inside the gamut: uniform in (roughly) display code values
    inside = colorimetry.RGB_to_XYZ(rng.uniform(0.0, 1.0, (n_in, 3)) ** 2.4, gamut) * scale
    # object colours: 1-3 rectangular bands on a base, many bright
    wl = np.arange(360.0, 781.0, 5.0)
    R = np.zeros((n_obj, wl.size))
    for share in (1.0, 0.6, 0.3):
        start = rng.uniform(360.0, 780.0, n_obj)[:, None]
        width = rng.uniform(5.0, 250.0, n_obj)[:, None]
        height = rng.uniform(-1.0, 1.0, n_obj) * (rng.uniform(size=n_obj) < share)
        R += height[:, None] * ((wl >= start) & (wl < start + width))
    R = np.clip(R + rng.uniform(0.0, 1.0, n_obj)[:, None], 0.0, 1.0)
    R *= rng.uniform(0.0, 1.0, n_obj)[:, None] ** 0.3
    objects = colorimetry.reflectance_to_XYZ(R, wl)
    # mixtures of up to three spectral lines at random luminance
    locus = colorimetry.spectral_locus_XYZ(1.0, np.arange(380.0, 701.0, 2.0))
    mix = rng.dirichlet(np.full(3, 0.5), n_mix)
    picked = locus[rng.integers(0, len(locus), (n_mix, 3))]
    lines = mix[:, 0, None] * picked[:, 0] + mix[:, 1, None] * picked[:, 1]
    lines = lines + mix[:, 2, None] * picked[:, 2]
    lines = lines / lines[:, 1:2] * rng.uniform(0.0, 1.0, n_mix)[:, None] ** 0.5
    XYZ = np.concatenate([inside, objects, lines])
    family = np.repeat([0, 1, 2], [n_in, n_obj, n_mix])
    return XYZ, family


def _apply(cfg, src, dst, values):
    """Convert ``values`` from colour space ``src`` to ``dst``.

    ``dst`` is a colour space, or a (display, view) pair; the conversion is by the config's CPU
    processor, float32.
    """
    import PyOpenColorIO as ocio

    if isinstance(dst, tuple):
        proc = cfg.getProcessor(src, dst[0], dst[1], ocio.TRANSFORM_DIR_FORWARD)
    else:
        proc = cfg.getProcessor(src, dst)
    px = np.ascontiguousarray(values, dtype=np.float32).reshape(-1, 3).copy()
    proc.getDefaultCPUProcessor().applyRGB(px)
    return px.astype(np.float64)


def _to_XYZ(cfg, start, values):
    """Convert ``values`` of the colour space ``start`` to CIE-XYZ-D65.

    In float64 for the registry's encoded spaces (their log curve, then their gamut's
    matrix): what the fit is trained on then does not depend on OCIO's float32 CPU path,
    whose SIMD kernels differ between CPUs (:mod:`ocio_thinfilm.reproducible`). Any
    other space (the shaper space of :func:`ocio_thinfilm.export.view.view_config`) by
    the config's CPU processor.
    """
    encoded = registry.find_encoded(start)
    if encoded is None:
        return _apply(cfg, start, "CIE-XYZ-D65", values)
    linear = log_curves.decode(encoded.curve, values)
    return colorimetry.RGB_to_XYZ(linear, encoded.gamut.name)


def _from_XYZ(cfg, start, XYZ):
    """Convert CIE-XYZ-D65 to the colour space ``start``: the inverse of :func:`_to_XYZ`."""
    encoded = registry.find_encoded(start)
    if encoded is None:
        return _apply(cfg, "CIE-XYZ-D65", start, XYZ)
    linear = colorimetry.XYZ_to_RGB(XYZ, encoded.gamut.name)
    return log_curves.encode(encoded.curve, linear)


def _view_codes(cfg, start, display, view, coords, XYZ, knobs):
    """Return the display code values of ``view`` for colours ``XYZ``.

    Analytic where the view has a closed form (:data:`ocio_thinfilm.colour.views.
    ANALYTIC_MAPS`, with the compression's ``knobs``), or else those of OCIO's view
    applied to ``coords`` in the ``start`` space.
    """
    form = analytic_map(view)
    if display in registry.DISPLAYS and form is not None:
        rgb = form.rgb(colorimetry.XYZ_to_RGB(XYZ, display), display, *knobs)
        # the display's encoding in float64 (colour.encodings), not OCIO's float32 CPU path
        return encodings.encode(rgb, registry.as_display(display, hdr=False).encoding)
    return _apply(cfg, start, (display, view), coords)


def _inside(display, XYZ):
    entry = registry.as_display(display)
    if isinstance(entry, registry.HDRDisplay):
        return clip.in_gamut(colorimetry.XYZ_to_RGB(XYZ / entry.scale, entry.gamut.name))
    return clip.in_gamut(colorimetry.XYZ_to_RGB(XYZ, entry.name))


def fit_view_table(
    cfg: ocio_ops.Config,
    start: str,
    display: str,
    view: str,
    size: int,
    inside_weight: float = INSIDE_WEIGHT,
    object_weight: float = OBJECT_WEIGHT,
    knobs: tuple[float, float] = (compress.THRESHOLD, compress.LIMIT),
) -> np.ndarray:
    """Fit the 3D table of ``display`` / ``view`` over a ``size``^3 grid.

    The grid is of the colour space ``start`` of ``cfg`` (a source space whose code values are
    the grid, or the shaper space of :func:`ocio_thinfilm.export.view.view_config`). The table
    has shape (size, size, size, 3), indexed [r, g, b]: display code values, possibly outside
    [0, 1]. The config must have ``CIE-XYZ-D65``. ``inside_weight``, ``object_weight``: the
    weights of the training colours inside the gamut and of the object colours outside it.
    ``knobs``: the compression's (threshold, limit), for its view's analytic target (the
    config ``cfg`` must have been made with the same).
    """
    g = np.linspace(0.0, 1.0, size)
    grid = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1).reshape(-1, 3)
    prior = _view_codes(cfg, start, display, view, grid, _to_XYZ(cfg, start, grid), knobs)
    XYZ, family = training_colours(display)
    coords = np.clip(_from_XYZ(cfg, start, XYZ), 0.0, 1.0)
    values = _view_codes(cfg, start, display, view, coords, XYZ, knobs)
    weights = np.where(
        _inside(display, XYZ),
        inside_weight,
        np.where(family == 2, SPREAD_WEIGHT, object_weight),
    )
    prior = _snapped(prior.reshape(size, size, size, 3))
    nodes = lattice_fit.fit_lattice(
        coords,
        values,
        weights,
        prior,
        prior_weight=PRIOR_WEIGHT,
        smoothness=SMOOTHNESS,
        tolerance=TOLERANCE,
    )
    return _snapped(np.where(np.abs(nodes - prior) < SNAP[0], prior, nodes))


def _snapped(values):
    """``values`` with those within ``SNAP[1]`` of 0 or 1 made 0 or 1."""
    values = np.where(np.abs(values - 1.0) < SNAP[1], 1.0, values)
    return np.where(np.abs(values) < SNAP[1], 0.0, values)
