"""``ocio-thinfilm export film --films FILE --film KEY``: a user's film as standalone files.

:func:`export_film` writes a film's table (:func:`ocio_thinfilm.lut.film_tables.user_film_table`,
pixel value = physical thickness of its varying layer in micrometres) in every 1D LUT
format with its domain in the file (CLF: a range matrix before the Lut1D; ``.cube``:
``LUT_1D_INPUT_RANGE``; ``.spi1d``: ``From lo hi``; OCIO's writers,
:func:`ocio_thinfilm.export.files.write_lut`), and as a ramp texture for shaders: an
OpenEXR image, float32 CIE XYZ in R, G, B, texel ``i`` of ``width`` holding the colour
at thickness ``lo + (i + 0.5) / width * (hi - lo)`` (sample it at
``u = (t - lo) / (hi - lo)`` with linear filtering and clamp-to-edge), 8 rows, its domain
in the header (``ocio_thinfilm:domain`` and ``ImageDescription``).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from ocio_thinfilm.checks import ParameterError, as_choice, as_count
from ocio_thinfilm.config.data import film_lut_stem
from ocio_thinfilm.export.bake import load_films
from ocio_thinfilm.export.files import FORMATS, write_lut
from ocio_thinfilm.io import StrPath, check_output_file, check_writable, transaction, write_image
from ocio_thinfilm.lut import film_tables, ocio_ops

__all__ = ["FILM_FORMATS", "RAMP_HEIGHT", "pick_film", "film_contents", "export_film"]

#: The formats a film is written in: the 1D LUT formats and the EXR ramp.
FILM_FORMATS = tuple(f for f in FORMATS if 1 in FORMATS[f][2]) + ("exr",)
#: Rows of the ramp texture (every row the same).
RAMP_HEIGHT = 8
#: A fixed EXR timestamp: equal inputs give equal bytes.
_DATETIME = "2000:01:01 00:00:00"


def pick_film(films: StrPath | Any, film: str | None) -> Any:
    """Return the film ``film`` (its key or colour space name) of a film file.

    ``films`` may also be any films :func:`ocio_thinfilm.export.bake.load_films`
    accepts; with one film in the file ``film`` may be left out.

    Parameters
    ----------
    films : str, pathlib.Path or sequence of Film
        The film file or its films.
    film : str or None
        The film's key or colour space name.

    Returns
    -------
    Film
        The film chosen.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``film``) naming the films there are.
    """
    found = load_films(films)
    if film is None:
        if len(found) == 1:
            return found[0]
        raise ParameterError("film", f" must name one of {[f.key for f in found]}")
    for f in found:
        if film in (f.key, f.name):
            return f
    raise ParameterError("film", f" must be one of {[f.key for f in found]}, got {film!r}")


def film_contents(film: Any, size: int | None = None) -> tuple[np.ndarray, Any, dict[str, Any]]:
    """Return a film's table for :func:`ocio_thinfilm.export.files.write_lut`.

    Parameters
    ----------
    film : Film
        The film.
    size : int, optional
        Entries, uniform over its range (default
        :func:`ocio_thinfilm.lut.film_tables.default_size`).

    Returns
    -------
    values : numpy.ndarray
        (size, 3) CIE XYZ.
    lut : PyOpenColorIO.Lut1DTransform
        The values as an OCIO Lut1D.
    meta : dict
        Name, input and output descriptions, range, size and CLF id.
    """
    table = film_tables.user_film_table(film, size)
    lo, hi = film.range_um
    stem = film_lut_stem(film)
    meta = dict(
        name=stem,
        input=table.input_descriptor,
        output=f"CIE-XYZ-D65 (perfect reflector{film_tables.light_words(film)} Y = 1), unclipped",
        description=table.description,
        range=(lo, hi),
        size=table.size,
        id=ocio_ops.transform_id("Export", stem),
    )
    return np.asarray(table.values), ocio_ops.lut1d_transform(table.values), meta


def export_film(
    films: StrPath | Any,
    film: str | None = None,
    out: StrPath | None = None,
    *,
    fmt: str | None = None,
    size: int | None = None,
) -> list[Path]:
    """Write a user's film as standalone files.

    Parameters
    ----------
    films : str, pathlib.Path or sequence of Film
        The film file (TOML) or its films.
    film : str, optional
        The film's key (or colour space name); optional with one film.
    out : str or pathlib.Path, optional
        A file (its extension, or ``fmt``, says the format: one file) or a directory
        (every format of :data:`FILM_FORMATS`, named after the film); default the
        current directory.
    fmt : str, optional
        One of :data:`FILM_FORMATS`: that format only.
    size : int, optional
        Entries of the table and texels of the ramp, in [2, 65536] (default: the
        film's table size).

    Returns
    -------
    list of pathlib.Path
        The files written, each atomically (checked, then renamed into place) after
        every argument and the film were checked.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``films``, ``film``, ``size``, ``fmt`` or ``out``) an unreadable film file, an
        unknown film, a size that is not an integer in [2, 65536], an unknown format or
        an ``out`` that is neither a directory nor a file of one of :data:`FILM_FORMATS`.
    TypeError
        If ``films`` holds something other than films, or ``size`` is not a number.
    """
    chosen = pick_film(films, film)
    if size is not None:
        size = as_count("size", size, 2, 1 << 16)
    out_path = Path(".") if out is None else Path(out)
    suffix = out_path.suffix.lower().lstrip(".")
    if fmt is None and suffix in FILM_FORMATS:
        fmt = suffix
    if fmt is not None:
        fmt = as_choice("fmt", fmt, FILM_FORMATS)
    stem = film_lut_stem(chosen)
    if suffix and suffix not in FILM_FORMATS and not out_path.is_dir():
        raise ParameterError(
            "out",
            f" {out_path}: must be a directory or a file ending in "
            f"{', '.join('.' + f for f in FILM_FORMATS)}",
        )
    if fmt is not None and suffix:
        targets = {fmt: check_output_file(out_path, "out")}
    else:
        if out_path.exists() and not out_path.is_dir():
            raise ParameterError("out", f" {out_path}: not a directory")
        names = {f: stem + "." + FORMATS[f][1] for f in FORMATS if f in FILM_FORMATS}
        names["exr"] = stem + "_ramp.exr"
        targets = {f: out_path / names[f] for f in (FILM_FORMATS if fmt is None else (fmt,))}
        try:  # the output folder: created here, its parent must exist
            check_writable(out_path)
        except ValueError as error:
            raise ParameterError("out", f" {error}") from None
    values, lut, meta = film_contents(chosen, size)
    written = []
    if "exr" in targets:
        lo, hi = chosen.range_um
        width = meta["size"]
        t = lo + (np.arange(width) + 0.5) / width * (hi - lo)
        ramp = np.broadcast_to(film_tables.film_XYZ(chosen, t), (RAMP_HEIGHT, width, 3))
        description = (
            f"{chosen.name}: CIE XYZ D65 (perfect reflector"
            f"{film_tables.light_words(chosen)} Y = 1) against the "
            f"physical thickness of the {chosen.varying.name} layer, {lo:g}-{hi:g} um "
            f"along x (texel i at lo + (i + 0.5) / {width} * (hi - lo)); "
            f"{chosen.describe()}"
        )
        attributes: Mapping[str, Any] = {
            "ImageDescription": description,
            "ocio_thinfilm:domain": (lo, hi),
            "DateTime": _DATETIME,
        }
    with transaction() as tx:
        for f, path in targets.items():
            path.parent.mkdir(parents=True, exist_ok=True)
            if f == "exr":
                write_image(
                    path,
                    ramp,
                    channel_names=("R", "G", "B"),
                    dtype="float",
                    attributes=attributes,
                    tx=tx,
                )
            else:
                write_lut(path, f, values, lut, meta)
            written.append(path)
    return written
