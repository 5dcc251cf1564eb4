"""One registry of the displays, views and thin-film input spaces the package ships.

Every other module takes its lists from here: ``clip.DISPLAYS``, the config's display
colour spaces and encodings, its thin-film spaces and views, the LUT file names of the
config and of ``export``, and the renderer's display choices and PNG tags. Adding a
display is one :class:`Display` entry in :data:`DISPLAY_LIST` (then ``ocio-thinfilm
bake``); an HDR display is one
:class:`HDRDisplay` entry in :data:`HDR_DISPLAY_LIST`, which reuses the clip LUTs of the
SDR display with its primaries (:data:`DISPLAYS` are the SDR displays, the gamuts the
clip is baked for; :data:`ALL_DISPLAYS` are the config's displays, HDR ones included).

Displays travel through the package as these objects, the way colour-science passes an
``RGB_Colourspace``: a public function that takes a ``display`` accepts the object or its
name and resolves it once (:func:`as_display`); what follows reads its attributes (its
gamut, whether it is HDR, its scale, its LUT stems) instead of looking the name up again.

The registry is plain data (frozen dataclasses) and imports nothing of the pipeline (the
stages import it; ``tests/test_registry.py`` checks its names against the colorimetry);
it is validated once, at import (:func:`validate`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Literal, TypeAlias, overload

from ocio_thinfilm.checks import ParameterError

__all__ = [
    "Display",
    "HDRDisplay",
    "View",
    "ThinFilmSpace",
    "DISPLAY_LIST",
    "HDR_DISPLAY_LIST",
    "VIEW_LIST",
    "THIN_FILM_LIST",
    "DISPLAYS",
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


@dataclass(frozen=True)
class Display:
    """A display of the config.

    ``name``: the OCIO display name (also the gamut the clip works in);
    ``colorimetry``: its RGB space in :data:`.colorimetry.RGB_SPACES` (primaries,
    white); ``colorspace``: the config's display colour space; ``description``: that
    colour space's description; ``encoding``: (description, gamma, offset) of the
    inverse EOTF -- an offset is the sRGB-style piecewise curve, ``None`` a pure power
    (BT.1886); ``lut_stem``: the display's part of LUT file names;
    ``png_colorspace``: the OpenImageIO colour interop ID a PNG for it is tagged with.
    """

    name: str
    colorimetry: str
    colorspace: str
    description: str
    encoding: tuple
    lut_stem: str
    png_colorspace: str

    #: An SDR display (its volume is its RGB parallelepiped up to white).
    hdr: ClassVar[bool] = False

    @property
    def gamut(self) -> Display:
        """The SDR display whose gamut (and clip LUTs) this display uses: itself."""
        return self

    @property
    def scale(self) -> float:
        """Peak white in units of the reference white: 1 for an SDR display."""
        return 1.0

    def clip_lut_stem(self, white: bool = False) -> str:
        """File stem of this display's clip LUT: the pass against the faces through
        black (``white=False``) or through white.

        >>> as_display("Display P3").clip_lut_stem(white=True)
        'ConstantLightnessClip_DisplayP3_WhiteFaces'
        """
        return f"{CLIP_FILE_STEM}_{self.lut_stem}" + ("_WhiteFaces" if white else "_BlackFaces")

    def compress_lut_stem(self, white: bool = False) -> str:
        """File stem of this display's compression squeeze before the clip's pass
        against the faces through black (``white=False``) or through white.

        >>> as_display("sRGB").compress_lut_stem()
        'ConstantLightnessCompress_sRGB_BlackFaces'
        """
        return f"{COMPRESS_FILE_STEM}_{self.lut_stem}" + ("_WhiteFaces" if white else "_BlackFaces")


#: Luminance (cd/m2) at which an HDR display shows the reference white Y = 1: the HDR
#: reference (diffuse) white of ITU-R BT.2408 (PQ and HLG alike).
HDR_REFERENCE_WHITE = 203.0
#: Luminance (cd/m2) of CIE XYZ Y = 1 at the input of OCIO's built-in HDR display
#: transforms (``DISPLAY - CIE-XYZ-D65_to_REC.2100-PQ`` etc.: "linear nits/100").
OCIO_XYZ_UNIT = 100.0


@dataclass(frozen=True)
class HDRDisplay:
    """An HDR display of the config: the parallelepiped of its primaries scaled to the
    peak luminance, so every view is the SDR one of ``gamut`` scaled by
    ``peak / HDR_REFERENCE_WHITE`` (the clip is scale-covariant: the same LUT files).

    ``name``: the OCIO display name; ``gamut``: the SDR display of :data:`DISPLAYS` with
    its primaries and white (whose clip LUTs it reuses); ``colorspace``: the config's
    display colour space; ``description``: its description; ``transfer``: ``"PQ"``
    (SMPTE ST 2084) or ``"HLG"`` (ARIB STD-B67 with the BT.2100 OOTF for ``peak``);
    ``builtin``: OCIO's built-in display transform (CIE XYZ with Y = 1 at
    :data:`OCIO_XYZ_UNIT` cd/m2 -> code values; OCIO >= 2.1); ``peak``: peak white in
    cd/m2; ``lut_stem``: the display's part of file names; ``png_colorspace``: the
    OpenImageIO colour interop ID a (16-bit) PNG for it is tagged with (OpenImageIO 3
    writes it as the PNG cICP chunk, ITU-T H.273 code points).
    """

    name: str
    gamut: Display
    colorspace: str
    description: str
    transfer: str
    builtin: str
    peak: float
    lut_stem: str
    png_colorspace: str

    #: An HDR display (its volume reaches ``scale`` times the reference white).
    hdr: ClassVar[bool] = True

    @property
    def colorimetry(self) -> str:
        """The RGB space of its primaries and white: its gamut's."""
        return self.gamut.colorimetry

    @property
    def scale(self) -> float:
        """Peak white in units of the reference white: the display volume is the
        gamut's RGB parallelepiped up to this value (1000 / 203 = 4.926)."""
        return self.peak / HDR_REFERENCE_WHITE

    def clip_lut_stem(self, white: bool = False) -> str:
        """The clip LUT of its gamut (the same files, scaled)."""
        return self.gamut.clip_lut_stem(white)

    def compress_lut_stem(self, white: bool = False) -> str:
        """The compression squeeze of its gamut (the same files, scaled)."""
        return self.gamut.compress_lut_stem(white)


