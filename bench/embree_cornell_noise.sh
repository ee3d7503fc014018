#!/usr/bin/env bash
# radiant against Embree's tutorial path tracer at equal noise: how long each takes to reach the
# error the tutorial has at --spp samples per pixel. bench/embree_cornell.sh compares equal
# samples; this asks what a user waits for, a clean image.
#
# Each renderer's error is measured against its own converged render (--reference-spp), so only
# noise counts, not the few-per-mille differences between the two renderers' models, and never
# against a reference that contains the measured samples (bench/equal_error.sh): radiant's
# references use seeds 1 and 2 (the measured renders seed 0), and the reference's own error,
# estimated from the two, is removed. The tutorial has no seed: its reference is its own first
# samples plus more, so its error is corrected for that nesting (independent samples).
# Both images are compared as the tutorial writes them: linear, clamped to [0, 1], 8 bits
# (radiant's EXR goes through oiiotool the same way). radiant's sample count is raised from spp/16
# in steps of spp/16 until its error is no larger than the tutorial's, then found to the sample
# within that last step; then both are timed in
# alternating runs, with the tutorial also on radiant's watertight Embree kernel
# (embree_cornell_common.sh); each run records the load and its CPU share (quiet_machine.sh).
#
# Usage: bench/embree_cornell_noise.sh [--size 512] [--spp 64] [--reference-spp 1024] [--repeats 5]
#                                      [--threads 2] [--max-load 0.5]
#                                      [--scene cornell.scene|cornell.gltf|cornell-lambertian.gltf]
#                                      [--radiant-flags "--indirect-paths 4"]
# (--scene: radiant's file for the box, as in bench/embree_cornell.sh; for the glTF path use
# cornell-lambertian.gltf: cornell.gltf's coated materials make a darker, less noisy image than the
# tutorial's, so reaching the tutorial's error there would flatter radiant. --radiant-flags: radiant is
# also measured and timed with these flags, beside its plain renders; its references stay plain.)
# Needs: embree-tools (pathtracer), openimageio-tools (oiiotool; scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
size=512 spp=64 reference_spp=1024 repeats=5 threads=2 max_load=0.5
while (($#)); do
  case $1 in
    --max-load) max_load=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --reference-spp) reference_spp=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --scene) radiant_scene=$2; shift 2 ;;
    --radiant-flags) measured_flags=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
command -v oiiotool >/dev/null || { echo "install openimageio-tools for oiiotool" >&2; exit 1; }
cmake --build build --target radiant -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/embree_cornell_common.sh
source bench/quiet_machine.sh
source bench/equal_error.sh

# radiant_ppm SPP OUT.ppm [SEED [FLAGS]]: radiant's linear render written as the tutorial writes its own.
radiant_ppm() {
  radiant_seed=${3:-0} radiant_flags=${4:-} radiant_render "$size" "$1" "$work/radiant.exr"
  oiiotool "$work/radiant.exr" --clamp:min=0:max=1 -d uint8 -o "$2"
}

require_quiet_machine "$max_load"
echo "references at $reference_spp spp ..." >&2
embree_render "$size" "$reference_spp" "$work/embree_reference.ppm"
radiant_ppm "$reference_spp" "$work/radiant_reference.ppm" 1
radiant_ppm "$reference_spp" "$work/radiant_reference2.ppm" 2
radiant_reference_error=$(reference_error "$work/radiant_reference.ppm" "$work/radiant_reference2.ppm")

