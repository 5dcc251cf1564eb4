"""One registry of the displays, views and thin-film input spaces the package ships.

Every other module takes its lists from here: ``clip.DISPLAYS``, the config's display
colour spaces and encodings, its thin-film spaces and views, the LUT file names of the
config and of ``export``, and the renderer's display choices and PNG tags. Adding a
display is one :class:`Display` entry in :data:`DISPLAY_LIST` (then ``ocio-thinfilm
bake``); an HDR display is one
:class:`HDRDisplay` entry in :data:`HDR_DISPLAY_LIST`, which reuses the clip LUTs of the
SDR display with its primaries (:data:`DISPLAYS` are the SDR displays, the gamuts the
clip is baked for, except that displays with one gamut share the tables of the first of
them, :data:`GAMUT_DISPLAYS`; :data:`ALL_DISPLAYS` are the config's displays, HDR ones
included).

Displays travel through the package as these objects, the way colour-science passes an
``RGB_Colourspace``: a public function that takes a ``display`` accepts the object or its
name and resolves it once (:func:`as_display`); what follows reads its attributes (its
gamut, whether it is HDR, its scale, its LUT stems) instead of looking the name up again.

The registry is plain data (frozen dataclasses) and imports nothing of the pipeline (the
stages import it; ``tests/test_registry.py`` checks its names against the colorimetry);
it is validated once, at import (:func:`validate`). Its entries live in
:mod:`.displays`, :mod:`.views` and :mod:`.spaces`; this module holds the names, the
look-ups and the validation, and every public name of the three.
"""

from __future__ import annotations

from typing import Literal, TypeAlias, overload

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.registry.curves import BLACK_TOLERANCE, CURVE_KINDS
from ocio_thinfilm.registry.displays import (
    CLIP_FILE_STEM,
    COMPRESS_FILE_STEM,
    DISPLAY_LIST,
    HDR_DISPLAY_LIST,
    HDR_REFERENCE_WHITE,
    OCIO_XYZ_UNIT,
    Display,
    Encoding,
    HDRDisplay,
)
from ocio_thinfilm.registry.spaces import (
    ENCODED_LIST,
    GAMUT_LIST,
    LOG_CURVE_LIST,
    RAW_SPACE,
    REFERENCE,
    RGB_COLORIMETRY,
    SCENE_LINEAR_BY_NAME,
    SCENE_LINEAR_LIST,
    TEXTURE_SPACE,
    THIN_FILM_LIST,
    EncodedSpace,
    Gamut,
    LogCurve,
    SceneSpace,
    ThinFilmSpace,
)
from ocio_thinfilm.registry.views import (
    CLIP_VIEW,
    COMPRESS_VIEW,
    VIEW_KINDS,
    VIEW_LIST,
    View,
    view_of_kind,
)

__all__ = [
    "Display",
    "HDRDisplay",
    "View",
    "ThinFilmSpace",
    "Encoding",
    "SceneSpace",
    "EncodedSpace",
    "REFERENCE",
    "TEXTURE_SPACE",
    "RAW_SPACE",
    "RGB_COLORIMETRY",
    "SCENE_LINEAR_LIST",
    "SCENE_LINEAR_SPACES",
    "ENCODED_LIST",
    "ENCODED_SPACES",
    "linear_space_of",
    "find_encoded",
    "SPACE_KINDS",
    "space_kind",
    "SCENE_LINEAR_BY_NAME",
    "DISPLAY_LIST",
    "HDR_DISPLAY_LIST",
    "VIEW_LIST",
    "COMPRESS_VIEW",
    "VIEW_KINDS",
    "view_of_kind",
    "as_view",
    "CLIP_VIEW",
    "LogCurve",
    "LOG_CURVE_LIST",
    "LOG_CURVES",
    "CURVE_KINDS",
    "BLACK_TOLERANCE",
    "find_curve",
    "Gamut",
    "GAMUT_LIST",
    "THIN_FILM_LIST",
    "DISPLAYS",
    "GAMUT_DISPLAY_LIST",
    "GAMUT_DISPLAYS",
    "colorimetry_of",
    "HDR_DISPLAYS",
    "ALL_DISPLAY_LIST",
    "ALL_DISPLAYS",
    "VIEWS",
    "THIN_FILM_SPACES",
    "AnyDisplay",
    "DisplayLike",
    "as_display",
    "find_display",
    "display_name",
    "HDR_REFERENCE_WHITE",
    "OCIO_XYZ_UNIT",
    "thin_film_space_for_kind",
    "CLIP_FILE_STEM",
    "COMPRESS_FILE_STEM",
    "validate",
]


