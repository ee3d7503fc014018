#!/bin/sh
# Regenerates the golden images golden/NAME.exr from golden/cases.txt, with the command lines
# tests/golden/golden_test.cpp uses (golden/README.md). LOOK at every new golden before
# committing it: the test only checks that renders still match what was committed.
#
#   scripts/update-goldens.sh              # every case
#   scripts/update-goldens.sh cornell-path # only the named cases
#
# RADIANT=path/to/radiant overrides the executable (default build/radiant).
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
radiant=${RADIANT:-$root/build/radiant}
[ -x "$radiant" ] || { echo "update-goldens: no executable $radiant (build first)" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Keep in step with tests/golden/golden_cases.h: the golden's seed and the stored channels.
golden_seed=1

picks=" $* "
trim() { printf '%s' "$1" | sed 's/^ *//; s/ *$//'; }

cases=$(grep -v '^[[:space:]]*\(#\|$\)' "$root/golden/cases.txt")
for pick in "$@"; do
  printf '%s\n' "$cases" | grep -q "^$pick *|" || { echo "update-goldens: no case $pick" >&2; exit 2; }
done

# The last column, the test's spp, is the test's business.
printf '%s\n' "$cases" | while IFS='|' read -r name check scene flags golden_spp _; do
  name=$(trim "$name"); check=$(trim "$check"); scene=$(trim "$scene")
  flags=$(trim "$flags"); golden_spp=$(trim "$golden_spp")
  [ "$picks" = "  " ] || case $picks in *" $name "*) ;; *) continue ;; esac
  case $check in
    threshold) aov="" channels="R,G,B" format=float ;;
    z-test) aov="--aov variance" channels="R,G,B,variance.R,variance.G,variance.B" format=half ;;
    *) echo "update-goldens: $name: unknown check '$check'" >&2; exit 2 ;;
  esac
  echo "$name: radiant render $scene $flags --spp $golden_spp --seed $golden_seed $aov"
  # shellcheck disable=SC2086 # flags are a list of words
  (cd "$root" && "$radiant" render "$scene" -o "$scratch/$name.exr" $flags \
    --spp "$golden_spp" --seed "$golden_seed" $aov --quiet --no-metadata)
  # No software, temporary path, render time or date (radiant records none with --no-metadata,
  # oiiotool stamps the time unless given one): regenerating an unchanged image changes no byte.
  oiiotool --nosoftwareattrib "$scratch/$name.exr" --ch "$channels" \
    --attrib DateTime "1970:01:01 00:00:00" \
    -d "$format" --compression zip \
    -o "$root/golden/$name.exr"
done
