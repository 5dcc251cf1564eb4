"""Standalone LUT files (``ocio-thinfilm export``) and the shipped ``luts/`` set.

Every file is written by OpenColorIO's own writers
(``GroupTransform.write`` for CLF, ``Baker`` for .cube / .spi1d / .spi3d / .csp),
atomically (:mod:`ocio_thinfilm.io`), and without timestamps, so equal inputs give equal
bytes. Every file takes the value itself as input (no hand scaling):

- ``film`` / ``morpho``: a 1D table over ``--range`` (thickness in um, or cos(theta));
  output CIE-XYZ-D65, or with ``--display`` the clipped display-linear RGB;
- ``clip``: the constant-lightness clip of one display as a 3D LUT over display-linear
  RGB in ``--range``;
- ``view`` (:mod:`ocio_thinfilm.export.view`): a whole display/view of the config.

How each format carries the range: docs/config.md, *Design notes*.

Functions: :func:`lut_contents`, :func:`write_lut`, :func:`export_lut`, :func:`progress_bar`
(the shipped set, ``luts/``: :func:`ocio_thinfilm.export.bake.export_set`).
"""

from __future__ import annotations

import math
import numbers
import sys
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.checks import ParameterError, as_choice, as_pair, as_real
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.io import StrPath, atomic_file, check_output_file
from ocio_thinfilm.lut import ocio_ops, tables

if TYPE_CHECKING:
    from tqdm import tqdm

__all__ = [
    "CLF_WRITER",
    "LUT_FORMATS",
    "FORMATS",
    "TABLES",
    "DEFAULT_SIZE",
    "DEFAULT_RANGE",
    "lut_format",
    "lut_contents",
    "write_lut",
    "export_lut",
    "LogProgress",
    "progress_bar",
]

#: OpenColorIO's name of its CLF writer (``GroupTransform.write``, ``Baker.setFormat``).
CLF_WRITER = "Academy/ASC Common LUT Format"
#: Every LUT file format the package writes: name (= extension) -> (OCIO writer format,
#: file extension, LUT dimensions it can hold).
LUT_FORMATS = {
    "clf": (CLF_WRITER, "clf", (1, 3)),
    "ctf": ("Color Transform Format", "ctf", (1, 3)),
    "cube": ("resolve_cube", "cube", (1, 3)),
    "spi1d": ("spi1d", "spi1d", (1,)),
    "spi3d": ("spi3d", "spi3d", (3,)),
    "csp": ("cinespace", "csp", (3,)),
}
#: The formats of the tables and the clip (``export film|morpho|clip``, ``bake --luts``):
#: all but CTF, OpenColorIO's own superset of CLF, which only whole views are written in.
FORMATS = {name: spec for name, spec in LUT_FORMATS.items() if name != "ctf"}
TABLES = ("film", "morpho", "clip")


def lut_format(
    out: StrPath | None, fmt: str | None, formats: Mapping[str, Any], default: str
) -> str:
    """Return the format of a LUT file: ``fmt``, else told from ``out``'s extension.

    Parameters
    ----------
    out : str or os.PathLike or None
        The output file (``None``: the default file name).
    fmt : str or None
        The format asked for.
    formats : mapping
        The allowed formats (name -> (OCIO writer, extension, dimensions)).
    default : str
        The format without ``out`` and ``fmt``.

    Returns
    -------
    str
        A key of ``formats``.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``fmt``) an unknown format, no format told from ``out``, or a format whose
        files end otherwise than ``out``'s LUT extension (a .cube written into a
        ``.spi1d`` name would mislead every host that reads by extension).

    Examples
    --------
    >>> lut_format("a.spi1d", None, FORMATS, "clf"), lut_format(None, "csp", FORMATS, "clf")
    ('spi1d', 'csp')
    """
    suffix = Path(out).suffix.lstrip(".").lower() if out else ""
    if fmt is None:
        fmt = suffix if out else default
        if fmt not in formats:
            raise ParameterError(
                "fmt", f" is needed: no format can be told from {out!r} ({', '.join(formats)})"
            )
        return fmt
    fmt = as_choice("fmt", fmt, formats)
    known = {spec[1] for spec in LUT_FORMATS.values()}
    if suffix in known and suffix != formats[fmt][1]:
        raise ParameterError(
            "fmt",
            f" {fmt} writes .{formats[fmt][1]} files, but {out} ends in .{suffix}: "
            "give a matching name or leave the format to the extension",
        )
    return fmt


