"""``ocio-thinfilm export material``: a film as a view-dependent material table for renderers.

:func:`material_table` evaluates a film (:mod:`ocio_thinfilm.physics.films`) over its
thickness range and every view angle (:func:`ocio_thinfilm.lut.material_tables.film_angle_XYZ`)
and converts the colours to a scene-linear RGB space of the registry
(:func:`ocio_thinfilm.colour.colorimetry.XYZ_to_RGB`); :func:`export_material` writes
the tables as float OpenEXR images (docs/materials.md):

- ``<stem>_R.exr``: unpolarised reflectance; ``<stem>_T.exr``: transmittance, for a
  free-standing film (:func:`~ocio_thinfilm.lut.material_tables.free_standing`);
- x: the varying layer's physical thickness over ``range_um``, column ``i`` of ``W``
  at ``lo + (i + 0.5) (hi - lo) / W``; y: cos theta in the incident medium, texture
  row ``j`` of ``H`` (v = 0 at the bottom) at ``(j + 0.5) / H``; a host samples
  ``u = (t - lo) / (hi - lo)``, ``v = cos theta`` bilinearly with clamp-to-edge;
- RGB of the space, white = the perfect reflector under the film's illuminant; colours
  outside the space's gamut keep their negative channels (measured in
  docs/materials.md: renderers carry them, and the config's views map them at display).
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import __version__, registry
from ocio_thinfilm.checks import ParameterError, as_choice, as_count
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.config.data import ROLES, film_lut_stem
from ocio_thinfilm.io import StrPath, atomic_directory, claim_directory, write_image
from ocio_thinfilm.lut import material_tables
from ocio_thinfilm.physics.films import Film

__all__ = [
    "DEFAULT_SPACE",
    "MAX_SIZE",
    "GAMUTS",
    "MaterialTable",
    "gamut_display",
    "HostWriter",
    "MAX_SECONDS",
    "NS_PER_SAMPLE",
    "check_space",
    "parse_size",
    "available_memory",
    "table_cost",
    "check_size",
    "material_table",
    "host_files",
    "export_material",
]

#: The default scene space: the config's scene_linear role.
DEFAULT_SPACE = ROLES["scene_linear"]
#: What a table does with colours outside its space's gamut (:func:`material_table`).
GAMUTS = ("keep", "clip")
#: Largest width or height of a table.
MAX_SIZE = 16384
#: The longest an export may be estimated to take (s): a larger ``size`` is refused
#: before anything is computed (:func:`check_size`).
MAX_SECONDS = 600.0
#: Time per sample (a texel at one wavelength, ns) of one worker of
#: :func:`~ocio_thinfilm.lut.material_tables.film_angle_XYZ`, measured by
#: benchmarks/bench_material.py on the development machine (the 10 um soap film, where
#: per-row costs are amortised, on a busy 2-core machine: an upper estimate;
#: docs/materials.md): the time estimate of :func:`check_size`.
NS_PER_SAMPLE = 45.0
#: Bytes per texel of one table while it is made and written: its XYZ, RGB and clipped
#: RGB (float64) and the EXR's float32 pixels.
_BYTES_PER_TEXEL = 3 * (8 + 8 + 8 + 4)
#: Bytes a worker's block of work holds (coefficients, powers and spectra of a group of
#: rows, :mod:`ocio_thinfilm.lut.material_tables`).
_WORKER_BYTES = 96 << 20
#: Fraction of the available memory an export may plan to use.
_MEMORY_SHARE = 0.8
#: A fixed EXR timestamp: equal inputs give equal bytes.
_DATETIME = "2000:01:01 00:00:00"

#: A host writer: (film key, reflectance EXR, transmittance EXR or None, range_um) ->
#: the text of a file for that host (a Blender script, an ES module, a MaterialX
#: document).
HostWriter = Callable[[str, Path, "Path | None", tuple[float, float]], str]


@dataclass(frozen=True)
class MaterialTable:
    """A film's reflectance (and transmittance) over thickness x cos theta.

    ``reflectance``, ``transmittance``: (H, W, 3) float64 linear RGB of ``space`` in
    texture row order (row 0 at cos theta = 0.5 / H, v ascending), ``transmittance``
    None unless the film is free-standing; ``range_um``: the thickness axis' range;
    ``film``: the film.
    """

    reflectance: np.ndarray
    transmittance: np.ndarray | None
    range_um: tuple[float, float]
    space: str
    film: Film

    @property
    def size(self) -> tuple[int, int]:
        """(width, height) of the table."""
        h, w = self.reflectance.shape[:2]
        return w, h

    def lookup(
        self, thickness_um: npt.ArrayLike, cos_theta: npt.ArrayLike, quantity: str = "reflectance"
    ) -> np.ndarray:
        """Return the table's colour as a host reads it: bilinear, texel-centre, clamp-to-edge.

        Parameters
        ----------
        thickness_um, cos_theta : array_like
            Points (broadcast together).
        quantity : str, optional
            ``"reflectance"`` or ``"transmittance"``.

        Returns
        -------
        numpy.ndarray
            RGB, shape ``broadcast shape + (3,)``.
        """
        image = self.reflectance if quantity == "reflectance" else self.transmittance
        if image is None:
            raise ParameterError("quantity", f" {quantity!r}: the film has no such table")
        lo, hi = self.range_um
        t, c = np.broadcast_arrays(np.asarray(thickness_um, float), np.asarray(cos_theta, float))
        h, w = image.shape[:2]
        x = np.clip((t - lo) / (hi - lo) * w - 0.5, 0.0, w - 1.0)
        y = np.clip(c * h - 0.5, 0.0, h - 1.0)
        x0 = np.minimum(np.floor(x).astype(int), max(w - 2, 0))
        y0 = np.minimum(np.floor(y).astype(int), max(h - 2, 0))
        x1, y1 = np.minimum(x0 + 1, w - 1), np.minimum(y0 + 1, h - 1)
        fx, fy = (x - x0)[..., None], (y - y0)[..., None]
        top = image[y0, x0] * (1 - fx) + image[y0, x1] * fx
        bottom = image[y1, x0] * (1 - fx) + image[y1, x1] * fx
        return top * (1 - fy) + bottom * fy


def check_space(space: str) -> str:
    """Return ``space`` if it is a scene-linear space of the registry.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``space``) naming the scene-linear spaces.
    """
    if space not in registry.SCENE_LINEAR_SPACES:
        raise ParameterError(
            "space",
            f" must be a scene-linear space, one of {', '.join(registry.SCENE_LINEAR_SPACES)}; "
            f"got {space!r}",
        )
    return space


def parse_size(size: str | tuple[int, int] | None) -> tuple[int, int] | None:
    """Return a table size ``"WxH"`` (or ``(W, H)``) as two integers in [2, :data:`MAX_SIZE`].

    Examples
    --------
    >>> parse_size("256x64"), parse_size(None)
    ((256, 64), None)
    """
    if size is None:
        return None
    if isinstance(size, str):
        m = re.fullmatch(r"\s*(\d+)\s*[xX]\s*(\d+)\s*", size)
        if not m:
            raise ParameterError(
                "size", f" must be WIDTHxHEIGHT, two integers in [2, {MAX_SIZE}], got {size!r}"
            )
        size = (int(m.group(1)), int(m.group(2)))
    w, h = size
    return as_count("size", w, 2, MAX_SIZE), as_count("size", h, 2, MAX_SIZE)


def available_memory() -> int:
    """Return the memory (bytes) available to a new allocation without swapping.

    ``MemAvailable`` of /proc/meminfo (Linux), else the free physical pages
    (``os.sysconf``), else 0 (unknown: no memory bound).

    Returns
    -------
    int
        Bytes.
    """
    try:
        with open("/proc/meminfo", encoding="ascii") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))
    except (OSError, ValueError, AttributeError):
        return 0


def table_cost(film: Film, width: int, height: int, workers: int) -> tuple[float, float, float]:
    """Estimate what a film's table of ``width`` x ``height`` texels costs to make.

    Parameters
    ----------
    film : Film
        The film.
    width, height : int
        The table's size.
    workers : int
        Threads that evaluate it.

    Returns
    -------
    memory : float
        Bytes: the tables (R, and T for a free-standing film) while made and written, and
        each worker's block of work.
    seconds : float
        Wall time on the development machine: the samples
        (:func:`~ocio_thinfilm.lut.material_tables.sample_count`) times
        :data:`NS_PER_SAMPLE`, over the workers.
    samples : float
        The samples.
    """
    quantities = 2 if material_tables.free_standing(film) else 1
    samples = material_tables.sample_count(film, width, height)
    memory = float(width) * height * quantities * _BYTES_PER_TEXEL + workers * _WORKER_BYTES
    return memory, samples * NS_PER_SAMPLE * 1e-9 / workers, samples


def _amount(value: float, unit: str) -> str:
    return f"{value:.2g} {unit}" if value < 10 else f"{value:.0f} {unit}"


def _bytes(n: float) -> str:
    for unit, scale in (("GB", 1e9), ("MB", 1e6)):
        if n >= scale:
            return _amount(n / scale, unit)
    return _amount(n / 1e3, "kB")


def _duration(seconds: float) -> str:
    for unit, scale in (("h", 3600.0), ("min", 60.0)):
        if seconds >= scale:
            return _amount(seconds / scale, unit)
    return _amount(seconds, "s")


def check_size(
    film: Film, width: int, height: int, workers: int, parameter: str = "size"
) -> tuple[int, int]:
    """Refuse a table the machine cannot hold or finish in :data:`MAX_SECONDS`.

    The estimates of :func:`table_cost` against :func:`available_memory` (at most 80 %
    of it) and :data:`MAX_SECONDS`; milliseconds, before anything is computed.

    Parameters
    ----------
    film : Film
        The film.
    width, height : int
        The table's size.
    workers : int
        Threads that would evaluate it.
    parameter : str, optional
        The parameter named in the message (default ``"size"``).

    Returns
    -------
    tuple of int
        (width, height).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``parameter``) with the estimates and about the most texels allowed.
    """
    memory, seconds, samples = table_cost(film, width, height, workers)
    available = available_memory() * _MEMORY_SHARE
    texels = float(width) * height
    fits = available <= 0 or memory <= available
    if fits and seconds <= MAX_SECONDS:
        return width, height
    per_texel_memory = (memory - workers * _WORKER_BYTES) / texels
    limits = [MAX_SECONDS / (seconds / texels)]
    if available > 0:
        limits.append(max(0.0, available - workers * _WORKER_BYTES) / per_texel_memory)
    most = min(limits)
    side = max(2, int(math.sqrt(most)))
    where = f"{_bytes(available / _MEMORY_SHARE)} available" if available > 0 else ""
    raise ParameterError(
        parameter,
        f" {width}x{height}: needs about {_bytes(memory)} of memory"
        f"{f' ({where})' if where else ''} and {_duration(seconds)} here with {workers} "
        f"worker{'s' if workers != 1 else ''} (at most {_duration(MAX_SECONDS)}); at most "
        f"about {most / 1e6:.3g} million texels (e.g. {side}x{side})",
    )


def gamut_display(space: str) -> registry.Display | None:
    """Return the SDR display whose gamut (primaries and white) is the scene space's.

    The constant-lightness clip (Smits & Meyer 1990, Section 3.2) works in a display's
    RGB cube; a scene space with a display's primaries (linear Rec.709, P3-D65,
    Rec.2020) can be clipped in it. ``None`` for the others (ACEScg, the camera gamuts).
    """
    M = colorimetry.matrix_XYZ_to_RGB(registry.SCENE_LINEAR_BY_NAME[space].colorimetry)
    for display in registry.DISPLAY_LIST:
        if np.array_equal(colorimetry.matrix_XYZ_to_RGB(display.colorimetry), M):
            return display
    return None


def material_table(
    film: Film,
    *,
    space: str = DEFAULT_SPACE,
    width: int | None = None,
    height: int | None = None,
    gamut: str = "keep",
    workers: int | None = None,
    progress: Callable[[int], object] | None = None,
) -> MaterialTable:
    """Return a film's reflectance (and transmittance) table over thickness x cos theta.

    Parameters
    ----------
    film : Film
        The film (:func:`ocio_thinfilm.physics.films.read_films`).
    space : str, optional
        A scene-linear space of the registry (default the config's scene_linear).
    width, height : int, optional
        Texels along thickness and cos theta, in [2, :data:`MAX_SIZE`] (default
        :func:`ocio_thinfilm.lut.material_tables.default_resolution`).
    gamut : str, optional
        Colours outside the space's gamut: ``"keep"`` (default) their negative
        channels, for renderers that carry them; ``"clip"`` the constant-lightness clip
        into the space's RGB cube (:func:`ocio_thinfilm.colour.clip.clip_RGB`: Y and the
        hue line kept), for renderers that clamp negative colours per channel (Cycles,
        MaterialX's generated code); only for a space with a display's primaries
        (:func:`gamut_display`).
    workers : int, optional
        Threads (default :func:`~ocio_thinfilm.lut.material_tables.available_workers`);
        the table is the same bits for any number.
    progress : callable, optional
        Called with the number of rows finished, as they finish.

    Returns
    -------
    MaterialTable
        The tables in texture row order.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``film``, ``space``, ``width``, ``height``, ``gamut``, ``workers``) a film whose
        incident medium absorbs or whose range has zero width, a space that is not
        scene-linear, a size out of range or beyond what the machine can hold or finish
        (:func:`check_size`), a gamut choice not in :data:`GAMUTS` or a clip in a space
        without a display's primaries, a worker count below 1.
    """
    w, h, workers = _check_table(film, space, width, height, gamut, workers, "width")
    return _table(film, space, w, h, gamut, workers, progress)


def _check_table(
    film: Film,
    space: str,
    width: int | None,
    height: int | None,
    gamut: str,
    workers: int | None,
    parameter: str,
) -> tuple[int, int, int]:
    """Check :func:`material_table`'s arguments; return the size and the workers."""
    material_tables.check_film(film)
    space = check_space(space)
    gamut = as_choice("gamut", gamut, GAMUTS)
    display = gamut_display(space)
    if gamut == "clip" and display is None:
        with_display = [
            s.name for s in registry.SCENE_LINEAR_LIST if gamut_display(s.name) is not None
        ]
        raise ParameterError(
            "gamut",
            f" 'clip' needs a space with a display's primaries ({', '.join(with_display)}), "
            f"got {space!r}",
        )
    w0, h0 = material_tables.default_resolution(film)
    w = w0 if width is None else as_count("width", width, 2, MAX_SIZE)
    h = h0 if height is None else as_count("height", height, 2, MAX_SIZE)
    workers = (
        material_tables.available_workers()
        if workers is None
        else as_count("workers", workers, 1, 4096)
    )
    check_size(film, w, h, workers, parameter)
    return w, h, workers


