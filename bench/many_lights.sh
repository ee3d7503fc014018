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
# Before the timing, both render --equal-spp samples per pixel (the scene's own 16 by default):
# the error at equal samples, which is not a timing and holds on any machine.
#
# Usage: bench/many_lights.sh [--width 320] [--height 240] [--seconds 10] [--reference-spp 4096]
#                             [--equal-spp 16] [--repeats 3] [--threads 2] [--max-load 0.5]
# A smoke test that it works (seconds, not a measurement):
#   bench/many_lights.sh --width 32 --height 24 --seconds 0.5 --reference-spp 64 --repeats 1 --max-load 99
# Needs: openimageio-tools (oiiotool; scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
width=320 height=240 seconds=10 reference_spp=4096 equal_spp=16 repeats=3 threads=2 max_load=0.5
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
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
command -v oiiotool >/dev/null || { echo "install openimageio-tools for oiiotool" >&2; exit 1; }
cmake --build build --target radiant -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/quiet_machine.sh
source bench/equal_error.sh
scene=assets/many-lights.scene

# render SAMPLER SEED OUT.exr [FLAGS...]: the scene as the file sets it (path, depth 3), at our size.
render() {
  build/radiant render "$scene" -o "$3" --width "$width" --height "$height" --light-sampler "$1" --seed "$2" \
    --threads "$threads" --quiet "${@:4}"
}

echo "references at $reference_spp spp ..." >&2
render bvh 1 "$work/reference1.exr" --spp "$reference_spp"
render bvh 2 "$work/reference2.exr" --spp "$reference_spp"
clamped_linear "$work/reference1.exr" "$work/reference1c.exr"
clamped_linear "$work/reference2.exr" "$work/reference2c.exr"
reference_error=$(reference_error "$work/reference1c.exr" "$work/reference2c.exr")
level=$(mean_value "$work/reference1c.exr")

# relative_error_of IMAGE.exr: sets relative (see above).
relative_error_of() {
  clamped_linear "$1" "$work/clamped.exr"
  local own
  own=$(own_error "$(rms_error "$work/clamped.exr" "$work/reference1c.exr")" "$reference_error")
  relative=$(awk -v e="$own" -v m="$level" 'BEGIN {printf "%.4g", e / m}')
}

# measure SAMPLER: renders for $seconds, sets timed_seconds/timed_note, spp_reached and relative.
measure() {
  timed_run "$1" render "$1" 0 "$work/$1.exr" --spp 16777216 --time-limit "$seconds" --stats "$work/$1.json"
  spp_reached=$(awk -v w="$width" -v h="$height" '/"samples":/ {gsub(/,/, "", $2); printf "%.1f", $2 / (w * h)}' "$work/$1.json")
  relative_error_of "$work/$1.exr"
}

render power 0 "$work/power_equal.exr" --spp "$equal_spp"
relative_error_of "$work/power_equal.exr"
power_equal=$relative
render bvh 0 "$work/bvh_equal.exr" --spp "$equal_spp"
relative_error_of "$work/bvh_equal.exr"
bvh_equal=$relative

require_quiet_machine "$max_load"
ratios=() log=""
for ((i = 0; i < repeats; i++)); do
  measure power; p=$relative p_spp=$spp_reached p_note="$timed_seconds s, $timed_note"
  measure bvh; b=$relative b_spp=$spp_reached b_note="$timed_seconds s, $timed_note"
  ratios+=("$(awk -v p="$p" -v b="$b" 'BEGIN {printf "%.4g", (b > 0 ? p / b : 0)}')")
  log+="| $((i + 1)) | $p_spp | $p | $p_note | $b_spp | $b | $b_note |"$'\n'
done

echo "assets/many-lights.scene (400 emissive quads), ${width}x${height}, path, depth 3, $threads threads, $seconds s each"
echo "relative error = RMS error (linear, clamped to [0, 1]) / mean of the reference ($level), the reference's own"
echo "error ($reference_error, from two $reference_spp-spp BVH renders on seeds 1 and 2) removed"
echo "at $equal_spp spp: relative error power $power_equal, BVH $bvh_equal (power / BVH $(awk -v p="$power_equal" -v b="$bvh_equal" 'BEGIN {printf "%.3g", (b > 0 ? p / b : 0)}'))"
echo "at equal time:"
echo "| run | power spp | power relative error | power time (load, CPU share) | BVH spp | BVH relative error | BVH time |"
echo "|---|---|---|---|---|---|---|"
printf '%s' "$log"
summarize_ratios "relative error, power / BVH, at equal time" "${ratios[@]}"
