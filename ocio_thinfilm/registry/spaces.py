"""The registry's input colour spaces: thin-film tables, scene-linear and log spaces.

The reference (CIE-XYZ-D65), the texture space, the scene-linear spaces and the encoded
(log) spaces, each one entry: a log curve over a scene-linear space, both objects
(:mod:`.curves`); the lists of curves, linear spaces and gamuts derive from the entries.
Part of :mod:`ocio_thinfilm.registry` (import it from there).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ocio_thinfilm.registry.curves import Gamut, LogCurve
from ocio_thinfilm.registry.displays import DISPLAY_LIST, P3_GAMUT, REC2020_GAMUT

__all__ = [
    "ThinFilmSpace",
    "THIN_FILM_LIST",
    "SceneSpace",
    "Gamut",
    "GAMUT_LIST",
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
    gamut : Gamut
        Its primaries and white.
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
    blender : tuple of str or None, optional
        ``(name, interop id)`` of the colour space in Blender's own OCIO config (its
        name and its OCIO interop id), for the film tables a Blender script loads in a
        scene of that working space (Blender 5: ``bpy.data.colorspace.working_space``);
        ``None`` (default) where Blender has none.
    """

    name: str
    gamut: Gamut
    description: str
    shaper_from_zero: bool = False
    materialx: str | None = None
    threejs: str | None = None
    blender: tuple[str, str] | None = None

    @property
    def colorimetry(self) -> str:
        """Its gamut's name (a key of :data:`RGB_COLORIMETRY`, as the colorimetry takes)."""
        return self.gamut.name


