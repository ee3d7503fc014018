#!/usr/bin/env bash
# radiant against Embree's tutorial path tracer at equal noise: how long each takes to reach the
# error the tutorial has at --spp samples per pixel. bench/embree_cornell.sh compares equal
# samples; this asks what a user waits for, a clean image.
#
# Each renderer's error is the RMS difference from its own converged render (--reference-spp),
# so only noise counts, not the few-per-mille differences between the two renderers' models.
# Both images are compared as the tutorial writes them: linear, clamped to [0, 1], 8 bits
# (radiant's EXR goes through oiiotool the same way). radiant's sample count is raised from spp/4
# in steps of spp/16 until its error is no larger than the tutorial's; then both are timed alternately,
# with the tutorial also run on radiant's watertight Embree kernel (embree_cornell_common.sh).
#
# Usage: bench/embree_cornell_noise.sh [--size 256] [--spp 64] [--reference-spp 2048] [--repeats 3] [--threads 2]
# Needs: embree-tools (pathtracer), openimageio-tools (oiiotool; scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
size=256 spp=64 reference_spp=2048 repeats=3 threads=2
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --reference-spp) reference_spp=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
command -v oiiotool >/dev/null || { echo "install openimageio-tools for oiiotool" >&2; exit 1; }
cmake --build build --target radiant -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/embree_cornell_common.sh

# radiant_ppm SPP OUT.ppm: radiant's linear render written as the tutorial writes its own.
radiant_ppm() {
  radiant_render "$size" "$1" "$work/radiant.exr"
  oiiotool "$work/radiant.exr" --clamp:min=0:max=1 -d uint8 -o "$2"
}
# oiiotool --diff exits non-zero when the images differ, which they always do here.
rms_error() { { oiiotool "$1" "$2" --diff 2>&1 || true; } | awk '/RMS error/ {print $NF}'; }

echo "references at $reference_spp spp ..." >&2
embree_render "$size" "$reference_spp" "$work/embree_reference.ppm"
radiant_ppm "$reference_spp" "$work/radiant_reference.ppm"

embree_render "$size" "$spp" "$work/embree.ppm"
embree_error=$(rms_error "$work/embree.ppm" "$work/embree_reference.ppm")
embree_render_robust "$size" "$spp" "$work/embree_robust.ppm"
robust_error=$(rms_error "$work/embree_robust.ppm" "$work/embree_reference.ppm")
step=$((spp / 16 > 0 ? spp / 16 : 1))
errors_table=""
equal_spp=""
for ((n = (spp / 4 / step > 0 ? spp / 4 / step : 1) * step; n <= 4 * spp; n += step)); do
  radiant_ppm "$n" "$work/radiant.ppm"
  error=$(rms_error "$work/radiant.ppm" "$work/radiant_reference.ppm")
  errors_table+="| radiant | $n | $error |"$'\n'
  if awk -v a="$error" -v b="$embree_error" 'BEGIN {exit !(a <= b)}'; then equal_spp=$n; break; fi
done
[[ -n $equal_spp ]] || { echo "radiant did not reach the tutorial's error within $((4 * spp)) spp" >&2; exit 1; }

embree_times=() robust_times=() radiant_times=()
for ((i = 0; i < repeats; i++)); do
  t0=$(now); embree_render "$size" "$spp" "$work/embree.ppm"; t1=$(now)
  embree_render_robust "$size" "$spp" "$work/embree_robust.ppm"; t2=$(now)
  # Each writes its own 8-bit image, as bench/embree_cornell.sh times them: the tutorial a PPM,
  # radiant a PNG (the EXR above is only for measuring the error in linear values).
  radiant_render "$size" "$equal_spp" "$work/radiant.png"; t3=$(now)
  embree_times+=("$(echo "$t1 - $t0" | bc)") robust_times+=("$(echo "$t2 - $t1" | bc)")
  radiant_times+=("$(echo "$t3 - $t2" | bc)")
done
embree_s=$(median "${embree_times[@]}") robust_s=$(median "${robust_times[@]}") radiant_s=$(median "${radiant_times[@]}")

echo "Cornell box (Embree tutorial scene), ${size}x${size}, path length 8, $threads threads;"
echo "RMS error against each renderer's own $reference_spp-spp render (linear, clamped, 8 bits)"
echo "| renderer | spp | RMS error |"
echo "|---|---|---|"
echo "| Embree tutorial pathtracer | $spp | $embree_error |"
echo "| Embree tutorial pathtracer, radiant's watertight kernel | $spp | $robust_error |"
printf '%s' "$errors_table"
awk -v es="$embree_s" -v bs="$robust_s" -v rs="$radiant_s" -v spp="$spp" -v n="$equal_spp" -v r="$repeats" 'BEGIN {
  printf "\nequal noise: radiant at %d spp, tutorial at %d spp; median of %d alternating runs\n", n, spp, r
  printf "wall time: tutorial %.2f s, tutorial on the watertight kernel %.2f s, radiant %.2f s\n", es, bs, rs
  printf "time ratio radiant / Embree tutorial at equal noise: %.2f\n", rs / es
  printf "time ratio radiant / Embree tutorial on the same watertight kernel at equal noise: %.2f\n", rs / bs
}'
