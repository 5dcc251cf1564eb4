"""The config's named transforms (OCIO >= 2.0) as plain data.

The clip and the compression of each display on their own (display-linear RGB in and
out, for hosts that apply a named transform as a node) and each thin-film table on its
own (pixel value in, CIE-XYZ-D65 out).
"""

from __future__ import annotations

from ocio_thinfilm import registry
from ocio_thinfilm.colour import compress as compress_map
from ocio_thinfilm.config.luts import clip_passes, compress_passes, lut_reference, named_lut
from ocio_thinfilm.lut import clip_lut, compress_lut, display_transforms, ocio_ops

__all__ = [
    "CLIP_NAMED_TRANSFORM",
    "COMPRESS_NAMED_TRANSFORM",
    "TABLE_NAMED_TRANSFORM",
    "clip_named_transform",
    "compress_named_transform",
    "named_transforms",
]


#: Named transform of the clip alone, per display (display-linear RGB in and out).
CLIP_NAMED_TRANSFORM = registry.CLIP_VIEW + " - {display} (display-linear)"
#: Named transform of the compression alone, per display.
COMPRESS_NAMED_TRANSFORM = registry.COMPRESS_VIEW + " - {display} (display-linear)"
#: Named transform of a thin-film table (pixel value in, CIE XYZ out).
TABLE_NAMED_TRANSFORM = "{space} to CIE-XYZ-D65"


def clip_named_transform(
    lut: clip_lut.ClipLUT,
    *,
    inline: bool = False,
    luts: dict[str, ocio_ops.Transform] | None = None,
) -> ocio_ops.Transform:
    """Return the constant-lightness clip of ``lut``'s display on its own.

    Display-linear RGB in, display-linear RGB in [0, 1] out (XYZ -> the two LUT passes
    -> decoded), for hosts that apply a named transform as a node (Nuke
    OCIONamedTransform, Houdini).

    Parameters
    ----------
    lut : ClipLUT
        The display's clip LUT.
    inline : bool, optional
        Put the LUTs into the transform (``True``) or refer to the LUT files by
        FileTransform (``False``, the default).
    luts : dict, optional
        The LUT files (:func:`lut_files`); required with ``inline=True``.

    Returns
    -------
    PyOpenColorIO.GroupTransform
        The named transform's transform.
    """
    return ocio_ops.group(
        [display_transforms.display_matrix_transform(lut.display, inverse=True)]
        + clip_passes(lut, luts, inline)
        + [clip_lut.working_decoding_transform()]
    )


def compress_named_transform(
    soft: compress_lut.CompressLUT,
    *,
    inline: bool = False,
    luts: dict[str, ocio_ops.Transform] | None = None,
) -> ocio_ops.Transform:
    """Return the soft constant-lightness compression of ``soft``'s display on its own.

    Display-linear RGB in and out (as :func:`clip_named_transform`).

    Parameters
    ----------
    soft : CompressLUT
        The display's compression LUT.
    inline : bool, optional
        Put the LUTs into the transform (``True``) or refer to the LUT files by
        FileTransform (``False``, the default).
    luts : dict, optional
        The LUT files (:func:`lut_files`); required with ``inline=True``.

    Returns
    -------
    PyOpenColorIO.GroupTransform
        The named transform's transform.
    """
    return ocio_ops.group(
        [display_transforms.display_matrix_transform(soft.display, inverse=True)]
        + compress_passes(soft, luts, inline)
        + [clip_lut.working_decoding_transform()]
    )


def named_transforms(
    luts_by_display: dict,
    *,
    inline: bool = False,
    luts: dict[str, ocio_ops.Transform] | None = None,
    compress_by_display: dict | None = None,
) -> list:
    """Return the named transforms (OCIO >= 2.0) as data.

    The clip and the compression per display, and the three thin-film tables (pixel
    value in, CIE-XYZ-D65 out, whatever the config's reference space: merged configs
    add the same ones).

    Parameters
    ----------
    luts_by_display : dict
        Display name -> ClipLUT: one clip named transform each
        (:data:`CLIP_NAMED_TRANSFORM`).
    inline : bool, optional
        Put the LUTs into the transforms (``True``) or refer to the LUT files by
        FileTransform (``False``, the default).
    luts : dict, optional
        The LUT files (:func:`lut_files`); required with ``inline=True``.
    compress_by_display : dict, optional
        Display name -> CompressLUT: one compression named transform each
        (:data:`COMPRESS_NAMED_TRANSFORM`); ``None`` (default) for none.

    Returns
    -------
    list of dict
        Keyword arguments of
        :func:`~ocio_thinfilm.config.factories.named_transform_factory`.
    """

    def gamut_map(name, display, what, transform):
        return dict(
            name=name.format(display=display),
            family="Thin Film",
            categories=["gamut-mapping"],
            encoding="display-linear",
            description=(
                f"{what}: {display} display-linear RGB in (any values), "
                "display-linear RGB in [0, 1] out, luminance kept. Apply it "
                "as a node, then encode for the display."
            ),
            transform=transform,
        )

    out = [
        gamut_map(
            CLIP_NAMED_TRANSFORM,
            display,
            f"Smits & Meyer 1990 constant-lightness clip into {display} on its own",
            clip_named_transform(lut, inline=inline, luts=luts),
        )
        for display, lut in luts_by_display.items()
    ]
    for display, squeeze in (compress_by_display or {}).items():
        t, lim = (compress_map.knob_text(v) for v in squeeze.parameters[:2])
        out.append(
            gamut_map(
                COMPRESS_NAMED_TRANSFORM,
                display,
                f"Soft constant-lightness compression into {display} on its own "
                f"(threshold {t}, limit {lim})",
                compress_named_transform(squeeze, inline=inline, luts=luts),
            )
        )
    for space in registry.THIN_FILM_LIST:
        table = named_lut(space.lut_stem)
        out.append(
            dict(
                name=TABLE_NAMED_TRANSFORM.format(space=space.name),
                family="Thin Film",
                categories=["thin-film"],
                encoding="scene-linear",
                description=(
                    f"The {space.name} table on its own: pixel value in (all channels "
                    "equal, as for the colour space of that name), unclipped CIE XYZ "
                    "(D65, perfect reflector Y = 1) out."
                ),
                transform=lut_reference(table, luts, inline),
            )
        )
    return out