@dataclass(frozen=True)
class View:
    """A view of every display: ``name``, ``description`` (of its view transforms;
    empty for ``Raw``) and ``raw`` (data passed through: no view transform)."""

    name: str
    description: str = ""
    raw: bool = False


@dataclass(frozen=True)
class ThinFilmSpace:
    """A thin-film input colour space (pixel value -> CIE-XYZ-D65): ``name``,
    ``table`` (``"film"`` or ``"morpho"``: :func:`ocio_thinfilm.lut.tables.film_table` /
    :func:`ocio_thinfilm.lut.tables.morpho_table`), ``args`` for that factory,
    ``lut_stem`` (its CLF file in the config) and ``file_stem`` (the standalone LUT
    files of its table, ``ocio-thinfilm export``)."""

    name: str
    table: str
    args: tuple
    lut_stem: str
    file_stem: str

    @property
    def kind(self) -> str:
        """The table kind (``"phase-change"``, ``"no-phase-change"`` or ``"morpho"``)."""
        return self.args[0] if self.table == "film" else "morpho"


_SRGB_PIECEWISE = ("sRGB piecewise (IEC 61966-2-1)", 2.4, 0.055)

DISPLAY_LIST = (
    Display(
        "sRGB",
        "sRGB",
        "sRGB - Display",
        "sRGB (IEC 61966-2-1) display: Rec.709 primaries, D65, sRGB piecewise encoding",
        _SRGB_PIECEWISE,
        "sRGB",
        "srgb_rec709_display",
    ),
    Display(
        "Display P3",
        "Display P3",
        "Display P3 - Display",
        "Apple Display P3: P3 primaries, D65, sRGB piecewise encoding",
        _SRGB_PIECEWISE,
        "DisplayP3",
        "srgb_p3d65_display",
    ),
    Display(
        "Rec.2020",
        "Rec.2020",
        "Rec.1886 Rec.2020 - Display",
        "ITU-R BT.2020 primaries, D65, BT.1886 gamma 2.4 encoding",
        ("BT.1886 gamma 2.4", 2.4, None),
        "Rec2020",
        "g24_rec2020_display",
    ),
)

