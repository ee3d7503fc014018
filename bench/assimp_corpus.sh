#!/usr/bin/env bash
# radiant on real-world files: every OBJ, glTF and GLB of Debian's assimp-testmodels rendered
# small, one process each. Reports per file the exit status (0 rendered, 1 refused with one
# line, anything else a crash), the first warning or the error, and a total; exits 1 when any
# file crashed (a signal, a timeout or an exit status other than 0 and 1). Not a timing.
#
# Usage: bench/assimp_corpus.sh [--size 64] [--spp 4] [--out DIR] [--models /usr/share/assimp/models]
#   --out keeps the images (DIR/<folder>__<file>.png) to look at; the table goes to stdout.
# Needs: assimp-testmodels (installed here on first use, not by setup.sh or CI).
set -uo pipefail
cd "$(dirname "$0")/.."
size=64 spp=4 out="" models=/usr/share/assimp/models
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --models) models=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
source bench/quiet_machine.sh
[ -d "$models/OBJ" ] || install_debian_packages assimp-testmodels
cmake --build build --target radiant -j2 >/dev/null || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -n "$out" ] && mkdir -p "$out"
rendered=0 refused=0 crashed=0
printf '| file | status | first warning or error |\n|---|---|---|\n'
while IFS= read -r file; do
  relative=${file#"$models"/}
  image="$work/image.png"
  [ -n "$out" ] && image="$out/$(echo "$relative" | tr '/' '_' | sed 's/\.[^.]*$//').png"
  timeout 120 build/radiant render "$file" -o "$image" --width "$size" --height "$size" --spp "$spp" \
    --allow-external-files >"$work/out" 2>"$work/err"
  status=$?
  # A refusal's one line, or a render's first warning.
  pattern='^radiant: warning: '
  ((status == 0)) || pattern='.'
  message=$( (grep -m 1 -e "$pattern" "$work/err" || true) | sed "s|$models/||g; s/|/\\\\|/g")
  case $status in
    0) rendered=$((rendered + 1)); verdict=rendered ;;
    1) refused=$((refused + 1)); verdict=refused ;;
    *) crashed=$((crashed + 1)); verdict="CRASH ($status)" ;;
  esac
  printf '| %s | %s | %s |\n' "$relative" "$verdict" "${message:0:160}"
done < <(find "$models/OBJ" "$models/glTF2" -type f \( -iname '*.obj' -o -iname '*.gltf' -o -iname '*.glb' \) | sort)
printf '\n%d rendered, %d refused, %d crashed\n' "$rendered" "$refused" "$crashed"
((crashed == 0))
