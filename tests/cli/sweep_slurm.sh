#!/usr/bin/env bash
# A sweep as a Slurm job array on a single-node cluster that this test starts (munged,
# slurmctld, slurmd, all on localhost with their files in a temporary directory): 3 array
# tasks run `sweep --shard $SLURM_ARRAY_TASK_ID/3`, sweep-merge joins them, and the result is
# compared byte for byte with the unsharded run. Needs root (the daemons) and the Debian
# packages slurm-wlm and munge; without them it is skipped (exit 77) and says why. Bounded: the
# job array must finish within 120 s.
set -euo pipefail
bin=$1 src=$2
skip() { echo "SKIP: $*"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "starting munged, slurmctld and slurmd needs root (CI runs as root)"
for tool in munged slurmctld slurmd sbatch squeue; do
  command -v "$tool" >/dev/null || skip "$tool is missing (Debian packages slurm-wlm and munge; .ci/run installs them)"
done

tmp=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
  rm -rf "$tmp"
}
trap cleanup EXIT
chmod 700 "$tmp"
mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool" "$tmp/work"
chmod 700 "$tmp/munge"
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
socket=$tmp/munge/munge.socket
munged -F -f --key-file="$tmp/munge/munge.key" --socket="$socket" --pid-file="$tmp/munge/munged.pid" \
  --seed-file="$tmp/munge/seed" --log-file="$tmp/munge/munged.log" > "$tmp/munged.out" 2>&1 &
pids+=($!)

# Ports from the process id, so two runs of this test on one machine do not collide.
port=$((20000 + ($$ % 20000)))
node=$(hostname -s)
cat > "$tmp/slurm.conf" <<CONF
ClusterName=pltest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SchedulerType=sched/builtin
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=lab Nodes=$node Default=YES MaxTime=10 State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf

for i in $(seq 50); do [ -S "$socket" ] && break; sleep 0.1; done
[ -S "$socket" ] || { cat "$tmp/munge/munged.log"; skip "munged did not start (log above)"; }
slurmctld -D -i > "$tmp/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D > "$tmp/slurmd.out" 2>&1 &
pids+=($!)
ready=no
for i in $(seq 100); do
  if sinfo -h -N -o '%T' 2>/dev/null | grep -Eq '^(idle|mixed|allocated)'; then ready=yes; break; fi
  sleep 0.2
done
if [ $ready != yes ]; then
  tail -n 20 "$tmp/slurmctld.log" "$tmp/slurmd.log" 2>/dev/null || true
  sinfo 2>&1 || true
  skip "the single-node cluster did not come up within 20 s (logs above)"
fi

cd "$tmp/work"
preset=$src/presets/optimal_angle.json
axes=(--axis launch.elevation_deg=20:70:11 --axis drag.model=none,quadratic --duration 6.5
      --metrics range_at_first_impact_m,apex_height_m)
"$bin" sweep "$preset" "${axes[@]}" --out whole.csv

# The job script of docs/scale-out.md: one array task per shard, resumable.
cat > sweep.sbatch <<JOB
#!/bin/bash
#SBATCH --job-name=pl-sweep
#SBATCH --array=0-2
#SBATCH --output=$tmp/work/slurm-%A_%a.out
exec "$bin" sweep "$preset" ${axes[*]} --threads 1 --shard \$SLURM_ARRAY_TASK_ID/3 --out shard\$SLURM_ARRAY_TASK_ID.csv --resume
JOB
timeout 120 sbatch --wait --chdir="$tmp/work" sweep.sbatch || {
  echo "the job array failed or timed out"; cat slurm-*.out 2>/dev/null; tail -n 30 "$tmp/slurmctld.log" "$tmp/slurmd.log"; exit 1; }
"$bin" sweep-merge shard0.csv shard1.csv shard2.csv --out merged.csv
cmp whole.csv merged.csv
echo "ok: a 3-task Slurm job array merged byte-identical to the unsharded sweep"
