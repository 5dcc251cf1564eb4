"""The film in MaterialX 1.39: a node of its own, reading the tables, feeding BSDFs.

:func:`materialx_document` writes a ``.mtlx`` document (MaterialX Specification 1.39,
standard library nodes only) that defines the film as a node and uses it:

- the node definition ``ND_<name>`` (``<name>``: :func:`materialx_identifier`) with the
  inputs ``thickness`` (float, µm, connectable) and ``roughness`` (vector2, default 0);
- its implementation, the node graph ``NG_<name>``: the tables' node-centred axes read
  with ``image`` at (thickness, N·V), a ``generalized_schlick_bsdf`` tinted by R and, for
  a free-standing film, ``add`` of a ``dielectric_bsdf`` transmitting T;
- an instance ``SS_<name>`` of the node and the ``surfacematerial`` ``<name>``.

Without a transmittance table the material is the film's reflection over an opaque,
black substrate (or a metal in the film's stack). The graph node by node:
docs/materialx.md, *The node*.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from os import PathLike

from ocio_thinfilm import __version__, registry
from ocio_thinfilm.checks import ParameterError, as_choice, as_count
from ocio_thinfilm.export.hosts import table_name, thickness_range

__all__ = ["MATERIALX_COLORSPACES", "materialx_document", "materialx_identifier"]

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


def materialx_identifier(name: str) -> str:
    """Return ``name`` as a MaterialX name.

    Characters other than ASCII letters, digits and ``_`` become ``_``; a name that would
    start with a digit (not an identifier in the generated GLSL and OSL) gets ``film_``
    in front.

    Parameters
    ----------
    name : str
        The film's name (``TableFiles.name``).

    Returns
    -------
    str
        The node and material name ``<name>`` (and ``ND_<name>``, ``NG_<name>``,
        ``SS_<name>``).

    Examples
    --------
    >>> materialx_identifier("Soap bubble (n = 1.33)"), materialx_identifier("3M film")
    ('Soap_bubble__n___1_33_', 'film_3M_film')
    """
    ident = re.sub(r"[^A-Za-z0-9_]", "_", name)
    return f"film_{ident}" if ident[:1].isdigit() else ident


def materialx_document(
    key: str,
    reflectance_exr: str | PathLike[str],
    range_um: tuple[float, float],
    *,
    size: tuple[int, int],
    space: str = "Linear Rec.709 (sRGB)",
    transmittance_exr: str | PathLike[str] | None = None,
    name: str | None = None,
) -> str:
    """Return a MaterialX 1.39 document (text) of the film as a node and a material.

    Parameters
    ----------
    key : str
        The film's key in its film file (in the document's comment).
    reflectance_exr : str or os.PathLike
        The reflectance table; the document names its file (resolved beside the
        document, as MaterialX resolves relative file names).
    range_um : tuple of float
        The table's thickness axis ``(lo, hi)`` in µm (the film's ``range_um``).
    size : tuple of int
        The tables' ``(width, height)`` in texels, each >= 2: their axes are
        node-centred, read at ``(f (N - 1) + 0.5) / N``.
    space : str, optional
        The tables' scene space (a key of :data:`MATERIALX_COLORSPACES`).
    transmittance_exr : str or os.PathLike, optional
        The transmittance table of a free-standing film: the node transmits T (a
        ``dielectric_bsdf`` of ior 1 tinted by T, added to the reflection).
    name : str, optional
        The film's name (``TableFiles.name``, as in the tables' ImageDescription):
        names the node (category) and the material ``<name>``, the node's definition
        ``ND_<name>``, its graph ``NG_<name>`` and the instance ``SS_<name>``
        (:func:`materialx_identifier`). Default ``key``.

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
    >>> '<surfacematerial name="Soap" type="material">' in text
    True
    """
    if not isinstance(key, str) or not key:
        raise TypeError(f"key must be a non-empty string, got {key!r}")
    name = key if name is None else name
    if not isinstance(name, str) or not name:
        raise TypeError(f"name must be a non-empty string, got {name!r}")
    tables = {"reflectance": table_name("reflectance_exr", reflectance_exr)}
    if transmittance_exr is not None:
        tables["transmittance"] = table_name("transmittance_exr", transmittance_exr)
    lo, hi = thickness_range(range_um)
    if not isinstance(size, (tuple, list)) or len(size) != 2:
        raise ParameterError("size", f" must be (width, height), got {size!r}")
    width, height = (as_count("size", n, 2) for n in size)
    colorspace = MATERIALX_COLORSPACES[as_choice("space", space, MATERIALX_COLORSPACES)]
    ident = materialx_identifier(name)

    root = ET.Element("materialx", version="1.39", colorspace=colorspace)
    root.append(
        ET.Comment(
            f" Thin film {name.replace('--', '- -')} ({key.replace('--', '- -')}): "
            f"{' and '.join(tables)} (thickness, angle) from {', '.join(tables.values())} "
            f"(x: thickness {lo}-{hi} um, y: cos theta; written by ocio-thinfilm "
            f"{__version__}) "
        )
    )
    _nodedef(root, ident, (lo, hi))
    graph = ET.SubElement(root, "nodegraph", name=f"NG_{ident}")
    graph.set("nodedef", f"ND_{ident}")
    _table_reads(graph, tables, colorspace, (lo, hi), (width, height))
    _bsdfs(graph, "transmittance" in tables)
    _node(root, ident, f"SS_{ident}", "surfaceshader")
    _node(
        root,
        "surfacematerial",
        ident,
        "material",
        surfaceshader=("surfaceshader", {"nodename": f"SS_{ident}"}),
    )
    ET.indent(root, "  ")
    return '<?xml version="1.0"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


def _nodedef(root: ET.Element, ident: str, range_um: tuple[float, float]) -> None:
    """Add the film's node definition: inputs thickness and roughness, a surfaceshader."""
    lo, hi = range_um
    nodedef = ET.SubElement(
        root,
        "nodedef",
        name=f"ND_{ident}",
        node=ident,
        nodegroup="pbr",
        doc="A thin film's exact reflectance (and transmittance) from its tables.",
    )
    ET.SubElement(
        nodedef,
        "input",
        name="thickness",
        type="float",
        value=repr(round((lo + hi) / 2, 6)),
        uimin=repr(lo),
        uimax=repr(hi),
        uiname="Thickness (um)",
        doc="Physical thickness of the film's varying layer, in micrometres.",
    )
    ET.SubElement(
        nodedef,
        "input",
        name="roughness",
        type="vector2",
        value="0.0, 0.0",
        uiname="Roughness",
        doc="The lobes' roughness (alpha in u and v); 0 is a mirror.",
    )
    ET.SubElement(nodedef, "output", name="out", type="surfaceshader")


