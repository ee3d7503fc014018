#!/usr/bin/env bash
# What reading a scene once buys an animation: N frames rendered by one process
# (`radiant render --frames 0-(N-1)`) against the same N frames rendered by N processes
# (`radiant render --frame f` each), in alternating rounds on one thread. Both give the same
# images (tests/cli/render_frames_test.cpp; the script checks it again in its first round). Each
# run's load average and CPU share are recorded (quiet_machine.sh); the ratio of a round is its
# N-process time over its one-process time, reported as median (min, max) over rounds.
#
# Usage: bench/frames.sh [--scene FILE] [--frames 24] [--fps 24] [--size 64] [--spp 4] [--repeats 5] [--max-load 0.5]
# The default scene is assets/cornell.gltf with its short block sliding 0.1 m in one second
# (written by this script). Any animated glTF can be given instead.
set -euo pipefail
cd "$(dirname "$0")/.."
scene="" frames=24 fps=24 size=64 spp=4 repeats=5 max_load=0.5
while (($#)); do
  case $1 in
    --scene) scene=$(realpath "$2"); shift 2 ;;
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
  python3 - assets/cornell.gltf "$scene" <<'PY'
import base64, json, struct, sys
document = json.load(open(sys.argv[1]))
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

one_process() { "$radiant" render "$scene" "${flags[@]}" --frames "0-$((frames - 1))" -o "$work/one/f-####.png"; }
many_processes() {
  for ((f = 0; f < frames; f++)); do
    "$radiant" render "$scene" "${flags[@]}" --frame "$f" -o "$(printf '%s/many/f-%04d.png' "$work" "$f")"
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
