"""Thin-film interference spectra (Smits & Meyer 1990, Section 2).

Stage 1 of the pipeline: spectra -> XYZ -> clip -> tables/LUTs -> config -> render.

Every model returns a reflectance ``R(lambda)`` relative to the illuminant, so a
perfect reflector (``R == 1``) is white. Arrays broadcast: the wavelength grid is
always the *last* axis of the result; thickness, angle and index arrays broadcast
against each other in front of it. Lengths are in nanometres, angles in degrees.

Public functions
----------------
- :func:`wavelength_grid`, :func:`check_wavelengths`
- :func:`optical_thickness` -- Eq. 10 form (refraction angle, default) or literal Eq. 11
- :func:`two_beam_reflectance` -- Eq. 5-8 (phase change / no phase change)
- :func:`morpho_layer_thickness` -- Eq. 14
- :func:`multilayer_reflectance` -- Eq. 9 (Anderson & Richards), peak-normalised
- :func:`airy_reflectance` -- exact single film: Airy sum with s/p Fresnel amplitudes
- :func:`transfer_matrix_reflectance` -- exact multilayer (characteristic matrices)

Band-limited integration
------------------------
The interference models are cosine series in a round-trip phase
``phi(lambda) = 2*pi*P/lambda`` (``P`` the optical path difference). A fixed
wavelength sampling aliases once ``phi`` turns by more than ~pi within one bin
(thick films). With ``band_limited=True`` each sample returns the *exact average*
of ``R`` under the trapezoid rule's hat function of that sample (the triangle from
the previous to the next sample), taken in wavenumber (``phi`` is linear in
``1/lambda``): every harmonic ``cos(k*phi)`` becomes
``cos(k*phi_c) * sinc(k*dphi/2)**2`` (a triangle is a box convolved with itself).
The colorimetry stage's trapezoid sum then equals the exact integral of ``R``
against the linearly interpolated matching-function weights. (A plain box average
over one bin, ``sinc`` instead of ``sinc**2``, leaves a residual oscillation of up
to 22 % that aliases: Delta E2000 1.4 at t' = 33 um with 5 nm sampling, against
0.16 with the hat.) One implementation, :func:`_cosine_series`, serves all three
interference models, so thick films tend to their incoherent average instead of
false colours.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "MORPHO",
    "wavelength_grid",
    "check_wavelengths",
    "optical_thickness",
    "two_beam_reflectance",
    "morpho_layer_thickness",
    "multilayer_reflectance",
    "airy_reflectance",
    "transfer_matrix_reflectance",
    "bin_edges",
]

#: Morpho wing scale geometry from the paper (Section 4.3, Eq. 14): spacing d1 and
#: thickness d2 of the mullions in nm, their index n, and the number of layers l
#: ("twelve horizontal mullions").
MORPHO = {"d1": 150.0, "d2": 50.0, "n": 1.53, "layers": 12}


# --------------------------------------------------------------------------- #
# Validation helpers: one place that words every error message.
# --------------------------------------------------------------------------- #
def _array(name, value, *, minimum=None, maximum=None, strict=False, unit=""):
    a = np.asarray(value)
    if a.dtype.kind == "c":
        check = a.real
    else:
        a = a.astype(np.float64, copy=False)
        check = a
    if check.size and not np.all(np.isfinite(check)):
        raise ValueError(f"{name} must be finite{_range_text(minimum, maximum, strict, unit)}")
    if minimum is not None and check.size:
        bad = check <= minimum if strict else check < minimum
        if np.any(bad):
            raise ValueError(
                f"{name} must be {'>' if strict else '>='} {minimum:g}{unit}"
                f"{'' if maximum is None else f' and <= {maximum:g}{unit}'}, "
                f"got {check[bad].flat[0]:g}"
            )
    if maximum is not None and check.size and np.any(check > maximum):
        raise ValueError(
            f"{name} must be in [{minimum:g}, {maximum:g}]{unit}, got {check[check > maximum].flat[0]:g}"
        )
    return a


def _range_text(minimum, maximum, strict, unit):
    if minimum is None:
        return ""
    if maximum is None:
        return f" and {'>' if strict else '>='} {minimum:g}{unit}"
    return f" and in [{minimum:g}, {maximum:g}]{unit}"


def _angle(theta):
    return _array("theta", theta, minimum=0.0, maximum=90.0, unit=" degrees")


def _index(name, n):
    return _array(name, n, minimum=0.0, strict=True)


def check_wavelengths(wavelengths) -> np.ndarray:
    """Validate a wavelength grid (nm): 1-D, non-empty, positive, strictly increasing."""
    wl = np.asarray(wavelengths, dtype=np.float64)
    if wl.ndim != 1 or wl.size == 0:
        raise ValueError("wavelengths must be a non-empty 1-D array of nm values")
    if not np.all(np.isfinite(wl)) or np.any(wl <= 0):
        raise ValueError("wavelengths must be finite and > 0 nm")
    if wl.size > 1 and np.any(np.diff(wl) <= 0):
        raise ValueError("wavelengths must be strictly increasing")
    return wl


def wavelength_grid(start: float = 360.0, stop: float = 780.0, step: float = 5.0) -> np.ndarray:
    """Uniform wavelength grid in nm, ``start`` and ``stop`` included."""
    if not (np.isfinite(step) and step > 0):
        raise ValueError(f"step must be > 0 nm, got {step}")
    if not (0 < start < stop):
        raise ValueError(f"wavelength range must satisfy 0 < start < stop, got {start}..{stop}")
    count = int(round((stop - start) / step)) + 1
    return check_wavelengths(start + step * np.arange(count))


def bin_edges(wavelengths) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper edge (nm) of each sample's bin: midpoints between samples.

    The outer bins are half bins, so a sum over bins is the trapezoid rule. A
    single sample gets a zero-width bin (point evaluation).
    """
    wl = check_wavelengths(wavelengths)
    mid = 0.5 * (wl[1:] + wl[:-1])
    lower = np.concatenate([wl[:1], mid])
    upper = np.concatenate([mid, wl[-1:]])
    return lower, upper


