"""``ocio-thinfilm bake --into`` and ``.ocioz`` archives, written safely.

The merged config (:func:`ocio_thinfilm.config.merge.merge_config`) and archives of
a config folder:

- :func:`write_merged` -- a merged config's ``config.ocio`` and ``luts/`` into a
  directory (checked: it validates and every added view's processor builds);
- :func:`bake_into` -- that, into a directory it owns or an ``.ocioz``;
- :func:`write_archive`, :func:`bake_archive` -- a config folder / the project's config
  as an ``.ocioz`` (OCIO >= 2.2 reads them).
"""

from __future__ import annotations

import shutil
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.config import merge
from ocio_thinfilm.export.bake import load_films, write_checked_config, write_config, write_luts
from ocio_thinfilm.io import StrPath, atomic_directory, atomic_file, check_writable
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.lut.options import MapOptions, as_options

__all__ = ["write_merged", "bake_into", "write_archive", "bake_archive"]


def _copy_base_files(base, source, directory):
    """Copy a base config file's relative search-path folders next to the result."""
    if str(source).startswith("ocio://"):
        return
    root = Path(source).resolve().parent
    for entry in list(base.getSearchPaths()):
        if not entry or Path(entry).is_absolute() or "$" in entry:
            continue
        src, dst = root / entry, Path(directory) / entry
        if src.is_dir() and src.resolve() != root and not dst.exists():
            shutil.copytree(src, dst)


def write_merged(
    source: StrPath,
    directory: StrPath,
    *,
    films: Sequence[Any] = (),
    options: MapOptions | None = None,
) -> tuple[Path, dict[str, tuple[str, str]]]:
    """Write the merged config (``config.ocio``, ``luts/``) into the existing ``directory``.

    The base config file's relative search-path folders are copied beside it. The
    files are written in place, not atomically (the directory is meant to be a staging
    directory: :func:`bake_into`). The config is validated, and the processors of every
    view of the matched displays and of every named transform are built, before
    ``config.ocio`` is written.

    Parameters
    ----------
    source : str or os.PathLike
        The base config: a file or an ``ocio://`` URI
        (:func:`~ocio_thinfilm.config.merge.load_base`).
    directory : str or os.PathLike
        The directory to write into.
    films : sequence of Film, optional
        Users' films (:func:`ocio_thinfilm.export.bake.load_films`), added as input
        colour spaces.
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`); ``None``
        (default) for the defaults.

    Returns
    -------
    path : pathlib.Path
        The config path, ``directory / "config.ocio"``.
    matches : dict
        {display: (display colour space name, clip display)} of the displays given the
        views (:func:`~ocio_thinfilm.config.merge.merge_config`).

    Raises
    ------
    ParameterError
        Naming ``source``, if it cannot be loaded.
    ValueError
        If the base cannot be extended (see
        :func:`~ocio_thinfilm.config.merge.merge_config`).
    PyOpenColorIO.Exception
        If the result does not validate or a processor cannot be built.
    OSError
        If a file cannot be written.
    """
    ocio = ocio_ops.module()
    base = merge.load_base(source)
    cfg, luts, matches = merge.merge_config(base, films=films, options=options)
    directory = Path(directory)
    _copy_base_files(base, source, directory)
    write_luts(directory, luts)
    cfg.setWorkingDir(str(directory))
    interchange = dict(cfg.getRoles())["cie_xyz_d65_interchange"]
    views = [
        (interchange, display, view, ocio.TRANSFORM_DIR_FORWARD)
        for display in matches
        for view in cfg.getViews(display)
    ]
    named = [(name, ocio.TRANSFORM_DIR_FORWARD) for name in cfg.getNamedTransformNames()]
    return write_checked_config(cfg, directory, [*views, *named]), matches


