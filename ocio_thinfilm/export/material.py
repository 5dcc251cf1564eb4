"""``ocio-thinfilm export material``: a film as a view-dependent material table for renderers.

:func:`material_table` evaluates a film (:mod:`ocio_thinfilm.physics.films`) over its
thickness range and every view angle (:func:`ocio_thinfilm.lut.material_tables.film_angle_XYZ`)
and converts the colours to a scene-linear RGB space of the registry
(:func:`ocio_thinfilm.colour.colorimetry.XYZ_to_RGB`); :func:`export_material` writes
the tables as float OpenEXR images (docs/materials.md):

- ``<stem>_R.exr``: unpolarised reflectance; ``<stem>_T.exr``: transmittance, for a
  free-standing film (:func:`~ocio_thinfilm.lut.material_tables.free_standing`);
- node-centred axes (:func:`ocio_thinfilm.lut.material_tables.axis_nodes`): x the
  varying layer's physical thickness over ``range_um``, column ``i`` of ``W`` at
  ``lo + i (hi - lo) / (W - 1)``; y cos theta in the incident medium, texture row
  ``j`` of ``H`` (v = 0 at the bottom) at ``j / (H - 1)``: row 0 is grazing incidence,
  row ``H - 1`` normal incidence, both exact; a host reads fraction ``f`` of an axis
  (``(t - lo) / (hi - lo)``, cos theta, clamped to [0, 1]) at the texture coordinate
  ``(f (N - 1) + 0.5) / N`` bilinearly
  (:func:`~ocio_thinfilm.lut.material_tables.texture_coordinate`);
- RGB of the space, white = the perfect reflector under the film's illuminant; colours
  outside the space's gamut keep their negative channels (how far: docs/materials.md;
  renderers carry them, and the config's views map them at display).
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import __version__, registry
from ocio_thinfilm.checks import ParameterError, as_choice, as_count
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.config.data import ROLES, film_lut_stem
from ocio_thinfilm.export.hosts import TableFiles
from ocio_thinfilm.export.material_cost import check_size
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
    "BinaryWriter",
    "GLTF_SPACE",
    "outside_gamut",
    "check_space",
    "check_spaces",
    "space_stem",
    "parse_size",
    "material_table",
    "host_files",
    "gltf_files",
    "export_material",
]

#: The default scene space: the config's scene_linear role.
DEFAULT_SPACE = ROLES["scene_linear"]
#: What a table does with colours outside its space's gamut (:func:`material_table`).
GAMUTS = ("keep", "clip")
#: Largest width or height of a table.
MAX_SIZE = 16384
#: A fixed EXR timestamp: equal inputs give equal bytes.
_DATETIME = "2000:01:01 00:00:00"

#: A host writer: the written tables (:class:`~ocio_thinfilm.export.hosts.TableFiles`)
#: -> the text of a file for that host (a Blender script, an ES module, a MaterialX
#: document).
HostWriter = Callable[[TableFiles], str]
#: A writer of a binary file from the tables themselves (the ``.glb``): the written
#: tables' record and the :class:`MaterialTable` -> the file's bytes.
BinaryWriter = Callable[[TableFiles, "MaterialTable"], bytes]
#: glTF's colours are linear Rec.709 (sRGB primaries, D65).
GLTF_SPACE = "Linear Rec.709 (sRGB)"
#: Table nodes the ``.glb``'s KHR_materials_iridescence fit looks at (thickness x cos theta).
_GLTF_FIT_NODES = (48, 12)


@dataclass(frozen=True)
class MaterialTable:
    """A film's reflectance (and transmittance) over thickness x cos theta.

    ``reflectance``, ``transmittance``: (H, W, 3) float64 linear RGB of ``space`` in
    texture row order (row 0 at cos theta = 0, row H - 1 at 1), ``transmittance``
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
        """Return the table's colour as a host reads it: bilinear between nodes, clamped.

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
        # node-centred axes: sample i of n at fraction i / (n - 1)
        x = np.clip((t - lo) / (hi - lo), 0.0, 1.0) * (w - 1)
        y = np.clip(c, 0.0, 1.0) * (h - 1)
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


def check_spaces(space: str | Sequence[str]) -> list[str]:
    """Return the tables' spaces: one name, or several, each a scene-linear space once.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``space``) an empty list, a space named twice or one that is not scene-linear.
    """
    spaces = [space] if isinstance(space, str) else list(space)
    if not spaces:
        raise ParameterError("space", " needs at least one scene-linear space")
    for i, name in enumerate(spaces):
        check_space(name)
        if name in spaces[:i]:
            raise ParameterError("space", f" names {name!r} twice")
    return spaces


def space_stem(stem: str, space: str, first: bool) -> str:
    """Return the file stem of a film's tables in ``space``.

    The first space's tables keep the film's stem (``<stem>_R.exr``: one space's file
    names are those of a single-space export); a further space's carry its name without
    spaces and punctuation (``<stem>_LinearRec2020_R.exr``, ``<stem>_ACEScg_R.exr``).

    Examples
    --------
    >>> space_stem("ThinFilm_User_Soap", "Linear Rec.2020", first=False)
    'ThinFilm_User_Soap_LinearRec2020'
    """
    return stem if first else f"{stem}_{re.sub(r'[^A-Za-z0-9]+', '', space)}"


def outside_gamut(table: MaterialTable) -> tuple[float, float]:
    """Return the fraction of a table's texels outside its space's gamut, and the lowest value.

    A texel of the reflectance or transmittance table is outside where a channel is
    negative; the lowest value is the most negative channel (0.0 where none is).
    """
    images = [table.reflectance] + ([] if table.transmittance is None else [table.transmittance])
    rgb = np.concatenate([image.reshape(-1, 3) for image in images])
    fraction = float(np.mean((rgb < 0).any(axis=1)))
    return round(fraction, 4), round(min(float(rgb.min()), 0.0), 4)


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
        (:func:`~ocio_thinfilm.export.material_cost.check_size`), a gamut choice not in
        :data:`GAMUTS` or a clip in a space without a display's primaries, a worker
        count below 1.
    """
    w, h, workers = _check_table(film, space, width, height, gamut, workers, "width")
    return _in_space(film, _film_XYZ(film, w, h, workers, progress), space, gamut)


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


