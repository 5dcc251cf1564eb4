"""Wavelength grids, argument checks and band-limited integration, shared by every model.

- :func:`wavelength_grid`, :func:`check_wavelengths`, :func:`bin_edges` -- the
  wavelength samples (nm) and their trapezoid-rule bins;
- :func:`phase`, :func:`cosine_series` -- the round-trip phase of an optical path and
  the band-limited sum of a cosine series in it;
- :func:`as_angle`, :func:`as_index` -- the physical arguments' checks (built on
  :mod:`ocio_thinfilm.checks`, which words every error message).

Band-limited integration: the interference models are cosine series in a round-trip
phase ``phi(lambda) = 2*pi*P/lambda``; with ``band_limited=True`` each sample is the
exact average of ``R`` under the trapezoid rule's hat function of that sample, taken in
wavenumber: every harmonic ``cos(k*phi)`` becomes ``cos(k*phi_c) * sinc(k*dphi/2)**2``.
The colorimetry stage's trapezoid sum then equals the exact integral of ``R`` against
the linearly interpolated matching-function weights, and thick films tend to their
incoherent average instead of false colours. Why the hat and not a box:
docs/films.md, *Design notes*.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import ParameterError, as_array, short_repr

__all__ = [
    "MAX_SAMPLES",
    "MAX_LAYERS",
    "as_angle",
    "as_index",
    "check_wavelengths",
    "wavelength_grid",
    "bin_edges",
    "phase",
    "cosine_series",
]


# --------------------------------------------------------------------------- #
# The physical arguments (ocio_thinfilm.checks words every message).
# --------------------------------------------------------------------------- #
#: Largest wavelength grid :func:`wavelength_grid` makes, and most Eq. 9 layers.
MAX_SAMPLES = 10_000_000
MAX_LAYERS = 100_000


def as_angle(theta: npt.ArrayLike) -> np.ndarray:
    """Return ``theta`` as an array: an angle of incidence in degrees, in [0, 90]."""
    return as_array("theta", theta, minimum=0.0, maximum=90.0, unit=" degrees")


def as_index(name: str, n: npt.ArrayLike) -> np.ndarray:
    """Return ``n`` as an array: a real refractive index, finite and > 0."""
    return as_array(name, n, minimum=0.0, strict=True)


def check_wavelengths(wavelengths: npt.ArrayLike) -> np.ndarray:
    """Validate a wavelength grid.

    Parameters
    ----------
    wavelengths : array_like
        Wavelengths in nm: 1-D, non-empty, finite, positive, strictly increasing.

    Returns
    -------
    numpy.ndarray
        The wavelengths as float64.

    Raises
    ------
    ValueError
        Naming what is wrong (a TypeError for what is not numbers).

    Examples
    --------
    >>> check_wavelengths([400, 500]).tolist()
    [400.0, 500.0]
    >>> check_wavelengths([500, 400])
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: wavelengths must be strictly increasing
    """
    if np.asarray(wavelengths).dtype.kind not in "biuf":  # a string is not parsed
        raise TypeError(
            f"wavelengths must be a number array of nm values, got {short_repr(wavelengths)}"
        )
    wl = np.asarray(wavelengths, dtype=np.float64)
    if wl.ndim != 1 or wl.size == 0:
        raise ParameterError("wavelengths", " must be a non-empty 1-D array of nm values")
    if not np.all(np.isfinite(wl)) or np.any(wl <= 0):
        raise ParameterError("wavelengths", " must be finite and > 0 nm")
    if wl.size > 1 and np.any(np.diff(wl) <= 0):
        raise ParameterError("wavelengths", " must be strictly increasing")
    return wl


def wavelength_grid(start: float = 360.0, stop: float = 780.0, step: float = 5.0) -> np.ndarray:
    """Uniform wavelength grid, ``start`` and ``stop`` included.

    Parameters
    ----------
    start, stop, step : float
        In nm; ``0 < start < stop``, ``0 < step <= stop - start``.

    Returns
    -------
    numpy.ndarray
        The wavelengths (nm).

    Examples
    --------
    >>> wavelength_grid(400, 700, 100).tolist()
    [400.0, 500.0, 600.0, 700.0]
    """
    for name, value in (("start", start), ("stop", stop), ("step", step)):
        if isinstance(value, (str, bytes)):  # a string is not parsed
            raise TypeError(f"{name} must be a number of nm, got {value!r}")
        try:
            value = float(value)
        except (TypeError, ValueError):
            raise TypeError(f"{name} must be a number of nm, got {value!r}") from None
        if not np.isfinite(value):
            raise ParameterError(name, f" must be finite, got {value}")
    start, stop, step = float(start), float(stop), float(step)
    if not step > 0:
        raise ParameterError("step", f" must be > 0 nm, got {step}")
    if not (0 < start < stop):
        raise ValueError(f"wavelength range must satisfy 0 < start < stop, got {start}..{stop}")
    if step > stop - start:
        raise ParameterError(
            "step", f" must be at most stop - start ({stop - start:g} nm), got {step:g}"
        )
    count = int(round((stop - start) / step)) + 1
    if count > MAX_SAMPLES:
        raise ParameterError("step", f" {step:g} nm gives {count} samples; at most {MAX_SAMPLES}")
    return check_wavelengths(start + step * np.arange(count))


def bin_edges(wavelengths: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper edge of each sample's bin: the midpoints between samples.

    The outer bins are half bins, so a sum over bins is the trapezoid rule. A
    single sample gets a zero-width bin (point evaluation).

    Parameters
    ----------
    wavelengths : array_like
        The samples (nm), see :func:`check_wavelengths`.

    Returns
    -------
    lower, upper : numpy.ndarray
        Bin edges in nm.

    Examples
    --------
    >>> [edges.tolist() for edges in bin_edges([400, 500, 700])]
    [[400.0, 450.0, 600.0], [450.0, 600.0, 700.0]]
    """
    wl = check_wavelengths(wavelengths)
    mid = 0.5 * (wl[1:] + wl[:-1])
    lower = np.concatenate([wl[:1], mid])
    upper = np.concatenate([mid, wl[-1:]])
    return lower, upper


