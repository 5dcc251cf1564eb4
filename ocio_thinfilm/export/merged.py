"""``ocio-thinfilm bake --into`` and ``.ocioz`` archives: the merged config
(:func:`ocio_thinfilm.config.merge.merge_config`) and archives of a config folder,
written safely.

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

from ocio_thinfilm import config
from ocio_thinfilm.config import merge
from ocio_thinfilm.export.bake import load_films, write_config
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.io import StrPath, atomic_directory, atomic_file, check_writable
from ocio_thinfilm.lut import clip_lut, ocio_ops

__all__ = ["write_merged", "bake_into", "write_archive", "bake_archive"]


def _copy_base_files(base, source, directory):
    """A base config file's relative search-path folders, copied next to the result."""
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
    clip_size: int = clip_lut.CLIP_SIZE,
    films: Sequence[Any] = (),
) -> tuple[Path, dict[str, tuple[str, str]]]:
    """Write the merged config (``config.ocio``, ``luts/``) into the existing
    ``directory``; returns (config path, display matches). ``films``: users' films
    (:func:`ocio_thinfilm.export.bake.load_films`), added as input spaces."""
    ocio = ocio_ops.module()
    base = merge.load_base(source)
    cfg, luts, matches = merge.merge_config(base, clip_size=clip_size, films=films)
    directory = Path(directory)
    _copy_base_files(base, source, directory)
    (directory / config.LUT_DIRECTORY).mkdir(parents=True, exist_ok=True)
    raw = ocio.Config.CreateRaw()
    for filename, transform in sorted(luts.items()):
        transform.write(
            "Academy/ASC Common LUT Format", str(directory / config.LUT_DIRECTORY / filename), raw
        )
    cfg.setWorkingDir(str(directory))
    cfg.validate()
    for display in matches:
        for view in cfg.getViews(display):
            cfg.getProcessor(
                dict(cfg.getRoles())["cie_xyz_d65_interchange"],
                display,
                view,
                ocio.TRANSFORM_DIR_FORWARD,
            )
    for name in cfg.getNamedTransformNames():
        cfg.getProcessor(name, ocio.TRANSFORM_DIR_FORWARD)
    path = directory / "config.ocio"
    text = cfg.serialize()
    path.write_text(text if text.endswith("\n") else text + "\n")
    return path, matches


def write_archive(config_path: StrPath, out: StrPath) -> Path:
    """Archive the config folder of ``config_path`` as ``out`` (``.ocioz``, OCIO >= 2.2
    to read), atomically."""
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
    clip_size: int = clip_lut.CLIP_SIZE,
    films: StrPath | Sequence[Any] | None = None,
) -> Path:
    """``ocio-thinfilm bake --into SOURCE --out OUT``: a folder or an ``.ocioz``;
    ``films``: a film file or films (:func:`ocio_thinfilm.export.bake.load_films`)."""
    film_list = load_films(films)
    out = Path(out)
    check_writable(out.parent if str(out.parent) else Path("."))
    if out.suffix.lower() == ".ocioz":
        with tempfile.TemporaryDirectory() as tmp:
            path, _ = write_merged(source, tmp, clip_size=clip_size, films=film_list)
            return write_archive(path, out)
    if out.exists() and not out.is_dir():
        raise ParameterError("out", f" {out}: not a directory")
    with atomic_directory(out) as tmp:
        write_merged(source, tmp, clip_size=clip_size, films=film_list)
    return out / "config.ocio"


def bake_archive(
    out: StrPath,
    *,
    clip_size: int = clip_lut.CLIP_SIZE,
    films: StrPath | Sequence[Any] | None = None,
) -> Path:
    """``ocio-thinfilm bake --out thinfilm.ocioz``: the project's config as an archive
    (with ``films``, a film file or films, as :func:`ocio_thinfilm.export.bake.bake`)."""
    film_list = load_films(films)
    out = Path(out)
    check_writable(out.parent if str(out.parent) else Path("."))
    with tempfile.TemporaryDirectory() as tmp:
        path = write_config(tmp, clip_size=clip_size, films=film_list)
        return write_archive(path, out)