def write_archive(config_path: StrPath, out: StrPath) -> Path:
    """Archive the config folder of ``config_path`` as ``out``, atomically.

    Parameters
    ----------
    config_path : str or os.PathLike
        The config file; its folder and search paths go into the archive.
    out : str or os.PathLike
        The archive to write (``.ocioz``; OCIO >= 2.2 reads it).

    Returns
    -------
    pathlib.Path
        ``out``.

    Raises
    ------
    ValueError
        If the config is not archivable (absolute or parent search paths or LUT
        paths).
    PyOpenColorIO.Exception
        If the config cannot be loaded.
    OSError
        If the archive cannot be written.
    """
    ocio = ocio_ops.module()
    cfg = ocio.Config.CreateFromFile(str(config_path))
    if not cfg.isArchivable():
        raise ValueError(
            f"{config_path}: not archivable (absolute or parent search paths or LUT paths)"
        )
    with atomic_file(Path(out)) as tmp:
        cfg.archive(str(tmp))
    return Path(out)


def bake_into(
    source: StrPath,
    out: StrPath,
    *,
    films: StrPath | Sequence[Any] | None = None,
    options: MapOptions | None = None,
) -> Path:
    """Merge into the base config and write the result: ``bake --into SOURCE --out OUT``.

    Parameters
    ----------
    source : str or os.PathLike
        The base config: a file or an ``ocio://`` URI.
    out : str or os.PathLike
        An ``.ocioz`` archive to write atomically (:func:`write_archive`), or an output
        directory: new, empty or written by an earlier run (its files are committed
        together, ``config.ocio`` included).
    films : str, os.PathLike or sequence of Film, optional
        A film file or films (:func:`ocio_thinfilm.export.bake.load_films`), added as
        input colour spaces.
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`); ``None``
        (default) for the defaults.

    Returns
    -------
    pathlib.Path
        The archive, or ``out / "config.ocio"``.

    Raises
    ------
    ParameterError
        Naming ``source`` (it cannot be loaded) or ``out`` (not a directory, or a
        directory this tool may not write).
    ValueError
        If ``out``'s directory cannot be written, or the base cannot be extended
        (:func:`~ocio_thinfilm.config.merge.merge_config`, :func:`write_archive`).
    PyOpenColorIO.Exception
        If the result does not validate or a processor cannot be built.
    OSError
        If a file cannot be written.
    """
    options = as_options(options)
    film_list = load_films(films)
    out = Path(out)
    check_writable(out.parent if str(out.parent) else Path("."), create=False)
    if out.suffix.lower() == ".ocioz":
        with tempfile.TemporaryDirectory() as tmp:
            path, _ = write_merged(source, tmp, films=film_list, options=options)
            return write_archive(path, out)
    if out.exists() and not out.is_dir():
        raise ParameterError("out", f" {out}: not a directory")
    with atomic_directory(out) as tmp:
        write_merged(source, tmp, films=film_list, options=options)
    return out / "config.ocio"


def bake_archive(
    out: StrPath,
    *,
    films: StrPath | Sequence[Any] | None = None,
    options: MapOptions | None = None,
) -> Path:
    """Write the project's config as an archive: ``bake --out thinfilm.ocioz``.

    Parameters
    ----------
    out : str or os.PathLike
        The ``.ocioz`` archive to write, atomically.
    films : str, os.PathLike or sequence of Film, optional
        A film file or films, as for :func:`ocio_thinfilm.export.bake.bake`.
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`); ``None``
        (default) for the defaults.

    Returns
    -------
    pathlib.Path
        ``out``.

    Raises
    ------
    ValueError
        If ``out``'s directory cannot be written.
    OSError
        If the archive cannot be written.
    """
    options = as_options(options)
    film_list = load_films(films)
    out = Path(out)
    check_writable(out.parent if str(out.parent) else Path("."), create=False)
    with tempfile.TemporaryDirectory() as tmp:
        path = write_config(tmp, films=film_list, options=options)
        return write_archive(path, out)
