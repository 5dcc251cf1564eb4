"""The registry's displays: SDR displays and HDR ones, and the display gamuts.

Adding a display is one :class:`Display` entry in :data:`DISPLAY_LIST` (then
``ocio-thinfilm bake``); its gamut (primaries and white) is a :class:`Gamut` object,
and displays with the same gamut share one set of clip tables (those of the first of
them). An HDR display is one :class:`HDRDisplay` entry in :data:`HDR_DISPLAY_LIST`,
which reuses the clip LUTs of the SDR display with its primaries. Part of
:mod:`ocio_thinfilm.registry` (import it from there).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ocio_thinfilm.registry.curves import Gamut

__all__ = [
    "Encoding",
    "SRGB_GAMUT",
    "P3_GAMUT",
    "REC2020_GAMUT",
    "DCI_P3_GAMUT",
    "Display",
    "HDRDisplay",
    "HDR_REFERENCE_WHITE",
    "OCIO_XYZ_UNIT",
    "CLIP_FILE_STEM",
    "COMPRESS_FILE_STEM",
    "DISPLAY_LIST",
    "HDR_DISPLAY_LIST",
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
        The OCIO display name.
    primaries : Gamut
        Its gamut: primaries and white (scene white D65 is shown at this white, by a
        Bradford adaptation where they differ). Displays with the same gamut share the
        clip tables of the first of them (:attr:`gamut`).
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
    png_cicp : tuple of 4 int, optional
        The PNG's cICP code points (ITU-T H.273: primaries, transfer, matrix, full
        range) where OpenImageIO writes no tag for ``png_colorspace`` (``None``: its
        tag). BT.1886 displays take transfer 1 (BT.709), as video signals do.
    """

    name: str
    primaries: Gamut
    colorspace: str
    description: str
    encoding: Encoding
    lut_stem: str
    png_colorspace: str
    png_cicp: tuple[int, int, int, int] | None = None

    #: An SDR display (its volume is its RGB parallelepiped up to white).
    hdr: ClassVar[bool] = False

    @property
    def colorimetry(self) -> str:
        """Its RGB space: the name of its gamut (a key of ``RGB_COLORIMETRY``)."""
        return self.primaries.name

    @property
    def gamut(self) -> Display:
        """The SDR display whose clip tables it uses.

        The first of :data:`DISPLAY_LIST` with its primaries and white: itself, unless an
        earlier display has them.
        """
        return next(d for d in DISPLAY_LIST if d.primaries == self.primaries)

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
        >>> DISPLAY_LIST[1].clip_lut_stem(white=True)
        'ConstantLightnessClip_DisplayP3_WhiteFaces'

        A display with another's gamut names that display's files:

        >>> DISPLAY_LIST[3].name, DISPLAY_LIST[3].clip_lut_stem()
        ('Rec.1886 Rec.709', 'ConstantLightnessClip_sRGB_BlackFaces')
        """
        stem = self.gamut.lut_stem
        return f"{CLIP_FILE_STEM}_{stem}" + ("_WhiteFaces" if white else "_BlackFaces")

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
        >>> DISPLAY_LIST[0].compress_lut_stem()
        'ConstantLightnessCompress_sRGB_BlackFaces'
        """
        stem = self.gamut.lut_stem
        return f"{COMPRESS_FILE_STEM}_{stem}" + ("_WhiteFaces" if white else "_BlackFaces")


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


#: File stem of the clip's LUT files (the config's passes and ``export clip``).
CLIP_FILE_STEM = "ConstantLightnessClip"
#: File stem of the compression's own LUT files (the config's squeezes).
COMPRESS_FILE_STEM = "ConstantLightnessCompress"


#: The display gamuts: primaries and white (colour-science's colourspaces).
SRGB_GAMUT = Gamut("sRGB", "sRGB")
P3_GAMUT = Gamut("Display P3", "Display P3")
REC2020_GAMUT = Gamut("Rec.2020", "ITU-R BT.2020")
#: SMPTE RP 431-2 (DCI) primaries and the DCI white (x, y = 0.314, 0.351).
DCI_P3_GAMUT = Gamut("DCI-P3", "DCI-P3")

_SRGB_PIECEWISE = Encoding("sRGB piecewise (IEC 61966-2-1)", gamma=2.4, offset=0.055)
_BT1886 = Encoding("BT.1886 gamma 2.4", gamma=2.4)

DISPLAY_LIST = (
    Display(
        name="sRGB",
        primaries=SRGB_GAMUT,
        colorspace="sRGB - Display",
        description="sRGB (IEC 61966-2-1) display: Rec.709 primaries, D65, sRGB piecewise encoding",
        encoding=_SRGB_PIECEWISE,
        lut_stem="sRGB",
        png_colorspace="srgb_rec709_display",
    ),
    Display(
        name="Display P3",
        primaries=P3_GAMUT,
        colorspace="Display P3 - Display",
        description="Apple Display P3: P3 primaries, D65, sRGB piecewise encoding",
        encoding=_SRGB_PIECEWISE,
        lut_stem="DisplayP3",
        png_colorspace="srgb_p3d65_display",
    ),
    Display(
        name="Rec.2020",
        primaries=REC2020_GAMUT,
        colorspace="Rec.1886 Rec.2020 - Display",
        description="ITU-R BT.2020 primaries, D65, BT.1886 gamma 2.4 encoding",
        encoding=_BT1886,
        lut_stem="Rec2020",
        png_colorspace="g24_rec2020_display",
        png_cicp=(9, 1, 0, 1),
    ),
    Display(
        name="Rec.1886 Rec.709",
        primaries=SRGB_GAMUT,
        colorspace="Rec.1886 Rec.709 - Display",
        description="ITU-R BT.1886 broadcast reference monitor: Rec.709 primaries, D65, "
        "BT.1886 gamma 2.4 encoding (black level 0)",
        encoding=_BT1886,
        lut_stem="Rec1886Rec709",
        png_colorspace="g24_rec709_display",
    ),
    Display(
        name="P3-DCI",
        primaries=DCI_P3_GAMUT,
        colorspace="P3-DCI - Display",
        description="DCI cinema projector (SMPTE RP 431-2): P3 primaries, DCI white "
        "(scene D65 white shown at the DCI white, Bradford adaptation), gamma 2.6 encoding",
        encoding=Encoding("gamma 2.6 (SMPTE RP 431-2)", gamma=2.6),
        lut_stem="P3DCI",
        png_colorspace="g26_p3dci_display",
        png_cicp=(11, 17, 0, 1),
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
