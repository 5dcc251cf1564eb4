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
  outside the space's gamut keep their negative channels (measured in
  docs/materials.md: renderers carry them, and the config's views map them at display).
"""

from __future__ import annotations

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
from ocio_thinfilm.export.hosts import TableFiles
from ocio_thinfilm.io import StrPath, atomic_directory, write_image
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
    "check_space",
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

    Returns
    -------
    MaterialTable
        The tables in texture row order.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``film``, ``space``, ``width``, ``height``, ``gamut``) a film whose incident
        medium absorbs or whose range has zero width, a space that is not scene-linear, a
        size out of range, a gamut choice not in :data:`GAMUTS` or a clip in a space
        without a display's primaries.
    """
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
    lo, hi = film.range_um
    t = material_tables.axis_nodes(lo, hi, w)
    c = material_tables.axis_nodes(0.0, 1.0, h)
    transmit = material_tables.free_standing(film)
    XYZ_R, XYZ_T = material_tables.film_angle_XYZ(film, t, c, transmittance=transmit)
    colorimetry_name = registry.SCENE_LINEAR_BY_NAME[space].colorimetry
    R = colorimetry.XYZ_to_RGB(XYZ_R, colorimetry_name)
    T = None if XYZ_T is None else colorimetry.XYZ_to_RGB(XYZ_T, colorimetry_name)
    if gamut == "clip" and display is not None:
        R = clip.clip_RGB(R, display)
        T = None if T is None else clip.clip_RGB(T, display)
    return MaterialTable(R, T, (lo, hi), space, film)


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


def host_files(film: Film, space: str = DEFAULT_SPACE) -> dict[str, HostWriter]:
    """Return the host files ``export material`` writes beside a film's tables.

    - ``<stem>.py``: a Python script Blender runs (the node group and material,
      :func:`ocio_thinfilm.export.hosts.blender.blender_script`; reflection, and
      transmission for a free-standing film);
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

    def blender_file(files: TableFiles) -> str:
        t_name = None if files.transmittance is None else files.transmittance.name
        return blender.blender_script(files.key, files.reflectance.name, t_name, files.range_um)

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
    files: dict[str, HostWriter] = {f"{stem}.py": blender_file}
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
    space: str = DEFAULT_SPACE,
    size: str | tuple[int, int] | None = None,
    hosts: Mapping[str, HostWriter] | None = None,
    gamut: str = "keep",
    binaries: Mapping[str, BinaryWriter] | None = None,
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
        File name -> host writer: each is called with the written tables
        (:class:`~ocio_thinfilm.export.hosts.TableFiles`: the film's key and name, the
        paths of the reflectance and transmittance EXRs, ``range_um``, the size, the
        space) and its text is written to ``out_dir / name`` with the tables (default
        none).
    gamut : str, optional
        ``"keep"`` (default) or ``"clip"`` (:func:`material_table`).
    binaries : mapping, optional
        File name -> binary writer (:data:`BinaryWriter`, e.g. :func:`gltf_files`):
        called with the written tables' record and the table, its bytes written with the
        tables (default none).

    Returns
    -------
    list of pathlib.Path
        The files written, together (all or none).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        The errors of :func:`material_table` and :func:`parse_size` (``size``), and
        (``out``) an output directory holding files this tool did not write.
    """
    dims = parse_size(size)
    width, height = (None, None) if dims is None else dims
    table = material_table(film, space=space, width=width, height=height, gamut=gamut)
    stem = film_lut_stem(film)
    images = {f"{stem}_R.exr": ("reflectance", table.reflectance)}
    if table.transmittance is not None:
        images[f"{stem}_T.exr"] = ("transmittance", table.transmittance)
    out = Path(out_dir)
    paths = {name: out / name for name in images}
    files = TableFiles(
        key=film.key,
        name=film.name,
        reflectance=paths[f"{stem}_R.exr"],
        transmittance=paths.get(f"{stem}_T.exr"),
        range_um=table.range_um,
        size=table.size,
        space=table.space,
    )
    texts: dict[str, str | bytes] = {}
    for name, writer in (hosts or {}).items():
        if Path(name).name != name or name in images:
            raise ParameterError("hosts", f" {name!r}: must be a new file name without folders")
        texts[name] = writer(files)
    for name, binary in (binaries or {}).items():
        if Path(name).name != name or name in images or name in texts:
            raise ParameterError("binaries", f" {name!r}: must be a new file name without folders")
        texts[name] = binary(files, table)
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
            if isinstance(text, bytes):
                (stage / name).write_bytes(text)
            else:
                (stage / name).write_text(text, encoding="utf-8")
    return [out / name for name in (*images, *texts)]
