"""File output shared by every command: safe writes and image I/O (OpenImageIO).

One implementation, used by ``bake``, ``export``, ``render``, ``demo`` and ``report``:

- **Transactions.** Every output is written aside first (a temporary sibling named
  ``.ocio-thinfilm-tmp-<pid>-<start>-<token>-<name>``), checked (the writer's own
  result, the close, an XML parse of ``.clf``/``.ctf`` files), fsynced, and only then
  renamed into place; a command that writes several files stages them all in one
  :class:`Transaction` and commits them together, so a failure anywhere leaves every
  previous output as it was. Signals are held back (``pthread_sigmask``) while the
  renames run.
- **Special files and links.** An existing destination that is not a regular file
  (``/dev/null``, ``/dev/full``, a FIFO, ``/dev/stdout``, anything reached through
  ``/proc/*/fd``) is *written through*: opened and written, never replaced or
  created. A symbolic link to a regular file (or a dangling one) is followed: its
  target is replaced atomically in the target's directory and the link itself is kept.
  A directory where a file should go is a one-line error.
- **Owned directories.** A directory-valued output (``bake --out``, ``bake --luts``) is
  written only if it is missing, empty, or recognisably ours: it holds the marker
  file :data:`MARKER` listing the files a previous run wrote (or matches the layout of
  a marker-less earlier bake, via the caller's ``legacy`` test). Only listed files are
  replaced or removed; anything else in the directory is left alone. Files are
  renamed one by one with the directory kept (the caller names the file to rename
  last, e.g. ``config.ocio``), the marker always lists every file of ours present, so
  at every instant the directory holds complete files and loads.
- **Stale temporaries** of killed runs (their pid dead, or reused by another process)
  are removed by the next write into the same directory.
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import secrets
import shutil
import signal
import stat
import sys
import tempfile
import threading
from collections.abc import Callable, Iterable, Iterator, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeAlias

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

__all__ = [
    "UsageError",
    "ParameterError",
    "StrPath",
    "MARKER",
    "TMP_PREFIX",
    "Transaction",
    "transaction",
    "atomic_file",
    "atomic_directory",
    "claim_directory",
    "check_writable",
    "check_output_file",
    "clean_stale",
    "is_stdout",
    "write_bytes",
    "write_image",
    "read_image",
    "deferred_signals",
]

#: Prefix of every temporary file or directory this package creates.
TMP_PREFIX = ".ocio-thinfilm-tmp-"
#: Marker file of an owned output directory: one relative path per line.
MARKER = ".ocio-thinfilm-owned"
_MARKER_HEADER = "# ocio-thinfilm: files written by the last run (replaced or removed by the next)"

#: A file-system path as the functions here accept it: a string or a path object.
StrPath: TypeAlias = str | os.PathLike[str]


class UsageError(ValueError):
    """A bad command-line argument: the CLI prints it on one line and exits with 2."""


class ParameterError(ValueError):
    """A library function's argument outside what it allows, naming the Python parameter:
    ``str(error)`` is ``parameter + detail`` (``"index applies to film tables only"``,
    ``"value_range: thickness must not be negative, got -1"``). The command line
    names its option instead (:meth:`for_option`; ``--index applies to ...``)."""

    def __init__(self, parameter: str, detail: str) -> None:
        super().__init__(parameter + detail)
        self.parameter = parameter
        self.detail = detail

    def for_option(self, option: str) -> str:
        """The message with ``option`` (e.g. ``--range``) in place of the parameter."""
        return option + self.detail


# --------------------------------------------------------------------------- #
# Small helpers
# --------------------------------------------------------------------------- #
def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _start_time(pid: int) -> str:
    """The process's start time in clock ticks since boot (Linux), '' if unknown."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            data = f.read()
        return data[data.rindex(b")") + 2 :].split()[19].decode()
    except (OSError, ValueError, IndexError):
        return ""


def _host_key() -> str:
    """8 hex digits naming this machine, boot and pid namespace: a pid in a temporary's
    name is only meaningful where this key matches (not on another host sharing an
    NFS render directory, nor in another container)."""
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


def _self_id() -> str:
    pid = os.getpid()
    if _SELF["pid"] != pid:  # recomputed after a fork
        _SELF.update(pid=pid, start=_start_time(pid) or "0", host=_SELF["host"] or _host_key())
    return f"{_SELF['host']}-{pid}-{_SELF['start']}"