#: Formats with no way to state their input domain: only usable over exactly [0, 1].
NO_DOMAIN = ("spi3d",)
_FILM_DEFAULTS = registry.thin_film_space_for_kind("phase-change")
_MORPHO_DEFAULTS = registry.thin_film_space_for_kind("morpho")
#: Default entries and input range of each table: the thin-film spaces' (registry), and
#: for the clip over display-linear RGB a 33^3 grid over [-0.5, 1.5].
DEFAULT_SIZE = {
    "film": _FILM_DEFAULTS.default_size,
    "morpho": _MORPHO_DEFAULTS.default_size,
    "clip": 33,
}
MAX_SIZE = {"film": 1 << 20, "morpho": 1 << 20, "clip": 129}
DEFAULT_RANGE = {
    "film": _FILM_DEFAULTS.default_range,
    "morpho": _MORPHO_DEFAULTS.default_range,
    "clip": (-0.5, 1.5),
}


# --------------------------------------------------------------------------- #
# Validation
# --------------------------------------------------------------------------- #
def _validate(table, kind, display, index, value_range, size, fmt):
    as_choice("table", table, TABLES)
    as_choice("fmt", fmt, FORMATS)
    dims = 3 if table == "clip" else 1
    if dims not in FORMATS[fmt][2]:
        allowed = [f for f, spec in FORMATS.items() if dims in spec[2]]
        raise ValueError(
            f"format {fmt} cannot hold a {dims}D LUT; for {table} use {', '.join(allowed)}"
        )
    if display is not None:
        as_choice("display", display, clip.DISPLAYS)
    if table == "clip" and display is None:
        raise ParameterError("display", " is required for the clip (the gamut to clip into)")
    as_choice("kind", kind, colorimetry.FILM_KINDS)
    if index is not None:
        index = as_real("index", index)
        if table != "film":
            raise ParameterError("index", " applies to film tables only")
        if not (math.isfinite(index) and 1.0 <= index <= 10.0):
            raise ParameterError("index", f" must be a refractive index in [1, 10], got {index:g}")
    size = DEFAULT_SIZE[table] if size is None else size
    if isinstance(size, bool) or not isinstance(size, numbers.Integral):
        raise TypeError(f"size must be an integer, got {size!r} ({type(size).__name__})")
    if not 2 <= int(size) <= MAX_SIZE[table]:
        raise ParameterError("size", f" must be in [2, {MAX_SIZE[table]}] for {table}, got {size}")
    lo, hi = DEFAULT_RANGE[table] if value_range is None else as_pair("value_range", value_range)
    if not (math.isfinite(lo) and math.isfinite(hi)) or lo >= hi:
        raise ParameterError(
            "value_range", f" must be two finite numbers MIN < MAX, got {lo:g} {hi:g}"
        )
    if table == "film" and lo < 0:
        raise ParameterError("value_range", f": thickness must not be negative, got {lo:g}")
    if table == "morpho" and (lo < 0 or hi > 1):
        raise ParameterError("value_range", f": cos(theta) must lie in [0, 1], got {lo:g} {hi:g}")
    if table == "clip" and (lo > 0 or hi < 1):
        raise ParameterError("value_range", f" must contain [0, 1] for clip, got {lo:g} {hi:g}")
    if table == "film" and hi > 1000:
        raise ParameterError(
            "value_range", f": thickness above 1000 um is the incoherent grey; got {hi:g}"
        )
    if fmt in NO_DOMAIN and (lo, hi) != (0.0, 1.0):
        usable = [f for f in FORMATS if f not in NO_DOMAIN and dims in FORMATS[f][2]]
        raise ValueError(
            f"format {fmt} has no input domain (it always takes 0..1), so it "
            f"cannot take {table} input over {lo:g}..{hi:g}; use "
            f"{', '.join(usable)}"
        )
    return size, (float(lo), float(hi))


