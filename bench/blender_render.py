"""Renders a glTF file with Blender Cycles the way radiant renders it (run by bench scripts):

    blender -b --factory-startup -P bench/blender_render.py -- SCENE.gltf OUT SIZE SPP MAX_DEPTH SEED THREADS \
        [env=R,G,B] [principled]

Settings that would make Cycles do different work than radiant are switched off: adaptive
sampling, denoising, clamping, light-threshold culling, the Blackman-Harris pixel filter (a
one-pixel box, as radiant's), and the Filmic view (Standard: sRGB, clamped, as radiant's PNG).
MAX_DEPTH counts surface interactions as radiant's --max-depth does, so Cycles gets
MAX_DEPTH - 1 bounces. Every non-metallic Principled BSDF becomes a Diffuse BSDF plus its emission
(see as_lambert): radiant's Lambertian glTF material, metallic 0 with KHR_materials_specular
factor 0, which Blender 3.4's importer does not read; `principled` keeps the imported Principled
BSDF instead (the material comparisons of bench/material_balls.sh). `env=R,G,B` is the world's
uniform radiance (radiant's --env-color; default black). OUT ending in
.exr is written linear, anything else as 8-bit sRGB. Prints "render seconds: S" (scene sync, BVH
and sampling, measured around the render call) for the bench script to read.
"""
import os
import sys
import time

import bpy
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_like_radiant import configure_cycles  # noqa: E402

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which its numpy (1.24) removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

args = sys.argv[sys.argv.index("--") + 1:]
scene_path, out_path = args[0], args[1]
size, spp, max_depth, seed, threads = (int(a) for a in args[2:7])
environment = next((tuple(float(c) for c in a[4:].split(",")) for a in args[7:] if a.startswith("env=")), (0, 0, 0))
keep_principled = "principled" in args[7:]

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=scene_path)
scene = bpy.context.scene
cameras = [o for o in scene.objects if o.type == "CAMERA"]
if not cameras:
    sys.exit("the glTF file has no camera")
scene.camera = cameras[0]


def as_lambert(material):
    """Replaces a non-metallic Principled BSDF by a Diffuse BSDF (Lambert at roughness 0) plus its
    emission: Blender 3.4's Principled diffuse is Burley's, whose retro-reflection makes rough
    walls up to 20% brighter than the Lambertian glTF material (metallic 0, specular 0)."""
    tree = material.node_tree
    principled = next((n for n in tree.nodes if n.type == "BSDF_PRINCIPLED"), None)
    output = next((n for n in tree.nodes if n.type == "OUTPUT_MATERIAL"), None)
    if principled is None or output is None or principled.inputs["Metallic"].default_value != 0:
        return
    diffuse = tree.nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Roughness"].default_value = 0.0
    base = principled.inputs["Base Color"]
    if base.is_linked:
        tree.links.new(base.links[0].from_socket, diffuse.inputs["Color"])
    else:
        diffuse.inputs["Color"].default_value = base.default_value
    emission = tree.nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = principled.inputs["Emission"].default_value
    emission.inputs["Strength"].default_value = principled.inputs["Emission Strength"].default_value
    add = tree.nodes.new("ShaderNodeAddShader")
    tree.links.new(diffuse.outputs["BSDF"], add.inputs[0])
    tree.links.new(emission.outputs["Emission"], add.inputs[1])
    tree.links.new(add.outputs["Shader"], output.inputs["Surface"])


for material in bpy.data.materials:
    if material.node_tree and not keep_principled:
        as_lambert(material)

configure_cycles(scene, size, spp, max_depth, seed)
scene.render.threads_mode = "FIXED"
scene.render.threads = threads
scene.render.use_persistent_data = False
scene.world = bpy.data.worlds.new("background") if scene.world is None else scene.world
scene.world.use_nodes = False
scene.world.color = environment

settings = scene.render.image_settings
if out_path.endswith(".exr"):
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
else:
    settings.file_format = "PNG"
    settings.color_depth = "8"
scene.render.filepath = out_path

start = time.perf_counter()
bpy.ops.render.render(write_still=True)
print("render seconds: %.3f" % (time.perf_counter() - start))
