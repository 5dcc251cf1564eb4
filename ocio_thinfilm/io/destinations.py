"""Where an output goes: a regular file replaced atomically, or a special file written
through.

An existing destination that is not a regular file (``/dev/null``, ``/dev/full``, a
FIFO, ``/dev/stdout``, anything reached through ``/proc/*/fd``) is written through:
opened and written, never replaced or created. A symbolic link to a regular file (or a
dangling one) is followed: its target is replaced in the target's directory and the
link itself is kept. A directory where a file should go is a one-line error."""

from __future__ import annotations

import os
import re
import stat
import tempfile
from pathlib import Path
from typing import TypeAlias

from ocio_thinfilm.checks import ParameterError

__all__ = [
    "StrPath",
    "is_stdout",
    "destination",
    "fd_alias",
    "check_writable",
    "check_output_file",
]


#: A file-system path as the functions here accept it: a string or a path object.
StrPath: TypeAlias = str | os.PathLike[str]

_FD_ALIAS = re.compile(r"/dev/(stdin|stdout|stderr)|/dev/fd/(\d+)|/proc/self/fd/(\d+)")


def fd_alias(p: Path) -> int | None:
    """The descriptor number of /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N."""
    m = _FD_ALIAS.fullmatch(os.path.abspath(p))
    if not m:
        return None
    fd = (
        {"stdin": 0, "stdout": 1, "stderr": 2}[m.group(1)]
        if m.group(1)
        else int(m.group(2) or m.group(3))
    )
    try:
        os.fstat(fd)
    except OSError:
        return None
    return fd


def _via_proc(p: Path) -> bool:
    """True if following ``p``'s links passes through /proc (a process's descriptor)."""
    current = os.path.abspath(p)
    for _ in range(40):
        if current.startswith("/proc/"):
            return True
        if not os.path.islink(current):
            return False
        current = os.path.normpath(os.path.join(os.path.dirname(current), os.readlink(current)))
    return False


def is_stdout(path: StrPath) -> bool:
    """True if ``path`` names this process's standard output (then messages should go
    to stderr, not into the data)."""
    try:
        a, b = os.stat(path), os.fstat(1)
    except (OSError, ValueError):
        return False
    return (
        fd_alias(Path(path)) == 1
        or (a.st_dev, a.st_ino) == (b.st_dev, b.st_ino)
        and not stat.S_ISCHR(a.st_mode)
    )


def destination(path: StrPath) -> tuple[str, Path]:
    """('replace', where) for a regular file (or nothing yet) to replace atomically, or
    ('through', path) for an existing special file to write through."""
    text = os.fspath(path)
    if text == "":
        raise ValueError("output path is empty")
    p = Path(text)
    try:
        st = os.stat(p)
    except FileNotFoundError:
        st = None
    except OSError as error:
        raise ValueError(f"{p}: {(error.strerror or str(error)).lower()}") from None
    if st is not None:
        if stat.S_ISDIR(st.st_mode):
            raise ValueError(f"{p} is a directory, not a file")
        if not stat.S_ISREG(st.st_mode):
            return "through", p
    if fd_alias(p) is not None or _via_proc(p):  # /dev/stdout redirected to a file
        return "through", p
    real = Path(os.path.realpath(p))
    if st is None and real.parent.exists() and not real.parent.is_dir():
        raise ValueError(f"{real.parent} is not a directory")
    return "replace", real if p.is_symlink() else p


def check_writable(directory: StrPath) -> Path:
    """Fail early, with a one-line error, if ``directory`` cannot be created or written."""
    d = Path(directory)
    if os.fspath(directory) == "":
        d = Path(".")
    probe = d
    while not probe.exists() and not probe.is_symlink():
        probe = probe.parent
    if not probe.is_dir() or not os.access(probe, os.W_OK | os.X_OK):
        raise ValueError(f"{d}: directory is not writable")
    try:  # access() says yes to root everywhere (even /proc): try a real file, kept nowhere
        with tempfile.TemporaryFile(dir=probe):
            pass
    except OSError:
        raise ValueError(f"{d}: directory is not writable") from None
    return d


def check_output_file(path: StrPath, parameter: str = "out") -> Path:
    """Fail early, with a one-line error, if the file ``path`` cannot be written: a
    directory in its place, or an unwritable directory (a :class:`ParameterError`
    naming ``parameter``, the caller's name for ``path``). Special files (written
    through) need only exist."""
    try:
        mode, dest = destination(path)
    except ValueError as error:
        raise ParameterError(parameter, f" {error}") from None
    if mode == "replace":
        check_writable(dest.parent)
    return Path(path)