# --------------------------------------------------------------------------- #
# LUT contents
# --------------------------------------------------------------------------- #
def _stem(table, kind, display, index):
    if table == "clip":
        stem = registry.CLIP_FILE_STEM
    else:
        stem = registry.thin_film_space_for_kind(kind if table == "film" else "morpho").file_stem
        if index is not None:
            stem += f"_n{index:g}"
    if display is not None:
        stem += "_" + registry.as_display(display, hdr=False).lut_stem
    return stem


def lut_contents(
    table: str,
    *,
    kind: str = "phase-change",
    display: registry.DisplayLike | None = None,
    index: float | None = None,
    value_range: Sequence[float] | None = None,
    size: int | None = None,
    progress: Callable[[float], object] | None = None,
) -> tuple[np.ndarray, ocio_ops.Transform, dict[str, Any]]:
    """Compute one standalone LUT: its values, its transform and its metadata.

    Parameters
    ----------
    table : str
        ``"film"`` (thickness table), ``"morpho"`` (angle table) or ``"clip"`` (the
        constant-lightness clip as a 3D LUT over display-linear RGB).
    kind : str, optional
        The film kind, ``"phase-change"`` (default) or ``"no-phase-change"``; checked
        for every table, used by ``"film"``.
    display : str or Display, optional
        An SDR display of :data:`ocio_thinfilm.registry.DISPLAYS` (or the registry's
        object): the gamut to clip into. Required for ``"clip"``; for a table it makes
        the output clipped display-linear RGB instead of CIE XYZ. Default ``None``.
    index : float, optional
        For ``"film"`` only: a refractive index n in [1, 10] that makes the input the
        physical thickness t (t' = n t, normal incidence). Default ``None``.
    value_range : sequence of two floats, optional
        The input range MIN < MAX: thickness in micrometres (film: from 0, at most
        1000), cos(theta) within [0, 1] (morpho), display-linear RGB per channel
        containing [0, 1] (clip). Default :data:`DEFAULT_RANGE`.
    size : int, optional
        Entries (1D) or grid edge (3D), an integer in [2, 1048576] for the tables and
        [2, 129] for the clip. Default :data:`DEFAULT_SIZE`.
    progress : callable, optional
        ``progress(fraction)``, called with fractions of the work that add up to 1.

    Returns
    -------
    values : numpy.ndarray
        (size, 3) or (size, size, size, 3), on the uniform grid over the normalised
        input p in [0, 1].
    lut : PyOpenColorIO.Transform
        The LUT1D or LUT3D transform of ``values``.
    meta : dict
        ``name`` (the file stem), ``input``, ``output``, ``description``, ``range``
        (lo, hi), ``size`` and ``id``.

    Raises
    ------
    TypeError
        For a ``size``, ``index`` or ``value_range`` that is not numbers, or a display
        object that is neither a name nor a registry display.
    ParameterError
        Naming the parameter, for a value it does not allow (an unknown table, kind or
        display, a missing display for ``"clip"``, an ``index`` for another table or
        out of range, a ``size`` or ``value_range`` out of range).
    """
    display = registry.display_name(display)
    size, value_range = _validate(table, kind, display, index, value_range, size, "clf")
    return _contents(table, kind, display, index, value_range, size, progress)


