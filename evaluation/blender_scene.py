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
  its ``Thin Film Thickness`` (nm) from the same ramp.

The film thickness is ``thickness_um[0]`` at object x = -1 to ``thickness_um[1]`` at
x = +1, linear in x (the Texture Coordinate node's Object output). The answer (JSON at
``job["answer"]``): Blender's version and the seconds of each render (``runs`` of them).

This file imports only ``bpy``, ``bmesh`` and the standard library.
"""

import json
import runpy
import sys
import time

import bpy


def scene_setup(job):
    bpy.ops.wm.read_factory_settings(use_empty=True)
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
        cycles.seed = 0
        cycles.max_bounces = 16
        cycles.transparent_max_bounces = 16
    else:
        scene.eevee.taa_render_samples = job.get("samples", 1)
    return scene, sphere


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
        runpy.run_path(spec["script"], run_name="__main__")
        material = bpy.data.materials[spec["name"]]
        tree = material.node_tree
        group = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeGroup")
        group.inputs["Roughness"].default_value = roughness
        tree.links.new(thickness_ramp(tree, lo, hi, 1.0), group.inputs["Thickness"])
        return material
    material = bpy.data.materials.new("Principled thin film")
    if material.node_tree is None:
        material.use_nodes = True
    tree = material.node_tree
    bsdf = tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Metallic"].default_value = 0.0
    bsdf.inputs["IOR"].default_value = spec["ior"]
    bsdf.inputs["Thin Film IOR"].default_value = spec["film_ior"]
    tree.links.new(thickness_ramp(tree, lo, hi, 1000.0), bsdf.inputs["Thin Film Thickness"])
    return material


def main():
    job = json.loads(open(sys.argv[1]).read())
    scene, sphere = scene_setup(job)
    sphere.data.materials.append(film_material(job))
    seconds = []
    for _ in range(job.get("runs", 1)):
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        seconds.append(time.perf_counter() - start)
    answer = {"version": bpy.app.version_string, "seconds": seconds}
    with open(job["answer"], "w") as f:
        json.dump(answer, f)


main()
