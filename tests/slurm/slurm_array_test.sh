#!/usr/bin/env bash
# The Slurm job array (docs/scaling-out.md, 'Slurm') on a real one-node cluster: starts
# munged, slurmctld and slurmd on localhost with a private config, submits
# scripts/slurm/tactip-array.sbatch for a 4-run job in 2 array tasks, merges the parts and
# compares the result byte for byte with a one-machine 'tactip generate'. Stops every daemon
# it started, by PID, also on failure. Run by ctest (SKIP_RETURN_CODE 77).
#
# Usage: slurm_array_test.sh TACTIP_BINARY SOURCE_DIR
# Exit: 0 pass, 1 fail, 77 skip (not root, or slurm-wlm/munge not installed).
set -euo pipefail

tactip=$1
src=$2
script="$src/scripts/slurm/tactip-array.sbatch"

skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }

# --- Preconditions: root and the Debian packages slurm-wlm and munge ---------------------
[ "$(id -u)" -eq 0 ] || skip "needs root to start munged, slurmctld and slurmd"
export PATH="$PATH:/usr/sbin:/sbin"
for b in slurmctld slurmd sbatch sinfo squeue scancel munged munge unmunge runuser; do
  command -v "$b" >/dev/null || skip "$b not found (install the Debian packages slurm-wlm and munge)"
done
id munge >/dev/null 2>&1 || skip "no 'munge' user (install the Debian package munge)"
[ -x "$tactip" ] || fail "tactip binary '$tactip' not found"

# --- A private folder for the cluster's config, state, logs and the job's files ----------
work=$(mktemp -d "${TMPDIR:-/tmp}/tactip-slurm-test.XXXXXX")
chmod 755 "$work"
pids=()  # daemons started here, in start order

# True while process $1 runs (a child that exited but is not yet reaped does not count).
alive() {
  local state
  state=$(awk '{print $3}' "/proc/$1/stat" 2>/dev/null) || return 1
  [ -n "$state" ] && [ "$state" != Z ]
}

# Stops what this script started: jobs of the private cluster, then the daemons in reverse
# order (TERM, then KILL after 10 s), each by its PID. Keeps the logs when failing.
cleanup() {
  local rc=$?
  set +e
  [ -n "${sbatch_pid:-}" ] && kill -TERM "$sbatch_pid" 2>/dev/null
  if [ ${#pids[@]} -gt 0 ] && [ -n "${SLURM_CONF:-}" ]; then
    for job in $(squeue -h -o %A 2>/dev/null | sort -u); do scancel "$job" 2>/dev/null; done
  fi
  for ((k = ${#pids[@]} - 1; k >= 0; k--)); do
    local pid=${pids[k]}
    kill -TERM "$pid" 2>/dev/null
    for _ in $(seq 100); do alive "$pid" || break; sleep 0.1; done
    alive "$pid" && kill -KILL "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
  done
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 77 ]; then
    for log in "$work"/*.log "$work"/munge/*.log "$work"/out/*.log; do
      [ -f "$log" ] && { echo "--- $log"; tail -n 30 "$log"; }
    done
  fi
  rm -rf "$work"
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

# Ports nothing listens on, from a range unlikely to be used (Slurm's defaults are
# 6817/6818; a private pair lets this test run beside a real cluster).
free_port() {
  local p
  for ((p = $1; p < $1 + 200; p++)); do
    (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null || { echo "$p"; return; }
  done
  fail "no free port in $1-$(($1 + 199))"
}
base=$((27000 + ($$ % 500) * 4))
ctld_port=$(free_port "$base")
slurmd_port=$(free_port $((ctld_port + 1)))

# --- munge: the installed key, a private socket, run as the munge user -------------------
[ -s /etc/munge/munge.key ] || runuser -u munge -- mungekey --create
install -d -o munge -g munge -m 755 "$work/munge"
sock="$work/munge/munge.socket"
# In the foreground under runuser (a child of this script, so it is reaped here): keep
# runuser's PID and, once it has written its pid file, munged's.
runuser -u munge -- munged -F --socket="$sock" --pid-file="$work/munge/munged.pid" \
  --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed" > "$work/munge/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 100); do munge -n -S "$sock" 2>/dev/null | unmunge -S "$sock" >/dev/null 2>&1 && break; sleep 0.1; done
munge -n -S "$sock" | unmunge -S "$sock" >/dev/null || fail "munged did not start"
pids+=("$(cat "$work/munge/munged.pid")")

# --- slurm.conf: one node (this host, all its cores), no cgroups, no accounting ----------
host=$(hostname -s)
cpus=$(nproc)
mem=$(awk '/^MemTotal:/ {print int($2 / 1024 / 2)}' /proc/meminfo)
mkdir -p "$work/state" "$work/spool" "$work/out"
cat > "$work/slurm.conf" <<EOF
ClusterName=tactiptest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$sock
CredType=cred/munge
MailProg=/bin/true
MpiDefault=none
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=tactip Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$work/slurm.conf"

# --- slurmctld and slurmd in the foreground of background jobs; wait for an idle node -----
slurmctld -D -i -f "$SLURM_CONF" > "$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" > "$work/slurmd.out" 2>&1 &
pids+=($!)
state=""
for _ in $(seq 300); do
  state=$(sinfo -h -o %t 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.2
done
[ "$state" = idle ] || fail "node not idle after 60 s (sinfo says '$state')"
echo "cluster up: $host, $cpus CPUs, ports $ctld_port/$slurmd_port"

# --- The job: 4 quick runs in 2 array tasks, and the same job on one machine --------------
job_args=(rail --runs 4 --seed 11 --quiet --speed-mm-s 3 --set rail.lift_mm=5 --set rail.hold_s=0.1
  --set rail.settle_s=0.05 --set rail.post_fall_s=0.05)
"$tactip" generate "${job_args[@]}" --jobs 1 --out "$work/one.h5" > /dev/null
# sbatch --wait blocks until every task has ended; in the background so that a signal
# reaches the cleanup at once.
(cd "$work/out" && TACTIP="$tactip" exec timeout 180 sbatch --parsable --array=0-1 --wait "$script" \
  "${job_args[@]}" > "$work/sbatch.out") &
sbatch_pid=$!
wait "$sbatch_pid" || fail "array job failed (sbatch exit $?)"
sbatch_pid=""
job=$(cat "$work/sbatch.out")
echo "array job $job finished"
for i in 0 1; do
  log="$work/out/tactip-shard-${job}_$i.log"
  [ -f "$work/out/part$i.h5" ] || fail "task $i wrote no part$i.h5"
  grep -q "^shard        $i/2: " "$log" || fail "task $i did not write shard $i/2: $(cat "$log")"
done

# --- Merge and compare byte for byte ---------------------------------------------------------
"$tactip" merge "$work"/out/part*.h5 --out "$work/all.h5" --quiet > /dev/null
cmp "$work/one.h5" "$work/all.h5" || fail "merged file differs from the one-machine file"
echo "PASS: 2 Slurm array tasks merged into the one-machine file byte for byte"
