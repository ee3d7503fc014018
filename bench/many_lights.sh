#!/usr/bin/env bash
# Light BVH against power-proportional light selection at equal time, on the bundled many-lights
# scene (assets/many-lights.scene: 400 small emissive quads over a floor).
#
# Both samplers render for the same wall time (--time-limit, which counts from before loading);
# each image's relative error is its RMS difference from a converged reference, with the
# reference's own error removed (bench/equal_error.sh: references on seeds 1 and 2, the measured
# renders on seed 0), divided by the reference's mean. Images are compared as linear values
# clamped to [0, 1]. Runs alternate power, BVH, power, BVH...; each pair gives one error ratio
# (power / BVH: how many times lower the BVH's error is), and every run records the load and its
# CPU share (bench/quiet_machine.sh).
#
# Two errors are reported: over the whole image, and over the lit surfaces alone (the pixels that
# see no lamp: those where the reference is saturated, grown by one pixel to take the lamps'
# partly covered edges). The lamps seen directly are the same for both samplers (emission is
# not light-sampled), but their edges' antialiasing noise is most of the whole image's error at
# 16 spp; the lit surfaces show what light selection changes.
#
# Before the timing, both render --equal-spp samples per pixel (the scene's own 16 by default):
# the error at equal samples, which is not a timing and holds on any machine.
#
# Usage: bench/many_lights.sh [--width 320] [--height 240] [--seconds 10] [--reference-spp 4096]
#                             [--equal-spp 16] [--repeats 3] [--threads 2] [--max-load 0.5]
#                             [--binary build/radiant] [--paired] [--references DIR]
# (--paired: each round renders both samplers at once, one thread each, each pinned to its own core
# and the cores swapped every round, as bench/ab_pair.sh does, so that both see the same machine:
# on a virtual machine whose speed drifts between one 10-s render and the next, alternating runs
# measure the drift as much as the samplers. Use an even --repeats, so each sampler has each core
# equally often.
# --references: keep the two references in DIR and reuse them when they are there for this size
# and sample count, so that two builds are measured against the same ones (and the 4096-spp
# renders are made once).
# --binary: another build of radiant, e.g. a copy of the build before a change, to measure it
# the same way in the same hour; without it build/radiant is brought up to date first.)
# A smoke test that it works (seconds, not a measurement):
#   bench/many_lights.sh --width 32 --height 24 --seconds 0.5 --reference-spp 64 --repeats 1 --max-load 99
# Needs: openimageio-tools (oiiotool; scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
width=320 height=240 seconds=10 reference_spp=4096 equal_spp=16 repeats=3 threads=2 max_load=0.5 binary= paired=0 references=
while (($#)); do
  case $1 in
    --width) width=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --reference-spp) reference_spp=$2; shift 2 ;;
    --equal-spp) equal_spp=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --max-load) max_load=$2; shift 2 ;;
    --binary) binary=$2; shift 2 ;;
    --paired) paired=1; shift ;;
    --references) references=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
command -v oiiotool >/dev/null || { echo "install openimageio-tools for oiiotool" >&2; exit 1; }
if [[ -z $binary ]]; then
  cmake --build build --target radiant -j2 >/dev/null
  binary=build/radiant
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/quiet_machine.sh
source bench/equal_error.sh
scene=assets/many-lights.scene

# render SAMPLER SEED OUT.exr [FLAGS...]: the scene as the file sets it (path, depth 3), at our size.
render() {
  "$binary" render "$scene" -o "$3" --width "$width" --height "$height" --light-sampler "$1" --seed "$2" \
    --threads "$threads" --quiet "${@:4}"
}

for seed in 1 2; do
  kept=${references:+$references/reference$seed-${width}x$height-$reference_spp.exr}
  if [[ -n $kept && -f $kept ]]; then
    cp "$kept" "$work/reference$seed.exr"
    continue
  fi
  echo "reference $seed at $reference_spp spp ..." >&2
  render bvh "$seed" "$work/reference$seed.exr" --spp "$reference_spp"
  [[ -z $kept ]] || { mkdir -p "$references" && cp "$work/reference$seed.exr" "$kept"; }
done
clamped_linear "$work/reference1.exr" "$work/reference1c.exr"
clamped_linear "$work/reference2.exr" "$work/reference2c.exr"
reference_error=$(reference_error "$work/reference1c.exr" "$work/reference2c.exr")
level=$(mean_value "$work/reference1c.exr")
# keep.exr: 1 on the lit surfaces, 0 on and next to a lamp seen directly.
oiiotool "$work/reference1c.exr" --maxchan --subc 0.999 --mulc 1e6 --clamp:min=0:max=1 --dilate 3x3 \
  --mulc -1 --addc 1 --ch 0,0,0 --chnames R,G,B -o "$work/keep.exr"
lit_share=$(mean_value "$work/keep.exr")
oiiotool "$work/reference1c.exr" "$work/keep.exr" --mul -o "$work/reference1m.exr"
oiiotool "$work/reference2c.exr" "$work/keep.exr" --mul -o "$work/reference2m.exr"
reference_error_lit=$(reference_error "$work/reference1m.exr" "$work/reference2m.exr")
level_lit=$(mean_value "$work/reference1m.exr")

