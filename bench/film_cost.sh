#!/usr/bin/env bash
# What the exact film (fixed-point binned sums, src/film/exact_sum.h) costs against another
# build (main's double sums): instruction counts of one render under callgrind, which a busy
# machine does not disturb, and the peak resident memory per pixel of a large one-sample render,
# with and without AOV sums. Wall time needs a quiet machine: use bench/ab_pair.sh BASE NEW.
#
# Usage: bench/film_cost.sh BASE_BINARY NEW_BINARY [--size 64] [--spp 16] [--memory-size 1024]
# Needs: valgrind.
set -euo pipefail
(($# >= 2)) || { echo "usage: $0 BASE_BINARY NEW_BINARY [--size N] [--spp N] [--memory-size N]" >&2; exit 2; }
base=$(realpath "$1") new=$(realpath "$2")
shift 2
cd "$(dirname "$0")/.."
size=64 spp=16 memory_size=1024
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --memory-size) memory_size=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
command -v valgrind >/dev/null || { echo "needs valgrind (apt-get install valgrind)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=assets/cornell.gltf

# instructions BINARY: instructions executed by a one-thread path-traced render (all of it:
# loading, accelerator build, rendering, writing).
instructions() {
  valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" "$1" render "$scene" -o "$work/out.exr" \
    --width "$size" --height "$size" --spp "$spp" --mode path --max-depth 4 --threads 1 --quiet 2>"$work/valgrind.log"
  awk '/^summary:/ {print $2}' "$work/callgrind.out"
}

# peak_kib BINARY FLAGS...: peak resident memory of a one-sample render of memory_size^2 pixels.
peak_kib() {
  local binary=$1
  shift
  /usr/bin/time -f %M -o "$work/rss" "$binary" render "$scene" -o "$work/big.exr" --width "$memory_size" \
    --height "$memory_size" --spp 1 --max-depth 1 --threads 1 --quiet "$@"
  cat "$work/rss"
}

base_ir=$(instructions "$base") new_ir=$(instructions "$new")
echo "instructions, ${size}x${size} at $spp spp: base $base_ir, new $new_ir, new/base $(awk -v a="$base_ir" -v b="$new_ir" 'BEGIN {printf "%.4f", b / a}')"
pixels=$((memory_size * memory_size))
for aovs in "" "--aov albedo,normal,depth"; do
  base_kib=$(peak_kib "$base" $aovs) new_kib=$(peak_kib "$new" $aovs)
  echo "peak memory, ${memory_size}x${memory_size}${aovs:+ with $aovs}: base $base_kib KiB, new $new_kib KiB," \
    "new - base $(awk -v a="$base_kib" -v b="$new_kib" -v p="$pixels" 'BEGIN {printf "%+.1f", (b - a) * 1024 / p}') bytes per pixel"
done
echo "wall time (quiet machine only): bench/ab_pair.sh $base $new"
