#!/usr/bin/env bash
# CTest's paraview.RunXdmf: runs hvi-run on a small two-block scene (an SPH projectile and
# bumper striking FE layers, 3 us: particles are deleted, elements erode, nodes are orphaned),
# then opens its run.xmf in ParaView (check_run_xdmf.py) under a virtual X server.
#   run_xdmf_test.sh HVI_RUN SCENE OUT_DIR
set -euo pipefail
hvi_run=$1
scene=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
"$hvi_run" "$scene" --end-time-us 3 --snapshot-every-us 0.5 --threads 1 -q -o "$out/run.h5"
xvfb-run -a pvpython "$(dirname "$0")/check_run_xdmf.py" "$out/run.xmf" "$out/run.h5" \
  "$out/run.png"
test -s "$out/run.png"
