#!/usr/bin/env bash
# radiant against Blender Cycles on real glTF sample files: each file is imported by Blender's glTF
# importer (its Principled BSDF materials kept) and rendered by Cycles at a high sample count, and
# rendered by radiant from the same camera (radiant's framing camera, computed on Blender's import)
# under the same equirectangular environment, at the same size and path length, both with the
# Standard view. Prints the RMSE of the sRGB images per file (0 to 1 per channel), the median of
# the main set and of the held-out set, and writes a contact sheet: radiant left, Cycles right.
# Not a timing: it may run on a busy machine.
#
# Usage: bench/fidelity.sh [--models DIR] [--size 256] [--spp 256] [--ref-spp 1024]
#                          [--max-depth 8] [--out DIR] [--multiscatter] [--radiant-only] [NAME...]
#   DIR is the Models folder of a clone of KhronosGroup/glTF-Sample-Assets (default
#   $GLTF_SAMPLE_ASSETS/Models); NAME a model folder in it (default: the main and held-out sets
#   below). The environment is made here with oiiotool: a sky brighter overhead, a warm ground, a
#   small bright key light. Output (default bench-fidelity): the images, table.md, contact-sheet.png.
#   --multiscatter: Cycles' Principled BSDFs use Multiscatter GGX (energy-conserving, as radiant's
#   lobes), not the single-scattering GGX Blender 3.4's importer leaves. --radiant-only: keep the
#   Cycles renders already in DIR (and the camera recorded beside them) and render radiant again.
# Needs: blender (installed here on first use, not in CI), openimageio-tools.
set -uo pipefail
cd "$(dirname "$0")/.."
models=${GLTF_SAMPLE_ASSETS:-$HOME/glTF-Sample-Assets}/Models
size=256 spp=256 ref_spp=1024 max_depth=8 out=bench-fidelity names=() multiscatter= radiant_only=0
while (($#)); do
  case $1 in
    --models) models=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --ref-spp) ref_spp=$2; shift 2 ;;
    --max-depth) max_depth=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --multiscatter) multiscatter=multiscatter; shift ;;
    --radiant-only) radiant_only=1; shift ;;
    -*) echo "unknown option $1" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
main_set=(DamagedHelmet Avocado WaterBottle BoomBoxWithAxes Duck CesiumMilkTruck BrainStem Fox Suzanne
  MetalRoughSpheresNoTextures ClearCoatTest ClearCoatCarPaint SheenChair SheenCloth GlamVelvetSofa
  TransmissionTest TransmissionRoughnessTest AttenuationTest SpecularTest ToyCar MaterialsVariantsShoe
  NormalTangentTest TextureSettingsTest MultiUVTest VertexColorTest)
held_out=(AlphaBlendModeTest EmissiveStrengthTest GlassVaseFlowers GlassHurricaneCandleHolder NegativeScaleTest
  OrientationTest SpecGlossVsMetalRough StainedGlassLamp TextureTransformMultiTest CesiumMan)
