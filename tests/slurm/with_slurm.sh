#!/usr/bin/env bash
# Runs a command against a one-node Slurm cluster of its own, then stops the cluster.
#
#   with_slurm.sh COMMAND [ARGS...]
#
# The cluster lives in a fresh temporary folder: a munge key generated for it, munged on its
# own socket, slurmctld and slurmd on this machine (its CPUs, its own state, spool, pid and log
# files, two free TCP ports, no accounting), all started as root with this folder's
# slurm.conf. COMMAND runs once the node is idle, with SLURM_CONF set so that sbatch, squeue,
# scontrol and scancel talk to this cluster and no other. Its exit status is this script's.
#
# Whatever happens (COMMAND fails, a daemon does not start, Ctrl-C), the trap stops every
# daemon started here and every process of a job of this cluster (found by the SLURM_CONF in
# its environment), and removes the folder unless SOFTGRAIN_KEEP_SLURM_DIR=1. A daemon that
# cannot start is an error, never a skip: the script prints its log and exits with status 1.
# Needs root (slurmd starts job steps as their user) and Debian's slurm-wlm and munge
# (scripts/install-deps.sh).
set -euo pipefail

if [ $# -eq 0 ]; then
  echo "usage: $0 COMMAND [ARGS...]" >&2
  exit 2
fi
fail() {
  echo "with_slurm.sh: $*" >&2
  exit 1
}
[ "$(id -u)" -eq 0 ] || fail "needs root (slurmd runs the jobs' steps as their user)"
for tool in munged slurmctld slurmd sbatch squeue scontrol scancel sinfo; do
  command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] ||
    fail "'$tool' is missing: install slurm-wlm and munge (bash scripts/install-deps.sh)"
done
export PATH="$PATH:/usr/sbin"

