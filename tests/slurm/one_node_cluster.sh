#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A one-node Slurm cluster in a temporary folder, started and stopped by this script, no systemd
# (docs/slurm.md): munged with its own key and socket, slurmctld and slurmd with a slurm.conf
# written here. Sourced by the tests that run sharded jobs through it:
#   source tests/slurm/one_node_cluster.sh; cluster_start DIR; ...; (stopped on exit)
# It needs root (slurmd starts jobs as their user) and Debian's slurm-wlm and munge
# (scripts/deps.sh). Anything missing makes cluster_start fail with a message, never skip.

cluster_pids=()
cluster_dir=""

cluster_fail() {
  echo "one-node cluster: $*" >&2
  if [ -n "$cluster_dir" ]; then
    for log in "$cluster_dir"/munged.log "$cluster_dir"/slurmctld.log "$cluster_dir"/slurmd.log; do
      [ -f "$log" ] && { echo "--- $log (last 30 lines)" >&2; tail -n 30 "$log" >&2; }
    done
  fi
  exit 1
}

cluster_stop() {
  local p jobs
  # Jobs still queued or running are this cluster's (SLURM_CONF is the test's own): cancel them
  # before their daemons go.
  if [ -n "${SLURM_CONF:-}" ] && jobs=$(timeout 10 squeue -h -o %A 2>/dev/null) && [ -n "$jobs" ]; then
    timeout 10 scancel $jobs 2>/dev/null || true
    sleep 1
  fi
  for p in "${cluster_pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${cluster_pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$p" 2>/dev/null || true
  done
  cluster_pids=()
}

# Waits up to $1 seconds for the command after it to succeed.
cluster_wait() {
  local seconds=$1
  shift
  local end=$((SECONDS + seconds))
  until "$@" >/dev/null 2>&1; do
    [ $SECONDS -lt $end ] || return 1
    sleep 0.5
  done
}

cluster_node_idle() { [ "$(sinfo -h -N -o %T 2>/dev/null)" = idle ]; }

# Starts munged, slurmctld and slurmd with everything in $1 (created), exports SLURM_CONF.
cluster_start() {
  cluster_dir=$1
  mkdir -p "$cluster_dir/state" "$cluster_dir/spool"
  chmod 711 "$cluster_dir"  # munged wants its socket folder searchable
  trap cluster_stop EXIT
  trap 'exit 1' INT TERM HUP  # so that a timeout's kill runs the EXIT trap too
  [ "$(id -u)" -eq 0 ] || cluster_fail "needs root (slurmd runs jobs as their user): run the test as root"
  local tool
  for tool in munged mungekey slurmctld slurmd sinfo sbatch squeue; do
    command -v "$tool" >/dev/null ||
      cluster_fail "$tool not found: install Debian's slurm-wlm and munge (scripts/deps.sh)"
  done
  local node memory
  node=$(hostname -s)
  memory=$(($(awk '/^MemTotal:/ {print $2}' /proc/meminfo) / 1024))
  # Ports of the test's own (the defaults 6817/6818 may belong to a real cluster on the machine);
  # SCW_SLURM_PORT moves them.
  local port=${SCW_SLURM_PORT:-16817}

  mungekey --create --keyfile="$cluster_dir/munge.key" >/dev/null 2>&1 ||
    cluster_fail "mungekey could not create $cluster_dir/munge.key"
  # --force: munged refuses to run as root otherwise; the key and socket are this cluster's.
  munged --foreground --force --key-file="$cluster_dir/munge.key" \
    --socket="$cluster_dir/munge.sock" --pid-file="$cluster_dir/munged.pid" \
    --log-file="$cluster_dir/munged.log" --seed-file="$cluster_dir/munge.seed" \
    >>"$cluster_dir/munged.log" 2>&1 &
  cluster_pids+=($!)
  cluster_wait 20 test -S "$cluster_dir/munge.sock" || cluster_fail "munged did not start"

  cat > "$cluster_dir/slurm.conf" <<CONF
ClusterName=scwtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$cluster_dir/munge.sock
StateSaveLocation=$cluster_dir/state
SlurmdSpoolDir=$cluster_dir/spool
SlurmctldPidFile=$cluster_dir/slurmctld.pid
SlurmdPidFile=$cluster_dir/slurmd.pid
SlurmctldLogFile=$cluster_dir/slurmctld.log
SlurmdLogFile=$cluster_dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
SchedulerType=sched/backfill
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
  # The addresses are loopback's: the machine's name need not resolve.
  export SLURM_CONF="$cluster_dir/slurm.conf"
  slurmctld -D -i -f "$SLURM_CONF" >>"$cluster_dir/slurmctld.log" 2>&1 &
  cluster_pids+=($!)
  slurmd -D -f "$SLURM_CONF" >>"$cluster_dir/slurmd.log" 2>&1 &
  cluster_pids+=($!)
  cluster_wait 60 cluster_node_idle ||
    cluster_fail "node $node not idle after 60 s (sinfo: $(sinfo -N 2>&1 | tr '\n' ' '))"
}
