# Sourced by scripts/test-sanitized.sh and scripts/fuzz.sh, from the repository's root: how the
# sanitizers report, where the caller has not said otherwise.
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# use_tls=0: LeakSanitizer can crash scanning dynamic TLS (tests/sanitizer/lsan.supp, which is
# also the one place for leaks inside Debian's libraries).
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0:use_tls=0}
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer || true)}
