"""One registry of the displays, views and thin-film input spaces the package ships.

Every other module derives its lists from here: ``clip.DISPLAYS``,
``config.DISPLAY_SPACES``, ``display_transforms.DISPLAY_ENCODINGS``, the config's
thin-film spaces and views, the LUT file names of the config and of ``export``, and the
renderer's display choices and PNG tags. Adding a display is one :class:`Display`
entry in :data:`DISPLAY_LIST` (then ``ocio-thinfilm bake``); an HDR display is one
:class:`HDRDisplay` entry in :data:`HDR_DISPLAY_LIST`, which reuses the clip LUTs of the
SDR display with its primaries (:data:`DISPLAYS` are the SDR displays, the gamuts the
clip is baked for; :data:`ALL_DISPLAYS` are the config's displays, HDR ones included).

The registry is plain data (frozen dataclasses) and imports nothing but
:mod:`ocio_thinfilm.colour.colorimetry`; it is validated once, at import (:func:`validate`).
"""

from __future__ import annotations

from dataclasses import dataclass

from ocio_thinfilm.colour import colorimetry

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
    "ALL_DISPLAYS",
    "VIEWS",
    "THIN_FILM_SPACES",
    "display",
    "hdr_display",
    "is_hdr",
    "gamut_of",
    "HDR_REFERENCE_WHITE",
    "OCIO_XYZ_UNIT",
    "thin_film_space_for_kind",
    "CLIP_FILE_STEM",
    "clip_lut_stem",
    "COMPRESS_FILE_STEM",
    "compress_lut_stem",
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
    gamut: str
    colorspace: str
    description: str
    transfer: str
    builtin: str
    peak: float
    lut_stem: str
    png_colorspace: str

    @property
    def scale(self) -> float:
        """Peak white in units of the reference white: the display volume is the
        gamut's RGB parallelepiped up to this value (1000 / 203 = 4.926)."""
        return self.peak / HDR_REFERENCE_WHITE


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

HDR_DISPLAY_LIST = (
    HDRDisplay(
        "Rec.2100-PQ",
        "Rec.2020",
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
        "Rec.2020",
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
        "Display P3",
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
#: The config's displays: SDR, then HDR.
ALL_DISPLAYS = DISPLAYS + HDR_DISPLAYS
VIEWS = tuple(v.name for v in VIEW_LIST)
THIN_FILM_SPACES = tuple(s.name for s in THIN_FILM_LIST)

_BY_NAME = {d.name: d for d in DISPLAY_LIST}
_HDR_BY_NAME = {d.name: d for d in HDR_DISPLAY_LIST}


def display(name: str) -> Display:
    """The :class:`Display` called ``name`` (ValueError naming the choices otherwise)."""
    try:
        return _BY_NAME[name]
    except (KeyError, TypeError):
        raise ValueError(f"display must be one of {DISPLAYS}, got {name!r}") from None


def hdr_display(name: str) -> HDRDisplay:
    """The :class:`HDRDisplay` called ``name`` (ValueError naming the choices otherwise)."""
    try:
        return _HDR_BY_NAME[name]
    except (KeyError, TypeError):
        raise ValueError(f"display must be one of {HDR_DISPLAYS}, got {name!r}") from None


def is_hdr(name: str) -> bool:
    """Whether ``name`` is an HDR display of the registry."""
    return isinstance(name, str) and name in _HDR_BY_NAME


def gamut_of(name: str) -> str:
    """The SDR display (gamut, clip LUTs) of a display of :data:`ALL_DISPLAYS`.

    >>> gamut_of("Rec.2100-HLG"), gamut_of("sRGB")
    ('Rec.2020', 'sRGB')
    """
    if is_hdr(name):
        return _HDR_BY_NAME[name].gamut
    if isinstance(name, str) and name in _BY_NAME:
        return name
    raise ValueError(f"display must be one of {ALL_DISPLAYS}, got {name!r}")


def thin_film_space_for_kind(kind: str) -> ThinFilmSpace:
    """The thin-film input space holding the table of ``kind``."""
    for space in THIN_FILM_LIST:
        if space.kind == kind:
            return space
    raise ValueError(f"no thin-film colour space for table kind {kind!r}")


#: File stem of the clip's LUT files (the config's passes and ``export clip``).
CLIP_FILE_STEM = "ConstantLightnessClip"


def clip_lut_stem(name: str, white: bool = False) -> str:
    """File stem of a display's clip LUT: the pass against the faces through black
    (``white=False``) or through white.

    >>> clip_lut_stem("Display P3", white=True)
    'ConstantLightnessClip_DisplayP3_WhiteFaces'
    """
    return f"{CLIP_FILE_STEM}_{display(name).lut_stem}" + (
        "_WhiteFaces" if white else "_BlackFaces"
    )


#: File stem of the compression's own LUT files (the config's squeezes).
COMPRESS_FILE_STEM = "ConstantLightnessCompress"


def compress_lut_stem(name: str, white: bool = False) -> str:
    """File stem of a display's compression squeeze before the clip's pass against the
    faces through black (``white=False``) or through white.

    >>> compress_lut_stem("sRGB")
    'ConstantLightnessCompress_sRGB_BlackFaces'
    """
    return f"{COMPRESS_FILE_STEM}_{display(name).lut_stem}" + (
        "_WhiteFaces" if white else "_BlackFaces"
    )


def validate() -> None:
    """Names unique and non-empty, colorimetry spaces known, encodings well formed,
    LUT stems file-name safe and unique, exactly one raw view, last. Raises
    ValueError. The clip's math (:mod:`.clip`, :mod:`.tables`) looks matrices up by
    the display's name, so a display's name must equal its colorimetry space."""
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
        if d.colorimetry not in colorimetry.RGB_SPACES:
            raise ValueError(
                f"registry: display {d.name!r}: unknown colorimetry space {d.colorimetry!r}"
            )
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
            h.gamut not in DISPLAYS
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
            or (s.table == "film" and (len(s.args) != 1 or s.args[0] not in colorimetry.FILM_KINDS))
            or (s.table == "morpho" and s.args)
        ):
            raise ValueError(
                f"registry: thin-film space {s.name!r}: bad table {s.table!r} {s.args!r}"
            )


validate()
