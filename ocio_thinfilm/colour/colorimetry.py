"""Colorimetry: reflectance spectra -> CIE XYZ -> linear RGB (paper Section 2.1).

Stage 2 of the pipeline. Matching functions, illuminants and RGB colourspaces all
come from colour-science's datasets; nothing here is a typed-in matrix.

Conventions
-----------
- XYZ is relative: the perfect reflector (R == 1) under the chosen illuminant has
  Y = 1 (CIE 1931 2 degree observer and D65 by default).
- RGB matrices map that D65-relative XYZ to linear RGB with RGB = (1, 1, 1) at the
  colourspace's white; spaces whose white is not D65 (ACES) get a Bradford
  adaptation from D65.

Public functions
----------------
- :func:`spectral_weights` -- (W, 3) integration weights for a wavelength grid
- :func:`reflectance_to_XYZ` -- weights applied to a spectrum array
- :func:`film_XYZ` -- XYZ of the paper's single-film models (band-limited by default)
- :func:`morpho_XYZ` -- XYZ of the Morpho multilayer (Eq. 9 + 14) against angle
- :func:`matrix_XYZ_to_RGB`, :func:`XYZ_to_RGB`, :func:`RGB_to_XYZ`
- :func:`white_XYZ`, :func:`delta_E2000`, :func:`spectral_locus_XYZ`, :func:`cmfs_at`

Importing colour-science takes about 3 s, longer than rendering a scene. The few
arrays taken from its datasets (weights, matrices, CMF samples) are therefore
memoised on disk (:func:`persistent`), keyed by the arguments, the code that makes
them and colour-science's version: only the first process imports colour.
"""

from __future__ import annotations

import hashlib
import inspect
import os
from functools import wraps
from importlib import metadata
from pathlib import Path

import numpy as np

from ocio_thinfilm import cache
from ocio_thinfilm.physics import spectra

__all__ = [
    "DEFAULT_OBSERVER",
    "DEFAULT_ILLUMINANT",
    "RGB_SPACES",
    "spectral_weights",
    "reflectance_to_XYZ",
    "film_XYZ",
    "morpho_XYZ",
    "matrix_XYZ_to_RGB",
    "XYZ_to_RGB",
    "RGB_to_XYZ",
    "white_XYZ",
    "delta_E2000",
    "spectral_locus_XYZ",
    "cmfs_at",
]

DEFAULT_OBSERVER = "CIE 1931 2 Degree Standard Observer"
DEFAULT_ILLUMINANT = "D65"

#: Our names for RGB spaces -> colour-science colourspace names.
RGB_SPACES = {
    "sRGB": "sRGB",
    "Rec.709": "ITU-R BT.709",
    "Display P3": "Display P3",
    "Rec.2020": "ITU-R BT.2020",
    "ACEScg": "ACEScg",
    "ACES2065-1": "ACES2065-1",
}

FILM_KINDS = ("phase-change", "no-phase-change")


def _cache_dir() -> Path | None:
    """``$OCIO_THINFILM_CACHE`` (empty or ``0`` disables), else the user cache dir."""
    setting = os.environ.get("OCIO_THINFILM_CACHE")
    if setting is not None:
        return None if setting in ("", "0") else Path(setting)
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "ocio-thinfilm"


def persistent(function=None, *, modules=()):
    """Memoise a pure function of colour-science's datasets in memory and on disk.

    The key covers the arguments, the function's source, the full source of any
    ``modules`` it depends on (names, read at the first call) and colour-science's
    version, so changed code or a changed library never returns a stale array. A
    cache that cannot be read or written is ignored. Use as ``@persistent`` or
    ``@persistent(modules=("ocio_thinfilm.lut.tables",))``.
    """
    if function is None:
        return lambda f: persistent(f, modules=modules)
    source = inspect.getsource(function)

    @cache.memoize(maxsize=64)
    @wraps(function)
    def wrapper(*args):
        directory = _cache_dir()
        path = None
        if directory is not None:
            import importlib

            code = [source] + [inspect.getsource(importlib.import_module(m)) for m in modules]
            key = repr((args, code, metadata.version("colour-science")))
            digest = hashlib.sha256(key.encode()).hexdigest()[:32]
            path = directory / f"{function.__name__}-{digest}.npy"
            try:
                return np.load(path)
            except (OSError, ValueError):
                pass
        value = np.asarray(function(*args))
        if path is not None:
            from ocio_thinfilm.io import atomic_file

            try:
                with atomic_file(path) as tmp:
                    np.save(tmp, value)
            except OSError:
                pass
        return value

    return wrapper


