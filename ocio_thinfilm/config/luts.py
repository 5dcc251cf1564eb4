"""The config's LUT files: which there are, their names, and references to them.

Each display's clip LUT (:func:`clip_luts`) and compression LUT (:func:`compress_luts`)
is computed once and handed to every part of the config that uses it; the thin-film
tables and those LUTs are the config's CLF files (:func:`lut_files`), referred to by
FileTransform or put inline (:func:`lut_reference`).
"""

from __future__ import annotations

from ocio_thinfilm import registry
from ocio_thinfilm.config.factories import file_transform
from ocio_thinfilm.lut import clip_lut, compress_lut, ocio_ops, tables
from ocio_thinfilm.lut.options import MapOptions, as_options

__all__ = [
    "named_lut",
    "clip_luts",
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


def clip_luts(*, options: MapOptions | None = None) -> dict:
    """Return the clip LUTs of every SDR display of the registry.

    Parameters
    ----------
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`; here its
        ``clip_size``); ``None`` (default) for the defaults.

    Returns
    -------
    dict
        Display name (:data:`ocio_thinfilm.registry.GAMUT_DISPLAYS`) -> its
        :class:`~ocio_thinfilm.lut.clip_lut.ClipLUT` (each computed once, then cached).
    """
    size = as_options(options).clip_size
    return {display: clip_lut.clip_lut(display, size) for display in registry.GAMUT_DISPLAYS}


def compress_luts(*, options: MapOptions | None = None) -> dict:
    """Return the compression LUTs of every SDR display of the registry.

    Parameters
    ----------
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`: the
        compression's knobs and the clip size they run with); ``None`` (default) for
        the defaults.

    Returns
    -------
    dict
        Display name (:data:`ocio_thinfilm.registry.GAMUT_DISPLAYS`) -> its
        :class:`~ocio_thinfilm.lut.compress_lut.CompressLUT`.
    """
    options = as_options(options)
    threshold, limit = options.knobs()
    return {
        display: compress_lut.compress_lut(
            display, threshold=threshold, limit=limit, clip_size=options.clip_size
        )
        for display in registry.GAMUT_DISPLAYS
    }


def lut_files(
    luts_by_display: dict,
    *,
    compress_by_display: dict | None = None,
    options: MapOptions | None = None,
) -> dict:
    """Return every LUT file the config uses.

    The thin-film tables and, per display, the two passes of its clip LUT and the two
    squeezes of its compression.

    Parameters
    ----------
    luts_by_display : dict
        SDR display (name or registry display) -> its ClipLUT (:func:`clip_luts`).
    compress_by_display : dict, optional
        SDR display -> its CompressLUT (:func:`compress_luts`); ``None`` (default) for
        no compression files.
    options : MapOptions, optional
        The bake's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`; here the
        table sizes); ``None`` (default) for the defaults.

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
    options = as_options(options)
    files = {}
    for space in registry.THIN_FILM_LIST:
        table = tables.thin_film_table(
            space, film_size=options.film_size, morpho_size=options.morpho_size
        )
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
