#!/usr/bin/env bash
# The source study's erosion-factor calibration (issue #5, item 4): the NASA Whipple pair
# A1076 (perforated) and A1077 (not perforated), SPH projectile and bumper, FE rear wall,
# with erosion factors 0.5, 1.0 and 1.5; then, with WHIPPLE=1, the 3.125 mm Whipple of the
# same item (1.7 mm FE rear wall at 100, 150 and 200 mm, where the NASA JSC equation predicts
# no perforation with margins of 18, 35 and 48 %) at erosion 1.5 and its own 0.05 mm spacing
# (about 7, 10 and 12 min on 2 cores). Prints one line per run and leaves the run files,
# verdicts and pictures in OUTDIR. docs/notebook/fe-erosion.md has the measured tables;
# docs/fe-erosion.md the erosion rule.
# Usage: [WHIPPLE=1] workflows/erosion-calibration/run.sh [OUTDIR] [SPACING_MM] [THREADS]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
out="${1:-$root/out/erosion-calibration}"
spacing="${2:-0.04}"
threads="${3:-$(nproc)}"
bin="$root/build/tools"
tests="$root/data/validation/thesis_cases.json"
mkdir -p "$out"
for case in A1076 A1077; do
  for factor in 0.5 1.0 1.5; do
    name="${case}_erosion_${factor}"
    sed "s/\"erosion_factor\": 1.5/\"erosion_factor\": ${factor}/" "$here/$case.json" \
      > "$out/$name.json"
    start=$(date +%s)
    "$bin/hvi-run/hvi-run" "$out/$name.json" -o "$out/$name.h5" -q --threads "$threads" \
      --resolution-mm "$spacing"
    wall=$(( $(date +%s) - start ))
    expect=()
    [ -f "$tests" ] && expect=(--expect "$tests" --case "$case")
    set +e
    line=$("$bin/hvi-assess/hvi-assess" "$out/$name.h5" -o "$out/$name.verdict.json" \
      "${expect[@]}" 2>&1 | tail -1)
    set -e
    echo "$case erosion $factor (spacing $spacing mm, ${wall} s): $line"
  done
done
if [ "${WHIPPLE:-0}" = 1 ]; then
  for scene in UM3125-Whipple UM3125-Whipple-150 UM3125-Whipple-200; do
    name="${scene}_erosion_1.5"
    cp "$here/$scene.json" "$out/$name.json"
    start=$(date +%s)
    "$bin/hvi-run/hvi-run" "$out/$name.json" -o "$out/$name.h5" -q --threads "$threads"
    wall=$(( $(date +%s) - start ))
    set +e
    line=$("$bin/hvi-assess/hvi-assess" "$out/$name.h5" -o "$out/$name.verdict.json" 2>&1 |
      tail -1)
    set -e
    echo "$scene erosion 1.5 (spacing 0.05 mm, ${wall} s; the JSC equation: NP): $line"
  done
fi
