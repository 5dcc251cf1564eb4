"""Perlin gradient noise and turbulence (ocio_thinfilm.render.noise)."""

import numpy as np
import pytest

from ocio_thinfilm.render import noise


def _grid(n=256, scale=1 / 16):
    y, x = np.mgrid[0:n, 0:n].astype(np.float32) * np.float32(scale)
    return x, y


def test_zero_on_the_lattice_and_bounded():
    i = np.arange(-5, 300, dtype=np.float64)
    assert np.all(noise.noise(i, i * 0 + 3) == 0)
    assert np.all(noise.noise(i, i, i) == 0)
    x, y = _grid(512, 1 / 7.3)
    n = noise.noise(x, y)
    assert n.dtype == np.float32 and n.shape == x.shape
    assert -1.0 <= n.min() < -0.5 and 0.5 < n.max() <= 1.0
    assert abs(float(n.mean())) < 0.02


@pytest.mark.parametrize("dims", [1, 2, 3])
def test_deterministic_per_seed_and_independent_between_seeds(dims):
    rng = np.random.default_rng(3)
    pts = [rng.uniform(-50, 50, 4000) for _ in range(dims)]
    a = noise.noise(*pts, seed=7)
    b = noise.noise(*pts, seed=7)
    c = noise.noise(*pts, seed=8)
    assert a.tobytes() == b.tobytes()
    assert abs(np.corrcoef(a, c)[0, 1]) < 0.1


def test_periodic_and_continuous():
    x, y = _grid(64, 1 / 9.1)
    assert np.allclose(noise.noise(x + 256, y - 512), noise.noise(x, y), atol=1e-4)
    # C1 s-curve blend of linear gradients: tiny steps give tiny changes.
    t = np.linspace(0, 20, 20001)
    n = noise.noise(t, 0.37 + 0 * t)
    assert np.max(np.abs(np.diff(n))) < 2e-3


def test_chunked_threads_match_a_single_chunk(monkeypatch):
    x, y = _grid(300, 1 / 11)
    threaded = noise.noise(x, y, seed=2)
    monkeypatch.setattr(noise, "_WORKERS", 1)
    monkeypatch.setattr(noise, "_CHUNK", 1 << 30)
    assert threaded.tobytes() == noise.noise(x, y, seed=2).tobytes()


def test_2d_fast_path_equals_the_general_hash():
    rng = np.random.default_rng(9)
    x = rng.uniform(-600, 600, 5000).astype(np.float32)
    y = rng.uniform(-600, 600, 5000).astype(np.float32)
    perm, gperm = noise._tables(4, 2)
    general = noise._noise_chunk([x, y], perm, gperm)
    assert np.array_equal(noise.noise(x, y, seed=4), general)


def test_turbulence_is_the_octave_sum():
    x, y = _grid(128, 1 / 13)
    expected = sum(
        np.abs(noise.noise(x * 2**i + np.float32(17.31 * i), y * 2**i + np.float32(17.31 * i)))
        / 2**i
        for i in range(4)
    )
    got = noise.turbulence(x, y, octaves=4)
    assert np.allclose(got, expected, atol=1e-5)
    assert got.min() >= 0 and got.max() < 2


def test_turbulence_band_limit_fades_fine_octaves_to_their_mean():
    x, y = _grid(256, 1 / 3)
    sharp = noise.turbulence(x, y, octaves=6)
    soft = noise.turbulence(x, y, octaves=6, filter_width=1 / 3)
    # Octaves whose cell is below two pixels are replaced by their mean: same mean
    # brightness, much less pixel-to-pixel variation.
    assert abs(float(sharp.mean() - soft.mean())) < 0.03
    assert np.abs(np.diff(soft, axis=1)).mean() < 0.6 * np.abs(np.diff(sharp, axis=1)).mean()
    # A filter width of 0 is no filter at all.
    assert np.allclose(
        noise.turbulence(x, y, octaves=3, filter_width=0.0), noise.turbulence(x, y, octaves=3)
    )


@pytest.mark.parametrize("kwargs", [{"seed": -1}, {"seed": 1.5}, {"octaves": 0}])
def test_bad_arguments(kwargs):
    with pytest.raises(ValueError):
        noise.turbulence(np.zeros(3), np.zeros(3), **kwargs)


def test_non_finite_coordinates_rejected():
    with pytest.raises(ValueError, match="finite"):
        noise.noise(np.array([0.0, np.nan]), np.zeros(2))
