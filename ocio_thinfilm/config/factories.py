"""Small factories: one OCIO object from one dict of :func:`ocio_thinfilm.config.data.config_data`
(as OpenColorIO-Config-ACES builds its configs)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ocio_thinfilm.lut.ocio_ops import Transform

__all__ = [
    "colorspace_factory",
    "view_transform_factory",
    "named_transform_factory",
    "file_transform",
]


def file_transform(filename: str) -> Transform:
    """A ``FileTransform`` to ``filename`` (found on the config's search path)."""
    import PyOpenColorIO as ocio

    t = ocio.FileTransform(filename)
    t.setInterpolation(ocio.INTERP_DEFAULT)
    return t


def _reference_space(name):
    """``"scene"`` or ``"display"`` -> OCIO's ReferenceSpaceType."""
    import PyOpenColorIO as ocio

    if name not in ("scene", "display"):
        raise ValueError(f"reference_space must be 'scene' or 'display', got {name!r}")
    return ocio.REFERENCE_SPACE_DISPLAY if name == "display" else ocio.REFERENCE_SPACE_SCENE


def colorspace_factory(
    name: str,
    family: str = "",
    encoding: str = "",
    categories: Iterable[str] = (),
    description: str = "",
    to_reference: Transform | None = None,
    from_reference: Transform | None = None,
    is_data: bool = False,
    aliases: Iterable[str] = (),
    reference_space: str = "scene",
) -> Any:
    """One ``PyOpenColorIO.ColorSpace`` from data (cf. OpenColorIO-Config-ACES)."""
    import PyOpenColorIO as ocio

    cs = ocio.ColorSpace(_reference_space(reference_space))
    cs.setName(name)
    cs.setFamily(family)
    cs.setEncoding(encoding)
    cs.setDescription(description)
    cs.setIsData(bool(is_data))
    cs.setBitDepth(ocio.BIT_DEPTH_F32)
    for category in categories:
        cs.addCategory(category)
    for alias in aliases:
        cs.addAlias(alias)
    if to_reference is not None:
        cs.setTransform(to_reference, ocio.COLORSPACE_DIR_TO_REFERENCE)
    if from_reference is not None:
        cs.setTransform(from_reference, ocio.COLORSPACE_DIR_FROM_REFERENCE)
    return cs


def view_transform_factory(
    name: str,
    family: str = "",
    description: str = "",
    from_reference: Transform | None = None,
    reference_space: str = "scene",
) -> Any:
    """One ``PyOpenColorIO.ViewTransform`` from data."""
    import PyOpenColorIO as ocio

    vt = ocio.ViewTransform(_reference_space(reference_space))
    vt.setName(name)
    vt.setFamily(family)
    vt.setDescription(description)
    if from_reference is not None:
        vt.setTransform(from_reference, ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
    return vt


def named_transform_factory(
    name: str,
    transform: Transform,
    family: str = "",
    description: str = "",
    categories: Iterable[str] = (),
    encoding: str = "",
) -> Any:
    """One ``PyOpenColorIO.NamedTransform`` (forward direction) from data."""
    import PyOpenColorIO as ocio

    nt = ocio.NamedTransform()
    nt.setName(name)
    nt.setFamily(family)
    nt.setDescription(description)
    nt.setEncoding(encoding)
    for category in categories:
        nt.addCategory(category)
    nt.setTransform(transform, ocio.TRANSFORM_DIR_FORWARD)
    return nt
