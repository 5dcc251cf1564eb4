"""Test colours for evaluating the tables and the clip LUTs (not part of the shipped path).

The tests, the benchmarks and the report measure the LUTs against these sets; nothing
that builds a table, a LUT or the config imports this module.

- :func:`object_colours`: object and interference colours (random smooth reflectances,
  the ColorCheckers, the real Munsell colours, the two film kinds and the Morpho
  multilayer), CIE-XYZ-D65 with Y <= 1.
- :func:`spectral_colours`: monochromatic colours at a range of luminances.
- :func:`spectral_mixtures`: mixtures of one to three spectral lines up to Y = 0.99
  (saturated emissive colours: lasers, neon, LEDs), a quarter of them at Y >= 0.95.
- :func:`gamut_map_sets`: the gamut maps' test sets by name.
- :func:`ap0_below_white`: many random colours inside ACES AP0 with 0 <= Y < 1.
- :func:`half_way_colours`: colours of a display at most a given fraction of the way
  from their grey to the gamut boundary along the paper's ray (Smits & Meyer 1990,
  Section 3.2), found with colour-science's primaries (independent of the package).
"""

from __future__ import annotations

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.colour import colorimetry

__all__ = [
    "object_colours",
    "spectral_colours",
    "spectral_mixtures",
    "gamut_map_sets",
    "ap0_below_white",
    "half_way_colours",
]


def object_colours(seed: int = 0, n_random: int = 4000) -> np.ndarray:
    """A set of object colours (CIE-XYZ-D65, reflectances under D65, Y <= 1):

    ``n_random`` random smooth reflectance spectra (three Gaussian bumps on a
    random base, clipped to [0, 1], scaled), the ColorChecker sets of colour-science,
    the measured ("real") Munsell renotation colours, and the interference colours of
    the two film kinds (0-3 um, 3000 each) and of the Morpho multilayer (500 angles).
    """
    import colour
    from colour.notation.datasets.munsell import MUNSELL_COLOURS_REAL

    rng = np.random.default_rng(seed)
    wl = np.arange(360.0, 781.0, 5.0)
    R = np.zeros((n_random, wl.size))
    for _ in range(3):
        centre = rng.uniform(380, 720, n_random)[:, None]
        width = rng.uniform(10, 120, n_random)[:, None]
        amplitude = rng.uniform(-1, 1.2, n_random)[:, None]
        R += amplitude * np.exp(-0.5 * ((wl - centre) / width) ** 2)
    R = np.clip(R + rng.uniform(0, 0.6, n_random)[:, None], 0, 1)
    R *= rng.uniform(0.05, 1, n_random)[:, None]
    random_XYZ = colorimetry.reflectance_to_XYZ(R, wl)
    shape = colour.SpectralShape(360, 780, 5)
    checker = []
    for name in sorted(colour.SDS_COLOURCHECKERS):
        for sd in colour.SDS_COLOURCHECKERS[name].values():
            checker.append(
                colour.sd_to_XYZ(sd.copy().align(shape), illuminant=colour.SDS_ILLUMINANTS["D65"])
                / 100
            )
    munsell = np.array([v[1] for v in MUNSELL_COLOURS_REAL], dtype=np.float64)
    munsell[:, 2] /= 100.0
    munsell = colour.xyY_to_XYZ(munsell[munsell[:, 2] <= 1.0])
    t = np.linspace(0.0, 3000.0, 3000)
    films = np.concatenate(
        [
            colorimetry.film_XYZ(t, "phase-change"),
            colorimetry.film_XYZ(t, "no-phase-change"),
            colorimetry.morpho_XYZ(np.linspace(0.0, 89.0, 500)),
        ]
    )
    return np.concatenate([random_XYZ, np.array(checker), munsell, films])


def spectral_colours(max_Y: float = 0.6, levels: int = 60) -> np.ndarray:
    """Monochromatic colours 380-700 nm at ``levels`` luminances in (0, max_Y]."""
    Ys = np.linspace(max_Y / levels, max_Y, levels)
    return np.concatenate([colorimetry.spectral_locus_XYZ(Y) for Y in Ys])


