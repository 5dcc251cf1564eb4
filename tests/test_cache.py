"""One clearable store for the package's in-process caches (ocio_thinfilm.cache)."""

from __future__ import annotations

import functools
import importlib
import pkgutil

import numpy as np
import pytest

import ocio_thinfilm
from ocio_thinfilm import cache
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.render import noise
from ocio_thinfilm.lut import tables


def _lru_functions():
    """Every lru_cache function at module level in the package, by qualified name."""
    found = {}
    for info in pkgutil.walk_packages(ocio_thinfilm.__path__, "ocio_thinfilm."):
        if info.name.endswith("__main__"):  # runs the command
            continue
        module = importlib.import_module(info.name)
        for value in vars(module).values():
            if isinstance(value, functools._lru_cache_wrapper) and \
                    value.__module__ == module.__name__:
                found[f"{value.__module__}.{value.__qualname__}"] = value
    return found


def test_every_memoised_function_is_in_the_store():
    found = _lru_functions()
    # the noise module's thread pool is a resource, not a cached result
    found.pop("ocio_thinfilm.render.noise._pool")
    assert len(found) >= 8
    registered = cache.names()
    for name in found:
        assert name in registered, name


def test_clear_empties_every_cache_and_results_do_not_change():
    # a size no other test uses: the first call computes it
    film = tables.film_table("no-phase-change", 37)
    morpho = tables.morpho_table(41)
    noise.noise(np.array([0.3]), np.array([0.7]), seed=987)
    assert tables.film_table("no-phase-change", 37) is film  # cached
    assert cache.info()["ocio_thinfilm.lut.tables._film_table"].currsize > 0

    built = len(tables.BUILT)
    cache.clear()
    assert all(i.currsize == 0 for i in cache.info().values())
    again = tables.film_table("no-phase-change", 37)
    assert again is not film  # computed again ...
    assert np.array_equal(again.values, film.values)  # ... to the same values
    assert np.array_equal(tables.morpho_table(41).values, morpho.values)
    assert tables.BUILT[built:] == ["film:no-phase-change:37", "morpho:41"]


def test_colorimetry_matrices_survive_a_clear():
    before = colorimetry.matrix_XYZ_to_RGB("Rec.2020")
    cache.clear()
    assert np.array_equal(colorimetry.matrix_XYZ_to_RGB("Rec.2020"), before)


def test_register_refuses_a_plain_function():
    with pytest.raises(TypeError):
        cache.register(lambda x: x)
