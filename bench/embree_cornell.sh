#!/usr/bin/env bash
# radiant against Embree's own tutorial path tracer on the tutorial's Cornell box: same
# geometry and albedos (the tutorial's OBJ/MTL, included by a .scene), same camera, same point
# light, same resolution, samples and path length. Runs them alternately in one session (the
# machine is shared and noisy), prints the median wall-time ratio and each one's rays per
# second (rays counted exactly by an LD_PRELOAD shim around rtcIntersect1/rtcIntersect1M/rtcOccluded1,
# in one untimed run each after the timed ones: the shim's shared counter costs the tutorial, which
# calls Embree once a ray, a contended atomic a ray across threads, 13.4 s instead of 8.2 s at
# 512², 2 threads on an AMD EPYC, while radiant pays it once a stream), and
# the traversal rate of random rays in the render's own mix of closest-hit and occlusion rays
# through radiant's accelerator, for reference. A third run puts the tutorial on the watertight
# Embree kernel radiant uses (RTC_SCENE_FLAG_ROBUST; embree_cornell_common.sh), which separates
# what that kernel costs from what radiant's own code costs. Every run records the load average
# and its CPU share (bench/quiet_machine.sh); ratios are per alternating triple, min/median/max.
#
# Usage: bench/embree_cornell.sh [--size 512] [--spp 64] [--repeats 5] [--threads 2] [--max-load 0.5]
#                               [--radiant-flags "--batching all"]
#                               [--scene cornell.scene|cornell.gltf|cornell-lambertian.gltf]
# --scene picks radiant's file for the same box (embree_cornell_common.sh): the .scene (default),
# or glTF with the general metallic-roughness model or with exactly Lambertian materials.
# Needs: embree-tools (Debian) for /usr/bin/pathtracer; builds radiant's bench targets.
# bench/embree_cornell_noise.sh compares the two at equal noise instead of equal samples.
set -euo pipefail
cd "$(dirname "$0")/.."
size=512 spp=64 repeats=5 threads=2 max_load=0.5
while (($#)); do
  case $1 in
    --max-load) max_load=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --radiant-flags) radiant_flags=$2; shift 2 ;;
    --scene) radiant_scene=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
cmake --build build --target bench_all -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/embree_cornell_common.sh
source bench/quiet_machine.sh

counter=$(pwd)/build/bench/libray_counter.so
# run_X [environment...]: the timed runs pass none; the counting runs pass the shim's.
run_embree() { embree_render "$size" "$spp" "$work/embree.ppm" "$@"; }
run_embree_robust() { embree_render_robust "$size" "$spp" "$work/embree_robust.ppm" "$@"; }
run_radiant() { radiant_render "$size" "$spp" "$work/radiant.png" "$@"; }
count_rays() { "$1" RAY_COUNTER_OUT="$work/$2.rays" LD_PRELOAD="$counter"; }
total_rays() { awk '{s += $2} END {print s}' "$1"; }

require_quiet_machine "$max_load"
embree_times=() robust_times=() radiant_times=() ratios=() robust_ratios=() log=""
for ((i = 0; i < repeats; i++)); do
  timed_run tutorial run_embree; e=$timed_seconds e_note=$timed_note
  timed_run robust run_embree_robust; b=$timed_seconds b_note=$timed_note
  timed_run radiant run_radiant; r=$timed_seconds r_note=$timed_note
  embree_times+=("$e") robust_times+=("$b") radiant_times+=("$r")
  ratios+=("$(echo "$r / $e" | bc -l)") robust_ratios+=("$(echo "$r / $b" | bc -l)")
  log+="| $((i + 1)) | $e ($e_note) | $b ($b_note) | $r ($r_note) |"$'\n'
done
count_rays run_embree embree
count_rays run_embree_robust embree_robust
count_rays run_radiant radiant
embree_s=$(median "${embree_times[@]}") robust_s=$(median "${robust_times[@]}") radiant_s=$(median "${radiant_times[@]}")
embree_rays=$(total_rays "$work/embree.rays") robust_rays=$(total_rays "$work/embree_robust.rays")
radiant_rays=$(total_rays "$work/radiant.rays")
occlusion_fraction=$(awk '/occluded/ {o = $2} {s += $2} END {printf "%.4f", o / s}' "$work/radiant.rays")
raw=$(build/bench/bench_embree_raw_rays "$work/cornell.scene" --threads "$threads" --rays 20000000 \
  --occlusion-fraction "$occlusion_fraction" | awk '/rays_per_second/ {print $2}')

echo "Cornell box (Embree tutorial scene), ${size}x${size}, $spp spp, path length 8, $threads threads, $repeats alternating runs"
echo "| run | tutorial s (load, CPU share) | tutorial, watertight kernel s | radiant s |"
echo "|---|---|---|---|"
printf '%s' "$log"
echo
awk -v es="$embree_s" -v bs="$robust_s" -v rs="$radiant_s" -v er="$embree_rays" -v br="$robust_rays" \
    -v rr="$radiant_rays" 'BEGIN {
  printf "| renderer | median wall time (s) | rays traced | rays/s (M) |\n|---|---|---|---|\n"
  printf "| Embree tutorial pathtracer | %.2f | %d | %.2f |\n", es, er, er / es / 1e6
  printf "| Embree tutorial pathtracer, radiant'"'"'s watertight kernel | %.2f | %d | %.2f |\n", bs, br, br / bs / 1e6
  printf "| radiant --mode path | %.2f | %d | %.2f |\n", rs, rr, rr / rs / 1e6
}'
echo
summarize_ratios "time ratio radiant / Embree tutorial" "${ratios[@]}"
summarize_ratios "time ratio radiant / Embree tutorial on the same watertight kernel" "${robust_ratios[@]}"
awk -v raw="$raw" -v f="$occlusion_fraction" -v rr="$radiant_rays" -v rs="$radiant_s" 'BEGIN {
  printf "random incoherent rays through radiant'"'"'s accelerator, the render'"'"'s mix (%.0f%% occlusion): %.2f M rays/s;\n", 100 * f, raw / 1e6
  printf "radiant'"'"'s render traced %.2f of that rate (not a ceiling: a render'"'"'s rays are more coherent)\n", (rr / rs) / raw
}'
