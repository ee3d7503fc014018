#!/usr/bin/env python3
"""Material balls for the glTF material extensions, rendered by radiant and by Blender Cycles
(bench/material_balls.sh drives both).

    bench/material_balls.py write DIR      writes DIR/NAME.gltf, one file per extension
    bench/material_balls.py table DIR      reads DIR/radiant-NAME.exr and DIR/cycles-NAME.exr (R, G, B
                                           only) and prints the mean colour per ball as a Markdown table

Each file holds four UV spheres of radius 1 in a 2 x 2 grid, each with its own material (the
parameter values in BALLS), seen by an orthographic camera 4.4 units wide under a uniform
environment (the renderers' background colour), with no other light. The mean is taken over the
disk of 0.9 times each ball's radius on the image (pixels read through `oiiotool --dumpdata`:
no numpy needed).
"""
import base64
import json
import math
import re
import struct
import subprocess
import sys

SIZE_UNITS = 4.4  # the orthographic view's width and height
# name -> four (label, material) pairs, in reading order (top left, top right, bottom left, bottom right)
GREY, RED, NAVY = [0.5, 0.5, 0.5, 1], [0.8, 0.1, 0.1, 1], [0.05, 0.05, 0.2, 1]


def pbr(color, metallic, roughness, **extensions):
    material = {"pbrMetallicRoughness": {"baseColorFactor": color, "metallicFactor": metallic,
                                         "roughnessFactor": roughness}}
    if extensions:
        material["extensions"] = extensions
    return material


BALLS = {
    "specular": [
        ("black, roughness 1 (no fade)", pbr([0, 0, 0, 1], 0, 1)),
        ("grey r 0.4, specularFactor 0", pbr(GREY, 0, 0.4, KHR_materials_specular={"specularFactor": 0})),
        ("grey r 0.4, specularFactor 0.5", pbr(GREY, 0, 0.4, KHR_materials_specular={"specularFactor": 0.5})),
        ("grey r 0.4, specularFactor 1", pbr(GREY, 0, 0.4)),
    ],
    "clearcoat": [
        ("red r 0.6, no coat", pbr(RED, 0, 0.6)),
        ("coat 0.5, coat r 0.1", pbr(RED, 0, 0.6, KHR_materials_clearcoat={"clearcoatFactor": 0.5,
                                                                            "clearcoatRoughnessFactor": 0.1})),
        ("coat 1, coat r 0", pbr(RED, 0, 0.6, KHR_materials_clearcoat={"clearcoatFactor": 1})),
        ("coat 1, coat r 0.4", pbr(RED, 0, 0.6, KHR_materials_clearcoat={"clearcoatFactor": 1,
                                                                          "clearcoatRoughnessFactor": 0.4})),
    ],
    "sheen": [
        ("navy r 0.8, no sheen", pbr(NAVY, 0, 0.8)),
        ("sheen white, r 0.3", pbr(NAVY, 0, 0.8, KHR_materials_sheen={"sheenColorFactor": [1, 1, 1],
                                                                      "sheenRoughnessFactor": 0.3})),
        ("sheen orange, r 0.6", pbr(NAVY, 0, 0.8, KHR_materials_sheen={"sheenColorFactor": [1, 0.5, 0.2],
                                                                       "sheenRoughnessFactor": 0.6})),
        ("sheen grey 0.5, r 1", pbr(NAVY, 0, 0.8, KHR_materials_sheen={"sheenColorFactor": [0.5, 0.5, 0.5],
                                                                       "sheenRoughnessFactor": 1})),
    ],
    "volume": [
        ("clear glass", pbr([1, 1, 1, 1], 0, 0, KHR_materials_transmission={"transmissionFactor": 1})),
    ] + [
        ("attenuation (0.9, 0.5, 0.3) at %g" % d,
         pbr([1, 1, 1, 1], 0, 0, KHR_materials_transmission={"transmissionFactor": 1},
             KHR_materials_volume={"thicknessFactor": 1, "attenuationDistance": d,
                                   "attenuationColor": [0.9, 0.5, 0.3]}))
        for d in (4, 2, 1)
    ],
}


