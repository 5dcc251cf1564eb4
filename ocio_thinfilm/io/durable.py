"""Checked low-level writes: every write, fsync and close checked, and a written XML
file parsed to its end before it may replace anything (a file truncated by a full disk
is caught here, not by the host that later reads it)."""

from __future__ import annotations

import errno
import os
from typing import TYPE_CHECKING


__all__ = [
    "write_bytes",
    "check_xml",
    "fsync_file",
    "fsync_dir",
    "cannot_write",
    "current_umask",
    "CHECKS",
]

if TYPE_CHECKING:
    from ocio_thinfilm.io.destinations import StrPath


def current_umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def fsync_dir(directory: StrPath) -> None:
    try:
        fd = os.open(directory, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass  # some filesystems cannot fsync a directory; the files themselves were
    finally:
        os.close(fd)


def fsync_file(path: StrPath) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    except OSError as error:
        if error.errno not in (errno.EINVAL, errno.EROFS):  # e.g. a pipe: nothing to sync
            raise
    finally:
        os.close(fd)


def write_fd(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        n = os.write(fd, view)
        if n <= 0:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        view = view[n:]


def write_bytes(path: StrPath, data: bytes) -> None:
    """Create ``path`` (which must not exist) holding ``data``; every write, the fsync
    and the close are checked."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    try:
        write_fd(fd, data)
        os.fsync(fd)
    except BaseException:
        os.close(fd)
        raise
    os.close(fd)


def check_xml(path: StrPath, name: StrPath | None = None) -> None:
    """OSError naming ``name`` (default ``path``) unless ``path`` parses as XML to its
    end: a CLF truncated by a full disk is caught before it is renamed into place."""
    import xml.etree.ElementTree as ET

    try:
        for _ in ET.iterparse(path, events=("end",)):
            pass
    except ET.ParseError as error:
        raise OSError(
            f"cannot write {name or path}: incomplete file ({error}); disk full?"
        ) from None


def cannot_write(dest: StrPath, error: OSError) -> OSError:
    """``error`` reworded to name the destination (not a temporary) on one line."""
    text = str(error)
    if text.startswith("cannot write"):
        return error
    reason = error.strerror or text
    return (
        OSError(error.errno, f"cannot write {dest}: {reason}")
        if error.errno
        else OSError(f"cannot write {dest}: {reason}")
    )


#: Checks run on a staged file before it is committed, by suffix.
CHECKS = {".clf": check_xml, ".ctf": check_xml}