def _contents(table, kind, display, index, value_range, size, progress):
    """Compute :func:`lut_contents` of arguments already validated."""
    lo, hi = value_range
    x = np.linspace(lo, hi, size)
    if table == "film":
        n = 1.0 if index is None else index
        chunks = np.array_split(x, max(1, size // 8192))
        parts = []
        for chunk in chunks:
            parts.append(colorimetry.film_XYZ(chunk * n * 1000.0, kind, step=tables.SPECTRAL_STEP))
            if progress:
                progress(len(chunk) / size)
        values = np.concatenate(parts)
        what = (
            f"physical thickness t in um (t' = {n:g} t)"
            if index is not None
            else "optical thickness t' = n t cos(theta_t) in um"
        )
        description = (
            f"Smits & Meyer 1990 {kind} thin film, {size} entries uniform over {lo:g}-{hi:g} um"
        )
    elif table == "morpho":
        values = colorimetry.morpho_XYZ(
            np.degrees(np.arccos(np.clip(x, 0.0, 1.0))), step=tables.SPECTRAL_STEP
        )
        if progress:
            progress(1.0)
        what = "cos(theta), the facing ratio N.V"
        description = (
            f"Smits & Meyer 1990 Morpho multilayer (Eq. 9 + 14), {size} entries "
            f"uniform over cos(theta) {lo:g}-{hi:g}"
        )
    else:
        g = np.stack(np.meshgrid(x, x, x, indexing="ij"), axis=-1)
        values = clip.clip_RGB(g, display)
        if progress:
            progress(1.0)
        what = f"{display} display-linear RGB"
        description = (
            f"Smits & Meyer 1990 constant-lightness clip into {display} "
            f"(Section 3.2), {size}^3 tetrahedral LUT3D over display-linear RGB "
            f"{lo:g}..{hi:g} per channel"
        )
    if table != "clip":
        if display is None:
            output = "CIE-XYZ-D65 (perfect reflector Y = 1), unclipped"
        else:
            values = clip.clip_RGB(colorimetry.XYZ_to_RGB(values, display), display)
            output = f"{display} display-linear RGB, constant-lightness clipped"
            description += f", clipped into {display}"
        lut = ocio_ops.lut1d_transform(values)
    else:
        output = f"{display} display-linear RGB, constant-lightness clipped"
        lut = ocio_ops.lut3d_transform(values)
    meta = dict(
        name=_stem(table, kind, display, index),
        input=what,
        output=output,
        description=description,
        range=(lo, hi),
        size=size,
        id=ocio_ops.transform_id("Export", _stem(table, kind, display, index)),
    )
    return values, lut, meta


def _baker_config(lut, lo, hi):
    """Return a minimal in-memory config for baking ``lut`` over the input domain [lo, hi].

    - ``input`` (the reference): the raw value -- thickness, cos(theta) or RGB;
    - ``output``: from the reference, the range matrix (x - lo) / (hi - lo) then ``lut``;
    - ``domain``: an affine shaper space, [0, 1] <-> [lo, hi]. Given as the Baker's
      shaper space it makes the writers state the domain in the file: ``.cube``
      ``LUT_1D_INPUT_RANGE lo hi`` (1D) or an exact affine 1D shaper before the 3D LUT,
      ``.spi1d`` ``From lo hi``, ``.csp`` a prelut.
    """
    import PyOpenColorIO as ocio

    span = hi - lo
    config = ocio.Config.CreateRaw()
    config.setVersion(2, 1)
    for name in list(config.getColorSpaceNames()):
        config.removeColorSpace(name)
    ref = ocio.ColorSpace()
    ref.setName("input")
    config.addColorSpace(ref)
    out = ocio.ColorSpace()
    out.setName("output")
    out.setTransform(
        ocio_ops.group([ocio_ops.matrix(np.eye(3) / span, [-lo / span] * 3), lut]),
        ocio.COLORSPACE_DIR_FROM_REFERENCE,
    )
    config.addColorSpace(out)
    domain = ocio.ColorSpace()
    domain.setName("domain")
    domain.setTransform(
        ocio_ops.matrix(np.eye(3) * span, [lo] * 3), ocio.COLORSPACE_DIR_TO_REFERENCE
    )
    config.addColorSpace(domain)
    config.setRole("scene_linear", "input")
    return config


#: Entries of the affine shaper / prelut that carries a 3D LUT's domain (.cube, .csp).
#: The shaper is a straight line, so any size is exact; 1024 keeps ffmpeg's .csp
#: prelut resampling (it interpolates between knots without dividing by their spacing)
#: within 1/1023 of the grid coordinate.
DOMAIN_SHAPER_SIZE = 1024


def write_lut(
    path: StrPath, fmt: str, values: np.ndarray, lut: ocio_ops.Transform, meta: Mapping[str, Any]
) -> Path:
    """Write one LUT file with OCIO's writer for ``fmt``, atomically.

    Every format takes the value itself: the domain ``meta["range"]`` is carried by the
    file (CLF: a range matrix before the LUT; the others: the Baker's shaper).

    Parameters
    ----------
    path : str or os.PathLike
        The file to write.
    fmt : str
        A key of :data:`FORMATS` that can hold the LUT's dimension (not checked here:
        :func:`export_lut` checks it).
    values : numpy.ndarray
        The LUT's values (:func:`lut_contents`): (size, 3) or (size, size, size, 3).
    lut : PyOpenColorIO.Transform
        The LUT's transform (:func:`lut_contents`).
    meta : mapping
        Its metadata (:func:`lut_contents`): ``name``, ``id``, ``description``,
        ``input``, ``output``, ``range`` and ``size``.

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    ValueError
        For a format without an input domain (``spi3d``) and a range other than
        [0, 1].
    OSError
        If the file cannot be written.
    """
    import PyOpenColorIO as ocio

    writer, ext, _ = FORMATS[as_choice("fmt", fmt, FORMATS)]
    path = Path(path)
    lo, hi = meta["range"]
    if fmt in NO_DOMAIN and (lo, hi) != (0.0, 1.0):
        raise ValueError(f"format {fmt} has no input domain; cannot hold {lo:g}..{hi:g}")
    with atomic_file(path) as tmp:
        if fmt == "clf":
            span = hi - lo
            ops = []
            if (lo, hi) != (0.0, 1.0):
                ops.append(ocio_ops.matrix(np.eye(3) / span, [-lo / span] * 3))
            ops.append(lut)
            g = ocio_ops.group(
                ops,
                name=meta["name"],
                id=meta["id"],
                description=meta["description"],
                input_descriptor=meta["input"],
                output_descriptor=meta["output"],
            )
            g.write(writer, str(tmp), ocio.Config.CreateRaw())
        else:
            baker = ocio.Baker()
            baker.setConfig(_baker_config(lut, lo, hi))
            baker.setFormat(writer)
            baker.getFormatMetadata().addChildElement(
                "Description",
                f"{meta['name']}: input {meta['input']}, {lo:g}..{hi:g} "
                f"(the value itself); output {meta['output']}",
            )
            baker.setInputSpace("input")
            baker.setTargetSpace("output")
            size = meta["size"]
            baker.setCubeSize(size)  # the 1D writers take their length from the cube size
            if fmt not in NO_DOMAIN:
                baker.setShaperSpace("domain")
                baker.setShaperSize(size if values.ndim == 2 else DOMAIN_SHAPER_SIZE)
            text = baker.bake()
            Path(tmp).write_text(text if text.endswith("\n") else text + "\n")
    return path


def export_lut(
    table: str,
    out: StrPath | None = None,
    *,
    fmt: str | None = None,
    kind: str = "phase-change",
    display: registry.DisplayLike | None = None,
    index: float | None = None,
    value_range: Sequence[float] | None = None,
    size: int | None = None,
    show_progress: bool = False,
) -> Path:
    """Compute and write one standalone LUT.

    Parameters
    ----------
    table : str
        ``"film"``, ``"morpho"`` or ``"clip"`` (see :func:`lut_contents`).
    out : str or os.PathLike, optional
        The file to write; default a name from the options (the LUT's stem and the
        format's extension) in the current directory.
    fmt : str, optional
        A key of :data:`FORMATS` that can hold the table (film and morpho: clf, cube,
        spi1d; clip: clf, cube, csp, and spi3d only over [0, 1]); default ``out``'s
        extension, else ``"clf"``.
    kind, display, index, value_range, size
        As for :func:`lut_contents`.
    show_progress : bool, optional
        Show a progress bar on stderr when it is a terminal (default ``False``).

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    TypeError
        As :func:`lut_contents`.
    ParameterError
        Naming the parameter, as :func:`lut_contents`; naming ``fmt`` for an unknown
        format, or when none is given and ``out``'s extension names none; naming
        ``out`` when it cannot be written
        (:func:`~ocio_thinfilm.io.destinations.check_output_file`).
    ValueError
        For a format that cannot hold the table or its range, or an unwritable
        directory.
    OSError
        If the file cannot be written.
    """
    display = registry.display_name(display)
    fmt = lut_format(out, fmt, FORMATS, "clf")
    size, value_range = _validate(table, kind, display, index, value_range, size, fmt)
    if out is None:
        out = Path(_stem(table, kind, display, index) + "." + FORMATS[fmt][1])
    out = check_output_file(out)
    bar = progress_bar(show_progress, total=1.0, desc=f"export {out.name}")
    try:
        values, lut, meta = _contents(
            table, kind, display, index, value_range, size, bar.update if bar else None
        )
        write_lut(out, fmt, values, lut, meta)
    finally:
        if bar:
            bar.close()
    return out


class LogProgress:
    """Progress as plain lines on stderr, for a log or a pipe (no carriage returns).

    Silent for the first :attr:`DELAY` seconds (a quick or cached run prints nothing),
    then one line at most every :attr:`INTERVAL` seconds, ``<desc>: <done>/<total>
    (<seconds> s)``, and a last line when closed if it printed any. The methods a
    caller uses of a tqdm bar: ``update``, ``set_postfix_str`` (the stage, shown in the
    line), ``close``.
    """

    DELAY = 5.0
    INTERVAL = 15.0

    def __init__(self, total: float, desc: str, clock: Callable[[], float] | None = None):
        import time

        self.total, self.desc, self.done, self.stage = total, desc, 0.0, ""
        self._clock = clock or time.monotonic
        self._start = self._clock()
        self._last: float | None = None

    def _line(self) -> str:
        elapsed = self._clock() - self._start
        stage = f" {self.stage}" if self.stage else ""
        if self.total == 1.0:  # a fraction
            return f"{self.desc}: {100.0 * self.done:.0f} %{stage} ({elapsed:.0f} s)"
        return f"{self.desc}: {self.done:g}/{self.total:g}{stage} ({elapsed:.0f} s)"

    def set_postfix_str(self, s: str = "", refresh: bool = True) -> None:
        """Name the current stage (as tqdm's ``set_postfix_str``)."""
        self.stage = s

    def update(self, n: float = 1.0) -> None:
        """Advance by ``n``; print a line when one is due."""
        self.done += n
        now = self._clock()
        if now - self._start < self.DELAY:
            return
        if self._last is None or now - self._last >= self.INTERVAL:
            self._last = now
            print(self._line(), file=sys.stderr, flush=True)

    def close(self) -> None:
        """Print the last line, if any line was printed."""
        if self._last is not None:
            print(self._line() + ", done", file=sys.stderr, flush=True)


def progress_bar(
    show: bool, total: float, desc: str, *, unit: str = "file", delay: float = 0.0
) -> tqdm | LogProgress | None:
    """Return a progress display on stderr, or None.

    None unless ``show``; a tqdm bar where stderr is a terminal, else
    :class:`LogProgress` (plain lines after a few seconds, no carriage-return residue in
    a log).

    Parameters
    ----------
    show : bool
        Whether a bar is wanted.
    total : float
        The bar's total (a count of steps, or 1.0 for fractions).
    desc : str
        Its label.
    unit : str, optional
        What a step is (default ``"file"``).
    delay : float, optional
        Seconds before the bar appears (tqdm's ``delay``): a shorter run prints nothing.

    Returns
    -------
    tqdm.tqdm or LogProgress or None
        The bar (the caller closes it), or ``None``.
    """
    if not show:
        return None
    if not sys.stderr.isatty():
        return LogProgress(total, desc)
    from tqdm import tqdm

    return tqdm(
        total=total,
        desc=desc,
        unit=unit,
        delay=delay,
        leave=False,
        file=sys.stderr,
        mininterval=0.2,
        bar_format="{desc}: {percentage:3.0f}%|{bar}| {elapsed}",
    )
