#!/usr/bin/env python3
"""Writes a glTF of N instances of one small box by EXT_mesh_gpu_instancing, for measuring what
an instance costs (docs/gltf-obj.md, "GPU instancing"):

    bench/gpu_instances.py --count 1000000 --out /tmp/big.gltf
    /usr/bin/time -v build/radiant render /tmp/big.gltf -o /tmp/x.png --width 128 --height 128 --spp 4

The boxes stand on a square grid, each turned about y and scaled a little (every instance has
its own T, R and S), the box's 12 triangles stored once; the buffer is a .bin beside the file."""
import argparse
import json
import math
import os
import struct


def box():
    positions, indices = [], []
    faces = [((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
             ((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1))]
    for n, u, v in faces:
        base = len(positions)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            positions.append(tuple(0.4 * (n[i] + su * u[i] + sv * v[i]) for i in range(3)))
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, indices


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=1000000)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    positions, indices = box()
    side = math.ceil(math.sqrt(args.count))
    translations, rotations, scales = bytearray(), bytearray(), bytearray()
    for i in range(args.count):
        x, z = i % side, i // side
        angle = 0.5 * ((i * 7919) % 360) * math.pi / 180
        s = 0.8 + 0.4 * ((i * 104729) % 100) / 100
        translations += struct.pack("<3f", x - side / 2, 0, z - side / 2)
        rotations += struct.pack("<4f", 0, math.sin(angle), 0, math.cos(angle))
        scales += struct.pack("<3f", s, s, s)
    chunks = [b"".join(struct.pack("<3f", *p) for p in positions), struct.pack("<%dH" % len(indices), *indices),
              bytes(translations), bytes(rotations), bytes(scales)]
    binary, views = bytearray(), []
    for chunk in chunks:
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(chunk)})
        binary += chunk + b"\0" * (-len(chunk) % 4)
    n = args.count
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
         "min": [-0.4] * 3, "max": [0.4] * 3},
        {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        {"bufferView": 2, "componentType": 5126, "count": n, "type": "VEC3"},
        {"bufferView": 3, "componentType": 5126, "count": n, "type": "VEC4"},
        {"bufferView": 4, "componentType": 5126, "count": n, "type": "VEC3"},
    ]
    bin_name = os.path.splitext(os.path.basename(args.out))[0] + ".bin"
    document = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["EXT_mesh_gpu_instancing"],
        "buffers": [{"uri": bin_name, "byteLength": len(binary)}],
        "bufferViews": views,
        "accessors": accessors,
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.5, 0.3, 1], "metallicFactor": 0}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "nodes": [{"mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {
            "attributes": {"TRANSLATION": 2, "ROTATION": 3, "SCALE": 4}}}}],
        "scenes": [{"nodes": [0]}],
    }
    with open(args.out, "w") as out:
        json.dump(document, out)
    with open(os.path.join(os.path.dirname(os.path.abspath(args.out)), bin_name), "wb") as out:
        out.write(binary)


if __name__ == "__main__":
    main()
