#!/usr/bin/env python3
"""Writes the Embree tutorial's Cornell box (its OBJ/MTL) as a glTF file with the tutorial's camera
and point light, for timing radiant's glTF path against its .scene path on the same box.

Every material is glTF metallic-roughness with the MTL's Kd as base colour, metallic 0 and
roughness 1: the general model. With --lambertian each also gets KHR_materials_specular with
specularFactor 0, which makes it exactly Lambertian (radiant then uses its Lambert BSDF, as for
the .scene version's matte materials).

With --textured the box is textured as exported models are: every face gets planar UVs, a normal
and a tangent, and every material a checker base colour texture (times its Kd), a
metallic-roughness texture (roughness 0.35-1, metallic 0) and a normal map of gentle ripples.
The textures are small PNGs embedded in the file.

With --glass the tall block is glass instead (KHR_materials_transmission 1, roughness 0, the
default IOR 1.5), as a scene that is seen through: light reaches the floor past it by the
shadow rays' walk and by refraction.

Coordinates stay the OBJ's (millimetres); the point light's intensity, 100000, is the tutorial's
(-pointlight 213 300 227 100000 ...), radiometric as radiant reads glTF lights.

Usage: bench/cornell_obj_to_gltf.py OBJ MTL OUT.gltf [--lambertian | --textured | --glass]
"""
import base64
import json
import math
import struct
import sys
import zlib


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


def read_obj(path, glass_object=None):
    """Triangles per material, as lists of vertex positions (quads and polygons fanned); those of
    object `glass_object` under the material name "glass"."""
    positions, faces, material, in_glass = [], {}, None, False
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                positions.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "o":
                in_glass = words[1:2] == [glass_object]
            elif words[0] == "usemtl":
                material = words[1]
            elif words[0] == "f":
                # OBJ indices are 1-based, negative ones count back from the last vertex.
                corners = [int(w.split("/")[0]) for w in words[1:]]
                corners = [c - 1 if c > 0 else len(positions) + c for c in corners]
                for k in range(1, len(corners) - 1):
                    faces.setdefault("glass" if in_glass else material, []).append(
                        [positions[corners[0]], positions[corners[k]], positions[corners[k + 1]]])
    return faces


def png(width, height, channels, texel):
    """An 8-bit PNG (RGB or RGBA by `channels`) whose texel (x, y) is texel(x, y), as a data URI."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in texel(x, y)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    color_type = {3: 2, 4: 6}[channels]
    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))
    return "data:image/png;base64," + base64.b64encode(data).decode()


def textures():
    """The --textured box's images: a checker, roughness from 0.35 to 1 (G; metallic B = 0), and
    ripples as a tangent-space normal map."""
    size = 64
    def checker(x, y):
        light = (x // 8 + y // 8) % 2
        return (255, 255, 255) if light else (150, 150, 150)
    def roughness(x, y):
        return (0, int(90 + 165 * (0.5 + 0.5 * math.sin(x * 0.3) * math.cos(y * 0.2))), 0)
    def ripples(x, y):
        dx, dy = 0.25 * math.cos(x * 0.4), 0.25 * math.sin(y * 0.3)
        n = [-dx, -dy, 1.0]
        length = math.sqrt(sum(c * c for c in n))
        return tuple(int(round((c / length * 0.5 + 0.5) * 255)) for c in n)
    return [png(size, size, 3, f) for f in (checker, roughness, ripples)]


def face_frame(t):
    """A triangle's unit normal, and the two axes its planar UVs follow (a tangent along u)."""
    e1 = [t[1][i] - t[0][i] for i in range(3)]
    e2 = [t[2][i] - t[0][i] for i in range(3)]
    n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
    length = math.sqrt(sum(c * c for c in n)) or 1.0
    n = [c / length for c in n]
    major = max(range(3), key=lambda i: abs(n[i]))
    u_axis, v_axis = [a for a in range(3) if a != major]
    return n, u_axis, v_axis


def add_accessor(blob, views, accessors, values, kind, fmt):
    offset = len(blob)
    for v in values:
        blob += struct.pack(fmt, *v)
    views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset})
    accessor = {"bufferView": len(views) - 1, "componentType": 5126, "count": len(values), "type": kind}
    if kind == "VEC3":
        accessor["min"] = [min(v[i] for v in values) for i in range(3)]
        accessor["max"] = [max(v[i] for v in values) for i in range(3)]
    accessors.append(accessor)
    return len(accessors) - 1


def main():
    options = sys.argv[4:]
    if len(sys.argv) < 4 or len(options) > 1 or any(o not in ("--lambertian", "--textured", "--glass") for o in options):
        sys.exit(__doc__.strip().splitlines()[-1])
    obj, mtl, out = sys.argv[1:4]
    lambertian, textured, glass = "--lambertian" in options, "--textured" in options, "--glass" in options
    colors, faces = read_mtl(mtl), read_obj(obj, "tall_block" if glass else None)
    blob, views, accessors, primitives, materials = bytearray(), [], [], [], []
    for name, triangles in faces.items():
        vertices = [p for t in triangles for p in t]
        attributes = {"POSITION": add_accessor(blob, views, accessors, vertices, "VEC3", "<3f")}
        material = {"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": colors.get(name, [1.0, 1.0, 1.0]) + [1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}}
        if lambertian:
            material["extensions"] = {"KHR_materials_specular": {"specularFactor": 0.0}}
        if name == "glass":
            material["pbrMetallicRoughness"]["roughnessFactor"] = 0.0
            material["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": 1.0}}
        if textured:
            normals, tangents, uvs = [], [], []
            for t in triangles:
                n, u_axis, v_axis = face_frame(t)
                tangent = [0.0, 0.0, 0.0, 1.0]
                tangent[u_axis] = 1.0
                for p in t:
                    normals.append(n)
                    tangents.append(tangent)
                    uvs.append((p[u_axis] / 140.0, p[v_axis] / 140.0))  # a checker tile about 17 mm
            attributes["NORMAL"] = add_accessor(blob, views, accessors, normals, "VEC3", "<3f")
            attributes["TANGENT"] = add_accessor(blob, views, accessors, tangents, "VEC4", "<4f")
            attributes["TEXCOORD_0"] = add_accessor(blob, views, accessors, uvs, "VEC2", "<2f")
            material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
            material["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {"index": 1}
            material["normalTexture"] = {"index": 2}
        materials.append(material)
        primitives.append({"attributes": attributes, "material": len(materials) - 1})
    # The tutorial's camera: at (278, 273, -800) looking along +z (a glTF camera looks along its
    # -z, so half a turn about y), 37 degrees vertical.
    gltf = {
        "asset": {"version": "2.0", "generator": "radiant bench/cornell_obj_to_gltf.py"},
        "extensionsUsed": ["KHR_lights_punctual"] + (["KHR_materials_specular"] if lambertian else [])
                          + (["KHR_materials_transmission"] if glass else []),
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
        **({"textures": [{"source": i} for i in range(3)], "images": [{"uri": u} for u in textures()]}
           if textured else {}),
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    }
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)


if __name__ == "__main__":
    main()