def spectral_mixtures(n: int = 20000, seed: int = 3, max_Y: float = 0.99) -> np.ndarray:
    """``n`` mixtures of one to three monochromatic lines (380-700 nm, random
    weights), CIE-XYZ-D65 scaled to a random Y in (0, max_Y]; a quarter of them at
    Y in [0.95, max_Y], where the clip bends every colour towards white."""
    rng = np.random.default_rng(seed)
    locus = colorimetry.spectral_locus_XYZ(1.0, np.arange(380.0, 701.0))
    lines = rng.integers(1, 4, n)
    XYZ = np.zeros((n, 3))
    for k in range(3):
        weight = rng.uniform(0.0, 1.0, n) * (k < lines)
        XYZ += weight[:, None] * locus[rng.integers(0, len(locus), n)]
    Y = max_Y * rng.uniform(0.0, 1.0, n) ** 0.5
    Y[: n // 4] = rng.uniform(0.95, max_Y, n // 4)
    return XYZ / XYZ[:, 1:2] * Y[:, None]


def gamut_map_sets() -> dict:
    """The gamut maps' test sets (CIE-XYZ-D65), by name: ``object`` (object and
    interference colours, :func:`object_colours`), ``monochromatic`` (380-700 nm at
    Y = 0.02, 0.1, 0.3, 0.6), ``ap0`` (20,000 random colours inside ACES AP0 with
    0 <= Y <= 1) and ``mixtures`` (:func:`spectral_mixtures`)."""
    rng = np.random.default_rng(7)
    ap0_to_xyz = np.linalg.inv(colorimetry.matrix_XYZ_to_RGB("ACES2065-1"))
    ap0 = rng.uniform(0.0, 1.0, (60000, 3)) @ ap0_to_xyz.T
    ap0 = ap0[(ap0[:, 1] >= 0.0) & (ap0[:, 1] <= 1.0)][:20000]
    locus = np.concatenate(
        [colorimetry.spectral_locus_XYZ(Y, np.arange(380.0, 701.0)) for Y in (0.02, 0.1, 0.3, 0.6)]
    )
    return {
        "object": object_colours(),
        "monochromatic": locus,
        "ap0": ap0,
        "mixtures": spectral_mixtures(),
    }


def ap0_below_white(n: int = 200000, seed: int = 123) -> np.ndarray:
    """``n`` random colours inside ACES AP0 (uniform in AP0 RGB) with 0 <= Y < 1,
    CIE-XYZ-D65: ten times :func:`gamut_map_sets`' ``ap0`` and another seed, so the
    largest errors of a gamut map's LUT (in the corners beyond the display's primaries)
    are found."""
    rng = np.random.default_rng(seed)
    ap0_to_xyz = np.linalg.inv(colorimetry.matrix_XYZ_to_RGB("ACES2065-1"))
    out = []
    while sum(len(a) for a in out) < n:
        xyz = rng.uniform(0.0, 1.0, (2 * n, 3)) @ ap0_to_xyz.T
        out.append(xyz[(xyz[:, 1] >= 0.0) & (xyz[:, 1] < 1.0)])
    return np.concatenate(out)[:n]


def colour_science_RGB_to_XYZ(display: str) -> np.ndarray:
    """Display-linear RGB -> CIE XYZ (D65) matrix from colour-science's primaries and
    white for ``display`` (a display or gamut name), Bradford adapted to D65 where its
    white is another (DCI): RGB (1, 1, 1) is the D65 white."""
    import colour

    cs = colour.RGB_COLOURSPACES[registry.RGB_COLORIMETRY[registry.colorimetry_of(display)]]
    npm = colour.normalised_primary_matrix(cs.primaries, cs.whitepoint)
    d65 = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    cat = colour.adaptation.matrix_chromatic_adaptation_VonKries(
        colour.xy_to_XYZ(cs.whitepoint), colour.xy_to_XYZ(d65), transform="Bradford"
    )
    return cat @ npm


def half_way_colours(
    display: str, n: int = 40000, seed: int = 11, reach: float = 0.5
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``n`` colours of ``display`` at most ``reach`` of the way from their grey to the
    gamut boundary along the ray of Smits & Meyer (1990), Section 3.2 (towards the grey
    of the same luminance Y), with Y uniform in (0.0005, 0.999) and the direction and
    the fraction of the way uniform at random.

    Independent of the package: the luminance weights come from colour-science's
    primaries and white point, the boundary from a bisection along the ray against the
    unit cube.

    Returns
    -------
    tuple of numpy.ndarray
        (display-linear RGB (n, 3), Y (n,), the fraction of the way t (n,)); the grey
        of each colour is (Y, Y, Y).
    """

    w = colour_science_RGB_to_XYZ(display)[1]
    rng = np.random.default_rng(seed)
    Y = rng.uniform(0.0005, 0.999, n)
    direction = rng.normal(size=(n, 3))
    direction -= (direction @ w)[:, None] / w.sum()  # keeps Y
    lo, hi = np.zeros(n), np.full(n, 1e6)  # the largest s with Y + s direction inside
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        p = Y[:, None] + mid[:, None] * direction
        inside = np.all((p >= 0.0) & (p <= 1.0), axis=1)
        lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    t = rng.uniform(0.0, reach, n)
    return Y[:, None] + (t * lo)[:, None] * direction, Y, t
