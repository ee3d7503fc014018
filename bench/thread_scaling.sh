#!/usr/bin/env bash
# How much a second thread buys radiant and Embree's tutorial on the tutorial's Cornell box: each
# renderer at 1 and at 2 threads, in alternating rounds (radiant 1, radiant 2, tutorial 1,
# tutorial 2). The speed-up of a round is its 1-thread time over its 2-thread time; the script
# reports min/median/max over rounds, with each run's load and CPU share (quiet_machine.sh).
#
# Usage: bench/thread_scaling.sh [--size 256] [--spp 32] [--repeats 5] [--max-load 0.5]
# Needs: embree-tools (pathtracer).
set -euo pipefail
cd "$(dirname "$0")/.."
size=256 spp=32 repeats=5 max_load=0.5
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --max-load) max_load=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
cmake --build build --target radiant -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
threads=1
source bench/embree_cornell_common.sh
source bench/quiet_machine.sh

require_quiet_machine "$max_load"
radiant_speedups=() embree_speedups=() log=""
for ((i = 0; i < repeats; i++)); do
  threads=1; timed_run radiant-1 radiant_render "$size" "$spp" "$work/r1.png"; r1=$timed_seconds r1_note=$timed_note
  threads=2; timed_run radiant-2 radiant_render "$size" "$spp" "$work/r2.png"; r2=$timed_seconds r2_note=$timed_note
  threads=1; timed_run tutorial-1 embree_render "$size" "$spp" "$work/e1.ppm"; e1=$timed_seconds e1_note=$timed_note
  threads=2; timed_run tutorial-2 embree_render "$size" "$spp" "$work/e2.ppm"; e2=$timed_seconds e2_note=$timed_note
  radiant_speedups+=("$(echo "$r1 / $r2" | bc -l)") embree_speedups+=("$(echo "$e1 / $e2" | bc -l)")
  log+="| $((i + 1)) | $r1 ($r1_note) | $r2 ($r2_note) | $e1 ($e1_note) | $e2 ($e2_note) |"$'\n'
done
echo "Cornell box (Embree tutorial scene), ${size}x${size}, $spp spp, path length 8; wall seconds"
echo "| round | radiant, 1 thread | radiant, 2 threads | tutorial, 1 thread | tutorial, 2 threads |"
echo "|---|---|---|---|---|"
printf '%s' "$log"
summarize_ratios "radiant speed-up from 1 to 2 threads" "${radiant_speedups[@]}"
summarize_ratios "tutorial speed-up from 1 to 2 threads" "${embree_speedups[@]}"
