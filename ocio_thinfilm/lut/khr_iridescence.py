"""What a glTF viewer draws for ``KHR_materials_iridescence``: three.js r187's model in numpy.

glTF carries one film, ``KHR_materials_iridescence``: a dielectric layer of index
``iridescenceIor`` and thickness ``d`` nm over the material's base. three.js (r187,
``iridescence_fragment``, ``lights_fragment_begin``, ``lights_physical_pars_fragment``)
evaluates it with Belcour & Barla's (2017) Airy sum: Schlick's Fresnel at both interfaces
(``F_Schlick``: Epic's ``exp2`` form of ``(1 - cos)^5``)
(the base's index from its F0 as if it were seen from air), phase flips by comparing
indices, two harmonics of the optical path difference through Gaussian fits of the CIE
XYZ sensitivities (an implicit illuminant E) and sRGB's matrix, clamped at 0. The
material then mixes that Fresnel into its specular term:

- ``F0_i = Schlick_to_F0(I, 1, N·V)``, ``Fr = mix(F0_base, F0_i, iridescenceFactor)``, and
  image-based light takes ``Fr · f_a + f_b`` (the split-sum DFG terms; for a mirror,
  roughness 0, ``f_a = 1 - (1 - N·V)^5``, ``f_b = (1 - N·V)^5``);
- the dielectric lobe uses ``F0_base = ((ior - 1) / (ior + 1))^2`` (``KHR_materials_ior``),
  the metallic lobe the base colour, mixed by ``metalness``;
- a thickness of exactly 0 switches the film off.

:func:`iridescence_fresnel` is ``evalIridescence``; :func:`mirror_reflectance` the
specular reflectance of a mirror (roughness 0) under a uniform environment of radiance 1,
for a base of black diffuse colour or metalness 1 (no diffuse lobe) -- what a viewer
shows for a film whose substrate is in the film. Linear Rec.709 RGB.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import reproducible

__all__ = [
    "XYZ_TO_REC709",
    "KHRIridescence",
    "DEFAULT_IRIDESCENCE",
    "eval_sensitivity",
    "iridescence_fresnel",
    "schlick_to_f0",
    "mirror_reflectance",
    "mirror_transmittance",
]

#: three.js's ``XYZ_TO_REC709`` (row-major here; the GLSL ``mat3`` lists its columns).
XYZ_TO_REC709 = np.array(
    [
        [3.2404542, -1.5371385, -0.4985314],
        [-0.9692660, 1.8760108, 0.0415560],
        [0.0556434, -0.2040259, 1.0572252],
    ]
)


@dataclass(frozen=True)
class KHRIridescence:
    """A glTF material's film and base, as ``KHR_materials_iridescence`` and ``_ior`` say.

    ``ior``: the film's ``iridescenceIor``; ``thickness_nm``: ``iridescenceThicknessMinimum``
    and ``Maximum`` (the thickness texture's G channel maps [0, 1] onto them); ``factor``:
    ``iridescenceFactor``; ``base_ior``: the material's ``KHR_materials_ior``; ``metalness``
    and ``base_colour`` (linear RGB): ``pbrMetallicRoughness``; ``transmission``:
    ``KHR_materials_transmission``'s ``transmissionFactor`` (0: none; thin-walled, no
    ``KHR_materials_volume``).
    """

    ior: float = 1.3
    thickness_nm: tuple[float, float] = (100.0, 400.0)
    factor: float = 1.0
    base_ior: float = 1.5
    metalness: float = 0.0
    base_colour: tuple[float, float, float] = (0.0, 0.0, 0.0)
    transmission: float = 0.0

    def thickness(self, g: npt.ArrayLike) -> np.ndarray:
        """Return the film thickness (nm) at the thickness texture's value ``g``."""
        lo, hi = self.thickness_nm
        return (hi - lo) * np.asarray(g, dtype=np.float64) + lo


#: The extension's defaults (``iridescenceIor`` 1.3, 100-400 nm, factor 1) on glTF's
#: default dielectric (ior 1.5) with a black base colour.
DEFAULT_IRIDESCENCE = KHRIridescence()


def eval_sensitivity(opd_nm: npt.ArrayLike, shift: npt.ArrayLike) -> np.ndarray:
    """Return three.js's ``evalSensitivity``: the Fourier-space XYZ fit, as linear Rec.709.

    Parameters
    ----------
    opd_nm : array_like
        Optical path difference (nm), shape ``S``.
    shift : array_like
        Phase shift per channel, shape ``S + (3,)``.

    Returns
    -------
    numpy.ndarray
        Shape ``S + (3,)``.
    """
    phase = 2.0 * np.pi * np.asarray(opd_nm, dtype=np.float64)[..., None] * 1.0e-9
    shift = np.asarray(shift, dtype=np.float64)
    val = np.array([5.4856e-13, 4.4201e-13, 5.2481e-13])
    pos = np.array([1.6810e06, 1.7953e06, 2.2084e06])
    var = np.array([4.3278e09, 9.3046e09, 6.6121e09])
    xyz = val * np.sqrt(2.0 * np.pi * var) * np.cos(pos * phase + shift) * np.exp(-(phase**2) * var)
    extra = (
        9.7470e-14
        * np.sqrt(2.0 * np.pi * 4.5282e09)
        * np.cos(2.2399e06 * phase[..., 0] + shift[..., 0])
        * np.exp(-4.5282e09 * phase[..., 0] ** 2)
    )
    xyz = np.concatenate([(xyz[..., 0] + extra)[..., None], xyz[..., 1:]], axis=-1) / 1.0685e-7
    return reproducible.matmul(xyz, XYZ_TO_REC709.T)


