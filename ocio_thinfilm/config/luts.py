"""The config's LUT files: which there are, their names, and references to them.

Each display's clip LUT (:func:`clip_luts`) and compression LUT (:func:`compress_luts`)
is computed once and handed to every part of the config that uses it; the thin-film
tables and those LUTs are the config's CLF files (:func:`lut_files`), referred to by
FileTransform or put inline (:func:`lut_reference`).
"""

from __future__ import annotations

from ocio_thinfilm import registry
from ocio_thinfilm.colour import compress as compress_map
from ocio_thinfilm.config.factories import file_transform
from ocio_thinfilm.lut import clip_lut, compress_lut, ocio_ops, tables

__all__ = [
    "named_lut",
    "clip_luts",
    "KNOB_NAMES",
    "compress_luts",
    "lut_files",
    "lut_reference",
    "clip_passes",
    "compress_passes",
]


def named_lut(stem: str) -> str:
    """Return the config's file name of the LUT ``stem`` (CLF, in :data:`LUT_DIRECTORY`).

    Parameters
    ----------
    stem : str
        The LUT's file stem (e.g. a :class:`~ocio_thinfilm.registry.ThinFilmSpace`'s
        ``lut_stem``).

    Returns
    -------
    str
        ``stem + ".clf"``.

    Examples
    --------
    >>> named_lut("ThinFilm_Morpho_Iridescence")
    'ThinFilm_Morpho_Iridescence.clf'
    """
    return f"{stem}.clf"


def clip_luts(clip_size: int = clip_lut.CLIP_SIZE) -> dict:
    """Return the clip LUTs of every SDR display of the registry.

    Parameters
    ----------
    clip_size : int, optional
        Edge length of the clip's black pass, an integer in [9, 129] (default
        :data:`ocio_thinfilm.lut.clip_lut.CLIP_SIZE`).

    Returns
    -------
    dict
        Display name (:data:`ocio_thinfilm.registry.GAMUT_DISPLAYS`) -> its
        :class:`~ocio_thinfilm.lut.clip_lut.ClipLUT` (each computed once, then cached).

    Raises
    ------
    ValueError
        For a ``clip_size`` outside [9, 129].
    """
    return {display: clip_lut.clip_lut(display, clip_size) for display in registry.GAMUT_DISPLAYS}


#: The names of the compression's knobs in the functions that bake the config.
KNOB_NAMES = ("compress_threshold", "compress_limit")


def compress_luts(
    clip_size: int = clip_lut.CLIP_SIZE,
    *,
    compress_threshold: float = compress_map.THRESHOLD,
    compress_limit: float = compress_map.LIMIT,
) -> dict:
    """Return the compression LUTs of every SDR display of the registry.

    Parameters
    ----------
    clip_size : int, optional
        Edge length of the clip LUTs they run with, an integer in [9, 129] (default
        :data:`ocio_thinfilm.lut.clip_lut.CLIP_SIZE`).
    compress_threshold : float, optional
        The compression's threshold, in (0, 1) (default
        :data:`ocio_thinfilm.colour.compress.THRESHOLD`).
    compress_limit : float, optional
        The compression's limit, above 1 (default
        :data:`ocio_thinfilm.colour.compress.LIMIT`).

    Returns
    -------
    dict
        Display name (:data:`ocio_thinfilm.registry.GAMUT_DISPLAYS`) -> its
        :class:`~ocio_thinfilm.lut.compress_lut.CompressLUT`.

    Raises
    ------
    ParameterError
        Naming ``compress_threshold`` or ``compress_limit``, for knobs out of range
        (:func:`ocio_thinfilm.colour.compress.check_knobs`).
    ValueError
        For a ``clip_size`` outside [9, 129].
    """
    threshold, limit = compress_map.check_knobs(
        compress_threshold, compress_limit, names=KNOB_NAMES
    )
    return {
        display: compress_lut.compress_lut(
            display, threshold=threshold, limit=limit, clip_size=clip_size
        )
        for display in registry.GAMUT_DISPLAYS
    }


