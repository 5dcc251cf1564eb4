"""The package's in-process caches, in one clearable store.

Every memoised function of the package (the thin-film tables, the clip LUTs, the
colour-science data, the noise lattices) is a :class:`Memo` held here under its
qualified name, keyed by the whole argument tuple of its pure function: caching never
changes a result, :func:`clear` only makes the next call compute again.

- :func:`memoize` -- decorator: a :class:`Memo` (least-recently-used, ``maxsize``
  entries, one computation at a time), registered in the store;
- :func:`clear` -- empty every memo; with ``persistent=True`` also the on-disk entries;
- :func:`persistent` -- decorator: a memo that also keeps its arrays on disk (keyed by
  the code and colour-science's version), for the next process;
- :func:`info` -- ``{name: CacheInfo(hits, misses, maxsize, currsize)}``;
- :func:`entries` -- ``{name: (key, ...)}``: what each memo holds now.

It imports nothing from the package at import time, so any module may use it; why not
``functools.lru_cache``: docs/internals.md.

>>> @memoize(maxsize=2)
... def square(x):
...     return x * x
>>> square(3), square(3), square.keys(), square.cache_info().misses
(9, 9, ((3,),), 1)
"""

from __future__ import annotations

import functools
import hashlib
import inspect
import os
import threading
import weakref
from collections import OrderedDict, namedtuple
from collections.abc import Callable
from functools import wraps
from importlib import metadata
from pathlib import Path
from typing import Any, overload

__all__ = ["Memo", "CacheInfo", "memoize", "clear", "info", "entries", "names"]

#: Statistics of one memo (the fields of ``functools.lru_cache``'s ``cache_info()``).
CacheInfo = namedtuple("CacheInfo", "hits misses maxsize currsize")

#: name -> Memo, held weakly (a discarded memo is not kept alive by the store).
_STORE: weakref.WeakValueDictionary[str, Memo] = weakref.WeakValueDictionary()
_STORE_LOCK = threading.Lock()


class Memo:
    """A memoised pure function, registered in the store by :func:`memoize`.

    ``memo(*args)`` is ``function(*args)``, computed once per argument tuple
    (positional, hashable) while fewer than ``maxsize`` newer keys have been used (the
    least recently used key goes first); calls are serialised while a value is
    computed.

    Parameters
    ----------
    function : callable
        The pure function; its positional arguments must be hashable (keyword arguments
        are not supported).
    maxsize : int
        Number of entries kept.
    name : str
        The memo's name in the store (:func:`memoize` gives the qualified name).
    forget : callable, optional
        Called without arguments by :func:`clear` with ``persistent=True``: removes what
        the function keeps outside this process (its on-disk entries); ``None``
        (default) if nothing.
    """

    def __init__(self, function, maxsize: int, name: str, forget=None):
        functools.update_wrapper(self, function)
        self.function, self.maxsize, self.name = function, int(maxsize), name
        #: Called by :func:`clear` with ``persistent=True``: removes what the function
        #: keeps outside this process (its on-disk entries), if anything.
        self.forget = forget
        self._values: OrderedDict = OrderedDict()
        self._lock = threading.RLock()
        self._hits = self._misses = 0

    def __call__(self, *args):
        """Return ``function(*args)``, from the memo when it holds ``args``."""
        with self._lock:
            if args in self._values:
                self._hits += 1
                self._values.move_to_end(args)
                return self._values[args]
            value = self.function(*args)
            self._misses += 1
            self._values[args] = value
            while len(self._values) > self.maxsize:
                self._values.popitem(last=False)
            return value

    def cache_clear(self) -> None:
        """Empty the memo and reset its statistics (its on-disk entries stay)."""
        with self._lock:
            self._values.clear()
            self._hits = self._misses = 0

    def cache_info(self) -> CacheInfo:
        """Return the memo's statistics.

        Returns
        -------
        CacheInfo
            ``(hits, misses, maxsize, currsize)``, as ``functools.lru_cache`` gives them.
        """
        with self._lock:
            return CacheInfo(self._hits, self._misses, self.maxsize, len(self._values))

    def keys(self) -> tuple:
        """Return the argument tuples held now.

        Returns
        -------
        tuple of tuple
            The keys, least recently used first.
        """
        with self._lock:
            return tuple(self._values)

    def __repr__(self) -> str:
        """Return ``<Memo name (currsize/maxsize)>``."""
        return f"<Memo {self.name} ({len(self._values)}/{self.maxsize})>"


def memoize(
    maxsize: int = 128, *, forget: Callable[[], object] | None = None
) -> Callable[[Callable[..., Any]], Memo]:
    """Make a decorator that memoises a function as a :class:`Memo` in the store.

    The memo is registered by the function's qualified name (``module.qualname``); a
    new memo of the same name replaces the old one in the store.

    Parameters
    ----------
    maxsize : int, optional
        Number of entries kept (default 128).
    forget : callable, optional
        A callable without arguments that removes the function's persistent entries
        (called by :func:`clear` with ``persistent=True``); ``None`` (default) if it
        keeps none.

    Returns
    -------
    callable
        The decorator: function -> :class:`Memo`.

    Examples
    --------
    >>> @memoize(maxsize=1)
    ... def double(x):
    ...     return 2 * x
    >>> double(1), double(2), double.keys()
    (2, 4, ((2,),))
    """

    def decorate(function: Callable[..., Any]) -> Memo:
        memo = Memo(function, maxsize, f"{function.__module__}.{function.__qualname__}", forget)
        with _STORE_LOCK:
            _STORE[memo.name] = memo
        return memo

    return decorate


