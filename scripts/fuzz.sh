#!/usr/bin/env bash
# Fuzzes the tools' inputs with libFuzzer (tests/fuzz, issue #25). Builds ./build-sanitize
# (clang, AddressSanitizer + UndefinedBehaviorSanitizer, libFuzzer's coverage: the build
# scripts/test-sanitizers.sh also tests) and runs each target for SECONDS, two at a time,
# from a seed corpus of the repo's own inputs (schemas' keys as a dictionary). The corpus each
# run grows is kept in build-sanitize/fuzz/corpus/TARGET, so a later run goes on from it.
# Every run starts from -seed=1, so a run of the same length on the same build tries the same
# inputs. Prints a line per target (inputs executed, corpus size, findings) and fails if anything was
# found: the input is left as build-sanitize/fuzz/findings/TARGET/crash-* (or timeout-*,
# leak-*, oom-*); run build-sanitize/tests/fuzz/fuzz_TARGET FILE to see it again.
#
#   scripts/fuzz.sh [--seconds N] [TARGET ...]     (default 60 s; CI runs 45 s a target)
#
# Targets: ble_size foam2layers hcomb2rings hvi_run_scene material_library hvi_assess_run_file
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=60
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(ble_size foam2layers hcomb2rings hvi_run_scene
                                     material_library hvi_assess_run_file)

bash scripts/build-sanitize.sh --reduced
build=build-sanitize
work=$build/fuzz
mkdir -p "$work"

# The dictionary: every key the schemas name, and JSON's own tokens.
dict=$work/json.dict
{
  printf '"{"\n"}"\n"["\n"]"\n":"\n","\n"\\"\\""\n"true"\n"false"\n"null"\n"-1e308"\n"1e-300"\n'
  grep -oh '"[a-zA-Z_][a-zA-Z0-9_]*"' schemas/*.json data/hydro_materials.json | sort -u |
    sed 's/"/\\"/g; s/.*/"&"/'
} > "$dict"

seeds_of() {
  case "$1" in
    ble_size) echo tests/fuzz/seeds/ble-size/*.json workflows/default/constraints.json ;;
    foam2layers) echo tests/data/foam2layers/*.json workflows/examples/foam_*.json ;;
    hcomb2rings) echo tests/data/hcomb2rings/*.json workflows/examples/honeycomb_*.json ;;
    hvi_run_scene) echo workflows/extreme/*.json ;;
    material_library) echo tests/data/material/*.json ;;
    hvi_assess_run_file) echo "" ;; # its inputs are edit programs; it starts from nothing
  esac
}

run_target() {
  local t=$1 corpus=$work/corpus/$1 findings=$work/findings/$1 log=$work/$1.log
  mkdir -p "$corpus" "$findings"
  for s in $(seeds_of "$t"); do cp -n "$s" "$corpus/seed-$(basename "$s")"; done
  local status=0
  # One input may take up to 10 s (a slow one is a finding: timeout-*); memory beyond 4 GB is
  # a finding too (oom-*). Leak checks are off: OpenMP's thread pool outlives the inputs.
  ASAN_OPTIONS="detect_leaks=0:abort_on_error=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    "$build/tests/fuzz/fuzz_$t" "$corpus" -dict="$dict" -max_total_time="$seconds" \
    -seed=1 -timeout=10 -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$findings/" >"$log" 2>&1 || status=$?
  local execs found
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  found=$(find "$findings" -type f | wc -l)
  printf 'fuzz: %-20s %3s s  %8s inputs  corpus %5s  findings %s%s\n' "$t" "$seconds" \
    "${execs:-?}" "$(find "$corpus" -type f | wc -l)" "$found" \
    "$([ "$status" -ne 0 ] && echo "  (exit $status: see $log)")"
  [ "$status" -eq 0 ] && [ "$found" -eq 0 ]
}
export -f run_target seeds_of
export build work dict seconds

# Two targets at a time on two cores.
printf '%s\n' "${targets[@]}" | xargs -P 2 -I{} bash -c 'run_target {}'
