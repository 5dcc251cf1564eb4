"""The evaluation's independent truths, declared once: the other libraries' names.

Each registry entry the tests hold to another library is named here, typed apart from
the package's own fields (``Gamut.colour_science``, ``LogCurve.colour_science``,
``HDRDisplay.builtin``): a reference that read those names from the registry would agree
with a wrong entry of it. ``tests/test_truth.py`` checks that each mapping covers exactly
the registry's entries (a new gamut, log curve or display without its truth fails there,
naming the missing key) and that colour-science's colourspaces have the primaries and
white of the package's colorimetry.

- :data:`COLOUR_SCIENCE_GAMUTS` -- our gamut name -> ``colour.RGB_COLOURSPACES`` key.
- :data:`COLOUR_SCIENCE_LOGS` -- our log curve name -> colour-science's encoding and
  decoding functions (``colour.models``) with the arguments that select the published
  curve (stated even where they are colour-science's defaults, so a change of default
  cannot move the truth).
- :data:`OCIO_DISPLAY_BUILTINS` -- our display name -> OCIO's built-in display transform
  (``BuiltinTransform``, CIE-XYZ-D65 -> code values) of the same encoding and gamut.
- :data:`HDR_CICP` -- our HDR display name -> its ITU-T H.273 code points (the PNG's
  cICP chunk).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np
import numpy.typing as npt

__all__ = [
    "COLOUR_SCIENCE_GAMUTS",
    "COLOUR_SCIENCE_LOGS",
    "OCIO_DISPLAY_BUILTINS",
    "HDR_CICP",
    "LogTruth",
    "colour_science_gamut",
    "colour_science_RGB_to_XYZ",
    "log_encoding",
    "log_decoding",
    "missing",
]

#: The D65 white's chromaticity (CIE 1931 2 degree), the scene white of the package.
D65 = (0.3127, 0.3290)

#: Our gamut name (``registry.GAMUT_LIST``) -> colour-science's colourspace of it.
COLOUR_SCIENCE_GAMUTS: Mapping[str, str] = MappingProxyType(
    {
        "sRGB": "sRGB",
        "Display P3": "Display P3",
        "Rec.2020": "ITU-R BT.2020",
        "DCI-P3": "DCI-P3",  # SMPTE RP 431-2 primaries, DCI white (0.314, 0.351)
        "Rec.709": "ITU-R BT.709",
        "ACEScg": "ACEScg",
        "ACES2065-1": "ACES2065-1",
        "DaVinci Wide Gamut": "DaVinci Wide Gamut",
        "ARRI Wide Gamut 4": "ARRI Wide Gamut 4",
        "S-Gamut3.Cine": "S-Gamut3.Cine",
        "V-Gamut": "V-Gamut",
        "Cinema Gamut": "Cinema Gamut",
        "REDWideGamutRGB": "REDWideGamutRGB",
    }
)


@dataclass(frozen=True)
class LogTruth:
    """colour-science's functions of one log curve, with the arguments that select it.

    Parameters
    ----------
    encoding, decoding : str
        Names in ``colour.models``.
    encoding_kwargs, decoding_kwargs : mapping, optional
        Keyword arguments of each (default none).
    """

    encoding: str
    decoding: str
    encoding_kwargs: Mapping[str, object] = field(default_factory=dict)
    decoding_kwargs: Mapping[str, object] = field(default_factory=dict)

    def encode(self, linear: npt.ArrayLike) -> np.ndarray:
        """Scene-linear values -> code values, by colour-science."""
        import colour

        fn = getattr(colour.models, self.encoding)
        with np.errstate(divide="ignore", invalid="ignore"):  # log of the toe's negatives
            return np.asarray(fn(linear, **self.encoding_kwargs))

    def decode(self, codes: npt.ArrayLike) -> np.ndarray:
        """Code values -> scene-linear values, by colour-science."""
        import colour

        fn = getattr(colour.models, self.decoding)
        with np.errstate(over="ignore", invalid="ignore"):
            return np.asarray(fn(codes, **self.decoding_kwargs))


#: S-Log3, V-Log and Canon Log 3 take scene reflection (colour-science's
#: ``in_reflection``: linear / 0.9) and 10-bit normalised code values.
_REFLECTION_10BIT_IN = {"bit_depth": 10, "out_normalised_code_value": True, "in_reflection": True}
_REFLECTION_10BIT_OUT = {"bit_depth": 10, "in_normalised_code_value": True, "out_reflection": True}

#: Our log curve name (``registry.LOG_CURVES``) -> colour-science's functions of it.
COLOUR_SCIENCE_LOGS: Mapping[str, LogTruth] = MappingProxyType(
    {
        "ACEScct": LogTruth("log_encoding_ACEScct", "log_decoding_ACEScct"),
        "DaVinci Intermediate": LogTruth(
            "oetf_DaVinciIntermediate", "oetf_inverse_DaVinciIntermediate"
        ),
        "ARRI LogC4": LogTruth("log_encoding_ARRILogC4", "log_decoding_ARRILogC4"),
        "S-Log3": LogTruth(
            "log_encoding_SLog3", "log_decoding_SLog3", _REFLECTION_10BIT_IN, _REFLECTION_10BIT_OUT
        ),
        "Panasonic V-Log": LogTruth(
            "log_encoding_VLog", "log_decoding_VLog", _REFLECTION_10BIT_IN, _REFLECTION_10BIT_OUT
        ),
        "Canon Log 3": LogTruth(
            "log_encoding_CanonLog3",
            "log_decoding_CanonLog3",
            {**_REFLECTION_10BIT_IN, "method": "v1.2"},
            {**_REFLECTION_10BIT_OUT, "method": "v1.2"},
        ),
        "RED Log3G10": LogTruth(
            "log_encoding_Log3G10", "log_decoding_Log3G10", {"method": "v3"}, {"method": "v3"}
        ),
        "Apple Log": LogTruth("log_encoding_AppleLogProfile", "log_decoding_AppleLogProfile"),
    }
)

#: Our display name (``registry.ALL_DISPLAYS``) -> OCIO's built-in transform from
#: CIE-XYZ-D65 to its code values (the same primaries, white handling and encoding; the
#: HDR ones take Y = 1 at ``registry.OCIO_XYZ_UNIT`` cd/m2).
OCIO_DISPLAY_BUILTINS: Mapping[str, str] = MappingProxyType(
    {
        "sRGB": "DISPLAY - CIE-XYZ-D65_to_sRGB",
        "Display P3": "DISPLAY - CIE-XYZ-D65_to_DisplayP3",
        "Rec.2020": "DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.2020",
        "Rec.1886 Rec.709": "DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.709",
        "P3-DCI": "DISPLAY - CIE-XYZ-D65_to_G2.6-P3-DCI-BFD",
        "Rec.2100-PQ": "DISPLAY - CIE-XYZ-D65_to_REC.2100-PQ",
        "Rec.2100-HLG": "DISPLAY - CIE-XYZ-D65_to_REC.2100-HLG-1000nit",
        "P3-D65 PQ": "DISPLAY - CIE-XYZ-D65_to_ST2084-P3-D65",
    }
)


#: Our HDR display name (``registry.HDR_DISPLAYS``) -> ITU-T H.273 code points (colour
#: primaries: BT.2020 = 9, P3-D65 = 12; transfer: PQ = 16, HLG = 18; RGB matrix 0; full
#: range 1), what its PNG's cICP chunk must hold.
HDR_CICP: Mapping[str, tuple[int, int, int, int]] = MappingProxyType(
    {
        "Rec.2100-PQ": (9, 16, 0, 1),
        "Rec.2100-HLG": (9, 18, 0, 1),
        "P3-D65 PQ": (12, 16, 0, 1),
    }
)


def colour_science_gamut(name: str):
    """Return colour-science's ``RGB_Colourspace`` of our gamut ``name`` (a display's
    name stands for its gamut, as in the package's colorimetry)."""
    import colour

    from ocio_thinfilm import registry

    display = registry.find_display(name)
    gamut = display.colorimetry if display is not None else name
    return colour.RGB_COLOURSPACES[COLOUR_SCIENCE_GAMUTS[gamut]]


