"""Temporary files of this package: their names and the removal of stale ones.

Every output is first written to a temporary sibling named
``.ocio-thinfilm-tmp-<host>-<pid>-<start>-<token>-<name>``: the host key, process id and
process start time say whose it is, so the next write into the same directory removes
the temporaries of killed runs (their process gone, or its pid reused) and nothing else.
A temporary made on another host (an NFS render directory) or in another container is
removed only once it is a day old.
"""

from __future__ import annotations

import os
import re
import secrets
import shutil
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ocio_thinfilm.io.destinations import StrPath

__all__ = [
    "TMP_PREFIX",
    "FOREIGN_STALE_SECONDS",
    "clean_stale",
    "tmp_name",
    "remove_path",
]

#: Prefix of every temporary file or directory this package creates.
TMP_PREFIX = ".ocio-thinfilm-tmp-"


def start_time(pid: int) -> str:
    """Return a process's start time, in clock ticks since boot (Linux ``/proc``).

    Parameters
    ----------
    pid : int
        The process id.

    Returns
    -------
    str
        The start time as digits, ``""`` if it cannot be read (no such process, no
        ``/proc``).
    """
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            data = f.read()
        return data[data.rindex(b")") + 2 :].split()[19].decode()
    except (OSError, ValueError, IndexError):
        return ""


def _host_key() -> str:
    """Return 8 hex digits naming this machine, boot and pid namespace.

    A pid in a temporary's name is only meaningful where this key matches (not on
    another host sharing an NFS render directory, nor in another container).
    """
    import hashlib
    import socket

    parts = [socket.gethostname()]
    for source in ("/proc/sys/kernel/random/boot_id",):
        try:
            parts.append(Path(source).read_text().strip())
        except OSError:
            pass
    try:
        parts.append(str(os.stat("/proc/self/ns/pid").st_ino))
    except OSError:
        pass
    return hashlib.sha1("|".join(parts).encode()).hexdigest()[:8]


_SELF: dict[str, Any] = {"pid": None, "start": "", "host": None}
#: A temporary from another host (or container) is stale only when older than this.
FOREIGN_STALE_SECONDS = 24 * 3600


def self_id() -> str:
    """Return this process's part of temporary names.

    Recomputed after a fork; the start time is ``0`` where it cannot be read.

    Returns
    -------
    str
        ``<host key>-<pid>-<start time>``.
    """
    pid = os.getpid()
    if _SELF["pid"] != pid:  # recomputed after a fork
        _SELF.update(pid=pid, start=start_time(pid) or "0", host=_SELF["host"] or _host_key())
    return f"{_SELF['host']}-{pid}-{_SELF['start']}"


def tmp_name(label: str) -> str:
    """Return a new temporary name ending in ``label``.

    Parameters
    ----------
    label : str
        The end of the name (e.g. the destination's file name).

    Returns
    -------
    str
        ``TMP_PREFIX + self_id() + "-" + <8 random hex digits> + "-" + label``.
    """
    return f"{TMP_PREFIX}{self_id()}-{secrets.token_hex(4)}-{label}"


_TMP_RE = re.compile(re.escape(TMP_PREFIX) + r"([0-9a-f]{8})-(\d+)-(\d+)-[0-9a-f]+-")


def is_stale(name: str, directory: StrPath | None = None) -> bool:
    """Return whether ``name`` is a temporary left by a killed run.

    Parameters
    ----------
    name : str
        A file name.
    directory : str or os.PathLike, optional
        The directory holding it, to read its age; without it a temporary of another
        host is never stale.

    Returns
    -------
    bool
        ``True`` for a temporary of ours whose process is gone (or whose pid was
        reused); one made on another host or in another container counts as stale
        once older than :data:`FOREIGN_STALE_SECONDS` (a day). ``False`` for any
        other name.
    """
    m = _TMP_RE.match(name)
    if not m:
        return False
    self_id()
    host, pid, start = m.group(1), int(m.group(2)), m.group(3)
    if host != _SELF["host"]:
        if directory is None:
            return False
        import time

        try:
            age = time.time() - os.lstat(Path(directory) / name).st_mtime
        except OSError:
            return False
        return age > FOREIGN_STALE_SECONDS
    if pid == os.getpid():
        return start != _SELF["start"]
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    except PermissionError:
        pass
    now = start_time(pid)
    return bool(now) and start != "0" and now != start


def remove_path(path: Path) -> None:
    """Remove a file, a link or a directory tree; a missing one is no error.

    A directory tree is removed as far as it can be (errors ignored).

    Parameters
    ----------
    path : pathlib.Path
        What to remove (a link is removed, not what it points to).

    Raises
    ------
    OSError
        If a file or link exists and cannot be removed.
    """
    try:
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path, ignore_errors=True)
        else:
            path.unlink()
    except FileNotFoundError:
        pass


def clean_stale(directory: StrPath) -> list[Path]:
    """Remove the temporaries left in ``directory`` by killed runs.

    Parameters
    ----------
    directory : str or os.PathLike
        The directory; one that cannot be listed is left alone.

    Returns
    -------
    list of pathlib.Path
        What was removed.
    """
    removed: list[Path] = []
    try:
        names = os.listdir(directory)
    except OSError:
        return removed
    for name in names:
        if name.startswith(TMP_PREFIX) and is_stale(name, directory):
            remove_path(Path(directory) / name)
            removed.append(Path(directory) / name)
    return removed
