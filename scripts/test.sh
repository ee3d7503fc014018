#!/usr/bin/env bash
# Quick start, part 2: set everything up, then run every test through ctest.
# Usage: scripts/test.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
# The browser that tests --serve's page, and Node to drive it: tests only, not the renderer's setup.
for p in chromium nodejs; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed"; then
    sudo_cmd=(); [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends chromium nodejs >&2
    break
  fi
done
scripts/setup.sh "$build_dir" -DRADIANT_TESTS=ON "$@"
cd "$build_dir"
ctest --output-on-failure -j2 --timeout 600
