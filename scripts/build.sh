#!/usr/bin/env bash
# Configures and builds the toolkit into ./build (Release, warnings as errors).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DHVI_WERROR=ON >/dev/null
cmake --build build -j "$jobs"