def _table(
    film: Film,
    space: str,
    w: int,
    h: int,
    gamut: str,
    workers: int,
    progress: Callable[[int], object] | None,
) -> MaterialTable:
    """Compute :func:`material_table` with checked arguments."""
    display = gamut_display(space)
    lo, hi = film.range_um
    t = material_tables.texel_centres(lo, hi, w)
    c = material_tables.texel_centres(0.0, 1.0, h)
    transmit = material_tables.free_standing(film)
    XYZ_R, XYZ_T = material_tables.film_angle_XYZ(
        film, t, c, transmittance=transmit, workers=workers, progress=progress
    )
    colorimetry_name = registry.SCENE_LINEAR_BY_NAME[space].colorimetry
    R = colorimetry.XYZ_to_RGB(XYZ_R, colorimetry_name)
    T = None if XYZ_T is None else colorimetry.XYZ_to_RGB(XYZ_T, colorimetry_name)
    if gamut == "clip" and display is not None:
        R = clip.clip_RGB(R, display)
        T = None if T is None else clip.clip_RGB(T, display)
    return MaterialTable(R, T, (lo, hi), space, film)


def _progress_bar(show: bool, rows: int, key: str) -> Any:
    """Return a tqdm bar over the table's rows, shown after 2 s (short runs print nothing)."""
    from ocio_thinfilm.export.files import progress_bar

    return progress_bar(show, total=rows, desc=f"export material {key}", unit="row", delay=2.0)


