#!/usr/bin/env bash
# radiant against Blender Cycles (Debian's blender, headless) on the glTF Cornell box: the same
# file (assets/cornell.gltf with KHR_materials_specular factor 0 and colour 0 on every material,
# the exactly Lambertian glTF material), camera, resolution, spp and path length, CPU only.
# bench/blender_render.py sets Cycles up to do radiant's work and nothing else (no adaptive
# sampling, denoising, clamping or light culling; a one-pixel box filter; the Standard view).
#
#  1. Equal samples at --size: alternating runs; ratios against the Cycles render call (scene
#     sync, BVH and sampling, as Blender reports it, excluding Blender's start-up and glTF import)
#     and against the whole Blender process.
#  2. Equal error at --error-size: each renderer against its own --reference-spp renders on seeds
#     1 and 2 (bench/equal_error.sh), Cycles at --spp on seed 0; radiant's spp is raised until its
#     error is no larger; then both are timed alternately.
# Every run records the load and its CPU share (bench/quiet_machine.sh); ratios are per pair.
#
# Usage: bench/blender_cornell.sh [--size 512] [--spp 64] [--max-depth 8] [--repeats 5]
#          [--error-size 256] [--reference-spp 1024] [--threads 2] [--max-load 0.5]
# Needs: blender (installed here on first use, not in CI), openimageio-tools.
set -euo pipefail
cd "$(dirname "$0")/.."
size=512 spp=64 max_depth=8 repeats=5 error_size=256 reference_spp=1024 threads=2 max_load=0.5
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --max-depth) max_depth=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --error-size) error_size=$2; shift 2 ;;
    --reference-spp) reference_spp=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --max-load) max_load=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/quiet_machine.sh
source bench/equal_error.sh
command -v blender >/dev/null || install_debian_packages blender
cmake --build build --target radiant -j2 >/dev/null

# The bench's glTF: every material exactly Lambertian for both renderers.
python3 - assets/cornell.gltf "$work/cornell.gltf" <<'PY'
import json, sys
document = json.load(open(sys.argv[1]))
for material in document["materials"]:
    material.setdefault("extensions", {})["KHR_materials_specular"] = {"specularFactor": 0, "specularColorFactor": [0, 0, 0]}
document["extensionsUsed"] = sorted(set(document.get("extensionsUsed", [])) | {"KHR_materials_specular"})
json.dump(document, open(sys.argv[2], "w"))
PY

# render_cycles SIZE SPP OUT SEED: renders; sets cycles_render_seconds.
render_cycles() {
  blender -b --factory-startup -P bench/blender_render.py -- "$work/cornell.gltf" "$3" "$1" "$2" "$max_depth" "$4" \
    "$threads" >"$work/blender.log" 2>&1
  cycles_render_seconds=$(awk '/^render seconds:/ {print $3}' "$work/blender.log")
  [[ -n $cycles_render_seconds ]] || { cat "$work/blender.log" >&2; exit 1; }
}
render_radiant() {
  build/radiant render "$work/cornell.gltf" -o "$3" --width "$1" --height "$1" --spp "$2" --max-depth "$max_depth" \
    --mode path --seed "$4" --threads "$threads" --quiet
}

# time_pairs SIZE CYCLES_SPP RADIANT_SPP: alternating runs; fills log and ratio arrays.
time_pairs() {
  log="" render_ratios=() process_ratios=() cycles_times=() blender_times=() radiant_times=()
  for ((i = 0; i < repeats; i++)); do
    timed_run cycles render_cycles "$1" "$2" "$work/cycles.png" 0
    local b=$timed_seconds b_note=$timed_note c=$cycles_render_seconds
    timed_run radiant render_radiant "$1" "$3" "$work/radiant.png" 0
    local r=$timed_seconds r_note=$timed_note
    cycles_times+=("$c") blender_times+=("$b") radiant_times+=("$r")
    render_ratios+=("$(echo "$r / $c" | bc -l)") process_ratios+=("$(echo "$r / $b" | bc -l)")
    log+="| $((i + 1)) | $c | $b ($b_note) | $r ($r_note) |"$'\n'
  done
}
print_pairs() {
  echo "| pair | Cycles render s | Blender process s (load, CPU share) | radiant process s (load, CPU share) |"
  echo "|---|---|---|---|"
  printf '%s' "$log"
  echo "median: Cycles render $(median "${cycles_times[@]}") s, Blender process $(median "${blender_times[@]}") s, radiant $(median "${radiant_times[@]}") s"
  summarize_ratios "radiant / Cycles render" "${render_ratios[@]}"
  summarize_ratios "radiant / Blender process" "${process_ratios[@]}"
}