# --------------------------------------------------------------------------- #
# Phase and the band-limited cosine series (shared by every interference model).
# --------------------------------------------------------------------------- #
def _phase(path, wl, band_limited):
    """Round-trip phase 2*pi*P/lambda at the samples and its spread over each bin.

    Returns ``(phi_c, dphi)`` broadcast to ``path.shape + wl.shape``. With
    ``band_limited`` the phase is taken at the bin edges (exact in wavenumber);
    otherwise ``dphi`` is 0 and ``phi_c`` the point phase.
    """
    path = np.asarray(path, dtype=np.float64)[..., None]
    if not band_limited:
        return 2.0 * np.pi * path / wl, None
    lower, upper = bin_edges(wl)
    phi_hi = 2.0 * np.pi * path / lower  # phase at the short-wavelength edge
    phi_lo = 2.0 * np.pi * path / upper
    return 0.5 * (phi_hi + phi_lo), phi_hi - phi_lo


def _cosine_series(coefficients, phi_c, dphi):
    """Sum ``c_0 + sum_k Re(c_k exp(i k phi))``, each harmonic hat-averaged.

    ``coefficients`` is a list; entry k is a (broadcastable) array of the k-th
    harmonic's coefficient, complex allowed. The average of ``exp(i k phi)``
    under the triangle of half-width ``dphi`` centred on ``phi_c`` (the trapezoid
    rule's hat function: ``dphi`` is the phase step between neighbouring samples) is
    ``exp(i k phi_c) * sinc(k dphi / 2)**2`` (np.sinc is the normalised sinc).
    """
    total = np.real(np.asarray(coefficients[0]))[..., None] + np.zeros_like(phi_c)
    for k, c in enumerate(coefficients[1:], start=1):
        c = np.asarray(c)[..., None]
        if np.iscomplexobj(c):
            term = c.real * np.cos(k * phi_c) - c.imag * np.sin(k * phi_c)
        else:
            term = c * np.cos(k * phi_c)
        if dphi is not None:
            term = term * np.sinc(k * dphi / (2.0 * np.pi)) ** 2
        total = total + term
    return total