def _attributes(table: MaterialTable, quantity: str) -> dict[str, Any]:
    film = table.film
    lo, hi = table.range_um
    w, h = table.size
    return {
        "ImageDescription": (
            f"{film.name}: {quantity} of {re.sub(r' at [0-9.e+-]+ deg,', ',', film.describe())} "
            f"in {table.space} "
            f"(white = the perfect reflector); x: {film.varying.name} thickness "
            f"{lo:g}-{hi:g} um, column i at lo + (i + 0.5) (hi - lo) / {w}; y: cos theta in "
            f"the incident medium, texture row j (v = 0 at the bottom) at (j + 0.5) / {h}"
        ),
        "DateTime": _DATETIME,
        "ocio_thinfilm:film": film.key,
        "ocio_thinfilm:quantity": quantity,
        "ocio_thinfilm:space": table.space,
        "ocio_thinfilm:x": "thickness_um",
        "ocio_thinfilm:x_range": (lo, hi),
        "ocio_thinfilm:y": "cos_theta",
        "ocio_thinfilm:y_range": (0.0, 1.0),
        "ocio_thinfilm:sampling": "texel-centre",
        "ocio_thinfilm:illuminant": str(
            getattr(film, "illuminant", colorimetry.DEFAULT_ILLUMINANT)
        ),
        "ocio_thinfilm:version": __version__,
    }


