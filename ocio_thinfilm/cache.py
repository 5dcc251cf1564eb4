"""The package's in-process caches, in one clearable store.

Every memoised function of the package (the tables and clip LUTs of
:mod:`.tables`, the colour-science data of :mod:`.colorimetry`, the noise lattices of
:mod:`.noise`) is an :func:`functools.lru_cache` registered here, by its qualified
name. Caching never changes a result: :func:`clear` only makes the next call compute
again (and, for :mod:`.tables`, append to ``tables.BUILT`` again).

- :func:`memoize` -- ``lru_cache`` that registers the function;
- :func:`register` -- register an existing ``lru_cache`` function;
- :func:`clear` -- empty every registered cache (in memory: the on-disk cache of
  :func:`.colorimetry.persistent` is keyed by the code and stays valid);
- :func:`info` -- ``{name: functools CacheInfo}`` of every registered cache.

This module imports nothing from the package, so any module may use it.
"""

from __future__ import annotations

import threading
import weakref
from functools import lru_cache

__all__ = ["memoize", "register", "clear", "info", "names"]

#: name -> cache function, held weakly (a discarded cache is not kept alive by the store).
_CACHES = weakref.WeakValueDictionary()
_LOCK = threading.Lock()


def _name(function) -> str:
    return f"{function.__module__}.{function.__qualname__}"


def register(function, name: str | None = None):
    """Register an ``lru_cache``-wrapped ``function`` (has ``cache_clear`` and
    ``cache_info``); returns it unchanged. A new cache of the same name (the same
    function wrapped again) replaces the earlier one in the store."""
    if not (callable(getattr(function, "cache_clear", None))
            and callable(getattr(function, "cache_info", None))):
        raise TypeError(f"{function!r} is not an lru_cache function")
    key = name or _name(function)
    with _LOCK:
        _CACHES[key] = function
    return function


def memoize(maxsize: int = 128):
    """``functools.lru_cache(maxsize)``, registered in this store."""
    def decorate(function):
        return register(lru_cache(maxsize=maxsize)(function), _name(function))

    return decorate


def clear() -> None:
    """Empty every registered cache."""
    with _LOCK:
        caches = list(_CACHES.values())  # strong references while clearing
    for function in caches:
        function.cache_clear()


def info() -> dict:
    """``{name: CacheInfo(hits, misses, maxsize, currsize)}`` of every registered cache."""
    with _LOCK:
        return {name: function.cache_info() for name, function in sorted(_CACHES.items())}


def names() -> tuple:
    """The registered caches' names."""
    with _LOCK:
        return tuple(sorted(_CACHES))
