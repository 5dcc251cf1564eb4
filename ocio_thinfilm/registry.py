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
    "Encoding",
    "SceneSpace",
    "EncodedSpace",
    "REFERENCE",
    "TEXTURE_SPACE",
    "RGB_COLORIMETRY",
    "SCENE_LINEAR_LIST",
    "SCENE_LINEAR_SPACES",
    "ENCODED_LIST",
    "ENCODED_SPACES",
    "linear_space_of",
    "find_encoded",
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
class Encoding:
    """An SDR display's encoding (inverse EOTF).

    Parameters
    ----------
    description : str
        What the encoding is, for the config's descriptions.
    gamma : float
        The exponent, > 0.
    offset : float, optional
        In (0, 1): the sRGB-style piecewise curve (IEC 61966-2-1) with this offset;
        ``None`` (default): a pure power (ITU-R BT.1886 with a black level of 0).
    """

    description: str
    gamma: float
    offset: float | None = None


@dataclass(frozen=True)
class Display:
    """An SDR display of the config.

    Parameters
    ----------
    name : str
        The OCIO display name (also the gamut the clip works in).
    colorimetry : str
        Its RGB space (primaries, white), a key of :data:`RGB_COLORIMETRY`; equal to
        ``name`` (:func:`validate`).
    colorspace : str
        The config's display colour space.
    description : str
        That colour space's description.
    encoding : Encoding
        The inverse EOTF: an offset is the sRGB-style piecewise curve, ``None`` a pure
        power (BT.1886).
    lut_stem : str
        The display's part of LUT file names.
    png_colorspace : str
        The OpenImageIO colour interop ID a PNG for it is tagged with.
    """

    name: str
    colorimetry: str
    colorspace: str
    description: str
    encoding: Encoding
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
        """Return the file stem of one of this display's two clip LUTs.

        Parameters
        ----------
        white : bool, optional
            The pass against the faces through white (``True``) or through black
            (``False``, the default).

        Returns
        -------
        str
            ``ConstantLightnessClip_<lut_stem>_BlackFaces`` or ``..._WhiteFaces``.

        Examples
        --------
        >>> as_display("Display P3").clip_lut_stem(white=True)
        'ConstantLightnessClip_DisplayP3_WhiteFaces'
        """
        return f"{CLIP_FILE_STEM}_{self.lut_stem}" + ("_WhiteFaces" if white else "_BlackFaces")

    def compress_lut_stem(self, white: bool = False) -> str:
        """Return the file stem of one of this display's two compression squeezes.

        The squeeze comes before the clip's pass against the same faces.

        Parameters
        ----------
        white : bool, optional
            The squeeze before the pass against the faces through white (``True``) or
            through black (``False``, the default).

        Returns
        -------
        str
            ``ConstantLightnessCompress_<lut_stem>_BlackFaces`` or ``..._WhiteFaces``.

        Examples
        --------
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
    """An HDR display of the config.

    Its volume is the parallelepiped of its primaries scaled to the peak luminance, so
    every view is the SDR one of ``gamut`` scaled by ``peak / HDR_REFERENCE_WHITE`` (the
    clip is scale-covariant: the same LUT files).

    Parameters
    ----------
    name : str
        The OCIO display name.
    gamut : Display
        The SDR display of :data:`DISPLAY_LIST` with its primaries and white (whose clip
        LUTs it reuses).
    colorspace : str
        The config's display colour space.
    description : str
        That colour space's description.
    transfer : str
        ``"PQ"`` (SMPTE ST 2084) or ``"HLG"`` (ARIB STD-B67 with the BT.2100 OOTF for
        ``peak``).
    builtin : str
        OCIO's built-in display transform (CIE XYZ with Y = 1 at :data:`OCIO_XYZ_UNIT`
        cd/m2 -> code values; OCIO >= 2.1), ``"DISPLAY - CIE-XYZ-D65_to_..."``.
    peak : float
        Peak white in cd/m2, above :data:`HDR_REFERENCE_WHITE`.
    lut_stem : str
        The display's part of file names.
    png_colorspace : str
        The OpenImageIO colour interop ID a (16-bit) PNG for it is tagged with
        (OpenImageIO 3 writes it as the PNG cICP chunk, ITU-T H.273 code points).
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
        """Peak white in units of the reference white (1000 / 203 = 4.926).

        The display volume is the gamut's RGB parallelepiped up to this value.
        """
        return self.peak / HDR_REFERENCE_WHITE

    def clip_lut_stem(self, white: bool = False) -> str:
        """Return the file stem of its gamut's clip LUT (the same files, scaled).

        Parameters
        ----------
        white : bool, optional
            The pass against the faces through white (``True``) or through black
            (``False``, the default).

        Returns
        -------
        str
            :meth:`Display.clip_lut_stem` of :attr:`gamut`.
        """
        return self.gamut.clip_lut_stem(white)

    def compress_lut_stem(self, white: bool = False) -> str:
        """Return the file stem of its gamut's compression squeeze (the same files, scaled).

        Parameters
        ----------
        white : bool, optional
            The squeeze before the pass against the faces through white (``True``) or
            through black (``False``, the default).

        Returns
        -------
        str
            :meth:`Display.compress_lut_stem` of :attr:`gamut`.
        """
        return self.gamut.compress_lut_stem(white)


