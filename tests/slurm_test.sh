#!/usr/bin/env bash
# A real Slurm, not a mock: starts a single-node cluster on this machine (munged, slurmctld,
# slurmd), submits a small sweep with scripts/slurm/submit (a job array of 4 shards, then the
# merge job, sbatch --wait), checks the merged error columns against the unsharded run bit for
# bit (merge --same-as), and stops the daemons it started, by their pids. CI runs it as root
# (.ci/run) after scripts/test has built build/aabench; docs/cluster.md.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $(id -u) -ne 0 ]]; then
  echo "slurm_test: skipped: starting munged, slurmctld and slurmd needs root (CI runs it as root)"
  exit 0
fi
if ! command -v apt-get >/dev/null; then
  echo "slurm_test: skipped: needs Debian's slurm-wlm and munge packages (apt-get)"
  exit 0
fi
scripts/install-deps slurm-wlm munge
aabench=$PWD/build/aabench
[[ -x $aabench ]] || { echo "slurm_test: no $aabench: run scripts/build first" >&2; exit 1; }
start_ns=$(date +%s%N)
work=$(mktemp -d /tmp/aabench_slurm.XXXXXX)
chmod 755 "$work"
started=()  # pids of the daemons this test started, stopped in reverse order at exit
stop_daemons() {
  local rc=$?
  for ((i = ${#started[@]} - 1; i >= 0; --i)); do
    kill "${started[i]}" 2>/dev/null || true
    # Not `wait`: munged was started through setpriv's exec, still our child; a few seconds.
    for _ in $(seq 50); do kill -0 "${started[i]}" 2>/dev/null || break; sleep 0.1; done
  done
  if [[ $rc -ne 0 ]]; then
    echo "slurm_test: FAILED; the daemons' logs:" >&2
    tail -n 20 "$work"/*.log >&2 || true
  fi
  rm -rf "$work"
}
trap stop_daemons EXIT

# munged as the munge user, on its default socket in /run/munge (slurm's auth/munge looks there);
# one already serving it (a machine with munge running) is used as it is.
if ! munge -n </dev/null >/dev/null 2>&1; then
  mkdir -p /run/munge
  chown munge:munge /run/munge
  chmod 755 /run/munge
  [[ -f /etc/munge/munge.key ]] || setpriv --reuid=munge --regid=munge --clear-groups mungekey --create
  setpriv --reuid=munge --regid=munge --clear-groups /usr/sbin/munged --foreground \
    --log-file="$work/munged.log" >"$work/munged.out" 2>&1 &
  started+=($!)
  for _ in $(seq 100); do munge -n </dev/null >/dev/null 2>&1 && break; sleep 0.1; done
  munge -n </dev/null | unmunge >/dev/null
fi

host=$(hostname -s)  # slurmd matches its short name against NodeName
memory_mib=$(awk '/^MemTotal/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)
port=$((20000 + RANDOM % 20000))  # away from the default 6817/6818 of a real installation
export SLURM_CONF=$work/slurm.conf
mkdir -p "$work/state" "$work/spool"
cat >"$SLURM_CONF" <<CONF
ClusterName=aabench-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$memory_mib State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
# In the foreground (-D) so that $! is the daemon; their output goes to their logs.
/usr/sbin/slurmctld -D -f "$SLURM_CONF" >"$work/slurmctld.out" 2>&1 &
started+=($!)
/usr/sbin/slurmd -D -f "$SLURM_CONF" >"$work/slurmd.out" 2>&1 &
started+=($!)
for _ in $(seq 300); do
  [[ $(sinfo -h -o %T 2>/dev/null) == idle ]] && break
  sleep 0.2
done
[[ $(sinfo -h -o %T) == idle ]] || { echo "slurm_test: the node did not come up" >&2; exit 1; }
echo "slurm_test: single-node Slurm up on $host ($(sinfo -h -o '%c CPUs, %m MiB'))"

# The sweep: two patterns, three methods (box-multiscan with its sweep over n), 32x32.
opts=(--methods none,exact,box-multiscan --patterns star,strips --size 32x32 --runs 1 --sweep
      --no-hardcases)
"$aabench" compare "${opts[@]}" --quiet --out "$work/whole"
AABENCH=$aabench AABENCH_SAME_AS=$work/whole timeout 600 \
  scripts/slurm/submit --wait "$work/sweep" 4 "${opts[@]}" | tee "$work/submit.out"

array=$(sed -n 's/^submitted: array job \([0-9]*\).*/\1/p' "$work/submit.out")
echo "slurm_test: the array's tasks:"
scontrol -o show job "$array" | grep -o 'ArrayTaskId=[0-9]* .*JobState=[A-Z]*' |
  sed 's/ .*JobState=/ JobState=/' | sort | tee "$work/tasks.txt"
[[ $(grep -c 'JobState=COMPLETED' "$work/tasks.txt") -eq 4 ]]
for log in "$work"/sweep/slurm-shard-*.out; do head -n 1 "$log"; done
echo "slurm_test: the merge job's log:"
cat "$work"/sweep/slurm-merge-*.out | sed -n '/^aabench merge/p;/^  shard/,$p'
grep -q '^merged == unsharded' "$work"/sweep/slurm-merge-*.out
echo "slurm_test: passed in $(( ($(date +%s%N) - start_ns) / 1000000 )) ms (4 array tasks, the merge job, merged == unsharded)"
