#!/usr/bin/env bash
# Runs both loader fuzzers side by side (one core each) for SECONDS, starting from the seed
# corpora; exits non-zero if either finds a crash, a sanitizer report, a leak or a hang.
# Findings land in BUILD_DIR/fuzz-artifacts/ (docs/hardening.md turns them into regression tests).
# Usage: scripts/fuzz.sh [BUILD_DIR] [SECONDS]   (defaults: build-fuzz, 90)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-fuzz}
seconds=${2:-90}
artifacts="$build_dir/fuzz-artifacts"
mkdir -p "$artifacts"
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer || true)}

# $1 = harness, $2 = corpus and dictionary name. New inputs go to a scratch corpus in the build
# dir, never into the seeds; -timeout makes a hang a finding too.
run_fuzzer() {
  local work="$build_dir/fuzz-corpus/$2"
  mkdir -p "$work"
  "$build_dir/tests/fuzz/$1" "$work" "tests/fuzz/corpus/$2" -dict="tests/fuzz/$2.dict" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$2-" > "$build_dir/fuzz-$2.log" 2>&1
}

run_fuzzer fuzz_scene_format scene & scene_pid=$!
run_fuzzer fuzz_gltf gltf & gltf_pid=$!
status=0
wait "$scene_pid" || status=1
wait "$gltf_pid" || status=1

for name in scene gltf; do
  echo "== fuzz_$name: $build_dir/fuzz-$name.log =="
  # The summary on success; the sanitizer report and the artifact name on a finding.
  grep -E "^(==[0-9]+==ERROR|SUMMARY|artifact_prefix|Test unit written|terminate called|  what\(\)|#[0-9]+\s+DONE|stat::number_of_executed_units|stat::peak_rss_mb)|runtime error:|^\s+#[0-9]+ 0x" \
    "$build_dir/fuzz-$name.log" | head -40 || true
done
if ((status)); then echo "fuzz: FAILED, inputs in $artifacts/" >&2; exit 1; fi
echo "fuzz: no finding in ${seconds} s per fuzzer"
