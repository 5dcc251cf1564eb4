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
- :func:`spectral_weights`, :func:`reflectance_to_XYZ` -- (W, 3) integration weights for
  a wavelength grid, and applied to a spectrum array
- :func:`film_XYZ` -- XYZ of the paper's single-film models (band-limited by default)
- :func:`morpho_XYZ` -- XYZ of the Morpho multilayer (Eq. 9 + 14) against angle
- :func:`matrix_XYZ_to_RGB`, :func:`XYZ_to_RGB`, :func:`RGB_to_XYZ`, :func:`white_XYZ`,
  :func:`delta_E2000`, :func:`spectral_locus_XYZ`, :func:`cmfs_at`

colour-science is slow to import, so the arrays taken from its datasets are memoised on
disk (:func:`persistent`, keyed by the code): only the first process imports colour.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import cache, registry, reproducible
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.physics import sampling, spectra

__all__ = [
    "DEFAULT_OBSERVER",
    "DEFAULT_ILLUMINANT",
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

FILM_KINDS = ("phase-change", "no-phase-change")


@cache.persistent
def _weights_cached(wl_key: tuple, observer: str, illuminant: str) -> np.ndarray:
    import colour

    wl = np.asarray(wl_key)
    try:
        cmfs = colour.MSDS_CMFS[observer]
    except KeyError:
        raise ParameterError(
            "observer", f" must be one of colour.MSDS_CMFS, got {observer!r}"
        ) from None
    try:
        sd = colour.SDS_ILLUMINANTS[illuminant]
    except KeyError:
        raise ParameterError(
            "illuminant", f" must be one of colour.SDS_ILLUMINANTS, got {illuminant!r}"
        ) from None
    # colour-science interpolates (Sprague for the 1 nm CMFs / 5 nm D65) and holds the
    # end values constant outside the tabulated range.
    # (a single wavelength still needs a shape with end > start)
    shape = colour.SpectralShape(wl.min(), max(wl.max(), wl.min() + 1.0), 1)
    # colour-science interpolates with BLAS: its samples rounded to 32 significant bits
    # are the same on every CPU (ocio_thinfilm.reproducible)
    cmf = reproducible.canonical(np.asarray(cmfs.copy().extrapolate(shape)[wl]).reshape(-1, 3))
    s = reproducible.canonical(np.asarray(sd.copy().extrapolate(shape)[wl]).reshape(-1))
    lower, upper = sampling.bin_edges(wl)
    # bin widths: the trapezoid rule; one sample is a point evaluation (width 1)
    width = (upper - lower) if wl.size > 1 else np.ones(1)
    w = cmf * (s * width)[:, None]
    total = w[:, 1].sum()
    if not total > 0:
        raise ValueError(
            f"wavelengths: the luminance weight (y-bar times the illuminant) "
            f"is 0 over {wl.min():g}-{wl.max():g} nm; use wavelengths within "
            "the visible range"
        )
    return w / total


def spectral_weights(
    wavelengths: npt.ArrayLike,
    observer: str = DEFAULT_OBSERVER,
    illuminant: str = DEFAULT_ILLUMINANT,
) -> np.ndarray:
    """Integration weights ``W`` so that ``XYZ = R @ W`` and the perfect reflector has Y = 1.

    ``W`` has shape (len(wavelengths), 3).

    ``W[i] = cmf(l_i) S(l_i) (upper_i - lower_i) / sum(ybar S dl)`` with the bins
    of :func:`ocio_thinfilm.physics.sampling.bin_edges`: the trapezoid rule on the grid; for a
    band-limited (hat-averaged) spectrum, the exact integral of ``R`` against the
    linearly interpolated weights.

    This is the discrete form of the tristimulus integrals
    ``X = k sum R(l) S(l) xbar(l) dl`` (and Y, Z alike) with ``k = 1 / sum S ybar dl``
    (CIE 15:2004, Section 7), the conversion of Smits & Meyer (1990), Section 2.1.

    Parameters
    ----------
    wavelengths : array_like
        Sample wavelengths in nm, 1-D, finite and strictly increasing (checked by
        :func:`ocio_thinfilm.physics.sampling.check_wavelengths`). Matching functions and
        illuminant are interpolated by colour-science and held constant outside their
        tabulated range. A single wavelength is a point evaluation (bin width 1 nm).
    observer : str, optional
        A key of ``colour.MSDS_CMFS`` (default CIE 1931 2 degree standard observer).
    illuminant : str, optional
        A key of ``colour.SDS_ILLUMINANTS`` (default D65).

    Returns
    -------
    numpy.ndarray
        float64, shape ``(len(wavelengths), 3)``, columns (X, Y, Z); the Y column sums
        to 1. A new array on every call.

    Raises
    ------
    ValueError
        For an unknown observer or illuminant, or a grid on which ``ybar S`` is 0
        (no luminance to normalise by).

    References
    ----------
    CIE 15:2004 Colorimetry, 3rd ed., Section 7.
    Smits, B. E., & Meyer, G. W. (1990). Newton's Colors: Simulating Interference
    Phenomena in Realistic Image Synthesis. Section 2.1.

    Examples
    --------
    The perfect reflector has Y = 1 by construction, and its XYZ, the column sums, is
    the D65 white of CIE 15:2004, (0.95047, 1, 1.08883), to the grid's accuracy:

    >>> W = spectral_weights(np.arange(360.0, 781.0, 5.0))
    >>> W.shape
    (85, 3)
    >>> round(float(W[:, 1].sum()), 12)
    1.0
    >>> W.sum(axis=0).round(2).tolist()
    [0.95, 1.0, 1.09]
    """
    wl = sampling.check_wavelengths(wavelengths)
    return _weights_cached(tuple(wl.tolist()), observer, illuminant).copy()


def reflectance_to_XYZ(
    reflectance: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    observer: str = DEFAULT_OBSERVER,
    illuminant: str = DEFAULT_ILLUMINANT,
) -> np.ndarray:
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
    return reproducible.matmul(reflectance, spectral_weights(wavelengths, observer, illuminant))


def _chunked_XYZ(model, values, wavelengths, observer, illuminant, chunk=4096):
    """Apply ``model(values_chunk) -> spectra`` and integrate, chunk by chunk (memory)."""
    values = np.asarray(values, dtype=np.float64)
    flat = values.reshape(-1)
    w = spectral_weights(wavelengths, observer, illuminant)
    out = np.empty((flat.size, 3))
    for start in range(0, flat.size, chunk):
        out[start : start + chunk] = reproducible.matmul(model(flat[start : start + chunk]), w)
    return out.reshape(values.shape + (3,))


def film_XYZ(
    optical_thickness_nm: npt.ArrayLike,
    kind: str = "phase-change",
    *,
    step: float = 5.0,
    band_limited: bool = True,
    wavelengths: npt.ArrayLike | None = None,
    observer: str = DEFAULT_OBSERVER,
    illuminant: str = DEFAULT_ILLUMINANT,
) -> np.ndarray:
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
        raise ParameterError("kind", f" must be one of {FILM_KINDS}, got {kind!r}")
    wl = sampling.wavelength_grid(step=step) if wavelengths is None else wavelengths

    def model(t):
        return spectra.two_beam_reflectance(
            t, wl, phase_change=kind == "phase-change", band_limited=band_limited
        )

    return _chunked_XYZ(model, optical_thickness_nm, wl, observer, illuminant)


def morpho_XYZ(
    theta_degrees: npt.ArrayLike,
    *,
    layers: int = spectra.MORPHO["layers"],
    d1: npt.ArrayLike = spectra.MORPHO["d1"],
    d2: npt.ArrayLike = spectra.MORPHO["d2"],
    n: npt.ArrayLike = spectra.MORPHO["n"],
    step: float = 5.0,
    band_limited: bool = True,
    wavelengths: npt.ArrayLike | None = None,
    observer: str = DEFAULT_OBSERVER,
    illuminant: str = DEFAULT_ILLUMINANT,
) -> np.ndarray:
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
    wl = sampling.wavelength_grid(step=step) if wavelengths is None else wavelengths

    def model(theta):
        t = spectra.morpho_layer_thickness(theta, d1, d2, n)
        return spectra.multilayer_reflectance(t, wl, layers, band_limited=band_limited)

    return _chunked_XYZ(model, theta_degrees, wl, observer, illuminant)


def _xy_to_XYZ(xy: np.ndarray) -> np.ndarray:
    """XYZ with Y = 1 of chromaticities ``xy`` (..., 2)."""
    x, y = xy[..., 0], xy[..., 1]
    return np.stack([x / y, np.ones_like(x), (1.0 - x - y) / y], axis=-1)


def _normalised_primary_matrix(primaries: np.ndarray, whitepoint: np.ndarray) -> np.ndarray:
    """Return RGB -> XYZ of primaries (3, 2) and a white (2,) (SMPTE RP 177).

    ``colour.normalised_primary_matrix`` computes it with LAPACK and BLAS, whose
    kernels differ between CPUs in the last bits (:mod:`ocio_thinfilm.reproducible`);
    here with the same formula in elementwise arithmetic (``tests/test_colorimetry.py``
    holds it to colour-science's within 1e-14).
    """
    xy = np.asarray(primaries, dtype=np.float64).reshape(3, 2)
    P = np.stack([xy[:, 0], xy[:, 1], 1.0 - xy[:, 0] - xy[:, 1]])  # columns: R, G, B
    S = reproducible.matmul(reproducible.inv3(P), _xy_to_XYZ(np.asarray(whitepoint, float)))
    return P * S


def _bradford(source_xy: np.ndarray, target_xy: np.ndarray) -> np.ndarray:
    """Return the von Kries adaptation in Bradford's cone space from one white to another.

    ``colour.adaptation.matrix_chromatic_adaptation_VonKries(..., transform="Bradford")``
    by :func:`ocio_thinfilm.colour.adaptation.von_kries_matrix` (the same bits on every
    CPU), with colour-science's Bradford matrix.
    """
    import colour

    from ocio_thinfilm.colour.adaptation import von_kries_matrix

    return von_kries_matrix(
        _xy_to_XYZ(source_xy), _xy_to_XYZ(target_xy), colour.adaptation.CAT_BRADFORD
    )


@cache.persistent
def _matrix_cached(space: str) -> np.ndarray:
    import colour

    if registry.space_kind(space) == "reference":  # the reference XYZ: no matrix
        return np.eye(3)
    gamut = registry.colorimetry_of(space)
    if gamut is None:
        raise ParameterError(
            "space",
            f" must be one of {sorted(registry.RGB_COLORIMETRY)} or a display, got {space!r}",
        )
    cs = colour.RGB_COLOURSPACES[registry.RGB_COLORIMETRY[gamut]]
    # Normalised primary matrix from the primaries and white: RGB = 1 is the white.
    rgb_to_xyz = _normalised_primary_matrix(cs.primaries, cs.whitepoint)
    d65 = np.asarray(colour.CCS_ILLUMINANTS[DEFAULT_OBSERVER]["D65"], dtype=np.float64)
    if not np.allclose(cs.whitepoint, d65, atol=1e-4):
        cat = _bradford(d65, np.asarray(cs.whitepoint, dtype=np.float64))
        return reproducible.matmul(reproducible.inv3(rgb_to_xyz), cat)
    return reproducible.inv3(rgb_to_xyz)


def matrix_XYZ_to_RGB(space: str = "sRGB") -> np.ndarray:
    """3x3 matrix from D65-relative XYZ to the linear RGB of ``space``.

    The inverse of the normalised primary matrix of the space's primaries and white
    (so RGB = (1, 1, 1) is the space's white, SMPTE RP 177), preceded by a Bradford
    chromatic adaptation from D65 to the space's white for spaces whose white is not
    D65 (ACEScg, ACES2065-1). The RGB of the monitor in Smits & Meyer (1990),
    Section 2.1.

    Parameters
    ----------
    space : str, optional
        A key of :data:`.registry.RGB_COLORIMETRY` (default ``"sRGB"``), or
        ``"CIE-XYZ-D65"`` for the identity.

    Returns
    -------
    numpy.ndarray
        float64, shape (3, 3): ``RGB = M @ XYZ`` for column vectors, XYZ with the D65
        perfect reflector at Y = 1. A new array on every call.

    Raises
    ------
    ValueError
        For an unknown ``space``.

    References
    ----------
    IEC 61966-2-1:1999 (sRGB); SMPTE RP 177-1993 (normalised primary matrix).

    Examples
    --------
    The D65 white (0.95047, 1, 1.08883) is RGB = 1, and the matrix agrees with the
    one printed in IEC 61966-2-1 (first row 3.2406, -1.5372, -0.4986; derived there
    from a slightly different white) to about 5e-4:

    >>> M = matrix_XYZ_to_RGB("sRGB")
    >>> (M @ [0.95047, 1.0, 1.08883]).round(3).tolist()
    [1.0, 1.0, 1.0]
    >>> M[0].round(1).tolist()
    [3.2, -1.5, -0.5]
    """
    return _matrix_cached(space).copy()


def XYZ_to_RGB(XYZ: npt.ArrayLike, space: str = "sRGB") -> np.ndarray:
    """Linear RGB of ``space`` from D65-relative XYZ (last axis 3).

    Parameters
    ----------
    XYZ : array_like
        CIE XYZ (D65 perfect reflector at Y = 1), last axis 3, any leading shape.
    space : str, optional
        A key of :data:`.registry.RGB_COLORIMETRY` (default ``"sRGB"``) or
        ``"CIE-XYZ-D65"``.

    Returns
    -------
    numpy.ndarray
        Linear RGB, float64, shape of ``XYZ``. Out-of-gamut colours give channels
        below 0 or above 1 (not clipped; see :mod:`ocio_thinfilm.colour.clip`).

    See Also
    --------
    matrix_XYZ_to_RGB, RGB_to_XYZ

    References
    ----------
    Smits & Meyer (1990), Section 2.1 (XYZ to the monitor's RGB).

    Examples
    --------
    The D65 white is RGB = 1 in every space (the ACES spaces through their Bradford
    adaptation):

    >>> XYZ_to_RGB([0.95047, 1.0, 1.08883]).round(3).tolist()
    [1.0, 1.0, 1.0]
    >>> XYZ_to_RGB([0.95047, 1.0, 1.08883], "ACEScg").round(3).tolist()
    [1.0, 1.0, 1.0]
    """
    return reproducible.matmul(XYZ, _matrix_cached(space).T)


def RGB_to_XYZ(RGB: npt.ArrayLike, space: str = "sRGB") -> np.ndarray:
    """D65-relative XYZ from linear RGB of ``space`` (last axis 3).

    Parameters
    ----------
    RGB : array_like
        Linear RGB of ``space``, last axis 3, any leading shape.
    space : str, optional
        A key of :data:`.registry.RGB_COLORIMETRY` (default ``"sRGB"``) or
        ``"CIE-XYZ-D65"``.

    Returns
    -------
    numpy.ndarray
        CIE XYZ (D65 perfect reflector at Y = 1), float64, shape of ``RGB``.

    See Also
    --------
    matrix_XYZ_to_RGB, XYZ_to_RGB

    Examples
    --------
    The Y of the sRGB primaries are the Rec.709 luminance weights
    Y = 0.2126 R + 0.7152 G + 0.0722 B (ITU-R BT.709-6):

    >>> RGB_to_XYZ(np.eye(3), "sRGB")[:, 1].round(4).tolist()
    [0.2126, 0.7152, 0.0722]
    """
    return reproducible.matmul(RGB, reproducible.inv3(_matrix_cached(space)).T)


def white_XYZ(space: str = "sRGB") -> np.ndarray:
    """XYZ of the colourspace's white, RGB = (1, 1, 1).

    The end of the neutral diagonal of Smits & Meyer (1990), Section 3.2 (the white
    the clip pulls towards is the display's, not x = y = z).

    Parameters
    ----------
    space : str, optional
        A key of :data:`.registry.RGB_COLORIMETRY` (default ``"sRGB"``) or
        ``"CIE-XYZ-D65"``.

    Returns
    -------
    numpy.ndarray
        float64, shape (3,): D65-relative XYZ. For every space this is the D65 white,
        since spaces with another white are adapted from D65.

    Examples
    --------
    The D65 white of CIE 15:2004, (0.95047, 1, 1.08883):

    >>> white_XYZ("sRGB").round(3).tolist()
    [0.95, 1.0, 1.089]
    >>> white_XYZ("ACEScg").round(3).tolist()
    [0.95, 1.0, 1.089]
    """
    return RGB_to_XYZ(np.ones(3), space)


def delta_E2000(XYZ_a: npt.ArrayLike, XYZ_b: npt.ArrayLike) -> np.ndarray:
    """CIE Delta E 2000 between two D65-relative XYZ arrays (via CIELAB, D65 white).

    Both colours go to CIE 1976 L*a*b* with the D65 white (CIE 15:2004, Section 8.2.1)
    and are compared with colour-science's CIEDE2000 (``colour.delta_E(...,
    method="CIE 2000")``, k_L = k_C = k_H = 1).

    Parameters
    ----------
    XYZ_a, XYZ_b : array_like
        CIE XYZ (D65 perfect reflector at Y = 1), last axis 3, broadcasting together.

    Returns
    -------
    numpy.ndarray
        float64, the broadcast shape without the last axis (a NumPy float64 scalar
        for single colours). Symmetric and 0 for identical colours; about 1 is a just
        noticeable difference.

    References
    ----------
    CIE 15:2004 Colorimetry, 3rd ed., Section 8.3.
    Sharma, G., Wu, W., & Dalal, E. N. (2005). The CIEDE2000 color-difference formula:
    Implementation notes, supplementary test data, and mathematical observations.
    Color Research & Application, 30(1), 21-30.

    Examples
    --------
    Identical colours differ by 0; the first test pair of Sharma, Wu & Dalal (2005),
    L*a*b* (50, 2.6772, -79.7751) and (50, 0, -82.7485), differs by 2.0425:

    >>> round(float(delta_E2000([0.2, 0.3, 0.4], [0.2, 0.3, 0.4])), 12)
    0.0
    >>> import colour
    >>> d65 = colour.CCS_ILLUMINANTS[DEFAULT_OBSERVER]["D65"]
    >>> a = colour.Lab_to_XYZ([50.0, 2.6772, -79.7751], d65)
    >>> b = colour.Lab_to_XYZ([50.0, 0.0, -82.7485], d65)
    >>> round(float(delta_E2000(a, b)), 4)
    2.0425
    """
    import colour

    d65 = colour.CCS_ILLUMINANTS[DEFAULT_OBSERVER]["D65"]
    lab_a = colour.XYZ_to_Lab(np.asarray(XYZ_a, dtype=np.float64), d65)
    lab_b = colour.XYZ_to_Lab(np.asarray(XYZ_b, dtype=np.float64), d65)
    return colour.delta_E(lab_a, lab_b, method="CIE 2000")


@cache.persistent
def _cmfs_cached(wl_key: tuple, observer: str) -> np.ndarray:
    import colour

    try:
        cmfs = colour.MSDS_CMFS[observer]
    except KeyError:
        raise ParameterError(
            "observer", f" must be one of colour.MSDS_CMFS, got {observer!r}"
        ) from None
    # colour-science interpolates with BLAS: 32 significant bits are the same on every
    # CPU (ocio_thinfilm.reproducible)
    return reproducible.canonical(np.asarray(cmfs[np.asarray(wl_key)]))


def cmfs_at(wavelengths: npt.ArrayLike, observer: str = DEFAULT_OBSERVER) -> np.ndarray:
    """Colour matching functions (x-bar, y-bar, z-bar) at ``wavelengths`` (nm).

    Interpolated by colour-science; shape (len(wavelengths), 3).

    Parameters
    ----------
    wavelengths : array_like
        Wavelengths in nm, 1-D, finite and strictly increasing (checked by
        :func:`ocio_thinfilm.physics.sampling.check_wavelengths`).
    observer : str, optional
        A key of ``colour.MSDS_CMFS`` (default CIE 1931 2 degree standard observer).

    Returns
    -------
    numpy.ndarray
        float64, shape ``(len(wavelengths), 3)``, columns (x-bar, y-bar, z-bar);
        the tabulated values at tabulated wavelengths. A new array on every call.

    Raises
    ------
    ValueError
        For an unknown ``observer``.

    References
    ----------
    CIE 15:2004 Colorimetry, 3rd ed., tables of the CIE 1931 standard colorimetric
    observer.

    Examples
    --------
    The CIE 1931 table: (0.5121, 1.0000, 0.0057) at 555 nm and (1.0622, 0.6310,
    0.0008) at 600 nm:

    >>> cmfs_at([555.0, 600.0]).round(3).tolist()
    [[0.512, 1.0, 0.006], [1.062, 0.631, 0.001]]
    """
    wl = sampling.check_wavelengths(wavelengths)
    return _cmfs_cached(tuple(wl.tolist()), observer).copy()


def spectral_locus_XYZ(Y: float = 1.0, wavelengths: npt.ArrayLike | None = None) -> np.ndarray:
    """Monochromatic colours scaled to luminance ``Y``, from the CIE 1931 CMFs.

    The spectrum of the paper's Figure 4. Default 380-700 nm every 1 nm.

    The worst case of Smits & Meyer (1990), Section 3.2: "every color in the spectrum
    is monochromatic and as far out of the gamut of the monitor as possible".

    Parameters
    ----------
    Y : float, optional
        Luminance of every colour, finite and >= 0 (D65 perfect reflector at Y = 1).
    wavelengths : array_like, optional
        Wavelengths in nm (1-D, increasing); default ``np.arange(380.0, 701.0)``.
        Each must have y-bar > 0.

    Returns
    -------
    numpy.ndarray
        float64, shape ``(len(wavelengths), 3)``: ``Y * cmf(l) / ybar(l)``, so the Y
        column is ``Y`` everywhere and the chromaticities are those of the spectral
        locus.

    Raises
    ------
    ValueError
        For a ``Y`` that is not a finite number >= 0, or a wavelength where y-bar is 0.

    References
    ----------
    CIE 15:2004 Colorimetry, 3rd ed. (CIE 1931 standard colorimetric observer);
    Smits & Meyer (1990), Section 3.2 and Figure 4.

    Examples
    --------
    321 colours by default; at 555 nm (y-bar = 1) the CMFs times Y; at 520 nm the
    spectral locus chromaticity (x, y) = (0.0743, 0.8338) of the CIE 1931 table:

    >>> spectral_locus_XYZ().shape
    (321, 3)
    >>> spectral_locus_XYZ(0.3, [555.0]).round(3).tolist()
    [[0.154, 0.3, 0.002]]
    >>> X, Y, Z = spectral_locus_XYZ(1.0, [520.0])[0]
    >>> [round(float(X / (X + Y + Z)), 4), round(float(Y / (X + Y + Z)), 4)]
    [0.0743, 0.8338]
    """
    if isinstance(Y, (str, bytes)):  # a string is not parsed
        raise TypeError(f"Y must be a number, got {Y!r}")
    try:
        Y = float(Y)
    except (TypeError, ValueError):
        raise ValueError(f"Y must be a finite number >= 0, got {Y!r}") from None
    if not (np.isfinite(Y) and Y >= 0):
        raise ValueError(f"Y must be a finite number >= 0, got {Y!r}")
    xyz = cmfs_at(np.arange(380.0, 701.0) if wavelengths is None else wavelengths)
    if np.any(xyz[:, 1] <= 0):
        bad = np.asarray(
            np.arange(380.0, 701.0) if wavelengths is None else wavelengths, dtype=float
        )[xyz[:, 1] <= 0][0]
        raise ValueError(
            f"wavelengths: y-bar is 0 at {bad:g} nm, which has no luminance to scale to Y"
        )
    return xyz * (Y / xyz[:, 1:2])
