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
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# use_tls=0: LeakSanitizer can crash scanning dynamic TLS (tests/sanitizer/lsan.supp, which is
# also the one place for leaks inside Debian's libraries).
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0:use_tls=0}
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer || true)}
# The fuzzers first (setup-fuzz.sh), then what the suite adds to them: radiant and the test binary.
scripts/setup-fuzz.sh "$build_dir" -DRADIANT_TESTS=ON
cmake --build "$build_dir" -j2 >&2
cd "$build_dir"
ctest --output-on-failure -j2 --timeout 600