def sphere(rows=24, columns=48):
    """A unit UV sphere: positions (= normals) and triangle indices."""
    points, indices = [], []
    for r in range(rows + 1):
        theta = math.pi * r / rows
        for c in range(columns + 1):
            phi = 2 * math.pi * c / columns
            points.append((math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)))
    for r in range(rows):
        for c in range(columns):
            a, b = r * (columns + 1) + c, (r + 1) * (columns + 1) + c
            indices += [a, a + 1, b, a + 1, b + 1, b]
    return points, indices


def ball_centres():
    return [(-1.1, 1.1), (1.1, 1.1), (-1.1, -1.1), (1.1, -1.1)]


def write_gltf(path, materials):
    points, indices = sphere()
    data = b"".join(struct.pack("<3f", *p) for p in points)
    normals_offset = len(data)
    data += b"".join(struct.pack("<3f", *p) for p in points)
    indices_offset = len(data)
    data += b"".join(struct.pack("<I", i) for i in indices)
    used = sorted({name for m in materials for name in m.get("extensions", {})})
    document = {
        "asset": {"version": "2.0", "generator": "radiant bench/material_balls.py"},
        "extensionsUsed": used,
        "scene": 0,
        "scenes": [{"nodes": list(range(5))}],
        "nodes": [{"mesh": i, "translation": [x, y, 0]} for i, (x, y) in enumerate(ball_centres())] +
                 [{"camera": 0, "translation": [0, 0, 10]}],
        "cameras": [{"type": "orthographic",
                     "orthographic": {"xmag": SIZE_UNITS / 2, "ymag": SIZE_UNITS / 2, "znear": 0.1, "zfar": 100}}],
        "materials": materials,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": i}]}
                   for i in range(len(materials))],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(points), "type": "VEC3",
             "min": [-1, -1, -1], "max": [1, 1, 1]},
            {"bufferView": 1, "componentType": 5126, "count": len(points), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": normals_offset},
            {"buffer": 0, "byteOffset": normals_offset, "byteLength": indices_offset - normals_offset},
            {"buffer": 0, "byteOffset": indices_offset, "byteLength": len(data) - indices_offset},
        ],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }
    with open(path, "w") as f:
        json.dump(document, f)


def read_exr(path):
    """Width, height and rows top to bottom of (r, g, b), through oiiotool --dumpdata."""
    text = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True, text=True, check=True).stdout
    lines = text.splitlines()
    width, height = (int(v) for v in re.search(r"(\d+) x\s+(\d+)", lines[0]).groups())
    rows = [[None] * width for _ in range(height)]
    for line in lines[1:]:
        match = re.match(r"\s*Pixel \((\d+), (\d+)\): (.*)", line)
        if match:
            x, y = int(match.group(1)), int(match.group(2))
            rows[y][x] = tuple(float(v) for v in match.group(3).split()[:3])
    return width, height, rows


def ball_means(path):
    width, height, rows = read_exr(path)
    means = []
    for cx, cy in ball_centres():
        px, py = (cx / SIZE_UNITS + 0.5) * width, (0.5 - cy / SIZE_UNITS) * height
        radius = 0.9 * width / SIZE_UNITS
        total, n = [0.0, 0.0, 0.0], 0
        for y in range(height):
            for x in range(width):
                if (x + 0.5 - px) ** 2 + (y + 0.5 - py) ** 2 <= radius ** 2:
                    total = [t + v for t, v in zip(total, rows[y][x])]
                    n += 1
        means.append([t / n for t in total])
    return means


def table(folder):
    print("| extension | ball | radiant (R, G, B) | Cycles (R, G, B) | Cycles / radiant (mean) |")
    print("|---|---|---|---|---|")
    for name, balls in BALLS.items():
        ours, theirs = ball_means("%s/radiant-%s.exr" % (folder, name)), ball_means("%s/cycles-%s.exr" % (folder, name))
        for (label, _), a, b in zip(balls, ours, theirs):
            ratio = sum(b) / sum(a) if sum(a) > 0 else float("nan")
            print("| %s | %s | %.3f, %.3f, %.3f | %.3f, %.3f, %.3f | %.2f |" % ((name, label) + tuple(a) + tuple(b) + (ratio,)))


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("write", "table"):
        sys.exit(__doc__)
    if sys.argv[1] == "write":
        for name, balls in BALLS.items():
            write_gltf("%s/%s.gltf" % (sys.argv[2], name), [material for _, material in balls])
    else:
        table(sys.argv[2])
