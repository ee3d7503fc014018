#!/usr/bin/env python3
"""Writes assets/cornell.gltf: the Cornell box from the measured Cornell data, in metres.

Source data: https://www.graphics.cornell.edu/online/box/data.html (millimetres, camera looking
along +z from (278, 273, -800), 35 mm lens on a 25 mm film: 39.3 degrees vertical fov).
Walls are Lambertian (metallic 0, KHR_materials_specular specularFactor 0: no Fresnel layer) with
the usual reflectances; the ceiling light is
an emissive quad of radiance (17, 12, 4) = emissiveFactor x KHR_materials_emissive_strength.
Run from the repository root: python3 scripts/make_cornell_gltf.py
"""
import base64
import json
import math
import struct
import sys

MM = 0.001  # the data is in millimetres; glTF uses metres

# Each surface: a list of quads (four corners, mm), with its material.
FLOOR = [[(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)]]
CEILING = [[(556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2), (0, 548.8, 0)]]
BACK = [[(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556, 548.8, 559.2)]]
GREEN = [[(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]]
RED = [[(552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2), (556, 548.8, 0)]]
# Half a millimetre below the ceiling, so the two never overlap.
LIGHT = [[(343, 548.3, 227), (343, 548.3, 332), (213, 548.3, 332), (213, 548.3, 227)]]
SHORT_BLOCK = [
    [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)],
    [(290, 0, 114), (290, 165, 114), (240, 165, 272), (240, 0, 272)],
    [(130, 0, 65), (130, 165, 65), (290, 165, 114), (290, 0, 114)],
    [(82, 0, 225), (82, 165, 225), (130, 165, 65), (130, 0, 65)],
    [(240, 0, 272), (240, 165, 272), (82, 165, 225), (82, 0, 225)],
]
TALL_BLOCK = [
    [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)],
    [(423, 0, 247), (423, 330, 247), (472, 330, 406), (472, 0, 406)],
    [(472, 0, 406), (472, 330, 406), (314, 330, 456), (314, 0, 456)],
    [(314, 0, 456), (314, 330, 456), (265, 330, 296), (265, 0, 296)],
    [(265, 0, 296), (265, 330, 296), (423, 330, 247), (423, 0, 247)],
]
ROOM_CENTRE = (278, 274, 280)

MATERIALS = [
    ("white", (0.73, 0.73, 0.73), None),
    ("red", (0.63, 0.065, 0.05), None),
    ("green", (0.14, 0.45, 0.091), None),
    ("light", (0.78, 0.78, 0.78), ((1.0, 12 / 17, 4 / 17), 17.0)),
]

SURFACES = [  # name, quads, material, faces point towards (+1) or away from (-1) the reference
    ("floor", FLOOR, 0, +1, ROOM_CENTRE),
    ("ceiling", CEILING, 0, +1, ROOM_CENTRE),
    ("back wall", BACK, 0, +1, ROOM_CENTRE),
    ("red wall", RED, 1, +1, ROOM_CENTRE),
    ("green wall", GREEN, 2, +1, ROOM_CENTRE),
    ("short block", SHORT_BLOCK, 0, -1, None),
    ("tall block", TALL_BLOCK, 0, -1, None),
    ("light", LIGHT, 3, +1, (278, 0, 280)),
]


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def normalized(v):
    length = math.sqrt(dot(v, v))
    return tuple(x / length for x in v)


def centroid(points):
    return tuple(sum(p[i] for p in points) / len(points) for i in range(3))


def surface_geometry(quads, facing, reference):
    """Flat-shaded triangles, wound counter-clockwise seen from the side the face points to."""
    solid_centre = centroid([p for quad in quads for p in quad])
    positions, normals, indices = [], [], []
    for quad in quads:
        normal = normalized(cross(sub(quad[1], quad[0]), sub(quad[2], quad[0])))
        target = reference if reference is not None else solid_centre
        if dot(normal, sub(target, centroid(quad))) * facing < 0:
            quad, normal = list(reversed(quad)), tuple(-x for x in normal)
        base = len(positions)
        positions += [tuple(x * MM for x in p) for p in quad]
        normals += [normal] * 4
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def build():
    data = bytearray()
    views, accessors, meshes, nodes = [], [], [], []

    def add_view(payload, target):
        while len(data) % 4:
            data.append(0)
        views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(payload), "target": target})
        data.extend(payload)
        return len(views) - 1

    def add_vec3(values):
        payload = b"".join(struct.pack("<3f", *v) for v in values)
        accessor = {"bufferView": add_view(payload, 34962), "componentType": 5126, "count": len(values),
                    "type": "VEC3"}
        accessor["min"] = [min(v[i] for v in values) for i in range(3)]
        accessor["max"] = [max(v[i] for v in values) for i in range(3)]
        accessors.append(accessor)
        return len(accessors) - 1

    for name, quads, material, facing, reference in SURFACES:
        positions, normals, indices = surface_geometry(quads, facing, reference)
        position_accessor = add_vec3(positions)
        normal_accessor = add_vec3(normals)
        view = add_view(struct.pack("<%dH" % len(indices), *indices), 34963)
        accessors.append({"bufferView": view, "componentType": 5123, "count": len(indices), "type": "SCALAR"})
        meshes.append({"name": name, "primitives": [{
            "attributes": {"POSITION": position_accessor, "NORMAL": normal_accessor},
            "indices": len(accessors) - 1, "material": material}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})

    # The camera looks down its -Z: half a turn about +Y makes it look along +z.
    nodes.append({"name": "camera", "camera": 0, "translation": [278 * MM, 273 * MM, -800 * MM],
                  "rotation": [0, 1, 0, 0]})
    materials = []
    for name, color, emission in MATERIALS:
        material = {"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": list(color) + [1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}
        if emission:
            factor, strength = emission
            material["emissiveFactor"] = list(factor)
            material["extensions"]["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
        materials.append(material)
    vertical_fov = 2 * math.atan(12.5 / 35)
    return {
        "asset": {"version": "2.0", "generator": "radiant scripts/make_cornell_gltf.py",
                  "copyright": "CC0 1.0; geometry from the Cornell University Program of Computer Graphics"},
        "extensionsUsed": ["KHR_materials_emissive_strength", "KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"name": "Cornell box", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [{"name": "Cornell camera", "type": "perspective",
                     "perspective": {"yfov": vertical_fov, "aspectRatio": 1.0, "znear": 0.01, "zfar": 10.0}}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(data)).decode()}],
    }


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "assets/cornell.gltf"
    with open(out, "w") as f:
        json.dump(build(), f, indent=1)
        f.write("\n")
