"""The renderer tests' scene, run by the ``bpy`` venv's Python (:mod:`evaluation.blender`).

``python blender_scene.py JOB.json``: an empty scene, a uniform world (RGB ``world``,
strength 1), a smooth unit sphere at the origin, an orthographic camera on +z looking
down -z whose frame is ``2.2`` wide (pixel centres ``x = -1.1 + 2.2 (i + 0.5) / size``,
``y`` likewise from the top), a pixel filter 0.01 px wide (each pixel sees its centre),
Cycles without denoising or adaptive sampling (or EEVEE), the Standard view, and a
32-bit float EXR of the scene linear render (Blender's Linear Rec.709). The sphere's
material is

- ``{"kind": "script", "script": PATH, "name": NAME}``: the generated film script is run
  (``runpy``, so ``__file__`` is its path) and its material ``NAME`` is used, its group's
  ``Thickness`` driven by the ramp below;
- ``{"kind": "principled", "ior": n, "film_ior": n}``: a Principled BSDF, black base,
  its ``Thin Film Thickness`` (nm) from the same ramp;
- ``{"kind": "principled_bubble", "film_ior": n}``: Blender's nearest bubble, a
  Principled BSDF with white base, Transmission Weight 1, IOR 1.0, Roughness 0 and its
  thin film (``Thin Film IOR`` n, ``Thin Film Thickness`` from the ramp).

``"scene": "bubble"`` adds, behind the sphere, a checker backdrop (the plane z = -2,
8 x 8, squares of 0.5 in two colours, emitting: it adds no noise of its own) and makes
the world an environment whose colour varies with the direction (an orange-to-blue
gradient along z): the sphere shows the backdrop through itself and the world in its
reflection. ``"structure"`` rebuilds a script material's closures for the benchmark of
closure structures (``"add"``: as written; ``"mix"``: Mix Shader, factor avg(T) /
(avg(R) + avg(T)), of Glossy(R / (1 - factor)) and Transparent(T / factor));
``"render_method"`` sets EEVEE's (``"BLENDED"``, ``"DITHERED"``); ``"seed"`` Cycles'
seed. ``"shape": "plane"`` makes the object a square of side 2 in the plane z = 0
facing the camera (a flat film patch: every pixel at normal incidence);
``"backdrop": RGB`` an emitting plane of that colour behind it (z = -2); ``"series"``
more renders of the same scene in the same Blender, ``[samples, seed, EXR path]`` each;
``"working_space"`` Blender 5's blend-file working space, set before the material is
built (the EXR is then written in it).

This file imports only ``bpy``, ``bmesh`` and the standard library.
"""

import contextlib
import io
import json
import runpy
import sys
import time

import bpy


def scene_setup(job):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if job.get("working_space"):
        bpy.ops.wm.set_working_color_space(working_space=job["working_space"], convert_colors=False)
    scene = bpy.context.scene
    world = bpy.data.worlds.new("World")
    scene.world = world
    if world.node_tree is None:
        world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (*job.get("world", (1.0, 1.0, 1.0)), 1.0)
    background.inputs["Strength"].default_value = 1.0

    import bmesh  # importable once bpy is

    mesh = bpy.data.meshes.new("Sphere")
    bm = bmesh.new()
    if job.get("shape") == "plane":
        bmesh.ops.create_grid(bm, x_segments=1, y_segments=1, size=1.0)
    else:
        bmesh.ops.create_uvsphere(bm, u_segments=256, v_segments=128, radius=1.0)
    bm.to_mesh(mesh)
    bm.free()
    if hasattr(mesh, "shade_smooth"):
        mesh.shade_smooth()
    else:
        for polygon in mesh.polygons:
            polygon.use_smooth = True
    sphere = bpy.data.objects.new("Sphere", mesh)
    scene.collection.objects.link(sphere)

    camera = bpy.data.cameras.new("Camera")
    camera.type = "ORTHO"
    camera.ortho_scale = 2.2
    camera.clip_end = 100.0
    camera_object = bpy.data.objects.new("Camera", camera)
    camera_object.location = (0.0, 0.0, 5.0)
    scene.collection.objects.link(camera_object)
    scene.camera = camera_object

    render = scene.render
    render.engine = job["engine"]
    render.resolution_x = render.resolution_y = job["size"]
    render.resolution_percentage = 100
    render.film_transparent = False
    render.filter_size = job.get("filter", 0.01)
    render.image_settings.file_format = "OPEN_EXR"
    render.image_settings.color_depth = "32"
    render.image_settings.color_mode = "RGB"
    render.filepath = job["out"]
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    if job["engine"] == "CYCLES":
        cycles = scene.cycles
        cycles.device = "CPU"
        cycles.samples = job.get("samples", 1)
        cycles.use_adaptive_sampling = False
        cycles.use_denoising = False
        cycles.filter_width = job.get("filter", 0.01)
        cycles.seed = job.get("seed", 0)
        cycles.max_bounces = 16
        cycles.transparent_max_bounces = 16
    else:
        scene.eevee.taa_render_samples = job.get("samples", 1)
    if job.get("scene") == "bubble":
        bubble_scene(scene, world)
    if job.get("backdrop") is not None:
        backdrop(job["backdrop"])
    return scene, sphere


