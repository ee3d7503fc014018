"""radiant's framing camera computed on Blender's own import, shared by the Blender bench scripts:
the front view of the meshes' bounding box (docs/cli.md, "The framing camera"), a square image,
40 degrees vertical field of view."""
import math
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which its numpy (1.24) removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool


def to_gltf(v):
    """Blender's axes (+Z up) to glTF's (+Y up), as both importers convert."""
    return Vector((v.x, v.z, -v.y))


def to_blender(v):
    return Vector((v.x, -v.z, v.y))


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


def add_framing_camera(scene):
    """Adds and selects radiant's framing camera; returns "FROM AT UP" in glTF axes for radiant's
    --look-from/--look-at/--up with --fov 40, or None when nothing was imported."""
    corners = [to_gltf(o.matrix_world @ Vector(c)) for o in scene.objects if o.type == "MESH" for c in o.bound_box]
    if not corners:
        return None
    lower = Vector([min(c[i] for c in corners) for i in range(3)])
    upper = Vector([max(c[i] for c in corners) for i in range(3)])
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
    return "%r,%r,%r %r,%r,%r %r,%r,%r" % (*position, *target, *up)


def import_and_frame(scene_path):
    """Imports SCENE_PATH (glTF, or OBJ with Blender 3.4's importer) into an empty scene, adds
    radiant's framing camera and prints "camera: FROM AT UP" for radiant's flags; returns the
    scene, or exits when nothing was imported."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if scene_path.lower().endswith(".obj"):
        bpy.ops.wm.obj_import(filepath=scene_path)
    else:
        bpy.ops.import_scene.gltf(filepath=scene_path)
    scene = bpy.context.scene
    camera = add_framing_camera(scene)
    if camera is None:
        sys.exit("no meshes imported")
    print("camera: " + camera)
    return scene
