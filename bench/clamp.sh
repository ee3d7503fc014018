#!/usr/bin/env bash
# Firefly control (--clamp-direct, --clamp-indirect) on a small bright emitter: the Cornell box
# with its lamp shrunk to a tenth of its size and made a hundred times brighter (the same power)
# and its short block a glossy metal, so that light reaching the walls by way of the block comes
# from rare, very bright paths. At equal samples (a clamp costs no time) it prints each image's
# relative error against an unclamped converged reference (bench/equal_error.sh), and the bias
# a clamp buys: its own converged image's mean against the unclamped one's.
#
# Usage: bench/clamp.sh [--binary build/radiant] [--width 160] [--height 160] [--spp 64]
#        [--reference-spp 4096] [--threads 2]
# Needs: openimageio-tools (oiiotool).
set -euo pipefail
cd "$(dirname "$0")/.."
binary=build/radiant width=160 height=160 spp=64 reference_spp=4096 threads=2
while (($#)); do
  case $1 in
    --binary) binary=$2; shift 2 ;;
    --width) width=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --reference-spp) reference_spp=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    *) sed -n 9,10p "$0" >&2; exit 2 ;;
  esac
done
command -v oiiotool >/dev/null || { echo "install openimageio-tools for oiiotool" >&2; exit 1; }
binary=$(realpath "$binary")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/equal_error.sh

python3 - assets/cornell.gltf "$work/small-lamp.gltf" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
lamp = next(n for n in d["nodes"] if n.get("name") == "light")
box = d["accessors"][d["meshes"][lamp["mesh"]]["primitives"][0]["attributes"]["POSITION"]]
c = [(a + b) / 2 for a, b in zip(box["min"], box["max"])]
s = 0.1  # a tenth of the size about its centre (column-major: T(c) S T(-c))
lamp["matrix"] = [s, 0, 0, 0, 0, s, 0, 0, 0, 0, s, 0, c[0] * (1 - s), c[1] * (1 - s), c[2] * (1 - s), 1]
material = d["materials"][d["meshes"][lamp["mesh"]]["primitives"][0]["material"]]
material["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] *= 1 / (s * s)
d["materials"].append({"name": "glossy metal", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1],
                       "metallicFactor": 1.0, "roughnessFactor": 0.15}})
block = next(n for n in d["nodes"] if n.get("name") == "short block")
for p in d["meshes"][block["mesh"]]["primitives"]:
    p["material"] = len(d["materials"]) - 1
json.dump(d, open(sys.argv[2], "w"))
PY
scene=$work/small-lamp.gltf

render() {  # OUT.exr SEED SPP FLAGS...
  local out=$1 seed=$2 spp=$3
  shift 3
  "$binary" render "$scene" -o "$out" --width "$width" --height "$height" --mode path --seed "$seed" --spp "$spp" \
    --threads "$threads" --progress none --quiet "$@"
}
render "$work/ref1.exr" 1 "$reference_spp"
render "$work/ref2.exr" 2 "$reference_spp"
clamped_linear "$work/ref1.exr" "$work/ref1c.exr"
clamped_linear "$work/ref2.exr" "$work/ref2c.exr"
reference_own=$(reference_error "$work/ref1c.exr" "$work/ref2c.exr")
reference_mean=$(mean_value "$work/ref1.exr")

printf '%-36s %16s %28s\n' "$spp spp, $width x $height" "relative error" "bias (converged mean vs none)"
for clamps in "" "--clamp-indirect 10" "--clamp-indirect 1" "--clamp-direct 10 --clamp-indirect 1"; do
  # shellcheck disable=SC2086 # the clamp flags split into words
  render "$work/image.exr" 0 "$spp" $clamps
  clamped_linear "$work/image.exr" "$work/imagec.exr"
  error=$(own_error "$(rms_error "$work/imagec.exr" "$work/ref1c.exr")" "$reference_own")
  bias="0"
  if [[ -n $clamps ]]; then
    # shellcheck disable=SC2086
    render "$work/clamped_ref.exr" 1 "$reference_spp" $clamps
    bias=$(awk -v a="$(mean_value "$work/clamped_ref.exr")" -v b="$reference_mean" 'BEGIN {printf "%.1f%%", 100 * (a - b) / b}')
  fi
  printf '%-36s %16.4f %28s\n' "${clamps:-no clamp}" "$(awk -v e="$error" -v m="$(mean_value "$work/ref1c.exr")" 'BEGIN {print e / m}')" "$bias"
done
