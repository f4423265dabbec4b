#!/usr/bin/env bash
# Builds ./build-sanitize: the tree with clang at -O1, AddressSanitizer and
# UndefinedBehaviorSanitizer (any report fatal), and libFuzzer's coverage with the fuzz
# targets (tests/fuzz). scripts/test-sanitizers.sh runs tests there and scripts/fuzz.sh the
# fuzz targets. Needs clang, libclang-rt-14-dev and libomp-dev (scripts/install-deps.sh).
#
#   scripts/build-sanitize.sh            everything
#   scripts/build-sanitize.sh --reduced  the tools, the unit tests, the CLI tests of hostile
#                                        input, hvi-run and the pipeline, and the fuzz
#                                        targets: what CI runs (about two thirds of the build)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
if [ ! -f build-sanitize/CMakeCache.txt ]; then
  # -O1 with line tables: half the compile time of -O2 -g, and stack traces still name lines.
  # No NDEBUG: the libraries' own assertions (nlohmann::json's on absent keys) stay on.
  CC=clang CXX=clang++ cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=None \
    -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" -DCMAKE_C_FLAGS="-O1 -gline-tables-only" \
    -DHVI_SANITIZE=ON -DHVI_FUZZ=ON >/dev/null
fi
if [ "${1:-}" = "--reduced" ]; then
  mapfile -t targets < <(ninja -C build-sanitize -t targets all |
    sed -n 's/^\(tests\/test_unit_[A-Za-z0-9_]*\|tests\/test_cli_\(hostile_input\|hvi_run\|pipeline\)\|tests\/fuzz\/fuzz_[a-z_0-9]*\): .*/\1/p')
  cmake --build build-sanitize -j "$jobs" --target "${targets[@]##*/}"
else
  cmake --build build-sanitize -j "$jobs"
fi
