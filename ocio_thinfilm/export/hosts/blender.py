"""A film's material tables as a Blender node group and material (Cycles and EEVEE).

:func:`blender_script` returns the text of a Python script that, run in Blender 3.4 or
later (``blender --python FILE``, or the Text Editor's *Run Script*), builds

- the shader node group ``Thin Film <KEY>``: inputs ``Thickness`` (the film's physical
  thickness in micrometres, default the middle of the table's range) and ``Roughness``;
  outputs ``BSDF`` (the film as a shader), ``Reflectance`` and, for a free-standing film,
  ``Transmittance`` (the tables' colours at the shading point, to feed other shaders);
- the material ``Thin Film <KEY>``: that group into the material output.

Inside the group the cosine of the incidence angle is ``|N . I|`` clamped to [0, 1] (the
Geometry node's shading ``Normal`` and ``Incoming``, the unit vector towards the ray's
origin; the absolute value serves back faces, where a free-standing film is the same
seen from either side), the texture coordinates are ``u = (t - lo) / (hi - lo)`` and
``v = cos(theta)`` (the table's node-centred axes: ``docs/blender.md``, the material
table's contract: sample ``i`` of ``N`` at fraction ``i / (N - 1)``, so normal and grazing
incidence are table rows), and each table is read bilinearly in nodes: four Image Texture
nodes (colour space Non-Color, Closest interpolation, EXTEND) at the two samples around
(u, v) along each axis, mixed by the fractional position between them. A GPU's own
filtered read (EEVEE's Linear) picks a mipmap level from the screen-space derivatives
of (u, v) and so blurs the table across thicknesses; measured in bpy 5.0.1's EEVEE on
Mesa, it returned wrong colours outright (DeltaE2000 p50 16 against the exact film; 0.2
with the nodes).

The shader is a Glossy BSDF (multiscatter GGX, the ``Roughness`` input) tinted by the
reflectance R, plus, where a transmittance table is given, a Transparent BSDF tinted by
the transmittance T: light goes straight through a film far thinner than the object, and
the two weights add to R + T, the film's energy.

The script finds the tables beside itself (their paths are relative to the script's
folder, so the folder can be moved) and is idempotent: run again, it rebuilds the node
group and the material of the same names in place (materials and objects that use them
keep doing so) and reloads the images from disk; it touches no other data.
"""

from __future__ import annotations

import os
from pathlib import PurePosixPath

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.export.hosts import thickness_range

__all__ = ["blender_script", "blender_name"]


def blender_name(key: str) -> str:
    """Return the name of the node group and the material of film ``key``.

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


def blender_script(
    key: str,
    reflectance_exr: str | os.PathLike[str],
    transmittance_exr: str | os.PathLike[str] | None,
    range_um: tuple[float, float],
) -> str:
    """Return a Blender Python script that builds film ``key``'s node group and material.

    Parameters
    ----------
    key : str
        The film's key: the node group and the material are called ``Thin Film <key>``.
    reflectance_exr : str or os.PathLike
        The reflectance table (the material table's ``_R.exr``), relative to the folder
        the script is written to (usually its file name).
    transmittance_exr : str or os.PathLike or None
        The transmittance table of a free-standing film (``_T.exr``), relative the same
        way; None where the film transmits nothing the renderer should show (a film on
        an opaque or semi-infinite substrate): the material then reflects only.
    range_um : tuple of float
        The tables' thickness range ``(lo, hi)`` in micrometres, ``0 <= lo < hi``.

    Returns
    -------
    str
        The script's text (Python 3, no imports beyond ``bpy`` and ``os``).

    Raises
    ------
    ParameterError
        For an empty key, a path that is absolute, leaves the folder or is no ``.exr``,
        or a range that is not ``0 <= lo < hi`` (finite).

    Examples
    --------
    >>> text = blender_script("Soap", "ThinFilm_User_Soap_R.exr", None, (0.0, 1.0))
    >>> 'NAME = "Thin Film Soap"' in text, "RANGE_UM = (0.0, 1.0)" in text
    (True, True)
    """
    if not isinstance(key, str) or not key.strip() or any(c in key for c in "\r\n\0"):
        raise ParameterError("key", f" must be a non-empty one-line string, got {key!r}")
    reflectance = _relative("reflectance_exr", reflectance_exr)
    transmittance = (
        None if transmittance_exr is None else _relative("transmittance_exr", transmittance_exr)
    )
    lo, hi = thickness_range(range_um)
    from ocio_thinfilm import __version__

    head = (
        f'"""{blender_name(key)}: the film as a Blender node group and material.\n\n'
        f"Written by ocio-thinfilm {__version__}. Run it in Blender 3.4 or later: "
        "blender --python THIS_FILE,\nor open it in the Text Editor and Run Script. "
        "The tables are read from this file's folder.\n"
        '"""\n\n'
        "import os\n\n"
        "import bpy\n\n"
        f"NAME = {_quote(blender_name(key))}\n"
        f"REFLECTANCE = {_quote(reflectance)}\n"
        f"TRANSMITTANCE = {'None' if transmittance is None else _quote(transmittance)}\n"
        f"RANGE_UM = ({lo!r}, {hi!r})\n"
    )
    return head + _BODY