@persistent
def _weights_cached(wl_key: tuple, observer: str, illuminant: str) -> np.ndarray:
    import colour

    wl = np.asarray(wl_key)
    try:
        cmfs = colour.MSDS_CMFS[observer]
    except KeyError:
        raise ValueError(f"observer must be one of colour.MSDS_CMFS, got {observer!r}") from None
    try:
        sd = colour.SDS_ILLUMINANTS[illuminant]
    except KeyError:
        raise ValueError(
            f"illuminant must be one of colour.SDS_ILLUMINANTS, got {illuminant!r}") from None
    # colour-science interpolates (Sprague for the 1 nm CMFs / 5 nm D65) and holds the
    # end values constant outside the tabulated range.
    # (a single wavelength still needs a shape with end > start)
    shape = colour.SpectralShape(wl.min(), max(wl.max(), wl.min() + 1.0), 1)
    cmf = np.asarray(cmfs.copy().extrapolate(shape)[wl]).reshape(-1, 3)
    s = np.asarray(sd.copy().extrapolate(shape)[wl]).reshape(-1)
    lower, upper = spectra.bin_edges(wl)
    # bin widths: the trapezoid rule; one sample is a point evaluation (width 1)
    width = (upper - lower) if wl.size > 1 else np.ones(1)
    w = cmf * (s * width)[:, None]
    total = w[:, 1].sum()
    if not total > 0:
        raise ValueError(f"wavelengths: the luminance weight (y-bar times the illuminant) "
                         f"is 0 over {wl.min():g}-{wl.max():g} nm; use wavelengths within "
                         "the visible range")
    return w / total


def spectral_weights(wavelengths, observer: str = DEFAULT_OBSERVER,
                     illuminant: str = DEFAULT_ILLUMINANT) -> np.ndarray:
    """Integration weights ``W`` (shape (len(wavelengths), 3)) so that
    ``XYZ = R @ W`` and the perfect reflector has Y = 1.

    ``W[i] = cmf(l_i) S(l_i) (upper_i - lower_i) / sum(ybar S dl)`` with the bins
    of :func:`ocio_thinfilm.physics.spectra.bin_edges`: the trapezoid rule on the grid; for a
    band-limited (hat-averaged) spectrum, the exact integral of ``R`` against the
    linearly interpolated weights.
    """
    wl = spectra.check_wavelengths(wavelengths)
    return _weights_cached(tuple(wl.tolist()), observer, illuminant).copy()


def reflectance_to_XYZ(reflectance, wavelengths, observer: str = DEFAULT_OBSERVER,
                       illuminant: str = DEFAULT_ILLUMINANT) -> np.ndarray:
    """Relative XYZ of reflectance spectra.

    Parameters
    ----------
    reflectance : array_like
        R(lambda), last axis along ``wavelengths``.
    wavelengths : array_like
        Sample wavelengths in nm.
    observer, illuminant : str, optional
        colour-science names (default CIE 1931 2 degree, D65).

    Returns
    -------
    numpy.ndarray
        XYZ with the perfect reflector at Y = 1.

    Examples
    --------
    The perfect reflector is the D65 white (0.9505, 1, 1.0890):

    >>> wl = np.arange(360.0, 781.0, 5.0)
    >>> reflectance_to_XYZ(np.ones(wl.size), wl).round(4).tolist()
    [0.9505, 1.0, 1.089]
    """
    return np.asarray(reflectance) @ spectral_weights(wavelengths, observer, illuminant)


def _chunked_XYZ(model, values, wavelengths, observer, illuminant, chunk=4096):
    """Apply ``model(values_chunk) -> spectra`` and integrate, chunk by chunk (memory)."""
    values = np.asarray(values, dtype=np.float64)
    flat = values.reshape(-1)
    w = spectral_weights(wavelengths, observer, illuminant)
    out = np.empty((flat.size, 3))
    for start in range(0, flat.size, chunk):
        out[start:start + chunk] = model(flat[start:start + chunk]) @ w
    return out.reshape(values.shape + (3,))