def colour_science_RGB_to_XYZ(name: str) -> np.ndarray:
    """Return the linear RGB -> CIE-XYZ-D65 matrix of our gamut (or display) ``name``,
    built here by colour-science from its colourspace's primaries and white: the
    normalised primary matrix, Bradford-adapted to D65 where the white is another (DCI,
    ACES), as the package's colorimetry says it does."""
    import colour

    space = colour_science_gamut(name)
    npm = colour.normalised_primary_matrix(space.primaries, space.whitepoint)
    if np.allclose(space.whitepoint, D65, atol=1e-4):
        return npm
    cat = colour.adaptation.matrix_chromatic_adaptation_VonKries(
        colour.xy_to_XYZ(space.whitepoint), colour.xy_to_XYZ(D65), transform="Bradford"
    )
    return cat @ npm


def log_encoding(linear: npt.ArrayLike, curve) -> np.ndarray:
    """Scene-linear values -> codes of the log ``curve`` (a ``LogCurve`` or its name),
    by colour-science's function of it (:data:`COLOUR_SCIENCE_LOGS`)."""
    return COLOUR_SCIENCE_LOGS[getattr(curve, "name", curve)].encode(linear)


def log_decoding(codes: npt.ArrayLike, curve) -> np.ndarray:
    """Codes of the log ``curve`` (a ``LogCurve`` or its name) -> scene-linear values, by
    colour-science's function of it (:data:`COLOUR_SCIENCE_LOGS`)."""
    return COLOUR_SCIENCE_LOGS[getattr(curve, "name", curve)].decode(codes)


def missing(mapping: Mapping[str, object], names) -> tuple[list[str], list[str]]:
    """Return (the names without an entry, the entries without a name) of ``mapping``."""
    names = list(names)
    return [n for n in names if n not in mapping], [k for k in mapping if k not in names]
