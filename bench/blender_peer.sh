#!/usr/bin/env bash
# radiant against Blender's importers and Cycles on real files: each file is imported and
# rendered by Blender (bench/blender_peer.py: radiant's framing camera computed on Blender's own
# import, a uniform white world plus the file's lights) and by radiant from the same camera
# (--look-from/--look-at/--up, --fov 40, --env-color 1,1,1), path traced at the same size, spp
# and depth. Reports per file the ratio of mean colours (radiant / Blender, per channel, of the
# sRGB PNGs) and the share of pixels OpenImageIO's perceptual test (idiff -p) tells apart, and
# writes a contact sheet: radiant left, Blender right, one file a row, in the table's order.
# Not a timing: it may run on a busy machine.
#
# Usage: bench/blender_peer.sh [--size 128] [--spp 64] [--max-depth 8] [--out DIR] [FILE...]
#   default files: assimp's spider.obj, cube_mtllib_after_g.obj, concave_polygon.obj, the Draco
#   2CylinderEngine, BoxTextured and simple_skin. DIR (default bench-peer) keeps the images,
#   table.md and contact-sheet.png.
# Needs: blender and assimp-testmodels (installed here on first use, not in CI), openimageio-tools.
set -uo pipefail
cd "$(dirname "$0")/.."
size=128 spp=64 max_depth=8 out=bench-peer files=()
models=/usr/share/assimp/models
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --max-depth) max_depth=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -*) echo "unknown option $1" >&2; exit 2 ;;
    *) files+=("$1"); shift ;;
  esac
done
source bench/quiet_machine.sh
command -v blender >/dev/null || install_debian_packages blender
[ -d "$models/OBJ" ] || install_debian_packages assimp-testmodels
((${#files[@]})) || files=("$models/OBJ/spider.obj" "$models/OBJ/cube_mtllib_after_g.obj"
  "$models/OBJ/concave_polygon.obj" "$models/glTF2/draco/2CylinderEngine.gltf"
  "$models/glTF2/BoxTextured-glTF/BoxTextured.gltf" "$models/glTF2/simple_skin/simple_skin.gltf")
cmake --build build --target radiant -j2 >/dev/null || exit 1
mkdir -p "$out"

# "r g b" of an image's mean (oiiotool's average of the stored, sRGB-encoded values).
mean_rgb() { oiiotool "$1" --printstats 2>/dev/null | awk '/Stats Avg:/ {print $3, $4, $5; exit}'; }

table="$out/table.md"
printf '| file | mean ratio R G B (radiant / Blender) | pixels told apart (idiff -p) |\n|---|---|---|\n' >"$table"
sheet=()
for file in "${files[@]}"; do
  name=$(basename "${file%.*}")
  blender_png="$out/$name-blender.png" radiant_png="$out/$name-radiant.png"
  camera=$(blender -b --factory-startup -P bench/blender_peer.py -- "$file" "$blender_png" "$size" "$spp" "$max_depth" 2>&1 |
    awk '/^camera: / {print $2, $3, $4; exit}')
  if [ -z "$camera" ] || [ ! -f "$blender_png" ]; then
    printf '| %s | Blender did not import or render it | |\n' "$name" >>"$table"
    continue
  fi
  read -r from at up <<<"$camera"
  if ! build/radiant render "$file" -o "$radiant_png" --width "$size" --height "$size" --spp "$spp" --mode path \
    --max-depth "$max_depth" --look-from "$from" --look-at "$at" --up "$up" --fov 40 --env-color 1,1,1 \
    --allow-external-files --quiet 2>"$out/$name-radiant.err"; then
    printf '| %s | radiant refused it: %s | |\n' "$name" "$(head -n 1 "$out/$name-radiant.err")" >>"$table"
    continue
  fi
  read -r r1 g1 b1 <<<"$(mean_rgb "$radiant_png")"
  read -r r2 g2 b2 <<<"$(mean_rgb "$blender_png")"
  ratio=$(awk -v a="$r1" -v b="$g1" -v c="$b1" -v x="$r2" -v y="$g2" -v z="$b2" \
    'function q(n, d) { return d > 0 ? sprintf("%.3f", n / d) : "-" } BEGIN { print q(a, x), q(b, y), q(c, z) }')
  failed=$(idiff -p "$radiant_png" "$blender_png" 2>&1 | awk '/pixels \(/ && /failed/ {print $1; exit}')
  share=$(awk -v f="${failed:-0}" -v n="$((size * size))" 'BEGIN { printf "%.1f%%", 100 * f / n }')
  printf '| %s | %s | %s |\n' "$name" "$ratio" "$share" >>"$table"
  sheet+=("$radiant_png" "$blender_png")
done
cat "$table"
if ((${#sheet[@]})); then
  oiiotool "${sheet[@]}" --mosaic:pad=4 "2x$((${#sheet[@]} / 2))" -o "$out/contact-sheet.png" &&
    echo "contact sheet: $out/contact-sheet.png (radiant left, Blender right)"
fi
