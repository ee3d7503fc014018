"""Renders a glTF or OBJ file with Blender Cycles for bench/blender_peer.sh:

    blender -b --factory-startup -P bench/blender_peer.py -- SCENE OUT SIZE SPP MAX_DEPTH

Imports the file with Blender's own importer (glTF, or the OBJ importer of Blender 3.4), frames
the bounding box of its meshes the way radiant's framing camera does (docs/cli.md, "The framing
camera", a square image), lights it by a uniform white world (radiant's --env-color 1,1,1) plus
the file's own lights, and renders with the settings bench/blender_render.py explains (no
adaptive sampling, denoising or clamping, a one-pixel box filter, the Standard view). Prints
"camera: FROM AT UP" in glTF axes (+Y up) for radiant's --look-from/--look-at/--up and --fov 40.
"""
import math
import os
import sys

import bpy
import numpy
from mathutils import Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_like_radiant import configure_cycles  # noqa: E402

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which its numpy (1.24) removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

args = sys.argv[sys.argv.index("--") + 1:]
scene_path, out_path = args[0], args[1]
size, spp, max_depth = (int(a) for a in args[2:5])

bpy.ops.wm.read_factory_settings(use_empty=True)
if scene_path.lower().endswith(".obj"):
    bpy.ops.wm.obj_import(filepath=scene_path)
else:
    bpy.ops.import_scene.gltf(filepath=scene_path)
scene = bpy.context.scene


def to_gltf(v):
    """Blender's axes (+Z up) to glTF's (+Y up), as both importers convert."""
    return Vector((v.x, v.z, -v.y))


def to_blender(v):
    return Vector((v.x, -v.z, v.y))


corners = [to_gltf(o.matrix_world @ Vector(c)) for o in scene.objects if o.type == "MESH" for c in o.bound_box]
if not corners:
    sys.exit("no meshes imported")
lower = Vector([min(c[i] for c in corners) for i in range(3)])
upper = Vector([max(c[i] for c in corners) for i in range(3)])


def frame_box(lower, upper, fov_degrees=40.0, aspect=1.0):
    """radiant's frame_box (src/render/camera.cpp): the front view unless the side or the view from
    above shows more than twice the box's projected area; every corner in view with 5% margin."""
    center, extent = (lower + upper) * 0.5, upper - lower

    def area(d):
        return abs(d.x) * extent.y * extent.z + abs(d.y) * extent.x * extent.z + abs(d.z) * extent.x * extent.y

    toward = Vector((0, 0.25, 1)).normalized()
    best = 2 * area(toward)
    for view in (Vector((1, 0.25, 0)).normalized(), Vector((0, 1, 0.25)).normalized()):
        if area(view) > best:
            toward, best = view, area(view)
    forward = -toward
    up = forward.cross(Vector((0, 1, 0))).cross(forward).normalized()
    right = forward.cross(up)
    tan_v = math.tan(math.radians(fov_degrees) / 2)
    tan_h = tan_v * aspect
    distance = 1e-6 * max(1.0, max(abs(c) for c in center))
    for i in range(8):
        p = Vector((upper.x if i & 1 else lower.x, upper.y if i & 2 else lower.y, upper.z if i & 4 else lower.z))
        d = p - center
        needed = max(abs(d.dot(up)) / tan_v, abs(d.dot(right)) / tan_h)
        distance = max(distance, d.dot(toward) + 1.05 * needed)
    return center + toward * distance, center, up


position, target, up = frame_box(lower, upper)
camera_data = bpy.data.cameras.new("peer")
camera_data.sensor_fit = "VERTICAL"
camera_data.angle_y = math.radians(40.0)
camera_data.clip_start = 1e-4 * max((upper - lower).length, 1e-3)
camera_data.clip_end = 1e4 * max((upper - lower).length, 1e-3)
camera = bpy.data.objects.new("peer", camera_data)
scene.collection.objects.link(camera)
camera.location = to_blender(position)
direction = to_blender(target) - to_blender(position)
camera.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
scene.camera = camera
print("camera: %r,%r,%r %r,%r,%r %r,%r,%r" % (*position, *target, *up))

configure_cycles(scene, size, spp, max_depth, 0)
scene.world = bpy.data.worlds.new("white") if scene.world is None else scene.world
scene.world.use_nodes = False
scene.world.color = (1.0, 1.0, 1.0)
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_depth = "8"
scene.render.image_settings.color_mode = "RGB"  # radiant writes RGB: compared channel for channel
scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
