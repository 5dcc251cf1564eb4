"""``ocio-thinfilm bake``: the config folder (and the standalone LUT set), written safely.

:func:`bake` writes ``config.ocio`` and its ``luts/*.clf``
(:func:`write_config`) and, with ``luts``, the standalone set (:func:`export_set`), into
directories it owns
(:func:`ocio_thinfilm.io.claim_directory`), as one transaction.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

from ocio_thinfilm import config, registry
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.export import view as export_view
from ocio_thinfilm.export.files import CLF_WRITER, FORMATS, lut_contents, progress_bar, write_lut
from ocio_thinfilm.io import StrPath, check_xml, claim_directory, transaction
from ocio_thinfilm.lut import clip_lut, tables
from ocio_thinfilm.lut.options import MapOptions, as_options

__all__ = [
    "DEFAULT_CONFIG_DIR",
    "write_luts",
    "write_checked_config",
    "write_config",
    "export_set",
    "EXPORT_SET_VIEWS",
    "bake",
    "load_films",
]

DEFAULT_CONFIG_DIR = "configs/thinfilm"


def _check_staged_clfs(directory, final):
    for path in sorted(Path(directory).rglob("*.clf")):
        check_xml(path, Path(final) / path.relative_to(directory))


def write_luts(
    directory: StrPath,
    luts: Mapping[str, Any],
    progress: Callable[[str], object] | None = None,
) -> None:
    """Write a config's LUTs as CLF files into its LUT folder.

    Parameters
    ----------
    directory : str or os.PathLike
        The config's directory; the files go to its :data:`ocio_thinfilm.config.LUT_DIRECTORY`
        (made if missing).
    luts : mapping
        File name -> the OpenColorIO transform (a ``GroupTransform``) the file holds.
    progress : callable, optional
        ``progress(file_name)``, called once per file written.
    """
    import PyOpenColorIO as ocio

    folder = Path(directory) / config.LUT_DIRECTORY
    folder.mkdir(parents=True, exist_ok=True)
    raw = ocio.Config.CreateRaw()
    for filename, transform in sorted(luts.items()):
        transform.write(CLF_WRITER, str(folder / filename), raw)
        if progress:
            progress(filename)


def write_checked_config(cfg: Any, directory: StrPath, processors: Iterable[Sequence[Any]]) -> Path:
    """Validate ``cfg``, build its ``processors`` and write it as ``directory/config.ocio``.

    Parameters
    ----------
    cfg : PyOpenColorIO.Config
        The config; its LUTs already written (:func:`write_luts`).
    directory : str or os.PathLike
        The config's directory.
    processors : iterable of sequences
        Arguments of ``cfg.getProcessor`` to build before anything is written: each
        builds only if its FileTransforms resolve.

    Returns
    -------
    pathlib.Path
        ``directory / "config.ocio"``, ending with a newline.

    Raises
    ------
    PyOpenColorIO.Exception
        If the config does not validate or a processor cannot be built.
    """
    cfg.validate()
    for arguments in processors:
        cfg.getProcessor(*arguments)
    path = Path(directory) / "config.ocio"
    text = cfg.serialize()
    path.write_text(text if text.endswith("\n") else text + "\n")
    return path


def write_config(
    directory: StrPath,
    *,
    progress: Callable[[str], object] | None = None,
    films: Sequence[Any] = (),
    options: MapOptions | None = None,
) -> Path:
    """Write ``config.ocio`` and ``luts/*.clf`` into the (existing, empty) ``directory``.

    The files are written in place, not atomically: the directory is meant to be a
    staging directory (:func:`bake` commits it). The config is validated and every
    display view's and colour space's processor built before ``config.ocio`` is
    written. The files carry no timestamps: equal inputs give equal bytes.

    Parameters
    ----------
    directory : str or os.PathLike
        The directory to write into.
    progress : callable, optional
        ``progress(step_name)``, called once per file written (the LUT file's name,
        then ``"config.ocio"``).
    films : sequence of Film, optional
        Users' films (:func:`load_films`): an input colour space each.
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`); ``None``
        (default) for the defaults.

    Returns
    -------
    pathlib.Path
        The config path, ``directory / "config.ocio"``.

    Raises
    ------
    PyOpenColorIO.Exception
        If the config does not validate or a processor cannot be built.
    OSError
        If a file cannot be written.
    """
    import PyOpenColorIO as ocio

    directory = Path(directory)
    data = config.config_data(films=films, options=options)
    write_luts(directory, data.luts, progress)
    cfg = config.generate_config(data, validate=False, working_dir=directory)
    # every FileTransform resolves and every processor builds
    views = [
        ("CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD)
        for display in cfg.getDisplays()
        for view in cfg.getViews(display)
    ]
    spaces = [(name, "CIE-XYZ-D65") for name in cfg.getColorSpaceNames()]
    path = write_checked_config(cfg, directory, [*views, *spaces])
    if progress:
        progress("config.ocio")
    return path


#: Display LUTs in the shipped set: (input space, view, formats), for every display.
EXPORT_SET_VIEWS = (("ACEScct", registry.CLIP_VIEW, ("cube",)),)


def export_set(directory: StrPath, *, show_progress: bool = False) -> list[Path]:
    """Write the standalone LUT set shipped in ``luts/`` into ``directory``.

    Every table in every format that can hold it with its domain, plus the common
    display LUTs (:data:`EXPORT_SET_VIEWS`: ACEScct -> each display's Constant-Lightness
    Clip as a plain 65^3 .cube over [0, 1], which every reader applies alike). Each file
    is written atomically on its own.

    Parameters
    ----------
    directory : str or os.PathLike
        The directory, which must exist.
    show_progress : bool, optional
        Show a progress bar on stderr when it is a terminal (default ``False``).

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    OSError
        If a file cannot be written.
    """
    jobs: list[tuple[str, dict[str, Any], str]] = []
    for fmt in FORMATS:
        for kind in colorimetry.FILM_KINDS:
            if 1 in FORMATS[fmt][2]:
                jobs.append(("film", dict(kind=kind), fmt))
        if 1 in FORMATS[fmt][2]:
            jobs.append(("morpho", {}, fmt))
        # (the clip over display-linear RGB, `export clip`, is not shipped: a grid over
        # linear RGB cannot resolve dark saturated colours; the display LUTs below are
        # what to take)
    views = [
        (source, display, view, fmt)
        for source, view, fmts in EXPORT_SET_VIEWS
        for display in registry.DISPLAYS
        for fmt in fmts
    ]
    written = []
    bar = progress_bar(show_progress, total=len(jobs) + len(views), desc="export luts")
    cache = {}
    for table, kw, fmt in jobs:
        key = (table, tuple(sorted(kw.items())))
        if key not in cache:
            cache[key] = lut_contents(table, **kw)
        values, lut, meta = cache[key]
        path = Path(directory) / f"{meta['name']}.{FORMATS[fmt][1]}"
        write_lut(path, fmt, values, lut, meta)
        written.append(path)
        if bar:
            bar.update(1)
    for source, display, view, fmt in views:
        name = export_view.set_name(source, display, view) + "." + fmt
        written += export_view.export_view(
            source, display, view, Path(directory) / name, size=export_view.DEFAULT_VIEW_SIZE
        )
        if bar:
            bar.update(1)
    if bar:
        bar.close()
    return written


def bake(
    out: StrPath = DEFAULT_CONFIG_DIR,
    *,
    show_progress: bool = False,
    luts: StrPath | None = None,
    films: StrPath | Sequence[Any] | None = None,
    options: MapOptions | None = None,
) -> Path:
    """Write the config folder (config.ocio + luts/*.clf) and, optionally, the LUT set.

    Both directories must be new, empty, or written by an earlier bake (they then hold
    the marker :data:`.io.MARKER`; files they list are replaced or removed, nothing
    else is touched). Everything is validated, written aside and checked first, then
    committed file by file with ``config.ocio`` last, so a failure (a full disk,
    Ctrl-C) leaves both directories as they were, and a kill leaves each a complete,
    loadable set of files.

    Parameters
    ----------
    out : str or os.PathLike, optional
        The config directory (default :data:`DEFAULT_CONFIG_DIR`).
    show_progress : bool, optional
        Show a progress bar on stderr when it is a terminal (default ``False``).
    luts : str or os.PathLike, optional
        Also write the standalone LUT set (:func:`export_set`) to this directory,
        which must not be, contain or lie inside ``out``; ``None`` (default) for none.
    films : str, os.PathLike or sequence of Film, optional
        A film file (TOML, :func:`ocio_thinfilm.physics.films.read_films`) or films
        read from one: each adds an input colour space and its named transform. Bad
        films are refused (a ParameterError naming ``films``) before anything is
        written.
    options : MapOptions, optional
        The config's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`, checked
        when it is made, before anything is written); ``None`` (default) for the
        defaults. The standalone LUT set (``luts``) does not depend on them.

    Returns
    -------
    pathlib.Path
        The config path, ``out/config.ocio`` (a link ``out`` resolved).

    Raises
    ------
    ParameterError
        Naming ``out`` or ``luts``: a directory this tool may not write
        (:func:`ocio_thinfilm.io.claim_directory`), or ``luts`` overlapping ``out``.
    ValueError
        If a directory cannot be created or written.
    OSError
        ``"cannot write ...: ..."`` if a file cannot be written; nothing is then
        replaced.
    """
    options = as_options(options)
    film_list = load_films(films)
    if film_list:  # the tables are computed (and a bad film refused) before any claim
        from ocio_thinfilm.lut import film_tables

        for film in film_list:
            film_tables.user_film_table(film)
    claim, luts_claim = _claims(out, luts)
    # the thin-film tables, two clip and two compression LUTs per SDR display, config.ocio
    n_files = len(registry.THIN_FILM_LIST) + 4 * len(registry.GAMUT_DISPLAYS) + 1
    n_files += len(film_list)
    stages = _stages(options)
    bar = progress_bar(show_progress, total=len(stages) + n_files, desc=f"bake {claim.path}")
    try:
        _run_stages(stages, bar)
        with transaction() as tx:
            stage = tx.directory(claim)
            try:
                write_config(stage, progress=_advance(bar), films=film_list, options=options)
            except OSError as error:
                raise OSError(f"cannot write {claim.path}: {error.strerror or error}") from None
            except Exception:
                _check_staged_clfs(stage, claim.path)  # a truncated LUT (disk full) says so
                raise
            if luts_claim is not None:
                export_set(tx.directory(luts_claim), show_progress=show_progress)
    finally:
        if bar:
            bar.close()
    return claim.path / "config.ocio"


def _claims(out: StrPath, luts: StrPath | None) -> tuple[Any, Any]:
    """Claim the config folder and the LUT set's (:func:`claim_directory`), apart."""
    claim = claim_directory(out, parameter="out", last=("config.ocio",))
    if luts is None:
        return claim, None
    luts_claim = claim_directory(luts, parameter="luts")
    a, b = luts_claim.path.resolve(), claim.path.resolve()
    if a == b or a in b.parents or b in a.parents:
        raise ParameterError(
            "luts", f" {luts}: must not be, contain or lie inside the output directory {out}"
        )
    return claim, luts_claim


def _run_stages(stages: Sequence[tuple[str, Callable[[], object]]], bar: Any) -> None:
    """Run the bake's long computations (:func:`_stages`) in order, naming each on ``bar``."""
    for name, compute in stages:
        if bar:
            bar.set_postfix_str(name, refresh=False)
        compute()
        if bar:
            bar.update(1)


def _stages(options: MapOptions) -> list[tuple[str, Callable[[], object]]]:
    """Return the bake's long computations as (stage name, call), for ``options``.

    Each is cached once computed (in the process, and the clip LUTs on disk), so the
    config written next reuses them: running them first only lets the progress name
    its stages (a cold bake spends about a minute and a half here).
    """
    from functools import partial

    from ocio_thinfilm.lut import compress_lut

    sizes = dict(film_size=options.film_size, morpho_size=options.morpho_size)
    stages: list[tuple[str, Callable[[], object]]] = [
        (f"table {space.name}", partial(tables.thin_film_table, space, **sizes))
        for space in registry.THIN_FILM_LIST
    ]
    stages += [
        (f"clip {display}", partial(clip_lut.clip_lut, display, options.clip_size))
        for display in registry.GAMUT_DISPLAYS
    ]
    stages += [
        (
            f"compress {display}",
            partial(
                compress_lut.compress_lut,
                display,
                threshold=options.compress_threshold,
                limit=options.compress_limit,
                clip_size=options.clip_size,
            ),
        )
        for display in registry.GAMUT_DISPLAYS
    ]
    return stages


def _advance(bar: Any) -> Callable[[str], None] | None:
    """Return the bake's per-file callback: name the file written, advance the bar."""
    if bar is None:
        return None

    def advance(name: str) -> None:
        bar.set_postfix_str(str(name), refresh=False)
        bar.update(1)

    return advance


def load_films(films: StrPath | Sequence[Any] | None) -> list:
    """Return the films for a bake.

    They are read from a film file (a path), or taken as they are from a sequence of
    :class:`~ocio_thinfilm.physics.films.Film`; ``None`` gives none.

    Parameters
    ----------
    films : str, pathlib.Path, sequence of Film or None
        The film file or the films.

    Returns
    -------
    list
        The films, in the file's order.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``films``) a film file that cannot be read or is not a valid film file
        (:func:`ocio_thinfilm.physics.films.read_films`).
    TypeError
        If the sequence holds something other than films.
    """
    from ocio_thinfilm.physics import films as films_module

    if films is None:
        return []
    if isinstance(films, (str, os.PathLike)):
        return list(films_module.read_films(os.fspath(films)).values())
    out = list(films)
    for film in out:
        if not isinstance(film, films_module.Film):
            raise TypeError(f"films must be a film file or Film objects, got {film!r}")
    return out
