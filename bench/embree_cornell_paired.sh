#!/usr/bin/env bash
# radiant against Embree's tutorial path tracer at equal samples, both running at once: each
# round starts the two together, one thread each on its own core, so both see the same clock
# and the same background; which one starts first alternates, and so do the cores: each is
# pinned to one (taskset) and they swap every round, so that a fixed difference between the
# cores' speeds cancels in the geometric mean of the ratios over an even number of rounds, as
# in bench/ab_pair.sh. Unpinned, a 2-core AMD EPYC VM gave the same `.scene` box
# 0.80 in some rounds and 1.22 in others; pinned, one run's tutorial took 1.97-2.24 s on core 0
# and 2.40-2.65 s on core 1. On a virtual machine whose
# effective clock drifts between runs (bench/embree_cornell.sh has seen the tutorial take 9.5 s
# and 13.9 s for the same render within an hour), this ratio is steadier than one of runs in
# turn. It measures one thread each, not the two-thread render the other benchmark times; both
# processes' whole CPU time counts (loading and building included, as in that one's wall time).
# radiant writes PNG: EXR and PPM load OpenImageIO, about 0.4 s of start-up on this machine.
#
# Usage: bench/embree_cornell_paired.sh [--rounds 10] [--size 256] [--spp 32]
#                                       [--scene cornell.scene|cornell.gltf|cornell-lambertian.gltf]
#                                       [--tutorial-kernel default|watertight]
# (--tutorial-kernel watertight: the tutorial on the triangle kernel radiant's robust scenes get,
# embree_render_robust, for a like-for-like ratio; radiant's targets are against its default.)
# Needs: embree-tools (pathtracer).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=10 size=256 spp=32 threads=1 tutorial_kernel=default
while (($#)); do
  case $1 in
    --rounds) rounds=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --scene) radiant_scene=$2; shift 2 ;;
    --tutorial-kernel) tutorial_kernel=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
case $tutorial_kernel in
  default) tutorial_render=embree_render ;;
  watertight) tutorial_render=embree_render_robust ;;
  *) echo "--tutorial-kernel: default or watertight, not $tutorial_kernel" >&2; exit 2 ;;
esac
cmake --build build --target radiant -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/embree_cornell_common.sh
source bench/quiet_machine.sh

# cpu_seconds OUT_FILE COMMAND...: the command's user + system CPU time, written to OUT_FILE.
cpu_seconds() {
  local out=$1 TIMEFORMAT='%U %S'
  shift
  { time "$@" >/dev/null; } 2>"$out.time"
  awk '{print $1 + $2}' "$out.time" >"$out"
}
tutorial() { cpu_seconds "$work/tutorial" "$tutorial_render" "$size" "$spp" "$work/tutorial.ppm"; }
radiant() { cpu_seconds "$work/radiant" radiant_render "$size" "$spp" "$work/radiant.png"; }

# on_core CORE FUNCTION: the function in a subshell pinned to CORE, whose processes inherit it.
on_core() { (taskset -pc "$1" "$BASHPID" >/dev/null && "$2"); }
ratios=()
for ((i = 0; i < rounds; i++)); do
  if ((i % 2)); then
    on_core 0 radiant & on_core 1 tutorial & wait
  else
    on_core 0 tutorial & on_core 1 radiant & wait
  fi
  t=$(<"$work/tutorial") r=$(<"$work/radiant")
  echo "round $((i + 1)): tutorial $t s, radiant $r s (CPU)"
  ratios+=("$(awk -v t="$t" -v r="$r" 'BEGIN {print r / t}')")
done
echo "Cornell box (Embree tutorial scene; radiant's file ${radiant_scene:-cornell.scene}), ${size}x${size}, $spp spp, path length 8"
summarize_ratios "CPU time ratio radiant / Embree tutorial ($tutorial_kernel kernel), one thread each, run together" "${ratios[@]}"
printf 'geometric mean of the ratios (core speeds cancel over an even number of rounds): %.3f\n' \
  "$(geometric_mean "${ratios[@]}")"
