"""A stack at one angle reduced to coefficients of its varying layer's phasor.

Rouard's recursion (:func:`ocio_thinfilm.physics.exact.stack_transmittance`) maps the
reflection amplitude below a layer to the one above it by a Moebius transformation of
the layer's phasor ``z = exp(i phase d)``. The layers below the varying one are fixed
numbers and those above compose with it, so at one angle the whole stack is
``r = (P z + Q) / (S z + U)``, ``t = K sqrt(z) / (S z + U)`` with coefficients per
wavelength that do not depend on the varying thickness: a table over thickness costs a
few real operations per sample instead of a recursion of complex divisions and an
exponential (:mod:`ocio_thinfilm.lut.material_tables`).

- :func:`stack_coefficients` -- the coefficients (:class:`StackCoefficients`);
- :func:`cmul`, :func:`cexp_i`, :func:`abs2` -- complex arithmetic that gives the same
  bits on every CPU: numpy's complex multiply fuses multiply-adds on CPUs with FMA and
  its ``abs`` has SIMD variants (:mod:`ocio_thinfilm.reproducible`); these use
  correctly rounded real operations and libm's complex exponential.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import ParameterError, as_array, as_count

__all__ = ["StackCoefficients", "stack_coefficients", "cmul", "cexp_i", "abs2"]


def cmul(a: npt.ArrayLike, b: npt.ArrayLike) -> np.ndarray:
    """Return ``a * b`` for complex arrays in real arithmetic: the same bits on every CPU.

    numpy's complex multiply fuses multiply-adds where the CPU has FMA (its last bits
    depend on the SIMD level: tests/test_reproducible.py); four correctly rounded
    products and two sums do not.

    Parameters
    ----------
    a, b : array_like
        Complex (or real) arrays that broadcast together.

    Returns
    -------
    numpy.ndarray
        complex128.

    Examples
    --------
    >>> cmul([1 + 2j], [3 - 1j]).tolist()
    [(5+5j)]
    """
    a, b = np.asarray(a), np.asarray(b)
    re = a.real * b.real
    re -= a.imag * b.imag
    im = a.real * b.imag
    im += a.imag * b.real
    out = np.empty(re.shape, dtype=np.complex128)
    out.real, out.imag = re, im
    return out


def _cdiv(a: npt.ArrayLike, b: npt.ArrayLike) -> np.ndarray:
    """Return ``a / b`` in real arithmetic (``a conj(b) / |b|^2``), 0 where ``b == 0``."""
    a, b = np.asarray(a), np.asarray(b)
    den = b.real * b.real + b.imag * b.imag
    ok = den != 0
    safe = np.where(ok, den, 1.0)
    re = a.real * b.real + a.imag * b.imag
    im = a.imag * b.real - a.real * b.imag
    out = np.empty(re.shape, dtype=np.complex128)
    out.real, out.imag = np.where(ok, re / safe, 0.0), np.where(ok, im / safe, 0.0)
    return out


def cexp_i(phase: np.ndarray, length: npt.ArrayLike) -> np.ndarray:
    """Return ``exp(i phase length)`` for a complex ``phase`` and real ``length``.

    The argument is formed in real arithmetic; the exponential is libm's (numpy's
    complex exp has no SIMD variant: the same bits on every SIMD level).

    Parameters
    ----------
    phase : numpy.ndarray
        Complex phase per unit length.
    length : float or array_like
        The length (broadcast against ``phase``).

    Returns
    -------
    numpy.ndarray
        complex128, the broadcast shape.

    Examples
    --------
    >>> cexp_i(np.array([np.pi / 2 + 0j]), 1.0).round(12).tolist()
    [1j]
    """
    phase = np.asarray(phase, dtype=np.complex128)
    re = -phase.imag * np.asarray(length, dtype=np.float64)
    arg = np.empty(re.shape, dtype=np.complex128)
    arg.real, arg.imag = re, phase.real * length
    return np.exp(arg)


def abs2(a: np.ndarray) -> np.ndarray:
    """Return ``|a|^2`` as ``re^2 + im^2`` (numpy's ``abs`` has SIMD variants).

    Parameters
    ----------
    a : numpy.ndarray
        A complex (or real) array.

    Returns
    -------
    numpy.ndarray
        float64.

    Examples
    --------
    >>> abs2(np.array([3 + 4j])).tolist()
    [25.0]
    """
    return a.real * a.real + a.imag * a.imag


class StackCoefficients(NamedTuple):
    """A stack at one angle against the thickness ``d`` of its varying layer.

    With ``z = exp(i phase d)`` (the varying layer's round-trip phasor) the unpolarised
    reflectance and transmittance are, summed over the polarisations s and p,

    ``R = sum 0.5 |P z + Q|^2 / |S z + U|^2``, ``T = sum power |z| / |S z + U|^2``.

    Attributes
    ----------
    phase : numpy.ndarray
        ``2 k0 n cos(theta)`` of the varying layer, complex, per wavelength (1/nm).
    P, Q, S, U : tuple of numpy.ndarray
        (s, p) complex coefficients per wavelength.
    power : tuple of numpy.ndarray
        (s, p) ``0.5 flux |K|^2``, real (zeros without ``transmit``).
    above : tuple of tuple of numpy.ndarray
        (s, p) of the ``(S_j, U_j)`` of the layers above the varying one: their
        denominators ``S_j z + U_j``, where Rouard's recursion would divide by zero.
    """

    phase: np.ndarray
    P: tuple[np.ndarray, np.ndarray]
    Q: tuple[np.ndarray, np.ndarray]
    S: tuple[np.ndarray, np.ndarray]
    U: tuple[np.ndarray, np.ndarray]
    power: tuple[np.ndarray, np.ndarray]
    above: tuple[tuple[tuple[np.ndarray, np.ndarray], ...], ...]


def _snell(n0: np.ndarray, n: np.ndarray, sin0: np.ndarray) -> np.ndarray:
    """:func:`_cos_refracted` in real arithmetic (the same branch)."""
    x = np.empty(n0.shape, dtype=np.complex128)
    x.real, x.imag = n0.real * sin0, n0.imag * sin0
    s = _cdiv(x, n)
    cos_t = np.sqrt(1.0 - cmul(s, s))
    ncos = cmul(n, cos_t)
    flip = (ncos.imag < -1e-15) | ((np.abs(ncos.imag) <= 1e-15) & (ncos.real < 0))
    return np.where(flip, -cos_t, cos_t)


def stack_coefficients(
    n_media: npt.ArrayLike,
    thicknesses: npt.ArrayLike,
    vary: int,
    wavelengths: npt.ArrayLike,
    cos_theta: npt.ArrayLike,
    transmit: bool = False,
) -> StackCoefficients:
    r"""Return a stack at one angle as coefficients of its varying layer's phasor.

    Rouard's recursion of :func:`stack_reflectance` (Byrnes 2016) maps the reflection
    amplitude below a layer to the one above it by a Moebius transformation of the
    layer's phasor ``z``; the layers below the varying one are fixed numbers, and those
    above compose with it into one transformation, so
    ``r = (P z + Q) / (S z + U)`` and ``t = K sqrt(z) / (S z + U)`` with coefficients
    that do not depend on the varying thickness (the transfer-matrix form: ``t`` is
    ``1 / M_00`` of the stack's characteristic matrix, ``r = M_10 / M_00``, Born &
    Wolf Section 1.6.5). Starting at the varying layer ``v`` with the reflection ``r_b``
    and transmission ``t_b`` of the stack below it, ``P = r_b``, ``Q = rho_v``,
    ``S = rho_v r_b``, ``U = 1``, ``K = tau_v t_b``; each layer ``j`` above (Fresnel
    amplitudes ``rho_j``, ``tau_j``, phasor ``z_j``) maps
    ``(P, Q, S, U) -> (rho_j S + z_j P, rho_j U + z_j Q, S + rho_j z_j P,
    U + rho_j z_j Q)`` and ``K -> tau_j sqrt(z_j) K``. The power transmitted is
    ``flux |t|^2`` with the flux factor of :func:`stack_transmittance`.

    Every product is formed in real arithmetic and every transcendental function is
    libm's, so the coefficients are the same bits on every CPU
    (:mod:`ocio_thinfilm.reproducible`). The incident medium's cosine is ``cos_theta``
    itself: grazing (0) and normal (1) incidence are exact.

    Parameters
    ----------
    n_media : array_like
        Complex indices, shape ``(media, len(wavelengths))``, as
        :func:`stack_reflectance`; the incident medium must not absorb.
    thicknesses : array_like
        Thickness (nm) of each layer; entry ``vary`` is ignored.
    vary : int
        The varying layer (0-based among the layers).
    wavelengths : array_like
        Wavelengths in nm, > 0, in any order (each is evaluated by itself).
    cos_theta : float or array_like
        Cosine of the angle of incidence in the incident medium, in [0, 1]: one, or one
        per wavelength (several angles' grids evaluated together; each value is what
        it would be alone).
    transmit : bool, optional
        Also the transmitted power (else ``power`` is zeros).

    Returns
    -------
    StackCoefficients
        The coefficients per wavelength.

    References
    ----------
    Byrnes, S. J. (2016). Multilayer optical calculations. arXiv:1603.02720.
    Born, M., Wolf, E. Principles of Optics, Section 1.6.

    Examples
    --------
    A 250 nm film of index 1.5 in air at 555 nm (colour-science's documented value):

    >>> import numpy as np
    >>> k = stack_coefficients([[1.0], [1.5], [1.0]], [0.0], 0, [555.0], 1.0)
    >>> z = np.exp(1j * k.phase * 250.0)
    >>> R = sum(0.5 * abs(k.P[i] * z + k.Q[i]) ** 2 / abs(k.S[i] * z + k.U[i]) ** 2 for i in (0, 1))
    >>> R.round(7).tolist()
    [0.1215919]
    """
    wl, n, depths, vary = _checked_stack(n_media, thicknesses, vary, wavelengths)
    c = np.broadcast_to(as_array("cos_theta", cos_theta, minimum=0.0, maximum=1.0), wl.shape)
    sin0 = np.sqrt(1.0 - c * c)
    media = [n[i] for i in range(n.shape[0])]
    cosines = [c.astype(np.complex128)]
    cosines += [_snell(media[0], m, sin0) for m in media[1:]]
    k0 = 2.0 * np.pi / wl
    # 2 k0 n_j cos_j per medium: z_j = exp(i phase_j d_j)
    phases = [cmul(cmul(m, cj), 2.0 * k0) for m, cj in zip(media, cosines, strict=True)]
    v = vary + 1  # the varying layer's index among the media
    z, roots = _fixed_phasors(phases, depths, v, wl.shape)
    fluxes = _fluxes(media, cosines, wl.shape)
    out: dict[str, list] = {key: [] for key in ("P", "Q", "S", "U", "power", "above")}
    for polarisation in (0, 1):
        P, Q, S, U, K, above = _moebius(media, cosines, z, roots, v, polarisation)
        out["P"].append(P)
        out["Q"].append(Q)
        out["S"].append(S)
        out["U"].append(U)
        power = 0.5 * fluxes[polarisation] * abs2(K) if transmit else np.zeros(wl.shape)
        out["power"].append(power)
        out["above"].append(above)
    return StackCoefficients(
        phases[v],
        *(tuple(out[key]) for key in ("P", "Q", "S", "U", "power", "above")),
    )


def _checked_stack(
    n_media: npt.ArrayLike, thicknesses: npt.ArrayLike, vary: int, wavelengths: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
    """Check :func:`stack_coefficients`' stack; return (wavelengths, n, depths, vary)."""
    wl = np.atleast_1d(as_array("wavelengths", wavelengths, minimum=0.0, strict=True, unit=" nm"))
    if wl.ndim != 1:
        raise ParameterError("wavelengths", " must be a 1-D array of nm values")
    n = np.asarray(n_media)
    if n.dtype.kind not in "biufc":
        raise TypeError("n_media must be complex indices, one row per medium")
    n = np.broadcast_to(n.astype(np.complex128).reshape(n.shape[0], -1), (n.shape[0], wl.size))
    if n.shape[0] < 3:
        raise ParameterError("n_media", " must list the incident medium, >= 1 layer, the substrate")
    if not np.all(np.isfinite(n)) or np.any(n.real <= 0) or np.any(n.imag < 0):
        raise ParameterError("n_media", " must be finite with Re(n) > 0 and k >= 0")
    if np.any(n[0].imag != 0):
        raise ParameterError("n_media", " must start with a non-absorbing incident medium (k = 0)")
    layers = n.shape[0] - 2
    depths = np.atleast_1d(as_array("thicknesses", thicknesses, minimum=0.0, unit=" nm"))
    if depths.shape != (layers,):
        raise ParameterError("thicknesses", f" must give one thickness per layer ({layers})")
    return wl, n, depths, as_count("vary", vary, 0, layers - 1)


def _fixed_phasors(phases: list, depths: np.ndarray, v: int, shape: tuple) -> tuple[dict, dict]:
    """Return the fixed layers' phasors z_j and their square roots, by medium index."""
    z, roots = {}, {}
    for j in range(1, len(phases) - 1):
        if j != v:
            d = float(depths[j - 1])
            z[j] = cexp_i(phases[j], d) if d > 0 else np.ones(shape, complex)
            roots[j] = cexp_i(phases[j], 0.5 * d) if d > 0 else np.ones(shape, complex)
    return z, roots


def _fluxes(media: list, cosines: list, shape: tuple) -> list[np.ndarray]:
    """Return the flux factors (s, p) of the power transmitted (as ``_rouard``)."""
    fluxes = []
    for polarisation in (0, 1):
        cs, c0 = cosines[-1], cosines[0]
        if polarisation == 1:
            cs, c0 = np.conj(cs), np.conj(c0)
        num, den = cmul(media[-1], cs).real, cmul(media[0], c0).real
        fluxes.append(np.divide(num, den, out=np.zeros(shape), where=den > 0))
    return fluxes


def _moebius(media: list, cosines: list, z: dict, roots: dict, v: int, polarisation: int) -> tuple:
    """Return (P, Q, S, U, K, above) of one polarisation.

    The stack below the varying layer ``v`` by Rouard's recursion, then the layers
    above composed with it.
    """
    one = np.ones(np.shape(media[0]), complex)
    rho = [
        _fresnel_real(media[i], cosines[i], media[i + 1], cosines[i + 1], polarisation)
        for i in range(len(media) - 1)
    ]

    def tau(j: int) -> np.ndarray:
        # the Fresnel transmission amplitude into media[j]; p: (1 + r_p) n_i / n_j
        t = 1.0 + rho[j - 1]
        return cmul(t, _cdiv(media[j - 1], media[j])) if polarisation == 1 else t

    r = rho[-1].copy()
    t = tau(len(media) - 1)
    for j in range(len(media) - 2, v, -1):  # the fixed layers below the varying one
        a = rho[j - 1]
        rz = cmul(r, z[j])
        den = 1.0 + cmul(a, rz)
        ok = den != 0  # as _rouard: the interface's own reflection there
        r = np.where(ok, _cdiv(a + rz, den), a)
        t = np.where(ok, _cdiv(cmul(cmul(tau(j), t), roots[j]), den), 0)
    a = rho[v - 1]
    P, Q, S, U, K = r, a, cmul(a, r), one, cmul(tau(v), t)
    above = []
    for j in range(v - 1, 0, -1):  # the fixed layers above the varying one
        above.append((S, U))
        a = rho[j - 1]
        az = cmul(a, z[j])
        P, Q, S, U = (
            cmul(a, S) + cmul(z[j], P),
            cmul(a, U) + cmul(z[j], Q),
            S + cmul(az, P),
            U + cmul(az, Q),
        )
        K = cmul(cmul(tau(j), roots[j]), K)
    return P, Q, S, U, K, tuple(above)


def _fresnel_real(
    n_i: np.ndarray, cos_i: np.ndarray, n_j: np.ndarray, cos_j: np.ndarray, polarisation: int
) -> np.ndarray:
    """:func:`_fresnel`'s s (0) or p (1) amplitude in real arithmetic, 0 where 0 / 0."""
    if polarisation == 0:
        x, y = cmul(n_i, cos_i), cmul(n_j, cos_j)
    else:
        x, y = cmul(n_j, cos_i), cmul(n_i, cos_j)
    return _cdiv(x - y, x + y)
