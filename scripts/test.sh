#!/usr/bin/env bash
# The README's test command: installs what is missing (ParaView too, for the test that opens a
# run in it), builds, runs the whole suite (CTest), then the reduced sanitizer and fuzz jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --paraview
bash scripts/build.sh
# The ParaView test registers itself only where ParaView is installed: here it must run.
# (The listing is read whole first: grep -q on a pipe may close it early, and under pipefail
# ctest's SIGPIPE would fail the check at random.)
listed=$(ctest --test-dir build -N -L paraview)
grep -q "paraview.RunXdmf" <<<"$listed" ||
  { echo "test.sh: the ParaView test is not registered (pvpython or xvfb-run missing)" >&2; exit 1; }
ctest --test-dir build --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"
# The reduced sanitizer and fuzz jobs (docs/reliability.md): the unit tests and the CLI tests
# of hostile input under AddressSanitizer and UBSan, then each fuzz target for 45 s.
bash scripts/test-sanitizers.sh
bash scripts/fuzz.sh --seconds 45
