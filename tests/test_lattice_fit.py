"""ocio_thinfilm.lut.lattice_fit: lattice regression against independent references.

The interpolation weights are checked against colour-science's own table interpolators
(tetrahedral and trilinear), the fit against a dense least-squares solution of the same
objective by numpy.linalg.lstsq on a small lattice.
"""

from __future__ import annotations

import numpy as np
import pytest

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.lut import lattice_fit


@pytest.mark.parametrize("method", lattice_fit.METHODS)
def test_interpolation_is_colour_sciences(method):
    import colour

    rng = np.random.default_rng(0)
    nodes = rng.uniform(size=(9, 9, 9, 3))
    x = np.concatenate([rng.uniform(size=(3000, 3)), [[1.0, 1.0, 1.0], [0.0, 0.5, 1.0]]])
    reference = {
        "tetrahedral": colour.algebra.table_interpolation_tetrahedral,
        "trilinear": colour.algebra.table_interpolation_trilinear,
    }[method](x, nodes)
    np.testing.assert_allclose(lattice_fit.interpolate(nodes, x, method), reference, atol=1e-12)


def _dense_solution(x, y, w, prior, prior_weight, smoothness):
    """The same objective as fit_lattice, as one dense least-squares problem."""
    size = prior.shape[0]
    n_nodes = size**3
    P = prior.reshape(n_nodes, -1)
    rows, rhs = [], []
    for method in lattice_fit.METHODS:
        index, a = lattice_fit.cell_weights(x, size, method)
        A = np.zeros((len(x), n_nodes))
        np.add.at(A, (np.arange(len(x))[:, None], index), a)
        scale = np.sqrt(w / len(lattice_fit.METHODS))[:, None]
        rows.append(A * scale)
        rhs.append(y * scale)
    rows.append(np.sqrt(prior_weight) * np.eye(n_nodes))
    rhs.append(np.sqrt(prior_weight) * P)
    ids = np.arange(n_nodes).reshape((size,) * 3)
    for axis in range(3):
        lo = np.take(ids, np.arange(size - 1), axis=axis).ravel()
        hi = np.take(ids, np.arange(1, size), axis=axis).ravel()
        D = np.zeros((len(lo), n_nodes))
        D[np.arange(len(lo)), lo] = 1.0
        D[np.arange(len(lo)), hi] = -1.0
        rows.append(np.sqrt(smoothness) * D)
        rhs.append(np.sqrt(smoothness) * D @ P)
    return np.linalg.lstsq(np.vstack(rows), np.vstack(rhs), rcond=None)[0]


def test_fit_solves_the_stated_least_squares_problem():
    rng = np.random.default_rng(1)
    x, y, w = rng.uniform(size=(500, 3)), rng.uniform(size=(500, 2)), rng.uniform(size=500)
    prior = rng.uniform(size=(4, 4, 4, 2))
    got = lattice_fit.fit_lattice(
        x, y, w, prior, prior_weight=0.01, smoothness=0.1, tolerance=1e-12, iterations=2000
    )
    want = _dense_solution(x, y, w, prior, 0.01, 0.1)
    np.testing.assert_allclose(got.reshape(64, 2), want, atol=1e-9)


def test_fit_is_deterministic():
    rng = np.random.default_rng(2)
    x, y = rng.uniform(size=(20000, 3)), rng.uniform(size=(20000, 3))
    prior = rng.uniform(size=(9, 9, 9, 3))
    runs = [lattice_fit.fit_lattice(x, y, np.ones(20000), prior).tobytes() for _ in range(2)]
    assert runs[0] == runs[1]


def test_one_sided_clamp_fits_what_the_host_shows():
    """With ``clamp``, outputs beyond the clamp cost nothing where the target is there
    too: the clamped interpolant fits a clipped ramp far better."""
    rng = np.random.default_rng(0)
    x = rng.uniform(size=(3000, 3))
    t = np.clip(3 * x[:, :1] - 1.2 + x[:, 1:2], 0.0, 1.0)
    prior = np.zeros((4, 4, 4, 1))

    def shown_error(nodes):
        return sum(
            ((np.clip(lattice_fit.interpolate(nodes, x, m), 0, 1) - t) ** 2).sum()
            for m in lattice_fit.METHODS
        )

    kwargs = dict(prior_weight=1e-6, smoothness=0.0)
    plain = lattice_fit.fit_lattice(x, t, np.ones(3000), prior, **kwargs)
    one_sided = lattice_fit.fit_lattice(x, t, np.ones(3000), prior, clamp=(0.0, 1.0), **kwargs)
    assert shown_error(one_sided) < 0.1 * shown_error(plain)


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        (dict(coords=np.zeros((5, 2))), "coords"),
        (dict(values=np.zeros((10, 2))), "values"),
        (dict(weights=-np.ones(10)), "weights"),
        (dict(prior=np.zeros((3, 3, 2, 3))), "prior"),
        (dict(methods=("cubic",)), "methods"),
        (dict(prior_weight=0.0), "prior_weight"),
    ],
)
def test_errors_name_the_parameter(kwargs, parameter):
    call = dict(
        coords=np.zeros((10, 3)),
        values=np.zeros((10, 3)),
        weights=np.ones(10),
        prior=np.zeros((3, 3, 3, 3)),
    )
    call |= kwargs
    with pytest.raises(ParameterError) as raised:
        lattice_fit.fit_lattice(
            call.pop("coords"), call.pop("values"), call.pop("weights"), call.pop("prior"), **call
        )
    assert raised.value.parameter == parameter