def host_files(film: Film, space: str = DEFAULT_SPACE) -> dict[str, HostWriter]:
    """Return the host files ``export material`` writes beside a film's tables.

    - ``<stem>.py``: a Python script Blender runs (the node group and material,
      :func:`ocio_thinfilm.export.hosts.blender.blender_script`; reflection, and
      transmission for a free-standing film);
    - ``<stem>.js``: an ES module for three.js
      (:func:`ocio_thinfilm.export.hosts.three.three_module`), for tables in three.js's
      working space (linear Rec.709: the registry's ``threejs`` name);
    - ``<stem>.mtlx``: a MaterialX 1.39 document
      (:func:`ocio_thinfilm.export.hosts.materialx.materialx_document`), for the spaces
      MaterialX names.

    Parameters
    ----------
    film : Film
    space : str, optional
        The tables' scene-linear space (default the config's scene_linear).

    Returns
    -------
    dict
        File name -> :data:`HostWriter`.
    """
    from ocio_thinfilm.export.hosts import blender, materialx, three

    stem = film_lut_stem(film)
    space = check_space(space)

    def blender_file(key, reflectance, transmittance, range_um):
        t_name = None if transmittance is None else transmittance.name
        return blender.blender_script(key, reflectance.name, t_name, range_um)

    def three_file(key, reflectance, transmittance, range_um):
        return three.three_module(key, reflectance, range_um, module_name=f"{stem}.js")

    def materialx_file(key, reflectance, transmittance, range_um):
        return materialx.materialx_document(key, reflectance, range_um, space=space)

    entry = registry.SCENE_LINEAR_BY_NAME[space]
    files: dict[str, HostWriter] = {f"{stem}.py": blender_file}
    if entry.threejs is not None:
        files[f"{stem}.js"] = three_file
    if entry.materialx is not None:
        files[f"{stem}.mtlx"] = materialx_file
    return files