#: The kinds of view: what a view does, which each stage maps to its own code (the
#: config's transforms, the analytic maps, the shaders); a view is one :class:`View`
#: entry of a kind.
VIEW_KINDS = ("clip", "compress", "clamp", "aces", "raw")


@dataclass(frozen=True)
class View:
    """A view of every display.

    Parameters
    ----------
    name : str
        The OCIO view name.
    kind : str
        What it does, one of :data:`VIEW_KINDS`: ``"clip"`` the constant-lightness clip
        (Smits & Meyer 1990, Section 3.2), ``"compress"`` the soft constant-lightness
        compression, ``"clamp"`` a per-channel clamp, ``"aces"`` OCIO's ACES 1.3 gamut
        compression, ``"raw"`` no view transform (the data passes through).
    description : str, optional
        The description of its view transforms; empty (the default) for the raw view.
        The compression's holds the fields ``{threshold}`` and ``{limit}``
        (:meth:`describe`).
    """

    name: str
    kind: str
    description: str = ""

    @property
    def raw(self) -> bool:
        """Whether the view passes data through (no view transform)."""
        return self.kind == "raw"

    def describe(self, threshold: str, limit: str) -> str:
        """Return the description with the compression's knobs filled in.

        Parameters
        ----------
        threshold, limit : str
            The knobs as the description states them
            (:func:`ocio_thinfilm.colour.compress.knob_text`); only the compression's
            description uses them.

        Returns
        -------
        str

        Examples
        --------
        >>> "beyond 0.6 of the distance" in view_of_kind("compress").describe("0.6", "1.5")
        True
        """
        return self.description.format(threshold=threshold, limit=limit)


@dataclass(frozen=True)
class ThinFilmSpace:
    """A thin-film input colour space (pixel value -> CIE-XYZ-D65).

    Parameters
    ----------
    name : str
        The config's colour space name.
    table : str
        ``"film"`` or ``"morpho"``: :func:`ocio_thinfilm.lut.tables.film_table` or
        :func:`ocio_thinfilm.lut.tables.morpho_table`.
    args : tuple
        Positional arguments for that factory: ``(kind,)`` for a film, ``()`` for the
        Morpho table.
    lut_stem : str
        Stem of its CLF file in the config.
    file_stem : str
        Stem of the standalone LUT files of its table (``ocio-thinfilm export``).
    pixel : str
        What the pixel value is.
    default_range : tuple of float
        Default input range of an exported 1D LUT of it.
    default_size : int
        Default number of entries of an exported 1D LUT of it.
    """

    name: str
    table: str
    args: tuple
    lut_stem: str
    file_stem: str
    pixel: str
    default_range: tuple[float, float]
    default_size: int

    @property
    def kind(self) -> str:
        """The table kind (``"phase-change"``, ``"no-phase-change"`` or ``"morpho"``)."""
        return self.args[0] if self.table == "film" else "morpho"


_SRGB_PIECEWISE = Encoding("sRGB piecewise (IEC 61966-2-1)", gamma=2.4, offset=0.055)