_SDR = {d.name: d for d in DISPLAY_LIST}

HDR_DISPLAY_LIST = (
    HDRDisplay(
        "Rec.2100-PQ",
        _SDR["Rec.2020"],
        "Rec.2100-PQ - Display",
        "ITU-R BT.2100 PQ display: Rec.2020 primaries, D65, SMPTE ST 2084 encoding, "
        "1000 cd/m2 peak; CIE XYZ Y = 1 is 203 cd/m2 (ITU-R BT.2408 reference white)",
        "PQ",
        "DISPLAY - CIE-XYZ-D65_to_REC.2100-PQ",
        1000.0,
        "Rec2100PQ",
        "pq_rec2020_display",
    ),
    HDRDisplay(
        "Rec.2100-HLG",
        _SDR["Rec.2020"],
        "Rec.2100-HLG - Display",
        "ITU-R BT.2100 HLG display: Rec.2020 primaries, D65, HLG with the BT.2100 "
        "OOTF for a 1000 cd/m2 peak; CIE XYZ Y = 1 is 203 cd/m2 (ITU-R BT.2408 "
        "reference white)",
        "HLG",
        "DISPLAY - CIE-XYZ-D65_to_REC.2100-HLG-1000nit",
        1000.0,
        "Rec2100HLG",
        "hlg_rec2020_display",
    ),
    HDRDisplay(
        "P3-D65 PQ",
        _SDR["Display P3"],
        "ST2084-P3-D65 - Display",
        "P3-D65 PQ display: P3 primaries, D65, SMPTE ST 2084 encoding, 1000 cd/m2 "
        "peak; CIE XYZ Y = 1 is 203 cd/m2 (ITU-R BT.2408 reference white)",
        "PQ",
        "DISPLAY - CIE-XYZ-D65_to_ST2084-P3-D65",
        1000.0,
        "P3D65PQ",
        "pq_p3d65_display",
    ),
)

VIEW_LIST = (
    View(
        "Constant-Lightness Clip",
        "Smits & Meyer 1990 Section 3.2: display-linear RGB clipped at constant luminance "
        "Y towards the display's neutral axis (two 3D LUTs, faces through black then "
        "through white); scene-linear 1.0 is display white, above white gives white, no "
        "tone mapping.",
    ),
    View(
        "Constant-Lightness Compress",
        "Soft constant-lightness gamut compression: along the same ray as the clip "
        "(towards the grey of the same luminance Y, which it keeps exactly), colours "
        "beyond 0.8 of the distance to the gamut boundary are compressed by the ACES 1.3 "
        "power curve so that 1.3 boundary distances reach the boundary; further out, the "
        "clip. Smooth where the clip is flat (four 3D LUTs, two of them the clip's).",
    ),
    View("Channel Clamp", "Baseline: display-linear RGB clamped per channel to [0, 1]."),
    View(
        "ACES Gamut Compression",
        "Baseline: OCIO's ACES 1.3 reference gamut compression (ACES_GamutComp13) in "
        "display-linear RGB, then a clamp to [0, 1].",
    ),
    View("Raw", raw=True),
)

THIN_FILM_LIST = (
    ThinFilmSpace(
        "Thin Film Phase-Change Thickness",
        "film",
        ("phase-change",),
        "ThinFilm_PhaseChange_Thickness",
        "ThinFilm_PhaseChange",
    ),
    ThinFilmSpace(
        "Thin Film No-Phase-Change Thickness",
        "film",
        ("no-phase-change",),
        "ThinFilm_NoPhaseChange_Thickness",
        "ThinFilm_NoPhaseChange",
    ),
    ThinFilmSpace(
        "Thin Film Morpho Iridescence",
        "morpho",
        (),
        "ThinFilm_Morpho_Iridescence",
        "ThinFilm_Morpho",
    ),
)

#: Names, in order (DISPLAYS: the SDR displays, the gamuts the clip is baked for).
DISPLAYS = tuple(d.name for d in DISPLAY_LIST)
HDR_DISPLAYS = tuple(d.name for d in HDR_DISPLAY_LIST)
#: The config's displays: SDR, then HDR (the objects and their names).
ALL_DISPLAY_LIST: tuple[Display | HDRDisplay, ...] = DISPLAY_LIST + HDR_DISPLAY_LIST
ALL_DISPLAYS = DISPLAYS + HDR_DISPLAYS
VIEWS = tuple(v.name for v in VIEW_LIST)
THIN_FILM_SPACES = tuple(s.name for s in THIN_FILM_LIST)

