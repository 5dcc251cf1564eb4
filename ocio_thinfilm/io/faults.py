"""A test hook that kills the process at a named point of a commit.

``OCIO_THINFILM_FAULT=<point>`` in the environment makes :func:`fault_point` called
with that point send the process SIGKILL; the safety tests kill a bake at every step of
its commit this way and check that every directory still holds complete files.
"""

from __future__ import annotations

import os
import signal

__all__ = [
    "fault_point",
]


def fault_point(point: str) -> None:
    """Kill the process with SIGKILL if ``OCIO_THINFILM_FAULT`` names ``point``.

    A test hook: the tests kill a bake at every step of its commit this way.

    Parameters
    ----------
    point : str
        The name of this point of the commit (e.g. ``"before-commit"``,
        ``"rename-0"``).
    """
    want = os.environ.get("OCIO_THINFILM_FAULT")
    if want and want == point:
        os.kill(os.getpid(), signal.SIGKILL)
