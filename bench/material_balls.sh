#!/usr/bin/env bash
# The glTF material extensions in radiant and in Blender Cycles: bench/material_balls.py writes one
# file of four material balls per extension (uniform environment, no other light); both renderers
# render it at equal spp and path length, and the mean colour per ball goes into a Markdown table
# (docs/materials.md, "Checked against Cycles"). Not a timing: any machine will do.
#
# Usage: bench/material_balls.sh [--size 128] [--spp 256] [--max-depth 8] [--env 0.8] [--out DIR]
# Needs: blender (installed here on first use, not in CI), openimageio-tools.
set -euo pipefail
cd "$(dirname "$0")/.."
size=128 spp=256 max_depth=8 env=0.8 out=""
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --max-depth) max_depth=$2; shift 2 ;;
    --env) env=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
work=${out:-$(mktemp -d)}
mkdir -p "$work"
source bench/quiet_machine.sh
command -v blender >/dev/null || install_debian_packages blender
cmake --build build --target radiant -j2 >/dev/null

python3 bench/material_balls.py write "$work"
for scene in "$work"/*.gltf; do
  name=$(basename "$scene" .gltf)
  build/radiant render "$scene" -o "$work/radiant-$name.exr" --mode path --width "$size" --height "$size" \
    --spp "$spp" --max-depth "$max_depth" --env-color "$env,$env,$env" --quiet
  blender -b --factory-startup -P bench/blender_render.py -- "$scene" "$work/cycles-$name-rgba.exr" "$size" "$spp" \
    "$max_depth" 1 2 "env=$env,$env,$env" principled >"$work/blender-$name.log" 2>&1 ||
    { cat "$work/blender-$name.log" >&2; exit 1; }
  oiiotool "$work/cycles-$name-rgba.exr" --ch R,G,B -o "$work/cycles-$name.exr"
done
python3 bench/material_balls.py table "$work"
echo "images in $work" >&2
