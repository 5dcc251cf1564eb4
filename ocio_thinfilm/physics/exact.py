"""Exact thin-film optics beyond the paper: the references the paper's models are checked against.

- :func:`airy_reflectance` -- one film: the Airy sum of its multiple reflections with
  the exact s/p Fresnel amplitudes (absorbing and evanescent layers included),
  band-limited like the paper's models (:mod:`ocio_thinfilm.physics.sampling`);
- :func:`transfer_matrix_reflectance` -- a stack of layers by transfer matrices
  (Byrnes 2016, as colour-science's ``multilayer_tmm``), evaluated as a recursion;
- :func:`stack_reflectance`, :func:`stack_transmittance` -- the same against one
  layer's thickness with dispersive indices (and the power transmitted);
  :func:`stack_pointwise` at independent samples (a renderer's).

Lengths in nanometres, angles in degrees; the wavelength grid is the last axis of the
result.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import ParameterError, as_array, as_count
from ocio_thinfilm.physics.airy import airy_band_limited, airy_exact, airy_terms
from ocio_thinfilm.physics.sampling import (
    MAX_LAYERS,
    as_angle,
    as_index,
    check_wavelengths,
)

__all__ = [
    "airy_reflectance",
    "transfer_matrix_reflectance",
    "stack_reflectance",
    "stack_transmittance",
    "stack_pointwise",
    "adequate_step",
    "interface_amplitudes",
]


def _cos_refracted(
    n_incident: npt.ArrayLike, n_layer: npt.ArrayLike, sin_incident: np.ndarray
) -> np.ndarray:
    """cos(theta) inside a layer from Snell's law.

    On the branch colour-science's TMM and Byrnes' tmm use (forward-decaying for evanescent
    and absorbing layers).
    """
    n_layer = np.asarray(n_layer, dtype=np.complex128)
    sin_t = np.asarray(n_incident, dtype=np.complex128) * sin_incident / n_layer
    cos_t = np.sqrt(1.0 - sin_t * sin_t)
    # Forward wave: Im(n cos) >= 0 (decays into the layer); for lossless propagating
    # waves Re(n cos) > 0.
    ncos = n_layer * cos_t
    flip = (ncos.imag < -1e-15) | ((np.abs(ncos.imag) <= 1e-15) & (ncos.real < 0))
    return np.where(flip, -cos_t, cos_t)


def _fresnel(
    n_i: np.ndarray, cos_i: np.ndarray, n_j: np.ndarray, cos_j: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Fresnel amplitude reflection coefficients (s, p) at one interface.

    Both denominators vanish only when both cosines do (grazing incidence on an
    index-matched interface, which is no interface at all): r = 0 there, not 0/0.
    """

    def ratio(num: npt.ArrayLike, den: npt.ArrayLike) -> np.ndarray:
        num, den = np.broadcast_arrays(np.asarray(num, complex), np.asarray(den, complex))
        return np.divide(num, den, out=np.zeros_like(num), where=den != 0)

    rs = ratio(n_i * cos_i - n_j * cos_j, n_i * cos_i + n_j * cos_j)
    rp = ratio(n_j * cos_i - n_i * cos_j, n_j * cos_i + n_i * cos_j)
    return rs, rp


def _complex_index(name: str, n: npt.ArrayLike) -> np.ndarray:
    n = np.asarray(n)
    if n.dtype.kind != "c":
        n = as_index(name, n)
    elif np.any(n.real <= 0) or not np.all(np.isfinite(n)):
        raise ParameterError(name, " must have a finite real part > 0")
    return n.astype(np.complex128)


