#!/usr/bin/env python3
"""Writes the sample models of assets/models/ (all CC0, made by this script like an exporter would):

  checker-cube.gltf (+ .bin, checker.png)  textured cube, nearest sampler, camera, point light
  instanced-boxes.glb                      one box mesh placed by ten nodes (one mirrored), a
                                           ground, a sun and a camera, packed as GLB
  normal-mapped-quad.gltf                  a quad with an embedded normal map (no tangents: the
                                           loader generates them), a spot light and a camera
  textured-cube.obj (+ .mtl, .png)         the cube as OBJ with a map_Kd texture
  lit-windows.gltf                         a facade of 128 windows, 16 of them lit through one
                                           emission texture, over a street: no other light
  motion.gltf                              a box sliding across a ground and a box spinning
                                           beside it, for motion blur (--shutter)

Run from the repository root: python3 scripts/make_sample_models.py
"""
import base64
import json
import math
import os
import struct
import zlib

OUT = "assets/models"


# ---------------------------------------------------------------- images

def png(width, height, pixel):
    """An 8-bit RGB PNG; pixel(x, y) returns (r, g, b) in 0..255."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, payload):
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


def checker(x, y):
    light = ((x // 8) + (y // 8)) % 2 == 0
    if x < 32 and y < 32:  # a red quadrant shows which way the texture is oriented
        return (230, 80, 60) if light else (120, 30, 20)
    return (230, 230, 230) if light else (40, 40, 40)


def bumps(x, y):
    """Tangent-space normals of a grid of round bumps (8 per side), encoded as n * 0.5 + 0.5."""
    u, v = (x % 8 + 0.5) / 8 * 2 - 1, (y % 8 + 0.5) / 8 * 2 - 1
    r2 = u * u + v * v
    if r2 >= 0.8:
        n = (0.0, 0.0, 1.0)
    else:
        h = math.sqrt(1 - r2)
        n = (u / h * 0.5, -v / h * 0.5, 1.0)  # -v: image rows run down, tangent-space +y runs up
        length = math.sqrt(sum(c * c for c in n))
        n = tuple(c / length for c in n)
    return tuple(int(round((c * 0.5 + 0.5) * 255)) for c in n)


# ---------------------------------------------------------------- geometry

CUBE_FACES = [  # normal, tangent (u direction), bitangent (v direction in space, v up)
    ((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
]


def cube(half=0.5):
    """24 vertices (4 per face), counter-clockwise from outside; UVs in glTF convention (v down)."""
    positions, normals, uvs, indices = [], [], [], []
    for n, t, b in CUBE_FACES:
        base = len(positions)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            positions.append(tuple(half * (n[i] + su * t[i] + sv * b[i]) for i in range(3)))
            normals.append(n)
            uvs.append(((su + 1) / 2, 1 - (sv + 1) / 2))
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, uvs, indices


def quad(size):
    h = size / 2
    positions = [(-h, 0, h), (h, 0, h), (h, 0, -h), (-h, 0, -h)]  # in the XZ plane, facing +y
    return positions, [(0, 1, 0)] * 4, [(0, 1), (1, 1), (1, 0), (0, 0)], [0, 1, 2, 0, 2, 3]


# ---------------------------------------------------------------- transforms

def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return tuple(c / length for c in v)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def look_rotation(eye, target, up=(0, 1, 0)):
    """The quaternion (x, y, z, w) turning a node's -Z towards `target` with +Y near `up`."""
    back = normalize(tuple(e - t for e, t in zip(eye, target)))
    right = normalize(cross(up, back))
    true_up = cross(back, right)
    m = [[right[i], true_up[i], back[i]] for i in range(3)]  # columns: right, up, back
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = math.sqrt(trace + 1) * 2
        return [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4]
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = math.sqrt(1 + m[i][i] - m[j][j] - m[k][k]) * 2
    q = [0.0, 0.0, 0.0, (m[k][j] - m[j][k]) / s]
    q[i], q[j], q[k] = s / 4, (m[j][i] + m[i][j]) / s, (m[k][i] + m[i][k]) / s
    return q