umask 022  # munged refuses key, socket and log folders that others can write
# A Unix socket path has at most 107 bytes: a deep TMPDIR gives way to /tmp.
tmp=${TMPDIR:-/tmp}
[ ${#tmp} -gt 60 ] && tmp=/tmp
dir=$(mktemp -d "$tmp/softgrain-slurm.XXXXXX")
chmod 755 "$dir"  # munged refuses a socket folder writable by others; jobs must read the conf
export SLURM_CONF="$dir/slurm.conf"
pids=()
watchdog=""

# Every process started here, and every process of a job of this cluster (slurmstepd and the
# job's own processes carry SLURM_CONF in their environment; slurmstepd outlives slurmd).
cluster_processes() {
  local p
  for p in /proc/[0-9]*; do
    p=${p#/proc/}
    [ "$p" = $$ ] && continue
    if grep -qszxF "SLURM_CONF=$SLURM_CONF" "/proc/$p/environ"; then echo "$p"; fi
  done
  return 0
}

stop_cluster() {
  local status=$? p i left
  trap - EXIT INT TERM
  if [ -n "$watchdog" ]; then
    kill -TERM "$watchdog" 2>/dev/null || true
    wait "$watchdog" 2>/dev/null || true
  fi
  # Jobs first (while slurmctld can still cancel them), then the daemons, then stragglers.
  timeout 10 scancel --full --quiet --user=root >/dev/null 2>&1 || true
  for i in $(seq 1 20); do
    [ -z "$(timeout 5 squeue -h -t running,completing -o %i 2>/dev/null || true)" ] && break
    sleep 0.5
  done
  for p in "${pids[@]}"; do
    kill -TERM "$p" 2>/dev/null || true
  done
  for i in $(seq 1 50); do
    left=0
    for p in "${pids[@]}"; do
      kill -0 "$p" 2>/dev/null && left=1
    done
    [ $left -eq 0 ] && break
    sleep 0.2
  done
  for p in "${pids[@]}" $(cluster_processes); do
    kill -KILL "$p" 2>/dev/null || true
  done
  wait 2>/dev/null || true
  left=$(cluster_processes)
  if [ -n "$left" ]; then
    echo "with_slurm.sh: processes of the cluster still running: $left" >&2
    status=1
  fi
  if [ "${SOFTGRAIN_KEEP_SLURM_DIR:-0}" = 1 ]; then
    echo "with_slurm.sh: kept $dir" >&2
  else
    rm -rf "$dir"
  fi
  exit "$status"
}
trap stop_cluster EXIT
trap 'exit 130' INT TERM

show_log() {
  echo "----- $1 -----" >&2
  cat "$1" >&2 2>/dev/null || echo "(no log)" >&2
  echo "-----" >&2
}

# A TCP port no socket of this machine uses (the listening and the connected ones), below the
# ephemeral range so that no outgoing connection takes it meanwhile.
port_in_use() {
  local hex
  hex=$(printf ':%04X ' "$1")
  cat /proc/net/tcp /proc/net/tcp6 2>/dev/null | awk '{print $2}' | grep -q "${hex% }$"
}
free_port() {
  local p
  for _ in $(seq 1 200); do
    p=$((20000 + RANDOM % 12000))
    [ "$p" = "${1:-}" ] && continue
    port_in_use "$p" || { echo "$p"; return; }
  done
  fail "no free TCP port found in 20000-31999"
}
ctld_port=$(free_port)
slurmd_port=$(free_port "$ctld_port")

mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/log" "$dir/run"
chmod 700 "$dir/munge"

# munge: a key of its own, its own socket; slurm reaches it through AuthInfo=socket=.
dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/munge/munge.key"
socket="$dir/munge/munge.socket"
munged --foreground --force --socket="$socket" --key-file="$dir/munge/munge.key" \
  --log-file="$dir/log/munged.log" --pid-file="$dir/run/munged.pid" \
  --seed-file="$dir/munge/munged.seed" >"$dir/log/munged.out" 2>&1 &
pids+=($!)
for i in $(seq 1 50); do
  [ -S "$socket" ] && break
  kill -0 "${pids[-1]}" 2>/dev/null || break
  sleep 0.1
done
if [ ! -S "$socket" ]; then
  show_log "$dir/log/munged.out"
  show_log "$dir/log/munged.log"
  fail "munged did not start"
fi

host=$(hostname -s)
# The online CPUs (not nproc, which follows OMP_NUM_THREADS), at least 2 so that two tasks can
# run at once on any machine (config_overrides: slurmd takes the configured count as is).
cpus=$(getconf _NPROCESSORS_ONLN)
[ "$cpus" -ge 2 ] || cpus=2
memory_mb=$(awk '/^MemTotal:/ {print int($2 / 1024 * 0.8)}' /proc/meminfo)
cat >"$SLURM_CONF" <<CONF
# One-node test cluster written by tests/slurm/with_slurm.sh; everything in $dir.
ClusterName=softgrain-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
# Finished jobs stay visible to squeue/scontrol for 10 min (there is no accounting);
# a cancelled or timed-out task gets 5 s between SIGTERM and SIGKILL.
MinJobAge=600
KillWait=5
MaxArraySize=10001
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory_mb State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF

start_daemon() {  # name, then its command line
  local name=$1
  shift
  "$@" >"$dir/log/$name.out" 2>&1 &
  pids+=($!)
}
start_daemon slurmctld slurmctld -D -f "$SLURM_CONF"
start_daemon slurmd slurmd -D -f "$SLURM_CONF"

# Wait for the node to be idle (slurmd registered with slurmctld).
state=""
for i in $(seq 1 120); do
  for p in "${pids[@]}"; do
    kill -0 "$p" 2>/dev/null || break 2
  done
  state=$(timeout 5 sinfo -h -N -o %T 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.5
done
if [ "$state" != idle ]; then
  echo "with_slurm.sh: the node is not idle (sinfo: '${state:-no answer}')" >&2
  for log in munged.log slurmctld.out slurmctld.log slurmd.out slurmd.log; do
    show_log "$dir/log/$log"
  done
  fail "the test cluster did not start"
fi
# If this script is killed outright (SIGKILL, e.g. a test runner's time-out), the trap does not
# run: a watchdog then stops the daemons and the jobs' processes itself.
(
  trap 'exit 0' TERM
  while kill -0 $$ 2>/dev/null; do sleep 1 & wait $!; done
  for p in "${pids[@]}" $(cluster_processes); do kill -KILL "$p" 2>/dev/null; done
  rm -rf "$dir"
) </dev/null >/dev/null 2>&1 &
watchdog=$!
echo "with_slurm.sh: one-node cluster up ($cpus CPUs, ports $ctld_port/$slurmd_port, $dir)"

set +e
"$@"
status=$?
set -e
if [ $status -ne 0 ]; then
  for log in slurmctld.log slurmd.log; do
    show_log "$dir/log/$log"
  done
fi
exit $status