DISPLAY_LIST = (
    Display(
        name="sRGB",
        colorimetry="sRGB",
        colorspace="sRGB - Display",
        description="sRGB (IEC 61966-2-1) display: Rec.709 primaries, D65, sRGB piecewise encoding",
        encoding=_SRGB_PIECEWISE,
        lut_stem="sRGB",
        png_colorspace="srgb_rec709_display",
    ),
    Display(
        name="Display P3",
        colorimetry="Display P3",
        colorspace="Display P3 - Display",
        description="Apple Display P3: P3 primaries, D65, sRGB piecewise encoding",
        encoding=_SRGB_PIECEWISE,
        lut_stem="DisplayP3",
        png_colorspace="srgb_p3d65_display",
    ),
    Display(
        name="Rec.2020",
        colorimetry="Rec.2020",
        colorspace="Rec.1886 Rec.2020 - Display",
        description="ITU-R BT.2020 primaries, D65, BT.1886 gamma 2.4 encoding",
        encoding=Encoding("BT.1886 gamma 2.4", gamma=2.4),
        lut_stem="Rec2020",
        png_colorspace="g24_rec2020_display",
    ),
)

_SDR = {d.name: d for d in DISPLAY_LIST}

HDR_DISPLAY_LIST = (
    HDRDisplay(
        name="Rec.2100-PQ",
        gamut=_SDR["Rec.2020"],
        colorspace="Rec.2100-PQ - Display",
        description="ITU-R BT.2100 PQ display: Rec.2020 primaries, D65, SMPTE ST 2084 "
        "encoding, 1000 cd/m2 peak; CIE XYZ Y = 1 is 203 cd/m2 (ITU-R BT.2408 reference "
        "white)",
        transfer="PQ",
        builtin="DISPLAY - CIE-XYZ-D65_to_REC.2100-PQ",
        peak=1000.0,
        lut_stem="Rec2100PQ",
        png_colorspace="pq_rec2020_display",
    ),
    HDRDisplay(
        name="Rec.2100-HLG",
        gamut=_SDR["Rec.2020"],
        colorspace="Rec.2100-HLG - Display",
        description="ITU-R BT.2100 HLG display: Rec.2020 primaries, D65, HLG with the "
        "BT.2100 OOTF for a 1000 cd/m2 peak; CIE XYZ Y = 1 is 203 cd/m2 (ITU-R BT.2408 "
        "reference white)",
        transfer="HLG",
        builtin="DISPLAY - CIE-XYZ-D65_to_REC.2100-HLG-1000nit",
        peak=1000.0,
        lut_stem="Rec2100HLG",
        png_colorspace="hlg_rec2020_display",
    ),
    HDRDisplay(
        name="P3-D65 PQ",
        gamut=_SDR["Display P3"],
        colorspace="ST2084-P3-D65 - Display",
        description="P3-D65 PQ display: P3 primaries, D65, SMPTE ST 2084 encoding, "
        "1000 cd/m2 peak; CIE XYZ Y = 1 is 203 cd/m2 (ITU-R BT.2408 reference white)",
        transfer="PQ",
        builtin="DISPLAY - CIE-XYZ-D65_to_ST2084-P3-D65",
        peak=1000.0,
        lut_stem="P3D65PQ",
        png_colorspace="pq_p3d65_display",
    ),
)

_COMPRESS_DESCRIPTION = (
    "Soft constant-lightness gamut compression: along the same ray as the clip "
    "(towards the grey of the same luminance Y, which it keeps exactly), colours "
    "beyond {threshold} of the distance to the gamut boundary are compressed by the "
    "ACES 1.3 power curve so that {limit} boundary distances reach the boundary; "
    "further out, the clip. Smooth where the clip is flat (four 3D LUTs, two of them "
    "the clip's)."
)


VIEW_LIST = (
    View(
        "Constant-Lightness Clip",
        "clip",
        "Smits & Meyer 1990 Section 3.2: display-linear RGB clipped at constant luminance "
        "Y towards the display's neutral axis (two 3D LUTs, faces through black then "
        "through white); scene-linear 1.0 is display white, above white gives white, no "
        "tone mapping.",
    ),
    View("Constant-Lightness Compress", "compress", _COMPRESS_DESCRIPTION),
    View("Channel Clamp", "clamp", "Baseline: display-linear RGB clamped per channel to [0, 1]."),
    View(
        "ACES Gamut Compression",
        "aces",
        "Baseline: OCIO's ACES 1.3 reference gamut compression (ACES_GamutComp13) in "
        "display-linear RGB, then a clamp to [0, 1].",
    ),
    View("Raw", "raw"),
)


