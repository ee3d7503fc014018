#!/usr/bin/env python3
"""Writes the Embree tutorial's Cornell box (its OBJ/MTL) as a glTF file with the tutorial's camera
and point light, for timing radiant's glTF path against its .scene path on the same box.

Every material is glTF metallic-roughness with the MTL's Kd as base colour, metallic 0 and
roughness 1: the general model. With --lambertian each also gets KHR_materials_specular with
specularFactor 0, which makes it exactly Lambertian (radiant then uses its Lambert BSDF, as for
the .scene version's matte materials).

Coordinates stay the OBJ's (millimetres); the point light's intensity, 100000, is the tutorial's
(-pointlight 213 300 227 100000 ...), radiometric as radiant reads glTF lights.

Usage: bench/cornell_obj_to_gltf.py OBJ MTL OUT.gltf [--lambertian]
"""
import base64
import json
import math
import struct
import sys


def read_mtl(path):
    colors, name = {}, None
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "newmtl":
                name = words[1]
                colors[name] = [0.0, 0.0, 0.0]
            elif words[0] == "Kd" and name is not None:
                colors[name] = [min(1.0, float(w)) for w in words[1:4]]
    return colors


def read_obj(path):
    """Triangles per material, as lists of vertex positions (quads and polygons fanned)."""
    positions, faces, material = [], {}, None
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                positions.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "usemtl":
                material = words[1]
            elif words[0] == "f":
                # OBJ indices are 1-based, negative ones count back from the last vertex.
                corners = [int(w.split("/")[0]) for w in words[1:]]
                corners = [c - 1 if c > 0 else len(positions) + c for c in corners]
                for k in range(1, len(corners) - 1):
                    faces.setdefault(material, []).append(
                        [positions[corners[0]], positions[corners[k]], positions[corners[k + 1]]])
    return faces


def main():
    if len(sys.argv) not in (4, 5) or (len(sys.argv) == 5 and sys.argv[4] != "--lambertian"):
        sys.exit(__doc__.strip().splitlines()[-1])
    obj, mtl, out = sys.argv[1:4]
    lambertian = len(sys.argv) == 5
    colors, faces = read_mtl(mtl), read_obj(obj)
    blob, views, accessors, primitives, materials = bytearray(), [], [], [], []
    for name, triangles in faces.items():
        vertices = [p for t in triangles for p in t]
        offset = len(blob)
        for p in vertices:
            blob += struct.pack("<3f", *p)
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5126, "count": len(vertices), "type": "VEC3",
                          "min": [min(p[i] for p in vertices) for i in range(3)],
                          "max": [max(p[i] for p in vertices) for i in range(3)]})
        material = {"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": colors.get(name, [1.0, 1.0, 1.0]) + [1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}}
        if lambertian:
            material["extensions"] = {"KHR_materials_specular": {"specularFactor": 0.0}}
        materials.append(material)
        primitives.append({"attributes": {"POSITION": len(accessors) - 1}, "material": len(materials) - 1})
    # The tutorial's camera: at (278, 273, -800) looking along +z (a glTF camera looks along its
    # -z, so half a turn about y), 37 degrees vertical.
    gltf = {
        "asset": {"version": "2.0", "generator": "radiant bench/cornell_obj_to_gltf.py"},
        "extensionsUsed": ["KHR_lights_punctual"] + (["KHR_materials_specular"] if lambertian else []),
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 100000.0}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"mesh": 0},
                  {"camera": 0, "translation": [278.0, 273.0, -800.0], "rotation": [0.0, 1.0, 0.0, 0.0]},
                  {"translation": [213.0, 300.0, 227.0], "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": math.radians(37), "aspectRatio": 1.0,
                                                             "znear": 1.0}}],
        "meshes": [{"primitives": primitives}],
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    }
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)


if __name__ == "__main__":
    main()