# --------------------------------------------------------------------------- #
# The paper's models.
# --------------------------------------------------------------------------- #
def optical_thickness(thickness, n, theta=0.0, *, mode: str = "refraction"):
    """Optical thickness t' of a film (nm).

    ``mode="refraction"`` (default) uses the refraction angle inside the film:
    ``t' = t * n * cos(theta_t) = t * sqrt(n**2 - sin(theta)**2)`` -- the paper's
    own Eq. 10 form, which is the correct optical path for a film seen from air.

    ``mode="literal"`` is the paper's Eq. 11 as printed, ``t' = t * n * cos(theta)``
    with the *viewing* angle. It under-estimates t' away from normal incidence
    (at 60 degrees and n = 1.33 by 38 %), shifting colours too fast with angle.

    ``theta`` is the viewing angle in air in degrees, in [0, 90]. Below the critical
    angle of an ``n < 1`` film the refracted wave is evanescent and t' is 0.
    """
    t = _array("thickness", thickness, minimum=0.0, unit=" nm")
    n = _index("n", n)
    theta = np.deg2rad(_angle(theta))
    if mode == "refraction":
        return t * np.sqrt(np.maximum(n * n - np.sin(theta) ** 2, 0.0))
    if mode == "literal":
        return t * n * np.cos(theta)
    raise ValueError(f"mode must be 'refraction' or 'literal', got {mode!r}")


def two_beam_reflectance(optical_thickness_nm, wavelengths, *, phase_change: bool = True,
                         band_limited: bool = False):
    """Two-beam reflectance of a single film, normalised to a peak of 1 (Eq. 5-8).

    Eq. 7 (phase change: soap film, oil on water):   R = sin^2(2 pi t'/lambda)
    Eq. 8 (no phase change: film on a denser base):  R = cos^2(2 pi t'/lambda)

    Eq. 6 -> 7 drops the factor 4 of the two-beam amplitude sum, so R is relative
    to the illuminant with a peak of 1 and a thick-film (incoherent) mean of 1/2.
    Written as the cosine series ``1/2 (1 -/+ cos(phi))`` with ``phi = 4 pi t'/lambda``.
    """
    t = _array("optical_thickness", optical_thickness_nm, minimum=0.0, unit=" nm")
    wl = check_wavelengths(wavelengths)
    phi, dphi = _phase(2.0 * t, wl, band_limited)
    return _cosine_series([0.5, -0.5 if phase_change else 0.5], phi, dphi)


def morpho_layer_thickness(theta=0.0, d1: float = MORPHO["d1"], d2: float = MORPHO["d2"],
                           n: float = MORPHO["n"]):
    """Effective layer thickness for the Morpho scale, Eq. 14 (nm):
    ``t = d1 cos(theta) + d2 sqrt(n^2 - sin^2(theta))``."""
    theta = np.deg2rad(_angle(theta))
    d1 = _array("d1", d1, minimum=0.0, unit=" nm")
    d2 = _array("d2", d2, minimum=0.0, unit=" nm")
    n = _index("n", n)
    return d1 * np.cos(theta) + d2 * np.sqrt(np.maximum(n * n - np.sin(theta) ** 2, 0.0))


def multilayer_reflectance(thickness, wavelengths, layers: int = MORPHO["layers"], *,
                           band_limited: bool = False):
    """Multiple-film reflectance, Eq. 9 (Anderson & Richards 1942), peak-normalised.

    Eq. 9 reads ``I = 1/2 A0 (sin(2 pi (l+1) t/lambda) / sin(2 pi t/lambda))^2``. With
    ``x = 2 pi t/lambda`` the ratio is the Fejer kernel

        (sin((l+1)x) / sin x)^2 = (l+1) + 2 sum_{k=1..l} (l+1-k) cos(2 k x),

    a finite cosine series that is exact everywhere, including the 0/0 points
    ``sin x = 0`` where it takes its peak ``(l+1)^2``, with no cancellation
    spike next to them. We divide by that peak (and drop the 1/2), so R peaks at 1.
    ``thickness`` is the effective layer thickness (Eq. 10 or 14) in nm.
    """
    t = _array("thickness", thickness, minimum=0.0, unit=" nm")
    wl = check_wavelengths(wavelengths)
    if isinstance(layers, (bool, np.bool_)) or int(layers) != layers or layers < 1:
        raise ValueError(f"layers must be an integer >= 1, got {layers!r}")
    l = int(layers)
    peak = float((l + 1) ** 2)
    coefficients = [(l + 1) / peak] + [2.0 * (l + 1 - k) / peak for k in range(1, l + 1)]
    # cos(2 k x) = cos(k phi) with phi = 4 pi t / lambda: optical path P = 2 t.
    phi, dphi = _phase(2.0 * t, wl, band_limited)
    return _cosine_series(coefficients, phi, dphi)


