#!/usr/bin/env bash
# The GNU parallel recipe (examples/parallel/render.sh) on this machine: 6 shards (--split both),
# one failing on its first attempt and retried, merged to a PNG with a single render's pixels and
# the settings it records (the bytes differ: each image records its own command line and times).
# Run by .ci/run, not by ctest.
#
# Usage: tests/distributed/parallel_shards.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
radiant=$(realpath "${1:-build}")/radiant
work=$(mktemp -d /tmp/radiant-parallel.XXXXXX)
trap 'rm -rf "$work"' EXIT
scene=$PWD/assets/cornell.gltf
flags=(--width 32 --height 24 --spp 6 --max-depth 3 --mode path)
"$radiant" render "$scene" -o "$work/single.png" "${flags[@]}" --quiet

cat >"$work/flaky-radiant" <<FLAKY
#!/bin/bash
if [[ " \$* " == *" 4/6 "* && ! -e "$work/failed-once" ]]; then
  touch "$work/failed-once"
  exit 1
fi
exec "$radiant" "\$@"
FLAKY
chmod +x "$work/flaky-radiant"
RADIANT=$work/flaky-radiant RETRIES=2 JOBS=2 examples/parallel/render.sh "$scene" 6 "$work/shards" "$work/merged.png" \
  "${flags[@]}" --split both
[[ -e $work/failed-once ]] || { echo "the failing attempt never ran" >&2; exit 1; }
idiff -q -fail 0 -failpercent 0 -warn 0 -warnpercent 0 "$work/single.png" "$work/merged.png" ||
  { echo "the merged PNG's pixels differ from the single render's" >&2; exit 1; }
# field NAME IMAGE: the value `radiant info` shows for the metadata field NAME of IMAGE.
field() { "$radiant" info "$2" | sed -n "s/^    $1: //p"; }
for name in radiant:scene radiant:mode radiant:sampler radiant:spp radiant:seed radiant:rays; do
  single=$(field "$name" "$work/single.png") merged=$(field "$name" "$work/merged.png")
  [[ -n $single && $single == "$merged" ]] ||
    { echo "the merged PNG records $name '$merged', the single render '$single'" >&2; exit 1; }
done
echo "parallel: merged shards equal the single render pixel for pixel, with its settings recorded"
