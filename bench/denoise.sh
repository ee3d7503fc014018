#!/usr/bin/env bash
# What the denoiser buys, on the Cornell box, a textured glTF model and the showcase scene:
#   1. the denoised 16-spp image's relative MSE against the raw 256-spp image's (at most 1: the
#      denoiser saves 16 times the samples);
#   2. on textured regions (pixels within two of an albedo edge), the denoised 16-spp image's
#      relative MSE against the raw 64-spp image's (at most 1: textures are not smeared);
#   3. the denoiser's time as a percentage of the 16-spp render's at 512x512.
# Relative MSE: the mean over pixels and channels of (image - reference)^2 / (reference^2 + 0.01),
# in linear light clamped to [0, 64], every scene in path mode (the showcase's ambient light is then left out). References are rendered at --reference-spp on another seed
# (1), so that no image shares samples with its reference; their own error is not removed, so
# the ratios are conservative while the reference's error is small against the 256-spp image's.
#
# Usage: bench/denoise.sh [--size 128] [--reference-spp 4096] [--threads 2] [--radiant build/radiant]
# Needs: openimageio-tools (oiiotool).
set -euo pipefail
cd "$(dirname "$0")/.."
size=128 reference_spp=4096 threads=2 radiant=build/radiant timing_size=512
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --reference-spp) reference_spp=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --radiant) radiant=$2; shift 2 ;;
    --timing-size) timing_size=$2; shift 2 ;;
    *) sed -n 14p "$0" >&2; exit 2 ;;
  esac
done
command -v oiiotool >/dev/null || { echo "install openimageio-tools for oiiotool" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# render SCENE OUT SPP SEED [FLAGS...]
render() {
  local scene=$1 out=$2 spp=$3 seed=$4
  shift 4
  "$radiant" render "$scene" -o "$out" --width "$size" --height "$size" --spp "$spp" --seed "$seed" \
    --threads "$threads" --mode path --quiet "$@"
}

# relative_mse IMAGE REFERENCE [MASK]: as above, over the pixels where MASK is 1 (all without one).
relative_mse() {
  local image=$1 reference=$2 mask=${3:-}
  oiiotool "$image" --ch R,G,B --clamp:min=0:max=64 "$reference" --ch R,G,B --clamp:min=0:max=64 --sub \
    --dup --mul "$reference" --ch R,G,B --clamp:min=0:max=64 --dup --mul --addc 0.01 --div -o "$work/error.exr"
  if [[ -n $mask ]]; then
    local masked mean
    masked=$(oiiotool "$work/error.exr" "$mask" --mul --printstats | awk '/Stats Avg:/ {print ($3 + $4 + $5) / 3; exit}')
    mean=$(oiiotool "$mask" --printstats | awk '/Stats Avg:/ {print ($3 + $4 + $5) / 3; exit}')
    awk -v a="$masked" -v m="$mean" 'BEGIN {printf "%.4g", (m > 0 ? a / m : 0)}'
  else
    oiiotool "$work/error.exr" --printstats | awk '/Stats Avg:/ {printf "%.4g", ($3 + $4 + $5) / 3; exit}'
  fi
}

# texture_mask REFERENCE_WITH_ALBEDO OUT: 1 within two pixels of an albedo edge, else 0.
texture_mask() {
  oiiotool "$1" --ch albedo.R,albedo.G,albedo.B --chnames R,G,B --laplacian --abs --clamp:min=0:max=1 \
    --mulc 1000 --clamp:min=0:max=1 --dilate 5x5 -o "$2"
}

json_seconds() { sed -n "s/.*\"$2\": *\([0-9.e+-]*\).*/\1/p" "$1" | head -1; }

printf '%-28s %14s %14s %12s %16s %14s\n' scene "denoised16" "raw256" "ratio" "texture d16/r64" "denoise time"
for scene in assets/cornell.gltf assets/models/checker-cube.gltf assets/showcase.scene; do
  name=$(basename "$scene")
  render "$scene" "$work/reference.exr" "$reference_spp" 1 --aov albedo
  render "$scene" "$work/denoised16.exr" 16 0 --denoise
  render "$scene" "$work/raw64.exr" 64 0
  render "$scene" "$work/raw256.exr" 256 0
  texture_mask "$work/reference.exr" "$work/mask.exr"
  denoised=$(relative_mse "$work/denoised16.exr" "$work/reference.exr")
  raw=$(relative_mse "$work/raw256.exr" "$work/reference.exr")
  textured_denoised=$(relative_mse "$work/denoised16.exr" "$work/reference.exr" "$work/mask.exr")
  textured_raw=$(relative_mse "$work/raw64.exr" "$work/reference.exr" "$work/mask.exr")
  "$radiant" render "$scene" -o "$work/timing.exr" --width "$timing_size" --height "$timing_size" --spp 16 --mode path \
    --threads "$threads" --quiet --denoise --stats "$work/timing.json"
  render_seconds=$(json_seconds "$work/timing.json" render)
  denoise_seconds=$(json_seconds "$work/timing.json" denoise)
  printf '%-28s %14s %14s %12s %16s %13s%%\n' "$name" "$denoised" "$raw" \
    "$(awk -v a="$denoised" -v b="$raw" 'BEGIN {printf "%.3f", a / b}')" \
    "$(awk -v a="$textured_denoised" -v b="$textured_raw" 'BEGIN {printf "%.3f", (b > 0 ? a / b : 0)}')" \
    "$(awk -v a="$denoise_seconds" -v b="$render_seconds" 'BEGIN {printf "%.1f", 100 * a / b}')"
done
echo "size ${size}x${size}, references at $reference_spp spp (seed 1), timing at ${timing_size}x${timing_size}, $threads threads, $(nproc) cores" >&2
