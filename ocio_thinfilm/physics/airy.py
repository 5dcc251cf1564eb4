"""The Airy sum of one film in real arithmetic: the kernel of :func:`.exact.airy_reflectance`.

Per polarisation, with Fresnel amplitudes a = r01, b = r12 and z = e^{i delta} =
rho e^{i psi} (rho = 1 for a lossless propagating film), ``|a + b z|^2 / |1 + a b z|^2``
written out in real arithmetic::

    num = |a|^2 + |b|^2 rho^2 + 2 rho (Re(a* b) cos psi - Im(a* b) sin psi)
    den = 1 + |a b|^2 rho^2 + 2 rho (Re(a b) cos psi - Im(a b) sin psi)

One cosine per sample serves s and p (the sine only when a coefficient is complex: TIR,
absorption). Where den = 0 (|r01| = |r12| = 1 with r01 r12 z = -1: grazing incidence on
an absentee layer) the film drops out: R = |r02|^2.

- :func:`airy_terms` -- those coefficients of both polarisations;
- :func:`airy_exact` -- R at each wavelength (pointwise);
- :func:`airy_band_limited` -- R bin-averaged by its Fourier series in delta.

References: Born, M., Wolf, E. Principles of Optics, Section 7.6 (the Airy formulae).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.physics.sampling import cosine_series, phase

__all__ = ["airy_terms", "airy_exact", "airy_band_limited"]

#: Per polarisation: (num's (constant, square, 2 Re, -2 Im), den's, |r02|^2, r01, r12).
Term = tuple[tuple[np.ndarray, ...], tuple[np.ndarray, ...], np.ndarray, np.ndarray, np.ndarray]


def airy_terms(r01: tuple, r12: tuple, r02: tuple) -> tuple[list[Term], bool]:
    """Return the Airy quotient's real coefficients (s and p) and whether it needs sines.

    Parameters
    ----------
    r01, r12, r02 : tuple of numpy.ndarray
        (s, p) Fresnel amplitudes of the top and bottom interfaces and of the incident
        medium against the substrate.

    Returns
    -------
    tuple
        The two :data:`Term` and whether a coefficient is complex (sin psi is needed).
    """
    terms: list[Term] = []
    for a, b, c in zip(r01, r12, r02, strict=True):
        a, b = np.asarray(a), np.asarray(b)
        cross_num, cross_den = np.conj(a) * b, a * b
        # (constant, |b|^2 or |ab|^2 times rho^2, 2 Re(cross), -2 Im(cross)) for num, den
        terms.append(
            (
                (np.abs(a) ** 2, np.abs(b) ** 2, 2.0 * cross_num.real, -2.0 * cross_num.imag),
                (
                    np.ones_like(np.abs(a)),
                    np.abs(a * b) ** 2,
                    2.0 * cross_den.real,
                    -2.0 * cross_den.imag,
                ),
                np.abs(c) ** 2,
                a,
                b,
            )
        )
    need_sin = any(np.any(q[0][3]) or np.any(q[1][3]) for q in terms)
    return terms, bool(need_sin)


def _columns(terms: list[Term], lead: tuple) -> list:
    """Broadcast the terms to ``lead`` and flatten them to one column each."""

    def column(x: npt.ArrayLike) -> np.ndarray:
        return np.broadcast_to(x, lead).reshape(-1, 1)

    return [
        (
            [column(x) for x in q[0]],
            [column(x) for x in q[1]],
            column(q[2]),
            column(q[3]),
            column(q[4]),
        )
        for q in terms
    ]


def _halves(
    coefficients: tuple, rows: slice, cos_psi: np.ndarray, sin_psi: Any, rho_r: Any
) -> list[np.ndarray]:
    """Return the numerator and denominator of one polarisation on a block of rows."""
    halves = []
    for const, square, re2, im2 in coefficients:
        v = cos_psi * re2[rows]
        if sin_psi is not None:
            v += sin_psi * im2[rows]
        if rho_r is None:
            v += const[rows] + square[rows]
        else:
            v *= rho_r
            v += square[rows] * rho_r * rho_r
            v += const[rows]
        halves.append(v)
    return halves


def _block(
    flat: list, rows: slice, psi: np.ndarray, rho: np.ndarray | None, need_sin: bool
) -> np.ndarray:
    """Return unpolarised R on one block of rows of ``psi``."""
    cos_psi = np.cos(psi[rows])
    sin_psi = np.sin(psi[rows]) if need_sin else None
    rho_r = None if rho is None else rho[rows]
    total = np.zeros(cos_psi.shape)
    for num_coef, den_coef, bare, a, b in flat:
        num, den = _halves((num_coef, den_coef), rows, cos_psi, sin_psi, rho_r)
        if den.min() > 1e-6:
            num /= den
        else:
            # |r01 r12| -> 1 (grazing incidence with TIR): num and den both
            # cancel; the complex quotient keeps full precision there.
            zz = cos_psi + 1j * (np.sin(psi[rows]) if sin_psi is None else sin_psi)
            if rho_r is not None:
                zz *= rho_r
            ar, br = a[rows], b[rows]
            num, den = ar + br * zz, 1.0 + ar * br * zz
            ok = den != 0
            num = np.where(
                ok,
                np.abs(np.divide(num, den, out=np.zeros_like(num), where=ok)) ** 2,
                bare[rows],
            )
        total += num
    total *= 0.5
    return total


def _point(
    terms: list[Term], need_sin: bool, psi: np.ndarray, rho: np.ndarray | None = None
) -> np.ndarray:
    """Return unpolarised R at phases ``psi`` (last axis), amplitudes ``rho`` (None: 1)."""
    arrays = [x for q in terms for x in (*q[0], *q[1], *q[2:])]
    lead = np.broadcast_shapes(psi.shape[:-1], *(np.shape(x) for x in arrays))
    width = psi.shape[-1]
    psi = np.broadcast_to(psi, lead + (width,)).reshape(-1, width)
    if rho is not None:
        rho = np.broadcast_to(rho, lead + (width,)).reshape(-1, width)
    flat = _columns(terms, lead)
    out = np.empty(psi.shape)
    chunk = max(1, 32768 // max(width, 1))  # rows per block: temporaries stay in cache
    for start in range(0, psi.shape[0], chunk):
        rows = slice(start, start + chunk)
        out[rows] = _block(flat, rows, psi, rho, need_sin)
    return out.reshape(lead + (width,))


def airy_exact(
    terms: list[Term], need_sin: bool, path: np.ndarray, wavenumber: np.ndarray
) -> np.ndarray:
    """Return unpolarised R at each wavelength, unclipped.

    Parameters
    ----------
    terms, need_sin
        :func:`airy_terms`.
    path : numpy.ndarray
        The complex optical path ``2 n1 cos(theta1) d`` (nm).
    wavenumber : numpy.ndarray
        ``2 pi / lambda`` (1/nm), the last axis of the result.

    Returns
    -------
    numpy.ndarray
        R with ``wavenumber``'s axis last.
    """
    psi = np.real(path)[..., None] * wavenumber
    decay = np.imag(path)[..., None]
    return _point(terms, need_sin, psi, np.exp(-decay * wavenumber) if np.any(decay) else None)


def airy_band_limited(
    terms: list[Term],
    need_sin: bool,
    path: np.ndarray,
    wl: np.ndarray,
    real_path: np.ndarray,
    harmonics: int,
) -> np.ndarray:
    """Return R bin-averaged at each wavelength, in [0, 1].

    ``R(delta)`` over one period is expanded into ``harmonics`` Fourier terms (an FFT)
    and each bin-averaged by :func:`~ocio_thinfilm.physics.sampling.cosine_series`;
    where ``real_path`` is False (evanescent or absorbing films, near-grazing rows the
    truncated series would not resolve) R is the pointwise :func:`airy_exact`.

    Parameters
    ----------
    terms, need_sin
        :func:`airy_terms`.
    path : numpy.ndarray
        The complex optical path ``2 n1 cos(theta1) d`` (nm).
    wl : numpy.ndarray
        Wavelengths (nm), the last axis of the result.
    real_path : numpy.ndarray
        Where the series holds (broadcast to ``path``'s shape).
    harmonics : int
        Fourier terms of the expansion.

    Returns
    -------
    numpy.ndarray
        R with ``wl``'s axis last.
    """
    phi_c, dphi = phase(np.real(path), wl, True)
    grid = 2.0 * np.pi * np.arange(harmonics) / harmonics
    samples = _point(terms, need_sin, np.broadcast_to(grid, np.shape(np.real(path)) + (harmonics,)))
    spectrum = np.fft.rfft(samples, axis=-1) / harmonics
    coefficients = [spectrum[..., 0].real] + [
        2.0 * spectrum[..., k] for k in range(1, harmonics // 2)
    ]
    smooth = cosine_series(coefficients, phi_c, dphi)
    if np.all(real_path):
        return np.clip(smooth, 0.0, 1.0)
    exact = airy_exact(terms, need_sin, path, 2.0 * np.pi / wl)
    return np.clip(np.where(real_path[..., None], smooth, exact), 0.0, 1.0)
