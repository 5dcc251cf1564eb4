"""Perlin (1985) gradient noise and turbulence, vectorised over whole images.

Used by the example scenes (paper Section 4): Eq. 13's ``turb(x, y)`` that perturbs
the oil slick, the air currents on the soap film and the asphalt texture.

Public functions
----------------
- :func:`noise` -- Perlin's gradient ("improved lattice") noise in 1-3 dimensions:
  pseudo-random unit gradients on the integer lattice, hashed by a permutation
  table, blended with Perlin's cubic s-curve ``3t^2 - 2t^3``. Zero at every lattice
  point, roughly in [-1, 1], mean 0.
- :func:`turbulence` -- ``sum_i |noise(2^i p)| / 2^i`` over octaves (Perlin 1985,
  "An Image Synthesizer", Section 'Turbulence'), with optional per-pixel
  band-limiting: octaves finer than a pixel fade to their mean instead of aliasing.

Everything is array-in/array-out (float32 inside, any broadcastable shapes), with no
Python loop over pixels; the only loops are over octaves and lattice corners. The
result depends only on the coordinates and ``seed`` (NumPy's PCG64 builds the
tables), so a seed always gives the same bytes on the same platform.

References
----------
Perlin, K. (1985) An Image Synthesizer. Computer Graphics 19(3), 287-296.
"""

from __future__ import annotations

import os
from functools import lru_cache
from typing import Any

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import cache

__all__ = ["noise", "turbulence", "TABLE_SIZE", "MEAN_ABS_NOISE"]

#: Lattice period: the noise repeats every 256 units along each axis.
TABLE_SIZE = 256

#: Mean of |noise| in 1, 2 and 3 dimensions (sampled: 10^6 samples, seed 0): what
#: a fully band-limited octave of :func:`turbulence` fades to.
MEAN_ABS_NOISE = {1: 0.37, 2: 0.234, 3: 0.171}


@cache.memoize(maxsize=64)
def _tables(seed: int, dims: int):
    """Return the permutation table and the gradients per axis, gathered through it.

    Permutation (doubled, int32) and, per axis, the unit gradients already gathered
    through the permutation (``g[perm]``, float32, doubled): the last hash step and the
    gradient lookup are one gather.
    """
    if isinstance(seed, (bool, np.bool_)) or int(seed) != seed or seed < 0:
        raise ValueError(f"seed must be an integer >= 0, got {seed!r}")
    rng = np.random.Generator(np.random.PCG64([int(seed), dims, 1985]))
    perm = rng.permutation(TABLE_SIZE).astype(np.int32)
    # Uniform directions on the circle / sphere (Perlin's random unit gradients).
    g = rng.standard_normal((TABLE_SIZE, dims))
    g /= np.linalg.norm(g, axis=1, keepdims=True)
    # Scale so the noise spans roughly [-1, 1] (a 1-D gradient of +-1 peaks at 0.5).
    g *= {1: 2.0, 2: 1.4142135, 3: 1.1547005}[dims]
    perm2 = np.concatenate([perm, perm])
    gperm = [np.ascontiguousarray(g[perm2, k], dtype=np.float32) for k in range(dims)]
    return perm2, gperm


@cache.memoize(maxsize=64)
def _lattice2(seed: int):
    """Return the gradient of every lattice point of one period, hashed once (2-D).

    ``GX[i * 257 + j]`` is the x gradient at lattice point ``(i, j)`` (i, j in
    0..256, the 257th row/column repeating the first), exactly the value the general
    hash gives; one gather per corner and component replaces the hash chain.
    """
    perm, gperm = _tables(seed, 2)
    i, j = np.meshgrid(np.arange(_P2) & 255, np.arange(_P2) & 255, indexing="ij")
    h = (perm[i] + j).ravel()
    return (np.ascontiguousarray(gperm[0][h]), np.ascontiguousarray(gperm[1][h]))


_P2 = TABLE_SIZE + 1


def _noise2_chunk(x, y, gx, gy):
    """Return 2-D noise of one chunk with the :func:`_lattice2` tables.

    In-place arithmetic; identical results to :func:`_noise_chunk`.
    """
    fx0 = np.floor(x)
    fy0 = np.floor(y)
    fx = x - fx0
    fy = y - fy0
    ix = fx0.astype(np.intp)
    ix &= TABLE_SIZE - 1
    iy = fy0.astype(np.intp)
    iy &= TABLE_SIZE - 1
    u = _scurve(fx)
    v = _scurve(fy)
    fx1 = fx - np.float32(1.0)
    fy1 = fy - np.float32(1.0)
    idx = ix * _P2
    idx += iy

    def corner(dx, dy):
        r = np.take(gx, idx)
        r *= dx
        t = np.take(gy, idx)
        t *= dy
        r += t
        return r

    n00 = corner(fx, fy)
    idx += 1
    n01 = corner(fx, fy1)
    idx += _P2
    n11 = corner(fx1, fy1)
    idx -= 1
    n10 = corner(fx1, fy)
    n01 -= n00
    n01 *= v
    n01 += n00
    n11 -= n10
    n11 *= v
    n11 += n10
    n11 -= n01
    n11 *= u
    n11 += n01
    return n11