def _table_reads(
    graph: ET.Element,
    tables: dict[str, str],
    colorspace: str,
    range_um: tuple[float, float],
    size: tuple[int, int],
) -> None:
    """Add the nodes reading each table at (thickness, N·V), images named by quantity."""
    (lo, hi), (width, height) = range_um, size
    world = {"space": ("string", {"value": "world"})}
    _node(graph, "normal", "N", "vector3", **world)
    _node(graph, "viewdirection", "I", "vector3", **world)
    _node(graph, "dotproduct", "I_dot_N", "float", in1=_from("I"), in2=_from("N"))
    _node(graph, "multiply", "N_dot_V", "float", in1=_from("I_dot_N"), in2=_value("-1.0"))
    _node(
        graph,
        "clamp",
        "cos_theta",
        "float",
        **{"in": _from("N_dot_V"), "low": _value("0.0"), "high": _value("1.0")},
    )
    _remap(graph, "thickness_u", ("float", {"interfacename": "thickness"}), (lo, hi), width)
    _remap(graph, "cos_theta_v", _from("cos_theta"), (0.0, 1.0), height)
    _node(
        graph,
        "combine2",
        "uv",
        "vector2",
        in1=_from("thickness_u"),
        in2=_from("cos_theta_v"),
    )
    for quantity, table in tables.items():
        _node(
            graph,
            "image",
            quantity,
            "color3",
            file=("filename", {"value": table, "colorspace": colorspace}),
            texcoord=("vector2", {"nodename": "uv"}),
            uaddressmode=("string", {"value": "clamp"}),
            vaddressmode=("string", {"value": "clamp"}),
            filtertype=("string", {"value": "linear"}),
        )


def _bsdfs(graph: ET.Element, transmits: bool) -> None:
    """Add the BSDFs (R's reflection; plus T's transmission), the surface and the output."""
    roughness = ("vector2", {"interfacename": "roughness"})
    reflectance = ("color3", {"nodename": "reflectance"})
    _node(
        graph,
        "generalized_schlick_bsdf",
        "reflection",
        "BSDF",
        color0=reflectance,
        color90=reflectance,
        roughness=roughness,
    )
    bsdf = "reflection"
    if transmits:
        _node(
            graph,
            "dielectric_bsdf",
            "transmission",
            "BSDF",
            tint=("color3", {"nodename": "transmittance"}),
            ior=_value("1.0"),
            roughness=roughness,
            scatter_mode=("string", {"value": "T"}),
        )
        _node(graph, "add", "film", "BSDF", in1=_bsdf("reflection"), in2=_bsdf("transmission"))
        bsdf = "film"
    _node(graph, "surface", "shader", "surfaceshader", bsdf=_bsdf(bsdf))
    ET.SubElement(graph, "output", name="out", type="surfaceshader", nodename="shader")


def _from(node: str, kind: str = "float") -> tuple[str, dict[str, str]]:
    return ("vector3" if node in ("I", "N") else kind, {"nodename": node})


def _bsdf(node: str) -> tuple[str, dict[str, str]]:
    return ("BSDF", {"nodename": node})


def _value(value: str) -> tuple[str, dict[str, str]]:
    return ("float", {"value": value})


def _remap(
    graph: ET.Element,
    name: str,
    source: tuple[str, dict[str, str]],
    range_in: tuple[float, float],
    texels: int,
) -> None:
    """Add ``remap`` of ``source`` from ``range_in`` to the texel centres of an axis."""
    _node(
        graph,
        "remap",
        name,
        "float",
        **{
            "in": source,
            "inlow": _value(repr(range_in[0])),
            "inhigh": _value(repr(range_in[1])),
            "outlow": _value(repr(0.5 / texels)),
            "outhigh": _value(repr(1.0 - 0.5 / texels)),
        },
    )
