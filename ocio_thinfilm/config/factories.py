"""Small factories: one OCIO object from one dict of the config's data.

The dicts are those of :func:`ocio_thinfilm.config.data.config_data` (as
OpenColorIO-Config-ACES builds its configs).
"""

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
    """Return a ``FileTransform`` to ``filename`` (found on the config's search path).

    Parameters
    ----------
    filename : str
        The LUT file's name, relative to the config's search path.

    Returns
    -------
    PyOpenColorIO.FileTransform
        With OCIO's default interpolation.

    Examples
    --------
    >>> file_transform("ThinFilm_Morpho_Iridescence.clf").getSrc()
    'ThinFilm_Morpho_Iridescence.clf'
    """
    import PyOpenColorIO as ocio

    t = ocio.FileTransform(filename)
    t.setInterpolation(ocio.INTERP_DEFAULT)
    return t


def _reference_space(name):
    """Return OCIO's ReferenceSpaceType for ``"scene"`` or ``"display"``."""
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
    """Return one ``PyOpenColorIO.ColorSpace`` from data (cf. OpenColorIO-Config-ACES).

    Parameters
    ----------
    name : str
        The colour space's name.
    family : str, optional
        Its family (``/``-separated levels).
    encoding : str, optional
        Its encoding (``scene-linear``, ``sdr-video``, ``log``, ``data`` ...).
    categories : iterable of str, optional
        Its categories.
    description : str, optional
        Its description.
    to_reference : PyOpenColorIO.Transform, optional
        Its transform to the reference space.
    from_reference : PyOpenColorIO.Transform, optional
        Its transform from the reference space.
    is_data : bool, optional
        Whether it holds non-colour data (default ``False``).
    aliases : iterable of str, optional
        Other names of it.
    reference_space : str, optional
        ``"scene"`` (default) or ``"display"``: the reference it is defined against.

    Returns
    -------
    PyOpenColorIO.ColorSpace
        With 32-bit float bit depth.

    Raises
    ------
    ValueError
        For a ``reference_space`` other than ``"scene"`` or ``"display"``.

    Examples
    --------
    >>> raw = colorspace_factory("Raw", encoding="data", is_data=True, aliases=["Utility - Raw"])
    >>> raw.getName(), raw.isData(), list(raw.getAliases())
    ('Raw', True, ['Utility - Raw'])
    """
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
    """Return one ``PyOpenColorIO.ViewTransform`` from data.

    Parameters
    ----------
    name : str
        The view transform's name.
    family : str, optional
        Its family.
    description : str, optional
        Its description.
    from_reference : PyOpenColorIO.Transform, optional
        Its transform from the scene (or display) reference to the display reference.
    reference_space : str, optional
        ``"scene"`` (default) or ``"display"``: the reference it starts from.

    Returns
    -------
    PyOpenColorIO.ViewTransform

    Raises
    ------
    ValueError
        For a ``reference_space`` other than ``"scene"`` or ``"display"``.
    """
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
    """Return one ``PyOpenColorIO.NamedTransform`` (forward direction) from data.

    Parameters
    ----------
    name : str
        The named transform's name.
    transform : PyOpenColorIO.Transform
        Its forward transform.
    family : str, optional
        Its family.
    description : str, optional
        Its description.
    categories : iterable of str, optional
        Its categories.
    encoding : str, optional
        Its encoding.

    Returns
    -------
    PyOpenColorIO.NamedTransform
    """
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