def lut_files(
    luts_by_display: dict,
    film_size: int = tables.FILM_SIZE,
    morpho_size: int = tables.MORPHO_SIZE,
    compress_by_display: dict | None = None,
) -> dict:
    """Return every LUT file the config uses.

    The thin-film tables and, per display, the two passes of its clip LUT and the two
    squeezes of its compression.

    Parameters
    ----------
    luts_by_display : dict
        SDR display (name or registry display) -> its ClipLUT (:func:`clip_luts`).
    film_size : int, optional
        Entries of the thickness tables (default
        :data:`ocio_thinfilm.lut.tables.FILM_SIZE`).
    morpho_size : int, optional
        Entries of the Morpho angle table (default
        :data:`ocio_thinfilm.lut.tables.MORPHO_SIZE`).
    compress_by_display : dict, optional
        SDR display -> its CompressLUT (:func:`compress_luts`); ``None`` (default) for
        no compression files.

    Returns
    -------
    dict
        LUT file name (:func:`named_lut`) -> GroupTransform (CLF-writable).

    Raises
    ------
    ParameterError
        Naming ``luts_by_display`` or ``compress_by_display``, for a key that is not an
        SDR display of the registry.
    """
    files = {}
    for space in registry.THIN_FILM_LIST:
        table = tables.thin_film_table(space, film_size=film_size, morpho_size=morpho_size)
        files[named_lut(space.lut_stem)] = table.transform()
    for display, lut in luts_by_display.items():
        entry = registry.as_display(display, hdr=False, parameter="luts_by_display")
        files[named_lut(entry.clip_lut_stem())] = lut.black_core()
        files[named_lut(entry.clip_lut_stem(True))] = lut.white_core()
    for display, soft in (compress_by_display or {}).items():
        entry = registry.as_display(display, hdr=False, parameter="compress_by_display")
        files[named_lut(entry.compress_lut_stem())] = soft.black_core()
        files[named_lut(entry.compress_lut_stem(True))] = soft.white_core()
    return files


def lut_reference(name: str, luts: dict | None, inline: bool) -> ocio_ops.Transform:
    """Return the LUT file ``name``: its transform (``inline``) or a FileTransform to it.

    Parameters
    ----------
    name : str
        The LUT file's name (:func:`named_lut`).
    luts : dict or None
        The LUT files (:func:`lut_files`); required with ``inline=True``.
    inline : bool
        The transform itself (``True``) or a FileTransform to the file.

    Returns
    -------
    PyOpenColorIO.Transform
    """
    if inline:
        assert luts is not None, "inline needs the LUT files"
        return luts[name]
    return file_transform(name)


def clip_passes(lut: clip_lut.ClipLUT, luts: dict | None, inline: bool) -> list[ocio_ops.Transform]:
    """Return the clip chain of ``lut`` with its two passes as in the config.

    CIE-XYZ-D65 -> sRGB code values of the clipped display RGB.
    """
    entry = registry.as_display(lut.display)
    cores = [
        lut_reference(named_lut(entry.clip_lut_stem(white)), luts, inline)
        for white in (False, True)
    ]
    return lut.transforms(*cores)


def compress_passes(
    soft: compress_lut.CompressLUT, luts: dict | None, inline: bool
) -> list[ocio_ops.Transform]:
    """Return the compression chain of ``soft`` (a CompressLUT) as in the config.

    Its two squeezes and the clip's two passes: CIE-XYZ-D65 -> sRGB code values.
    """
    entry = registry.as_display(soft.display)
    cores = [
        lut_reference(named_lut(stem(white)), luts, inline)
        for stem in (entry.compress_lut_stem, entry.clip_lut_stem)
        for white in (False, True)
    ]
    return soft.transforms(*cores)
