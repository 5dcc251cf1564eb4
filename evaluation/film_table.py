"""Independent truth for the renderer materials: a single-layer film's reflectance R by
thickness and view angle, from colour-science alone, and a table EXR in the layout of the
package's ``export material`` (docs: the film-as-material table), for the host tests.

- :func:`film_rgb` -- linear RGB of R(thickness, cos θ): colour-science's exact
  transfer matrices (:func:`colour.phenomena.thin_film_tmm`, s and p averaged), the CIE
  1931 2° observer, illuminant D65, a colour-science RGB colourspace, white balanced so
  that the perfect reflector is RGB (1, 1, 1);
- :func:`write_table` -- that RGB as a float32 EXR table: thickness along x over
  ``range_um``, cos θ along y (the first scanline cos θ near 1), texel-centre sampled.

Nothing of ``ocio_thinfilm`` is used: the tests hold the hosts' renders to this.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import colour
import numpy as np
from colour.phenomena import thin_film_tmm

__all__ = ["WAVELENGTHS", "film_rgb", "table_axes", "write_table"]

#: The integration grid (nm): 360-780 nm by 5 nm.
WAVELENGTHS = np.arange(360.0, 781.0, 5.0)


def _weights(space: str) -> np.ndarray:
    """(wavelengths, 3): spectral R to linear RGB of ``space``, white-balanced."""
    shape = colour.SpectralShape(WAVELENGTHS[0], WAVELENGTHS[-1], 5)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    illuminant = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    xyz = cmfs.values * illuminant.values[:, None]
    xyz /= xyz[:, 1].sum()
    rgb = colour.RGB_COLOURSPACES[space].matrix_XYZ_to_RGB
    weights = xyz @ rgb.T
    return weights / weights.sum(axis=0)  # the perfect reflector: RGB (1, 1, 1)


def film_rgb(
    n: Sequence[float], thickness_um: np.ndarray, cos_theta: np.ndarray, space: str = "sRGB"
) -> np.ndarray:
    """Linear RGB of the unpolarised reflectance of a single-layer film.

    Parameters
    ----------
    n : sequence of float
        Constant refractive indices (incident medium, film, substrate).
    thickness_um : numpy.ndarray
        Film thicknesses (µm), 1-D.
    cos_theta : numpy.ndarray
        Cosines of the incidence angle in the incident medium, 1-D.
    space : str, optional
        A colour-science RGB colourspace name.

    Returns
    -------
    numpy.ndarray
        (len(cos_theta), len(thickness_um), 3) linear RGB.
    """
    theta = np.degrees(np.arccos(np.clip(np.asarray(cos_theta, float), 0.0, 1.0)))
    theta = np.minimum(theta, 89.99)  # cos θ = 0 exactly: grazing, R = 1
    R, _ = thin_film_tmm(
        list(n), np.atleast_1d(thickness_um) * 1000.0, WAVELENGTHS, np.atleast_1d(theta)
    )
    spectral = R.mean(axis=-1)  # (wavelengths, angles, thicknesses): s and p averaged
    return np.einsum("wat,wc->atc", spectral, _weights(space))


def table_axes(range_um: tuple[float, float], width: int, height: int):
    """The texel centres: (thicknesses (W,), cos θ by texture row (H,), row 0 = cos θ
    near 0)."""
    lo, hi = range_um
    t = lo + (np.arange(width) + 0.5) * (hi - lo) / width
    return t, (np.arange(height) + 0.5) / height


def write_table(
    path: Path,
    n: Sequence[float],
    range_um: tuple[float, float],
    width: int,
    height: int,
    space: str = "sRGB",
) -> np.ndarray:
    """Write the film's R table as a float32 RGB EXR (the first scanline cos θ near 1);
    return it in texture row order ((H, W, 3), row 0 = cos θ near 0)."""
    import OpenImageIO as oiio

    t, c = table_axes(range_um, width, height)
    table = film_rgb(n, t, c, space)
    spec = oiio.ImageSpec(width, height, 3, oiio.FLOAT)
    spec.attribute("ocio_thinfilm:x", "thickness_um")
    spec.attribute("ocio_thinfilm:y", "cos_theta")
    out = oiio.ImageOutput.create(str(path))
    assert out is not None and out.open(str(path), spec), oiio.geterror()
    out.write_image(np.ascontiguousarray(table[::-1], np.float32))
    out.close()
    return table
