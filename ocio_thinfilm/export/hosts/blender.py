"""A film's material tables as a Blender node group and material (Cycles and EEVEE).

:func:`blender_script` returns the text of a Python script that, run in Blender 3.4 or
later (``blender --python FILE``, or the Text Editor's *Run Script*), builds

- a shader node group named by the film's ``name``: inputs ``Thickness`` (um) and
  ``Roughness``; outputs ``BSDF``, ``Reflectance`` and, for a free-standing film,
  ``Transmittance``;
- a material of the same name: that group into the material output.

Inside the group cos theta is ``|N . I|``, the tables are read bilinearly in nodes (four
Closest-filtered Image Texture nodes per table on the node-centred axes), and the shader
is a Glossy BSDF tinted by R plus, for a free-standing film, a Transparent BSDF tinted by
T. The script loads the tables of the scene's working space (:class:`BlenderTables`),
finds them beside itself and is idempotent. Why nodes and not the GPU's filtering, the
closures, the working spaces: docs/blender.md.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import PurePosixPath

from ocio_thinfilm import registry
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.config.data import ROLES
from ocio_thinfilm.export.hosts import TableFiles, thickness_range

__all__ = [
    "BLENDER_SPACES",
    "WORKING_INTEROP_IDS",
    "wider_working_spaces",
    "clippable",
    "DEFAULT_SPACE",
    "BlenderTables",
    "blender_script",
    "blender_host",
    "blender_name",
]

#: The tables' space when none is named: ``export material``'s default (the config's
#: scene_linear role), Blender's default working space.
DEFAULT_SPACE = ROLES["scene_linear"]

#: Blender's names of the registry's scene-linear spaces (their ``blender`` field): the
#: registry's name -> (the colour space's name in Blender's OCIO config, its OCIO interop
#: id). Blender 5's working space (``bpy.data.colorspace.working_space``, set in the
#: Properties' Color Management panel or by ``bpy.ops.wm.set_working_color_space``) is
#: Linear Rec.709, Linear Rec.2020 or ACEScg; the script matches the scene's working
#: space to a table by either name.
BLENDER_SPACES: dict[str, tuple[str, str]] = {
    space.name: space.blender for space in registry.SCENE_LINEAR_LIST if space.blender
}


@dataclass(frozen=True)
class BlenderTables:
    """One space's tables of a film, as the script loads them.

    ``space``: the registry's scene-linear space of the tables' RGB; ``reflectance``,
    ``transmittance``: the EXRs' paths relative to the script's folder (``transmittance``
    None unless the film is free-standing); ``outside``: ``(fraction, lowest)``, the
    fraction of the tables' texels with a negative channel (outside the space's gamut)
    and the most negative channel value, ``(0.0, 0.0)`` for tables inside the gamut.
    """

    space: str
    reflectance: str | os.PathLike[str]
    transmittance: str | os.PathLike[str] | None = None
    outside: tuple[float, float] = (0.0, 0.0)


def blender_name(key: str) -> str:
    """Return the default name of film ``key``: the film file's default ``name``.

    Parameters
    ----------
    key : str
        The film's key in its film file.

    Returns
    -------
    str
        ``"Thin Film <key>"``.
    """
    return f"Thin Film {key}"


def _relative(parameter: str, path: str | os.PathLike[str]) -> str:
    text = os.fspath(path).replace("\\", "/")
    pure = PurePosixPath(text)
    if not text or pure.is_absolute() or ".." in pure.parts or ":" in text:
        raise ParameterError(
            parameter,
            " must be a path relative to the script's folder (e.g. the EXR's file name), "
            f"got {os.fspath(path)!r}",
        )
    if not text.lower().endswith(".exr"):
        raise ParameterError(parameter, f" must name an .exr file, got {os.fspath(path)!r}")
    return str(pure)


def _one_line(parameter: str, text: object) -> str:
    if not isinstance(text, str) or not text.strip() or any(c in text for c in "\r\n\0"):
        raise ParameterError(parameter, f" must be a non-empty one-line string, got {text!r}")
    return text


def _tables_entry(tables: BlenderTables, parameters: tuple[str, str, str, str]) -> str:
    """Return one table set as the script's dict literal (ruff-formatted).

    ``parameters`` names, for the error messages, the parameters of the space, of
    ``outside``, of the reflectance and of the transmittance path.
    """
    space_parameter, outside_parameter, r_parameter, t_parameter = parameters
    if tables.space not in BLENDER_SPACES:
        raise ParameterError(
            space_parameter,
            f" space must be one of {', '.join(BLENDER_SPACES)} (Blender's scene-linear "
            f"spaces), got {tables.space!r}",
        )
    fraction, lowest = (float(v) for v in tables.outside)
    if not (0.0 <= fraction <= 1.0 and math.isfinite(lowest) and lowest <= 0.0):
        raise ParameterError(
            outside_parameter,
            f" must be (fraction in [0, 1], value <= 0), got {tables.outside}",
        )
    reflectance = _relative(r_parameter, tables.reflectance)
    transmittance = (
        "None"
        if tables.transmittance is None
        else _quote(_relative(t_parameter, tables.transmittance))
    )
    name, interop = BLENDER_SPACES[tables.space]
    return (
        "    {\n"
        f'        "space": {_quote(tables.space)},\n'
        f'        "blender": ({_quote(name)}, {_quote(interop)}),\n'
        f'        "reflectance": {_quote(reflectance)},\n'
        f'        "transmittance": {transmittance},\n'
        f'        "outside": ({fraction!r}, {lowest!r}),\n'
        f'        "wider": {_tuple(wider_working_spaces(tables.space))},\n'
        f'        "clip": {clippable(tables.space)},\n'
        "    },\n"
    )


#: Blender 5's working spaces (``bpy.data.colorspace.working_space``), by their
#: interop ids (the registry's ``blender`` field).
WORKING_INTEROP_IDS = ("lin_rec709_scene", "lin_rec2020_scene", "lin_ap1_scene")


def _primaries(space: str) -> tuple[tuple[float, float], ...]:
    """Return the xy of a scene-linear space's primaries and white (colour-science's)."""
    import colour

    gamut = colour.RGB_COLOURSPACES[registry.SCENE_LINEAR_BY_NAME[space].gamut.colour_science]
    return tuple(map(tuple, gamut.primaries.tolist())) + (tuple(gamut.whitepoint.tolist()),)


def _inside(point: tuple[float, float], triangle: Sequence[tuple[float, float]]) -> bool:
    """Whether ``point`` lies in ``triangle`` (edges included, 1e-9 of slack)."""
    (x, y), signs = point, []
    for (x0, y0), (x1, y1) in zip(triangle, [*triangle[1:], triangle[0]], strict=True):
        signs.append((x1 - x0) * (y - y0) - (y1 - y0) * (x - x0))
    return all(s >= -1e-9 for s in signs) or all(s <= 1e-9 for s in signs)


def wider_working_spaces(space: str) -> tuple[str, ...]:
    """Return Blender 5's working spaces whose gamut holds ``space``'s and more.

    What the script advises for colours outside the loaded tables' gamut: tables in one
    of these, with that working space.

    Parameters
    ----------
    space : str
        A scene-linear space of the registry.

    Returns
    -------
    tuple of str
        Registry names, in the registry's order.

    Examples
    --------
    >>> wider_working_spaces("Linear Rec.709 (sRGB)")
    ('ACEScg', 'Linear Rec.2020')
    """
    own = _primaries(space)
    wider = []
    for other, (_, interop) in BLENDER_SPACES.items():
        if other == space or interop not in WORKING_INTEROP_IDS:
            continue
        theirs = _primaries(other)
        if theirs[:3] != own[:3] and all(_inside(p, theirs[:3]) for p in own[:3]):
            wider.append(other)
    return tuple(wider)


def clippable(space: str) -> bool:
    """Return whether ``space`` has an SDR display's primaries and white (``--gamut clip``).

    Parameters
    ----------
    space : str
        A scene-linear space of the registry.

    Returns
    -------
    bool
        Whether the constant-lightness clip can map its tables.
    """
    import numpy as np

    own = np.array(_primaries(space))
    return any(
        np.allclose(own, _display_primaries(display.colorimetry), atol=1e-12)
        for display in registry.DISPLAY_LIST
    )


def _display_primaries(colorimetry: str) -> tuple[tuple[float, float], ...]:
    import colour

    gamut = colour.RGB_COLOURSPACES[registry.RGB_COLORIMETRY[colorimetry]]
    return tuple(map(tuple, gamut.primaries.tolist())) + (tuple(gamut.whitepoint.tolist()),)


def _tuple(names: Sequence[str]) -> str:
    """Return ``names`` as a Python tuple literal of strings."""
    if len(names) == 1:
        return f"({_quote(names[0])},)"
    return "(" + ", ".join(_quote(n) for n in names) + ")"


def blender_script(
    key: str,
    reflectance_exr: str | os.PathLike[str],
    transmittance_exr: str | os.PathLike[str] | None,
    range_um: tuple[float, float],
    *,
    name: str | None = None,
    space: str = DEFAULT_SPACE,
    outside: tuple[float, float] = (0.0, 0.0),
    alternates: Sequence[BlenderTables] = (),
) -> str:
    """Return a Blender Python script that builds film ``key``'s node group and material.

    Parameters
    ----------
    key : str
        The film's key (the script's messages name the film by ``name``).
    reflectance_exr : str or os.PathLike
        The reflectance table (the material table's ``_R.exr``), relative to the folder
        the script is written to (usually its file name).
    transmittance_exr : str or os.PathLike or None
        The transmittance table of a free-standing film (``_T.exr``), relative the same
        way; None where the film transmits nothing the renderer should show (a film on
        an opaque or semi-infinite substrate): the material then reflects only.
    range_um : tuple of float
        The tables' thickness range ``(lo, hi)`` in micrometres, ``0 <= lo < hi``.
    name : str, optional
        The film's name, the name of the node group and the material (the EXR header's
        and the other hosts' name); default :func:`blender_name` of ``key``, the film
        file's default.
    space : str, optional
        The tables' scene-linear space (a key of :data:`BLENDER_SPACES`; default
        :data:`DEFAULT_SPACE`).
    outside : tuple of float, optional
        ``(fraction, lowest)`` of the tables' texels outside the space's gamut
        (:class:`BlenderTables`); the script reports them where it loads these tables.
    alternates : sequence of BlenderTables, optional
        The same film's tables in other spaces (each space once): the script loads the
        tables whose space is the scene's working space, else the first.

    Returns
    -------
    str
        The script's text (Python 3, no imports beyond ``bpy`` and ``os``; it passes the
        repository's ruff lint and format rules).

    Raises
    ------
    ParameterError
        For an empty key or name, a path that is absolute, leaves the folder or is no
        ``.exr``, a range that is not ``0 <= lo < hi`` (finite), a space Blender does
        not name or named twice, or an ``outside`` that is no fraction and value <= 0.

    Examples
    --------
    >>> text = blender_script("Soap", "ThinFilm_User_Soap_R.exr", None, (0.0, 1.0))
    >>> 'NAME = "Thin Film Soap"' in text, "RANGE_UM = (0.0, 1.0)" in text
    (True, True)
    """
    _one_line("key", key)
    title = _one_line("name", blender_name(key) if name is None else name)
    first = BlenderTables(space, reflectance_exr, transmittance_exr, outside)
    entries = [_tables_entry(first, ("space", "outside", "reflectance_exr", "transmittance_exr"))]
    spaces = [space]
    for other in alternates:
        if other.space in spaces:
            raise ParameterError("alternates", f" names space {other.space!r} twice")
        if (other.transmittance is None) != (transmittance_exr is None):
            raise ParameterError("alternates", " must all have a transmittance table or none")
        spaces.append(other.space)
        entries.append(_tables_entry(other, ("alternates",) * 4))
    lo, hi = thickness_range(range_um)
    from ocio_thinfilm import __version__

    head = (
        f'"""{_docstring(title)}: the film as a Blender node group and material.\n\n'
        f"Written by ocio-thinfilm {__version__}. Run it in Blender 3.4 or later: "
        "blender --python THIS_FILE,\nor open it in the Text Editor and Run Script. "
        "The tables are read from this file's folder.\n"
        '"""\n\n'
        "import os\n\n"
        "import bpy\n\n"
        f"NAME = {_quote(title)}\n"
        f"RANGE_UM = ({lo!r}, {hi!r})\n"
        "#: The film's tables, one entry per space: the first is loaded where the scene's\n"
        "#: working space is none of them; outside = (fraction of texels with a negative\n"
        "#: channel, the most negative value).\n"
        "TABLES = [\n" + "".join(entries) + "]\n"
    )
    return head + _BODY


