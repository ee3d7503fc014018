#!/usr/bin/env bash
# radiant against Embree's own tutorial path tracer on the tutorial's Cornell box: same
# geometry and albedos (the tutorial's OBJ/MTL, included by a .scene), same camera, same point
# light, same resolution, samples and path length. Runs them alternately in one session (the
# machine is shared and noisy), prints the median wall-time ratio and each one's rays per
# second (rays counted exactly by an LD_PRELOAD shim around rtcIntersect1/rtcOccluded1), and
# the raw Embree traversal rate on the same scene as the ceiling. A third run puts the tutorial
# on the watertight Embree kernel radiant uses (RTC_SCENE_FLAG_ROBUST; embree_cornell_common.sh),
# which separates what that kernel costs from what radiant's own code costs.
#
# Usage: bench/embree_cornell.sh [--size 512] [--spp 64] [--repeats 3] [--threads 2]
# Needs: embree-tools (Debian) for /usr/bin/pathtracer; builds radiant's bench targets.
# bench/embree_cornell_noise.sh compares the two at equal noise instead of equal samples.
set -euo pipefail
cd "$(dirname "$0")/.."
size=512 spp=64 repeats=3 threads=2
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
cmake --build build --target bench_all -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/embree_cornell_common.sh

counter=$(pwd)/build/bench/libray_counter.so
run_embree() { embree_render "$size" "$spp" "$work/embree.ppm" RAY_COUNTER_OUT="$work/embree.rays" LD_PRELOAD="$counter"; }
run_embree_robust() {
  embree_render_robust "$size" "$spp" "$work/embree_robust.ppm" RAY_COUNTER_OUT="$work/embree_robust.rays" LD_PRELOAD="$counter"
}
run_radiant() { radiant_render "$size" "$spp" "$work/radiant.png" RAY_COUNTER_OUT="$work/radiant.rays" LD_PRELOAD="$counter"; }
total_rays() { awk '{s += $2} END {print s}' "$1"; }

embree_times=() robust_times=() radiant_times=()
for ((i = 0; i < repeats; i++)); do
  t0=$(now); run_embree; t1=$(now); run_embree_robust; t2=$(now); run_radiant; t3=$(now)
  embree_times+=("$(echo "$t1 - $t0" | bc)") robust_times+=("$(echo "$t2 - $t1" | bc)")
  radiant_times+=("$(echo "$t3 - $t2" | bc)")
done
embree_s=$(median "${embree_times[@]}") robust_s=$(median "${robust_times[@]}") radiant_s=$(median "${radiant_times[@]}")
embree_rays=$(total_rays "$work/embree.rays") robust_rays=$(total_rays "$work/embree_robust.rays")
radiant_rays=$(total_rays "$work/radiant.rays")
raw=$(build/bench/bench_embree_raw_rays "$work/cornell.scene" --threads "$threads" --rays 20000000 | awk '/rays_per_second/ {print $2}')

awk -v es="$embree_s" -v bs="$robust_s" -v rs="$radiant_s" -v er="$embree_rays" -v br="$robust_rays" \
    -v rr="$radiant_rays" -v raw="$raw" \
    -v size="$size" -v spp="$spp" -v n="$repeats" -v t="$threads" 'BEGIN {
  printf "Cornell box (Embree tutorial scene), %dx%d, %d spp, path length 8, %d threads, median of %d alternating runs\n", size, size, spp, t, n
  printf "| renderer | wall time (s) | rays traced | rays/s (M) |\n|---|---|---|---|\n"
  printf "| Embree tutorial pathtracer | %.2f | %d | %.2f |\n", es, er, er / es / 1e6
  printf "| Embree tutorial pathtracer, radiant'"'"'s watertight kernel | %.2f | %d | %.2f |\n", bs, br, br / bs / 1e6
  printf "| radiant --mode path | %.2f | %d | %.2f |\n", rs, rr, rr / rs / 1e6
  printf "| raw Embree traversal (random rays, radiant accel) | | | %.2f |\n", raw / 1e6
  printf "\ntime ratio radiant / Embree tutorial: %.2f\n", rs / es
  printf "time ratio radiant / Embree tutorial on the same watertight kernel: %.2f\n", rs / bs
  printf "radiant rays/s as a fraction of raw traversal: %.2f\n", (rr / rs) / raw
}'
