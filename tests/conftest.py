"""Shared fixtures and independent reference implementations for the tests.

Everything here is a *reference*: written from the textbook formulas (or taken from
colour-science), never copied from the code under test. Shared fixtures: ``cfg`` (the
committed config), ``colour`` (colour-science), ``gl`` (a headless OpenGL context),
``cxx`` (a C++ compiler), ``chromium`` (headless Chromium), ``load_benchmark``, ``marked``. What
tests and benchmarks share as importable code (the test-colour sets, applying a view as
a host does, decoding display code values) is the repository's ``evaluation`` package:
:mod:`evaluation.colours`, :mod:`evaluation.views`.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

# Property tests generate large numpy arrays per example: no per-example deadline,
# deterministic examples so CI runs are reproducible.
settings.register_profile(
    "core",
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
settings.load_profile("core")


@pytest.fixture(scope="session")
def load_benchmark():
    """``load_benchmark("bench_render")``: that script of benchmarks/ as a module, so a
    test can render the markdown it writes from the committed JSON."""
    import importlib.util
    from pathlib import Path

    def load(name):
        path = Path(__file__).resolve().parents[1] / "benchmarks" / f"{name}.py"
        spec = importlib.util.spec_from_file_location(name, path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        return module

    return load


def between(text: str, begin: str, end: str) -> str:
    """The stripped text between the markers ``begin`` and ``end`` of a document."""
    return text.split(begin, 1)[1].split(end, 1)[0].strip()


@pytest.fixture(scope="session")
def marked():
    """:func:`between` for the tests that compare a document's generated block."""
    return between


@pytest.fixture(scope="module")
def cfg():
    """The committed config (``configs/thinfilm``) as an OCIO Config, one per test module
    (its processor cache, LUTs included, goes with the module); skips where
    PyOpenColorIO or the baked config is missing."""
    ocio = pytest.importorskip("PyOpenColorIO")
    from evaluation.views import COMMITTED_CONFIG

    if not COMMITTED_CONFIG.exists():
        pytest.skip(f"{COMMITTED_CONFIG} not built (ocio-thinfilm bake)")
    return ocio.Config.CreateFromFile(str(COMMITTED_CONFIG))


@pytest.fixture(scope="session")
def gl():
    """The headless OpenGL context of :mod:`evaluation.gpu` (Mesa llvmpipe in CI); skips
    with the reason where there is none."""
    from evaluation import gpu

    try:
        return gpu.default_context()
    except RuntimeError as error:
        pytest.skip(f"no headless OpenGL context: {error}")


@pytest.fixture(scope="session")
def cxx():
    """The C++ compiler the exported DCTLs are built with; skips where there is none."""
    from evaluation.shaders import compiler

    name = compiler()
    if name is None:
        pytest.skip("no C++ compiler (g++) to build the DCTL with")
    return name


@pytest.fixture(scope="session")
def chromium():
    """Headless Chromium (:mod:`evaluation.browser`); skips where there is none."""
    from evaluation.browser import chromium as find

    path = find()
    if path is None:
        pytest.skip("no chromium (Debian's chromium package) to open the page with")
    return path


@pytest.fixture(scope="session")
def colour():
    import colour as colour_module

    return colour_module


def fresnel_R(n0, n2, theta_deg):
    """Unpolarised reflectance of one bare interface, n0 -> n2 (complex n2 allowed),
    at ``theta_deg`` in n0: ``(|r_s|^2 + |r_p|^2) / 2`` with Born & Wolf's amplitudes
    (Principles of Optics, 1.5 (21)), written out here."""
    s = n0 * np.sin(np.deg2rad(theta_deg))
    c0 = np.cos(np.deg2rad(theta_deg))
    c2 = np.sqrt(1 - (s / n2) ** 2 + 0j)
    rs = (n0 * c0 - n2 * c2) / (n0 * c0 + n2 * c2)
    rp = (n2 * c0 - n0 * c2) / (n2 * c0 + n0 * c2)
    return (abs(rs) ** 2 + abs(rp) ** 2) / 2


def colour_thin_film_R(n_stack, thickness, wavelengths, theta):
    """colour-science's TMM single film, unpolarised, reshaped to ours.

    ``colour.phenomena.thin_film_tmm`` returns (W, A, T, 2) for [R_s, R_p]; we
    average the polarisations and return (A, T, W) -- the layout our functions
    give for ``thickness[None, :]`` and ``theta[:, None]``.
    """
    import colour

    R, _ = colour.phenomena.thin_film_tmm(
        n_stack, np.atleast_1d(thickness), np.atleast_1d(wavelengths), np.atleast_1d(theta)
    )
    return np.transpose(R.mean(axis=-1), (1, 2, 0))


def colour_multilayer_R(n_stack, thicknesses, wavelengths, theta):
    """colour-science's ``multilayer_tmm``, unpolarised, shape (A, W)."""
    import colour

    R, _ = colour.phenomena.multilayer_tmm(
        n_stack, thicknesses, np.atleast_1d(wavelengths), np.atleast_1d(theta)
    )
    return np.transpose(R.mean(axis=-1)[:, :, 0], (1, 0))


def mp_airy_R(n0, n1, n2, d, wavelength, theta_deg, dps=40):
    """Unpolarised reflectance of one film, written out from Born & Wolf with mpmath.

    Snell's law in complex form, ``cos_j = sqrt(1 - (n0 sin(theta)/n_j)^2)`` on the
    branch with ``Im(n_j cos_j) >= 0`` (the wave decays into the medium: evanescent
    under total internal reflection, absorbing for Im(n) > 0), Fresnel amplitudes
    for s and p, and the Airy sum ``r = (r01 + r12 e^{2i beta}) / (1 + r01 r12 e^{2i
    beta})`` with ``beta = 2 pi n1 d cos_1 / lambda``. Evaluated at ``dps`` digits.
    """
    import mpmath as mp

    with mp.workdps(dps):
        n0, n1, n2 = mp.mpc(n0), mp.mpc(n1), mp.mpc(n2)
        theta = mp.radians(mp.mpf(theta_deg))
        s0 = n0 * mp.sin(theta)

        def cosine(n):
            c = mp.sqrt(1 - (s0 / n) ** 2)
            nc = n * c
            if mp.im(nc) < 0 or (mp.im(nc) == 0 and mp.re(nc) < 0):
                c = -c
            return c

        c0, c1, c2 = mp.cos(theta), cosine(n1), cosine(n2)

        def fresnel(na, ca, nb, cb):
            den_s = na * ca + nb * cb
            den_p = nb * ca + na * cb
            rs = (na * ca - nb * cb) / den_s if den_s != 0 else mp.mpc(0)
            rp = (nb * ca - na * cb) / den_p if den_p != 0 else mp.mpc(0)
            return rs, rp

        beta = 2 * mp.pi * n1 * mp.mpf(d) * c1 / mp.mpf(wavelength)
        z = mp.exp(2j * beta)
        total = mp.mpf(0)
        for a, b in zip(fresnel(n0, c0, n1, c1), fresnel(n1, c1, n2, c2), strict=True):
            total += abs((a + b * z) / (1 + a * b * z)) ** 2
        return float(total / 2)