def blender_host(files: TableFiles) -> str:
    """Return the Blender script of ``export material``'s written tables.

    Parameters
    ----------
    files : TableFiles
        The written tables (their file names are kept: the script lies beside them),
        with the same film's tables in further spaces in ``files.others``.

    Returns
    -------
    str
        :func:`blender_script`'s text, the node group and material named ``files.name``.
    """

    def tables(record: TableFiles) -> BlenderTables:
        t_name = None if record.transmittance is None else record.transmittance.name
        return BlenderTables(record.space, record.reflectance.name, t_name, record.outside)

    first = tables(files)
    return blender_script(
        files.key,
        first.reflectance,
        first.transmittance,
        files.range_um,
        name=files.name,
        space=files.space,
        outside=files.outside,
        alternates=[tables(other) for other in files.others],
    )


def _quote(text: str) -> str:
    """Return ``text`` as a Python string literal, quoted as ruff format quotes it.

    Double quotes, unless the text holds more double quotes than single ones.
    """
    quote = "'" if text.count('"') > text.count("'") else '"'
    return quote + text.replace("\\", "\\\\").replace(quote, "\\" + quote) + quote


def _docstring(text: str) -> str:
    """Return ``text`` safe inside the script's triple-quoted docstring."""
    return text.replace("\\", "\\\\").replace('"', "'")


