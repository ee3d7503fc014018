#!/usr/bin/env bash
# Runs every fuzz target for SECONDS each, two at a time (one core each), starting from the seed
# corpora; exits non-zero if any finds a crash, a sanitizer report, a leak or a hang.
# Findings land in BUILD_DIR/fuzz-artifacts/ (docs/hardening.md turns them into regression tests).
# Usage: scripts/fuzz.sh [BUILD_DIR] [SECONDS] [TARGET...]   (defaults: build-fuzz, 60, all)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-fuzz}
seconds=${2:-60}
shift 2 || shift $#
targets=("$@")
((${#targets[@]})) || targets=(scene gltf render obj batch image page)
artifacts="$build_dir/fuzz-artifacts"
mkdir -p "$artifacts"
source scripts/sanitizer-env.sh

# The seed folders of a target: its own, and the render target also starts from every scene.
seeds() {
  case $1 in
    render) echo tests/fuzz/corpus/render tests/fuzz/corpus/scene tests/fuzz/corpus/gltf ;;
    *) echo "tests/fuzz/corpus/$1" ;;
  esac
}

# The render target's keywords are those of both scene formats.
dictionary() {
  case $1 in
    render) cat tests/fuzz/scene.dict tests/fuzz/gltf.dict > "$build_dir/fuzz-render.dict"
            echo "$build_dir/fuzz-render.dict" ;;
    *) echo "tests/fuzz/$1.dict" ;;
  esac
}

# New inputs go to a scratch corpus in the build dir, never into the seeds; -timeout makes a
# hang a finding too.
run_fuzzer() {
  local work="$build_dir/fuzz-corpus/$1"
  mkdir -p "$work"
  # shellcheck disable=SC2046  # the seed folders are separate arguments
  "$build_dir/tests/fuzz/fuzz_$1" "$work" $(seeds "$1") -dict="$(dictionary "$1")" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$1-" > "$build_dir/fuzz-$1.log" 2>&1
}

# Two at a time (the machine has two cores); the next starts as soon as one ends.
status=0
running=0
for name in "${targets[@]}"; do
  if ((running == 2)); then
    wait -n || status=1
    running=$((running - 1))
  fi
  run_fuzzer "$name" &
  running=$((running + 1))
done
while ((running > 0)); do
  wait -n || status=1
  running=$((running - 1))
done

for name in "${targets[@]}"; do
  echo "== fuzz_$name: $build_dir/fuzz-$name.log =="
  # The summary on success; the sanitizer report and the artifact name on a finding.
  grep -E "^(==[0-9]+==ERROR|SUMMARY|artifact_prefix|Test unit written|terminate called|  what\(\)|#[0-9]+\s+DONE|stat::number_of_executed_units|stat::peak_rss_mb)|runtime error:|Assertion .* failed|deadly signal|^\s+#[0-9]+ 0x" \
    "$build_dir/fuzz-$name.log" | head -40 || true
done
if ((status)); then
  # CI keeps only its log: each finding is printed whole, so it can be replayed from the log alone
  # (base64 -d > file, then the target's binary on that file).
  for finding in "$artifacts"/*; do
    [[ -f $finding ]] || continue
    echo "== finding $finding, base64: =="
    base64 -w 0 "$finding" | head -c 32768
    echo
  done
  echo "fuzz: FAILED, inputs in $artifacts/" >&2
  exit 1
fi
echo "fuzz: no finding in ${seconds} s per fuzz target"