def _tmp_name(label: str) -> str:
    return f"{TMP_PREFIX}{_self_id()}-{secrets.token_hex(4)}-{label}"


_TMP_RE = re.compile(re.escape(TMP_PREFIX) + r"([0-9a-f]{8})-(\d+)-(\d+)-[0-9a-f]+-")


def _is_stale(name: str, directory=None) -> bool:
    """True for a temporary of ours whose process is gone (or whose pid was reused);
    one made on another host or in another container counts as stale after a day."""
    m = _TMP_RE.match(name)
    if not m:
        return False
    _self_id()
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
    now = _start_time(pid)
    return bool(now) and start != "0" and now != start


def _remove(path: Path) -> None:
    try:
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path, ignore_errors=True)
        else:
            path.unlink()
    except FileNotFoundError:
        pass


def clean_stale(directory: StrPath) -> list[Path]:
    """Remove temporaries left in ``directory`` by killed runs; returns what went."""
    removed: list[Path] = []
    try:
        names = os.listdir(directory)
    except OSError:
        return removed
    for name in names:
        if name.startswith(TMP_PREFIX) and _is_stale(name, directory):
            _remove(Path(directory) / name)
            removed.append(Path(directory) / name)
    return removed


def _fsync_dir(directory) -> None:
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


def _fsync_file(path) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    except OSError as error:
        if error.errno not in (errno.EINVAL, errno.EROFS):  # e.g. a pipe: nothing to sync
            raise
    finally:
        os.close(fd)


def _write_fd(fd: int, data: bytes) -> None:
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
        _write_fd(fd, data)
        os.fsync(fd)
    except BaseException:
        os.close(fd)
        raise
    os.close(fd)


_SIGNALS = tuple(
    getattr(signal, s) for s in ("SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT") if hasattr(signal, s)
)


@contextlib.contextmanager
def deferred_signals() -> Iterator[None]:
    """Hold SIGINT/SIGTERM/SIGHUP/SIGQUIT back for the duration (main thread only):
    the renames of a commit run to the end; a pending signal is delivered after."""
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


def _cannot_write(dest, error: OSError) -> OSError:
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
_CHECKS = {".clf": check_xml, ".ctf": check_xml}


def _fault(point: str) -> None:
    """Test hook: ``OCIO_THINFILM_FAULT=<point>`` kills the process at that point
    (used by the tests to kill a bake at every step of its commit)."""
    want = os.environ.get("OCIO_THINFILM_FAULT")
    if want and want == point:
        os.kill(os.getpid(), signal.SIGKILL)


# --------------------------------------------------------------------------- #
# Destinations
# --------------------------------------------------------------------------- #
_FD_ALIAS = re.compile(r"/dev/(stdin|stdout|stderr)|/dev/fd/(\d+)|/proc/self/fd/(\d+)")


def _fd_alias(p: Path):
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
        _fd_alias(Path(path)) == 1
        or (a.st_dev, a.st_ino) == (b.st_dev, b.st_ino)
        and not stat.S_ISCHR(a.st_mode)
    )


