"""Peer algorithms the report compares against (implemented here, cited; not part of the
shipped pipeline).

- :func:`belcour_barla_sensitivity`, :func:`belcour_barla_film_XYZ`: the Gaussian fits of
  the CIE 1931 matching functions in Fourier space (Belcour & Barla 2017) that the
  Khronos glTF sample viewer and MaterialX use for thin-film iridescence.
- :func:`oklch_gamut_map_RGB`: the CSS Color 4 gamut mapping (binary search on the
  chroma in OKLCh), with Björn Ottosson's Oklab from colour-science.

References
----------
- Belcour, L., Barla, P. (2017). A Practical Extension to Microfacet Theory for the
  Modeling of Varying Iridescence. ACM Transactions on Graphics 36(4), 65. The Gaussian
  fits as shipped in the Khronos glTF sample viewer
  (``source/Renderer/shaders/iridescence.glsl``, ``evalSensitivity``) and MaterialX
  (``libraries/pbrlib/genglsl/lib/mx_microfacet_specular.glsl``, ``mx_eval_sensitivity``).
- W3C CSS Color Module Level 4, section 13.2 "CSS Gamut Mapping to an RGB Destination"
  (binary search in OKLCh, JND 0.02 in deltaEOK, epsilon 0.0001).
- Ottosson, B. (2020). A perceptual color space for image processing (Oklab).
  https://bottosson.github.io/posts/oklab/
"""

from __future__ import annotations

import warnings

import numpy as np

from ocio_thinfilm.colour import colorimetry

__all__ = ["belcour_barla_sensitivity", "belcour_barla_film_XYZ", "oklch_gamut_map_RGB"]


def belcour_barla_sensitivity(opd_nm, shift=0.0):
    """Belcour & Barla (2017) Gaussian fit of the CIE XYZ sensitivities in Fourier space.

    The fitted, normalised ``integral cmf(nu) cos(2 pi OPD nu + shift) dnu`` of the
    CIE 1931 matching functions over wavenumber ``nu``; ``S(0, 0) = (1, 1, 1)``
    (equal-energy white). The constants are those of ``evalSensitivity`` in the Khronos
    glTF sample viewer's ``iridescence.glsl`` (identical to MaterialX's
    ``mx_eval_sensitivity``): three Gaussians (``val``, ``pos``, ``var``) plus a second
    lobe for X, divided by 1.0685e-7.

    Parameters
    ----------
    opd_nm : array_like
        Optical path difference in nm, any shape.
    shift : float or array_like, optional
        Phase shift in radians, a scalar, one per channel (shape ``(3,)``) or
        broadcastable to ``opd.shape + (3,)``.

    Returns
    -------
    numpy.ndarray
        ``S(OPD, shift)``, float64, shape ``opd.shape + (3,)``.

    References
    ----------
    Belcour, L., Barla, P. (2017). A Practical Extension to Microfacet Theory for the
    Modeling of Varying Iridescence. ACM Transactions on Graphics 36(4), 65.
    """
    opd = np.asarray(opd_nm, dtype=np.float64)[..., None]
    shift = (
        np.broadcast_to(np.asarray(shift, dtype=np.float64), (3,))
        if np.ndim(shift) <= 1
        else np.asarray(shift, dtype=np.float64)
    )
    phase = 2.0 * np.pi * opd * 1.0e-9
    val = np.array([5.4856e-13, 4.4201e-13, 5.2481e-13])
    pos = np.array([1.6810e06, 1.7953e06, 2.2084e06])
    var = np.array([4.3278e09, 9.3046e09, 6.6121e09])
    xyz = val * np.sqrt(2.0 * np.pi * var) * np.cos(pos * phase + shift) * np.exp(-(phase**2) * var)
    xyz[..., 0] += (
        9.7470e-14
        * np.sqrt(2.0 * np.pi * 4.5282e09)
        * np.cos(2.2399e06 * phase[..., 0] + shift[..., 0])
        * np.exp(-4.5282e09 * phase[..., 0] ** 2)
    )
    return xyz / 1.0685e-7


def belcour_barla_film_XYZ(optical_thickness_nm, phase_change: bool = True):
    """XYZ of the paper's normalised two-beam film (Eq. 7/8) the Belcour & Barla way.

    ``R = 1/2 (1 + cos(phi + shift))`` with ``phi = 2 pi OPD / lambda`` and
    ``OPD = 2 t'`` integrates to ``1/2 (S(0, 0) + S(OPD, shift))``, with ``S`` from
    :func:`belcour_barla_sensitivity`; ``shift = pi`` with a phase change (Eq. 7).

    Parameters
    ----------
    optical_thickness_nm : array_like
        Optical thickness ``t'`` in nm, any shape.
    phase_change : bool, optional
        True for the soap film (Eq. 7, a half-wave phase change at one interface),
        False for the film on glass (Eq. 8).

    Returns
    -------
    numpy.ndarray
        XYZ with equal-energy white = 1, float64, shape ``t.shape + (3,)``.

    References
    ----------
    Belcour, L., Barla, P. (2017), see :func:`belcour_barla_sensitivity`;
    Smits, B. E., Meyer, G. W. (1990). Newton's Colors, Eq. 7 and 8.
    """
    opd = 2.0 * np.asarray(optical_thickness_nm, dtype=np.float64)
    shift = np.pi if phase_change else 0.0
    return 0.5 * (
        belcour_barla_sensitivity(np.zeros_like(opd)) + belcour_barla_sensitivity(opd, shift)
    )


