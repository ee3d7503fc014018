#!/usr/bin/env bash
# Two radiant builds on one scene at equal samples: each image's relative error against a
# converged reference, and each render's time, for changes to sampling (what is chosen, not how
# fast). The error at equal samples holds on any machine; the time ratio says whether it is also
# the error at equal time (error goes as 1 / sqrt(time)).
#
# References are rendered by build B with seeds 1 and 2 and the measured images with seed 0, so
# no image shares samples with its reference, and the references' own error is removed
# (bench/equal_error.sh). Relative error: that RMS error over the reference's mean, as linear
# values clamped to [0, 1]. Runs alternate A, B, A, B...; each round's renders use seeds 0, 10,
# 20... so that the rounds' errors spread as the noise does. Each round gives one ratio A / B of
# the errors and one of the times (min / median / max over the rounds), and each run records the
# load and its CPU share (bench/quiet_machine.sh).
#
# Usage: bench/ab_error.sh BINARY_A BINARY_B --file SCENE [--width 320] [--height 200] [--spp 32]
#        [--reference-spp 4096] [--repeats 5] [--threads 2] [--max-load 0.5] [-- RENDER FLAGS...]
# e.g. the emission textures' light estimates (docs/lights.md), the starting build against the new:
#   bench/ab_error.sh /tmp/radiant-before build/radiant --file assets/models/lit-windows.gltf
# Needs: openimageio-tools (oiiotool; scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
(($# >= 2)) || { sed -n 14,17p "$0" >&2; exit 2; }
binary_a=$(realpath "$1") binary_b=$(realpath "$2")
shift 2
file= width=320 height=200 spp=32 reference_spp=4096 repeats=5 threads=2 max_load=0.5 flags=()
while (($#)); do
  case $1 in
    --file) file=$2; shift 2 ;;
    --width) width=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --reference-spp) reference_spp=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --max-load) max_load=$2; shift 2 ;;
    --) shift; flags=("$@"); break ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
[[ -n $file ]] || { echo "--file SCENE is needed" >&2; exit 2; }
command -v oiiotool >/dev/null || { echo "install openimageio-tools for oiiotool" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source bench/quiet_machine.sh
source bench/equal_error.sh

# render BINARY SPP SEED OUT.exr
render() {
  "$1" render "$file" -o "$4" --width "$width" --height "$height" --spp "$2" --seed "$3" --threads "$threads" \
    --quiet "${flags[@]}"
}

for seed in 1 2; do
  echo "reference $seed at $reference_spp spp ..." >&2
  render "$binary_b" "$reference_spp" "$seed" "$work/reference$seed.exr"
  clamped_linear "$work/reference$seed.exr" "$work/reference$seed.clamped.exr"
done
reference="$work/reference1.clamped.exr"
reference_own=$(reference_error "$reference" "$work/reference2.clamped.exr")
level=$(mean_value "$reference")

# relative_error IMAGE.exr: its own error (the reference's removed) over the reference's mean.
relative_error() {
  clamped_linear "$1" "$work/measured.exr"
  awk -v e="$(own_error "$(rms_error "$work/measured.exr" "$reference")" "$reference_own")" -v m="$level" \
    'BEGIN {printf "%.6g", e / m}'
}

require_quiet_machine "$max_load"
error_ratios=() time_ratios=() log=""
for ((i = 0; i < repeats; i++)); do
  seed=$((10 * i))
  timed_run a render "$binary_a" "$spp" "$seed" "$work/a.exr"; ta=$timed_seconds na=$timed_note
  timed_run b render "$binary_b" "$spp" "$seed" "$work/b.exr"; tb=$timed_seconds nb=$timed_note
  ea=$(relative_error "$work/a.exr") eb=$(relative_error "$work/b.exr")
  error_ratios+=("$(echo "$ea / $eb" | bc -l)") time_ratios+=("$(echo "$ta / $tb" | bc -l)")
  log+="| $((i + 1)) | $ea | $eb | $ta ($na) | $tb ($nb) |"$'\n'
done

echo "$file, ${width}x$height, $spp spp, $threads threads; relative error against build B's $reference_spp-spp"
echo "reference (its own error $reference_own removed; mean $level)"
echo "| round | error A | error B | seconds A | seconds B |"
echo "|---|---|---|---|---|"
printf '%s' "$log"
summarize_ratios "error A / B" "${error_ratios[@]}"
summarize_ratios "time A / B" "${time_ratios[@]}"
