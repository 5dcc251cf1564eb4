"""Transactions: every output written aside, checked, then committed together.

Every output is written to a temporary sibling first (:mod:`.temporaries`), checked (the
writer's own result, the close, an XML parse of ``.clf``/``.ctf`` files), fsynced, and
only then renamed into place; a command that writes several files stages them all in
one :class:`Transaction` and commits them together, so a failure anywhere leaves every
previous output as it was. Signals are held back while the renames run
(:mod:`.signals`).
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
import threading
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.io import destinations, durable, faults, ownership, signals, temporaries
from ocio_thinfilm.io.destinations import StrPath

__all__ = [
    "Transaction",
    "transaction",
    "atomic_file",
    "atomic_directory",
    "write_text",
]


class _Entry:
    __slots__ = ("dest", "tmp", "mode", "check")

    def __init__(self, dest, tmp, mode, check):
        self.dest, self.tmp, self.mode, self.check = dest, tmp, mode, check


# --------------------------------------------------------------------------- #
# Transactions
# --------------------------------------------------------------------------- #
class Transaction:
    """Files (and owned directories) written aside, committed together.

    ``tx.file(path)`` returns the temporary path to write ``path``'s content to;
    ``tx.directory(claim)`` a staging directory whose tree replaces the claimed
    directory's own files. :meth:`commit` checks and fsyncs everything, then renames
    it all into place with signals held back; :meth:`abort` removes what was staged.
    Usually made by :func:`transaction`.

    Attributes
    ----------
    done : bool
        Whether the transaction was committed.
    """

    def __init__(self):
        self._files: list[_Entry] = []
        self._dirs: list[tuple[ownership.Claim, Path]] = []
        self._lock = threading.Lock()
        self._scratch: list[Path] = []
        self._cleaned: set[str] = set()
        self._made: list[Path] = []  # directories created for this transaction
        self.done = False

    def _mkdirs(self, directory: Path) -> None:
        """Create ``directory`` and its missing parents, remembering them.

        An aborted transaction removes them again if they are still empty.
        """
        missing = []
        d = Path(directory)
        while not d.exists() and not d.is_symlink() and d != d.parent:
            missing.append(d)
            d = d.parent
        Path(directory).mkdir(parents=True, exist_ok=True)
        self._made.extend(missing)  # deepest first

    # -- staging ------------------------------------------------------------ #
    def _clean(self, directory: Path) -> None:
        key = os.fspath(directory)
        if key not in self._cleaned:
            self._cleaned.add(key)
            temporaries.clean_stale(directory)

    def file(self, path: StrPath, *, check: Callable[[Path], object] | None = None) -> Path:
        """Stage ``path``: return the temporary path its content must be written to.

        A regular file (or a new one) is staged beside its destination (the directory is
        created if missing; killed runs' temporaries there are removed); a special file
        (written through at the commit) in a scratch directory.

        Parameters
        ----------
        path : str or os.PathLike
            The destination (:func:`ocio_thinfilm.io.destinations.destination`).
        check : callable, optional
            ``check(tmp)``, run at the commit, raises (an OSError) if the written file is
            wrong. ``.clf`` and ``.ctf`` files are always parsed as XML.

        Returns
        -------
        pathlib.Path
            The temporary path.

        Raises
        ------
        ValueError
            If ``path`` is staged twice in this transaction, or cannot be written
            (:func:`~ocio_thinfilm.io.destinations.destination`).
        """
        mode, dest = destinations.destination(path)
        with self._lock:
            if any(e.dest == dest for e in self._files):
                raise ValueError(f"{dest} would be written twice")
            if mode == "replace":
                self._mkdirs(dest.parent)
                self._clean(dest.parent)
                tmp = dest.parent / temporaries.tmp_name(dest.name)
            else:
                scratch = Path(tempfile.mkdtemp(prefix=temporaries.tmp_name("through")))
                self._scratch.append(scratch)
                tmp = scratch / (dest.name or "out")
            self._files.append(_Entry(dest, tmp, mode, check))
        return tmp

    def write(self, path: StrPath, data: str | bytes) -> Path:
        """Stage ``path`` with ``data``, written and fsynced now.

        Parameters
        ----------
        path : str or os.PathLike
            The destination.
        data : str or bytes
            The content; a str is encoded as UTF-8.

        Returns
        -------
        pathlib.Path
            The temporary path.

        Raises
        ------
        OSError
            ``"cannot write <path>: ..."`` if the temporary cannot be written.
        ValueError
            As :meth:`file`.
        """
        tmp = self.file(path)
        try:
            durable.write_bytes(tmp, data.encode("utf-8") if isinstance(data, str) else bytes(data))
        except OSError as error:
            raise durable.cannot_write(path, error) from None
        return tmp

    def directory(self, claim: ownership.Claim) -> Path:
        """Return a new, empty staging directory for ``claim`` (on the same filesystem).

        Parameters
        ----------
        claim : ocio_thinfilm.io.ownership.Claim
            The claimed output directory
            (:func:`~ocio_thinfilm.io.ownership.claim_directory`).

        Returns
        -------
        pathlib.Path
            The staging directory: inside the claimed directory when it exists, else beside
            it (the missing parents are created).
        """
        with self._lock:
            if claim.exists:
                self._clean(claim.path)
                stage = claim.path / temporaries.tmp_name("stage")
            else:
                self._mkdirs(claim.path.parent)
                self._clean(claim.path.parent)
                stage = claim.path.parent / temporaries.tmp_name(claim.path.name)
            stage.mkdir()
            self._dirs.append((claim, stage))
        return stage

    # -- commit ------------------------------------------------------------- #
    def _verify(self) -> list:
        plans = []
        for e in self._files:
            if not e.tmp.is_file():
                raise OSError(f"cannot write {e.dest}: the writer produced no file")
            try:
                if e.dest.suffix.lower() in durable.CHECKS:
                    durable.CHECKS[e.dest.suffix.lower()](e.tmp, e.dest)
                if e.check:
                    e.check(e.tmp)
                durable.fsync_file(e.tmp)
            except OSError as error:
                raise durable.cannot_write(e.dest, error) from None
        for claim, stage in self._dirs:
            files = sorted(
                p.relative_to(stage).as_posix()
                for p in stage.rglob("*")
                if p.is_file() or p.is_symlink()
            )
            for rel in files:
                if not (stage / rel).is_file():
                    raise OSError(f"cannot write {claim.path / rel}: not a regular file")
                target = claim.path / rel
                try:
                    if Path(rel).suffix.lower() in durable.CHECKS:
                        durable.CHECKS[Path(rel).suffix.lower()](stage / rel, target)
                    durable.fsync_file(stage / rel)
                except OSError as error:
                    raise durable.cannot_write(target, error) from None
                if (
                    claim.exists
                    and rel not in claim.owned
                    and (target.exists() or target.is_symlink())
                ):
                    raise ParameterError(
                        claim.parameter,
                        f" {claim.path}: {rel} exists and was "
                        "not written by ocio-thinfilm; not replacing it",
                    )
                if claim.exists and (target.is_dir() and not target.is_symlink()):
                    raise ParameterError(claim.parameter, f" {claim.path}: {rel} is a directory")
            plans.append((claim, stage, files))
        return plans

    def commit(self) -> None:
        """Check, fsync and rename everything staged into place; a second call does nothing.

        Every staged file must exist and pass its checks before anything is renamed.
        Special files are written through first (with signals deliverable: opening a FIFO
        waits for its reader); then, with signals held back, regular files are renamed
        (permissions 0666 less the umask) and the claimed directories committed
        (:func:`~ocio_thinfilm.io.ownership.commit_directory`).

        Raises
        ------
        OSError
            ``"cannot write <destination>: ..."`` if a file is missing, fails its check or
            cannot be written; nothing has been renamed when it comes from the checks.
        ParameterError
            If a claimed directory holds, in the place of a staged file, a file this tool
            did not write or a directory.
        """
        if self.done:
            return
        faults.fault_point("before-commit")
        plans = self._verify()
        umask = durable.current_umask()
        # Special files first, with signals deliverable: opening a FIFO waits for its
        # reader, and Ctrl-C must still end that wait.
        for e in self._files:
            if e.mode == "through":
                _write_through(e.tmp, e.dest)
        with signals.deferred_signals():
            for e in self._files:
                if e.mode == "replace":
                    os.chmod(e.tmp, 0o666 & ~umask)
                    os.replace(e.tmp, e.dest)
                    durable.fsync_dir(e.dest.parent)
            for claim, stage, files in plans:
                ownership.commit_directory(claim, stage, files, umask)
            self.done = True
        self.abort()  # scratch directories

    def abort(self) -> None:
        """Remove what was staged; after a failed commit also the directories it created.

        Called by :func:`transaction` in every case (after a commit it removes only the
        scratch directories); safe to call more than once.
        """
        for e in self._files:
            if e.mode == "replace":
                temporaries.remove_path(e.tmp)
        for _, stage in self._dirs:
            temporaries.remove_path(stage)
        for scratch in self._scratch:
            temporaries.remove_path(scratch)
        if not self.done:
            for d in self._made:  # deepest first; only if nothing else appeared there
                try:
                    d.rmdir()
                except OSError:
                    pass
            self._made = []


@contextlib.contextmanager
def transaction() -> Iterator[Transaction]:
    """Open a :class:`Transaction` for a ``with`` block.

    ``with transaction() as tx:`` stage files with ``tx.file`` / ``tx.write`` /
    ``tx.directory``; they are committed together when the block ends without an
    exception, and removed otherwise (also on Ctrl-C).

    Yields
    ------
    Transaction
        The transaction, committed when the block ends normally.
    """
    tx = Transaction()
    try:
        yield tx
        tx.commit()
    finally:
        tx.abort()


@contextlib.contextmanager
def atomic_file(path: StrPath) -> Iterator[Path]:
    """Write one file atomically: yield a temporary path next to ``path``.

    On success the temporary is checked, fsynced and renamed onto ``path``
    (permissions 0666 less the umask). Special files are written through; links to
    regular files are followed.

    Parameters
    ----------
    path : str or os.PathLike
        The destination.

    Yields
    ------
    pathlib.Path
        The temporary path to write to.

    Raises
    ------
    OSError
        Reworded to name ``path`` (not the temporary), for a failure of the block's
        write or of the commit.
    ValueError
        If ``path`` cannot be written
        (:func:`~ocio_thinfilm.io.destinations.destination`).
    """
    with transaction() as tx:
        tmp = tx.file(path)
        try:
            yield tmp
        except OSError as error:
            raise durable.cannot_write(path, error) from None


def _write_through(tmp: Path, dest: Path) -> None:
    """Copy ``tmp`` into the existing special file ``dest`` (never create, never replace)."""
    alias = destinations.fd_alias(dest)
    if alias is not None:  # our own descriptor: keep the shell's mode (> or >>)
        fd = alias
        for stream in (sys.stdout, sys.stderr):
            with contextlib.suppress(Exception):
                stream.flush()
    else:
        try:
            fd = os.open(dest, os.O_WRONLY)  # no O_CREAT, no O_TRUNC: a device or FIFO
        except FileNotFoundError:
            raise OSError(f"cannot write {dest}: it no longer exists") from None
    try:
        with open(tmp, "rb") as src:
            while chunk := src.read(1 << 20):
                durable.write_fd(fd, chunk)
    except OSError as error:
        raise OSError(f"cannot write {dest}: {error.strerror or error}") from None
    finally:
        if alias is None:
            os.close(fd)


@contextlib.contextmanager
def atomic_directory(
    path: StrPath,
    *,
    parameter: str = "out",
    last: Iterable[str] = (),
    keep_others: bool = False,
) -> Iterator[Path]:
    """Write a directory's files together: yield a staging directory for ``path``.

    On success the staged files replace ``path``'s own files (see
    :func:`~ocio_thinfilm.io.ownership.commit_directory`); files in it that this tool
    did not write are never touched.

    Parameters
    ----------
    path : str or os.PathLike
        The output directory: missing, empty or owned (see
        :func:`~ocio_thinfilm.io.ownership.claim_directory`).
    parameter : str, optional
        The caller's name for ``path``, for the error messages (default ``"out"``).
    last : iterable of str, optional
        Relative paths to rename after all others (e.g. ``config.ocio``).
    keep_others : bool, optional
        Keep the files of earlier runs that this one does not write.

    Yields
    ------
    pathlib.Path
        The staging directory.

    Raises
    ------
    ParameterError
        Naming ``parameter``, if ``path`` may not be written (see
        :func:`~ocio_thinfilm.io.ownership.claim_directory`).
    """
    claim = ownership.claim_directory(path, parameter=parameter, last=last, keep_others=keep_others)
    with transaction() as tx:
        yield tx.directory(claim)


def write_text(path: StrPath, text: str) -> Path:
    """Write ``text`` (UTF-8) to the file ``path`` with :func:`atomic_file`.

    Parameters
    ----------
    path : str or os.PathLike
        The destination (a regular file is replaced atomically, a special file written
        through).
    text : str
        The file's content.

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    OSError
        Naming ``path``, if the write or the commit fails.
    ValueError
        If ``path`` cannot be written.
    """
    with atomic_file(path) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")
    return Path(path)
