#!/usr/bin/env bash
# radiant against Embree's own tutorial path tracer on the tutorial's Cornell box: same
# geometry and albedos (the tutorial's OBJ/MTL, included by a .scene), same camera, same point
# light, same resolution, samples and path length. Runs them alternately in one session (the
# machine is shared and noisy), prints the median wall-time ratio and each one's rays per
# second (rays counted exactly by an LD_PRELOAD shim around rtcIntersect1/rtcOccluded1), and
# the raw Embree traversal rate on the same scene as the ceiling.
#
# Usage: bench/embree_cornell.sh [--size 512] [--spp 64] [--repeats 3] [--threads 2]
# Needs: embree-tools (Debian) for /usr/bin/pathtracer; builds radiant's bench targets.
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
command -v pathtracer >/dev/null || { echo "install embree-tools for Embree's pathtracer" >&2; exit 1; }
cmake --build build --target bench_all -j2 >/dev/null

models=/usr/share/doc/embree3/models
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$models/cornell_box.obj" "$models/cornell_box.mtl" "$work/"
# The tutorial's light: -pointlight 213 300 227 100000 100000 100000, radiance I/d^2 in its units.
# A .scene light color C (0-255 scale) is intensity pi*C/255 (docs/scene-format.md), so
# C = 100000 * 255 / pi; attenuation 0 0 1 is the inverse square law.
cat > "$work/cornell.scene" <<SCENE
scene Embree tutorial Cornell box
@camera
position 278 273 -800
look-at 278 273 0
up 0 1 0
fov 37
@light point
color 8116902.1 8116902.1 8116902.1
position 213 300 227
attenuation 0 0 1
@mesh
file cornell_box.obj
SCENE

counter=$(pwd)/build/bench/libray_counter.so
now() { date +%s.%N; }
run_embree() {
  RAY_COUNTER_OUT="$work/embree.rays" LD_PRELOAD="$counter" pathtracer -c "$models/cornell_box.ecs" \
    --threads "$threads" --size "$size" "$size" --spp "$spp" --max-path-length 8 -o "$work/embree.ppm" >/dev/null 2>&1
}
run_radiant() {
  RAY_COUNTER_OUT="$work/radiant.rays" LD_PRELOAD="$counter" build/radiant render "$work/cornell.scene" \
    -o "$work/radiant.png" --width "$size" --height "$size" --spp "$spp" --max-depth 8 --mode path \
    --threads "$threads" --quiet
}
total_rays() { awk '{s += $2} END {print s}' "$1"; }

embree_times=() radiant_times=()
for ((i = 0; i < repeats; i++)); do
  t0=$(now); run_embree; t1=$(now); run_radiant; t2=$(now)
  embree_times+=("$(echo "$t1 - $t0" | bc)") radiant_times+=("$(echo "$t2 - $t1" | bc)")
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
embree_s=$(median "${embree_times[@]}") radiant_s=$(median "${radiant_times[@]}")
embree_rays=$(total_rays "$work/embree.rays") radiant_rays=$(total_rays "$work/radiant.rays")
raw=$(build/bench/bench_embree_raw_rays "$work/cornell.scene" --threads "$threads" --rays 20000000 | awk '/rays_per_second/ {print $2}')

awk -v es="$embree_s" -v rs="$radiant_s" -v er="$embree_rays" -v rr="$radiant_rays" -v raw="$raw" \
    -v size="$size" -v spp="$spp" -v n="$repeats" -v t="$threads" 'BEGIN {
  printf "Cornell box (Embree tutorial scene), %dx%d, %d spp, path length 8, %d threads, median of %d alternating runs\n", size, size, spp, t, n
  printf "| renderer | wall time (s) | rays traced | rays/s (M) |\n|---|---|---|---|\n"
  printf "| Embree tutorial pathtracer | %.2f | %d | %.2f |\n", es, er, er / es / 1e6
  printf "| radiant --mode path | %.2f | %d | %.2f |\n", rs, rr, rr / rs / 1e6
  printf "| raw Embree traversal (random rays, radiant accel) | | | %.2f |\n", raw / 1e6
  printf "\ntime ratio radiant / Embree tutorial: %.2f\n", rs / es
  printf "radiant rays/s as a fraction of raw traversal: %.2f\n", (rr / rs) / raw
}'