def _schlick(f0: np.ndarray, cos_theta: np.ndarray) -> np.ndarray:
    # three.js's F_Schlick: Epic's (SIGGRAPH 2013) exp2 form of (1 - cos)^5
    fresnel = np.exp2((-5.55473 * cos_theta - 6.98316) * cos_theta)
    return f0 * (1.0 - fresnel) + fresnel


def iridescence_fresnel(
    film_ior: float, cos_theta: npt.ArrayLike, thickness_nm: npt.ArrayLike, base_f0: npt.ArrayLike
) -> np.ndarray:
    """Return three.js's ``evalIridescence(1, film_ior, cos_theta, thickness, base_f0)``.

    Parameters
    ----------
    film_ior : float
        ``iridescenceIor``.
    cos_theta : array_like
        N·V, shape ``S`` (broadcast with ``thickness_nm``).
    thickness_nm : array_like
        The film's thickness (nm).
    base_f0 : array_like
        The base's F0 (3 values, or broadcasting to ``S + (3,)``).

    Returns
    -------
    numpy.ndarray
        The film's Fresnel reflectance, linear Rec.709, ``>= 0``, shape ``S + (3,)``.
    """
    c1, d = np.broadcast_arrays(
        np.asarray(cos_theta, dtype=np.float64), np.asarray(thickness_nm, dtype=np.float64)
    )
    base_f0 = np.asarray(base_f0, dtype=np.float64)
    # smoothstep(0, 0.03, d): the film's index tends to the outside's as d -> 0
    s = np.clip(d / 0.03, 0.0, 1.0)
    eta = 1.0 + (film_ior - 1.0) * (s * s * (3.0 - 2.0 * s))
    cos2_sq = 1.0 - (1.0 / eta) ** 2 * (1.0 - c1**2)
    c2 = np.sqrt(np.maximum(cos2_sq, 0.0))
    R12 = _schlick(((eta - 1.0) / (eta + 1.0)) ** 2, c1)
    T121 = 1.0 - R12
    phi21 = np.where(eta < 1.0, 0.0, np.pi)
    sqrt_f0 = np.sqrt(np.clip(base_f0, 0.0, 0.9999))
    base_ior = (1.0 + sqrt_f0) / (1.0 - sqrt_f0)
    eta3 = eta[..., None]
    R23 = _schlick(((base_ior - eta3) / (base_ior + eta3)) ** 2, c2[..., None])
    phi = phi21[..., None] + np.where(base_ior < eta3, np.pi, 0.0)
    opd = 2.0 * eta * d * c2
    R123 = np.clip(R12[..., None] * R23, 1e-5, 0.9999)
    r123 = np.sqrt(R123)
    Rs = T121[..., None] ** 2 * R23 / (1.0 - R123)
    intensity = R12[..., None] + Rs
    Cm = Rs - T121[..., None]
    for m in (1, 2):
        Cm = Cm * r123
        intensity = intensity + Cm * 2.0 * eval_sensitivity(m * opd, m * phi)
    intensity = np.maximum(intensity, 0.0)
    return np.where(cos2_sq[..., None] < 0.0, 1.0, intensity)


def schlick_to_f0(f: npt.ArrayLike, cos_theta: npt.ArrayLike) -> np.ndarray:
    """Return three.js's ``Schlick_to_F0(f, 1, cos_theta)``.

    The F0 whose Schlick curve is ``f`` at ``cos_theta`` (``f`` shape ``S + (3,)``,
    ``cos_theta`` shape ``S``).
    """
    x = np.clip(1.0 - np.asarray(cos_theta, dtype=np.float64), 0.0, 1.0)[..., None]
    x5 = np.clip(x**5, 0.0, 0.9999)
    return (np.asarray(f, dtype=np.float64) - x5) / (1.0 - x5)


def _lobe(
    model: KHRIridescence, base_f0: np.ndarray, c: np.ndarray, d: np.ndarray, fab: np.ndarray
) -> np.ndarray:
    fa, fb = fab[..., 0:1], fab[..., 1:2]
    factor = np.where(d == 0.0, 0.0, np.clip(model.factor, 0.0, 1.0))[..., None]
    fresnel = iridescence_fresnel(model.ior, c, d, base_f0)
    fr = base_f0 + (schlick_to_f0(fresnel, c) - base_f0) * factor
    # computeMultiscatteringIridescence (Fdez-Aguera 2019), uniform light of radiance 1
    single = fr * fa + fb
    ems = 1.0 - (fa + fb)
    favg = fr + (1.0 - fr) * 0.047619
    return single + single * favg / (1.0 - ems * favg) * ems


