"""Signals held back while a commit renames its files (POSIX ``pthread_sigmask``).

A Ctrl-C or a farm's SIGTERM arrives after the last rename, never between two.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator

__all__ = [
    "deferred_signals",
]


_SIGNALS = tuple(
    getattr(signal, s) for s in ("SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT") if hasattr(signal, s)
)


@contextlib.contextmanager
def deferred_signals() -> Iterator[None]:
    """Hold SIGINT, SIGTERM, SIGHUP and SIGQUIT back for the duration of the block.

    The renames of a commit run to the end; a pending signal is delivered after. Only
    in the main thread where ``signal.pthread_sigmask`` exists (POSIX); elsewhere the
    block runs with signals as they are.

    Yields
    ------
    None
        While the signals are blocked.
    """
    if threading.current_thread() is not threading.main_thread() or not hasattr(
        signal, "pthread_sigmask"
    ):
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, _SIGNALS)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)
