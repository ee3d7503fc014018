#!/usr/bin/env bash
# What reading a scene once buys an animation: N frames rendered by one process
# (`radiant render --frames 0-(N-1)`) against the same N frames rendered by N processes
# (`radiant render --frame f` each), in alternating rounds on one thread. Both give the same
# images (tests/cli/render_frames_test.cpp; the script checks it again in its first round). Each
# run's load average and CPU share are recorded (quiet_machine.sh); the ratio of a round is its
# N-process time over its one-process time, reported as median (min, max) over rounds.
# From the --stats of the last round: the accelerator's seconds per frame both ways (a frame of
# --frames updates the previous frame's; a process builds its own) and the render seconds (both
# ways trace the same two-level layout, so they should agree).
#
# Usage: bench/frames.sh [--scene FILE] [--floor-cells N] [--frames 24] [--fps 24] [--size 64] [--spp 4]
#                        [--repeats 5] [--max-load 0.5]
# The default scene is assets/cornell.gltf with its short block sliding 0.1 m in one second
# (written by this script); --floor-cells N lays a still, bumpy N x N grid (2 N^2 triangles) on
# its floor, so that most of the scene does not move. Any animated glTF can be given instead.
set -euo pipefail
cd "$(dirname "$0")/.."
scene="" floor_cells=0 frames=24 fps=24 size=64 spp=4 repeats=5 max_load=0.5
while (($#)); do
  case $1 in
    --scene) scene=$(realpath "$2"); shift 2 ;;
    --floor-cells) floor_cells=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --fps) fps=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --max-load) max_load=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
((frames >= 1 && repeats >= 1)) || { echo "--frames and --repeats must be at least 1" >&2; exit 2; }
cmake --build build --target radiant -j2 >/dev/null
radiant=$(realpath build/radiant)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
threads=1
source bench/quiet_machine.sh

if [ -z "$scene" ]; then
  scene=$work/cornell-slide.gltf
  python3 - assets/cornell.gltf "$scene" "$floor_cells" <<'PY'