#: A display of the registry, SDR or HDR.
AnyDisplay: TypeAlias = "Display | HDRDisplay"
#: What a ``display`` parameter accepts: a display of the registry or its name.
DisplayLike: TypeAlias = "str | Display | HDRDisplay"

_BY_NAME: dict[str, Display | HDRDisplay] = {d.name: d for d in ALL_DISPLAY_LIST}


def find_display(name: str) -> Display | HDRDisplay | None:
    """The registry's display called ``name``, ``None`` if it has none (a display of
    another config, e.g. one merged with ``bake --into``)."""
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
    """The registry's display for ``display``, a :class:`Display` or :class:`HDRDisplay`
    of the registry or its name: the one look-up by name, at a public function's door.

    Parameters
    ----------
    display : str, Display or HDRDisplay
        A name of :data:`ALL_DISPLAYS` (of :data:`DISPLAYS` with ``hdr=False``) or one of
        the registry's display objects.
    hdr : bool, optional
        Whether HDR displays are allowed (default ``True``).
    parameter : str, optional
        The caller's parameter name, for the error messages.

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


def display_name(display: DisplayLike | None, *, parameter: str = "display") -> str | None:
    """The name of ``display``: a registry display object gives its name (checked with
    :func:`as_display`), a name or ``None`` passes unchanged (for functions that check
    names against a config of their own), anything else is a TypeError."""
    if display is None or isinstance(display, str):
        return display
    return as_display(display, parameter=parameter).name


def thin_film_space_for_kind(kind: str) -> ThinFilmSpace:
    """The thin-film input space holding the table of ``kind``."""
    for space in THIN_FILM_LIST:
        if space.kind == kind:
            return space
    raise ValueError(f"no thin-film colour space for table kind {kind!r}")


#: File stem of the clip's LUT files (the config's passes and ``export clip``).
CLIP_FILE_STEM = "ConstantLightnessClip"
#: File stem of the compression's own LUT files (the config's squeezes).
COMPRESS_FILE_STEM = "ConstantLightnessCompress"


def validate() -> None:
    """Names unique and non-empty, encodings well formed, LUT stems file-name safe and
    unique, exactly one raw view, last. Raises ValueError. The clip's math
    (:mod:`.clip`, :mod:`.tables`) looks matrices up by the display's name, so a
    display's name must equal its colorimetry space. (That the colorimetry knows those
    spaces and the film kinds is checked by ``tests/test_registry.py``: the registry
    imports nothing of the pipeline.)"""
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
    for d in DISPLAY_LIST:
        if d.colorimetry != d.name:
            raise ValueError(
                f"registry: display {d.name!r}: the clip looks its matrix up by "
                f"name, so its colorimetry space must be {d.name!r}"
            )
        text, gamma, offset = d.encoding
        if not text or not gamma > 0 or not (offset is None or 0 < offset < 1):
            raise ValueError(f"registry: display {d.name!r}: bad encoding {d.encoding!r}")
        if d.colorspace in THIN_FILM_SPACES or not d.colorspace:
            raise ValueError(f"registry: display {d.name!r}: bad colour space {d.colorspace!r}")
    spaces = [d.colorspace for d in DISPLAY_LIST + HDR_DISPLAY_LIST]
    if len(set(spaces)) != len(spaces):
        raise ValueError(f"registry: display colour spaces must be unique: {spaces}")
    for h in HDR_DISPLAY_LIST:
        if (
            h.gamut not in DISPLAY_LIST
            or h.transfer not in ("PQ", "HLG")
            or not h.builtin.startswith("DISPLAY - CIE-XYZ-D65_to_")
            or not h.peak > HDR_REFERENCE_WHITE
            or not h.png_colorspace
        ):
            raise ValueError(f"registry: HDR display {h.name!r}: bad entry {h!r}")
    if [v.name for v in VIEW_LIST if v.raw] != [VIEW_LIST[-1].name]:
        raise ValueError("registry: exactly one raw view, listed last")
    if any(not v.description for v in VIEW_LIST if not v.raw):
        raise ValueError("registry: every view but the raw one needs a description")
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