def _film_XYZ(
    film: Film, w: int, h: int, workers: int, progress: Callable[[int], object] | None
) -> tuple[np.ndarray, np.ndarray | None]:
    """Return the film's XYZ (R, and T or None) on the table's node-centred axes."""
    lo, hi = film.range_um
    t = material_tables.axis_nodes(lo, hi, w)
    c = material_tables.axis_nodes(0.0, 1.0, h)
    transmit = material_tables.free_standing(film)
    return material_tables.film_angle_XYZ(
        film, t, c, transmittance=transmit, workers=workers, progress=progress
    )


def _in_space(
    film: Film, XYZ: tuple[np.ndarray, np.ndarray | None], space: str, gamut: str
) -> MaterialTable:
    """Return the table of the film's XYZ in ``space`` (clipped into it for ``"clip"``)."""
    display = gamut_display(space)
    colorimetry_name = registry.SCENE_LINEAR_BY_NAME[space].colorimetry
    R, T = (None if v is None else colorimetry.XYZ_to_RGB(v, colorimetry_name) for v in XYZ)
    assert R is not None
    if gamut == "clip" and display is not None:
        R = clip.clip_RGB(R, display)
        T = None if T is None else clip.clip_RGB(T, display)
    return MaterialTable(R, T, film.range_um, space, film)


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
            f"{lo:g}-{hi:g} um, column i at lo + i (hi - lo) / {w - 1}; y: cos theta in "
            f"the incident medium, texture row j (v = 0 at the bottom) at j / {h - 1}; "
            f"node-centred: read fraction f of an axis of N texels at (f (N - 1) + 0.5) / N"
        ),
        "DateTime": _DATETIME,
        "ocio_thinfilm:film": film.key,
        "ocio_thinfilm:quantity": quantity,
        "ocio_thinfilm:space": table.space,
        "ocio_thinfilm:x": "thickness_um",
        "ocio_thinfilm:x_range": (lo, hi),
        "ocio_thinfilm:y": "cos_theta",
        "ocio_thinfilm:y_range": (0.0, 1.0),
        "ocio_thinfilm:sampling": "node-centred",
        "ocio_thinfilm:illuminant": str(
            getattr(film, "illuminant", colorimetry.DEFAULT_ILLUMINANT)
        ),
        "ocio_thinfilm:version": __version__,
    }