@dataclass(frozen=True)
class EncodedSpace:
    """A colour space of the config that encodes a scene-linear one with a log curve.

    One entry is the whole space: its curve and its linear space (with its gamut) are
    objects of the entry, from which every stage derives its code and the registry its
    lists (:data:`LOG_CURVE_LIST`, the linear spaces, :data:`RGB_COLORIMETRY`).

    Parameters
    ----------
    name : str
        The config's colour space name.
    linear : SceneSpace
        The scene-linear space it encodes (its gamut: primaries and white).
    curve : LogCurve
        Its log curve.
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
    linear: SceneSpace
    curve: LogCurve
    family: str
    description: str
    plain: bool = False

    @property
    def gamut(self) -> Gamut:
        """The gamut of the scene-linear space it encodes."""
        return self.linear.gamut


def _gamut(name: str, colour_science: str | None = None) -> Gamut:
    return Gamut(name, colour_science or name)


#: The gamuts of the explicit scene-linear spaces (the displays' are in :mod:`.displays`).
_REC709, _P3, _REC2020 = _gamut("Rec.709", "ITU-R BT.709"), P3_GAMUT, REC2020_GAMUT
_ACESCG, _AP0 = _gamut("ACEScg"), _gamut("ACES2065-1")

_ACESCG_SPACE = SceneSpace(
    name="ACEScg",
    gamut=_ACESCG,
    description="ACEScg: AP1 primaries, ACES white (Bradford from D65)",
    shaper_from_zero=True,
    materialx="acescg",
    blender=("ACEScg", "lin_ap1_scene"),
)
_REC2020_SPACE = SceneSpace(
    name="Linear Rec.2020",
    gamut=_REC2020,
    description="Scene-linear Rec.2020 primaries, D65",
    blender=("Linear Rec.2020", "lin_rec2020_scene"),
)
_DWG_SPACE = SceneSpace(
    name="Linear DaVinci Wide Gamut",
    gamut=_gamut("DaVinci Wide Gamut"),
    description="Scene-linear DaVinci Wide Gamut primaries, D65 (DaVinci Resolve's "
    "linear wide-gamut working space)",
)
_AWG4_SPACE = SceneSpace(
    name="Linear ARRI Wide Gamut 4",
    gamut=_gamut("ARRI Wide Gamut 4"),
    description="Scene-linear ARRI Wide Gamut 4 primaries, D65",
)
_SGAMUT3CINE_SPACE = SceneSpace(
    name="Linear S-Gamut3.Cine",
    gamut=_gamut("S-Gamut3.Cine"),
    description="Scene-linear Sony S-Gamut3.Cine primaries, D65",
)

#: The reference space of the scene and of the displays (CIE XYZ, D65 white, Y = 1 for
#: the perfect reflector).
REFERENCE = "CIE-XYZ-D65"
#: The non-colour data space (the data role; the raw view shows it): values pass unchanged.
RAW_SPACE = "Raw"
#: The sRGB-encoded texture space (8-bit images, colour picking): the sRGB display's
#: encoding over Rec.709 primaries.
TEXTURE_SPACE = "sRGB - Texture"

_LOGC4_A = (2.0**18 - 16.0) / 117.45
_LOGC4_B = (1023.0 - 95.0) / 1023.0
_LOGC4_C = 95.0 / 1023.0
_LOGC4_S = (7.0 * math.log(2.0) * 2.0 ** (7.0 - 14.0 * _LOGC4_C / _LOGC4_B)) / (_LOGC4_A * _LOGC4_B)
_LOGC4_T = (2.0 ** (14.0 * (-_LOGC4_C / _LOGC4_B) + 6.0) - 64.0) / _LOGC4_A
#: Canon Log 3 (v1.2) takes scene reflection / 0.9 (colour-science's ``in_reflection``).
_CLOG3_REFLECTION = 0.9

ENCODED_LIST = (
    EncodedSpace(
        name="ACEScct",
        linear=_ACESCG_SPACE,
        curve=LogCurve(
            name="ACEScct",
            reference="Academy S-2016-001, ACEScct (2016)",
            kind="log",
            base=2.0,
            log_slope=1.0 / 17.52,
            log_offset=9.72 / 17.52,
            lin_slope=1.0,
            lin_offset=0.0,
            lin_break=0.0078125,
            toe_slope=10.5402377416545,
            toe_offset=0.0729055341958355,
            black=0.0729055341958355,
            colour_science=("log_encoding_ACEScct", "log_decoding_ACEScct"),
            ocio_builtin=("ACEScct_to_ACES2065-1", "ACEScg_to_ACES2065-1"),
        ),
        family="ACES",
        description="ACEScct: ACEScg with the ACEScct log encoding (S-2016-001)",
        plain=True,
    ),
    EncodedSpace(
        name="DaVinci Intermediate WideGamut",
        linear=_DWG_SPACE,
        curve=LogCurve(
            name="DaVinci Intermediate",
            reference="Blackmagic Design, DaVinci Resolve 17 Wide Gamut Intermediate (2020)",
            kind="log",
            base=2.0,
            log_slope=0.07329248,
            log_offset=7.0 * 0.07329248,
            lin_slope=1.0,
            lin_offset=0.0075,
            lin_break=0.00262409,
            toe_slope=10.44426855,
            toe_offset=0.0,
            black=0.0,
            colour_science=("oetf_DaVinciIntermediate", "oetf_inverse_DaVinciIntermediate"),
        ),
        family="DaVinci",
        description="DaVinci Wide Gamut with the DaVinci Intermediate log encoding "
        "(Blackmagic Design 2020): DaVinci Resolve's wide-gamut timeline; code 1.0 is "
        "linear 100",
    ),
    EncodedSpace(
        name="ARRI LogC4",
        linear=_AWG4_SPACE,
        curve=LogCurve(
            name="ARRI LogC4",
            reference="ARRI, LogC4 Logarithmic Color Space Specification (2022)",
            kind="log",
            base=2.0,
            log_slope=_LOGC4_B / 14.0,
            log_offset=_LOGC4_C - 6.0 * _LOGC4_B / 14.0,
            lin_slope=_LOGC4_A,
            lin_offset=64.0,
            lin_break=_LOGC4_T,
            toe_slope=1.0 / _LOGC4_S,
            black=95.0 / 1023.0,
            colour_science=("log_encoding_ARRILogC4", "log_decoding_ARRILogC4"),
        ),
        family="ARRI",
        description="ARRI Wide Gamut 4 with the LogC4 log encoding (ARRI 2022); code 1.0 "
        "is linear 469.8",
    ),
    EncodedSpace(
        name="S-Log3 S-Gamut3.Cine",
        linear=_SGAMUT3CINE_SPACE,
        curve=LogCurve(
            name="S-Log3",
            reference="Sony, Technical Summary for S-Gamut3.Cine/S-Log3 and S-Gamut3/S-Log3 (2016)",
            kind="log",
            base=10.0,
            log_slope=261.5 / 1023.0,
            log_offset=420.0 / 1023.0,
            lin_slope=1.0 / 0.19,
            lin_offset=0.01 / 0.19,
            lin_break=0.01125,
            toe_slope=(171.2102946929 - 95.0) / 0.01125 / 1023.0,
            toe_offset=95.0 / 1023.0,
            black=95.0 / 1023.0,
            colour_science=("log_encoding_SLog3", "log_decoding_SLog3"),
        ),
        family="Sony",
        description="Sony S-Gamut3.Cine with the S-Log3 log encoding (Sony 2016); code "
        "1.0 is linear 38.4",
    ),
    EncodedSpace(
        name="V-Log V-Gamut",
        linear=SceneSpace(
            name="Linear V-Gamut",
            gamut=_gamut("V-Gamut"),
            description="Scene-linear Panasonic V-Gamut primaries, D65",
        ),
        curve=LogCurve(
            name="Panasonic V-Log",
            reference="Panasonic, VARICAM V-Log/V-Gamut (2014)",
            kind="log",
            base=10.0,
            log_slope=0.241514,
            log_offset=0.598206,
            lin_slope=1.0,
            lin_offset=0.00873,
            lin_break=0.01,
            toe_slope=5.6,
            toe_offset=0.125,
            black=0.125,
            continuity=1e-6,  # the published toe meets the log part 3.1e-7 low
            colour_science=("log_encoding_VLog", "log_decoding_VLog"),
        ),
        family="Panasonic",
        description="Panasonic V-Gamut with the V-Log log encoding (Panasonic 2014); code "
        "1.0 is linear 46.1",
    ),
    EncodedSpace(
        name="Canon Log 3 Cinema Gamut",
        linear=SceneSpace(
            name="Linear Cinema Gamut",
            gamut=_gamut("Cinema Gamut"),
            description="Scene-linear Canon Cinema Gamut primaries, D65",
        ),
        curve=LogCurve(
            name="Canon Log 3",
            reference="Canon, Canon Log Gamma Curves, Canon Log 3 v1.2 (2020)",
            kind="mirrored-log",
            base=10.0,
            log_slope=0.36726845,
            log_offset=0.12240537,
            lin_slope=14.98325 / _CLOG3_REFLECTION,
            lin_offset=1.0,
            lin_break=_CLOG3_REFLECTION * (0.15277891 - 0.12512219) / 1.9754798,
            toe_slope=1.9754798 / _CLOG3_REFLECTION,
            toe_offset=0.12512219,
            black=0.12512219,
            colour_science=("log_encoding_CanonLog3", "log_decoding_CanonLog3"),
            continuity=1e-8,  # the published log parts meet the toe 2.6e-9 off
        ),
        family="Canon",
        description="Canon Cinema Gamut with the Canon Log 3 log encoding (Canon 2020, "
        "v1.2); code 1.0 is linear 14.7",
    ),
    EncodedSpace(
        name="Log3G10 REDWideGamutRGB",
        linear=SceneSpace(
            name="Linear REDWideGamutRGB",
            gamut=_gamut("REDWideGamutRGB"),
            description="Scene-linear RED Wide Gamut RGB primaries, D65",
        ),
        curve=LogCurve(
            name="RED Log3G10",
            reference="RED, White Paper on REDWideGamutRGB and Log3G10 (2017, v3)",
            kind="log",
            base=10.0,
            log_slope=0.224282,
            log_offset=0.0,
            lin_slope=155.975327,
            lin_offset=0.01 * 155.975327 + 1.0,
            lin_break=-0.01,
            toe_slope=15.1927,
            toe_offset=15.1927 * 0.01,
            black=0.224282 * math.log10(0.01 * 155.975327 + 1.0),
            colour_science=("log_encoding_Log3G10", "log_decoding_Log3G10"),
        ),
        family="RED",
        description="RED Wide Gamut RGB with the Log3G10 log encoding (RED 2017); code "
        "1.0 is linear 184.3",
    ),
    EncodedSpace(
        name="Apple Log Rec.2020",
        linear=_REC2020_SPACE,
        curve=LogCurve(
            name="Apple Log",
            reference="Apple, Apple Log Profile White Paper (2023)",
            kind="quadratic-toe",
            base=2.0,
            log_slope=0.08550479,
            log_offset=0.69336945,
            lin_slope=1.0,
            lin_offset=0.00964052,
            lin_break=0.01,
            toe_slope=47.28711236,
            toe_origin=-0.05641088,
            black=47.28711236 * 0.05641088**2,
            colour_science=("log_encoding_AppleLogProfile", "log_decoding_AppleLogProfile"),
            continuity=1e-8,  # the published log part meets the toe 2.7e-9 off
        ),
        family="Apple",
        description="Rec.2020 with the Apple Log encoding, as iPhones record it (Apple "
        "2023); code 1.0 is linear 12.0",
    ),
)

#: The scene-linear spaces: the working and display gamuts, then each encoded space's
#: linear space (in the order of :data:`ENCODED_LIST`, once each).
SCENE_LINEAR_LIST: tuple[SceneSpace, ...] = (
    SceneSpace(
        name="ACES2065-1",
        gamut=_AP0,
        description="ACES2065-1: AP0 primaries, ACES white (Bradford from D65)",
        blender=("ACES2065-1", "lin_ap0_scene"),
    ),
    _ACESCG_SPACE,
    SceneSpace(
        name="Linear Rec.709 (sRGB)",
        gamut=_REC709,
        description="Scene-linear Rec.709 / sRGB primaries, D65",
        materialx="lin_rec709",
        threejs="srgb-linear",
        blender=("Linear Rec.709", "lin_rec709_scene"),
    ),
    SceneSpace(
        name="Linear P3-D65",
        gamut=_P3,
        description="Scene-linear P3 primaries, D65",
        materialx="lin_displayp3",
        blender=("Linear DCI-P3 D65", "lin_p3d65_scene"),
    ),
    _REC2020_SPACE,
)
SCENE_LINEAR_LIST += tuple(
    dict.fromkeys(e.linear for e in ENCODED_LIST if e.linear not in SCENE_LINEAR_LIST)
)
SCENE_LINEAR_BY_NAME = {s.name: s for s in SCENE_LINEAR_LIST}

#: The log curves of the encoded spaces, in their order.
LOG_CURVE_LIST = tuple(e.curve for e in ENCODED_LIST)

#: The gamuts: those of the displays and those of the scene-linear spaces, once each.
GAMUT_LIST = tuple(
    dict.fromkeys([d.primaries for d in DISPLAY_LIST] + [s.gamut for s in SCENE_LINEAR_LIST])
)
#: Our names of RGB colorimetries (primaries and white) -> colour-science's
#: ``colour.RGB_COLOURSPACES`` names (derived from :data:`GAMUT_LIST`).
RGB_COLORIMETRY = {g.name: g.colour_science for g in GAMUT_LIST}
