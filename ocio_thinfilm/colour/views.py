"""The views' maps in closed form, one entry per view kind of the registry.

:data:`ANALYTIC_MAPS` maps each kind of :data:`ocio_thinfilm.registry.VIEW_KINDS` to its
map in double precision (:class:`AnalyticMap`), or to ``None`` where the package has no
closed form (``"aces"``: OCIO's ACES 1.3 gamut compression, applied by OCIO; ``"raw"``:
no view transform). The export's fitted tables take their target from here, the
evaluation its truth.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry, compress

__all__ = ["AnalyticMap", "ANALYTIC_MAPS", "analytic_map"]

#: ``f(values, display, threshold, limit)``: the map of an SDR display's gamut.
MapFunction = Callable[[npt.ArrayLike, registry.DisplayLike, float, float], np.ndarray]


@dataclass(frozen=True)
class AnalyticMap:
    """A view's map in closed form, on display-linear RGB and on CIE-XYZ-D65.

    Parameters
    ----------
    rgb : callable
        ``rgb(RGB, display, threshold, limit)``: display-linear RGB of the SDR
        ``display`` -> its mapped RGB (the knobs are the compression's; the other maps
        ignore them).
    xyz : callable
        ``xyz(XYZ, display, threshold, limit)``: the same map on CIE-XYZ-D65.
    """

    rgb: MapFunction
    xyz: MapFunction


def _clamp_rgb(RGB, display, threshold, limit):
    return np.clip(np.asarray(RGB, dtype=np.float64), 0.0, 1.0)


def _clamp_xyz(XYZ, display, threshold, limit):
    gamut = registry.as_display(display, hdr=False).colorimetry
    return colorimetry.RGB_to_XYZ(_clamp_rgb(colorimetry.XYZ_to_RGB(XYZ, gamut), 0, 0, 0), gamut)


#: View kind -> its closed form, or ``None`` where there is none.
ANALYTIC_MAPS: dict[str, AnalyticMap | None] = {
    "clip": AnalyticMap(
        rgb=lambda RGB, display, threshold, limit: clip.clip_RGB(RGB, display),
        xyz=lambda XYZ, display, threshold, limit: clip.clip_XYZ(XYZ, display),
    ),
    "compress": AnalyticMap(rgb=compress.compress_RGB, xyz=compress.compress_XYZ),
    "clamp": AnalyticMap(rgb=_clamp_rgb, xyz=_clamp_xyz),
    "aces": None,
    "raw": None,
}


def analytic_map(view: str | registry.View) -> AnalyticMap | None:
    """Return the closed form of ``view`` (a view of the registry or its name), if any.

    Parameters
    ----------
    view : str or View
        A view of :data:`ocio_thinfilm.registry.VIEWS`.

    Returns
    -------
    AnalyticMap or None

    Examples
    --------
    >>> analytic_map("Channel Clamp").rgb([[1.2, 0.5, -0.1]], "sRGB", 0.8, 1.3).tolist()
    [[1.0, 0.5, 0.0]]
    >>> analytic_map("ACES Gamut Compression") is None
    True
    """
    return ANALYTIC_MAPS[registry.as_view(view).kind]