def _oklab(xyz):
    """XYZ -> Oklab (Ottosson 2020) through colour-science."""
    import colour

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return colour.XYZ_to_Oklab(xyz)


def _oklab_to_xyz(lab):
    """Oklab -> XYZ (Ottosson 2020) through colour-science."""
    import colour

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return colour.Oklab_to_XYZ(lab)


def oklch_gamut_map_RGB(RGB, display: str = "sRGB", jnd: float = 0.02, epsilon: float = 1e-4):
    """CSS Color 4 gamut mapping (section 13.2) of display-linear RGB, vectorised.

    In OKLCh: L >= 1 gives white, L <= 0 black; in-gamut colours pass; otherwise hold
    L and h and bisect the chroma until ``deltaEOK(clip(current), current) < jnd``
    (the binary search with the "min_inGamut" shortcut and the ``jnd - E < epsilon``
    early exit of the spec), returning the clipped colour. All pixels advance
    together; each is frozen once its own search has ended. Oklab conversions come
    from colour-science.

    Parameters
    ----------
    RGB : array_like
        Display-linear RGB, shape ``(..., 3)``.
    display : str, optional
        The display whose primaries define the gamut (see
        :func:`ocio_thinfilm.colour.colorimetry.matrix_XYZ_to_RGB`).
    jnd : float, optional
        The just-noticeable difference in deltaEOK (the spec's 0.02).
    epsilon : float, optional
        The chroma resolution of the search (the spec's 0.0001).

    Returns
    -------
    numpy.ndarray
        Gamut-mapped RGB in [0, 1], float64, the shape of ``RGB``.

    References
    ----------
    W3C CSS Color Module Level 4, section 13.2 "CSS Gamut Mapping to an RGB
    Destination". Ottosson, B. (2020). A perceptual color space for image processing.
    """
    M = colorimetry.matrix_XYZ_to_RGB(display)
    Minv = np.linalg.inv(M)
    rgb = np.asarray(RGB, dtype=np.float64)
    shape = rgb.shape
    rgb = rgb.reshape(-1, 3)
    lab = _oklab(rgb @ Minv.T)
    L = lab[:, 0]
    C = np.hypot(lab[:, 1], lab[:, 2])
    h = np.arctan2(lab[:, 2], lab[:, 1])
    out = rgb.copy()
    inside = np.all((rgb >= 0) & (rgb <= 1), axis=1)
    clipped = np.clip(rgb, 0.0, 1.0)
    E = np.linalg.norm(_oklab(clipped @ Minv.T) - lab, axis=1)
    out[~inside] = clipped[~inside]
    active = ~inside & (E >= jnd) & (L > 0) & (L < 1)
    out[L >= 1] = 1.0
    out[L <= 0] = 0.0
    idx = np.flatnonzero(active)
    lo = np.zeros(idx.size)
    hi = C[idx].copy()
    min_in = np.ones(idx.size, bool)
    last = clipped[idx].copy()
    running = np.ones(idx.size, bool)
    Li, hi_h = L[idx], h[idx]
    while True:
        running &= (hi - lo) > epsilon
        if not running.any():
            break
        r = np.flatnonzero(running)
        chroma = 0.5 * (lo[r] + hi[r])
        cur_lab = np.stack([Li[r], chroma * np.cos(hi_h[r]), chroma * np.sin(hi_h[r])], axis=1)
        cur = _oklab_to_xyz(cur_lab) @ M.T
        ing = np.all((cur >= 0) & (cur <= 1), axis=1)
        shortcut = min_in[r] & ing
        lo[r[shortcut]] = chroma[shortcut]
        rest = ~shortcut
        rr = r[rest]
        cl = np.clip(cur[rest], 0.0, 1.0)
        e = np.linalg.norm(_oklab(cl @ Minv.T) - cur_lab[rest], axis=1)
        last[rr] = cl
        good = e < jnd
        finish = good & ((jnd - e) < epsilon)
        running[rr[finish]] = False
        cont = good & ~finish
        min_in[rr[cont]] = False
        lo[rr[cont]] = chroma[rest][cont]
        hi[rr[~good]] = chroma[rest][~good]
    out[idx] = last
    return out.reshape(shape)
