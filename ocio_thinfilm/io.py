"""File output shared by every command: atomic writes and image I/O (OpenImageIO).

Nothing is ever half-written: files go to a temporary sibling and are renamed into
place; whole directories are built aside and swapped in.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from pathlib import Path

import numpy as np

__all__ = ["UsageError", "atomic_file", "atomic_directory", "check_writable", "write_image",
           "read_image"]


class UsageError(ValueError):
    """A bad command-line argument: the CLI prints it on one line and exits with 2."""


def check_writable(directory) -> Path:
    """Fail early, with a one-line error, if ``directory`` cannot be created or written."""
    d = Path(directory)
    probe = d
    while not probe.exists():
        probe = probe.parent
    if not probe.is_dir() or not os.access(probe, os.W_OK | os.X_OK):
        raise UsageError(f"{d}: directory is not writable")
    try:  # access() says yes to root everywhere (even /proc): try a real file, kept nowhere
        with tempfile.TemporaryFile(dir=probe):
            pass
    except OSError:
        raise UsageError(f"{d}: directory is not writable") from None
    return d


@contextlib.contextmanager
def atomic_file(path, suffix=None):
    """Yield a temporary path next to ``path``; on success rename it onto ``path``
    with the permissions a plain ``open()`` would have given (0666 less the umask)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}.", suffix=suffix or path.suffix,
                               dir=path.parent)
    os.close(fd)
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


@contextlib.contextmanager
def atomic_directory(path):
    """Yield an empty temporary directory next to ``path``; on success it replaces
    ``path`` (the old one is removed only after the new one is complete)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{path.name}.", dir=path.parent))
    old = path.parent / f".{path.name}.old"
    try:
        yield tmp
        os.chmod(tmp, 0o777 & ~_umask())
        if old.exists():
            shutil.rmtree(old)
        if path.exists():
            os.replace(path, old)
        os.replace(tmp, path)
        shutil.rmtree(old, ignore_errors=True)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def write_image(path, pixels, *, channel_names=None, dtype=None, attributes=None):
    """Write ``pixels`` (H, W, C) with OpenImageIO, atomically.

    ``dtype`` defaults to uint8 for .png and half for .exr. Float data written to an
    8-bit file is taken as 0..1 and rounded (OpenImageIO's own conversion).
    ``attributes`` values may be int, float, str or a tuple of floats (e.g. the EXR
    ``chromaticities``). OpenImageIO stamps EXRs with the current ``DateTime``
    unless an attribute sets it: pass a fixed one for byte-reproducible files.
    """
    import OpenImageIO as oiio

    path = Path(path)
    check_writable(path.parent)
    pixels = np.ascontiguousarray(pixels)
    if pixels.ndim == 2:
        pixels = pixels[:, :, None]
    h, w, c = pixels.shape
    if dtype is None:
        dtype = "uint8" if path.suffix.lower() == ".png" else "half"
    spec = oiio.ImageSpec(w, h, c, dtype)
    if channel_names:
        spec.channelnames = tuple(channel_names)
    if path.suffix.lower() == ".exr":
        spec.attribute("compression", "zip")
    for key, value in (attributes or {}).items():
        if isinstance(value, (tuple, list)):
            spec.attribute(key, oiio.TypeDesc(f"float[{len(value)}]"), tuple(map(float, value)))
        else:
            spec.attribute(key, value)
    with atomic_file(path) as tmp:
        out = oiio.ImageOutput.create(str(path))
        if out is None or not out.open(str(tmp), spec):
            raise OSError(f"cannot write {path}: {oiio.geterror()}")
        ok = out.write_image(pixels.astype(np.float32) if pixels.dtype.kind == "f" else pixels)
        out.close()
        if not ok:
            raise OSError(f"cannot write {path}: {out.geterror()}")
    return path


def read_image(path) -> np.ndarray:
    """Read an image as float32 (H, W, C) with OpenImageIO."""
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(str(path))
    if buf.has_error:
        raise OSError(f"cannot read {path}: {buf.geterror()}")
    return buf.get_pixels(oiio.FLOAT)