def _quote(text: str) -> str:
    """Return ``text`` as a Python string literal in double quotes."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


#: The script after its constants: plain Blender Python, 3.4 to 5.x (the node group's
#: sockets through ``interface`` from 4.0, ``inputs``/``outputs`` before).
_BODY = r'''

def folder():
    """The folder of this script: __file__, else the Text Editor's file."""
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


def table_path(relative):
    path = os.path.join(folder(), *relative.split("/"))
    if not os.path.isfile(path):
        raise FileNotFoundError(NAME + ": no table at " + path + " (nothing was changed)")
    return path


def table(relative):
    """The EXR table as an image, reloaded from disk, read as data (Non-Color)."""
    image = bpy.data.images.load(table_path(relative), check_existing=True)
    image.reload()
    for space in ("Non-Color", "Raw", "Utility - Raw", "Data"):
        try:
            image.colorspace_settings.name = space
            break
        except TypeError:
            continue
    return image


def clear_sockets(group):
    if hasattr(group, "interface"):
        group.interface.clear()
    else:
        group.inputs.clear()
        group.outputs.clear()


def socket(group, in_out, kind, name):
    if hasattr(group, "interface"):
        return group.interface.new_socket(name, in_out=in_out, socket_type=kind)
    return (group.inputs if in_out == "INPUT" else group.outputs).new(kind, name)


def build_group():
    for relative in (REFLECTANCE, TRANSMITTANCE):
        if relative is not None:
            table_path(relative)  # every table is there before anything changes
    group = bpy.data.node_groups.get(NAME)
    if group is None or group.bl_idname != "ShaderNodeTree":
        group = bpy.data.node_groups.new(NAME, "ShaderNodeTree")
    group.nodes.clear()
    clear_sockets(group)
    lo, hi = RANGE_UM
    thickness = socket(group, "INPUT", "NodeSocketFloat", "Thickness")
    thickness.default_value = 0.5 * (lo + hi)
    thickness.min_value, thickness.max_value = 0.0, max(10.0 * hi, 1.0)
    if hasattr(thickness, "description"):
        thickness.description = "Film thickness in micrometres (table: %g to %g)" % (lo, hi)
    roughness = socket(group, "INPUT", "NodeSocketFloat", "Roughness")
    roughness.default_value = 0.0
    roughness.min_value, roughness.max_value = 0.0, 1.0
    socket(group, "OUTPUT", "NodeSocketShader", "BSDF")
    socket(group, "OUTPUT", "NodeSocketColor", "Reflectance")
    if TRANSMITTANCE is not None:
        socket(group, "OUTPUT", "NodeSocketColor", "Transmittance")

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
        """The texel centres of the two samples around value (0-1) on a node-centred
        axis of size texels, and the weight of the second: p = value * (size - 1),
        centres (floor(p) + 0.5) / size and the next, weight p - floor(p) (EXTEND: a
        centre off the edge reads the edge, so values outside 0-1 read the end)."""
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
        """Bilinear lookup of the table from four Closest reads at its samples, the
        same on every engine (a GPU's filtered read picks a mipmap level from the
        screen-space derivatives of (u, v): it blurs the table across thicknesses)."""
        image = table(relative)
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
    r = texture(REFLECTANCE, 300, "Reflectance R")
    links.new(r, glossy.inputs["Color"])
    links.new(r, outputs.inputs["Reflectance"])
    bsdf = glossy.outputs[0]
    if TRANSMITTANCE is not None:
        t = texture(TRANSMITTANCE, -500, "Transmittance T")
        transparent = node("ShaderNodeBsdfTransparent", 1400, -150)
        links.new(t, transparent.inputs["Color"])
        links.new(t, outputs.inputs["Transmittance"])
        add = node("ShaderNodeAddShader", 1600, 0)
        links.new(glossy.outputs[0], add.inputs[0])
        links.new(transparent.outputs[0], add.inputs[1])
        bsdf = add.outputs[0]
    links.new(bsdf, outputs.inputs["BSDF"])
    return group


def build_material(group):
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
    if TRANSMITTANCE is not None:
        # EEVEE: the transparent part needs a see-through render method
        if hasattr(material, "surface_render_method"):
            material.surface_render_method = "DITHERED"
        elif hasattr(material, "blend_method"):
            material.blend_method = "HASHED"
            if hasattr(material, "shadow_method"):
                material.shadow_method = "HASHED"
    return material


build_material(build_group())
print(NAME + ": node group and material built from " + folder())
'''