def view_of_kind(kind: str) -> View:
    """Return the view of ``kind`` (one of :data:`VIEW_KINDS`).

    Parameters
    ----------
    kind : str
        A view kind.

    Returns
    -------
    View

    Raises
    ------
    ValueError
        If no view is of that kind.

    Examples
    --------
    >>> view_of_kind("clip").name
    'Constant-Lightness Clip'
    """
    for view in VIEW_LIST:
        if view.kind == kind:
            return view
    raise ValueError(f"no view of kind {kind!r}")


#: The constant-lightness clip's view and the compression's (whose knobs, threshold and
#: limit, a bake may set).
CLIP_VIEW = view_of_kind("clip").name
COMPRESS_VIEW = view_of_kind("compress").name


THIN_FILM_LIST = (
    ThinFilmSpace(
        name="Thin Film Phase-Change Thickness",
        table="film",
        args=("phase-change",),
        lut_stem="ThinFilm_PhaseChange_Thickness",
        file_stem="ThinFilm_PhaseChange",
        pixel="optical thickness t' in um",
        default_range=(0.0, 1.5),
        default_size=4096,
    ),
    ThinFilmSpace(
        name="Thin Film No-Phase-Change Thickness",
        table="film",
        args=("no-phase-change",),
        lut_stem="ThinFilm_NoPhaseChange_Thickness",
        file_stem="ThinFilm_NoPhaseChange",
        pixel="optical thickness t' in um",
        default_range=(0.0, 1.5),
        default_size=4096,
    ),
    ThinFilmSpace(
        name="Thin Film Morpho Iridescence",
        table="morpho",
        args=(),
        lut_stem="ThinFilm_Morpho_Iridescence",
        file_stem="ThinFilm_Morpho",
        pixel="cos(theta), the facing ratio N.V",
        default_range=(0.0, 1.0),
        default_size=1024,
    ),
)


@dataclass(frozen=True)
class SceneSpace:
    """A scene-linear RGB colour space of the config.

    Parameters
    ----------
    name : str
        The config's colour space name.
    colorimetry : str
        Its primaries and white: a key of :data:`RGB_COLORIMETRY`.
    description : str
        The colour space's description.
    shaper_from_zero : bool, optional
        Whether a display LUT's shaper over it starts at 0 (negative values clamped to
        the gamut's boundary: the ACES working gamut AP1, where a mirrored shaper would
        spend a fifth of its grid on the few colours outside it); default ``False``.
    """

    name: str
    colorimetry: str
    description: str
    shaper_from_zero: bool = False


@dataclass(frozen=True)
class LogCurve:
    """A logarithmic encoding of scene-linear values (a camera's or a grading space's).

    The curve's numbers live with its model
    (:data:`ocio_thinfilm.colour.log_curves.LOG_CURVES`); each stage maps the name to
    its own code (the config's OCIO transforms, the shaders' decoding, the evaluation's
    colour-science function).

    Parameters
    ----------
    name : str
        The curve's name.
    reference : str
        The document that defines it.
    """

    name: str
    reference: str


@dataclass(frozen=True)
class EncodedSpace:
    """A colour space of the config that encodes a scene-linear one with a log curve.

    Parameters
    ----------
    name : str
        The config's colour space name.
    linear : str
        The name of the :class:`SceneSpace` it encodes (its gamut: primaries and white).
    curve : str
        The name of its :class:`LogCurve`.
    family : str
        The config's family of the colour space (the maker of the encoding).
    description : str
        The colour space's description.
    plain : bool, optional
        Whether its code values in [0, 1] cover every value the views need (then a
        display LUT from it is a plain 3D LUT over [0, 1]); default ``False``. ACEScct
        does (1.0 is linear 222.9, and the views clamp AP1's negative values to the
        gamut); the camera logs do not: code 0 is linear 0 (DaVinci Intermediate),
        -0.018 (LogC4), -0.014 (S-Log3), but saturated object colours reach -0.05 to
        -0.11 in those wide gamuts, so their display LUTs carry a shaper over the linear
        values (the Resolve form of ``.cube``).
    """

    name: str
    linear: str
    curve: str
    family: str
    description: str
    plain: bool = False

    @property
    def gamut(self) -> SceneSpace:
        """The scene-linear space it encodes."""
        return SCENE_LINEAR_BY_NAME[self.linear]