def host_files(film: Film, space: str | Sequence[str] = DEFAULT_SPACE) -> dict[str, HostWriter]:
    """Return the host files ``export material`` writes beside a film's tables.

    - ``<stem>.py``: a Python script Blender runs (the node group and material named
      by the film's name, :func:`ocio_thinfilm.export.hosts.blender.blender_host`;
      reflection, and transmission for a free-standing film; it loads the tables of
      the scene's working space where several spaces were written);
    - ``<stem>.js``: an ES module for three.js
      (:func:`ocio_thinfilm.export.hosts.three.three_module`; reflection, thickness maps,
      and transmission for a free-standing film), for tables in three.js's working space
      (linear Rec.709: the registry's ``threejs`` name);
    - ``<stem>.mtlx``: a MaterialX 1.39 document
      (:func:`ocio_thinfilm.export.hosts.materialx.materialx_document`; the film as a
      node with a connectable thickness, reflection and transmission), for the spaces
      MaterialX names.

    Each names the film by its ``name`` (``TableFiles.name``).

    Parameters
    ----------
    film : Film
    space : str or sequence of str, optional
        The tables' scene-linear space (default the config's scene_linear), or spaces:
        the three.js and MaterialX files use the first.

    Returns
    -------
    dict
        File name -> :data:`HostWriter`.
    """
    from ocio_thinfilm.export.hosts import blender, materialx, three

    stem = film_lut_stem(film)
    space = check_spaces(space)[0]

    def three_file(files: TableFiles) -> str:
        return three.three_module(
            files.key,
            files.reflectance,
            files.range_um,
            transmittance_exr=files.transmittance,
            name=files.name,
            module_name=f"{stem}.js",
        )

    def materialx_file(files: TableFiles) -> str:
        return materialx.materialx_document(
            files.key,
            files.reflectance,
            files.range_um,
            space=space,
            size=files.size,
            transmittance_exr=files.transmittance,
            name=files.name,
        )

    entry = registry.SCENE_LINEAR_BY_NAME[space]
    files: dict[str, HostWriter] = {f"{stem}.py": blender.blender_host}
    if entry.threejs is not None:
        files[f"{stem}.js"] = three_file
    if entry.materialx is not None:
        files[f"{stem}.mtlx"] = materialx_file
    return files


def gltf_files(film: Film, space: str = DEFAULT_SPACE) -> dict[str, BinaryWriter]:
    """Return the glTF files ``export material --gltf`` writes beside a film's tables.

    - ``<stem>.glb``: the film on a sample sphere
      (:func:`ocio_thinfilm.export.hosts.gltf.gltf_binary`): the exact tables in the
      ``OCIO_THINFILM_materials_film`` extension and a ``KHR_materials_iridescence``
      fallback fitted to them (:func:`ocio_thinfilm.lut.iridescence_fit.fit_iridescence`);
    - ``ocio_thinfilm_gltf.js``: the three.js ``GLTFLoader`` plugin that draws the
      extension (:func:`ocio_thinfilm.export.hosts.gltf.plugin_module`).

    Parameters
    ----------
    film : Film
    space : str, optional
        The tables' space: must be :data:`GLTF_SPACE`.

    Returns
    -------
    dict
        File name -> :data:`BinaryWriter`.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``space``) another space than glTF's linear Rec.709; (``film``) a film not seen
        from air (glTF's materials sit in a medium of index 1).
    """
    from ocio_thinfilm.export.hosts import gltf
    from ocio_thinfilm.lut import iridescence_fit

    if check_space(space) != GLTF_SPACE:
        raise ParameterError(
            "space", f" must be {GLTF_SPACE!r} for --gltf (glTF's colours), got {space!r}"
        )
    material_tables.check_film(film)
    n0 = film.stack[0].index(np.linspace(380.0, 780.0, 81))
    if not np.allclose(n0, 1.0, rtol=0.0, atol=1e-3):
        raise ParameterError(
            "film",
            f" {film.key}: stack: glTF's materials are seen from air (n = 1); the incident "
            f"medium {film.stack[0].name!r} has n = {float(n0.real.mean()):.3g}",
        )

    def glb(files: TableFiles, table: MaterialTable) -> bytes:
        target = iridescence_fit.target_from_table(
            film,
            table.reflectance,
            table.range_um,
            *_GLTF_FIT_NODES,
            transmittance=table.transmittance,
        )
        fallback = iridescence_fit.fit_iridescence(target)
        return gltf.gltf_binary(
            film.key,
            table.reflectance,
            table.range_um,
            fallback,
            transmittance=table.transmittance,
            name=film.name,
        )

    def plugin(files: TableFiles, table: MaterialTable) -> bytes:
        return gltf.plugin_module().encode("utf-8")

    return {f"{film_lut_stem(film)}.glb": glb, gltf.PLUGIN_NAME: plugin}