embree_render "$size" "$spp" "$work/embree.ppm"
embree_error=$(nested_own_error "$(rms_error "$work/embree.ppm" "$work/embree_reference.ppm")" "$spp" "$reference_spp")
embree_render_robust "$size" "$spp" "$work/embree_robust.ppm"
robust_error=$(nested_own_error "$(rms_error "$work/embree_robust.ppm" "$work/embree_reference.ppm")" "$spp" "$reference_spp")
errors_table=""
# reaches_tutorial_error N [FLAGS]: renders radiant at N spp, logs its error, and succeeds when
# the error is no larger than the tutorial's.
reaches_tutorial_error() {
  radiant_ppm "$1" "$work/radiant.ppm" 0 "${2:-}"
  local measured error
  measured=$(rms_error "$work/radiant.ppm" "$work/radiant_reference.ppm")
  error=$(own_error "$measured" "$radiant_reference_error")
  errors_table+="| radiant${2:+ $2} | $1 | $error (measured $measured) |"$'\n'
  awk -v a="$error" -v b="$embree_error" 'BEGIN {exit !(a <= b)}'
}
# equal_spp_for FLAGS: the least sample count at which radiant reaches the tutorial's error, in
# $found_spp. Coarse steps of spp/16 first, then one sample at a time inside the last step:
# stopping at the coarse step would time radiant at up to spp/16 - 1 samples more than it needs
# (44 where 42 reach it is 5% of its time).
equal_spp_for() {
  local step=$((spp / 16 > 0 ? spp / 16 : 1)) n
  found_spp=""
  for ((n = step; n <= 4 * spp; n += step)); do
    if reaches_tutorial_error "$n" "$1"; then found_spp=$n; break; fi
  done
  [[ -n $found_spp ]] || { echo "radiant${1:+ $1} did not reach the tutorial's error within $((4 * spp)) spp" >&2; exit 1; }
  for ((n = found_spp - step + 1; n < found_spp; n++)); do
    if ((n > 0)) && reaches_tutorial_error "$n" "$1"; then found_spp=$n; break; fi
  done
  # (An if, not a chain of &&: when no count inside the step reaches the error, the chain's
  # failure was the loop's status, and `set -e` ended the script with the coarse count found.)
}
equal_spp_for ""
equal_spp=$found_spp
if [[ -n ${measured_flags:-} ]]; then equal_spp_for "$measured_flags"; flagged_spp=$found_spp; fi

embree_times=() robust_times=() radiant_times=() ratios=() robust_ratios=() log=""
flagged_times=() flagged_ratios=()
for ((i = 0; i < repeats; i++)); do
  timed_run tutorial embree_render "$size" "$spp" "$work/embree.ppm"; e=$timed_seconds e_note=$timed_note
  timed_run robust embree_render_robust "$size" "$spp" "$work/embree_robust.ppm"; b=$timed_seconds b_note=$timed_note
  # Each writes its own 8-bit image, as bench/embree_cornell.sh times them: the tutorial a PPM,
  # radiant a PNG (the EXR above is only for measuring the error in linear values).
  timed_run radiant radiant_render "$size" "$equal_spp" "$work/radiant.png"; r=$timed_seconds r_note=$timed_note
  embree_times+=("$e") robust_times+=("$b") radiant_times+=("$r")
  ratios+=("$(echo "$r / $e" | bc -l)") robust_ratios+=("$(echo "$r / $b" | bc -l)")
  row="| $((i + 1)) | $e ($e_note) | $b ($b_note) | $r ($r_note) |"
  if [[ -n ${measured_flags:-} ]]; then
    radiant_flags=$measured_flags timed_run flagged radiant_render "$size" "$flagged_spp" "$work/radiant.png"
    flagged_times+=("$timed_seconds") flagged_ratios+=("$(echo "$timed_seconds / $e" | bc -l)")
    row+=" $timed_seconds ($timed_note) |"
  fi
  log+="$row"$'\n'
done

echo "Cornell box (Embree tutorial scene), ${size}x${size}, path length 8, $threads threads;"
echo "RMS error (linear, clamped, 8 bits) against each renderer's own $reference_spp-spp render, the reference's own error"
echo "removed (radiant: references on seeds 1 and 2, its own error $radiant_reference_error; tutorial: nested samples)"
echo "| renderer | spp | RMS error |"
echo "|---|---|---|"
echo "| Embree tutorial pathtracer | $spp | $embree_error |"
echo "| Embree tutorial pathtracer, radiant's watertight kernel | $spp | $robust_error |"
printf '%s' "$errors_table"
echo
echo "equal noise: radiant at $equal_spp spp${measured_flags:+, with $measured_flags at $flagged_spp spp}, tutorial at $spp spp"
echo "| run | tutorial s (load, CPU share) | tutorial, watertight kernel s | radiant s |${measured_flags:+ radiant $measured_flags s |}"
echo "|---|---|---|---|${measured_flags:+---|}"
printf '%s' "$log"
echo "median wall time: tutorial $(median "${embree_times[@]}") s, watertight $(median "${robust_times[@]}") s, radiant $(median "${radiant_times[@]}") s"
summarize_ratios "time ratio radiant / Embree tutorial at equal noise" "${ratios[@]}"
summarize_ratios "time ratio radiant / Embree tutorial on the same watertight kernel at equal noise" "${robust_ratios[@]}"
if [[ -n ${measured_flags:-} ]]; then
  echo "median wall time, radiant $measured_flags: $(median "${flagged_times[@]}") s"
  summarize_ratios "time ratio radiant $measured_flags / Embree tutorial at equal noise" "${flagged_ratios[@]}"
fi
