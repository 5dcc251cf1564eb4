"""The config's colour spaces that need no LUT file, as plain data.

The reference, the scene-linear spaces, the encoded (log) spaces, the sRGB texture space,
``Raw`` and the display colour spaces, each a dict for
:func:`ocio_thinfilm.config.factories.colorspace_factory`, from the registry.

An encoded space decodes with its curve (:data:`CURVE_DECODINGS`, one entry per kind of
:data:`ocio_thinfilm.registry.CURVE_KINDS`, built from the curve's numbers) to its linear
space, then that space's matrix to CIE-XYZ-D65. Every transform is one that OCIO 2.1
reads (the config's profile version): OCIO's built-in where the curve names one (ACEScct,
its AP1 -> AP0 matrix undone), else ``LogCameraTransform`` and matrices only.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.colour import colorimetry
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


def _builtin_decoding(curve: registry.LogCurve) -> list[ocio_ops.Transform]:
    """Codes -> linear: the curve's OCIO built-in to ACES2065-1, its gamut's undone.

    The two matrices cancel when OCIO optimises, so the path is per channel, as OCIO's
    Baker requires of a shaper (ACEScct: ``ACEScct_to_ACES2065-1``, then the inverse of
    ``ACEScg_to_ACES2065-1``).
    """
    import PyOpenColorIO as ocio

    assert curve.ocio_builtin is not None
    decoding, gamut = curve.ocio_builtin
    to_linear = ocio.BuiltinTransform(gamut)
    to_linear.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    return [ocio.BuiltinTransform(decoding), to_linear]


def _log_camera(
    base: float,
    log_slope: float,
    log_offset: float,
    lin_slope: float,
    lin_offset: float,
    lin_break: float,
    linear_slope: float,
    *,
    inverse: bool = True,
) -> ocio_ops.Transform:
    """Return a ``LogCameraTransform`` (OCIO >= 2.0; its toe's offset from continuity)."""
    import PyOpenColorIO as ocio

    t = ocio.LogCameraTransform(
        base=base,
        logSideSlope=[log_slope] * 3,
        logSideOffset=[log_offset] * 3,
        linSideSlope=[lin_slope] * 3,
        linSideOffset=[lin_offset] * 3,
        linSideBreak=[lin_break] * 3,
        direction=ocio.TRANSFORM_DIR_INVERSE if inverse else ocio.TRANSFORM_DIR_FORWARD,
    )
    t.setLinearSlopeValue([linear_slope] * 3)
    return t


def _gap(curve: registry.LogCurve) -> float:
    """Return the curve's gap at its break, rounded to 12 decimals.

    libm's last bits do not reach the file; a continuous curve's round-off gives 0.
    """
    return float(ocio_ops.quantize(curve.gap, 12))


def _log_part(curve: registry.LogCurve, toe_slope: float) -> ocio_ops.Transform:
    """Return codes -> linear by the curve's log part, below its break a line.

    The line passes through the toe's code at the break (OCIO derives its offset from
    continuity): the gap of a published toe (V-Log's 3.1e-7, at most
    ``curve.continuity``) moves into the log side's offset, so the toe, and black,
    decode exactly.
    """
    c = curve
    offset = c.log_offset - _gap(c)
    return _log_camera(
        c.base, c.log_slope, offset, c.lin_slope, c.lin_offset, c.lin_break, toe_slope
    )


def _log_decoding(curve: registry.LogCurve) -> list[ocio_ops.Transform]:
    """Return a ``"log"`` curve's decoding: an inverse ``LogCameraTransform`` or a built-in."""
    if curve.ocio_builtin is not None:
        return _builtin_decoding(curve)
    return [_log_part(curve, curve.toe_slope)]


def _mirrored_decoding(curve: registry.LogCurve) -> list[ocio_ops.Transform]:
    """Return a ``"mirrored-log"`` curve's decoding (Canon Log 3's three segments).

    The log part and toe, then below ``-lin_break`` the mirrored log part, as an
    identity-toed ``LogCameraTransform`` on the negated values (``P(u) = u`` for ``u <=
    lin_break``, else ``U^-1(black + s u)``).
    """
    c = curve
    s = c.toe_slope
    negate = ocio_ops.matrix(-np.eye(3))
    offset = (c.log_offset - _gap(c) - c.black) / s
    mirror = _log_camera(
        c.base, c.log_slope / s, offset, c.lin_slope, c.lin_offset, c.lin_break, 1.0
    )
    return [_log_part(c, s), negate, mirror, negate]


def _quadratic_decoding(curve: registry.LogCurve) -> list[ocio_ops.Transform]:
    """Return a ``"quadratic-toe"`` curve's decoding (Apple Log) in OCIO 2.1 ops.

    The log part with a line below its break (slope ``s``, the quadratic's there,
    through its code ``P_t``), then for ``u = R_t - w > 0`` the square root ``R_t - q_t
    (1 - sqrt(1 - s u / P_t))`` as two identity-toed ``LogCameraTransform`` (a natural
    log, then its exponential halved), ``q_t = R_t - toe_origin``: exactly
    ``toe_origin + sqrt(code / toe_slope)``.
    """
    c = curve
    q_t = c.lin_break - c.toe_origin
    s = 2.0 * c.toe_slope * q_t
    flip = ocio_ops.matrix(-np.eye(3), [c.lin_break] * 3)
    log = _log_camera(math.e, -1.0, 0.0, -s / c.toe_break, 1.0, 0.0, 1.0, inverse=False)
    root = _log_camera(math.e, -2.0, 0.0, -1.0 / q_t, 1.0, 0.0, 1.0)
    return [_log_part(c, s), flip, log, root, flip]


#: Curve kind (:data:`ocio_thinfilm.registry.CURVE_KINDS`) -> its OCIO 2.1 transforms,
#: code values -> scene-linear values of the same gamut, per channel.
CURVE_DECODINGS: dict[str, Callable[[registry.LogCurve], list[ocio_ops.Transform]]] = {
    "log": _log_decoding,
    "mirrored-log": _mirrored_decoding,
    "quadratic-toe": _quadratic_decoding,
}


def encoded_to_reference(encoded: registry.EncodedSpace) -> ocio_ops.Transform:
    """Return an encoded space -> CIE-XYZ-D65: its curve's decoding, then its gamut's matrix.

    The code values are limited first to those of linear +-:data:`ocio_ops.LIMIT` (the
    curve's encoding of them, ``LogCurve.encode_one``, in float64, printed to 7
    significant digits), so the curve's exponential never overflows to Inf (and Inf -
    Inf to NaN in a matrix) at any optimisation level.

    Parameters
    ----------
    encoded : EncodedSpace
        An entry of :data:`ocio_thinfilm.registry.ENCODED_LIST`.

    Returns
    -------
    PyOpenColorIO.GroupTransform
    """
    curve = encoded.curve
    lo, hi = (float(f"{curve.encode_one(v):.7g}") for v in (-ocio_ops.LIMIT, ocio_ops.LIMIT))
    return ocio_ops.group(
        [ocio_ops.range_(lo, hi)]
        + CURVE_DECODINGS[curve.kind](curve)
        + [matrix_to_reference(encoded.gamut.name)]
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