def film_XYZ(optical_thickness_nm, kind: str = "phase-change", *, step: float = 5.0,
             band_limited: bool = True, wavelengths=None, observer: str = DEFAULT_OBSERVER,
             illuminant: str = DEFAULT_ILLUMINANT) -> np.ndarray:
    """CIE XYZ of the paper's single film (Eq. 7 or 8) against its optical thickness.

    Parameters
    ----------
    optical_thickness_nm : array_like
        t' = n t cos(theta_t) in nm, >= 0.
    kind : {"phase-change", "no-phase-change"}
        Eq. 7 (soap film, oil on water) or Eq. 8 (film on a denser base).
    step : float, optional
        Spectral sampling in nm over 360-780 nm (unless ``wavelengths`` is given).
    band_limited : bool, optional
        Integrate each bin exactly (see :mod:`.spectra`); thick films then tend to
        their incoherent average instead of aliasing into false colours.
    wavelengths : array_like, optional
        Explicit sample wavelengths (nm).
    observer, illuminant : str, optional
        colour-science names (default CIE 1931 2 degree, D65).

    Returns
    -------
    numpy.ndarray
        XYZ (perfect reflector Y = 1), shape ``t'.shape + (3,)``.

    References
    ----------
    Smits & Meyer (1990), Eq. 5-8 and Section 3.1.

    Examples
    --------
    No film is black (Eq. 7); a very thick film is the incoherent average, half the
    D65 white (0.4752, 0.5, 0.5445):

    >>> film_XYZ(0.0).tolist()
    [0.0, 0.0, 0.0]
    >>> film_XYZ(1e5).round(3).tolist()
    [0.475, 0.5, 0.544]
    """
    if kind not in FILM_KINDS:
        raise ValueError(f"kind must be one of {FILM_KINDS}, got {kind!r}")
    wl = spectra.wavelength_grid(step=step) if wavelengths is None else wavelengths

    def model(t):
        return spectra.two_beam_reflectance(t, wl, phase_change=kind == "phase-change",
                                            band_limited=band_limited)

    return _chunked_XYZ(model, optical_thickness_nm, wl, observer, illuminant)


def morpho_XYZ(theta_degrees, *, layers: int = spectra.MORPHO["layers"], d1=spectra.MORPHO["d1"],
               d2=spectra.MORPHO["d2"], n=spectra.MORPHO["n"], step: float = 5.0,
               band_limited: bool = True, wavelengths=None, observer: str = DEFAULT_OBSERVER,
               illuminant: str = DEFAULT_ILLUMINANT) -> np.ndarray:
    """CIE XYZ of the Morpho wing multilayer against the viewing angle.

    Eq. 9 (Anderson & Richards, :func:`.spectra.multilayer_reflectance`) with the
    effective layer thickness of Eq. 14 (:func:`.spectra.morpho_layer_thickness`).

    Parameters
    ----------
    theta_degrees : array_like
        Viewing angle in degrees, [0, 90].
    layers, d1, d2, n : optional
        The paper's scale geometry (12 layers, 150 nm, 50 nm, 1.53).
    step, band_limited, wavelengths, observer, illuminant : optional
        As in :func:`film_XYZ`.

    Returns
    -------
    numpy.ndarray
        XYZ (perfect reflector Y = 1), shape ``theta.shape + (3,)``.

    References
    ----------
    Smits & Meyer (1990), Eq. 9 and 14.

    Examples
    --------
    At normal incidence the reflection peaks at 2 t = 453 nm: a blue (Z > X > Y).

    >>> X, Y, Z = morpho_XYZ(0.0)
    >>> bool(Z > X > Y)
    True
    """
    wl = spectra.wavelength_grid(step=step) if wavelengths is None else wavelengths

    def model(theta):
        t = spectra.morpho_layer_thickness(theta, d1, d2, n)
        return spectra.multilayer_reflectance(t, wl, layers, band_limited=band_limited)

    return _chunked_XYZ(model, theta_degrees, wl, observer, illuminant)