#: Names, in order (DISPLAYS: the SDR displays).
DISPLAYS = tuple(d.name for d in DISPLAY_LIST)
#: The SDR displays the clip tables are baked for: one per gamut (primaries and white),
#: the first display with it; the others share its tables (``Display.gamut``).
GAMUT_DISPLAY_LIST = tuple(d for d in DISPLAY_LIST if d.gamut is d)
GAMUT_DISPLAYS = tuple(d.name for d in GAMUT_DISPLAY_LIST)
HDR_DISPLAYS = tuple(d.name for d in HDR_DISPLAY_LIST)
#: The config's displays: SDR, then HDR (the objects and their names).
ALL_DISPLAY_LIST: tuple[Display | HDRDisplay, ...] = DISPLAY_LIST + HDR_DISPLAY_LIST
ALL_DISPLAYS = DISPLAYS + HDR_DISPLAYS
VIEWS = tuple(v.name for v in VIEW_LIST)
THIN_FILM_SPACES = tuple(s.name for s in THIN_FILM_LIST)
SCENE_LINEAR_SPACES = tuple(s.name for s in SCENE_LINEAR_LIST)
ENCODED_SPACES = tuple(s.name for s in ENCODED_LIST)
LOG_CURVES = tuple(c.name for c in LOG_CURVE_LIST)

#: A display of the registry, SDR or HDR.
AnyDisplay: TypeAlias = "Display | HDRDisplay"
#: What a ``display`` parameter accepts: a display of the registry or its name.
DisplayLike: TypeAlias = "str | Display | HDRDisplay"

_BY_NAME: dict[str, Display | HDRDisplay] = {d.name: d for d in ALL_DISPLAY_LIST}


def find_display(name: str) -> Display | HDRDisplay | None:
    """Return the registry's display called ``name``, if it has one.

    Parameters
    ----------
    name : str
        A display name; anything that is not a string finds nothing.

    Returns
    -------
    Display, HDRDisplay or None
        The display, or ``None`` for a name the registry does not have (a display of
        another config, e.g. one merged with ``bake --into``).

    Examples
    --------
    >>> find_display("Rec.2100-PQ").peak, find_display("ACES 1.0 - SDR Video")
    (1000.0, None)
    """
    return _BY_NAME.get(name) if isinstance(name, str) else None


@overload
def as_display(
    display: DisplayLike, *, hdr: Literal[False], parameter: str = "display"
) -> Display: ...
@overload
def as_display(
    display: DisplayLike, *, hdr: bool = True, parameter: str = "display"
) -> Display | HDRDisplay: ...
def as_display(
    display: DisplayLike, *, hdr: bool = True, parameter: str = "display"
) -> Display | HDRDisplay:
    """Return the registry's display for ``display``, a display object or its name.

    The one look-up by name, at a public function's door.

    Parameters
    ----------
    display : str, Display or HDRDisplay
        A name of :data:`ALL_DISPLAYS` (of :data:`DISPLAYS` with ``hdr=False``) or one of
        the registry's display objects.
    hdr : bool, optional
        Whether HDR displays are allowed (default ``True``).
    parameter : str, optional
        The caller's parameter name, for the error messages (default ``"display"``).

    Returns
    -------
    Display or HDRDisplay
        The registry's display (an :class:`HDRDisplay` only with ``hdr=True``).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (a ValueError) for an unknown name, an HDR display where ``hdr=False``, or a
        display object that is not the registry's.
    TypeError
        For anything else.

    Examples
    --------
    >>> p3 = as_display("Display P3")
    >>> as_display(p3) is p3, p3.hdr, as_display("Rec.2100-HLG").gamut.name
    (True, False, 'Rec.2020')
    >>> as_display("Rec.2100-PQ", hdr=False)
    Traceback (most recent call last):
    ...
    ocio_thinfilm.checks.ParameterError: display must be one of ('sRGB', ...), got 'Rec.2100-PQ'
    """
    if isinstance(display, (Display, HDRDisplay)):
        entry = find_display(display.name)
        if entry != display:
            raise ParameterError(
                parameter, f" must be a display of the registry, got an unknown {display!r}"
            )
    elif isinstance(display, str):
        entry = find_display(display)
    else:
        raise TypeError(
            f"{parameter} must be a display name (str) or a registry Display, got "
            f"{display!r} ({type(display).__name__})"
        )
    if entry is None or (entry.hdr and not hdr):
        choices = ALL_DISPLAYS if hdr else DISPLAYS
        raise ParameterError(parameter, f" must be one of {choices}, got {display!r}")
    return entry


