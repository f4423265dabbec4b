#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for trying the workflows' job arrays (make
# slurm-validate / slurm-sweep SUBMIT=1) without a cluster: installs Debian's slurm-wlm and
# munge if missing (as root), starts munged, slurmctld and slurmd with a configuration in DIR
# (default /tmp/hvi-slurm), and prints the SLURM_CONF to export. `stop` stops them again.
#
#   scripts/slurm-local.sh start [DIR]   # then: export SLURM_CONF=DIR/slurm.conf
#   scripts/slurm-local.sh stop [DIR]
set -euo pipefail
action="${1:-start}"
dir="${2:-/tmp/hvi-slurm}"
conf="$dir/slurm.conf"

stop() {
  for d in slurmd slurmctld; do
    [ -f "$dir/$d.pid" ] && kill "$(cat "$dir/$d.pid")" 2>/dev/null || true
  done
  rm -f "$dir"/*.pid
}

if [ "$action" = stop ]; then
  stop
  echo "slurm-local: stopped"
  exit 0
fi

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  echo "slurm-local: installing slurm-wlm and munge"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q slurm-wlm munge >/dev/null
fi
mkdir -p "$dir/state" "$dir/spool"
host="$(hostname -s)"
cpus="$(nproc)"
mem_mb="$(awk '/MemTotal/ {print int($2 / 1024 * 0.9)}' /proc/meminfo)"
cat >"$conf" <<CONF
ClusterName=hvi-local
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$cpus RealMemory=$mem_mb State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF

# munge: a key (the package makes one; make it if not) and the daemon.
if [ ! -s /etc/munge/munge.key ]; then
  mkdir -p /etc/munge
  dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
  chmod 400 /etc/munge/munge.key
fi
mkdir -p /run/munge /var/log/munge /var/lib/munge
if ! pgrep -x munged >/dev/null; then
  munged --force
fi

stop
slurmctld -f "$conf"
slurmd -f "$conf"
export SLURM_CONF="$conf"
for _ in $(seq 1 50); do
  if sinfo -h -o %T 2>/dev/null | grep -qE '^(idle|mixed)'; then
    echo "slurm-local: one node ($host, $cpus CPUs) up; export SLURM_CONF=$conf"
    exit 0
  fi
  sleep 0.2
done
echo "slurm-local: the node did not come up; see $dir/slurmctld.log and $dir/slurmd.log" >&2
exit 1
