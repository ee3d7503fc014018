#!/usr/bin/env bash
# Quick start, part 1: set everything up, then render the bundled default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build -DRADIANT_TESTS=OFF  # the renderer alone: scripts/test.sh adds the tests
mkdir -p out
build/radiant render assets/cornell.gltf -o out/cornell.png --quiet
echo "radiant: rendered assets/cornell.gltf to $(pwd)/out/cornell.png"
