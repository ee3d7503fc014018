#!/usr/bin/env bash
# Installs what the fuzz build needs beyond scripts/setup.sh (only those missing): clang,
# libFuzzer and the sanitizer runtimes for it, and llvm-symbolizer for readable stack traces.
# Then configures and builds every fuzzer (fuzz_NAME) in BUILD_DIR (docs/hardening.md).
# Usage: scripts/setup-fuzz.sh [BUILD_DIR] [extra cmake args...]   (BUILD_DIR defaults to build-fuzz)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(clang libclang-rt-14-dev llvm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup-fuzz: installing ${missing[*]}" >&2
  sudo_cmd=(); [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

build_dir=${1:-build-fuzz}
shift || true
# The test suite is left out unless asked for: scripts/test-sanitized.sh passes -DRADIANT_TESTS=ON
# (a later -D wins) and runs it in this same build.
# -O1 -gline-tables-only (OSS-Fuzz's flags): a quarter less build time than -O2 -g, and stack
# traces still name file and line.
CC=clang CXX=clang++ cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
  "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
  -DRADIANT_FUZZ=ON -DRADIANT_SANITIZE=ON -DRADIANT_TESTS=OFF "$@" >&2
cmake --build "$build_dir" -j2 --target fuzzers >&2