# relative_error_of IMAGE.exr: sets relative and relative_lit (see above). The masked images'
# RMS and mean are over every pixel, zeros included: RMS / sqrt(share) and mean / share are
# those of the lit pixels.
relative_error_of() {
  clamped_linear "$1" "$work/clamped.exr"
  oiiotool "$work/clamped.exr" "$work/keep.exr" --mul -o "$work/masked.exr"
  local own own_lit
  own=$(own_error "$(rms_error "$work/clamped.exr" "$work/reference1c.exr")" "$reference_error")
  own_lit=$(own_error "$(rms_error "$work/masked.exr" "$work/reference1m.exr")" "$reference_error_lit")
  relative=$(awk -v e="$own" -v m="$level" 'BEGIN {printf "%.4g", e / m}')
  relative_lit=$(awk -v e="$own_lit" -v m="$level_lit" -v f="$lit_share" 'BEGIN {printf "%.4g", e * sqrt(f) / m}')
}

# ratio P B: P / B, how many times lower B is.
ratio() { awk -v p="$1" -v b="$2" 'BEGIN {printf "%.4g", (b > 0 ? p / b : 0)}'; }

# samples_per_pixel STATS.json: the samples per pixel a timed render reached.
samples_per_pixel() {
  awk -v w="$width" -v h="$height" '/"samples":/ {gsub(/,/, "", $2); printf "%.1f", $2 / (w * h)}' "$1"
}

# measure SAMPLER: renders for $seconds, sets timed_seconds/timed_note, spp_reached and relative.
measure() {
  timed_run "$1" render "$1" 0 "$work/$1.exr" --spp 16777216 --time-limit "$seconds" --stats "$work/$1.json"
  spp_reached=$(samples_per_pixel "$work/$1.json")
  relative_error_of "$work/$1.exr"
}

# measure_pair ROUND (--paired): both samplers for $seconds at once, one thread each, power on
# core ROUND mod 2 and the BVH on the other.
measure_pair() {
  local power_core=$(($1 % 2)) sampler pids=()
  for sampler in power bvh; do
    local core=$power_core
    [[ $sampler == bvh ]] && core=$((1 - power_core))
    taskset -c "$core" "$binary" render "$scene" -o "$work/$sampler.exr" --width "$width" --height "$height" \
      --light-sampler "$sampler" --seed 0 --threads 1 --quiet --spp 16777216 --time-limit "$seconds" \
      --stats "$work/$sampler.json" &
    pids+=($!)
  done
  wait "${pids[@]}"
  p_spp=$(samples_per_pixel "$work/power.json") b_spp=$(samples_per_pixel "$work/bvh.json")
  relative_error_of "$work/power.exr"
  p=$relative pl=$relative_lit p_note="core $power_core"
  relative_error_of "$work/bvh.exr"
  b=$relative bl=$relative_lit b_note="core $((1 - power_core))"
}

render power 0 "$work/power_equal.exr" --spp "$equal_spp"
relative_error_of "$work/power_equal.exr"
power_equal=$relative power_equal_lit=$relative_lit
render bvh 0 "$work/bvh_equal.exr" --spp "$equal_spp"
relative_error_of "$work/bvh_equal.exr"
bvh_equal=$relative bvh_equal_lit=$relative_lit

require_quiet_machine "$max_load"
ratios=() ratios_lit=() log=""
for ((i = 0; i < repeats; i++)); do
  if ((paired)); then
    measure_pair "$i"
  else
    measure power; p=$relative pl=$relative_lit p_spp=$spp_reached p_note="$timed_seconds s, $timed_note"
    measure bvh; b=$relative bl=$relative_lit b_spp=$spp_reached b_note="$timed_seconds s, $timed_note"
  fi
  ratios+=("$(ratio "$p" "$b")") ratios_lit+=("$(ratio "$pl" "$bl")")
  log+="| $((i + 1)) | $p_spp | $p | $pl | $p_note | $b_spp | $b | $bl | $b_note |"$'\n'
done

if ((paired)); then
  echo "assets/many-lights.scene (400 emissive quads), ${width}x${height}, path, depth 3, $seconds s each, both samplers at once, one thread each on its own core"
else
  echo "assets/many-lights.scene (400 emissive quads), ${width}x${height}, path, depth 3, $threads threads, $seconds s each"
fi
echo "relative error = RMS error (linear, clamped to [0, 1]) / mean of the reference ($level), the reference's own"
echo "error ($reference_error, from two $reference_spp-spp BVH renders on seeds 1 and 2) removed"
echo "lit surfaces: the $lit_share of the pixels that see no lamp (level $level_lit, reference error $reference_error_lit)"
echo "at $equal_spp spp, whole image: relative error power $power_equal, BVH $bvh_equal (power / BVH $(ratio "$power_equal" "$bvh_equal"))"
echo "at $equal_spp spp, lit surfaces: relative error power $power_equal_lit, BVH $bvh_equal_lit (power / BVH $(ratio "$power_equal_lit" "$bvh_equal_lit"))"
echo "at equal time:"
echo "| run | power spp | power error, whole | power error, lit | power time (load, CPU share) or core | BVH spp | BVH error, whole | BVH error, lit | BVH time or core |"
echo "|---|---|---|---|---|---|---|---|---|"
printf '%s' "$log"
summarize_ratios "relative error of the whole image, power / BVH, at equal time" "${ratios[@]}"
summarize_ratios "relative error of the lit surfaces, power / BVH, at equal time" "${ratios_lit[@]}"