@persistent
def _matrix_cached(space: str) -> np.ndarray:
    import colour

    if space == "CIE-XYZ-D65":
        return np.eye(3)
    if space not in RGB_SPACES:
        raise ValueError(f"space must be one of {sorted(RGB_SPACES)}, got {space!r}")
    cs = colour.RGB_COLOURSPACES[RGB_SPACES[space]]
    # Normalised primary matrix from the primaries and white: RGB = 1 is the white.
    rgb_to_xyz = colour.normalised_primary_matrix(cs.primaries, cs.whitepoint)
    d65 = colour.CCS_ILLUMINANTS[DEFAULT_OBSERVER]["D65"]
    if not np.allclose(cs.whitepoint, d65, atol=1e-4):
        cat = colour.adaptation.matrix_chromatic_adaptation_VonKries(
            colour.xy_to_XYZ(d65), colour.xy_to_XYZ(cs.whitepoint), transform="Bradford")
        return np.linalg.inv(rgb_to_xyz) @ cat
    return np.linalg.inv(rgb_to_xyz)


def matrix_XYZ_to_RGB(space: str = "sRGB") -> np.ndarray:
    """3x3 matrix from D65-relative XYZ to the linear RGB of ``space``."""
    return _matrix_cached(space).copy()


def XYZ_to_RGB(XYZ, space: str = "sRGB") -> np.ndarray:
    """Linear RGB of ``space`` from D65-relative XYZ (last axis 3)."""
    return np.asarray(XYZ) @ _matrix_cached(space).T


def RGB_to_XYZ(RGB, space: str = "sRGB") -> np.ndarray:
    """D65-relative XYZ from linear RGB of ``space`` (last axis 3)."""
    return np.asarray(RGB) @ np.linalg.inv(_matrix_cached(space)).T


def white_XYZ(space: str = "sRGB") -> np.ndarray:
    """XYZ of the colourspace's white, RGB = (1, 1, 1)."""
    return RGB_to_XYZ(np.ones(3), space)


def delta_E2000(XYZ_a, XYZ_b) -> np.ndarray:
    """CIE Delta E 2000 between two D65-relative XYZ arrays (via CIELAB, D65 white)."""
    import colour

    d65 = colour.CCS_ILLUMINANTS[DEFAULT_OBSERVER]["D65"]
    lab_a = colour.XYZ_to_Lab(np.asarray(XYZ_a, dtype=np.float64), d65)
    lab_b = colour.XYZ_to_Lab(np.asarray(XYZ_b, dtype=np.float64), d65)
    return colour.delta_E(lab_a, lab_b, method="CIE 2000")


@persistent
def _cmfs_cached(wl_key: tuple, observer: str) -> np.ndarray:
    import colour

    try:
        cmfs = colour.MSDS_CMFS[observer]
    except KeyError:
        raise ValueError(f"observer must be one of colour.MSDS_CMFS, got {observer!r}") from None
    return np.asarray(cmfs[np.asarray(wl_key)])


def cmfs_at(wavelengths, observer: str = DEFAULT_OBSERVER) -> np.ndarray:
    """Colour matching functions (x-bar, y-bar, z-bar) at ``wavelengths`` (nm),
    interpolated by colour-science; shape (len(wavelengths), 3)."""
    wl = spectra.check_wavelengths(wavelengths)
    return _cmfs_cached(tuple(wl.tolist()), observer).copy()


def spectral_locus_XYZ(Y: float = 1.0, wavelengths=None) -> np.ndarray:
    """Monochromatic colours scaled to luminance ``Y``, from the CIE 1931 CMFs
    (the spectrum of the paper's Figure 4). Default 380-700 nm every 1 nm."""
    try:
        Y = float(Y)
    except (TypeError, ValueError):
        raise ValueError(f"Y must be a finite number >= 0, got {Y!r}") from None
    if not (np.isfinite(Y) and Y >= 0):
        raise ValueError(f"Y must be a finite number >= 0, got {Y!r}")
    xyz = cmfs_at(np.arange(380.0, 701.0) if wavelengths is None else wavelengths)
    if np.any(xyz[:, 1] <= 0):
        bad = np.asarray(np.arange(380.0, 701.0) if wavelengths is None
                         else wavelengths, dtype=float)[xyz[:, 1] <= 0][0]
        raise ValueError(f"wavelengths: y-bar is 0 at {bad:g} nm, which has no luminance "
                         "to scale to Y")
    return xyz * (Y / xyz[:, 1:2])