LOG_CURVE_LIST = (
    LogCurve("ACEScct", "Academy S-2016-001, ACEScct (2016)"),
    LogCurve(
        "DaVinci Intermediate",
        "Blackmagic Design, DaVinci Resolve 17 Wide Gamut Intermediate (2020)",
    ),
    LogCurve("ARRI LogC4", "ARRI, LogC4 Logarithmic Color Space Specification (2022)"),
    LogCurve(
        "S-Log3",
        "Sony, Technical Summary for S-Gamut3.Cine/S-Log3 and S-Gamut3/S-Log3 (2016)",
    ),
)


#: The reference space of the scene and of the displays (CIE XYZ, D65 white, Y = 1 for
#: the perfect reflector).
REFERENCE = "CIE-XYZ-D65"
#: The sRGB-encoded texture space (8-bit images, colour picking): the sRGB display's
#: encoding over Rec.709 primaries.
TEXTURE_SPACE = "sRGB - Texture"

#: Our names of RGB colorimetries (primaries and white) -> colour-science's
#: ``colour.RGB_COLOURSPACES`` names.
RGB_COLORIMETRY = {
    "sRGB": "sRGB",
    "Rec.709": "ITU-R BT.709",
    "Display P3": "Display P3",
    "Rec.2020": "ITU-R BT.2020",
    "ACEScg": "ACEScg",
    "ACES2065-1": "ACES2065-1",
    "DaVinci Wide Gamut": "DaVinci Wide Gamut",
    "ARRI Wide Gamut 4": "ARRI Wide Gamut 4",
    "S-Gamut3.Cine": "S-Gamut3.Cine",
}

SCENE_LINEAR_LIST = (
    SceneSpace(
        name="ACES2065-1",
        colorimetry="ACES2065-1",
        description="ACES2065-1: AP0 primaries, ACES white (Bradford from D65)",
    ),
    SceneSpace(
        name="ACEScg",
        colorimetry="ACEScg",
        description="ACEScg: AP1 primaries, ACES white (Bradford from D65)",
        shaper_from_zero=True,
    ),
    SceneSpace(
        name="Linear Rec.709 (sRGB)",
        colorimetry="Rec.709",
        description="Scene-linear Rec.709 / sRGB primaries, D65",
    ),
    SceneSpace(
        name="Linear P3-D65",
        colorimetry="Display P3",
        description="Scene-linear P3 primaries, D65",
    ),
    SceneSpace(
        name="Linear Rec.2020",
        colorimetry="Rec.2020",
        description="Scene-linear Rec.2020 primaries, D65",
    ),
    SceneSpace(
        name="Linear DaVinci Wide Gamut",
        colorimetry="DaVinci Wide Gamut",
        description="Scene-linear DaVinci Wide Gamut primaries, D65 (DaVinci Resolve's "
        "linear wide-gamut working space)",
    ),
    SceneSpace(
        name="Linear ARRI Wide Gamut 4",
        colorimetry="ARRI Wide Gamut 4",
        description="Scene-linear ARRI Wide Gamut 4 primaries, D65",
    ),
    SceneSpace(
        name="Linear S-Gamut3.Cine",
        colorimetry="S-Gamut3.Cine",
        description="Scene-linear Sony S-Gamut3.Cine primaries, D65",
    ),
)
SCENE_LINEAR_BY_NAME = {s.name: s for s in SCENE_LINEAR_LIST}

