"""The film in MaterialX 1.39: a node graph reading the table, feeding a BSDF.

The graph reads the reflectance table by thickness and view angle.

:func:`materialx_document` writes a ``.mtlx`` document (MaterialX Specification 1.39,
standard library nodes only):

- the node graph ``NG_ThinFilm_<key>`` with one input, ``thickness`` (µm, default the
  middle of the film's range), and one output, ``reflectance`` (color3): the table's
  node-centred axes read at ``(f (N - 1) + 0.5) / N`` for fraction ``f``: ``u`` =
  ``remap(thickness, lo, hi, 0.5 / W, 1 - 0.5 / W)``, ``v`` = ``remap(cos θ, 0, 1, 0.5 /
  H, 1 - 0.5 / H)`` with cos θ = ``clamp(-dotproduct(viewdirection, normal), 0, 1)`` = N·V
  (MaterialX's view direction points from the eye to the surface; both in world
  space), ``image`` of the table at ``(u, v)`` with
  ``uaddressmode``/``vaddressmode`` ``clamp`` and ``filtertype`` ``linear`` (MaterialX
  addresses images with v = 0 at the bottom row, the table's cos θ near 0);
- ``generalized_schlick_bsdf`` with ``color0`` = ``color90`` = the reflectance (the
  Fresnel term is R at the shading point's N·V over the whole lobe; ``color82`` left at
  its default white, which adds no F82 tint), ``roughness`` an input of the BSDF
  (default 0: a mirror), then ``surface`` and the ``surfacematerial`` ``ThinFilm_<key>``.

The light the film transmits is not in the document: it is the film on an opaque,
black substrate (or a metal in the film's stack).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from os import PathLike

from ocio_thinfilm import __version__, registry
from ocio_thinfilm.checks import ParameterError, as_choice, as_count
from ocio_thinfilm.export.hosts import table_name, thickness_range

__all__ = ["MATERIALX_COLORSPACES", "materialx_document"]

#: The table's scene space -> MaterialX's colour space name (its default colour
#: management system's names, MaterialX Specification 1.39, "Color Spaces"), from the
#: registry's scene-linear spaces.
MATERIALX_COLORSPACES = {
    space.name: space.materialx
    for space in registry.SCENE_LINEAR_LIST
    if space.materialx is not None
}


def _node(parent: ET.Element, category: str, name: str, kind: str, **inputs) -> ET.Element:
    """Add a node; each input is ``(type, {attribute: value})``."""
    node = ET.SubElement(parent, category, name=name, type=kind)
    for input_name, (input_type, attributes) in inputs.items():
        ET.SubElement(node, "input", name=input_name, type=input_type, **attributes)
    return node


def materialx_document(
    key: str,
    reflectance_exr: str | PathLike[str],
    range_um: tuple[float, float],
    *,
    size: tuple[int, int],
    space: str = "Linear Rec.709 (sRGB)",
) -> str:
    """Return a MaterialX 1.39 document (text) of the film as a material.

    Parameters
    ----------
    key : str
        The film's key: names the node graph ``NG_ThinFilm_<key>`` and the material
        ``ThinFilm_<key>`` (characters MaterialX names do not allow become ``_``).
    reflectance_exr : str or os.PathLike
        The reflectance table; the document names its file (resolved beside the
        document, as MaterialX resolves relative file names).
    range_um : tuple of float
        The table's thickness axis ``(lo, hi)`` in µm (the film's ``range_um``).
    size : tuple of int
        The table's ``(width, height)`` in texels, each >= 2: its axes are node-centred,
        read at ``(f (N - 1) + 0.5) / N``.
    space : str, optional
        The table's scene space (a key of :data:`MATERIALX_COLORSPACES`).

    Returns
    -------
    str
        The ``.mtlx`` document.

    Raises
    ------
    ParameterError
        For a thickness range that is not ``0 <= lo < hi``, a table that is not an EXR or
        a space MaterialX has no name for.

    Examples
    --------
    >>> text = materialx_document("Soap", "ThinFilm_User_Soap_R.exr", (0.0, 1.0), size=(64, 32))
    >>> '<surfacematerial name="ThinFilm_Soap" type="material">' in text
    True
    """
    if not isinstance(key, str) or not key:
        raise TypeError(f"key must be a non-empty string, got {key!r}")
    table = table_name("reflectance_exr", reflectance_exr)
    lo, hi = thickness_range(range_um)
    if not isinstance(size, (tuple, list)) or len(size) != 2:
        raise ParameterError("size", f" must be (width, height), got {size!r}")
    width, height = (as_count("size", n, 2) for n in size)
    colorspace = MATERIALX_COLORSPACES[as_choice("space", space, MATERIALX_COLORSPACES)]
    name = re.sub(r"[^A-Za-z0-9_]", "_", key)
    graph_name = f"NG_ThinFilm_{name}"

    root = ET.Element("materialx", version="1.39", colorspace=colorspace)
    root.append(
        ET.Comment(
            f" Thin film {key.replace('--', '- -')}: reflectance R(thickness, angle) from "
            f"{table} (x: thickness {lo}-{hi} um, y: cos theta; written by ocio-thinfilm "
            f"{__version__}) "
        )
    )
    graph = ET.SubElement(root, "nodegraph", name=graph_name)
    ET.SubElement(
        graph,
        "input",
        name="thickness",
        type="float",
        value=repr(round((lo + hi) / 2, 6)),
        uimin=repr(lo),
        uimax=repr(hi),
        uiname="Thickness (um)",
        doc="Physical thickness of the film's varying layer, in micrometres.",
    )
    world = {"space": ("string", {"value": "world"})}
    _node(graph, "normal", "N", "vector3", **world)
    _node(graph, "viewdirection", "I", "vector3", **world)
    _node(
        graph,
        "dotproduct",
        "I_dot_N",
        "float",
        in1=("vector3", {"nodename": "I"}),
        in2=("vector3", {"nodename": "N"}),
    )
    _node(
        graph,
        "multiply",
        "N_dot_V",
        "float",
        in1=("float", {"nodename": "I_dot_N"}),
        in2=("float", {"value": "-1.0"}),
    )
    _node(
        graph,
        "clamp",
        "cos_theta",
        "float",
        **{
            "in": ("float", {"nodename": "N_dot_V"}),
            "low": ("float", {"value": "0.0"}),
            "high": ("float", {"value": "1.0"}),
        },
    )
    _node(
        graph,
        "remap",
        "thickness_u",
        "float",
        **{
            "in": ("float", {"interfacename": "thickness"}),
            "inlow": ("float", {"value": repr(lo)}),
            "inhigh": ("float", {"value": repr(hi)}),
            "outlow": ("float", {"value": repr(0.5 / width)}),
            "outhigh": ("float", {"value": repr(1.0 - 0.5 / width)}),
        },
    )
    _node(
        graph,
        "remap",
        "cos_theta_v",
        "float",
        **{
            "in": ("float", {"nodename": "cos_theta"}),
            "inlow": ("float", {"value": "0.0"}),
            "inhigh": ("float", {"value": "1.0"}),
            "outlow": ("float", {"value": repr(0.5 / height)}),
            "outhigh": ("float", {"value": repr(1.0 - 0.5 / height)}),
        },
    )
    _node(
        graph,
        "combine2",
        "uv",
        "vector2",
        in1=("float", {"nodename": "thickness_u"}),
        in2=("float", {"nodename": "cos_theta_v"}),
    )
    _node(
        graph,
        "image",
        "table",
        "color3",
        file=("filename", {"value": table, "colorspace": colorspace}),
        texcoord=("vector2", {"nodename": "uv"}),
        uaddressmode=("string", {"value": "clamp"}),
        vaddressmode=("string", {"value": "clamp"}),
        filtertype=("string", {"value": "linear"}),
    )
    ET.SubElement(graph, "output", name="reflectance", type="color3", nodename="table")

    reflectance = ("color3", {"nodegraph": graph_name, "output": "reflectance"})
    _node(
        root,
        "generalized_schlick_bsdf",
        f"BSDF_ThinFilm_{name}",
        "BSDF",
        color0=reflectance,
        color90=reflectance,
        roughness=("vector2", {"value": "0.0, 0.0"}),
    )
    _node(
        root,
        "surface",
        f"SS_ThinFilm_{name}",
        "surfaceshader",
        bsdf=("BSDF", {"nodename": f"BSDF_ThinFilm_{name}"}),
    )
    _node(
        root,
        "surfacematerial",
        f"ThinFilm_{name}",
        "material",
        surfaceshader=("surfaceshader", {"nodename": f"SS_ThinFilm_{name}"}),
    )
    ET.indent(root, "  ")
    return '<?xml version="1.0"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
