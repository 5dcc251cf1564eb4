"""The bake's knobs as one validated object: :class:`MapOptions`.

The stages after this one (the config, the files, the shaders, the command line) take
one ``options: MapOptions | None`` instead of the separate knobs and hand it down;
:func:`as_options` turns ``None`` into the defaults. The knobs are documented once, in
:class:`MapOptions`, and each is checked by one function: :func:`check_clip_size` and
:func:`ocio_thinfilm.colour.compress.check_knobs`.
"""

from __future__ import annotations

from dataclasses import dataclass

from ocio_thinfilm.checks import as_count
from ocio_thinfilm.colour import compress
from ocio_thinfilm.lut import clip_lut, tables

__all__ = [
    "KNOB_NAMES",
    "CLIP_SIZES",
    "check_clip_size",
    "MapOptions",
    "as_options",
]

#: The names of the compression's knobs in the API after the ``lut`` stage (and, as
#: ``--compress-threshold`` and ``--compress-limit``, on the command line).
KNOB_NAMES = ("compress_threshold", "compress_limit")
#: Edge lengths the clip LUTs may have (bounds included).
CLIP_SIZES = (9, 129)


def check_clip_size(clip_size: object) -> int:
    """Return ``clip_size`` as an int in the range :data:`CLIP_SIZES` allows.

    Parameters
    ----------
    clip_size : int
        Edge length of the clip LUTs: an integer in [9, 129] (a float equal to one is
        accepted, :func:`ocio_thinfilm.checks.as_count`).

    Returns
    -------
    int

    Raises
    ------
    TypeError
        If ``clip_size`` is not a number.
    ParameterError
        Naming ``clip_size``, for a bool, a non-integer or a value outside [9, 129].

    Examples
    --------
    >>> check_clip_size(65)
    65
    >>> check_clip_size(7)
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: clip_size must be an integer in [9, 129], got 7
    """
    lo, hi = CLIP_SIZES
    return as_count("clip_size", clip_size, lo, hi)


@dataclass(frozen=True)
class MapOptions:
    """The knobs of a bake: the gamut maps' LUTs and the thin-film tables.

    Validated on construction (the values are stored as checked: floats and ints), so a
    function given a ``MapOptions`` has valid knobs. Frozen and hashable.

    Parameters
    ----------
    compress_threshold : float, optional
        The Constant-Lightness Compress view's threshold, ``0 < threshold < 1``
        (default :data:`ocio_thinfilm.colour.compress.THRESHOLD`, 0.8): the fraction of
        the distance to the gamut boundary left untouched.
    compress_limit : float, optional
        Its limit, ``> 1`` (default :data:`ocio_thinfilm.colour.compress.LIMIT`, 1.3):
        the boundary distance mapped onto the boundary (further out: the clip). Both
        knobs are checked by :func:`ocio_thinfilm.colour.compress.check_knobs`; the
        view's description, its LUTs' and its named transforms' state them, and the
        other views do not depend on them.
    clip_size : int, optional
        Edge length of the clip LUTs (the clip's black pass), an integer in [9, 129]
        (:func:`check_clip_size`; default :data:`ocio_thinfilm.lut.clip_lut.CLIP_SIZE`,
        65).
    film_size : int, optional
        Entries of the thickness tables, an integer in [2, 2^20] (default
        :data:`ocio_thinfilm.lut.tables.FILM_SIZE`, 8192).
    morpho_size : int, optional
        Entries of the Morpho angle table, an integer in [2, 2^20] (default
        :data:`ocio_thinfilm.lut.tables.MORPHO_SIZE`, 1024).

    Raises
    ------
    TypeError
        Naming the parameter, for a value that is not a number (a string is not
        parsed).
    ocio_thinfilm.checks.ParameterError
        (a ValueError) naming the parameter, for a value out of its range.

    Examples
    --------
    >>> MapOptions().compress_threshold, MapOptions().clip_size
    (0.8, 65)
    >>> MapOptions(compress_threshold=0.6, compress_limit=1.5).knobs()
    (0.6, 1.5)
    >>> MapOptions(clip_size=7)
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: clip_size must be an integer in [9, 129], got 7
    """

    compress_threshold: float = compress.THRESHOLD
    compress_limit: float = compress.LIMIT
    clip_size: int = clip_lut.CLIP_SIZE
    film_size: int = tables.FILM_SIZE
    morpho_size: int = tables.MORPHO_SIZE

    def __post_init__(self) -> None:
        """Check every knob (naming its parameter) and store the checked values."""
        threshold, limit = compress.check_knobs(
            self.compress_threshold, self.compress_limit, names=KNOB_NAMES
        )
        checked = dict(
            compress_threshold=threshold,
            compress_limit=limit,
            clip_size=check_clip_size(self.clip_size),
            film_size=tables.check_size(self.film_size, what="film_size"),
            morpho_size=tables.check_size(self.morpho_size, what="morpho_size"),
        )
        for name, value in checked.items():
            object.__setattr__(self, name, value)

    def knobs(self, limit_max: float | None = None) -> tuple[float, float]:
        """Return the compression's knobs ``(threshold, limit)``.

        Parameters
        ----------
        limit_max : float, optional
            The largest limit the caller allows (the shaders':
            :data:`ocio_thinfilm.colour.compress.LIMIT_MAX`), checked by
            :func:`ocio_thinfilm.colour.compress.check_knobs`; ``None`` (default) for
            no bound beyond the object's own check.

        Returns
        -------
        tuple of float
            ``(compress_threshold, compress_limit)``.

        Raises
        ------
        ocio_thinfilm.checks.ParameterError
            Naming ``compress_limit``, if it is above ``limit_max``.
        """
        if limit_max is None:
            return self.compress_threshold, self.compress_limit
        return compress.check_knobs(
            self.compress_threshold, self.compress_limit, names=KNOB_NAMES, limit_max=limit_max
        )


def as_options(options: MapOptions | None) -> MapOptions:
    """Return ``options``, or the defaults for ``None``.

    Parameters
    ----------
    options : MapOptions or None
        The knobs given to a function, if any.

    Returns
    -------
    MapOptions

    Raises
    ------
    TypeError
        If ``options`` is neither a :class:`MapOptions` nor ``None``.

    Examples
    --------
    >>> as_options(None) == MapOptions()
    True
    """
    if options is None:
        return MapOptions()
    if not isinstance(options, MapOptions):
        raise TypeError(f"options must be a MapOptions or None, got {options!r}")
    return options