# --------------------------------------------------------------------------- #
# Phase and the band-limited cosine series (shared by every interference model).
# --------------------------------------------------------------------------- #
def phase(
    path: np.ndarray, wl: np.ndarray, band_limited: bool
) -> tuple[np.ndarray, np.ndarray | None]:
    """Round-trip phase 2*pi*P/lambda at the samples and its spread over each bin.

    Returns ``(phi_c, dphi)`` broadcast to ``path.shape + wl.shape``. With
    ``band_limited`` the phase is taken at the bin edges (exact in wavenumber);
    otherwise ``dphi`` is 0 and ``phi_c`` the point phase.
    """
    path = np.asarray(path, dtype=np.float64)[..., None]
    if not band_limited:
        return path * (2.0 * np.pi / wl), None  # one pass over the output
    lower, upper = bin_edges(wl)
    phi_hi = 2.0 * np.pi * path / lower  # phase at the short-wavelength edge
    phi_lo = 2.0 * np.pi * path / upper
    return 0.5 * (phi_hi + phi_lo), phi_hi - phi_lo


def cosine_series(
    coefficients: Sequence[Any], phi_c: np.ndarray, dphi: np.ndarray | None
) -> np.ndarray:
    """Sum ``c_0 + sum_k Re(c_k exp(i k phi))``, each harmonic hat-averaged.

    ``coefficients`` is a list; entry k is a (broadcastable) array of the k-th
    harmonic's coefficient, complex allowed. The average of ``exp(i k phi)``
    under the triangle of half-width ``dphi`` centred on ``phi_c`` (the trapezoid
    rule's hat function: ``dphi`` is the phase step between neighbouring samples) is
    ``exp(i k phi_c) * sinc(k dphi / 2)**2`` (np.sinc is the normalised sinc).
    """
    coefficients = [np.asarray(c)[..., None] for c in coefficients]
    shape = np.broadcast_shapes(np.shape(phi_c), *(c.shape for c in coefficients))
    total = np.zeros(shape)
    for k, c in enumerate(coefficients[1:], start=1):
        arg = phi_c if k == 1 else k * phi_c
        # Built in place in a full-size buffer: the cosine is the only costly pass.
        term = np.empty(shape)
        if np.iscomplexobj(c):
            np.multiply(np.cos(arg), c.real, out=term)
            term -= c.imag * np.sin(arg)
        else:
            np.multiply(np.cos(arg), c, out=term)
        if dphi is not None:
            term *= np.sinc(k * dphi / (2.0 * np.pi)) ** 2
        total += term
    total += np.real(coefficients[0])
    return total
