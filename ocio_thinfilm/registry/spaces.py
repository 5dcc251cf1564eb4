"""The registry's input colour spaces: thin-film tables, scene-linear and log spaces.

The reference (CIE-XYZ-D65), the texture space, the RGB colorimetries (our names of
colour-science's ``RGB_COLOURSPACES``), the scene-linear spaces, the log curves and the
encoded (log) spaces, each a log curve over a scene-linear gamut. Part of
:mod:`ocio_thinfilm.registry` (import it from there).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = [
    "ThinFilmSpace",
    "THIN_FILM_LIST",
    "SceneSpace",
    "LogCurve",
    "EncodedSpace",
    "LOG_CURVE_LIST",
    "REFERENCE",
    "TEXTURE_SPACE",
    "RAW_SPACE",
    "RGB_COLORIMETRY",
    "SCENE_LINEAR_LIST",
    "SCENE_LINEAR_BY_NAME",
    "ENCODED_LIST",
]


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
    materialx : str or None, optional
        Its name in MaterialX's default colour management (MaterialX Specification 1.39,
        "Color Spaces"), for the film tables a MaterialX document reads; ``None``
        (default) where MaterialX has none.
    threejs : str or None, optional
        Its name as three.js's working colour space (``THREE.LinearSRGBColorSpace``'s
        value), for the film tables a three.js module reads; ``None`` (default) where
        three.js does not work in it.
    """

    name: str
    colorimetry: str
    description: str
    shaper_from_zero: bool = False
    materialx: str | None = None
    threejs: str | None = None


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
#: The non-colour data space (the data role; the raw view shows it): values pass unchanged.
RAW_SPACE = "Raw"
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
        materialx="acescg",
    ),
    SceneSpace(
        name="Linear Rec.709 (sRGB)",
        colorimetry="Rec.709",
        description="Scene-linear Rec.709 / sRGB primaries, D65",
        materialx="lin_rec709",
        threejs="srgb-linear",
    ),
    SceneSpace(
        name="Linear P3-D65",
        colorimetry="Display P3",
        description="Scene-linear P3 primaries, D65",
        materialx="lin_displayp3",
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