#: Points per work chunk: small enough for the cache, large enough for NumPy.
_CHUNK = 1 << 16


def _scurve(t):
    return t * t * (np.float32(3.0) - np.float32(2.0) * t)


def _noise_chunk(coords, perm, gperm):
    """Noise at flat float32 coordinate arrays (one chunk)."""
    dims = len(coords)
    cell, frac, fade = [], [], []
    for c in coords:
        f = np.floor(c)
        fr = c - f
        cell.append(f.astype(np.int32) & (TABLE_SIZE - 1))
        frac.append(fr)
        fade.append(_scurve(fr))
    # Hash prefixes over all but the last axis: 2^(dims-1) of them.
    prefixes: dict[tuple[int, ...], np.ndarray | None] = {(): None}
    for axis in range(dims - 1):
        nxt: dict[tuple[int, ...], np.ndarray | None] = {}
        for key, h in prefixes.items():
            for o in (0, 1):
                idx = cell[axis] + o if h is None else h + cell[axis] + o
                nxt[key + (o,)] = perm[idx]
        prefixes = nxt
    last = dims - 1
    values: dict[tuple[int, ...], Any] = {}
    for key, h in prefixes.items():
        for o in (0, 1):
            idx = cell[last] + o if h is None else h + cell[last] + o
            offsets = key + (o,)
            d: Any = gperm[0][idx] * (frac[0] - offsets[0]) if dims else None
            for axis in range(1, dims):
                d += gperm[axis][idx] * (frac[axis] - offsets[axis])
            values[offsets] = d
    # Blend along the last axis first, then inwards, with the s-curve weights.
    for axis in reversed(range(dims)):
        merged: dict[tuple[int, ...], np.ndarray] = {}
        for key in {k[:axis] for k in values}:
            lo, hi = values[key + (0,)], values[key + (1,)]
            merged[key] = lo + fade[axis] * (hi - lo)
        values = merged
    return values[()]


def noise(
    x: npt.ArrayLike,
    y: npt.ArrayLike | None = None,
    z: npt.ArrayLike | None = None,
    *,
    seed: int = 0,
) -> np.ndarray:
    """Perlin gradient noise at the points ``(x[, y[, z]])`` (broadcast together).

    Lattice period 256; deterministic for a given ``seed``; different seeds give
    independent fields. Zero at every lattice point, roughly in [-1, 1], mean 0.

    Parameters
    ----------
    x : array_like
        First coordinate, in noise lattice units.
    y, z : array_like, optional
        Further coordinates (``z`` needs ``y``); all broadcast together. Coordinates
        are taken in float32 (fine for the scenes' ranges, ``|p| < 10^4``) and must be
        finite.
    seed : int, optional
        Integer >= 0 selecting the permutation and gradient tables (default 0).

    Returns
    -------
    numpy.ndarray
        float32, the broadcast shape of the coordinates.

    Raises
    ------
    ValueError
        For ``z`` without ``y``, a bad ``seed`` or non-finite coordinates.

    Examples
    --------
    >>> float(noise(3.0, 5.0)), noise([[0.5, 1.5]], seed=2).shape
    (0.0, (1, 2))
    """
    if y is None and z is not None:
        raise ValueError("noise takes x, (x, y) or (x, y, z)")
    coords = [c for c in (x, y, z) if c is not None]
    dims = len(coords)
    perm, gperm = _tables(seed, dims)
    arrays = np.broadcast_arrays(*[np.asarray(c, dtype=np.float32) for c in coords])
    shape = arrays[0].shape
    flat = [np.ascontiguousarray(c).reshape(-1) for c in arrays]
    if flat[0].size and not all(np.all(np.isfinite(c)) for c in flat):
        raise ValueError("noise coordinates must be finite")
    out = np.empty(flat[0].size, np.float32)

    if dims == 2:
        gx, gy = _lattice2(seed)

        def kernel(part):
            return _noise2_chunk(part[0], part[1], gx, gy)
    else:

        def kernel(part):
            return _noise_chunk(part, perm, gperm)

    def work(start):
        out[start : start + _CHUNK] = kernel([c[start : start + _CHUNK] for c in flat])

    starts = range(0, out.size, _CHUNK)
    if len(starts) > 1 and _WORKERS > 1:
        # NumPy releases the GIL in its loops: chunks run in parallel threads. Each
        # chunk writes its own slice, so the result does not depend on scheduling.
        list(_pool().map(work, starts))
    else:
        for start in starts:
            work(start)
    return out.reshape(shape)


_WORKERS = max(1, min(4, os.cpu_count() or 1))


@lru_cache(maxsize=1)
def _pool():
    from concurrent.futures import ThreadPoolExecutor

    return ThreadPoolExecutor(max_workers=_WORKERS, thread_name_prefix="noise")