ENCODED_LIST = (
    EncodedSpace(
        name="ACEScct",
        linear="ACEScg",
        curve="ACEScct",
        family="ACES",
        description="ACEScct: ACEScg with the ACEScct log encoding (S-2016-001)",
        plain=True,
    ),
    EncodedSpace(
        name="DaVinci Intermediate WideGamut",
        linear="Linear DaVinci Wide Gamut",
        curve="DaVinci Intermediate",
        family="DaVinci",
        description="DaVinci Wide Gamut with the DaVinci Intermediate log encoding "
        "(Blackmagic Design 2020): DaVinci Resolve's wide-gamut timeline; code 1.0 is "
        "linear 100",
    ),
    EncodedSpace(
        name="ARRI LogC4",
        linear="Linear ARRI Wide Gamut 4",
        curve="ARRI LogC4",
        family="ARRI",
        description="ARRI Wide Gamut 4 with the LogC4 log encoding (ARRI 2022); code 1.0 "
        "is linear 469.8",
    ),
    EncodedSpace(
        name="S-Log3 S-Gamut3.Cine",
        linear="Linear S-Gamut3.Cine",
        curve="S-Log3",
        family="Sony",
        description="Sony S-Gamut3.Cine with the S-Log3 log encoding (Sony 2016); code "
        "1.0 is linear 38.4",
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
    return None if encoded is None else encoded.gamut


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
    >>> find_encoded("S-Log3 S-Gamut3.Cine").curve, find_encoded("ACEScg")
    ('S-Log3', None)
    """
    for encoded in ENCODED_LIST:
        if encoded.name == name:
            return encoded
    return None


#: File stem of the clip's LUT files (the config's passes and ``export clip``).
CLIP_FILE_STEM = "ConstantLightnessClip"
#: File stem of the compression's own LUT files (the config's squeezes).
COMPRESS_FILE_STEM = "ConstantLightnessCompress"


def validate() -> None:
    """Check the registry's entries against each other (run once, at import).

    Names unique and non-empty, encodings well formed, LUT stems file-name safe and
    unique, exactly one raw view, last. The clip's math (:mod:`.clip`, :mod:`.tables`)
    looks matrices up by the display's name, so a display's name must equal its
    colorimetry space. (That the colorimetry knows those spaces and the film kinds is
    checked by ``tests/test_registry.py``: the registry imports nothing of the
    pipeline.)

    Raises
    ------
    ValueError
        Naming the first entry that breaks a rule.
    """
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
            h.gamut not in DISPLAY_LIST
            or h.transfer not in ("PQ", "HLG")
            or not h.builtin.startswith("DISPLAY - CIE-XYZ-D65_to_")
            or not h.peak > HDR_REFERENCE_WHITE
            or not h.png_colorspace
        ):
            raise ValueError(f"registry: HDR display {h.name!r}: bad entry {h!r}")
    if sorted(v.kind for v in VIEW_LIST) != sorted(VIEW_KINDS):
        raise ValueError(f"registry: one view of each kind {VIEW_KINDS}")
    for kind, names in (("encoded space", ENCODED_SPACES), ("log curve", LOG_CURVES)):
        if len(set(names)) != len(names) or not all(names):
            raise ValueError(f"registry: {kind} names must be unique and non-empty: {names}")
    if [v.name for v in VIEW_LIST if v.raw] != [VIEW_LIST[-1].name]:
        raise ValueError("registry: exactly one raw view, listed last")
    if any(not v.description for v in VIEW_LIST if not v.raw):
        raise ValueError("registry: every view but the raw one needs a description")
    spaces_all = (
        [REFERENCE]
        + list(SCENE_LINEAR_SPACES)
        + list(ENCODED_SPACES)
        + list(THIN_FILM_SPACES)
        + [d.colorspace for d in ALL_DISPLAY_LIST]
    )
    if len(set(spaces_all)) != len(spaces_all):
        raise ValueError(f"registry: colour space names must be unique: {spaces_all}")
    for c in SCENE_LINEAR_LIST:
        if c.colorimetry not in RGB_COLORIMETRY:
            raise ValueError(f"registry: {c.name!r}: unknown colorimetry {c.colorimetry!r}")
    for d in DISPLAY_LIST:
        if d.colorimetry not in RGB_COLORIMETRY:
            raise ValueError(f"registry: {d.name!r}: unknown colorimetry {d.colorimetry!r}")
    for encoded in ENCODED_LIST:
        if encoded.linear not in SCENE_LINEAR_SPACES:
            raise ValueError(
                f"registry: {encoded.name!r} encodes an unknown space {encoded.linear!r}"
            )
        if encoded.curve not in LOG_CURVES or not encoded.family:
            raise ValueError(f"registry: {encoded.name!r}: bad curve or family {encoded!r}")
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
