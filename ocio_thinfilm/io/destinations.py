"""Where an output goes: a regular file replaced atomically, or a special file written through.

An existing destination that is not a regular file (``/dev/null``, ``/dev/full``, a
FIFO, ``/dev/stdout``, anything reached through ``/proc/*/fd``) is written through:
opened and written, never replaced or created. A symbolic link to a regular file (or a
dangling one) is followed: its target is replaced in the target's directory and the
link itself is kept. A directory where a file should go is a one-line error.
"""

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
    """Return the open file descriptor that ``p`` names, if it names one.

    Parameters
    ----------
    p : pathlib.Path
        A path; relative paths are taken from the current directory (links are not
        followed).

    Returns
    -------
    int or None
        0, 1 or 2 for ``/dev/stdin``, ``/dev/stdout``, ``/dev/stderr``; N for
        ``/dev/fd/N`` or ``/proc/self/fd/N``; ``None`` for any other path or a
        descriptor that is not open.

    Examples
    --------
    >>> fd_alias(Path("/dev/stdout")), fd_alias(Path("/tmp/frame.exr"))
    (1, None)
    """
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
    """Return whether following ``p``'s links passes through /proc (a descriptor)."""
    current = os.path.abspath(p)
    for _ in range(40):
        if current.startswith("/proc/"):
            return True
        if not os.path.islink(current):
            return False
        current = os.path.normpath(os.path.join(os.path.dirname(current), os.readlink(current)))
    return False


def is_stdout(path: StrPath) -> bool:
    """Return whether ``path`` names this process's standard output.

    Then messages should go to stderr, not into the data.

    Parameters
    ----------
    path : str or os.PathLike
        Any path.

    Returns
    -------
    bool
        ``True`` for ``/dev/stdout`` (or another alias of descriptor 1), or for the
        file that standard output is redirected to (same device and inode, not a
        character device); ``False`` otherwise, also when ``path`` or the descriptor
        cannot be examined.
    """
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
    """Return how an output to ``path`` is written, and where.

    Parameters
    ----------
    path : str or os.PathLike
        The output path (not empty).

    Returns
    -------
    tuple of (str, pathlib.Path)
        ``("replace", where)`` for a regular file (or nothing yet) to replace
        atomically -- ``where`` is the link's target for a symbolic link, else ``path``
        -- or ``("through", path)`` for an existing special file (a device, a FIFO, a
        descriptor alias such as ``/dev/stdout``) to write through.

    Raises
    ------
    ValueError
        If ``path`` is empty, is a directory, cannot be examined (e.g. permission
        denied), or its parent exists and is not a directory.

    Examples
    --------
    >>> destination("/dev/null")
    ('through', PosixPath('/dev/null'))
    """
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


def check_writable(directory: StrPath, *, create: bool = True) -> Path:
    """Fail early, with a one-line error, if ``directory`` cannot be created or written.

    The package's one rule for outputs: it creates the output (a file, or a folder
    when the output is a folder), never a chain of missing folders above it, so a
    mistyped path is caught instead of silently made. ``directory`` must exist, or,
    with ``create``, its parent must; that directory must be writable (tried with a
    real temporary file: ``access()`` says yes to root everywhere).

    Parameters
    ----------
    directory : str or os.PathLike
        The directory; ``""`` is the current directory.
    create : bool, optional
        Whether the tool creates ``directory`` itself (an output folder: its parent
        must exist); False for the folder a file goes into (it must exist).

    Returns
    -------
    pathlib.Path
        ``directory`` as a path (``.`` for ``""``).

    Raises
    ------
    ValueError
        ``"<directory>: directory is not writable"`` (also when a path on the way is
        not a directory), or a missing folder named.
    """
    d = Path(directory)
    if os.fspath(directory) == "":
        d = Path(".")
    probe = d
    if not probe.exists() and not probe.is_symlink():
        probe = d.parent
        if not create:
            raise ValueError(f"{d}: folder does not exist (create it first)")
        if not probe.exists() and not probe.is_symlink():
            raise ValueError(
                f"{d}: its folder {probe} does not exist (ocio-thinfilm creates the output "
                "folder, not the folders above it)"
            )
    if not probe.is_dir() or not os.access(probe, os.W_OK | os.X_OK):
        raise ValueError(f"{d}: directory is not writable")
    try:  # access() says yes to root everywhere (even /proc): try a real file, kept nowhere
        with tempfile.TemporaryFile(dir=probe):
            pass
    except OSError:
        raise ValueError(f"{d}: directory is not writable") from None
    return d


def check_output_file(
    path: StrPath, parameter: str = "out", *, in_new_folder: bool = False
) -> Path:
    """Fail early, with a one-line error, if the file ``path`` cannot be written.

    Special files (written through) need only exist.

    Parameters
    ----------
    path : str or os.PathLike
        The output file.
    parameter : str, optional
        The caller's name for ``path``, for the error message (default ``"out"``).
    in_new_folder : bool, optional
        Whether the file goes into an output folder the command creates (a render's
        ``--out``): then that folder may be missing, but not its parent.

    Returns
    -------
    pathlib.Path
        ``path`` as a path (as given: a link is not resolved).

    Raises
    ------
    ParameterError
        Naming ``parameter``, for what :func:`destination` refuses (an empty path, a
        directory in its place, a parent that is not a directory).
        Also when the file's directory cannot be created or written.
    """
    try:
        mode, dest = destination(path)
        if mode == "replace":
            folder = dest.parent
            missing = not folder.exists() and not folder.is_symlink()
            if missing and not in_new_folder:
                raise ValueError(f"{path}: its folder {folder} does not exist (create it first)")
            check_writable(folder, create=in_new_folder)
    except ParameterError:
        raise
    except ValueError as error:
        raise ParameterError(parameter, f" {error}") from None
    return Path(path)