def _destination(path) -> tuple[str, Path]:
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
    if _fd_alias(p) is not None or _via_proc(p):  # /dev/stdout redirected to a file
        return "through", p
    real = Path(os.path.realpath(p))
    if st is None and real.parent.exists() and not real.parent.is_dir():
        raise ValueError(f"{real.parent} is not a directory")
    return "replace", real if p.is_symlink() else p


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
    """

    def __init__(self):
        self._files: list[_Entry] = []
        self._dirs: list[tuple[Claim, Path]] = []
        self._lock = threading.Lock()
        self._scratch: list[Path] = []
        self._cleaned: set[str] = set()
        self._made: list[Path] = []  # directories created for this transaction
        self.done = False

    def _mkdirs(self, directory: Path) -> None:
        """Create ``directory`` and its missing parents, remembering them (an aborted
        transaction removes them again if they are still empty)."""
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
            clean_stale(directory)

    def file(self, path: StrPath, *, check: Callable[[Path], object] | None = None) -> Path:
        """Stage ``path``: returns the temporary path its content must be written to.
        ``check(tmp)`` (optional) raises if the written file is wrong."""
        mode, dest = _destination(path)
        with self._lock:
            if any(e.dest == dest for e in self._files):
                raise ValueError(f"{dest} would be written twice")
            if mode == "replace":
                self._mkdirs(dest.parent)
                self._clean(dest.parent)
                tmp = dest.parent / _tmp_name(dest.name)
            else:
                scratch = Path(tempfile.mkdtemp(prefix=_tmp_name("through")))
                self._scratch.append(scratch)
                tmp = scratch / (dest.name or "out")
            self._files.append(_Entry(dest, tmp, mode, check))
        return tmp

    def write(self, path: StrPath, data: str | bytes) -> Path:
        """Stage ``path`` with ``data`` (bytes or str, UTF-8), written and fsynced now."""
        tmp = self.file(path)
        try:
            write_bytes(tmp, data.encode("utf-8") if isinstance(data, str) else bytes(data))
        except OSError as error:
            raise _cannot_write(path, error) from None
        return tmp

    def directory(self, claim: Claim) -> Path:
        """A new, empty staging directory for ``claim`` (on the same filesystem)."""
        with self._lock:
            if claim.exists:
                self._clean(claim.path)
                stage = claim.path / _tmp_name("stage")
            else:
                self._mkdirs(claim.path.parent)
                self._clean(claim.path.parent)
                stage = claim.path.parent / _tmp_name(claim.path.name)
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
                if e.dest.suffix.lower() in _CHECKS:
                    _CHECKS[e.dest.suffix.lower()](e.tmp, e.dest)
                if e.check:
                    e.check(e.tmp)
                _fsync_file(e.tmp)
            except OSError as error:
                raise _cannot_write(e.dest, error) from None
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
                    if Path(rel).suffix.lower() in _CHECKS:
                        _CHECKS[Path(rel).suffix.lower()](stage / rel, target)
                    _fsync_file(stage / rel)
                except OSError as error:
                    raise _cannot_write(target, error) from None
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
        if self.done:
            return
        _fault("before-commit")
        plans = self._verify()
        umask = _umask()
        # Special files first, with signals deliverable: opening a FIFO waits for its
        # reader, and Ctrl-C must still end that wait.
        for e in self._files:
            if e.mode == "through":
                _write_through(e.tmp, e.dest)
        with deferred_signals():
            for e in self._files:
                if e.mode == "replace":
                    os.chmod(e.tmp, 0o666 & ~umask)
                    os.replace(e.tmp, e.dest)
                    _fsync_dir(e.dest.parent)
            for claim, stage, files in plans:
                _commit_directory(claim, stage, files, umask)
            self.done = True
        self.abort()  # scratch directories

    def abort(self) -> None:
        for e in self._files:
            if e.mode == "replace":
                _remove(e.tmp)
        for _, stage in self._dirs:
            _remove(stage)
        for scratch in self._scratch:
            _remove(scratch)
        if not self.done:
            for d in self._made:  # deepest first; only if nothing else appeared there
                try:
                    d.rmdir()
                except OSError:
                    pass
            self._made = []


@contextlib.contextmanager
def transaction() -> Iterator[Transaction]:
    """``with transaction() as tx:`` stage files with ``tx.file`` / ``tx.write`` /
    ``tx.directory``; they are committed together when the block ends without an
    exception, and removed otherwise (also on Ctrl-C)."""
    tx = Transaction()
    try:
        yield tx
        tx.commit()
    finally:
        tx.abort()


@contextlib.contextmanager
def atomic_file(path: StrPath, suffix: str | None = None) -> Iterator[Path]:
    """Yield a temporary path next to ``path``; on success it is checked, fsynced and
    renamed onto ``path`` (permissions 0666 less the umask). Special files are
    written through; links to regular files are followed."""
    with transaction() as tx:
        tmp = tx.file(path)
        try:
            yield tmp
        except OSError as error:
            raise _cannot_write(path, error) from None


def _write_through(tmp: Path, dest: Path) -> None:
    """Copy ``tmp`` into the existing special file ``dest`` (never create, never replace)."""
    alias = _fd_alias(dest)
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
                _write_fd(fd, chunk)
    except OSError as error:
        raise OSError(f"cannot write {dest}: {error.strerror or error}") from None
    finally:
        if alias is None:
            os.close(fd)


# --------------------------------------------------------------------------- #
# Owned directories
# --------------------------------------------------------------------------- #
class Claim:
    """A directory this run may write: where, whether it exists, which files in it are
    ours (relative POSIX paths), and the parameter that named it (for messages)."""

    def __init__(self, path: Path, exists: bool, owned: set, parameter: str, last=()):
        self.path, self.exists, self.owned, self.parameter = path, exists, owned, parameter
        self.last = tuple(last)


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
    legacy: Callable[[Path], set[str] | None] | None = None,
    last: Iterable[str] = (),
) -> Claim:
    """Check that ``path`` may be (re)written as an output directory of this tool.

    Allowed: missing, empty, holding :data:`MARKER`, or ``legacy(path)`` returning the
    set of files a marker-less earlier run wrote there. Anything else is a
    :class:`ParameterError` naming ``parameter`` (the caller's name for ``path``): the
    directory holds files this tool did not write. ``last``: relative paths to rename
    after all others (e.g. ``config.ocio``).
    """
    text = os.fspath(path)
    if text.strip() == "":
        raise ParameterError(parameter, " must name a directory, got an empty string")
    p = Path(text)
    if p.is_symlink() and p.exists():
        p = Path(os.path.realpath(p))  # keep the link, write into what it points to
    if p.exists() and not p.is_dir():
        raise ParameterError(parameter, f" {p}: exists and is not a directory")
    if not p.exists():
        check_writable(p)
        return Claim(p, False, set(), parameter, last)
    check_writable(p)
    clean_stale(p)
    names = [n for n in os.listdir(p) if not n.startswith(TMP_PREFIX)]
    owned: set | None
    if MARKER in names:
        if not (p / MARKER).is_file():
            raise ParameterError(parameter, f" {p}: {MARKER} is not a file")
        owned = _read_marker(p / MARKER)
    elif not names:
        owned = set()
    else:
        owned = legacy(p) if legacy else None
        if owned is None:
            raise ParameterError(
                parameter,
                f" {p}: directory is not empty and was not written "
                f"by ocio-thinfilm (no {MARKER}); give a new or "
                "empty directory",
            )
    return Claim(p, True, set(owned), parameter, last)


def _write_marker(directory: Path, files, umask) -> None:
    body = "\n".join([_MARKER_HEADER] + sorted(files)) + "\n"
    tmp = directory / _tmp_name(MARKER.lstrip("."))
    write_bytes(tmp, body.encode("utf-8"))
    os.chmod(tmp, 0o666 & ~umask)
    os.replace(tmp, directory / MARKER)


def _commit_directory(claim: Claim, stage: Path, files: list, umask: int) -> None:
    new = set(files)
    for d in [stage, *(p for p in stage.rglob("*") if p.is_dir())]:
        os.chmod(d, 0o777 & ~umask)
    for rel in files:
        os.chmod(stage / rel, 0o666 & ~umask)
    if not claim.exists:
        _write_marker(stage, new, umask)
        _fsync_dir(stage)
        try:
            os.rename(stage, claim.path)  # atomic: the directory appears complete
            _fsync_dir(claim.path.parent)
            return
        except OSError:
            if not claim.path.is_dir():
                raise
            claim.exists = True  # created meanwhile: fall back to file-by-file
            names = [n for n in os.listdir(claim.path) if not n.startswith(TMP_PREFIX)]
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
        _fault("after-marker")
        # 2. file by file, the caller's "last" files (config.ocio) at the end
        order = [r for r in files if r not in claim.last] + [r for r in claim.last if r in new]
        for i, rel in enumerate(order):
            target = claim.path / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            os.replace(stage / rel, target)
            _fault(f"rename-{i}")
        for d in {(claim.path / r).parent for r in order}:
            _fsync_dir(d)
        _fault("after-renames")
        # 3. files of the previous run that this one does not write
        for rel in sorted(old - new):
            target = claim.path / rel
            if target.is_file() or target.is_symlink():
                target.unlink()
        # 4. the marker lists exactly what is there now
        _write_marker(claim.path, new, umask)
        _fsync_dir(claim.path)
        _fault("after-commit")
    finally:
        os.close(lock)
        _remove(stage)


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
        mode, dest = _destination(path)
    except ValueError as error:
        raise ParameterError(parameter, f" {error}") from None
    if mode == "replace":
        check_writable(dest.parent)
    return Path(path)


@contextlib.contextmanager
def atomic_directory(
    path: StrPath,
    *,
    parameter: str = "out",
    legacy: Callable[[Path], set[str] | None] | None = None,
    last: Iterable[str] = (),
) -> Iterator[Path]:
    """Yield a staging directory whose files replace ``path``'s own files on success.

    ``path`` must be missing, empty or owned (see :func:`claim_directory`); files in it
    that this tool did not write are never touched."""
    claim = claim_directory(path, parameter=parameter, legacy=legacy, last=last)
    with transaction() as tx:
        yield tx.directory(claim)


# --------------------------------------------------------------------------- #
# Images
# --------------------------------------------------------------------------- #
def write_image(
    path: StrPath,
    pixels: npt.ArrayLike,
    *,
    channel_names: Iterable[str] | None = None,
    dtype: str | None = None,
    attributes: Mapping[str, Any] | None = None,
    tx: Transaction | None = None,
) -> Path:
    """Write ``pixels`` (H, W, C) with OpenImageIO, safely (see the module docstring).

    ``dtype`` defaults to uint8 for .png and half for .exr. Float data written to an
    8-bit file is taken as 0..1 and rounded (OpenImageIO's own conversion).
    ``attributes`` values may be int, float, str or a tuple of floats (e.g. the EXR
    ``chromaticities``). OpenImageIO stamps EXRs with the current ``DateTime``
    unless an attribute sets it: pass a fixed one for byte-reproducible files.
    ``tx``: stage the file in this :class:`Transaction` (committed by the caller)
    instead of committing it on return.
    """
    if tx is None:
        with transaction() as own:
            return write_image(
                path,
                pixels,
                channel_names=channel_names,
                dtype=dtype,
                attributes=attributes,
                tx=own,
            )
    import numpy as np
    import OpenImageIO as oiio

    path = Path(path)
    pixels = np.ascontiguousarray(pixels)
    if pixels.ndim == 2:
        pixels = pixels[:, :, None]
    h, w, c = pixels.shape
    # A name without an extension (/dev/stdout, a FIFO) is written as PNG.
    ext = path.suffix.lower() or ".png"
    if dtype is None:
        dtype = "uint8" if ext == ".png" else "half"
    spec = oiio.ImageSpec(w, h, c, dtype)
    if channel_names:
        spec.channelnames = tuple(channel_names)
    if ext == ".exr":
        spec.attribute("compression", "zip")
    for key, value in (attributes or {}).items():
        if isinstance(value, (tuple, list)):
            spec.attribute(key, oiio.TypeDesc(f"float[{len(value)}]"), tuple(map(float, value)))
        else:
            spec.attribute(key, value)
    tmp = tx.file(path)
    out = oiio.ImageOutput.create(str(path) if path.suffix else ext.lstrip("."))
    if out is None:
        raise OSError(f"cannot write {path}: {oiio.geterror() or 'unknown image format'}")
    if not out.open(str(tmp), spec):
        raise OSError(f"cannot write {path}: {out.geterror() or oiio.geterror()}")
    ok = out.write_image(pixels.astype(np.float32) if pixels.dtype.kind == "f" else pixels)
    closed = out.close()
    # OpenImageIO's PNG writer reports short writes (a full disk) only through
    # geterror(): any message there is a failure, whatever the return values said.
    message = out.geterror()
    if not (ok and closed) or message:
        first = (message or "write failed").strip().splitlines()[0]
        raise OSError(f"cannot write {path}: {first}")
    # It does not always say even that (a full disk can leave a 0-byte PNG and report
    # success): decode what was written, in full, before it may replace anything.
    _check_image_file(tmp, path, (h, w, c))
    return path


def _check_image_file(tmp, path, shape) -> None:
    import OpenImageIO as oiio

    h, w, c = shape
    inp = oiio.ImageInput.open(str(tmp))
    if inp is None:
        raise OSError(
            f"cannot write {path}: the written file does not read back "
            f"({(oiio.geterror() or 'unreadable').strip().splitlines()[0]}); "
            "disk full?"
        )
    try:
        spec = inp.spec()
        data = (
            inp.read_image(0, 0, 0, c, "uint8")
            if (spec.width, spec.height, spec.nchannels) == (w, h, c)
            else None
        )
        problem = inp.geterror()
    finally:
        inp.close()
    if data is None or problem or _np_shape(data) != (h, w, c):
        raise OSError(
            f"cannot write {path}: the written file is incomplete "
            f"({(problem or 'wrong size').strip().splitlines()[0]}); disk full?"
        )


def _np_shape(a):
    return tuple(getattr(a, "shape", ()))


def read_image(path: StrPath) -> np.ndarray:
    """Read an image as float32 (H, W, C) with OpenImageIO."""
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(str(path))
    if buf.has_error:
        raise OSError(f"cannot read {path}: {buf.geterror()}")
    pixels = buf.get_pixels(oiio.FLOAT)
    assert pixels is not None  # has_error is False: the pixels were read
    return pixels
