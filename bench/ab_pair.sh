#!/usr/bin/env bash
# Two radiant builds against each other on Embree's tutorial Cornell box, for changes too small
# for sequential timing on this shared, noisy machine: each round runs both at once, one thread
# each on its own core, so both see the same background load; which one starts first alternates.
# Prints each round's CPU seconds (A/B) and the median ratio B/A. An A/A run shows the noise:
# rounds spread about ±5%, medians of 10 rounds within about 1%.
#
# Each is pinned to its own core (taskset), and the cores swap every round, so that a fixed
# difference between the cores cancels in the geometric mean of the ratios over an even number
# of rounds (printed too). On a 2-core VM one core can run the same work at 3.1 s and the other
# at 4.0 s, and which core is slow can change between rounds: such noise only averages out. Changes of a few percent are better measured in
# instructions (docs/performance.md, "How to measure an instruction count").
#
# Usage: bench/ab_pair.sh BINARY_A BINARY_B [--rounds 10] [--size 256] [--spp 32]
#        [--scene cornell.scene|cornell.gltf|cornell-lambertian.gltf|cornell-textured.gltf|cornell-glass.gltf]
#        [--file SCENE]
#        [--flags "RADIANT FLAGS"] [--mode path|naive|whitted]
# (--file: any scene file instead of the tutorial's box, rendered at --size x --size, e.g.
# assets/many-lights.scene for the light BVH's descent. --flags: more flags for both renders,
# e.g. "--env sky.exr" to light a model by an environment map. --mode: the integrator, path
# unless given.)
# Needs: embree-tools (the tutorial's scene).
set -euo pipefail
(($# >= 2)) || { echo "usage: $0 BINARY_A BINARY_B [--rounds N] [--size N] [--spp N]" >&2; exit 2; }
binary_a=$(realpath "$1") binary_b=$(realpath "$2")
shift 2
cd "$(dirname "$0")/.."
rounds=10 size=256 spp=32 threads=1 mode=path extra_flags=()
while (($#)); do
  case $1 in
    --rounds) rounds=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --scene) radiant_scene=$2; shift 2 ;;
    --file) scene_file=$(realpath "$2"); shift 2 ;;
    --flags) read -r -a extra_flags <<<"$2"; shift 2 ;;
    --mode) mode=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/embree_cornell_common.sh
source bench/quiet_machine.sh

# cpu_seconds CORE BINARY OUT_FILE: the render's user CPU time on CORE, written to OUT_FILE.
cpu_seconds() {
  local TIMEFORMAT=%U core=$1
  shift
  { time taskset -c "$core" "$1" render "${scene_file:-$work/${radiant_scene:-cornell.scene}}" -o "$2.png" --width "$size" --height "$size" --spp "$spp" \
      --max-depth 8 --mode "$mode" --threads "$threads" --quiet "${extra_flags[@]}" >/dev/null; } 2>"$2"
}
ratios=()
for ((i = 0; i < rounds; i++)); do
  if ((i % 2)); then
    cpu_seconds 0 "$binary_b" "$work/b" & cpu_seconds 1 "$binary_a" "$work/a" & wait
  else
    cpu_seconds 0 "$binary_a" "$work/a" & cpu_seconds 1 "$binary_b" "$work/b" & wait
  fi
  a=$(<"$work/a") b=$(<"$work/b")
  echo "round $((i + 1)): A $a s, B $b s"
  ratios+=("$(awk -v a="$a" -v b="$b" 'BEGIN {print b / a}')")
done
printf 'median CPU time ratio B/A over %d rounds: %.3f\n' "$rounds" "$(median "${ratios[@]}")"
printf 'geometric mean of the ratios (core speeds cancel over an even number of rounds): %.3f\n' \
  "$(geometric_mean "${ratios[@]}")"
