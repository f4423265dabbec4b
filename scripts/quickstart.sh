#!/usr/bin/env bash
# The README's first command: install what is missing, build, and run the design workflow
# (make -C workflows design) on the built-in default case; results in out/design/default/.
# Arguments are passed to make, e.g. scripts/quickstart.sh RESOLUTION=0.08 END_TIME_US=10.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
make -s -C workflows design "$@"
