"""A test hook that kills the process at a named point of a commit.

``OCIO_THINFILM_FAULT=<point>`` in the environment makes :func:`fault_point` called
with that point send the process SIGKILL; the safety tests kill a bake at every step of
its commit this way and check that every directory still holds complete files."""

from __future__ import annotations

import os
import signal

__all__ = [
    "fault_point",
]


def fault_point(point: str) -> None:
    """Test hook: ``OCIO_THINFILM_FAULT=<point>`` kills the process at that point
    (used by the tests to kill a bake at every step of its commit)."""
    want = os.environ.get("OCIO_THINFILM_FAULT")
    if want and want == point:
        os.kill(os.getpid(), signal.SIGKILL)
