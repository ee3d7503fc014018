#!/usr/bin/env bash
# The GNU parallel recipe (examples/parallel/render.sh) on this machine: 6 shards (--split both),
# one failing on its first attempt and retried, merged to a PNG byte-identical to a single render.
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
cmp "$work/single.png" "$work/merged.png" || { echo "the merged PNG differs from the single render" >&2; exit 1; }
echo "parallel: merged shards equal the single render byte for byte"
