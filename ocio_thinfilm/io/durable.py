"""Checked low-level writes: every write, fsync and close checked.

A written XML file is parsed to its end before it may replace anything (a file
truncated by a full disk is caught here, not by the host that later reads it).
"""

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
    """Return the process's umask (set to 0 and back for an instant to read it).

    Returns
    -------
    int
        The umask, e.g. ``0o022``.
    """
    mask = os.umask(0)
    os.umask(mask)
    return mask


def fsync_dir(directory: StrPath) -> None:
    """Fsync ``directory`` (its entries: the renames into it), ignoring failures.

    A directory that cannot be opened, or a filesystem that cannot fsync a directory,
    is no error: the files themselves were fsynced.

    Parameters
    ----------
    directory : str or os.PathLike
        The directory.
    """
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
    """Fsync the file ``path``.

    Parameters
    ----------
    path : str or os.PathLike
        The file, opened read-only.

    Raises
    ------
    OSError
        If it cannot be opened or fsynced; ``EINVAL`` and ``EROFS`` (e.g. a pipe:
        nothing to sync) are ignored.
    """
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    except OSError as error:
        if error.errno not in (errno.EINVAL, errno.EROFS):  # e.g. a pipe: nothing to sync
            raise
    finally:
        os.close(fd)


def write_fd(fd: int, data: bytes) -> None:
    """Write all of ``data`` to the open descriptor ``fd``, however many writes it takes.

    Parameters
    ----------
    fd : int
        An open file descriptor.
    data : bytes-like
        The data.

    Raises
    ------
    OSError
        From a write, or ``ENOSPC`` when a write writes nothing.
    """
    view = memoryview(data)
    while view:
        n = os.write(fd, view)
        if n <= 0:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        view = view[n:]


def write_bytes(path: StrPath, data: bytes) -> None:
    """Create ``path`` holding ``data``; every write, the fsync and the close are checked.

    Parameters
    ----------
    path : str or os.PathLike
        The file to create (mode 0600); it must not exist.
    data : bytes
        The content.

    Raises
    ------
    OSError
        ``FileExistsError`` if ``path`` exists, or any failure of the open, a write,
        the fsync or the close (the file is then left as it is, for the caller to
        remove).
    """
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    try:
        write_fd(fd, data)
        os.fsync(fd)
    except BaseException:
        os.close(fd)
        raise
    os.close(fd)


def check_xml(path: StrPath, name: StrPath | None = None) -> None:
    """Check that ``path`` parses as XML to its end.

    A CLF truncated by a full disk is caught before it is renamed into place.

    Parameters
    ----------
    path : str or os.PathLike
        The written (temporary) file.
    name : str or os.PathLike, optional
        The name for the message: the destination the file is for (default ``path``).

    Raises
    ------
    OSError
        ``"cannot write <name>: incomplete file (...); disk full?"`` if the file does
        not parse (an unreadable file raises the OSError of opening it).
    """
    import xml.etree.ElementTree as ET

    try:
        for _ in ET.iterparse(path, events=("end",)):
            pass
    except ET.ParseError as error:
        raise OSError(
            f"cannot write {name or path}: incomplete file ({error}); disk full?"
        ) from None


def cannot_write(dest: StrPath, error: OSError) -> OSError:
    """Return ``error`` reworded to name the destination (not a temporary) on one line.

    Parameters
    ----------
    dest : str or os.PathLike
        The destination the failed write was for.
    error : OSError
        The failure.

    Returns
    -------
    OSError
        ``error`` itself if its message already starts with ``"cannot write"``, else a
        new OSError ``"cannot write <dest>: <reason>"`` with the same errno (the reason
        is ``strerror`` when there is one).

    Examples
    --------
    >>> import errno
    >>> cannot_write("luts/a.clf", OSError(errno.ENOSPC, "No space left on device"))
    OSError(28, 'cannot write luts/a.clf: No space left on device')
    """
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
