"""Lattice regression: 3D LUT node values fitted to a function through the interpolation.

Where a function has a kink inside a LUT cell (a gamut clip's boundary), interpolating
its samples blends clipped values into colours that need no mapping. Lattice regression
(Garcia & Gupta 2009) instead chooses the node values so that the *interpolated* LUT is
closest, in weighted least squares, to the function on sample inputs, for the
interpolations hosts apply (tetrahedral: ffmpeg's ``lut3d``; trilinear: OpenColorIO's
``FileTransform``, colour-science's ``LUT3D.apply``) at once. The normal equations (27
diagonals, assembled by :func:`numpy.bincount`) are solved by a Jacobi-preconditioned
conjugate gradient in numpy alone, every sum in a fixed order: the same inputs give the
same bytes. More: docs/gamut_map.md, *Fitted tables (lattice regression)*.

- :func:`cell_weights` -- the 8 corner indices and weights of each input's cell for
  one interpolation;
- :func:`interpolate` -- a node lattice applied to inputs (tetrahedral or trilinear);
- :func:`fit_lattice` -- node values fitted to sample values.

References
----------
Garcia, E. and Gupta, M. R. (2009). Lattice regression. *Advances in Neural
Information Processing Systems 22* (NeurIPS 2009), 594-602.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from ocio_thinfilm.checks import ParameterError

__all__ = ["METHODS", "cell_weights", "interpolate", "fit_lattice"]

#: The interpolations a fit can serve.
METHODS = ("tetrahedral", "trilinear")
#: The 8 corners of a cell as (dr, dg, db) offsets, corner k = 4 dr + 2 dg + db.
_CORNERS = np.array([[(k >> 2) & 1, (k >> 1) & 1, k & 1] for k in range(8)])


def _check_coords(coords: npt.ArrayLike, size: int) -> np.ndarray:
    c = np.asarray(coords, dtype=np.float64)
    if c.ndim != 2 or c.shape[1] != 3:
        raise ParameterError("coords", f" must be an (n, 3) array, got shape {c.shape}")
    if isinstance(size, bool) or not isinstance(size, (int, np.integer)) or size < 2:
        raise ParameterError("size", f" must be an integer >= 2, got {size!r}")
    return np.clip(c, 0.0, 1.0)


def cell_weights(
    coords: npt.ArrayLike, size: int, method: str = "tetrahedral"
) -> tuple[np.ndarray, np.ndarray]:
    """Flat node indices and interpolation weights of the 8 corners of each input's cell.

    Parameters
    ----------
    coords : array_like, shape (n, 3)
        Inputs in lattice coordinates, [0, 1] per axis (r, g, b); clamped to it, as
        hosts clamp a LUT's input to its domain.
    size : int
        Nodes per axis.
    method : {"tetrahedral", "trilinear"}
        The interpolation. Tetrahedral weights are zero at the 4 corners off the
        input's tetrahedron.

    Returns
    -------
    index : numpy.ndarray, shape (n, 8), int64
        Flat node index ``(r * size + g) * size + b`` of corner k, whose offset in the
        cell is ``(k >> 2 & 1, k >> 1 & 1, k & 1)``.
    weight : numpy.ndarray, shape (n, 8)
        Interpolation weights (each row sums to 1).

    Examples
    --------
    >>> index, weight = cell_weights([[0.25, 0.5, 1.0]], 3, "trilinear")
    >>> index[0, [0, 7]].tolist(), weight.sum().round(12)
    ([4, 17], 1.0)
    """
    if method not in METHODS:
        raise ParameterError("method", f" must be one of {', '.join(METHODS)}, got {method!r}")
    c = _check_coords(coords, size)
    t = c * (size - 1)
    i0 = np.minimum(np.floor(t), size - 2).astype(np.int64)
    f = t - i0
    index = ((i0[:, None, 0] + _CORNERS[:, 0]) * size + i0[:, None, 1] + _CORNERS[:, 1]) * size + (
        i0[:, None, 2] + _CORNERS[:, 2]
    )
    if method == "trilinear":
        weight = np.ones((len(c), 8))
        for axis in range(3):
            on = _CORNERS[:, axis].astype(bool)
            weight[:, on] *= f[:, axis, None]
            weight[:, ~on] *= 1.0 - f[:, axis, None]
        return index, weight
    # tetrahedral: axes in descending fraction a1, a2, a3 (ties: r before g before b,
    # as OCIO and ffmpeg test fr > fg > fb); the path 0 -> e_a1 -> e_a1 + e_a2 -> 1
    order = np.argsort(-f, axis=1, kind="stable")
    fs = np.take_along_axis(f, order, axis=1)
    bit = np.array([4, 2, 1])[order]  # corner bit of each axis in that order
    rows = np.arange(len(c))
    weight = np.zeros((len(c), 8))
    weight[rows, 0] = 1.0 - fs[:, 0]
    weight[rows, bit[:, 0]] += fs[:, 0] - fs[:, 1]
    weight[rows, bit[:, 0] + bit[:, 1]] += fs[:, 1] - fs[:, 2]
    weight[rows, 7] += fs[:, 2]
    return index, weight


def interpolate(
    nodes: npt.ArrayLike, coords: npt.ArrayLike, method: str = "tetrahedral"
) -> np.ndarray:
    """Apply the lattice ``nodes`` to ``coords`` by ``method``.

    ``nodes`` has shape (size, size, size, c), indexed [r, g, b]; ``coords`` shape (n, 3),
    lattice coordinates in [0, 1]. Returns shape (n, c).

    Examples
    --------
    >>> g = np.linspace(0.0, 1.0, 5)
    >>> identity = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1)
    >>> interpolate(identity, [[0.3, 0.7, 0.11]]).round(12).tolist()
    [[0.3, 0.7, 0.11]]
    """
    v = np.asarray(nodes, dtype=np.float64)
    size = v.shape[0]
    if v.ndim != 4 or v.shape[:3] != (size,) * 3:
        raise ParameterError("nodes", f" must have shape (size, size, size, c), got {v.shape}")
    index, weight = cell_weights(coords, size, method)
    flat = v.reshape(size**3, -1)
    out = np.zeros((len(index), flat.shape[1]))
    for k in range(8):
        out += weight[:, k, None] * flat[index[:, k]]
    return out


def _band(delta: np.ndarray) -> np.ndarray:
    """Band number 0..26 of a node offset (dr, dg, db) in {-1, 0, 1}^3."""
    return (delta[..., 0] + 1) * 9 + (delta[..., 1] + 1) * 3 + (delta[..., 2] + 1)


_OFFSETS = np.array([[a, b, c] for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)])
_CENTRE = 13


class _Banded:
    """A symmetric matrix over the nodes with 27 bands (offsets in {-1, 0, 1}^3).

    ``bands[b, i]`` is the entry (i, i + shift[b]).
    """

    def __init__(self, size: int, channels: int = 1):
        self.size = size
        self.n = size**3
        self.bands = np.zeros((27, self.n, channels))
        self.shift = _OFFSETS @ np.array([size * size, size, 1])
        self.pad = size * size + size + 1

    def add(self, row: np.ndarray, band: int, values: np.ndarray) -> None:
        """Add ``values`` (shape (len(row),) or (len(row), channels)) at (row, band)."""
        values = np.broadcast_to(values.reshape(len(row), -1), (len(row), self.bands.shape[2]))
        for ch in range(self.bands.shape[2]):
            self.bands[band, :, ch] += np.bincount(row, weights=values[:, ch], minlength=self.n)

    def mirror(self) -> None:
        """Fill the bands below the centre from those above.

        The matrix is symmetric: entry (i, i - s) is entry (i - s, i).
        """
        for band in range(_CENTRE):
            shift = int(self.shift[26 - band])  # > 0
            self.bands[band, shift:] += self.bands[26 - band, :-shift]

    def matvec(self, x: np.ndarray) -> np.ndarray:
        padded = np.zeros((self.n + 2 * self.pad, x.shape[1]))
        padded[self.pad : self.pad + self.n] = x
        y = self.bands[_CENTRE] * x
        term = np.empty_like(x)
        for band, shift in enumerate(self.shift):
            if band != _CENTRE:
                start = self.pad + shift
                np.multiply(self.bands[band], padded[start : start + self.n], out=term)
                y += term
        return y


def _add_neighbour_smoothing(matrix: _Banded, weight: float) -> None:
    """``weight`` times the lattice's graph Laplacian (first differences along r, g, b)."""
    size = matrix.size
    idx = np.arange(matrix.n).reshape((size,) * 3)
    for axis in range(3):
        lo = np.take(idx, np.arange(size - 1), axis=axis).ravel()
        hi = np.take(idx, np.arange(1, size), axis=axis).ravel()
        delta = np.zeros(3, dtype=np.int64)
        delta[axis] = 1
        w = np.full(lo.size, weight)
        matrix.add(lo, _CENTRE, w)
        matrix.add(hi, _CENTRE, w)
        matrix.add(lo, int(_band(delta)), -w)
        matrix.add(hi, int(_band(-delta)), -w)


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Per-column dot products in a fixed summation order (no BLAS)."""
    return np.sum(a * b, axis=0)


def fit_lattice(
    coords: npt.ArrayLike,
    values: npt.ArrayLike,
    weights: npt.ArrayLike,
    prior: npt.ArrayLike,
    *,
    methods: Sequence[str] = METHODS,
    prior_weight: float = 1e-3,
    smoothness: float = 1e-2,
    iterations: int = 400,
    tolerance: float = 1e-4,
    clamp: tuple[float, float] | None = None,
    passes: int = 3,
) -> np.ndarray:
    """Fit node values whose interpolation best fits ``values`` at ``coords``.

    Lattice regression (Garcia & Gupta 2009).

    Minimises, over the nodes x (the lattice's values, per output channel),

    ``sum_m sum_s weights[s] |interp_m(x, coords[s]) - values[s]|^2 / len(methods)
    + prior_weight |x - prior|^2 + smoothness sum_edges |(x - prior)_i - (x - prior)_j|^2``

    where m runs over ``methods`` (the interpolations hosts apply) and the edges join
    neighbouring nodes. The last two terms decide nodes that no sample reaches (they
    keep ``prior``) and keep the correction ``x - prior`` smooth, without pulling the
    lattice's own gradient towards zero (Garcia & Gupta's graph Laplacian acts on the
    correction here, not on the values).

    Parameters
    ----------
    coords : array_like, shape (n, 3)
        Sample inputs in lattice coordinates, [0, 1] per axis (r, g, b).
    values : array_like, shape (n, c)
        The function's value at each sample (the target).
    weights : array_like, shape (n,)
        Non-negative weight of each sample.
    prior : array_like, shape (size, size, size, c)
        The lattice the fit starts from and falls back to (e.g. the function's values
        at the nodes), indexed [r, g, b].
    methods : sequence of str
        Interpolations to serve, from :data:`METHODS`.
    prior_weight, smoothness : float
        Weights of the two regularising terms (> 0 and >= 0).
    iterations : int
        Most conjugate-gradient steps.
    tolerance : float
        Stop when the preconditioned residual norm falls below this fraction of the
        right-hand side's.
    clamp : (float, float), optional
        The range hosts clamp the output to (display code values: (0, 1)). A sample's
        channel whose target and interpolated value both lie at or beyond the same end
        costs nothing: the fit is solved ``passes`` times, each time dropping those
        (an active-set iteration on the one-sided squares).
    passes : int
        Solves with ``clamp``.

    Returns
    -------
    numpy.ndarray, shape (size, size, size, c)
        The fitted nodes (not clamped).

    Examples
    --------
    A function with a kink, y = max(x, 0.5) on the r axis, fitted only where x < 0.5
    (weight 1) through a 3-node lattice: the middle and upper nodes extrapolate the
    identity there instead of sampling the kink.

    >>> g = np.linspace(0.0, 1.0, 3)
    >>> prior = np.maximum(np.stack(np.meshgrid(g, g, g, indexing="ij"), -1)[..., :1], 0.5)
    >>> x = np.linspace(0.0, 0.49, 50)
    >>> coords = np.stack([x, 0.5 * np.ones(50), 0.5 * np.ones(50)], axis=1)
    >>> nodes = fit_lattice(coords, x[:, None], np.ones(50), prior, smoothness=0.0,
    ...                     prior_weight=1e-9)
    >>> nodes[:2, 1, 1, 0].round(4).tolist()
    [0.0, 0.5]
    """
    P = np.asarray(prior, dtype=np.float64)
    size = P.shape[0]
    if P.ndim != 4 or P.shape[:3] != (size,) * 3:
        raise ParameterError("prior", f" must have shape (size, size, size, c), got {P.shape}")
    c = _check_coords(coords, size)
    y = np.asarray(values, dtype=np.float64).reshape(len(c), -1)
    if y.shape[1] != P.shape[3]:
        raise ParameterError(
            "values", f" must have {P.shape[3]} channels (as prior), got {y.shape[1]}"
        )
    w = np.asarray(weights, dtype=np.float64).reshape(-1)
    if w.shape != (len(c),) or not np.all(w >= 0):
        raise ParameterError("weights", f" must be {len(c)} non-negative numbers")
    if not methods or any(m not in METHODS for m in methods):
        raise ParameterError("methods", f" must be taken from {', '.join(METHODS)}")
    if not prior_weight > 0 or not smoothness >= 0:
        raise ParameterError("prior_weight", " must be > 0 (and smoothness >= 0)")

    n_nodes = size**3
    x0 = P.reshape(n_nodes, -1)
    share = w / len(methods)
    index, _ = cell_weights(c, size, "trilinear")
    a = [cell_weights(c, size, m)[1] for m in methods]
    d = np.zeros_like(x0)
    active = None
    for _ in range(passes if clamp is not None else 1):
        matrix, rhs = _normal_equations(index, a, share, active, x0, y, size)
        matrix.bands[_CENTRE] += prior_weight
        if smoothness > 0:
            _add_neighbour_smoothing(matrix, smoothness)
        d = _conjugate_gradient(matrix, rhs, d, iterations, tolerance)
        if clamp is not None:
            active = _unclamped(index, a, x0 + d, y, clamp)
    return (x0 + d).reshape(P.shape)


def _interpolated(index: np.ndarray, a: np.ndarray, x: np.ndarray) -> np.ndarray:
    out = np.zeros((len(index), x.shape[1]))
    for k in range(8):
        out += a[:, k, None] * x[index[:, k]]
    return out


def _unclamped(index, a, x, y, clamp):
    """Return per method the mask of the samples' channels that count.

    1 where a sample's channel counts, 0 where both the target and the interpolated value lie
    at or beyond the same end of ``clamp`` (the host's clamp makes them equal).
    """
    lo, hi = clamp
    masks = []
    for am in a:
        f = _interpolated(index, am, x)
        gone = ((y <= lo + 1e-6) & (f <= lo)) | ((y >= hi - 1e-6) & (f >= hi))
        masks.append((~gone).astype(np.float64))
    return masks


def _normal_equations(index, a, share, active, x0, y, size):
    """Return the banded normal matrix and right-hand side of the correction d = x - prior.

    The matrix is without regularisers. ``active``: per method, per-sample-and-channel weights
    (or None: all 1, one matrix for every channel).
    """
    n_nodes = size**3
    channels = y.shape[1]
    act = active if active is not None else [np.ones((1, 1))] * len(a)
    # residuals of the prior, per method
    r = [(y - _interpolated(index, am, x0)) * m for am, m in zip(a, act, strict=True)]
    rhs = np.zeros_like(x0)
    for k in range(8):
        contribution = sum(am[:, k, None] * rm for am, rm in zip(a, r, strict=True))
        contribution = contribution * share[:, None]
        for ch in range(channels):
            rhs[:, ch] += np.bincount(index[:, k], weights=contribution[:, ch], minlength=n_nodes)
    # normal matrix: the pairs (k, j) with j's band at or above the centre, then mirrored
    matrix = _Banded(size, 1 if active is None else channels)
    for k in range(8):
        for j in range(8):
            band = int(_band(_CORNERS[j] - _CORNERS[k]))
            if band < _CENTRE or (band == _CENTRE and j != k):
                continue
            coefficient = sum(
                (am[:, k] * am[:, j] * share)[:, None] * m for am, m in zip(a, act, strict=True)
            )
            matrix.add(index[:, k], band, coefficient)
    matrix.mirror()
    return matrix, rhs


def _conjugate_gradient(matrix, rhs, d, iterations, tolerance):
    """Jacobi-preconditioned conjugate gradient from ``d``, one system per channel."""
    inv_diag = 1.0 / matrix.bands[_CENTRE]
    d = d.copy()
    res = rhs - matrix.matvec(d)
    z = inv_diag * res
    p = z.copy()
    rz = _dot(res, z)
    stop = tolerance * np.sqrt(_dot(rhs, inv_diag * rhs)) + 1e-300
    for _ in range(int(iterations)):
        if np.all(np.sqrt(rz) <= stop):
            break
        q = matrix.matvec(p)
        pq = _dot(p, q)
        alpha = rz / np.where(pq > 0, pq, 1.0)
        d += alpha * p
        res -= alpha * q
        z = inv_diag * res
        rz_new = _dot(res, z)
        p = z + (rz_new / np.where(rz > 0, rz, 1.0)) * p
        rz = rz_new
    return d