def colorimetry_of(name: str) -> str | None:
    """Return the RGB space (a key of :data:`RGB_COLORIMETRY`) a name stands for.

    A gamut's name stands for itself, a display's name for its gamut (so the clip's
    math may be given either).

    Parameters
    ----------
    name : str
        A gamut of :data:`GAMUT_LIST` or a display of :data:`ALL_DISPLAYS`.

    Returns
    -------
    str or None
        The gamut's name, or ``None`` for a name that is neither.

    Examples
    --------
    >>> colorimetry_of("P3-DCI"), colorimetry_of("Rec.2100-PQ"), colorimetry_of("ACEScg")
    ('DCI-P3', 'Rec.2020', 'ACEScg')
    """
    if name in RGB_COLORIMETRY:
        return name
    entry = find_display(name)
    return None if entry is None else entry.colorimetry


def display_name(display: DisplayLike | None, *, parameter: str = "display") -> str | None:
    """Return the name of ``display``.

    A registry display object gives its name (checked with :func:`as_display`); a name
    or ``None`` passes unchanged, unchecked (for functions that check names against a
    config of their own).

    Parameters
    ----------
    display : str, Display, HDRDisplay or None
        A display name, one of the registry's display objects, or ``None``.
    parameter : str, optional
        The caller's parameter name, for the error messages (default ``"display"``).

    Returns
    -------
    str or None
        The name, or ``None``.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        For a display object that is not the registry's.
    TypeError
        For anything else.

    Examples
    --------
    >>> display_name(as_display("sRGB")), display_name("any name"), display_name(None)
    ('sRGB', 'any name', None)
    """
    if display is None or isinstance(display, str):
        return display
    return as_display(display, parameter=parameter).name


_VIEW_BY_NAME = {v.name: v for v in VIEW_LIST}


def as_view(view: str | View, *, parameter: str = "view", raw: bool = True) -> View:
    """Return the registry's view for ``view``, a view object or its name.

    The one look-up of a view by name, at a public function's door; what follows reads
    its :attr:`View.kind`.

    Parameters
    ----------
    view : str or View
        A name of :data:`VIEWS` or one of the registry's views.
    parameter : str, optional
        The caller's parameter name, for the error messages (default ``"view"``).
    raw : bool, optional
        Whether the raw view is allowed (default ``True``).

    Returns
    -------
    View

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (a ValueError) for an unknown view, or the raw one where ``raw=False``.

    Examples
    --------
    >>> as_view("Channel Clamp").kind
    'clamp'
    """
    entry = _VIEW_BY_NAME.get(view.name if isinstance(view, View) else view)
    if isinstance(view, View) and entry != view:
        entry = None
    if entry is None or (entry.raw and not raw):
        choices = VIEWS if raw else tuple(v.name for v in VIEW_LIST if not v.raw)
        raise ParameterError(parameter, f" must be one of {choices}, got {view!r}")
    return entry


def thin_film_space_for_kind(kind: str) -> ThinFilmSpace:
    """Return the thin-film input space holding the table of ``kind``.

    Parameters
    ----------
    kind : str
        ``"phase-change"``, ``"no-phase-change"`` or ``"morpho"``.

    Returns
    -------
    ThinFilmSpace
        The space of :data:`THIN_FILM_LIST` whose :attr:`ThinFilmSpace.kind` is ``kind``.

    Raises
    ------
    ValueError
        If no space holds that kind.

    Examples
    --------
    >>> thin_film_space_for_kind("morpho").name
    'Thin Film Morpho Iridescence'
    """
    for space in THIN_FILM_LIST:
        if space.kind == kind:
            return space
    raise ValueError(f"no thin-film colour space for table kind {kind!r}")


#: The kinds of the config's colour spaces the registry names: what a space is, which a
#: stage maps to its own code (the input decodings of the shaders and of ``export view``).
SPACE_KINDS = ("reference", "scene-linear", "encoded", "texture", "raw", "thin-film", "display")

_SPACE_KIND = {
    REFERENCE: "reference",
    TEXTURE_SPACE: "texture",
    RAW_SPACE: "raw",
    **{name: "scene-linear" for name in SCENE_LINEAR_SPACES},
    **{name: "encoded" for name in ENCODED_SPACES},
    **{name: "thin-film" for name in THIN_FILM_SPACES},
    **{d.colorspace: "display" for d in ALL_DISPLAY_LIST},
}


