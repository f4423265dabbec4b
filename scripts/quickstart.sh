#!/usr/bin/env bash
# The README's first command: install what is missing, build, and run the design workflow
# on the built-in default case (results in out/default/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
bash workflows/default/run.sh "$@"