# --------------------------------------------------------------------------- #
# Exact physics beyond the paper.
# --------------------------------------------------------------------------- #
def _cos_refracted(n_incident, n_layer, sin_incident):
    """cos(theta) inside a layer from Snell's law, on the branch colour-science's TMM
    and Byrnes' tmm use (forward-decaying for evanescent and absorbing layers)."""
    n_layer = np.asarray(n_layer, dtype=np.complex128)
    sin_t = np.asarray(n_incident, dtype=np.complex128) * sin_incident / n_layer
    cos_t = np.sqrt(1.0 - sin_t * sin_t)
    # Forward wave: Im(n cos) >= 0 (decays into the layer); for lossless propagating
    # waves Re(n cos) > 0.
    ncos = n_layer * cos_t
    flip = (ncos.imag < -1e-15) | ((np.abs(ncos.imag) <= 1e-15) & (ncos.real < 0))
    return np.where(flip, -cos_t, cos_t)


def _fresnel(n_i, cos_i, n_j, cos_j):
    """Fresnel amplitude reflection coefficients (s, p) at one interface."""
    rs = (n_i * cos_i - n_j * cos_j) / (n_i * cos_i + n_j * cos_j)
    rp = (n_j * cos_i - n_i * cos_j) / (n_j * cos_i + n_i * cos_j)
    return rs, rp


def _complex_index(name, n):
    n = np.asarray(n)
    if n.dtype.kind != "c":
        n = _index(name, n)
    elif np.any(n.real <= 0) or not np.all(np.isfinite(n)):
        raise ValueError(f"{name} must have a finite real part > 0")
    return n.astype(np.complex128)


