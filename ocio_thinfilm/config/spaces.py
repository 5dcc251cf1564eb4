"""The config's colour spaces that need no LUT file, as plain data.

The reference, the scene-linear spaces, the encoded (log) spaces, the sRGB texture space,
``Raw`` and the display colour spaces, each a dict for
:func:`ocio_thinfilm.config.factories.colorspace_factory`, from the registry.

An encoded space decodes with its curve (:data:`CURVE_DECODINGS`, one entry per curve of
:data:`ocio_thinfilm.registry.LOG_CURVES`) to its linear space, then that space's matrix
to CIE-XYZ-D65. Every transform is one that OCIO 2.1 reads (the config's profile
version): ACEScct is OCIO's built-in ``ACEScct_to_ACES2065-1`` (with the AP1 -> AP0
matrix undone), the camera and grading logs a ``LogCameraTransform`` with the curve's
numbers (:data:`ocio_thinfilm.colour.log_curves.LOG_CURVES`): OCIO 2.1 has no built-in
for DaVinci Intermediate or LogC4.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.colour.log_curves import LOG_CURVES
from ocio_thinfilm.lut import display_transforms, ocio_ops

__all__ = [
    "CURVE_DECODINGS",
    "matrix_to_reference",
    "encoded_to_reference",
    "scene_colorspaces",
    "display_colorspaces",
]


def matrix_to_reference(colorimetry_name: str) -> ocio_ops.Transform:
    """Return linear RGB of ``colorimetry_name`` -> CIE-XYZ-D65, the components limited first.

    The limit is +-:data:`ocio_thinfilm.lut.ocio_ops.LIMIT`: float32-max or infinite
    values (e.g. ACEScct codes above ~7.9) would overflow the matrix to Inf - Inf = NaN,
    which no later op can repair at OPTIMIZATION_NONE (ops not composed); no real pixel
    comes near 1e6.

    Parameters
    ----------
    colorimetry_name : str
        A key of :data:`ocio_thinfilm.registry.RGB_COLORIMETRY`.

    Returns
    -------
    PyOpenColorIO.GroupTransform
    """
    M = colorimetry.matrix_XYZ_to_RGB(colorimetry_name)
    return ocio_ops.group(
        [ocio_ops.finite_limit_transform(), ocio_ops.matrix(reproducible.inv3(M))]
    )


def _acescct_decoding() -> list[ocio_ops.Transform]:
    """ACEScct codes -> ACEScg: OCIO's built-in to ACES2065-1, then AP0 -> AP1 undone.

    The two matrices cancel when OCIO optimises, so the path is per channel, as OCIO's
    Baker requires of a shaper.
    """
    import PyOpenColorIO as ocio

    to_linear = ocio.BuiltinTransform("ACEScg_to_ACES2065-1")
    to_linear.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return [ocio.BuiltinTransform("ACEScct_to_ACES2065-1"), to_linear]


def _log_camera_decoding(curve: str) -> Callable[[], list[ocio_ops.Transform]]:
    """Return a factory of the inverse ``LogCameraTransform`` of ``curve`` (OCIO >= 2.0)."""

    def decoding() -> list[ocio_ops.Transform]:
        import PyOpenColorIO as ocio

        c = LOG_CURVES[curve]
        t = ocio.LogCameraTransform(
            base=c.base,
            logSideSlope=[c.log_slope] * 3,
            logSideOffset=[c.log_offset] * 3,
            linSideSlope=[c.lin_slope] * 3,
            linSideOffset=[c.lin_offset] * 3,
            linSideBreak=[c.lin_break] * 3,
            direction=ocio.TRANSFORM_DIR_INVERSE,
        )
        t.setLinearSlopeValue([c.linear_slope] * 3)
        return [t]

    return decoding


#: Log curve (:data:`ocio_thinfilm.registry.LOG_CURVES`) -> a factory of its OCIO 2.1
#: transforms, code values -> scene-linear values of the same gamut, per channel.
CURVE_DECODINGS: dict[str, Callable[[], list[ocio_ops.Transform]]] = {
    "ACEScct": _acescct_decoding,
    "DaVinci Intermediate": _log_camera_decoding("DaVinci Intermediate"),
    "ARRI LogC4": _log_camera_decoding("ARRI LogC4"),
    "S-Log3": _log_camera_decoding("S-Log3"),
}


def encoded_to_reference(encoded: registry.EncodedSpace) -> ocio_ops.Transform:
    """Return an encoded space -> CIE-XYZ-D65: its curve's decoding, then its gamut's matrix.

    The code values are limited first to those of linear +-:data:`ocio_ops.LIMIT` (the
    curve's encoding of them, :data:`ocio_thinfilm.colour.log_curves.LOG_CURVES`, in
    float64, printed to 7 significant digits), so the curve's exponential never
    overflows to Inf (and Inf - Inf to NaN in a matrix) at any optimisation level.

    Parameters
    ----------
    encoded : EncodedSpace
        An entry of :data:`ocio_thinfilm.registry.ENCODED_LIST`.

    Returns
    -------
    PyOpenColorIO.GroupTransform
    """
    curve = LOG_CURVES[encoded.curve]
    lo, hi = (float(f"{curve.encode_one(v):.7g}") for v in (-ocio_ops.LIMIT, ocio_ops.LIMIT))
    return ocio_ops.group(
        [ocio_ops.range_(lo, hi)]
        + CURVE_DECODINGS[encoded.curve]()
        + [matrix_to_reference(encoded.gamut.colorimetry)]
    )


def scene_colorspaces() -> list[dict[str, Any]]:
    """Return the reference, scene-linear, encoded, texture and ``Raw`` colour spaces.

    Returns
    -------
    list of dict
        Keyword arguments of :func:`ocio_thinfilm.config.factories.colorspace_factory`.
    """
    cs: list[dict[str, Any]] = [
        dict(
            name=registry.REFERENCE,
            family="Utility",
            encoding="scene-linear",
            categories=["file-io", "working-space"],
            aliases=["cie_xyz_d65"],
            description="CIE XYZ, D65-relative: the perfect reflector under D65 has "
            "Y = 1 (CIE 1931 2 degree observer). The reference space.",
        )
    ]
    cs += [
        dict(
            name=linear.name,
            family="Scene-Linear",
            encoding="scene-linear",
            categories=["file-io", "working-space"],
            description=linear.description,
            to_reference=matrix_to_reference(linear.colorimetry),
        )
        for linear in registry.SCENE_LINEAR_LIST
    ]
    cs += [
        dict(
            name=encoded.name,
            family=encoded.family,
            encoding="log",
            categories=["file-io", "working-space"],
            description=encoded.description,
            to_reference=encoded_to_reference(encoded),
        )
        for encoded in registry.ENCODED_LIST
    ]
    cs.append(
        dict(
            name=registry.TEXTURE_SPACE,
            family="Texture",
            encoding="sdr-video",
            categories=["file-io", "texture"],
            aliases=["srgb_tx"],
            description="sRGB-encoded Rec.709 primaries, D65 (8-bit textures, colour picking)",
            to_reference=ocio_ops.group(
                [
                    ocio_ops.inverse([display_transforms.display_encoding_transform("sRGB")]),
                    matrix_to_reference("Rec.709"),
                ]
            ),
        )
    )
    cs.append(
        dict(
            name=registry.RAW_SPACE,
            family="Utility",
            encoding="data",
            is_data=True,
            categories=["file-io"],
            aliases=["Utility - Raw"],
            description="Non-colour data: passed through unchanged",
        )
    )
    return cs


def display_colorspaces() -> list[dict[str, Any]]:
    """Return the display colour spaces, one per display of the registry.

    Returns
    -------
    list of dict
        Keyword arguments of :func:`ocio_thinfilm.config.factories.colorspace_factory`.
    """
    return [
        dict(
            name=entry.colorspace,
            family="Display",
            encoding="hdr-video" if entry.hdr else "sdr-video",
            categories=["file-io"],
            reference_space="display",
            description=entry.description,
            from_reference=display_transforms.display_colorspace_transform(entry),
        )
        for entry in registry.ALL_DISPLAY_LIST
    ]