def backdrop(colour):
    """An emitting plane of one colour behind the object (z = -2, 8 x 8)."""
    bpy.ops.mesh.primitive_plane_add(size=8.0, location=(0.0, 0.0, -2.0))
    plane = bpy.context.active_object
    material = bpy.data.materials.new("Backdrop")
    if material.node_tree is None:
        material.use_nodes = True
    tree = material.node_tree
    emission = tree.nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*colour, 1.0)
    tree.links.new(emission.outputs[0], tree.nodes["Material Output"].inputs["Surface"])
    plane.data.materials.append(material)


def bubble_scene(scene, world):
    """A checker backdrop behind the sphere and a world varying with the direction."""
    tree = world.node_tree
    coordinates = tree.nodes.new("ShaderNodeTexCoord")
    separate = tree.nodes.new("ShaderNodeSeparateXYZ")
    ramp = tree.nodes.new("ShaderNodeMapRange")
    mix = tree.nodes.new("ShaderNodeMix")
    mix.data_type = "RGBA"
    mix.inputs["A"].default_value = (0.9, 0.5, 0.2, 1.0)
    mix.inputs["B"].default_value = (0.2, 0.4, 1.2, 1.0)
    ramp.inputs["From Min"].default_value = -1.0
    tree.links.new(coordinates.outputs["Generated"], separate.inputs[0])
    tree.links.new(separate.outputs["Z"], ramp.inputs["Value"])
    tree.links.new(ramp.outputs["Result"], mix.inputs["Factor"])
    tree.links.new(mix.outputs["Result"], tree.nodes["Background"].inputs["Color"])

    bpy.ops.mesh.primitive_plane_add(size=8.0, location=(0.0, 0.0, -2.0))
    plane = bpy.context.active_object
    material = bpy.data.materials.new("Backdrop")
    if material.node_tree is None:
        material.use_nodes = True
    nodes = material.node_tree.nodes
    checker = nodes.new("ShaderNodeTexChecker")
    checker.inputs["Scale"].default_value = 8.0
    checker.inputs["Color1"].default_value = (0.8, 0.75, 0.1, 1.0)
    checker.inputs["Color2"].default_value = (0.05, 0.3, 0.6, 1.0)
    emission = nodes.new("ShaderNodeEmission")
    material.node_tree.links.new(checker.outputs["Color"], emission.inputs["Color"])
    output = nodes["Material Output"]
    material.node_tree.links.new(emission.outputs[0], output.inputs["Surface"])
    plane.data.materials.append(material)


def restructure(material, structure):
    """Rebuild the film group's closures as ``structure`` (the closure benchmark)."""
    group = next(n for n in material.node_tree.nodes if n.bl_idname == "ShaderNodeGroup")
    tree = group.node_tree
    nodes, links = tree.nodes, tree.links
    output = next(n for n in nodes if n.bl_idname == "NodeGroupOutput")
    glossy = next(n for n in nodes if n.type == "BSDF_GLOSSY" or "Glossy" in n.bl_idname)
    transparent = next(n for n in nodes if n.bl_idname == "ShaderNodeBsdfTransparent")
    r = output.inputs["Reflectance"].links[0].from_socket
    t = output.inputs["Transmittance"].links[0].from_socket
    if structure == "add":
        return
    if structure == "mix":

        def average(colour):
            value = nodes.new("ShaderNodeVectorMath")
            value.operation = "DOT_PRODUCT"
            links.new(colour, value.inputs[0])
            value.inputs[1].default_value = (1 / 3, 1 / 3, 1 / 3)
            return value.outputs["Value"]

        total = nodes.new("ShaderNodeMath")
        total.operation = "ADD"
        links.new(average(r), total.inputs[0])
        links.new(average(t), total.inputs[1])
        factor = nodes.new("ShaderNodeMath")
        factor.operation = "DIVIDE"
        links.new(average(t), factor.inputs[0])
        links.new(total.outputs[0], factor.inputs[1])
        rest = nodes.new("ShaderNodeMath")
        rest.operation = "SUBTRACT"
        rest.inputs[0].default_value = 1.0
        links.new(factor.outputs[0], rest.inputs[1])
        for colour, weight, shader in ((r, rest, glossy), (t, factor, transparent)):
            scaled = nodes.new("ShaderNodeVectorMath")
            scaled.operation = "DIVIDE"
            links.new(colour, scaled.inputs[0])
            links.new(weight.outputs[0], scaled.inputs[1])
            links.new(scaled.outputs[0], shader.inputs["Color"])
        mix = nodes.new("ShaderNodeMixShader")
        links.new(factor.outputs[0], mix.inputs["Fac"])
        links.new(glossy.outputs[0], mix.inputs[1])
        links.new(transparent.outputs[0], mix.inputs[2])
        links.new(mix.outputs[0], output.inputs["BSDF"])
        return
    raise ValueError(f"unknown structure {structure!r}")


