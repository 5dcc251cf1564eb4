"""One clearable store for the package's in-process caches (ocio_thinfilm.cache)."""

from __future__ import annotations

import functools
import importlib
import pkgutil

import numpy as np

import ocio_thinfilm
from ocio_thinfilm import cache
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.lut import tables
from ocio_thinfilm.render import noise


def _memoised_functions():
    """Every memoised function (an lru_cache or a cache.Memo) at module level in the
    package, by qualified name."""
    found = {}
    for info in pkgutil.walk_packages(ocio_thinfilm.__path__, "ocio_thinfilm."):
        if info.name.endswith("__main__"):  # runs the command
            continue
        module = importlib.import_module(info.name)
        for value in vars(module).values():
            if (
                isinstance(value, (functools._lru_cache_wrapper, cache.Memo))
                and value.__module__ == module.__name__
            ):
                found[f"{value.__module__}.{value.__qualname__}"] = value
    return found


def test_every_memoised_function_is_in_the_store():
    found = _memoised_functions()
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

    cache.clear()
    assert all(i.currsize == 0 for i in cache.info().values())
    again = tables.film_table("no-phase-change", 37)
    assert again is not film  # computed again ...
    assert np.array_equal(again.values, film.values)  # ... to the same values
    assert np.array_equal(tables.morpho_table(41).values, morpho.values)
    assert cache.entries("ocio_thinfilm.lut.tables.") == {
        "ocio_thinfilm.lut.tables._film_table": (
            ("no-phase-change", 37, tables.FILM_TMAX_UM, tables.FILM_T0_UM, tables.SPECTRAL_STEP),
        ),
        "ocio_thinfilm.lut.tables._morpho_table": ((41, tables.SPECTRAL_STEP),),
    }


def test_colorimetry_matrices_survive_a_clear():
    before = colorimetry.matrix_XYZ_to_RGB("Rec.2020")
    cache.clear()
    assert np.array_equal(colorimetry.matrix_XYZ_to_RGB("Rec.2020"), before)


def test_a_memo_holds_at_most_maxsize_values_newest_kept():
    calls = []

    @cache.memoize(maxsize=2)
    def square(x):
        calls.append(x)
        return x * x

    assert [square(v) for v in (1, 2, 1, 3, 1, 2)] == [1, 4, 1, 9, 1, 4]
    assert calls == [1, 2, 3, 2]  # 2 was the least recently used when 3 came
    assert square.keys() == ((1,), (2,))
    assert square.cache_info() == cache.CacheInfo(hits=2, misses=4, maxsize=2, currsize=2)
    assert (
        "test_cache.test_a_memo_holds_at_most_maxsize_values_newest_kept.<locals>.square"
        in " ".join(cache.names())
    )


def test_clear_persistent_removes_the_disk_entries_too(tmp_path, monkeypatch):
    """``cache.clear(persistent=True)`` empties the memos and removes the on-disk entries
    of :func:`cache.persistent` functions (only theirs: other files stay)."""
    monkeypatch.setenv("OCIO_THINFILM_CACHE", str(tmp_path))
    calls = []

    def cubed(x):
        calls.append(x)
        return np.arange(3.0) * x**3

    memo = cache.persistent(cubed)
    memo(2.0)
    other = tmp_path / "notes.txt"
    other.write_text("mine")
    assert len(list(tmp_path.glob("cubed-*.npy"))) == 1
    cache.clear()
    memo(2.0)
    assert calls == [2.0]  # memory emptied, the disk entry read back
    cache.clear(persistent=True)
    assert list(tmp_path.glob("cubed-*.npy")) == [] and other.read_text() == "mine"
    np.testing.assert_array_equal(memo(2.0), np.arange(3.0) * 8.0)
    assert calls == [2.0, 2.0]  # computed again


def test_persistent_cache_returns_what_a_fresh_computation_gives(tmp_path, monkeypatch):
    """The disk memo (cache.persistent): a value read back from the cache equals
    the freshly computed one, another process's call reads the file instead of
    computing, the key changes with the code it depends on, and "0" disables it."""

    monkeypatch.setenv("OCIO_THINFILM_CACHE", str(tmp_path))
    calls = []

    def square(x):
        calls.append(x)
        return np.arange(4.0) * x

    first = cache.persistent(square)(3.0)
    assert calls == [3.0] and len(list(tmp_path.glob("square-*.npy"))) == 1
    again = cache.persistent(square)(3.0)  # a new wrapper: empty in-memory cache
    assert calls == [3.0]
    np.testing.assert_array_equal(first, again)
    np.testing.assert_array_equal(again, np.arange(4.0) * 3.0)

    cache.persistent(square, modules=("ocio_thinfilm.physics.spectra",))(3.0)
    assert calls == [3.0, 3.0]  # other dependencies: another key, computed again

    monkeypatch.setenv("OCIO_THINFILM_CACHE", "0")
    cache.persistent(square)(3.0)
    assert calls == [3.0, 3.0, 3.0]