def mirror_reflectance(
    model: KHRIridescence,
    g: npt.ArrayLike,
    cos_theta: npt.ArrayLike,
    fab: npt.ArrayLike | None = None,
) -> np.ndarray:
    """Return what three.js shows of a mirror with the film under a uniform white light.

    The specular reflectance (roughness 0: the split-sum terms of a mirror, no
    multiple-scattering gain) of the material ``model`` at the thickness texture value
    ``g`` and N·V ``cos_theta``; the diffuse lobe is left out (black base colour or
    metalness 1).

    Parameters
    ----------
    model : KHRIridescence
        The material.
    g, cos_theta : array_like
        Thickness texture values in [0, 1] and N·V (broadcast together).
    fab : array_like, optional
        The split-sum terms ``(f_a, f_b)`` (three.js's ``dfgLUT`` at the pixel's
        roughness), shape ``broadcast shape + (2,)``; default a mirror's,
        ``(1 - x^5, x^5)`` with ``x = 1 - N·V``, where the multiple-scattering term is 0.

    Returns
    -------
    numpy.ndarray
        Linear Rec.709 RGB, shape ``broadcast shape + (3,)``.

    Examples
    --------
    Without a film (factor 0) a dielectric of ior 1.5 shows Schlick's 0.04 head-on:

    >>> from dataclasses import replace
    >>> plain = replace(DEFAULT_IRIDESCENCE, factor=0.0)
    >>> mirror_reflectance(plain, 0.5, 1.0).round(6).tolist()
    [0.04, 0.04, 0.04]
    """
    g_arr, c = np.broadcast_arrays(
        np.asarray(g, dtype=np.float64), np.clip(np.asarray(cos_theta, dtype=np.float64), 0, 1)
    )
    d = model.thickness(g_arr)
    if fab is None:
        x5 = (1.0 - c) ** 5
        terms = np.stack([1.0 - x5, x5], axis=-1)
    else:
        terms = np.broadcast_to(np.asarray(fab, dtype=np.float64), c.shape + (2,))
    f0 = ((model.base_ior - 1.0) / (model.base_ior + 1.0)) ** 2
    out = np.zeros(c.shape + (3,))
    if model.metalness < 1.0:
        out = out + (1.0 - model.metalness) * _lobe(model, np.full(3, f0), c, d, terms)
    if model.metalness > 0.0:
        base = np.asarray(model.base_colour, dtype=np.float64)
        out = out + model.metalness * _lobe(model, base, c, d, terms)
    return out


def mirror_transmittance(
    model: KHRIridescence, cos_theta: npt.ArrayLike, fab: npt.ArrayLike | None = None
) -> np.ndarray:
    """Return what three.js r187 transmits of the background through a thin-walled mirror.

    ``transmission_fragment`` / ``getIBLVolumeRefraction`` with ``KHR_materials_transmission``
    and no volume (thickness 0: the pixel straight behind): the background times
    ``transmission (1 - metalness) base_colour (1 - F)``, ``F = F0 f_a + f_b`` the split-sum
    Fresnel of the base's own F0 (``KHR_materials_ior``). The iridescence does not reach
    it: three.js weighs the transmitted light by the base's Schlick Fresnel only. The
    transmitted light replaces the diffuse lobe (``mix(diffuse, transmitted,
    transmission)``), which :func:`mirror_reflectance` leaves out.

    Parameters
    ----------
    model : KHRIridescence
        The material.
    cos_theta : array_like
        N·V.
    fab : array_like, optional
        The split-sum terms, as for :func:`mirror_reflectance` (default a mirror's).

    Returns
    -------
    numpy.ndarray
        The factor on the background's linear Rec.709 RGB, shape ``cos_theta.shape + (3,)``.

    Examples
    --------
    >>> from dataclasses import replace
    >>> clear = replace(DEFAULT_IRIDESCENCE, transmission=1.0, base_colour=(1.0, 1.0, 1.0))
    >>> mirror_transmittance(clear, 1.0).round(6).tolist()
    [0.96, 0.96, 0.96]
    """
    c = np.clip(np.asarray(cos_theta, dtype=np.float64), 0.0, 1.0)
    if fab is None:
        x5 = (1.0 - c) ** 5
        terms = np.stack([1.0 - x5, x5], axis=-1)
    else:
        terms = np.broadcast_to(np.asarray(fab, dtype=np.float64), c.shape + (2,))
    f0 = ((model.base_ior - 1.0) / (model.base_ior + 1.0)) ** 2
    fresnel = f0 * terms[..., 0] + terms[..., 1]
    weight = model.transmission * (1.0 - model.metalness) * (1.0 - fresnel)
    return weight[..., None] * np.asarray(model.base_colour, dtype=np.float64)
