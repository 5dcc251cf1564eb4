"""Image files through OpenImageIO, written safely.

The file is staged in a :class:`~ocio_thinfilm.io.transactions.Transaction`, and
decoded in full before it may replace anything (OpenImageIO's PNG writer does not
always report a full disk).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ocio_thinfilm.io.destinations import StrPath
from ocio_thinfilm.io.transactions import Transaction, transaction

__all__ = [
    "write_image",
    "read_image",
    "draw_labels",
]

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt


def write_image(
    path: StrPath,
    pixels: npt.ArrayLike,
    *,
    channel_names: Iterable[str] | None = None,
    dtype: str | None = None,
    attributes: Mapping[str, Any] | None = None,
    tx: Transaction | None = None,
) -> Path:
    """Write ``pixels`` with OpenImageIO, safely (see the module docstring).

    OpenImageIO stamps EXRs with the current ``DateTime`` unless an attribute sets it:
    pass a fixed one for byte-reproducible files.

    Parameters
    ----------
    path : str or os.PathLike
        The image file; its extension chooses the format (an EXR is ZIP-compressed
        unless ``attributes`` says otherwise). A name without an extension
        (``/dev/stdout``, a FIFO) is written as PNG.
    pixels : array_like
        (H, W, C) or (H, W) values. Float data written to an 8- or 16-bit file is
        taken as 0..1 and rounded (OpenImageIO's own conversion).
    channel_names : iterable of str, optional
        Names of the C channels (default: OpenImageIO's, R, G, B, A ...).
    dtype : str, optional
        OpenImageIO's pixel type of the file (``"uint8"``, ``"uint16"``, ``"half"``,
        ``"float"`` ...); default uint8 for a PNG (or no extension) and half for
        anything else.
    attributes : mapping, optional
        Metadata: values may be int, float, str, a tuple (list) of ints (e.g. the PNG
        ``CICP``) or of floats (e.g. the
        EXR ``chromaticities``).
    tx : Transaction, optional
        Stage the file in this transaction (committed by the caller) instead of
        committing it on return.

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    OSError
        ``"cannot write <path>: ..."`` if OpenImageIO cannot create or write the file,
        or the written file does not decode in full (e.g. a full disk); nothing is
        then replaced.
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
        if isinstance(value, (tuple, list)) and all(isinstance(v, int) for v in value):
            spec.attribute(key, oiio.TypeDesc(f"int[{len(value)}]"), tuple(value))
        elif isinstance(value, (tuple, list)):
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
    """Read an image with OpenImageIO.

    Parameters
    ----------
    path : str or os.PathLike
        Any image file OpenImageIO reads.

    Returns
    -------
    numpy.ndarray
        float32 (H, W, C) pixels.

    Raises
    ------
    OSError
        ``"cannot read <path>: ..."`` if OpenImageIO cannot read it.
    """
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(str(path))
    if buf.has_error:
        raise OSError(f"cannot read {path}: {buf.geterror()}")
    pixels = buf.get_pixels(oiio.FLOAT)
    assert pixels is not None  # has_error is False: the pixels were read
    return pixels


def draw_labels(
    rgb: np.ndarray,
    labels: Sequence[tuple[float, float, str, float]],
    code: float,
) -> tuple[np.ndarray, bool]:
    """Draw captions with OpenImageIO's ``render_text`` and its bundled font.

    Parameters
    ----------
    rgb : numpy.ndarray
        (H, W, 3) display code values.
    labels : sequence of (float, float, str, float)
        ``(x, y, text, size)`` captions: the text centred at x, its baseline at y
        (pixels, truncated to integers), ``size`` its height in pixels.
    code : float, optional
        The captions' grey, a code value.

    Returns
    -------
    image : numpy.ndarray
        float32 (H, W, 3) with the captions; ``rgb`` itself when there are no labels
        or when a caption could not be drawn (then none is drawn).
    drawn : bool
        Whether the captions were drawn (``True`` without labels).
    """
    if not labels:
        return rgb, True
    import numpy as np
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(oiio.ImageSpec(rgb.shape[1], rgb.shape[0], 3, oiio.FLOAT))
    buf.set_pixels(oiio.ROI(), np.ascontiguousarray(rgb, dtype=np.float32))
    drawn = True
    for x, y, text, size in labels:
        ok = oiio.ImageBufAlgo.render_text(
            buf, int(x), int(y), text, int(size), "", (code, code, code), "center", "baseline", 0
        )
        drawn = drawn and bool(ok)
    if not drawn:
        return rgb, False
    pixels = buf.get_pixels(oiio.FLOAT)
    assert pixels is not None  # the buffer was filled above
    return pixels, True