#: The script after its constants: plain Blender Python, 3.4 to 5.x (the node group's
#: sockets through ``interface`` from 4.0, ``inputs``/``outputs`` before). Its helpers
#: are private (``_``) and its docstrings numpydoc-clean: the script passes the
#: repository's ruff rules wherever it is saved.
_BODY = r'''

def _folder():
    """Return the folder of this script: __file__, else the Text Editor's file."""
    path = globals().get("__file__")
    if path and os.path.isfile(path):
        return os.path.dirname(os.path.abspath(path))
    text = getattr(getattr(bpy.context, "space_data", None), "text", None)
    if text is not None and text.filepath:
        return os.path.dirname(os.path.abspath(bpy.path.abspath(text.filepath)))
    raise RuntimeError(
        NAME + ": cannot tell this script's folder; run it with blender --python FILE "
        "or open the file in the Text Editor"
    )


def _table_path(relative):
    path = os.path.join(_folder(), *relative.split("/"))
    if not os.path.isfile(path):
        raise FileNotFoundError(NAME + ": no table at " + path + " (nothing was changed)")
    return path


def _table(relative):
    """Return the EXR table as an image, reloaded from disk, read as data (Non-Color)."""
    image = bpy.data.images.load(_table_path(relative), check_existing=True)
    image.reload()
    for space in ("Non-Color", "Raw", "Utility - Raw", "Data"):
        try:
            image.colorspace_settings.name = space
            break
        except TypeError:
            continue
    return image


def _working_space():
    """Return the scene's working space as (name, interop id), or None if unknown.

    Blender 5: the blend file's working colour space. Before: the scene_linear role of
    Blender's own colour config, Linear Rec.709, unless $OCIO names another config.
    """
    colorspace = getattr(bpy.data, "colorspace", None)
    if getattr(colorspace, "working_space", None):
        return colorspace.working_space, getattr(colorspace, "working_space_interop_id", "")
    if os.environ.get("OCIO"):
        return None
    return "Linear Rec.709", "lin_rec709_scene"


def _choose(found):
    """Return the entry of TABLES for the working space ``found`` (else the first)."""
    for entry in TABLES:
        if found is not None and (found[0] in entry["blender"] or found[1] in entry["blender"]):
            return entry
    return TABLES[0]


def _report(entry, found):
    """Print, once each, the space mismatch and the share of the table out of gamut."""
    space = entry["space"]
    if found is None:
        print(f"{NAME}: cannot tell the scene's working space ($OCIO); using the {space} tables")
    elif found[0] not in entry["blender"] and found[1] not in entry["blender"]:
        print(
            f"{NAME}: the tables are in {space} but the scene's working space is "
            f"{found[0]}: colours will be wrong; export the film with --space for it "
            f"(tables here: {', '.join(e['space'] for e in TABLES)})"
        )
    fraction, lowest = entry["outside"]
    if fraction > 0:
        print(
            f"{NAME}: {100 * fraction:.1f} % of the table's texels lie outside {space}'s "
            f"gamut (a channel down to {lowest:.3f}); Cycles clamps them per channel: "
            f"{_advice(entry)}"
        )


def _advice(entry):
    """Return what to do about the colours outside the tables' gamut."""
    ways = []
    if entry["wider"]:
        options = " or ".join(f"--space '{space}'" for space in entry["wider"])
        ways.append(f"export with {options} for a scene in that working space (Blender 5)")
    if entry["clip"]:
        ways.append("with --gamut clip")
    return "; or ".join(ways) or "no wider working space of Blender holds them"


def _clear_sockets(group):
    if hasattr(group, "interface"):
        group.interface.clear()
    else:
        group.inputs.clear()
        group.outputs.clear()


def _socket(group, in_out, kind, name):
    if hasattr(group, "interface"):
        return group.interface.new_socket(name, in_out=in_out, socket_type=kind)
    return (group.inputs if in_out == "INPUT" else group.outputs).new(kind, name)


def _build_group(entry):
    reflectance, transmittance = entry["reflectance"], entry["transmittance"]
    for relative in (reflectance, transmittance):
        if relative is not None:
            _table_path(relative)  # every table is there before anything changes
    group = bpy.data.node_groups.get(NAME)
    if group is None or group.bl_idname != "ShaderNodeTree":
        group = bpy.data.node_groups.new(NAME, "ShaderNodeTree")
    group.nodes.clear()
    _clear_sockets(group)
    lo, hi = RANGE_UM
    thickness = _socket(group, "INPUT", "NodeSocketFloat", "Thickness")
    thickness.default_value = 0.5 * (lo + hi)
    thickness.min_value, thickness.max_value = 0.0, max(10.0 * hi, 1.0)
    if hasattr(thickness, "description"):
        thickness.description = f"Film thickness in micrometres (table: {lo:g} to {hi:g})"
    roughness = _socket(group, "INPUT", "NodeSocketFloat", "Roughness")
    roughness.default_value = 0.0
    roughness.min_value, roughness.max_value = 0.0, 1.0
    _socket(group, "OUTPUT", "NodeSocketShader", "BSDF")
    _socket(group, "OUTPUT", "NodeSocketColor", "Reflectance")
    if transmittance is not None:
        _socket(group, "OUTPUT", "NodeSocketColor", "Transmittance")

    nodes, links = group.nodes, group.links

    def node(kind, x, y, **settings):
        n = nodes.new(kind)
        n.location = (x, y)
        for name, value in settings.items():
            setattr(n, name, value)
        return n

    inputs = node("NodeGroupInput", -900, 0)
    outputs = node("NodeGroupOutput", 1800, 0)
    geometry = node("ShaderNodeNewGeometry", -900, -250)
    dot = node("ShaderNodeVectorMath", -700, -250, operation="DOT_PRODUCT")
    links.new(geometry.outputs["Normal"], dot.inputs[0])
    links.new(geometry.outputs["Incoming"], dot.inputs[1])
    cosine = node("ShaderNodeMath", -500, -250, operation="ABSOLUTE", use_clamp=True)
    cosine.label = "cos theta"
    links.new(dot.outputs["Value"], cosine.inputs[0])
    u = node("ShaderNodeMath", -500, 50, operation="MULTIPLY_ADD")
    u.label = "u = (t - lo) / (hi - lo)"
    links.new(inputs.outputs["Thickness"], u.inputs[0])
    u.inputs[1].default_value = 1.0 / (hi - lo)
    u.inputs[2].default_value = -lo / (hi - lo)

    def neighbours(value, size, x, y):
        """Return the texel centres around ``value`` on a node-centred axis, and a weight.

        The texel centres of the two samples around value (0-1) on an axis of size
        texels, and the weight of the second: p = value * (size - 1), centres
        (floor(p) + 0.5) / size and the next, weight p - floor(p) (EXTEND: a centre off
        the edge reads the edge, so values outside 0-1 read the end).
        """
        p = node("ShaderNodeMath", x, y, operation="MULTIPLY_ADD")
        links.new(value, p.inputs[0])
        p.inputs[1].default_value = float(size - 1)
        p.inputs[2].default_value = 0.0
        low = node("ShaderNodeMath", x + 150, y, operation="FLOOR")
        links.new(p.outputs[0], low.inputs[0])
        weight = node("ShaderNodeMath", x + 300, y, operation="SUBTRACT")
        links.new(p.outputs[0], weight.inputs[0])
        links.new(low.outputs[0], weight.inputs[1])
        first = node("ShaderNodeMath", x + 300, y - 150, operation="MULTIPLY_ADD")
        links.new(low.outputs[0], first.inputs[0])
        first.inputs[1].default_value = 1.0 / size
        first.inputs[2].default_value = 0.5 / size
        second = node("ShaderNodeMath", x + 450, y - 150, operation="ADD")
        links.new(first.outputs[0], second.inputs[0])
        second.inputs[1].default_value = 1.0 / size
        return first.outputs[0], second.outputs[0], weight.outputs[0]

    def lerp(a, b, weight, x, y):
        difference = node("ShaderNodeVectorMath", x, y, operation="SUBTRACT")
        links.new(b, difference.inputs[0])
        links.new(a, difference.inputs[1])
        result = node("ShaderNodeVectorMath", x + 150, y, operation="MULTIPLY_ADD")
        links.new(difference.outputs[0], result.inputs[0])
        links.new(weight, result.inputs[1])
        links.new(a, result.inputs[2])
        return result.outputs[0]

    def texture(relative, y, label):
        """Return the table's bilinear lookup from four Closest reads at its samples.

        The same on every engine (a GPU's filtered read picks a mipmap level from the
        screen-space derivatives of (u, v): it blurs the table across thicknesses).
        """
        image = _table(relative)
        width, height = image.size
        u0, u1, wu = neighbours(u.outputs[0], width, -300, y + 300)
        v0, v1, wv = neighbours(cosine.outputs[0], height, -300, y)
        corners = []
        for i, (a, b) in enumerate(((u0, v0), (u1, v0), (u0, v1), (u1, v1))):
            uv = node("ShaderNodeCombineXYZ", 300, y + 300 - 150 * i)
            links.new(a, uv.inputs[0])
            links.new(b, uv.inputs[1])
            t = node(
                "ShaderNodeTexImage",
                450,
                y + 300 - 150 * i,
                interpolation="Closest",
                extension="EXTEND",
            )
            t.image = image
            t.label = label
            links.new(uv.outputs[0], t.inputs["Vector"])
            corners.append(t.outputs["Color"])
        low = lerp(corners[0], corners[1], wu, 700, y + 250)
        high = lerp(corners[2], corners[3], wu, 700, y)
        return lerp(low, high, wv, 1000, y + 100)

    glossy = node("ShaderNodeBsdfGlossy", 1400, 100)
    try:
        glossy.distribution = "MULTI_GGX"
    except TypeError:
        glossy.distribution = "GGX"
    links.new(inputs.outputs["Roughness"], glossy.inputs["Roughness"])
    r = texture(reflectance, 300, "Reflectance R")
    links.new(r, glossy.inputs["Color"])
    links.new(r, outputs.inputs["Reflectance"])
    bsdf = glossy.outputs[0]
    if transmittance is not None:
        t = texture(transmittance, -500, "Transmittance T")
        transparent = node("ShaderNodeBsdfTransparent", 1400, -150)
        links.new(t, transparent.inputs["Color"])
        links.new(t, outputs.inputs["Transmittance"])
        add = node("ShaderNodeAddShader", 1600, 0)
        links.new(glossy.outputs[0], add.inputs[0])
        links.new(transparent.outputs[0], add.inputs[1])
        bsdf = add.outputs[0]
    links.new(bsdf, outputs.inputs["BSDF"])
    return group


def _build_material(group, transmits):
    material = bpy.data.materials.get(NAME) or bpy.data.materials.new(NAME)
    if getattr(material, "node_tree", None) is None:
        material.use_nodes = True
    tree = material.node_tree
    tree.nodes.clear()
    film = tree.nodes.new("ShaderNodeGroup")
    film.node_tree = group
    film.location = (0, 0)
    film.inputs["Thickness"].default_value = 0.5 * (RANGE_UM[0] + RANGE_UM[1])
    film.inputs["Roughness"].default_value = 0.0
    output = tree.nodes.new("ShaderNodeOutputMaterial")
    output.location = (300, 0)
    tree.links.new(film.outputs["BSDF"], output.inputs["Surface"])
    if transmits:
        # EEVEE: Blended shows the coloured transmission without noise
        # (docs/blender.md); Dithered (Alpha Hashed in 3.x) is stochastic and speckles
        if hasattr(material, "surface_render_method"):
            material.surface_render_method = "BLENDED"
        elif hasattr(material, "blend_method"):
            material.blend_method = "BLEND"
            if hasattr(material, "shadow_method"):
                material.shadow_method = "HASHED"
    return material


def _main():
    found = _working_space()
    entry = _choose(found)
    _build_material(_build_group(entry), entry["transmittance"] is not None)
    _report(entry, found)
    print(f"{NAME}: node group and material built from {_folder()} ({entry['space']} tables)")


_main()
'''
