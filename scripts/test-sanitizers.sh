#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer (issue #25): builds
# ./build-sanitize (scripts/build-sanitize.sh: clang, any report fatal) and runs the tests
# there. By default the unit tests and the CLI tests of hostile input and the run loop (CI
# runs this reduced set after the main suite, then scripts/fuzz.sh); `--all` runs every test,
# the verification scenes included.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
if [ "${1:-}" = "--all" ]; then
  bash scripts/build-sanitize.sh
else
  bash scripts/build-sanitize.sh --reduced
fi
# Leak checking stays on; OpenMP's runtime keeps its thread pool to exit, which LSan reports.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizer-suppressions.txt"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
if [ "${1:-}" = "--all" ]; then
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
else
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -L unit
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs" \
    -R '^cli\.(hostile_input|hvi_run|pipeline)$'
fi