import base64, json, math, struct, sys
document = json.load(open(sys.argv[1]))
cells = int(sys.argv[3])
if cells > 0:  # a still, bumpy grid 5 mm above the floor, as wide
    floor = next(i for i, node in enumerate(document["nodes"]) if node.get("name") == "floor")
    floor_primitive = document["meshes"][document["nodes"][floor]["mesh"]]["primitives"][0]
    box = document["accessors"][floor_primitive["attributes"]["POSITION"]]
    (x0, y0, z0), (x1, _, z1) = box["min"], box["max"]
    positions = []
    for j in range(cells + 1):
        for i in range(cells + 1):
            x, z = x0 + (x1 - x0) * i / cells, z0 + (z1 - z0) * j / cells
            positions += [x, y0 + 0.005 + 0.003 * math.sin(200 * x) * math.cos(200 * z), z]
    indices = []
    for j in range(cells):
        for i in range(cells):
            a = j * (cells + 1) + i
            indices += [a, a + cells + 1, a + 1, a + 1, a + cells + 1, a + cells + 2]
    data = struct.pack(f"<{len(positions)}f", *positions) + struct.pack(f"<{len(indices)}I", *indices)
    buffer = len(document["buffers"])
    document["buffers"].append({"byteLength": len(data),
                                "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()})
    views = len(document["bufferViews"])
    document["bufferViews"] += [{"buffer": buffer, "byteOffset": 0, "byteLength": 4 * len(positions)},
                                {"buffer": buffer, "byteOffset": 4 * len(positions), "byteLength": 4 * len(indices)}]
    accessors = len(document["accessors"])
    document["accessors"] += [
        {"bufferView": views, "componentType": 5126, "count": len(positions) // 3, "type": "VEC3",
         "min": [min(positions[k::3]) for k in range(3)], "max": [max(positions[k::3]) for k in range(3)]},
        {"bufferView": views + 1, "componentType": 5125, "count": len(indices), "type": "SCALAR"}]
    material = floor_primitive.get("material")
    primitive = {"attributes": {"POSITION": accessors}, "indices": accessors + 1}
    if material is not None:
        primitive["material"] = material
    document["meshes"].append({"name": "bumps", "primitives": [primitive]})
    document["nodes"].append({"name": "bumps", "mesh": len(document["meshes"]) - 1})
    document["scenes"][document.get("scene", 0)]["nodes"].append(len(document["nodes"]) - 1)
block = next(i for i, node in enumerate(document["nodes"]) if node.get("name") == "short block")
data = struct.pack("<2f", 0, 1) + struct.pack("<6f", 0, 0, 0, 0.1, 0, 0)
buffer = len(document["buffers"])
document["buffers"].append({"byteLength": len(data),
                            "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()})
views = len(document["bufferViews"])
document["bufferViews"] += [{"buffer": buffer, "byteOffset": 0, "byteLength": 8},
                            {"buffer": buffer, "byteOffset": 8, "byteLength": 24}]
accessors = len(document["accessors"])
document["accessors"] += [{"bufferView": views, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [1]},
                          {"bufferView": views + 1, "componentType": 5126, "count": 2, "type": "VEC3"}]
document["animations"] = [{"name": "slide", "samplers": [{"input": accessors, "output": accessors + 1}],
                           "channels": [{"sampler": 0, "target": {"node": block, "path": "translation"}}]}]
json.dump(document, open(sys.argv[2], "w"))
PY
fi
# --no-metadata: the two ways' command lines differ, and the images would record them.
flags=(--width "$size" --height "$size" --spp "$spp" --threads 1 --quiet --fps "$fps" --no-metadata)

one_process() {
  "$radiant" render "$scene" "${flags[@]}" --frames "0-$((frames - 1))" -o "$work/one/f-####.png" \
    --stats "$work/one/s-####.json"
}
many_processes() {
  for ((f = 0; f < frames; f++)); do
    "$radiant" render "$scene" "${flags[@]}" --frame "$f" -o "$(printf '%s/many/f-%04d.png' "$work" "$f")" \
      --stats "$(printf '%s/many/s-%04d.json' "$work" "$f")"
  done
}

mkdir -p "$work/one" "$work/many"
require_quiet_machine "$max_load"
ratios=() one_times=() many_times=() log=""
for ((i = 0; i < repeats; i++)); do
  timed_run one one_process; one=$timed_seconds one_note=$timed_note
  timed_run many many_processes; many=$timed_seconds many_note=$timed_note
  if ((i == 0)); then
    for ((f = 0; f < frames; f++)); do
      name=$(printf 'f-%04d.png' "$f")
      cmp -s "$work/one/$name" "$work/many/$name" || { echo "frame $f differs between the two ways" >&2; exit 1; }
    done
  fi
  ratios+=("$(echo "$many / $one" | bc -l)") one_times+=("$one") many_times+=("$many")
  log+="| $((i + 1)) | $one ($one_note) | $many ($many_note) |"$'\n'
done
echo "$(basename "$scene"): $frames frames at $fps fps, ${size}x${size}, $spp spp, 1 thread; wall seconds"
echo "| round | one process (--frames) | $frames processes (--frame) |"
echo "|---|---|---|"
printf '%s' "$log"
echo "median per frame: one process $(echo "$(median "${one_times[@]}") / $frames" | bc -l | xargs printf '%.4f') s," \
  "$frames processes $(echo "$(median "${many_times[@]}") / $frames" | bc -l | xargs printf '%.4f') s"
summarize_ratios "$frames processes / one process" "${ratios[@]}"
python3 - "$work" "$frames" <<'PY'
import json, statistics, sys
work, frames = sys.argv[1], int(sys.argv[2])
def seconds(way, phase):
    return [json.load(open(f"{work}/{way}/s-{f:04d}.json"))["seconds"][phase] for f in range(frames)]
one_build, many_build = seconds("one", "build"), seconds("many", "build")
print(f"accelerator, last round: the first frame built in {one_build[0]:.4f} s; later frames of --frames "
      f"updated in a median {statistics.median(one_build[1:] or [0]):.5f} s; a process built in a median "
      f"{statistics.median(many_build):.4f} s")
one_render, many_render = sum(seconds("one", "render")), sum(seconds("many", "render"))
print(f"render seconds, last round: one process {one_render:.4f}, {frames} processes {many_render:.4f}, "
      f"ratio {one_render / many_render:.3f}")
PY
