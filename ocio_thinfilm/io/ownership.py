"""Owned output directories: written only if missing, empty, or recognisably ours.

A directory-valued output (``bake --out``, ``bake --luts``) holds the marker file
:data:`MARKER` listing the files the last run wrote. Only listed files are replaced or
removed; anything else in the directory is left alone, and a non-empty directory
without the marker is refused. A commit renames files one by one with the directory
kept (the caller names the file to rename last, e.g. ``config.ocio``) and the marker
always lists every file of ours present, so at every instant the directory holds
complete files and loads.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.io import destinations, durable, faults, temporaries

__all__ = [
    "MARKER",
    "Claim",
    "claim_directory",
    "commit_directory",
]

if TYPE_CHECKING:
    from ocio_thinfilm.io.destinations import StrPath

#: Marker file of an owned output directory: one relative path per line.
MARKER = ".ocio-thinfilm-owned"
_MARKER_HEADER = "# ocio-thinfilm: files written by the last run (replaced or removed by the next)"


class Claim:
    """A directory this run may write, as :func:`claim_directory` found it.

    Parameters
    ----------
    path : pathlib.Path
        The directory (a link's target when ``path`` was a link to a directory).
    exists : bool
        Whether it exists.
    owned : set of str
        The files in it that are ours (relative POSIX paths from its marker).
    parameter : str
        The parameter that named it (for messages).
    last : iterable of str, optional
        Relative paths to rename after all others (e.g. ``config.ocio``).
    keep_others : bool, optional
        Keep the files of earlier runs that this one does not write (a directory that
        collects several runs' outputs, e.g. one material per film); default ``False``.
    """

    def __init__(
        self, path: Path, exists: bool, owned: set, parameter: str, last=(), keep_others=False
    ):
        self.path, self.exists, self.owned, self.parameter = path, exists, owned, parameter
        self.last = tuple(last)
        self.keep_others = bool(keep_others)


def _read_marker(path: Path) -> set:
    owned = set()
    for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        parts = Path(line).parts
        if Path(line).is_absolute() or ".." in parts or line == MARKER:
            continue  # never trust a marker to point outside its directory
        owned.add(Path(line).as_posix())
    return owned


def claim_directory(
    path: StrPath,
    *,
    parameter: str = "out",
    last: Iterable[str] = (),
    keep_others: bool = False,
) -> Claim:
    """Check that ``path`` may be (re)written as an output directory of this tool.

    Allowed: missing, empty, or holding :data:`MARKER`; temporaries of killed runs in it
    are removed. Nothing else is written.

    Parameters
    ----------
    path : str or os.PathLike
        The output directory; a link to a directory is kept, and what it points to is
        written.
    parameter : str, optional
        The caller's name for ``path``, for the error messages (default ``"out"``).
    last : iterable of str, optional
        Relative paths to rename after all others (e.g. ``config.ocio``).
    keep_others : bool, optional
        Keep the earlier runs' files that this run does not write (see :class:`Claim`).

    Returns
    -------
    Claim
        The directory, whether it exists and the files in it that are ours.

    Raises
    ------
    ParameterError
        Naming ``parameter``: an empty ``path``, a file that is not a directory, a
        :data:`MARKER` that is not a file, or a non-empty directory without the marker
        (it holds files this tool did not write).
        Also (``parameter``) if the directory cannot be created or written
        (:func:`ocio_thinfilm.io.destinations.check_writable`: a missing parent folder
        included).
    """
    text = os.fspath(path)
    if text.strip() == "":
        raise ParameterError(parameter, " must name a directory, got an empty string")
    p = Path(text)
    if p.is_symlink() and p.exists():
        p = Path(os.path.realpath(p))  # keep the link, write into what it points to
    if p.exists() and not p.is_dir():
        raise ParameterError(parameter, f" {p}: exists and is not a directory")
    try:
        destinations.check_writable(p)
    except ValueError as error:
        raise ParameterError(parameter, f" {error}") from None
    if not p.exists():
        return Claim(p, False, set(), parameter, last, keep_others)
    temporaries.clean_stale(p)
    names = [n for n in os.listdir(p) if not n.startswith(temporaries.TMP_PREFIX)]
    owned: set
    if MARKER in names:
        if not (p / MARKER).is_file():
            raise ParameterError(parameter, f" {p}: {MARKER} is not a file")
        owned = _read_marker(p / MARKER)
    elif not names:
        owned = set()
    else:
        raise ParameterError(
            parameter,
            f" {p}: directory is not empty and was not written "
            f"by ocio-thinfilm (no {MARKER}); give a new or "
            "empty directory",
        )
    return Claim(p, True, set(owned), parameter, last, keep_others)


def _write_marker(directory: Path, files, umask) -> None:
    body = "\n".join([_MARKER_HEADER] + sorted(files)) + "\n"
    tmp = directory / temporaries.tmp_name(MARKER.lstrip("."))
    durable.write_bytes(tmp, body.encode("utf-8"))
    os.chmod(tmp, 0o666 & ~umask)
    os.replace(tmp, directory / MARKER)


def commit_directory(claim: Claim, stage: Path, files: list, umask: int) -> None:
    """Move the staged files of ``claim`` into place: the directory part of a commit.

    A new directory is the stage itself, marker included, renamed into place at once. An
    existing one is locked (``flock``) and changed file by file so that it always holds
    complete files that load: the marker first lists the old and the new files, then the
    files are renamed (the claim's ``last`` ones at the end), the previous run's files
    that this one does not write are removed (kept with ``keep_others``), and the marker
    is rewritten to list exactly the files there. The stage is removed in the end.

    Parameters
    ----------
    claim : Claim
        The claimed directory.
    stage : pathlib.Path
        The staging directory holding the new files, on the same filesystem.
    files : list of str
        The staged files, relative POSIX paths.
    umask : int
        The umask the permissions are computed with (files 0666, directories 0777,
        less the umask).

    Raises
    ------
    ParameterError
        If a directory that was missing at the claim appeared meanwhile and is not
        empty (nothing is replaced).
    OSError
        From the renames, the marker's write or the lock.
    """
    new = set(files)
    for d in [stage, *(p for p in stage.rglob("*") if p.is_dir())]:
        os.chmod(d, 0o777 & ~umask)
    for rel in files:
        os.chmod(stage / rel, 0o666 & ~umask)
    if not claim.exists:
        _write_marker(stage, new, umask)
        durable.fsync_dir(stage)
        try:
            os.rename(stage, claim.path)  # atomic: the directory appears complete
            durable.fsync_dir(claim.path.parent)
            return
        except OSError:
            if not claim.path.is_dir():
                raise
            claim.exists = True  # created meanwhile: fall back to file-by-file
            names = [n for n in os.listdir(claim.path) if not n.startswith(temporaries.TMP_PREFIX)]
            if names:
                raise ParameterError(
                    claim.parameter, f" {claim.path}: appeared while writing; nothing replaced"
                ) from None
            (stage / MARKER).unlink()
    import fcntl

    lock = os.open(claim.path, os.O_RDONLY)
    try:
        fcntl.flock(lock, fcntl.LOCK_EX)
        old = claim.owned
        # 1. the marker covers old and new files before any of them appears
        _write_marker(claim.path, old | new, umask)
        faults.fault_point("after-marker")
        # 2. file by file, the caller's "last" files (config.ocio) at the end
        order = [r for r in files if r not in claim.last] + [r for r in claim.last if r in new]
        for i, rel in enumerate(order):
            target = claim.path / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            os.replace(stage / rel, target)
            faults.fault_point(f"rename-{i}")
        for d in {(claim.path / r).parent for r in order}:
            durable.fsync_dir(d)
        faults.fault_point("after-renames")
        # 3. files of the previous run that this one does not write (unless kept)
        if claim.keep_others:
            new = old | new
        for rel in sorted(old - new):
            target = claim.path / rel
            if target.is_file() or target.is_symlink():
                target.unlink()
        # 4. the marker lists exactly what is there now
        _write_marker(claim.path, new, umask)
        durable.fsync_dir(claim.path)
        faults.fault_point("after-commit")
    finally:
        os.close(lock)
        temporaries.remove_path(stage)
