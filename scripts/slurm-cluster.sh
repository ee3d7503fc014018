#!/usr/bin/env bash
# A single-node Slurm cluster for CI (tests/distributed/slurm_shards.sh), on a machine without
# systemd or cgroups: writes a config into DIR and starts munged, slurmctld and slurmd directly
# (scripts/setup-distributed.sh installs them). Needs root.
#
#   scripts/slurm-cluster.sh start DIR   # prints: export SLURM_CONF=DIR/slurm.conf
#   scripts/slurm-cluster.sh stop DIR    # stops the daemons this script started in DIR
#
# Pitfalls handled: the packages start no service here; munged runs as the munge user with its
# socket folder /run/munge; RealMemory must not exceed what `slurmd -C` reports;
# proctrack/linuxproc and task/none need no cgroups; batch_sched_delay=0 starts arrays at once.
set -euo pipefail
(($# == 2)) || { echo "usage: $0 start|stop DIR" >&2; exit 2; }
action=$1 dir=$(realpath -m "$2")

# stop_process PID_FILE: ends the process it names and waits (up to 10 s) until it has exited,
# so that its files can be removed (an exited daemon whose parent has not reaped it counts).
stop_process() {
  [[ -f $1 ]] || return 0
  local pid
  pid=$(<"$1")
  kill "$pid" 2>/dev/null || true
  for ((i = 0; i < 100; i++)); do
    local state
    state=$(ps -o stat= -p "$pid" 2>/dev/null || true)
    [[ -z $state || $state == Z* ]] && break
    sleep 0.1
  done
  rm -f "$1"
}

stop() {
  stop_process "$dir/slurmd.pid"
  stop_process "$dir/slurmctld.pid"
  stop_process "$dir/munged.started"
}

if [[ $action == stop ]]; then
  stop
  exit 0
fi
[[ $action == start ]] || { echo "usage: $0 start|stop DIR" >&2; exit 2; }

command -v slurmctld >/dev/null && command -v munged >/dev/null ||
  { echo "slurm-wlm and munge are not installed: run scripts/setup-distributed.sh" >&2; exit 1; }
mkdir -p "$dir/state" "$dir/spool"

# munge: one daemon per machine; start it unless one runs.
if ! pgrep -x munged >/dev/null; then
  mkdir -p /run/munge /var/log/munge /var/lib/munge
  chown munge:munge /run/munge /var/log/munge /var/lib/munge
  [[ -f /etc/munge/munge.key ]] || runuser -u munge -- /usr/sbin/mungekey --create
  runuser -u munge -- /usr/sbin/munged
  pgrep -x -n munged >"$dir/munged.started"
fi

host=$(hostname -s)
# slurmd -C prints the node as slurmd sees it: CPUs and RealMemory (MiB), never more than that.
node=$(slurmd -C | head -1)
cpus=$(sed -n 's/.*CPUs=\([0-9]*\).*/\1/p' <<<"$node")
memory=$(sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' <<<"$node")
cat >"$dir/slurm.conf" <<CONF
ClusterName=radiant-ci
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0
MpiDefault=none
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=ci Nodes=$host Default=YES MaxTime=10 State=UP OverSubscribe=NO
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -c   # -c: a clean start, no state from an earlier cluster
slurmd
# Ready when the node takes jobs.
for ((i = 0; i < 60; i++)); do
  state=$(sinfo -h -N -o %t 2>/dev/null | head -1 || true)
  [[ $state == idle ]] && break
  sleep 0.5
done
[[ $state == idle ]] || { echo "slurm did not come up (node state '$state'); see $dir/*.log" >&2; stop; exit 1; }
echo "export SLURM_CONF=$dir/slurm.conf"