def turbulence(
    x: npt.ArrayLike,
    y: npt.ArrayLike | None = None,
    z: npt.ArrayLike | None = None,
    *,
    octaves: int = 6,
    seed: int = 0,
    filter_width: npt.ArrayLike | None = None,
) -> np.ndarray:
    """Perlin's turbulence ``sum_{i<octaves} |noise(2^i p)| / 2^i`` (float32).

    ``filter_width`` (scalar or array broadcasting with the coordinates) is the size
    of one pixel in noise units. Octave ``i`` is kept in full while a pixel covers
    less than a quarter of its lattice cell (``filter_width * 2^i < 0.25``), fades
    linearly to its mean (:data:`MEAN_ABS_NOISE`) by half a cell, and is skipped when
    every pixel is past that -- a cheap band limit that keeps distant texture from
    aliasing into sparkle. The result lies in about ``[0, 2)``.

    The ``turb(x, y)`` of Smits & Meyer (1990), Eq. 13 (Section 4.1, the oil slick's
    irregular spreading) and Section 4.2 (air currents on the soap film), after
    Perlin (1985). Octave ``i`` samples the noise at ``2^i p + 17.31 i`` (the offset
    keeps the octaves' lattices from lining up at the origin).

    Parameters
    ----------
    x : array_like
        First coordinate, in noise lattice units (the lattice period is
        :data:`TABLE_SIZE`, 256).
    y, z : array_like, optional
        Further coordinates (``z`` needs ``y``); all broadcast together. Coordinates
        are taken in float32 and must be finite.
    octaves : int, optional
        Number of octaves, an integer >= 1 (default 6).
    seed : int, optional
        Integer >= 0 selecting the permutation and gradient tables (default 0).
    filter_width : float or array_like, optional
        Size of one pixel in noise units, broadcasting with the coordinates; ``None``
        (default) keeps every octave in full.

    Returns
    -------
    numpy.ndarray
        float32, the broadcast shape of the coordinates (0-d for scalars). Since
        ``|noise| <= 1`` (the gradients are scaled so that the bound sqrt(N) / 2 of
        N-dimensional gradient noise with unit gradients becomes 1) and every faded
        octave's mean is below 1, the result lies in
        ``[0, 2 - 2^(1 - octaves)]`` up to float32 rounding. It depends only on the
        coordinates, ``octaves``, ``seed`` and ``filter_width``.

    Raises
    ------
    ValueError
        For ``octaves`` not an integer >= 1, a bad ``seed`` or non-finite
        coordinates.

    References
    ----------
    Perlin, K. (1985). An Image Synthesizer. Computer Graphics (SIGGRAPH '85
    Proceedings), 19(3), 287-296.
    Perlin, K. (2002). Improving Noise. ACM Transactions on Graphics (SIGGRAPH 2002
    Proceedings), 21(3), 681-682 (its quintic fade and fixed gradient set are not
    used here: this is the 1985 noise).
    Smits & Meyer (1990), Eq. 13, Sections 4.1 and 4.2.

    Examples
    --------
    Deterministic for a seed, different for another, and within
    [0, 2 - 2^-5] for six octaves:

    >>> x, y = np.meshgrid(np.linspace(0.0, 8.0, 64), np.linspace(0.0, 8.0, 64))
    >>> t = turbulence(x, y, seed=3)
    >>> str(t.dtype), t.shape
    ('float32', (64, 64))
    >>> bool(np.array_equal(t, turbulence(x, y, seed=3)))
    True
    >>> bool(np.array_equal(t, turbulence(x, y, seed=4)))
    False
    >>> bool(t.min() >= 0.0 and t.max() <= 2.0 - 2.0 ** -5)
    True

    One octave at a lattice point is 0 (octave 0 has no offset); with pixels larger
    than half a cell every octave is its mean, 0.234 (2 - 2^-5) = 0.4607 in 2-D:

    >>> float(turbulence(3.0, 5.0, octaves=1))
    0.0
    >>> round(float(turbulence(0.3, 0.7, filter_width=1.0)), 4)
    0.4607
    """
    if isinstance(octaves, bool) or int(octaves) != octaves or octaves < 1:
        raise ValueError(f"octaves must be an integer >= 1, got {octaves!r}")
    coords = [np.asarray(c, dtype=np.float32) for c in (x, y, z) if c is not None]
    shape = np.broadcast_shapes(*[c.shape for c in coords])
    fw = None if filter_width is None else np.asarray(filter_width, dtype=np.float32)
    total = np.zeros(shape, np.float32)
    mean = np.float32(MEAN_ABS_NOISE[len(coords)])
    for i in range(int(octaves)):
        f = np.float32(2**i)
        amp = np.float32(1.0 / f)
        if fw is None:
            weight = None
        else:
            weight = np.clip(np.float32(2.0) - np.float32(4.0) * f * fw, 0.0, 1.0)
            if not np.any(weight > 0):
                total += amp * mean
                continue
        # Offset each octave so their lattices do not line up at the origin.
        shifted = [c * f + np.float32(17.31 * i) for c in coords]
        n = np.abs(noise(*shifted, seed=seed))
        if weight is not None:
            n = weight * n + (np.float32(1.0) - weight) * mean
        total += amp * n
    return total