def thickness_ramp(tree, lo, hi, scale):
    """Map Range: object x in [-1, 1] -> [lo, hi] * scale."""
    coordinates = tree.nodes.new("ShaderNodeTexCoord")
    coordinates.location = (-700, 0)
    separate = tree.nodes.new("ShaderNodeSeparateXYZ")
    separate.location = (-500, 0)
    ramp = tree.nodes.new("ShaderNodeMapRange")
    ramp.location = (-300, 0)
    ramp.clamp = False
    ramp.inputs["From Min"].default_value = -1.0
    ramp.inputs["From Max"].default_value = 1.0
    ramp.inputs["To Min"].default_value = lo * scale
    ramp.inputs["To Max"].default_value = hi * scale
    tree.links.new(coordinates.outputs["Object"], separate.inputs[0])
    tree.links.new(separate.outputs["X"], ramp.inputs["Value"])
    return ramp.outputs["Result"]


def film_material(job):
    spec = job["material"]
    lo, hi = job["thickness_um"]
    roughness = job.get("roughness", 0.0)
    if spec["kind"] == "script":
        with contextlib.redirect_stdout(io.StringIO()) as said:
            runpy.run_path(spec["script"], run_name="__main__")
        job["said"] = said.getvalue().splitlines()
        print(said.getvalue(), end="")
        material = bpy.data.materials[spec["name"]]
        tree = material.node_tree
        group = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeGroup")
        group.inputs["Roughness"].default_value = roughness
        tree.links.new(thickness_ramp(tree, lo, hi, 1.0), group.inputs["Thickness"])
        if job.get("structure"):
            restructure(material, job["structure"])
        if job.get("render_method"):
            set_render_method(material, job["render_method"])
        return material
    material = bpy.data.materials.new("Principled thin film")
    if material.node_tree is None:
        material.use_nodes = True
    tree = material.node_tree
    bsdf = tree.nodes["Principled BSDF"]
    bubble = spec["kind"] == "principled_bubble"
    base = 1.0 if bubble else 0.0
    bsdf.inputs["Base Color"].default_value = (base, base, base, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Metallic"].default_value = 0.0
    bsdf.inputs["IOR"].default_value = 1.0 if bubble else spec["ior"]
    if bubble:
        bsdf.inputs["Transmission Weight"].default_value = 1.0
    bsdf.inputs["Thin Film IOR"].default_value = spec["film_ior"]
    tree.links.new(thickness_ramp(tree, lo, hi, 1000.0), bsdf.inputs["Thin Film Thickness"])
    set_render_method(material, job.get("render_method") or "DITHERED")
    return material


def set_render_method(material, method):
    """EEVEE's render method (Blender 4.2+), or the blend mode of Blender 3.x."""
    if hasattr(material, "surface_render_method"):
        material.surface_render_method = method
    else:
        material.blend_method = {"BLENDED": "BLEND", "DITHERED": "HASHED"}[method]


def main():
    job = json.loads(open(sys.argv[1]).read())
    scene, sphere = scene_setup(job)
    sphere.data.materials.append(film_material(job))
    seconds = []
    for _ in range(job.get("runs", 1)):
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        seconds.append(time.perf_counter() - start)
    for samples, seed, out in job.get("series", ()):
        # more renders of the same scene in this Blender: (samples, seed, EXR path)
        if scene.render.engine == "CYCLES":
            scene.cycles.samples, scene.cycles.seed = samples, seed
        else:
            scene.eevee.taa_render_samples = samples
        scene.render.filepath = out
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        seconds.append(time.perf_counter() - start)
    answer = {"version": bpy.app.version_string, "seconds": seconds, "said": job.get("said", [])}
    with open(job["answer"], "w") as f:
        json.dump(answer, f)


main()