def _memos() -> dict:
    with _STORE_LOCK:
        return dict(sorted(_STORE.items()))  # strong references while in use


def clear(*, persistent: bool = False) -> None:
    """Empty every memo of the store.

    Parameters
    ----------
    persistent : bool, optional
        Also remove the memos' on-disk entries (each memo's ``forget``); default
        ``False``. The on-disk entries never go stale: removing them only costs the
        next process the computation.
    """
    for memo in _memos().values():
        memo.cache_clear()
        if persistent and memo.forget is not None:
            memo.forget()


def info() -> dict:
    """Return the statistics of every memo.

    Returns
    -------
    dict
        ``{name: CacheInfo(hits, misses, maxsize, currsize)}``, sorted by name.
    """
    return {name: memo.cache_info() for name, memo in _memos().items()}


def entries(prefix: str = "") -> dict:
    """Return what the memos hold now.

    Parameters
    ----------
    prefix : str, optional
        Only memos whose name starts with it (default ``""``: all), e.g.
        ``"ocio_thinfilm.lut."`` for the tables and clip LUTs computed in this process
        and still cached.

    Returns
    -------
    dict
        ``{name: keys}`` (:meth:`Memo.keys`) of the matching memos that hold at least
        one value, sorted by name.
    """
    return {
        name: memo.keys()
        for name, memo in _memos().items()
        if name.startswith(prefix) and memo.keys()
    }


def names() -> tuple:
    """Return the registered memos' names.

    Returns
    -------
    tuple of str
        The qualified names, sorted.
    """
    return tuple(_memos())


# --------------------------------------------------------------------------- #
# On disk
# --------------------------------------------------------------------------- #
def _cache_dir() -> Path | None:
    """``$OCIO_THINFILM_CACHE`` (empty or ``0`` disables), else the user cache dir."""
    setting = os.environ.get("OCIO_THINFILM_CACHE")
    if setting is not None:
        return None if setting in ("", "0") else Path(setting)
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "ocio-thinfilm"


@overload
def persistent(function: Callable[..., Any], *, modules: tuple[str, ...] = ()) -> Memo: ...
@overload
def persistent(
    function: None = None, *, modules: tuple[str, ...] = ()
) -> Callable[[Callable[..., Any]], Memo]: ...
def persistent(
    function: Callable[..., Any] | None = None, *, modules: tuple[str, ...] = ()
) -> Memo | Callable[[Callable[..., Any]], Memo]:
    """Memoise a pure function of colour-science's datasets in memory and on disk.

    The key covers the arguments, the function's source, the full source of any
    ``modules`` it depends on (names, read at the first call) and colour-science's
    version, so changed code or a changed library never returns a stale array. A
    cache that cannot be read or written is ignored. Use as ``@persistent`` or
    ``@persistent(modules=("ocio_thinfilm.lut.tables",))``.

    Parameters
    ----------
    function : callable, optional
        The function to memoise. Its positional arguments must be hashable and have a
        stable ``repr`` (tuples of floats, strings); keyword arguments are not
        supported. Its result must be convertible by :func:`numpy.asarray`. ``None``
        when used as ``@persistent(modules=...)``.
    modules : tuple of str, optional
        Importable module names whose full source also enters the key (for functions
        whose result depends on code outside their own body).

    Returns
    -------
    callable
        The memoised function (or, with ``function=None``, a decorator making one).
        It returns :class:`numpy.ndarray` (the value as saved with :func:`numpy.save`),
        the same array object for repeated in-process calls (an in-memory
        :func:`ocio_thinfilm.cache.memoize` of 64 entries): callers that hand the
        array out should copy it.

    Notes
    -----
    The on-disk store is ``$OCIO_THINFILM_CACHE`` (empty or ``0`` disables it), else
    ``$XDG_CACHE_HOME/ocio-thinfilm`` or ``~/.cache/ocio-thinfilm``; each entry is one
    ``<name>-<sha256 prefix>.npy`` file written atomically;
    ``ocio_thinfilm.cache.clear(persistent=True)`` removes them.
    """
    if function is None:
        return lambda f: persistent(f, modules=modules)
    source = inspect.getsource(function)

    def forget():
        """Remove this function's entries from the on-disk store."""
        directory = _cache_dir()
        if directory is not None and directory.is_dir():
            for path in directory.glob(f"{function.__name__}-{'?' * 32}.npy"):
                path.unlink(missing_ok=True)

    @memoize(maxsize=64, forget=forget)
    @wraps(function)
    def wrapper(*args):
        import numpy

        directory = _cache_dir()
        path = None
        if directory is not None:
            import importlib

            code = [source] + [inspect.getsource(importlib.import_module(m)) for m in modules]
            key = repr((args, code, metadata.version("colour-science")))
            digest = hashlib.sha256(key.encode()).hexdigest()[:32]
            path = directory / f"{function.__name__}-{digest}.npy"
            try:
                return numpy.load(path)
            except (OSError, ValueError):
                pass
        value = numpy.asarray(function(*args))
        if path is not None:
            from ocio_thinfilm.io import atomic_file

            try:
                with atomic_file(path) as tmp:
                    numpy.save(tmp, value)
            except OSError:
                pass
        return value

    return wrapper