def space_kind(name: str) -> str | None:
    """Return the kind (:data:`SPACE_KINDS`) of the config's colour space ``name``.

    The one look-up of a colour space's kind by its name: what follows reads the kind.

    Parameters
    ----------
    name : str
        A colour space name of the config.

    Returns
    -------
    str or None
        One of :data:`SPACE_KINDS`, or ``None`` for a name the registry does not have
        (a space of another config, a film file's space).

    Examples
    --------
    >>> space_kind("CIE-XYZ-D65"), space_kind("ACEScct"), space_kind("sRGB - Texture")
    ('reference', 'encoded', 'texture')
    >>> space_kind("no such space") is None
    True
    """
    return _SPACE_KIND.get(name) if isinstance(name, str) else None


def linear_space_of(name: str) -> SceneSpace | None:
    """Return the scene-linear space holding the RGB of the config's colour space ``name``.

    Parameters
    ----------
    name : str
        A colour space name of the config.

    Returns
    -------
    SceneSpace or None
        The space itself for a :class:`SceneSpace`, the one it encodes for an
        :class:`EncodedSpace`, ``None`` for any other (the reference XYZ included).

    Examples
    --------
    >>> linear_space_of("ACEScct").name, linear_space_of("CIE-XYZ-D65")
    ('ACEScg', None)
    """
    if name in SCENE_LINEAR_BY_NAME:
        return SCENE_LINEAR_BY_NAME[name]
    encoded = find_encoded(name)
    return None if encoded is None else encoded.linear


def find_encoded(name: str) -> EncodedSpace | None:
    """Return the encoded space called ``name``, if the registry has one.

    Parameters
    ----------
    name : str
        A colour space name of the config.

    Returns
    -------
    EncodedSpace or None

    Examples
    --------
    >>> find_encoded("S-Log3 S-Gamut3.Cine").curve.name, find_encoded("ACEScg")
    ('S-Log3', None)
    """
    for encoded in ENCODED_LIST:
        if encoded.name == name:
            return encoded
    return None


def find_curve(name: str) -> LogCurve:
    """Return the log curve called ``name`` (a name of :data:`LOG_CURVES`).

    Parameters
    ----------
    name : str
        A log curve's name.

    Returns
    -------
    LogCurve

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        For a name the registry does not have.

    Examples
    --------
    >>> find_curve("Apple Log").kind
    'quadratic-toe'
    """
    for curve in LOG_CURVE_LIST:
        if curve.name == name:
            return curve
    raise ParameterError("curve", f" must be one of {LOG_CURVES}, got {name!r}")


def validate() -> None:
    """Check the registry's entries against each other (run once, at import).

    Names unique and non-empty, encodings well formed, LUT stems file-name safe and
    unique, exactly one raw view, last; a display named like a gamut has that gamut (the
    clip's math takes either name, :func:`colorimetry_of`). (That the colorimetry
    knows those spaces and the film kinds is
    checked by ``tests/test_registry.py``: the registry imports nothing of the
    pipeline.)

    Raises
    ------
    ValueError
        Naming the first entry that breaks a rule.
    """
    _check_names()
    _check_displays()
    _check_views()
    _check_spaces()
    _check_thin_film_spaces()


def _check_names() -> None:
    """Check that names are unique and non-empty, LUT stems unique and file-name safe."""
    import re

    for kind, names in (
        ("display", DISPLAYS + HDR_DISPLAYS),
        ("view", VIEWS),
        ("thin-film space", THIN_FILM_SPACES),
    ):
        if len(set(names)) != len(names) or not all(names):
            raise ValueError(f"registry: {kind} names must be unique and non-empty: {names}")
    stems = (
        [d.lut_stem for d in DISPLAY_LIST + HDR_DISPLAY_LIST]
        + [s.lut_stem for s in THIN_FILM_LIST]
        + [s.file_stem for s in THIN_FILM_LIST]
    )
    if len(set(stems)) != len(stems):
        raise ValueError(f"registry: LUT file stems must be unique: {stems}")
    for stem in stems:
        if not re.fullmatch(r"[A-Za-z0-9_]+", stem):
            raise ValueError(f"registry: LUT file stem {stem!r} is not file-name safe")


