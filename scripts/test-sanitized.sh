#!/usr/bin/env bash
# Every test under AddressSanitizer and UndefinedBehaviorSanitizer, in the fuzz build
# (scripts/setup-fuzz.sh: clang, -O1 -gline-tables-only): one sanitized build of radiant serves
# both the suite and the fuzzers, where two (GCC's for the suite, clang's for libFuzzer) took
# most of CI's time (docs/hardening.md, "What CI runs"). A sanitizer report fails its test.
# Run it after scripts/setup.sh, which installs the libraries.
# Usage: scripts/test-sanitized.sh [BUILD_DIR]   (BUILD_DIR defaults to build-fuzz)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-fuzz}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
source scripts/sanitizer-env.sh
# The fuzzers first (setup-fuzz.sh), then what the suite adds to them: radiant and the test binary.
scripts/setup-fuzz.sh "$build_dir" -DRADIANT_TESTS=ON
cmake --build "$build_dir" -j2 >&2
cd "$build_dir"
ctest --output-on-failure -j2 --timeout 600