declare -A is_held_out
for name in "${held_out[@]}"; do is_held_out[$name]=1; done
((${#names[@]})) || names=("${main_set[@]}" "${held_out[@]}")
[ -d "$models" ] || { echo "fidelity: $models is missing: pass --models DIR (the Models folder of glTF-Sample-Assets)" >&2; exit 2; }
source bench/quiet_machine.sh
((radiant_only)) || command -v blender >/dev/null || install_debian_packages blender
cmake --build build --target radiant -j2 >/dev/null || exit 1
mkdir -p "$out"

env_map="$out/environment.exr"
oiiotool --pattern fill:top=0.55,0.65,0.9:bottom=1.1,1.05,1.0 512x128 3 \
  --pattern fill:top=0.35,0.3,0.25:bottom=0.12,0.1,0.08 512x128 3 --mosaic 1x2 \
  --box:color=40,38,34:fill=1 300,40,318,58 -d float -o "$env_map" || exit 1

# An image's linear RGB as an 8-bit sRGB PNG, clamped as the Standard view clamps.
to_srgb() { oiiotool "$1" --ch R,G,B --colorconvert linear sRGB -d uint8 -o "$2"; }
model_file() {
  local dir="$models/$1"
  for f in "$dir/glTF-Binary/$1.glb" "$dir/glTF/$1.gltf"; do [ -f "$f" ] && { echo "$f"; return; }; done
}

table="$out/table.md"
printf '| file | set | RMSE (sRGB) |\n|---|---|---|\n' >"$table"
main_rmse=() held_rmse=() sheet=()
for name in "${names[@]}"; do
  set_name=main
  [ -n "${is_held_out[$name]:-}" ] && set_name=held-out
  file=$(model_file "$name")
  if [ -z "$file" ]; then
    printf '| %s | %s | not found under %s |\n' "$name" "$set_name" "$models" >>"$table"
    continue
  fi
  cycles_exr="$out/$name-cycles.exr" radiant_exr="$out/$name-radiant.exr"
  camera_file="$out/$name-camera.txt"
  if ((radiant_only)); then
    camera=$(cat "$camera_file" 2>/dev/null)
  else
    camera=$(blender -b --factory-startup -P bench/fidelity.py -- "$file" "$cycles_exr" "$size" "$ref_spp" \
      "$max_depth" 1 "$(realpath "$env_map")" $multiscatter 2>&1 | awk '/^camera: / {print $2, $3, $4; exit}')
    [ -n "$camera" ] && echo "$camera" >"$camera_file"
  fi
  if [ -z "$camera" ] || [ ! -f "$cycles_exr" ]; then
    printf '| %s | %s | Blender did not import or render it |\n' "$name" "$set_name" >>"$table"
    continue
  fi
  read -r from at _ <<<"$camera"
  # --frame 1 --fps 24: Blender's importer puts the first animation's time 0 at frame 0 of its
  # 24 fps scene, which shows frame 1 (BrainStem, Fox and CesiumMan are posed by it); a file
  # without animations keeps its static state.
  if ! build/radiant render "$file" -o "$radiant_exr" --width "$size" --height "$size" --spp "$spp" --mode path \
    --max-depth "$max_depth" --look-from "$from" --look-at "$at" --up 0,1,0 --fov 40 --env "$env_map" \
    --background env --frame 1 --fps 24 --seed 2 --quiet 2>"$out/$name-radiant.err"; then
    printf '| %s | %s | radiant refused it: %s |\n' "$name" "$set_name" "$(head -n 1 "$out/$name-radiant.err")" >>"$table"
    continue
  fi
  to_srgb "$cycles_exr" "$out/$name-cycles.png" && to_srgb "$radiant_exr" "$out/$name-radiant.png" || continue
  rmse=$(idiff "$out/$name-radiant.png" "$out/$name-cycles.png" 2>&1 | awk '/RMS error/ {print $4; exit}')
  printf '| %s | %s | %.4f |\n' "$name" "$set_name" "$rmse" >>"$table"
  if [ "$set_name" = main ]; then main_rmse+=("$rmse"); else held_rmse+=("$rmse"); fi
  sheet+=("$out/$name-radiant.png" "$out/$name-cycles.png")
done
((${#main_rmse[@]})) && printf '\nmedian RMSE, main set (%d files): %s\n' "${#main_rmse[@]}" "$(median "${main_rmse[@]}")" >>"$table"
((${#held_rmse[@]})) && printf 'median RMSE, held-out set (%d files): %s\n' "${#held_rmse[@]}" "$(median "${held_rmse[@]}")" >>"$table"
cat "$table"
if ((${#sheet[@]})); then
  oiiotool "${sheet[@]}" --mosaic:pad=4 "4x$(((${#sheet[@]} + 3) / 4))" -o "$out/contact-sheet.png" &&
    echo "contact sheet: $out/contact-sheet.png (pairs: radiant left, Cycles right)"
fi
