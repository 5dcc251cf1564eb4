"""Test inputs shared by several sections (seeded: the same in every run)."""

from __future__ import annotations

import numpy as np

from ocio_thinfilm.colour import colorimetry

__all__ = ["test_thicknesses", "lut_test_sets", "INTERFERENCE", "MIXTURES"]

INTERFERENCE = "interference colours"
MIXTURES = "spectral mixtures (Y 0.01-0.99)"


def test_thicknesses(q, hi_um=1.5, n=None):
    """``n`` random optical thicknesses in [0, ``hi_um``] µm (4000 / 40000 by default)."""
    rng = np.random.default_rng(11)
    n = n or (4000 if q else 40000)
    return rng.uniform(0.0, hi_um, n)


def lut_test_sets(q) -> dict:
    """XYZ test colours: interference colours, and spectral mixtures (up to three
    spectral lines, mostly near-monochromatic, at luminances 0.01-0.99: extreme
    inputs, mostly outside the object-colour solid). Keys: :data:`INTERFERENCE`,
    :data:`MIXTURES`."""
    rng = np.random.default_rng(7)
    t = rng.uniform(0.0, 1500.0, 3000 if q else 20000)
    interference = np.concatenate(
        [
            colorimetry.film_XYZ(t),
            colorimetry.film_XYZ(t, kind="no-phase-change"),
            colorimetry.morpho_XYZ(rng.uniform(0.0, 89.0, 1000 if q else 5000)),
        ]
    )
    locus = colorimetry.spectral_locus_XYZ(1.0, np.arange(400.0, 701.0, 5.0))
    n = 5000 if q else 40000
    w = rng.dirichlet(np.full(3, 0.3), n)
    picks = rng.integers(0, locus.shape[0], (n, 3))
    mix = np.einsum("nk,nkc->nc", w, locus[picks])
    mix = mix / mix[:, 1:2] * rng.uniform(0.01, 0.99, (n, 1))
    return {INTERFERENCE: interference, MIXTURES: mix}
