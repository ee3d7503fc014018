"""Renders a glTF file with Blender Cycles for bench/fidelity.sh:

    blender -b --factory-startup -P bench/fidelity.py -- SCENE OUT.exr SIZE SPP MAX_DEPTH SEED ENV.exr [multiscatter]

Imports the file with Blender's glTF importer, keeps the imported Principled BSDF materials, frames
the meshes with radiant's framing camera (bench/blender_framing.py), lights them by the
equirectangular map ENV.exr (seen by the camera, as radiant's --background env) plus the file's
own lights, and writes the linear image. Cycles does only radiant's work (no adaptive sampling,
denoising or clamping, a one-pixel box filter; bench/cycles_like_radiant.py). Prints
"camera: FROM AT UP" in glTF axes for radiant's --look-from/--look-at/--up and --fov 40.

With "multiscatter", every imported Principled BSDF uses Multiscatter GGX, the energy-conserving
microfacet model radiant's lobes follow; Blender 3.4's importer leaves them at single-scattering
GGX, which returns a third of the light of a rough metal head on.
"""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_framing import import_and_frame  # noqa: E402
from cycles_like_radiant import configure_cycles  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
scene_path, out_path = args[0], args[1]
size, spp, max_depth, seed = (int(a) for a in args[2:6])
env_path = args[6]
multiscatter = len(args) > 7 and args[7] == "multiscatter"

scene = import_and_frame(scene_path)
if multiscatter:
    for material in bpy.data.materials:
        for node in material.node_tree.nodes if material.node_tree else ():
            if node.type == "BSDF_PRINCIPLED":
                node.distribution = "MULTI_GGX"

configure_cycles(scene, size, spp, max_depth, seed)
world = bpy.data.worlds.new("environment")
world.use_nodes = True
nodes = world.node_tree.nodes
texture = nodes.new("ShaderNodeTexEnvironment")
texture.image = bpy.data.images.load(env_path)
texture.interpolation = "Linear"
world.node_tree.links.new(texture.outputs["Color"], nodes["Background"].inputs["Color"])
scene.world = world
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.color_mode = "RGB"
scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