# ---------------------------------------------------------------- glTF writing

class Document:
    def __init__(self):
        self.data = bytearray()
        self.gltf = {"asset": {"version": "2.0", "generator": "radiant scripts/make_sample_models.py",
                               "copyright": "CC0 1.0"},
                     "bufferViews": [], "accessors": [], "meshes": [], "nodes": [], "materials": []}

    def view(self, payload, target=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)}
        if target:
            view["target"] = target
        self.gltf["bufferViews"].append(view)
        self.data.extend(payload)
        return len(self.gltf["bufferViews"]) - 1

    def accessor(self, values, kind):
        width = {"VEC2": 2, "VEC3": 3}[kind]
        payload = b"".join(struct.pack("<%df" % width, *v) for v in values)
        accessor = {"bufferView": self.view(payload, 34962), "componentType": 5126, "count": len(values),
                    "type": kind, "min": [min(v[i] for v in values) for i in range(width)],
                    "max": [max(v[i] for v in values) for i in range(width)]}
        self.gltf["accessors"].append(accessor)
        return len(self.gltf["accessors"]) - 1

    def mesh(self, name, geometry, material):
        positions, normals, uvs, indices = geometry
        attributes = {"POSITION": self.accessor(positions, "VEC3"), "NORMAL": self.accessor(normals, "VEC3"),
                      "TEXCOORD_0": self.accessor(uvs, "VEC2")}
        view = self.view(struct.pack("<%dH" % len(indices), *indices), 34963)
        self.gltf["accessors"].append({"bufferView": view, "componentType": 5123, "count": len(indices),
                                       "type": "SCALAR"})
        self.gltf["meshes"].append({"name": name, "primitives": [{
            "attributes": attributes, "indices": len(self.gltf["accessors"]) - 1, "material": material}]})
        return len(self.gltf["meshes"]) - 1

    def material(self, name, color, roughness=0.8, **extra):
        material = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1],
                                                           "metallicFactor": 0.0, "roughnessFactor": roughness}}
        material.update(extra)
        self.gltf["materials"].append(material)
        return len(self.gltf["materials"]) - 1

    def node(self, **fields):
        self.gltf["nodes"].append(fields)
        return len(self.gltf["nodes"]) - 1

    def camera_node(self, eye, target, yfov=0.7):
        self.gltf.setdefault("cameras", []).append(
            {"name": "main", "type": "perspective", "perspective": {"yfov": yfov, "znear": 0.05, "zfar": 100}})
        return self.node(name="camera", camera=len(self.gltf["cameras"]) - 1, translation=list(eye),
                         rotation=look_rotation(eye, target))

    def light_node(self, light, eye, target=(0, 0, 0)):
        lights = self.gltf.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})["lights"]
        lights.append(light)
        self.gltf.setdefault("extensionsUsed", []).append("KHR_lights_punctual")
        return self.node(name=light["name"], translation=list(eye), rotation=look_rotation(eye, target),
                         extensions={"KHR_lights_punctual": {"light": len(lights) - 1}})

    def image(self, name, png_bytes, embed):
        self.gltf.setdefault("images", []).append(
            {"name": name, "uri": "data:image/png;base64," + base64.b64encode(png_bytes).decode()} if embed else
            {"name": name, "uri": name})
        self.gltf.setdefault("samplers", []).append({"magFilter": 9728 if "checker" in name else 9729,
                                                     "minFilter": 9987, "wrapS": 10497, "wrapT": 10497})
        self.gltf.setdefault("textures", []).append({"source": len(self.gltf["images"]) - 1,
                                                     "sampler": len(self.gltf["samplers"]) - 1})
        return len(self.gltf["textures"]) - 1

    def finish(self, roots, buffer_uri=None):
        self.gltf["scene"] = 0
        self.gltf["scenes"] = [{"nodes": roots}]
        self.gltf["buffers"] = [{"byteLength": len(self.data)}]
        if buffer_uri is not None:
            self.gltf["buffers"][0]["uri"] = buffer_uri
        self.gltf["extensionsUsed"] = sorted(set(self.gltf.get("extensionsUsed", [])))
        return self.gltf

    def glb(self, roots):
        text = json.dumps(self.finish(roots), separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        data = bytes(self.data) + b"\0" * (-len(self.data) % 4)
        body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
        return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def write(name, content):
    mode = "wb" if isinstance(content, bytes) else "w"
    with open(os.path.join(OUT, name), mode) as f:
        f.write(content)


# ---------------------------------------------------------------- the models

def checker_cube():
    doc = Document()
    texture = doc.image("checker.png", None, embed=False)
    material = doc.material("checker", (1, 1, 1), pbrMetallicRoughness={
        "baseColorTexture": {"index": texture}, "metallicFactor": 0.0, "roughnessFactor": 0.7})
    cube_node = doc.node(name="cube", mesh=doc.mesh("cube", cube(), material), rotation=[0, 0.3826834, 0, 0.9238795])
    roots = [cube_node, doc.camera_node((1.6, 1.4, 2.4), (0, 0, 0)),
             doc.light_node({"name": "bulb", "type": "point", "intensity": 20, "color": [1, 0.95, 0.9]}, (2, 3, 2))]
    write("checker-cube.gltf", json.dumps(doc.finish(roots, "checker-cube.bin"), indent=1) + "\n")
    write("checker-cube.bin", bytes(doc.data))
    write("checker.png", png(64, 64, checker))


def instanced_boxes():
    doc = Document()
    box = doc.mesh("box", cube(0.2), doc.material("orange", (0.9, 0.45, 0.1), roughness=0.5))
    ground = doc.mesh("ground", quad(6), doc.material("ground", (0.6, 0.6, 0.6)))
    boxes = [doc.node(name="box %d" % i, mesh=box, translation=[(i % 3 - 1) * 0.8, 0.2, (i // 3 - 1) * 0.8])
             for i in range(9)]
    mirrored = doc.node(name="mirrored box", mesh=box, translation=[0, 0.7, 0], scale=[-1, 1, 1])
    grid = doc.node(name="grid", children=boxes + [mirrored], rotation=[0, 0.258819, 0, 0.9659258])
    roots = [doc.node(name="ground", mesh=ground), grid, doc.camera_node((2.5, 2.2, 3.0), (0, 0.2, 0)),
             doc.light_node({"name": "sun", "type": "directional", "intensity": 3}, (1, 3, 2))]
    write("instanced-boxes.glb", doc.glb(roots))


def normal_mapped_quad():
    doc = Document()
    normal_map = doc.image("bumps.png", png(64, 64, bumps), embed=True)
    material = doc.material("bumpy", (0.8, 0.8, 0.8), roughness=0.6, normalTexture={"index": normal_map})
    plane = doc.node(name="quad", mesh=doc.mesh("quad", quad(2), material))
    light = {"name": "spot", "type": "spot", "intensity": 30, "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}}
    roots = [plane, doc.camera_node((0, 1.8, 1.8), (0, 0, 0)), doc.light_node(light, (1.5, 1.5, 0))]
    gltf = doc.finish(roots, "data:application/octet-stream;base64," + base64.b64encode(bytes(doc.data)).decode())
    write("normal-mapped-quad.gltf", json.dumps(gltf, indent=1) + "\n")


def textured_cube_obj():
    positions, normals, uvs, indices = cube()
    lines = ["# Textured cube, CC0 (radiant scripts/make_sample_models.py)", "mtllib textured-cube.mtl", "o cube"]
    lines += ["v %g %g %g" % p for p in positions]
    lines += ["vt %g %g" % (u, 1 - v) for u, v in uvs]  # OBJ's v runs up
    lines += ["vn %g %g %g" % n for n in normals]
    lines += ["g cube", "usemtl checker"]
    for face in range(6):
        corners = [face * 4 + k + 1 for k in range(4)]
        lines.append("f " + " ".join("%d/%d/%d" % (c, c, c) for c in corners))
    write("textured-cube.obj", "\n".join(lines) + "\n")
    write("textured-cube.mtl", "# CC0\nnewmtl checker\nKa 0 0 0\nKd 1 1 1\nKs 0.2 0.2 0.2\nNs 32\nillum 2\n"
                               "map_Kd textured-cube.png\n")
    write("textured-cube.png", png(64, 64, checker))


def window_light(x, y):
    """The facade's emission texture: 16 x 8 cells of 4 x 4 texels; a lit window is the inner
    2 x 2 texels of its cell, warm white, and everything else (wall, dark windows) is black."""
    column, row = x // 4, y // 4
    inner = 1 <= x % 4 <= 2 and 1 <= y % 4 <= 2
    return (255, 200, 120) if inner and (column, row) in LIT_WINDOWS else (0, 0, 0)


# One window in eight lit, scattered by a fixed linear congruential sequence.
LIT_WINDOWS = set()
_state = 12345
while len(LIT_WINDOWS) < 16:
    _state = (_state * 1103515245 + 12345) % 2 ** 31
    LIT_WINDOWS.add(((_state >> 8) % 16, (_state >> 16) % 8))


def facade():
    """16 x 8 one-metre cells in the XY plane (x from -8 to 8, y from 0 to 8), facing +z; cell
    (column, row) maps onto its 4 x 4 texels of the 64 x 32 texture (row 0 at the top)."""
    positions, normals, uvs, indices = [], [], [], []
    for row in range(8):
        for column in range(16):
            base = len(positions)
            x0, y1 = column - 8, 8 - row
            for dx, dy in ((0, -1), (1, -1), (1, 0), (0, 0)):
                positions.append((x0 + dx, y1 + dy, 0))
                normals.append((0, 0, 1))
                uvs.append(((column + dx) / 16, (row - dy) / 8))
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, uvs, indices


def lit_windows():
    doc = Document()
    emission = doc.image("windows.png", png(64, 32, window_light), embed=True)
    wall = doc.material("windows", (0.1, 0.1, 0.1), emissiveFactor=[1, 1, 1],
                        emissiveTexture={"index": emission},
                        extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 20}})
    doc.gltf.setdefault("extensionsUsed", []).append("KHR_materials_emissive_strength")
    street = doc.material("street", (0.5, 0.5, 0.5))
    street_quad = ([(-10, 0, 14), (10, 0, 14), (10, 0, 0), (-10, 0, 0)], [(0, 1, 0)] * 4,
                   [(0, 1), (1, 1), (1, 0), (0, 0)], [0, 1, 2, 0, 2, 3])
    roots = [doc.node(name="facade", mesh=doc.mesh("facade", facade(), wall)),
             doc.node(name="street", mesh=doc.mesh("street", street_quad, street)),
             doc.camera_node((0, 6, 14), (0, 1, 2), yfov=0.9)]
    gltf = doc.finish(roots, "data:application/octet-stream;base64," + base64.b64encode(bytes(doc.data)).decode())
    write("lit-windows.gltf", json.dumps(gltf, indent=1) + "\n")


def turntable():
    doc = Document()
    orange = doc.material("orange", (0.9, 0.45, 0.1), roughness=0.5)
    blue = doc.material("blue", (0.1, 0.3, 0.9), roughness=0.5)
    box = doc.mesh("box", cube(0.5), orange)
    # KHR_materials_variants: the box in orange (the default) or in blue.
    doc.gltf["meshes"][box]["primitives"][0]["extensions"] = {"KHR_materials_variants": {"mappings": [
        {"material": orange, "variants": [0]}, {"material": blue, "variants": [1]}]}}
    doc.gltf["extensions"] = {"KHR_materials_variants": {"variants": [{"name": "orange"}, {"name": "blue"}]}}
    doc.gltf["extensionsUsed"] = ["KHR_materials_variants"]
    ground = doc.mesh("ground", quad(4), doc.material("ground", (0.6, 0.6, 0.6)))
    box_node = doc.node(name="box", mesh=box, translation=[0, 0.5, 0])
    # "spin": one turn about +y in 2 seconds, as five keys a quarter turn apart.
    times = [0.0, 0.5, 1.0, 1.5, 2.0]
    turns = [[0, math.sin(math.pi * t / 2), 0, math.cos(math.pi * t / 2)] for t in times]
    accessors = doc.gltf["accessors"]
    accessors.append({"bufferView": doc.view(struct.pack("<5f", *times)), "componentType": 5126, "count": 5,
                      "type": "SCALAR", "min": [0.0], "max": [2.0]})
    accessors.append({"bufferView": doc.view(b"".join(struct.pack("<4f", *q) for q in turns)), "componentType": 5126,
                      "count": 5, "type": "VEC4"})
    doc.gltf["animations"] = [{"name": "spin", "samplers": [
        {"input": len(accessors) - 2, "output": len(accessors) - 1, "interpolation": "LINEAR"}],
        "channels": [{"sampler": 0, "target": {"node": box_node, "path": "rotation"}}]}]
    roots = [doc.node(name="ground", mesh=ground), box_node, doc.camera_node((2.4, 2.2, 3.2), (0, 0.4, 0)),
             doc.light_node({"name": "sun", "type": "directional", "intensity": 3}, (1, 3, 2))]
    gltf = doc.finish(roots, "data:application/octet-stream;base64," + base64.b64encode(bytes(doc.data)).decode())
    write("turntable.gltf", json.dumps(gltf, indent=1) + "\n")


def keyed(doc, times, values, width):
    """Adds the input and output accessors of one animation sampler; returns the sampler."""
    accessors = doc.gltf["accessors"]
    accessors.append({"bufferView": doc.view(struct.pack("<%df" % len(times), *times)), "componentType": 5126,
                      "count": len(times), "type": "SCALAR", "min": [min(times)], "max": [max(times)]})
    accessors.append({"bufferView": doc.view(b"".join(struct.pack("<%df" % width, *v) for v in values)),
                      "componentType": 5126, "count": len(values), "type": {3: "VEC3", 4: "VEC4"}[width]})
    return {"input": len(accessors) - 2, "output": len(accessors) - 1, "interpolation": "LINEAR"}


def motion():
    doc = Document()
    ground = doc.mesh("ground", quad(6), doc.material("ground", (0.6, 0.6, 0.6)))
    box = doc.mesh("box", cube(0.4), doc.material("red", (0.85, 0.15, 0.1), roughness=0.5))
    spinner = doc.mesh("spinner", cube(0.4), doc.material("blue", (0.1, 0.3, 0.9), roughness=0.5))
    slider = doc.node(name="slider", mesh=box, translation=[-1.5, 0.4, 0.8])
    spinning = doc.node(name="spinning", mesh=spinner, translation=[0, 0.4, -1])
    # "move": the slider crosses 3 units in a second; the spinner turns once about +y meanwhile.
    times = [0.0, 0.25, 0.5, 0.75, 1.0]
    turns = [[0, math.sin(math.pi * t), 0, math.cos(math.pi * t)] for t in times]
    doc.gltf["animations"] = [{"name": "move", "samplers": [
        keyed(doc, [0.0, 1.0], [[-1.5, 0.4, 0.8], [1.5, 0.4, 0.8]], 3), keyed(doc, times, turns, 4)],
        "channels": [{"sampler": 0, "target": {"node": slider, "path": "translation"}},
                     {"sampler": 1, "target": {"node": spinning, "path": "rotation"}}]}]
    roots = [doc.node(name="ground", mesh=ground), slider, spinning, doc.camera_node((0, 3, 4.5), (0, 0.3, 0)),
             doc.light_node({"name": "sun", "type": "directional", "intensity": 3}, (1, 3, 2))]
    gltf = doc.finish(roots, "data:application/octet-stream;base64," + base64.b64encode(bytes(doc.data)).decode())
    write("motion.gltf", json.dumps(gltf, indent=1) + "\n")


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    checker_cube()
    instanced_boxes()
    normal_mapped_quad()
    textured_cube_obj()
    lit_windows()
    turntable()
    motion()