def export_material(
    film: Film,
    out_dir: StrPath,
    *,
    space: str | Sequence[str] = DEFAULT_SPACE,
    size: str | tuple[int, int] | None = None,
    hosts: Mapping[str, HostWriter] | None = None,
    gamut: str = "keep",
    binaries: Mapping[str, BinaryWriter] | None = None,
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
    space : str or sequence of str, optional
        A scene-linear space of the registry (default the config's scene_linear), or
        several: one set of tables each, the first named ``<stem>_R.exr`` (``_T.exr``),
        the others by :func:`space_stem` (``<stem>_LinearRec2020_R.exr``); the host
        writers get the first's record with the others in ``others``.
    size : str or tuple of int, optional
        ``"WxH"`` or ``(W, H)`` (default
        :func:`~ocio_thinfilm.lut.material_tables.default_resolution`).
    hosts : mapping, optional
        File name -> host writer: each is called with the written tables
        (:class:`~ocio_thinfilm.export.hosts.TableFiles`: the film's key and name, the
        paths of the reflectance and transmittance EXRs, ``range_um``, the size, the
        space) and its text is written to ``out_dir / name`` with the tables (default
        none).
    gamut : str, optional
        ``"keep"`` (default) or ``"clip"`` (:func:`material_table`).
    binaries : mapping, optional
        File name -> binary writer (:data:`BinaryWriter`, e.g. :func:`gltf_files`):
        called with the written tables' record and the first space's table, its bytes
        written with the tables (default none).
    workers : int, optional
        Threads (:func:`material_table`).
    show_progress : bool, optional
        Progress on stderr for an export longer than about 2 s: a bar on a terminal,
        plain lines in a log (:func:`ocio_thinfilm.export.files.progress_bar`).

    Returns
    -------
    list of pathlib.Path
        The files written, together (all or none).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        The errors of :func:`material_table` and :func:`parse_size` (``size``, also a
        size beyond what the machine can hold or finish:
        :func:`~ocio_thinfilm.export.material_cost.check_size`), and
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
    spaces = check_spaces(space)
    checked = [_check_table(film, name, width, height, gamut, workers, "size") for name in spaces]
    w, h, workers = checked[0]
    stem = film_lut_stem(film)
    out = Path(out_dir)
    transmit = material_tables.free_standing(film)
    stems = [space_stem(stem, name, first=i == 0) for i, name in enumerate(spaces)]
    names = [f"{s}_{q}.exr" for s in stems for q in ("R", "T")[: 1 + transmit]]
    for kind, writers in (("hosts", hosts), ("binaries", binaries)):
        for name in writers or {}:
            if Path(name).name != name or name in names:
                raise ParameterError(kind, f" {name!r}: must be a new file name without folders")
            names.append(name)
    # the output directory: refused now, not after the computation (nothing is written)
    try:
        claim_directory(out, parameter="out", keep_others=True)
    except ParameterError:
        raise
    except ValueError as error:  # not writable: name the parameter too
        raise ParameterError("out", f" {error}") from None
    bar = _progress_bar(show_progress, h, film.key)
    try:  # the film's colours once, then each space's RGB
        XYZ = _film_XYZ(film, w, h, workers, None if bar is None else bar.update)
    finally:
        if bar is not None:
            bar.close()
    tables = [_in_space(film, XYZ, name, gamut) for name in spaces]
    images, records = _images_and_records(film, tables, stems, out)
    files = dataclasses.replace(records[0], others=tuple(records[1:]))
    texts: dict[str, str | bytes] = {name: writer(files) for name, writer in (hosts or {}).items()}
    for name, binary in (binaries or {}).items():
        texts[name] = binary(files, tables[0])
    _write_files(out, images, texts)
    return [out / name for name in (*images, *texts)]


def _images_and_records(
    film: Film, tables: list[MaterialTable], stems: list[str], out: Path
) -> tuple[dict[str, tuple[str, np.ndarray, MaterialTable]], list[TableFiles]]:
    """Return the EXRs to write (name -> quantity, pixels, table) and the spaces' records."""
    images: dict[str, tuple[str, np.ndarray, MaterialTable]] = {}
    records = []
    for table, tables_stem in zip(tables, stems, strict=True):
        images[f"{tables_stem}_R.exr"] = ("reflectance", table.reflectance, table)
        if table.transmittance is not None:
            images[f"{tables_stem}_T.exr"] = ("transmittance", table.transmittance, table)
        records.append(
            TableFiles(
                key=film.key,
                name=film.name,
                reflectance=out / f"{tables_stem}_R.exr",
                transmittance=(
                    None if table.transmittance is None else out / f"{tables_stem}_T.exr"
                ),
                range_um=table.range_um,
                size=table.size,
                space=table.space,
                outside=outside_gamut(table),
            )
        )
    return images, records


def _write_files(
    out: Path,
    images: dict[str, tuple[str, np.ndarray, MaterialTable]],
    texts: dict[str, str | bytes],
) -> None:
    """Write the tables' EXRs and the host files into ``out``, all or none."""
    with atomic_directory(out, parameter="out", keep_others=True) as stage:
        for name, (quantity, pixels, table) in images.items():
            # the EXR's first scanline is the top: cos theta descending
            write_image(
                stage / name,
                pixels[::-1],
                channel_names=("R", "G", "B"),
                dtype="float",
                attributes=_attributes(table, quantity),
            )
        for name, text in texts.items():
            if isinstance(text, bytes):
                (stage / name).write_bytes(text)
            else:
                (stage / name).write_text(text, encoding="utf-8")