def export_material(
    film: Film,
    out_dir: StrPath,
    *,
    space: str = DEFAULT_SPACE,
    size: str | tuple[int, int] | None = None,
    hosts: Mapping[str, HostWriter] | None = None,
    gamut: str = "keep",
    workers: int | None = None,
    show_progress: bool = False,
) -> list[Path]:
    """Write a film's material tables (and host files) into the directory ``out_dir``.

    Parameters
    ----------
    film : Film
        The film.
    out_dir : str or os.PathLike
        The output directory: created if missing; an existing one must be empty or hold
        files of earlier runs only (:func:`ocio_thinfilm.io.ownership.claim_directory`,
        its files from other films are kept).
    space : str, optional
        A scene-linear space of the registry (default the config's scene_linear).
    size : str or tuple of int, optional
        ``"WxH"`` or ``(W, H)`` (default the measured
        :func:`~ocio_thinfilm.lut.material_tables.default_resolution`).
    hosts : mapping, optional
        File name -> host writer: each is called with the film's key, the paths of the
        written reflectance and transmittance EXRs (None without one) and ``range_um``,
        and its text is written to ``out_dir / name`` with the tables (default none).
    gamut : str, optional
        ``"keep"`` (default) or ``"clip"`` (:func:`material_table`).
    workers : int, optional
        Threads (:func:`material_table`).
    show_progress : bool, optional
        A progress bar on stderr (a terminal only) for an export longer than about 2 s.

    Returns
    -------
    list of pathlib.Path
        The files written, together (all or none).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        The errors of :func:`material_table` and :func:`parse_size` (``size``, also a
        size beyond what the machine can hold or finish: :func:`check_size`), and
        (``out``) an output directory holding files this tool did not write, a file
        in its place.
    ValueError
        If ``out_dir`` cannot be created or written.

    Notes
    -----
    Everything that can be checked is checked before the table is computed (in well
    under a second, nothing written): the film, the space, the gamut, the size and its
    cost, the workers, the host file names and the output directory.
    """
    dims = parse_size(size)
    width, height = (None, None) if dims is None else dims
    w, h, workers = _check_table(film, space, width, height, gamut, workers, "size")
    stem = film_lut_stem(film)
    names = [f"{stem}_R.exr"]
    if material_tables.free_standing(film):
        names.append(f"{stem}_T.exr")
    for name in hosts or {}:
        if Path(name).name != name or name in names:
            raise ParameterError("hosts", f" {name!r}: must be a new file name without folders")
    out = Path(out_dir)
    # the output directory: refused now, not after the computation (nothing is written)
    try:
        claim_directory(out, parameter="out", keep_others=True)
    except ParameterError:
        raise
    except ValueError as error:  # not writable: name the parameter too
        raise ParameterError("out", f" {error}") from None
    bar = _progress_bar(show_progress, h, film.key)
    try:
        table = _table(film, space, w, h, gamut, workers, None if bar is None else bar.update)
    finally:
        if bar is not None:
            bar.close()
    images = {f"{stem}_R.exr": ("reflectance", table.reflectance)}
    if table.transmittance is not None:
        images[f"{stem}_T.exr"] = ("transmittance", table.transmittance)
    paths = {name: out / name for name in images}
    texts = {}
    for name, writer in (hosts or {}).items():
        t_path = paths.get(f"{stem}_T.exr")
        texts[name] = writer(film.key, paths[f"{stem}_R.exr"], t_path, table.range_um)
    with atomic_directory(out, parameter="out", keep_others=True) as stage:
        for name, (quantity, pixels) in images.items():
            # the EXR's first scanline is the top: cos theta descending
            write_image(
                stage / name,
                pixels[::-1],
                channel_names=("R", "G", "B"),
                dtype="float",
                attributes=_attributes(table, quantity),
            )
        for name, text in texts.items():
            (stage / name).write_text(text, encoding="utf-8")
    return [out / name for name in (*images, *texts)]
