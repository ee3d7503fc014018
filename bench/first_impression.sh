#!/usr/bin/env bash
# The plain command on real files, as a new user meets it: each file rendered with no flag at
# all, timed, judged lit (the model is not black) and framed (it is in view and not cut by the
# image border), and put on a contact sheet in the order of the table.
#
#   bench/first_impression.sh [--out DIR] [--size N] [FILE...]
#
# Without files: the glTF 2.0 and OBJ models of Debian's assimp-testmodels that radiant reads
# (apt-get install assimp-testmodels), less those made of points and lines only (not drawn yet)
# and those that test broken input. --size N adds --width N --height N (the plain command is
# 512x512 for most files). Needs build/radiant and oiiotool (openimageio-tools).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
radiant=${RADIANT:-$root/build/radiant}
out=first-impression
size_flags=()
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --size) size_flags=(--width "$2" --height "$2"); shift 2 ;;
    *) break ;;
  esac
done
files=("$@")
if [ ${#files[@]} -eq 0 ]; then
  models=/usr/share/assimp/models
  [ -d "$models" ] || { echo "first_impression: no files given and $models missing (apt-get install assimp-testmodels)" >&2; exit 2; }
  while IFS= read -r f; do files+=("$f"); done < <(
    find "$models/glTF2" "$models/OBJ" \( -name '*.gltf' -o -name '*.glb' -o -name '*.obj' \) |
      grep -v -e SchemaFailures -e IncorrectVertexArrays -e IndexOutOfRange -e MissingBin -e RecursiveNodes \
        -e wrongTypes -e TestNoRootNode -e BoxWithInfinites -e techniqueWebGL -e UTF16 -e point_cloud \
        -e testline -e testpoints -e number_formats -e 'Mesh_PrimitiveMode_0' -e 'Mesh_PrimitiveMode_10' | sort)
fi
mkdir -p "$out"

# "mean of the alpha-covered colour, coverage, alpha on the border" of a premultiplied RGBA EXR.
measure() {
  local image=$1 side=$2 avg edge=0 cut
  avg=$(oiiotool --stats "$image" 2>/dev/null | awk '/Stats Avg/ {print $3, $4, $5, $6; exit}')
  for cut in "${side}x1+0+0" "${side}x1+0+$((side - 1))" "1x${side}+0+0" "1x${side}+$((side - 1))+0"; do
    oiiotool "$image" --cut "$cut" -o "$out/edge.exr"
    edge=$(awk -v e="$edge" -v a="$(oiiotool --stats "$out/edge.exr" | awk '/Stats Avg/ {print $6; exit}')" \
      'BEGIN {print e + a / 4}')
  done
  rm -f "$out/edge.exr"
  awk -v avg="$avg" -v edge="$edge" 'BEGIN {
    split(avg, c, " "); lit = c[4] > 0 ? (c[1] + c[2] + c[3]) / 3 / c[4] : 0
    printf "%.3f %.3f %.3f\n", lit, c[4], edge }'
}

printf '| # | file | seconds | model mean | coverage | on border | lit | framed |\n|---|---|---|---|---|---|---|---|\n' > "$out/table.md"
good=0 index=0 sheet=()
for file in "${files[@]}"; do
  index=$((index + 1))
  name=$(printf '%02d-%s' "$index" "$(basename "${file%.*}")")
  start=$(date +%s.%N)
  if ! "$radiant" render "$file" -o "$out/$name.png" "${size_flags[@]}" --quiet 2> "$out/$name.err"; then
    printf '| %d | %s | failed: %s | | | | no | no |\n' "$index" "${file#/usr/share/assimp/models/}" "$(head -c 120 "$out/$name.err")" >> "$out/table.md"
    continue
  fi
  seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.1f", e - s}')
  # The model's coverage from a small transparent render of the same view.
  "$radiant" render "$file" -o "$out/$name-cover.exr" --background transparent --width 96 --height 96 --spp 4 --quiet
  read -r mean coverage border < <(measure "$out/$name-cover.exr" 96)
  lit=$(awk -v m="$mean" 'BEGIN {print (m > 0.01) ? "yes" : "no"}')
  framed=$(awk -v c="$coverage" -v b="$border" 'BEGIN {print (c > 0.02 && b < 0.25) ? "yes" : "no"}')
  [ "$lit" = yes ] && [ "$framed" = yes ] && good=$((good + 1))
  printf '| %d | %s | %s | %s | %s | %s | %s | %s |\n' "$index" "${file#/usr/share/assimp/models/}" "$seconds" "$mean" \
    "$coverage" "$border" "$lit" "$framed" >> "$out/table.md"
  oiiotool "$out/$name.png" --resize 128x128 -o "$out/$name-small.png"
  sheet+=("$out/$name-small.png")
done
columns=6
if [ ${#sheet[@]} -gt 0 ]; then
  rows=$(((${#sheet[@]} + columns - 1) / columns))
  oiiotool "${sheet[@]}" --mosaic "${columns}x${rows}" -o "$out/contact-sheet.png"
fi
cat "$out/table.md"
echo "lit and framed: $good of ${#files[@]} (contact sheet: $out/contact-sheet.png)"
