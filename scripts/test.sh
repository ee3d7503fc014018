#!/usr/bin/env bash
# Quick start, part 2: set everything up, then run every test through ctest.
# Usage: scripts/test.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
scripts/setup.sh "$build_dir" "$@"
cd "$build_dir"
ctest --output-on-failure -j2 --timeout 600