require_quiet_machine "$max_load"
time_pairs "$size" "$spp" "$spp"
echo "== equal samples: glTF Cornell box, ${size}x${size}, $spp spp, $max_depth surface interactions ($((max_depth - 1)) Cycles bounces), $threads threads"
print_pairs
cp "$work/cycles.png" "$work/cycles-equal-spp.png"
cp "$work/radiant.png" "$work/radiant-equal-spp.png"
echo "mean colour (8-bit sRGB): Cycles $(oiiotool "$work/cycles-equal-spp.png" --printstats | awk '/Stats Avg/ {print $3, $4, $5}')," \
  "radiant $(oiiotool "$work/radiant-equal-spp.png" --printstats | awk '/Stats Avg/ {print $3, $4, $5}')"
if [[ -n ${KEEP_IMAGES:-} ]]; then cp "$work/cycles-equal-spp.png" "$KEEP_IMAGES-cycles.png"; cp "$work/radiant-equal-spp.png" "$KEEP_IMAGES-radiant.png"; fi

echo "references at $reference_spp spp, ${error_size}x${error_size} ..." >&2
for seed in 1 2; do
  render_cycles "$error_size" "$reference_spp" "$work/cycles-ref$seed.exr" "$seed"
  clamped_linear "$work/cycles-ref$seed.exr" "$work/cycles-ref$seed.tif"
  render_radiant "$error_size" "$reference_spp" "$work/radiant-ref$seed.exr" "$seed"
  clamped_linear "$work/radiant-ref$seed.exr" "$work/radiant-ref$seed.tif"
done
cycles_reference_error=$(reference_error "$work/cycles-ref1.tif" "$work/cycles-ref2.tif")
radiant_reference_error=$(reference_error "$work/radiant-ref1.tif" "$work/radiant-ref2.tif")
render_cycles "$error_size" "$spp" "$work/cycles.exr" 0
clamped_linear "$work/cycles.exr" "$work/cycles.tif"
cycles_error=$(own_error "$(rms_error "$work/cycles.tif" "$work/cycles-ref1.tif")" "$cycles_reference_error")
step=$((spp / 16 > 0 ? spp / 16 : 1)) equal_spp="" errors_table=""
for ((n = step; n <= 4 * spp; n += step)); do
  render_radiant "$error_size" "$n" "$work/radiant.exr" 0
  clamped_linear "$work/radiant.exr" "$work/radiant.tif"
  error=$(own_error "$(rms_error "$work/radiant.tif" "$work/radiant-ref1.tif")" "$radiant_reference_error")
  errors_table+="| radiant | $n | $error |"$'\n'
  if awk -v a="$error" -v b="$cycles_error" 'BEGIN {exit !(a <= b)}'; then equal_spp=$n; break; fi
done
[[ -n $equal_spp ]] || { echo "radiant did not reach Cycles' error within $((4 * spp)) spp" >&2; exit 1; }
time_pairs "$error_size" "$spp" "$equal_spp"
echo
echo "== equal error: ${error_size}x${error_size}; RMS error (linear, clamped to [0, 1]) against each renderer's own"
echo "   $reference_spp-spp render, its own error removed (Cycles $cycles_reference_error, radiant $radiant_reference_error)"
echo "| renderer | spp | RMS error |"
echo "|---|---|---|"
echo "| Cycles | $spp | $cycles_error |"
printf '%s' "$errors_table"
echo "equal error: radiant at $equal_spp spp, Cycles at $spp spp"
print_pairs