def airy_reflectance(
    thickness: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    n_film: npt.ArrayLike,
    theta: npt.ArrayLike = 0.0,
    *,
    n_incident: npt.ArrayLike = 1.0,
    n_substrate: npt.ArrayLike = 1.0,
    band_limited: bool = False,
    harmonics: int = 64,
) -> np.ndarray:
    """Exact reflectance of one film: the Airy sum of all internal reflections.

    ``r = (r01 + r12 e^{i delta}) / (1 + r01 r12 e^{i delta})`` with Fresnel
    amplitudes r01, r12 for s and p, ``delta = 4 pi n1 d cos(theta1) / lambda``;
    returns ``(|r_s|^2 + |r_p|^2) / 2`` (unpolarised light). Indices may be complex
    (absorbing media); total internal reflection (``n_film`` or ``n_substrate`` below
    ``n_incident sin(theta)``) follows from the complex refraction angle. Indices do
    not depend on wavelength here.

    For a lossless, propagating film ``R(delta)`` is 2 pi-periodic, so with
    ``band_limited=True`` it is expanded into ``harmonics`` Fourier terms (an FFT
    over one period) and each bin-averaged by
    :func:`~ocio_thinfilm.physics.sampling.cosine_series`. Evanescent or
    absorbing films do not oscillate and are evaluated pointwise; so is near-grazing
    incidence, where ``|r01 r12|**(harmonics/2) >= 1e-6`` and the truncated series
    would ring (R outside [0, 1]).

    Parameters
    ----------
    thickness : array_like
        Physical film thickness d in nm, >= 0.
    wavelengths : array_like
        Wavelengths in nm (the last axis of the result).
    n_film, n_incident, n_substrate : complex or array_like
        Refractive indices (complex: absorbing).
    theta : array_like, optional
        Angle of incidence, degrees in [0, 90].
    band_limited : bool, optional
        Bin-average each sample (see the module docstring).
    harmonics : int, optional
        Fourier terms of the band-limited expansion.

    Returns
    -------
    numpy.ndarray
        Unpolarised reflectance in [0, 1].

    References
    ----------
    Born, M., Wolf, E. Principles of Optics, Section 7.6 (the Airy formulae).

    Examples
    --------
    colour-science's ``thin_film_tmm`` documents R = 0.1215919 for a 250 nm film of
    index 1.5 in air at 555 nm:

    >>> airy_reflectance(250.0, [555.0], 1.5).round(7).tolist()
    [0.1215919]
    """
    d = as_array("thickness", thickness, minimum=0.0, unit=" nm")
    wl = check_wavelengths(wavelengths)
    harmonics = as_count("harmonics", harmonics, 1, MAX_LAYERS)
    theta = np.deg2rad(as_angle(theta))
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

    r02 = _fresnel(n0, cos0, n2, cos2)
    terms, need_sin = airy_terms(r01, r12, r02)
    path = 2.0 * beta_path
    if not band_limited:
        return np.clip(airy_exact(terms, need_sin, path, 2.0 * np.pi / wl), 0.0, 1.0)
    # Lossless propagating film: real path. Fourier-expand R over one period of delta.
    # (A property of the film, not of the product with d: a zero-thickness evanescent
    # film has a real path but R(delta) with poles, which no Fourier series captures.)
    # The k-th Fourier coefficient of R(delta) decays like |r01 r12|^k: near grazing
    # incidence (|r01 r12| -> 1) R(delta) is too sharp for ``harmonics`` terms, and
    # those rows are evaluated pointwise too (else the truncated series rings, R > 1).
    film = n1 * cos1
    ab = np.maximum(np.abs(r01[0] * r12[0]), np.abs(r01[1] * r12[1]))
    converged = ab ** (harmonics // 2) < 1e-6
    real_path = np.broadcast_to(
        (np.abs(np.imag(film)) <= 1e-12 * np.abs(film)) & converged, np.shape(path)
    )
    return airy_band_limited(terms, need_sin, path, wl, real_path, harmonics)


def transfer_matrix_reflectance(
    n_layers: npt.ArrayLike,
    thicknesses: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    theta: npt.ArrayLike = 0.0,
    *,
    n_incident: npt.ArrayLike = 1.0,
    n_substrate: npt.ArrayLike = 1.0,
) -> np.ndarray:
    """Exact reflectance of a multilayer stack (transfer-matrix physics).

    ``n_layers`` and ``thicknesses`` (nm) list the layers from the incidence side;
    ``theta`` (degrees) broadcasts against the wavelength axis. Returns the
    unpolarised ``(R_s + R_p) / 2`` with shape ``theta.shape + (len(wavelengths),)``.
    Evaluated pointwise (no band limiting: a stack has many incommensurate paths).

    The product of characteristic matrices is evaluated in its equivalent recursive
    form (Rouard's method: the Airy sum applied layer by layer from the substrate
    up), ``r_j = (rho_j + r_{j+1} z_j) / (1 + rho_j r_{j+1} z_j)`` with the Fresnel
    amplitude ``rho_j`` above layer j and ``z_j = exp(2 i beta_j)``,
    ``beta_j = 2 pi n_j d_j cos(theta_j) / lambda``. Since ``|z_j| <= 1`` on the
    forward-decaying branch, thick evanescent (total internal reflection) or absorbing
    layers cannot overflow, which the raw matrix product (cosh of a large argument)
    does. Zero-thickness layers are absent.

    Parameters
    ----------
    n_layers : array_like
        Indices of the layers from the incidence side (complex: absorbing).
    thicknesses : array_like
        Their thicknesses in nm.
    wavelengths : array_like
        Wavelengths in nm (the last axis of the result).
    theta : array_like, optional
        Angle of incidence, degrees in [0, 90].
    n_incident, n_substrate : complex, optional
        The media on either side.

    Returns
    -------
    numpy.ndarray
        Unpolarised reflectance, shape ``theta.shape + (len(wavelengths),)``.

    References
    ----------
    Byrnes, S. J. (2016). Multilayer optical calculations. arXiv:1603.02720.

    Examples
    --------
    One layer is the Airy film (the value colour-science documents):

    >>> transfer_matrix_reflectance([1.5], [250.0], [555.0]).round(7).tolist()
    [0.1215919]
    """
    wl = check_wavelengths(wavelengths)
    angle: np.ndarray = np.deg2rad(as_angle(theta))[..., None]  # radians; broadcasts against wl
    n_list = [_complex_index("n_layers", n) for n in np.atleast_1d(n_layers)]
    d_list = np.atleast_1d(as_array("thicknesses", thicknesses, minimum=0.0, unit=" nm"))
    if not n_list:
        raise ParameterError("n_layers", " must list at least 1 layer (an empty stack is no film)")
    if len(n_list) != d_list.size or d_list.ndim != 1:
        raise ParameterError("n_layers", " and thicknesses must be 1-D and of equal length")
    n0 = _complex_index("n_incident", n_incident)
    ns = _complex_index("n_substrate", n_substrate)
    sin0 = np.sin(angle) + 0j
    keep = [j for j in range(d_list.size) if d_list[j] > 0]
    media = [n0] + [n_list[j] for j in keep] + [ns]
    depths = [d_list[j] for j in keep]
    cosines = [_cos_refracted(n0, m, sin0) for m in media]
    shape = np.broadcast_shapes(angle.shape, wl.shape)
    # z_j for every layer (shared by both polarisations); media[j] is layer j.
    z = [
        np.exp(2j * (2.0 * np.pi / wl) * media[j] * cosines[j] * depths[j - 1])
        for j in range(1, len(media) - 1)
    ]
    return _rouard(media, cosines, z, shape)[0]


def _rouard(
    media: list[np.ndarray],
    cosines: list[np.ndarray],
    z: list[np.ndarray],
    shape: tuple,
    transmit: bool = False,
) -> tuple[np.ndarray, np.ndarray | None]:
    """Return the unpolarised reflectance (and transmittance) of the stack ``media``.

    ``media``: incident medium, layers, substrate; the layers' round-trip phasors are
    ``z``. Rouard's recursion runs from the substrate up, per polarisation (see
    :func:`transfer_matrix_reflectance`); with ``transmit`` the transmitted amplitude
    follows the same recursion, ``t_j = tau_j t_{j+1} sqrt(z_j) / (1 + rho_j r_{j+1}
    z_j)`` with the Fresnel transmission amplitude ``tau_j`` (Byrnes 2016, Eq. 13 and
    15), and ``T = Re(n_s cos_s) / Re(n_0 cos_0) |t|^2`` for s and with the conjugate
    cosines for p (the power flow through a non-absorbing incident medium).
    """
    out = np.zeros(shape)
    through = np.zeros(shape) if transmit else None
    roots = [np.sqrt(zj) for zj in z] if transmit else []
    for polarisation in (0, 1):
        rho = [
            _fresnel(media[i], cosines[i], media[i + 1], cosines[i + 1])[polarisation]
            for i in range(len(media) - 1)
        ]
        r = np.broadcast_to(rho[-1], shape).astype(complex)
        t = np.broadcast_to(1.0 + rho[-1], shape).astype(complex) if transmit else None
        if transmit and polarisation == 1:  # tau_p = (1 + r_p) n_i / n_j
            t = t * np.broadcast_to(media[-2] / media[-1], shape)
        for j in range(len(media) - 2, 0, -1):
            a = np.broadcast_to(rho[j - 1], shape).astype(complex)
            rz = r * z[j - 1]
            den = 1.0 + a * rz
            # den = 0 needs |rho| = |r z| = 1 (grazing incidence on an absentee layer):
            # keep the interface's own total reflection there.
            ok = den != 0
            r = np.divide(a + rz, den, out=a.copy(), where=ok)
            if t is not None:
                tau = 1.0 + a
                if polarisation == 1:
                    tau = tau * (media[j - 1] / media[j])
                t = np.divide(tau * t * roots[j - 1], den, out=np.zeros(shape, complex), where=ok)
        out += 0.5 * np.abs(r) ** 2
        if through is not None and t is not None:
            n0, ns, c0, cs = media[0], media[-1], cosines[0], cosines[-1]
            conj = np.conj if polarisation == 1 else np.asarray
            num, den = np.broadcast_arrays(np.real(ns * conj(cs)), np.real(n0 * conj(c0)))
            # grazing incidence (cos = 0) carries no power into the stack: T = 0
            flux = np.divide(num, den, out=np.zeros(num.shape), where=den > 0)
            through += 0.5 * np.broadcast_to(flux, shape) * np.abs(t) ** 2
    # |r|^2 <= 1; rounding can leave 1e-16 outside
    return np.clip(out, 0.0, 1.0), None if through is None else np.clip(through, 0.0, 1.0)


def stack_reflectance(
    n_media: npt.ArrayLike,
    thicknesses: npt.ArrayLike,
    vary: int,
    thickness: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    theta: float = 0.0,
) -> np.ndarray:
    """Exact unpolarised reflectance of a stack against the thickness of one layer.

    The transfer-matrix physics of :func:`transfer_matrix_reflectance` (Rouard's
    recursion, both polarisations averaged) with dispersive, complex indices: each
    medium's index is given on the wavelength grid. Evaluated pointwise: the caller
    samples the wavelengths finely enough for the stack's optical paths
    (:func:`adequate_step`).

    Parameters
    ----------
    n_media : array_like
        Complex indices ``n + ik``, shape ``(media, len(wavelengths))`` (or one value
        per medium): the incident medium, the layers from the incidence side, the
        substrate. ``Re(n) > 0``, ``k >= 0``.
    thicknesses : array_like
        Thickness (nm) of each layer (``media - 2`` values); entry ``vary`` is ignored.
    vary : int
        The layer (0-based, among the layers) whose thickness varies.
    thickness : array_like
        Its thicknesses in nm, >= 0 (the leading axes of the result).
    wavelengths : array_like
        Wavelengths in nm (the last axis of the result).
    theta : float, optional
        Angle of incidence in the incident medium, degrees in [0, 90].

    Returns
    -------
    numpy.ndarray
        ``(R_s + R_p) / 2`` in [0, 1], shape ``thickness.shape + (len(wavelengths),)``.

    References
    ----------
    Byrnes, S. J. (2016). Multilayer optical calculations. arXiv:1603.02720.
    Born, M., Wolf, E. Principles of Optics, Section 1.6.

    Examples
    --------
    A 250 nm film of index 1.5 in air at 555 nm (colour-science's documented value):

    >>> stack_reflectance([1.0, 1.5, 1.0], [0.0], 0, [250.0], [555.0]).round(7).tolist()
    [[0.1215919]]
    """
    return _stack(n_media, thicknesses, vary, thickness, wavelengths, theta, False)[0]


def stack_transmittance(
    n_media: npt.ArrayLike,
    thicknesses: npt.ArrayLike,
    vary: int,
    thickness: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    theta: float = 0.0,
) -> tuple[np.ndarray, np.ndarray]:
    """Exact unpolarised reflectance and transmittance of a stack against one layer's thickness.

    The arguments and the reflectance are those of :func:`stack_reflectance`; the
    transmittance ``(T_s + T_p) / 2`` is the power carried into the substrate, through
    Rouard's recursion for the transmitted amplitude (Byrnes 2016, Eq. 13-15, 21-22).
    The incident medium must not absorb (the power flow there is then well defined).
    For lossless layers ``R + T = 1``; absorbing layers take the rest, ``A = 1 - R - T``.

    Parameters
    ----------
    n_media, thicknesses, vary, thickness, wavelengths, theta
        As :func:`stack_reflectance`.

    Returns
    -------
    R, T : numpy.ndarray
        Each in [0, 1], shape ``thickness.shape + (len(wavelengths),)``.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``n_media``) if the incident medium absorbs, and the errors of
        :func:`stack_reflectance`.

    References
    ----------
    Byrnes, S. J. (2016). Multilayer optical calculations. arXiv:1603.02720.

    Examples
    --------
    A 250 nm film of index 1.5 in air at 555 nm: R as colour-science documents, and
    T = 1 - R:

    >>> R, T = stack_transmittance([1.0, 1.5, 1.0], [0.0], 0, [250.0], [555.0])
    >>> R.round(7).tolist(), (R + T).round(12).tolist()
    ([[0.1215919]], [[1.0]])
    """
    if np.any(np.asarray(n_media)[0].imag != 0):
        raise ParameterError("n_media", " must start with a non-absorbing incident medium (k = 0)")
    R, T = _stack(n_media, thicknesses, vary, thickness, wavelengths, theta, True)
    assert T is not None
    return R, T


def _stack(
    n_media: npt.ArrayLike,
    thicknesses: npt.ArrayLike,
    vary: int,
    thickness: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    theta: float,
    transmit: bool,
) -> tuple[np.ndarray, np.ndarray | None]:
    """Check the arguments of :func:`stack_reflectance` and run Rouard's recursion."""
    wl = check_wavelengths(wavelengths)
    n = np.asarray(n_media)
    if n.dtype.kind not in "biufc":
        raise TypeError("n_media must be complex indices, one row per medium")
    n = np.broadcast_to(n.astype(np.complex128).reshape(n.shape[0], -1), (n.shape[0], wl.size))
    if n.shape[0] < 3:
        raise ParameterError("n_media", " must list the incident medium, >= 1 layer, the substrate")
    if not np.all(np.isfinite(n)) or np.any(n.real <= 0) or np.any(n.imag < 0):
        raise ParameterError("n_media", " must be finite with Re(n) > 0 and k >= 0")
    layers = n.shape[0] - 2
    depths = np.atleast_1d(as_array("thicknesses", thicknesses, minimum=0.0, unit=" nm"))
    if depths.shape != (layers,):
        raise ParameterError("thicknesses", f" must give one thickness per layer ({layers})")
    vary = as_count("vary", vary, 0, layers - 1)
    d = as_array("thickness", thickness, minimum=0.0, unit=" nm")
    sin0 = np.sin(np.deg2rad(as_angle(theta))) + 0j
    media = [n[i] for i in range(n.shape[0])]
    cosines = [_cos_refracted(media[0], m, sin0) for m in media]
    z = _phasors(media, cosines, depths, vary, d[..., None], 2.0 * np.pi / wl)
    return _rouard(media, cosines, z, d.shape + wl.shape, transmit)


def _phasors(media: list, cosines: list, depths: np.ndarray, vary: int, d: Any, k0: Any) -> list:
    """Return ``z_j = exp(2 i k0 n_j cos_j d_j)`` per layer (layer ``vary``: ``d``; 0: none)."""
    z = []
    for j in range(len(media) - 2):
        beta = k0 * media[j + 1] * cosines[j + 1]
        depth = d if j == vary else depths[j]
        z.append(np.exp(2j * beta * depth) if j == vary or depth > 0 else np.ones(np.shape(beta)))
    return z


def stack_pointwise(
    n_media: npt.ArrayLike,
    thicknesses: npt.ArrayLike,
    vary: int,
    thickness: npt.ArrayLike,
    wavelengths: npt.ArrayLike,
    cos_theta: npt.ArrayLike,
    *,
    transmit: bool = True,
) -> tuple[np.ndarray, np.ndarray | None]:
    """Exact unpolarised R (and T) of a stack per sample (:func:`stack_transmittance`'s physics).

    Every argument broadcasts elementwise: each sample has its own wavelength, angle and
    thickness (a renderer's); the caller checks the stack once.

    Parameters
    ----------
    n_media : array_like
        Complex indices, shape ``(media, ...)``, broadcasting against the samples.
    thicknesses, vary, transmit
        As :func:`stack_reflectance`; ``transmit``: also T (else None).
    thickness, wavelengths, cos_theta : array_like
        Per sample: the varying layer's thickness (nm), the wavelength (nm), cos of the
        angle of incidence in the (non-absorbing) incident medium.

    Returns
    -------
    R, T : numpy.ndarray
        The samples' shape (T None unless ``transmit``).

    Examples
    --------
    >>> R, T = stack_pointwise([[1.0], [1.5], [1.0]], [0.0], 0, [250.0], [555.0], [1.0])
    >>> R.round(7).tolist(), (R + T).round(12).tolist()
    ([0.1215919], [1.0])
    """
    n, c = np.asarray(n_media, np.complex128), np.clip(np.asarray(cos_theta, np.float64), 0, 1)
    wl, d = np.asarray(wavelengths, dtype=np.float64), np.asarray(thickness, dtype=np.float64)
    shape = np.broadcast_shapes(n.shape[1:], c.shape, wl.shape, d.shape)
    cosines = [_cos_refracted(n[0], m, np.sqrt(1.0 - c * c) + 0j) for m in n]
    depths = np.asarray(thicknesses, dtype=np.float64).reshape(-1)
    z = _phasors(list(n), cosines, depths, vary, np.maximum(d, 0.0), 2.0 * np.pi / wl)
    return _rouard(list(n), cosines, z, shape, transmit)


def adequate_step(
    optical_path_nm: float,
    lo: float = 380.0,
    *,
    sharpness: float = 0.0,
    maximum: float = 5.0,
    minimum: float = 0.02,
) -> float:
    """Return a wavelength step (nm) that resolves the interference of optical paths.

    The step resolves optical paths up to ``optical_path_nm`` (round trip,
    ``P = 2 sum n d cos(theta)``) down to ``lo`` nm.

    The phase ``2 pi P / lambda`` turns ``2 pi P dl / lambda^2`` per step. A film whose
    two reflections have amplitudes ``|r_a r_b| = sharpness`` has an Airy spectrum whose
    k-th harmonic falls like ``sharpness**k``; the step samples the harmonics down to
    1e-4 (``K`` of them) 16 times per period: ``dl = lo^2 / (16 P max(1, K / 2))``,
    within ``[minimum, maximum]``.

    Parameters
    ----------
    optical_path_nm : float
        The longest round-trip optical path, nm.
    lo : float, optional
        The shortest wavelength, nm.
    sharpness : float, optional
        ``|r_a r_b|`` in [0, 1): 0 for a two-beam (cosine) spectrum.
    maximum, minimum : float, optional
        Bounds of the step, nm.

    Returns
    -------
    float
        The step in nm.

    Examples
    --------
    >>> adequate_step(1000.0)
    5.0
    >>> round(adequate_step(6000.0), 3)
    1.504
    >>> round(adequate_step(6000.0, sharpness=0.9), 3)
    0.034
    """
    path = max(float(optical_path_nm), 1e-9)
    s = min(max(float(sharpness), 0.0), 0.9999)
    harmonics = np.log(1e-4) / np.log(s) if s > 0 else 1.0
    return float(min(maximum, max(minimum, lo * lo / (16.0 * path * max(1.0, harmonics / 2)))))


def interface_amplitudes(
    n_media: npt.ArrayLike, theta: npt.ArrayLike = 0.0
) -> list[tuple[np.ndarray, np.ndarray]]:
    """Return the Fresnel amplitudes ``(r_s, r_p)`` of every interface of a stack.

    They are at the angle ``theta`` (degrees) in the first medium (complex Snell's law,
    the branch of :func:`transfer_matrix_reflectance`).

    Parameters
    ----------
    n_media : array_like
        Complex indices, shape ``(media, ...)``: the incident medium first.
    theta : float or array_like, optional
        Angle of incidence, degrees in [0, 90] (an array broadcasts with the indices).

    Returns
    -------
    list of tuple of numpy.ndarray
        One ``(r_s, r_p)`` per interface, from the incidence side.

    Examples
    --------
    Air to glass at normal incidence: ``(1 - 1.5) / (1 + 1.5) = -0.2`` for s (p has
    the opposite sign convention there):

    >>> [complex(r).real for r in interface_amplitudes([1.0, 1.5])[0]]
    [-0.2, 0.2]
    """
    n = np.asarray(n_media).astype(np.complex128)
    sin0 = np.sin(np.deg2rad(as_angle(theta))) + 0j
    media = [n[i] for i in range(n.shape[0])]
    cosines = [_cos_refracted(media[0], m, sin0) for m in media]
    return [
        _fresnel(media[i], cosines[i], media[i + 1], cosines[i + 1]) for i in range(len(media) - 1)
    ]