def _check_displays() -> None:
    """Check the displays: gamut-named ones, encodings, colour spaces, HDR entries."""
    for d in DISPLAY_LIST:
        if d.name in RGB_COLORIMETRY and d.colorimetry != d.name:
            raise ValueError(
                f"registry: display {d.name!r} is named like a gamut, so its gamut "
                f"must be {d.name!r}, not {d.colorimetry!r}"
            )
        e = d.encoding
        if not e.description or not e.gamma > 0 or not (e.offset is None or 0 < e.offset < 1):
            raise ValueError(f"registry: display {d.name!r}: bad encoding {d.encoding!r}")
        if d.colorspace in THIN_FILM_SPACES or not d.colorspace:
            raise ValueError(f"registry: display {d.name!r}: bad colour space {d.colorspace!r}")
    spaces = [d.colorspace for d in DISPLAY_LIST + HDR_DISPLAY_LIST]
    if len(set(spaces)) != len(spaces):
        raise ValueError(f"registry: display colour spaces must be unique: {spaces}")
    for h in HDR_DISPLAY_LIST:
        if (
            h.gamut not in GAMUT_DISPLAY_LIST
            or h.transfer not in ("PQ", "HLG")
            or not h.builtin.startswith("DISPLAY - CIE-XYZ-D65_to_")
            or not h.peak > HDR_REFERENCE_WHITE
            or not h.png_colorspace
        ):
            raise ValueError(f"registry: HDR display {h.name!r}: bad entry {h!r}")


def _check_views() -> None:
    """Check one view of each kind, the raw one last; encodings' and curves' names."""
    if sorted(v.kind for v in VIEW_LIST) != sorted(VIEW_KINDS):
        raise ValueError(f"registry: one view of each kind {VIEW_KINDS}")
    for kind, names in (("encoded space", ENCODED_SPACES), ("log curve", LOG_CURVES)):
        if len(set(names)) != len(names) or not all(names):
            raise ValueError(f"registry: {kind} names must be unique and non-empty: {names}")
    if [v.name for v in VIEW_LIST if v.raw] != [VIEW_LIST[-1].name]:
        raise ValueError("registry: exactly one raw view, listed last")
    if any(not v.description for v in VIEW_LIST if not v.raw):
        raise ValueError("registry: every view but the raw one needs a description")


def _check_spaces() -> None:
    """Check colour space and gamut names unique, colorimetries and encodings known."""
    spaces_all = (
        [REFERENCE, TEXTURE_SPACE, RAW_SPACE]
        + list(SCENE_LINEAR_SPACES)
        + list(ENCODED_SPACES)
        + list(THIN_FILM_SPACES)
        + [d.colorspace for d in ALL_DISPLAY_LIST]
    )
    if len(set(spaces_all)) != len(spaces_all):
        raise ValueError(f"registry: colour space names must be unique: {spaces_all}")
    gamuts = [g.name for g in GAMUT_LIST]
    if len(set(gamuts)) != len(gamuts):
        raise ValueError(f"registry: gamut names must be unique: {gamuts}")
    for c in SCENE_LINEAR_LIST:
        if c.colorimetry not in RGB_COLORIMETRY:
            raise ValueError(f"registry: {c.name!r}: unknown colorimetry {c.colorimetry!r}")
    for d in DISPLAY_LIST:
        if d.colorimetry not in RGB_COLORIMETRY:
            raise ValueError(f"registry: {d.name!r}: unknown colorimetry {d.colorimetry!r}")
    for encoded in ENCODED_LIST:
        if SCENE_LINEAR_BY_NAME.get(encoded.linear.name) != encoded.linear:
            raise ValueError(
                f"registry: {encoded.name!r} encodes an unknown space {encoded.linear!r}"
            )
        if not isinstance(encoded.curve, LogCurve) or not encoded.family:
            raise ValueError(f"registry: {encoded.name!r}: bad curve or family {encoded!r}")
    if sorted(set(_SPACE_KIND.values())) != sorted(SPACE_KINDS):
        raise ValueError(f"registry: a colour space of each kind {SPACE_KINDS}")


def _check_thin_film_spaces() -> None:
    """Check one thin-film space per table kind, each with a well-formed table."""
    kinds = [s.kind for s in THIN_FILM_LIST]
    if len(set(kinds)) != len(kinds):
        raise ValueError(f"registry: one thin-film space per table kind: {kinds}")
    for s in THIN_FILM_LIST:
        if (
            s.table not in ("film", "morpho")
            or (s.table == "film" and (len(s.args) != 1 or not isinstance(s.args[0], str)))
            or (s.table == "morpho" and s.args)
        ):
            raise ValueError(
                f"registry: thin-film space {s.name!r}: bad table {s.table!r} {s.args!r}"
            )


validate()
