"""Renders a glTF or OBJ file with Blender Cycles for bench/blender_peer.sh:

    blender -b --factory-startup -P bench/blender_peer.py -- SCENE OUT SIZE SPP MAX_DEPTH

Imports the file with Blender's own importer (glTF, or the OBJ importer of Blender 3.4), frames
the bounding box of its meshes the way radiant's framing camera does (docs/cli.md, "The framing
camera", a square image), lights it by a uniform white world (radiant's --env-color 1,1,1) plus
the file's own lights, and renders with the settings bench/blender_render.py explains (no
adaptive sampling, denoising or clamping, a one-pixel box filter, the Standard view). Prints
"camera: FROM AT UP" in glTF axes (+Y up) for radiant's --look-from/--look-at/--up and --fov 40.
"""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_framing import import_and_frame  # noqa: E402
from cycles_like_radiant import configure_cycles  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
scene_path, out_path = args[0], args[1]
size, spp, max_depth = (int(a) for a in args[2:5])

scene = import_and_frame(scene_path)

configure_cycles(scene, size, spp, max_depth, 0)
scene.world = bpy.data.worlds.new("white") if scene.world is None else scene.world
scene.world.use_nodes = False
scene.world.color = (1.0, 1.0, 1.0)
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_depth = "8"
scene.render.image_settings.color_mode = "RGB"  # radiant writes RGB: compared channel for channel
scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
