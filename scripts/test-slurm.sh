#!/usr/bin/env bash
# The Slurm path against a real scheduler: starts a one-node Slurm on localhost
# (scripts/slurm-local.sh, installing slurm-wlm and munge if missing; needs root), runs the
# workflow's Slurm tests (CTest cli.slurm_workflow: job arrays submitted with SUBMIT=1 and
# collected), and stops the cluster. CI runs the same tests without a cluster, where the
# submission test is skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=/tmp/hvi-slurm-test
bash scripts/slurm-local.sh start "$dir"
trap 'bash scripts/slurm-local.sh stop "$dir"' EXIT
export SLURM_CONF="$dir/slurm.conf"
build/tests/test_cli_slurm_workflow
