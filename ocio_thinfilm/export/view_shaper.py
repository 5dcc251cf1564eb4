"""The shaper of ``export view``: a per-channel curve of the input onto [0, 1].

A 3D LUT samples [0, 1]^3: inputs that are not already in [0, 1] go through the shaper
first, a colour space of the config in memory that :func:`view_config` adds.

Per channel of the input's *linear* RGB (ACEScct: ACEScg), a mirrored square root
``e = sign(x) |x|^(1/2)`` mapped affinely from [e(lo), e(hi)] onto [0, 1]. Its domain
[lo, hi] covers every object colour under D65 (the optimal colours: per channel the
sum of the positive, and of the negative, spectral weights), with hi at least 1.5
so that scene values somewhat above white, which every view maps to white, stay
inside; values beyond are clamped. A square root spends the grid on the upper half
of the range, where this config's views bend hardest (every colour converges to the
display white as Y approaches 1); a log or ACEScct allocation spends it on the
shadows and leaves cells near white about 0.27 stops wide. Of the three the square-root
shaper is the most accurate (``tests/test_export_view.py``; the figures:
docs/gamut_map.md, *Design notes*).
"""

from __future__ import annotations

import numpy as np

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.options import MapOptions

__all__ = [
    "DEFAULT_VIEW_SIZE",
    "SHAPER_SIZE",
    "SHAPER_SPACE",
    "linear_sibling",
    "shaper_from_zero",
    "shaper_domain",
    "view_config",
]

#: The default edge of ``export view``'s 3D LUTs (the grid the shaper is for).
DEFAULT_VIEW_SIZE = 65
#: Entries of the shaper (.cube 1D part, .csp prelut knots, companion .spi1d).
SHAPER_SIZE = 4096
SHAPER_GAMMA = 2.0
#: Lower bound of the shaper's upper end (scene-linear; 1.0 is the display white).
SHAPER_MIN_HI = 1.5
SHAPER_SPACE = "ocio-thinfilm export shaper"


def linear_sibling(source: str) -> str | None:
    """Return the config space holding ``source``'s linear RGB (the shaper works there).

    The reference XYZ or a scene-linear space itself, an encoded space's linear one;
    None for the others (thin-film and display spaces).
    """
    if registry.space_kind(source) == "reference":
        return source
    space = registry.linear_space_of(source)
    return None if space is None else space.name


def shaper_from_zero(linear_space: str) -> bool:
    """Return whether the shaper over ``linear_space`` starts at 0 (its ``shaper_from_zero``)."""
    space = registry.linear_space_of(linear_space)
    return space is not None and space.shaper_from_zero


def _colorimetry(linear_space: str) -> str:
    space = registry.linear_space_of(linear_space)
    return registry.REFERENCE if space is None else space.colorimetry


def shaper_domain(
    linear_space: str,
    size: int = DEFAULT_VIEW_SIZE,
    display: registry.DisplayLike | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """Return (lo, hi) of the shaper over ``linear_space``.

    ``linear_space`` is the reference XYZ or a scene-linear space of the registry. The
    range is the same for the three channels so that every grid node on the diagonal
    is a neutral (greys stay grey under tetrahedral interpolation): it covers the
    channel extremes of all object colours under D65 (optimal colours: reflectance
    1 where a channel's spectral weight is positive, 0 elsewhere, and the reverse),
    widened by 10 %, and at least [0, 1.5] (from 0 for a space whose
    ``shaper_from_zero`` is set: AP1, the ACES working gamut -- a mirrored square root
    spends a fifth of the grid on the few object colours outside it, down to -0.09, and
    doubles the worst error without them; values below 0 are clamped to the AP1
    boundary). (Nudging it so that black and white fall on grid nodes was tried and made
    the worst case worse; ``size`` is kept for that reason in the signature. The figures:
    docs/gamut_map.md, *Design notes*.) For an HDR ``display`` the
    upper end is at least 1.5 times its peak (1000 / 203 in units of the reference
    white), so highlights up to the peak are not clamped by the shaper.
    """
    wl = np.arange(360.0, 781.0, 1.0)
    W = colorimetry.spectral_weights(wl)  # XYZ per unit reflectance at each wavelength
    w = reproducible.matmul(W, colorimetry.matrix_XYZ_to_RGB(_colorimetry(linear_space)).T)
    lo = min(0.0, 1.1 * float(np.minimum(w, 0.0).sum(axis=0).min()))
    if shaper_from_zero(linear_space):
        lo = 0.0
    least = SHAPER_MIN_HI * (1.0 if display is None else registry.as_display(display).scale)
    hi = max(least, 1.1 * float(np.maximum(w, 0.0).sum(axis=0).max()))
    return ocio_ops.quantize(lo, 6), ocio_ops.quantize(hi, 6)


def _mirror_root(x):
    return np.sign(x) * np.abs(x) ** (1.0 / SHAPER_GAMMA)


def _shaper_to_linear(lo, hi):
    """OCIO transform: shaper value u in [0, 1] -> linear RGB in [lo, hi]."""
    import PyOpenColorIO as ocio

    e_lo, e_hi = _mirror_root(lo), _mirror_root(hi)
    power = ocio.ExponentTransform([SHAPER_GAMMA] * 3 + [1.0])
    power.setNegativeStyle(ocio.NEGATIVE_MIRROR)
    return ocio_ops.group([ocio_ops.matrix(np.eye(3) * (e_hi - e_lo), [e_lo] * 3), power])


def view_config(
    source: str,
    size: int = DEFAULT_VIEW_SIZE,
    display: registry.DisplayLike | None = None,
    *,
    options: MapOptions | None = None,
) -> tuple[ocio_ops.Config, str | None]:
    """Return the config in memory (LUTs inline, no files) and the shaper space's name.

    The shaper colour space for ``source`` (for a ``size`` grid and ``display``) is
    added when it needs one.

    Parameters
    ----------
    source : str
        The input colour space of the config.
    size : int, optional
        Edge of the 3D LUT the shaper is for (default :data:`DEFAULT_VIEW_SIZE`).
    display : str or registry display, optional
        The display (an HDR display widens the shaper's domain).
    options : MapOptions, optional
        The config's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`); ``None``
        (default) for the defaults.

    Returns
    -------
    config : PyOpenColorIO.Config
        The config, with the shaper space added when ``source`` needs one.
    shaper : str or None
        The shaper space's name, or ``None``.
    """
    import PyOpenColorIO as ocio

    from ocio_thinfilm import config as config_module

    data = config_module.config_data(inline=True, options=options)
    cfg = config_module.generate_config(data, validate=False)
    sibling = linear_sibling(source)
    if sibling is None:
        return cfg, None
    lo, hi = shaper_domain(sibling, size, display)
    to_ref = cfg.getColorSpace(sibling).getTransform(ocio.COLORSPACE_DIR_TO_REFERENCE)
    parts = [_shaper_to_linear(lo, hi)] + ([to_ref] if to_ref is not None else [])
    cs = ocio.ColorSpace()
    cs.setName(SHAPER_SPACE)
    cs.setFamily("Utility")
    cs.setDescription(
        f"Shaper for {source}: per channel of {sibling}, "
        f"sign(x)|x|^(1/2) from {lo:.6g}..{hi:.6g} onto 0..1"
    )
    cs.setTransform(ocio_ops.group(parts), ocio.COLORSPACE_DIR_TO_REFERENCE)
    cfg.addColorSpace(cs)
    return cfg, SHAPER_SPACE