def airy_reflectance(thickness, wavelengths, n_film, theta=0.0, *, n_incident=1.0,
                     n_substrate=1.0, band_limited: bool = False, harmonics: int = 64):
    """Exact reflectance of one film: the Airy sum of all internal reflections.

    ``r = (r01 + r12 e^{i delta}) / (1 + r01 r12 e^{i delta})`` with Fresnel
    amplitudes r01, r12 for s and p, ``delta = 4 pi n1 d cos(theta1) / lambda``;
    returns ``(|r_s|^2 + |r_p|^2) / 2`` (unpolarised light). Indices may be complex
    (absorbing media); total internal reflection (``n_film`` or ``n_substrate`` below
    ``n_incident sin(theta)``) follows from the complex refraction angle. Indices do
    not depend on wavelength here.

    For a lossless, propagating film ``R(delta)`` is 2 pi-periodic, so with
    ``band_limited=True`` it is expanded into ``harmonics`` Fourier terms (an FFT
    over one period) and each bin-averaged by :func:`_cosine_series`. Evanescent or
    absorbing films do not oscillate and are evaluated pointwise.
    """
    d = _array("thickness", thickness, minimum=0.0, unit=" nm")
    wl = check_wavelengths(wavelengths)
    theta = np.deg2rad(_angle(theta))
    n0 = _complex_index("n_incident", n_incident)
    n1 = _complex_index("n_film", n_film)
    n2 = _complex_index("n_substrate", n_substrate)
    sin0 = np.sin(theta)
    cos0 = _cos_refracted(n0, n0, sin0)
    cos1 = _cos_refracted(n0, n1, sin0 + 0j)
    cos2 = _cos_refracted(n0, n2, sin0 + 0j)
    r01 = _fresnel(n0, cos0, n1, cos1)
    r12 = _fresnel(n1, cos1, n2, cos2)
    beta_path = n1 * cos1 * d  # delta = 2 pi (2 beta_path) / lambda

    def point(delta_factor):
        out = 0.0
        for a, b in zip(r01, r12):
            a, b = np.asarray(a)[..., None], np.asarray(b)[..., None]
            z = np.exp(1j * delta_factor)
            r = (a + b * z) / (1.0 + a * b * z)
            out = out + 0.5 * np.abs(r) ** 2
        return out

    path = 2.0 * beta_path
    if not band_limited:
        return point(2.0 * np.pi * path[..., None] / wl)
    # Lossless propagating film: real path. Fourier-expand R over one period of delta.
    real_path = np.abs(np.imag(path)) < 1e-12 * np.maximum(np.abs(path), 1.0)
    phi_c, dphi = _phase(np.real(path), wl, True)
    grid = 2.0 * np.pi * np.arange(harmonics) / harmonics
    samples = point(np.broadcast_to(grid, np.shape(np.real(path)) + (harmonics,)))
    spectrum = np.fft.rfft(samples, axis=-1) / harmonics
    coefficients = [spectrum[..., 0].real] + [2.0 * spectrum[..., k]
                                              for k in range(1, harmonics // 2)]
    smooth = _cosine_series(coefficients, phi_c, dphi)
    if np.all(real_path):
        return smooth
    return np.where(real_path[..., None], smooth, point(2.0 * np.pi * path[..., None] / wl))


def transfer_matrix_reflectance(n_layers, thicknesses, wavelengths, theta=0.0, *,
                                n_incident=1.0, n_substrate=1.0):
    """Exact reflectance of a multilayer stack by characteristic (transfer) matrices.

    ``n_layers`` and ``thicknesses`` (nm) list the layers from the incidence side;
    ``theta`` (degrees) broadcasts against the wavelength axis. Returns the
    unpolarised ``(R_s + R_p) / 2`` with shape ``theta.shape + (len(wavelengths),)``.
    Evaluated pointwise (no band limiting: a stack has many incommensurate paths).
    """
    wl = check_wavelengths(wavelengths)
    theta = np.deg2rad(_angle(theta))[..., None]
    n_list = [_complex_index("n_layers", n) for n in np.atleast_1d(n_layers)]
    d_list = np.atleast_1d(_array("thicknesses", thicknesses, minimum=0.0, unit=" nm"))
    if len(n_list) != d_list.size or d_list.ndim != 1:
        raise ValueError("n_layers and thicknesses must be 1-D and of equal length")
    n0 = _complex_index("n_incident", n_incident)
    ns = _complex_index("n_substrate", n_substrate)
    sin0 = np.sin(theta) + 0j
    out = 0.0
    for polarisation in (0, 1):
        media = [n0] + n_list + [ns]
        cosines = [_cos_refracted(n0, m, sin0) for m in media]

        def admittance(m, c):
            return m * c if polarisation == 0 else m / c

        # Characteristic matrix product M = prod [[cos b, -i sin b / eta], [-i eta sin b, cos b]]
        m11 = np.ones(np.broadcast_shapes(theta.shape, wl.shape), complex)
        m12 = np.zeros_like(m11)
        m21 = np.zeros_like(m11)
        m22 = np.ones_like(m11)
        for j, (m, d) in enumerate(zip(n_list, d_list), start=1):
            c = cosines[j]
            eta = admittance(m, c)
            b = 2.0 * np.pi * m * c * d / wl
            cb, sb = np.cos(b), np.sin(b)
            a11, a12, a21, a22 = cb, -1j * sb / eta, -1j * eta * sb, cb
            m11, m12, m21, m22 = (m11 * a11 + m12 * a21, m11 * a12 + m12 * a22,
                                  m21 * a11 + m22 * a21, m21 * a12 + m22 * a22)
        eta0 = admittance(n0, cosines[0])
        etas = admittance(ns, cosines[-1])
        num = eta0 * m11 + eta0 * etas * m12 - m21 - etas * m22
        den = eta0 * m11 + eta0 * etas * m12 + m21 + etas * m22
        out = out + 0.5 * np.abs(num / den) ** 2
    return out
