#!/usr/bin/env bash
# Adaptive sampling (--noise-threshold) against uniform sampling, error per time, on three
# scenes: for each, a uniform render at --spp N and an adaptive one at --noise-threshold X (with
# --spp 8N as its ceiling), each image's relative error against a converged reference
# (bench/equal_error.sh: references on other seeds, their own error removed), and each render's
# CPU seconds (user + system: what the samples cost, whatever else shares the machine). Monte
# Carlo error goes as 1 / sqrt(time), so error x sqrt(CPU seconds) is the error at equal time:
# the last column, adaptive's over uniform's, is below 1 where adaptive wins.
#
# Usage: bench/adaptive.sh [--binary build/radiant] [--width 160] [--height 120] [--spp 64]
#        [--threshold 0.05] [--reference-spp 4096] [--threads 2]
# Needs: openimageio-tools (oiiotool).
set -euo pipefail
cd "$(dirname "$0")/.."
binary=build/radiant width=160 height=120 spp=64 threshold=0.05 reference_spp=4096 threads=2
while (($#)); do
  case $1 in
    --binary) binary=$2; shift 2 ;;
    --width) width=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --threshold) threshold=$2; shift 2 ;;
    --reference-spp) reference_spp=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    *) sed -n 10,11p "$0" >&2; exit 2 ;;
  esac
done
command -v oiiotool >/dev/null || { echo "install openimageio-tools for oiiotool" >&2; exit 1; }
binary=$(realpath "$binary")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/quiet_machine.sh
source bench/equal_error.sh

# The Cornell box (noise everywhere, darker in the corners), a room lit through its windows
# (bright sky beside dim interior), and depth of field (noise only where the image is blurred).
scenes=(assets/cornell.gltf assets/models/lit-windows.gltf assets/depth-of-field.scene)

# render SCENE OUT.exr SEED FLAGS...: sets cpu_seconds and mean_spp.
render() {
  local scene=$1 out=$2 seed=$3 before after
  shift 3
  children_cpu_seconds before
  "$binary" render "$scene" -o "$out" --width "$width" --height "$height" --mode path --seed "$seed" \
    --threads "$threads" --progress none --quiet --stats "$work/stats.json" "$@"
  children_cpu_seconds after
  cpu_seconds=$(echo "$after - $before" | bc)
  mean_spp=$(python3 -c "import json, sys; s = json.load(open(sys.argv[1])); print('%.1f' % (s['samples'] / ($width * $height)))" "$work/stats.json")
}

# relative_error IMAGE REF1 REF2: the image's RMS error over the reference's mean, the
# reference's own error removed.
relative_error() {
  clamped_linear "$1" "$work/measured.exr"
  local e r
  e=$(rms_error "$work/measured.exr" "$2")
  r=$(reference_error "$2" "$3")
  awk -v e="$(own_error "$e" "$r")" -v m="$(mean_value "$2")" 'BEGIN {printf "%.5f", e / m}'
}

printf '%-34s %26s %34s %10s\n' scene "uniform: spp, CPU s, error" "adaptive: mean spp, CPU s, error" "adaptive/uniform at equal time"
for scene in "${scenes[@]}"; do
  render "$scene" "$work/ref1.exr" 1 --spp "$reference_spp"
  render "$scene" "$work/ref2.exr" 2 --spp "$reference_spp"
  clamped_linear "$work/ref1.exr" "$work/ref1c.exr"
  clamped_linear "$work/ref2.exr" "$work/ref2c.exr"
  render "$scene" "$work/uniform.exr" 0 --spp "$spp"
  uniform_cpu=$cpu_seconds uniform_spp=$mean_spp
  uniform_error=$(relative_error "$work/uniform.exr" "$work/ref1c.exr" "$work/ref2c.exr")
  render "$scene" "$work/adaptive.exr" 0 --spp $((8 * spp)) --noise-threshold "$threshold"
  adaptive_cpu=$cpu_seconds adaptive_spp=$mean_spp
  adaptive_error=$(relative_error "$work/adaptive.exr" "$work/ref1c.exr" "$work/ref2c.exr")
  ratio=$(awk -v ea="$adaptive_error" -v ta="$adaptive_cpu" -v eu="$uniform_error" -v tu="$uniform_cpu" \
    'BEGIN {printf "%.2f", (ea * sqrt(ta)) / (eu * sqrt(tu))}')
  printf '%-34s %8s %8.2f %8.4f %12s %8.2f %8.4f %10s\n' "$scene" "$uniform_spp" "$uniform_cpu" "$uniform_error" \
    "$adaptive_spp" "$adaptive_cpu" "$adaptive_error" "$ratio"
done
