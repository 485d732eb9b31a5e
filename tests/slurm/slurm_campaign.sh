#!/usr/bin/env bash
# A campaign on a real single-node Slurm (issue 14), started by this script and stopped on any
# exit: its own munge key and socket, slurm.conf, state and spool folders in a scratch folder,
# munged, slurmctld and slurmd on localhost, nothing of the machine's own Slurm or munge
# touched. Two batch jobs run the small test campaign on 2 processes, as campaigns/README.md's
# sbatch example does: `mpirun --oversubscribe -np 2` inside the allocation, and
# `srun -n 2 --mpi=pmix` (Debian's Open MPI joins a Slurm step through PMIx only: it has no PMI2
# component). A third job runs the campaign under `srun --mpi=none`, which Open MPI cannot join:
# it must fail with growthuq's one message and leave no results; a fourth under
# `srun --mpi=pmi2`, which Open MPI's MPI_Init refuses itself: it must fail and leave nothing. The first two jobs' summary.csv
# and samples.csv must equal a serial run's byte for byte, and results.h5 value for value.
# Exits 77 (skipped) when not root or when the daemons cannot start, with the reason.
# Usage: slurm_campaign.sh CLI CAMPAIGN COMPARE_H5 WORK
set -euo pipefail

cli=$1 campaign=$2 compare=$3 work=$4
skip() { echo "SKIPPED: $*" >&2; exit 77; }

((EUID == 0)) || skip "the Slurm daemons must be started as root (running as uid $EUID)"
for program in munged mungekey slurmctld slurmd sbatch squeue sinfo mpirun; do
  command -v "$program" >/dev/null || skip "$program is not installed (bash tools/install-deps installs slurm-wlm and munge)"
done

rm -rf "$work"
mkdir -p "$work"/{state,spool,munge,jobs,tmp}
chmod 700 "$work/munge"
daemons=()
stop_daemons() {
  local pid
  for pid in "${daemons[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${daemons[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
}
trap stop_daemons EXIT
# The daemons' logs, shown when something fails.
show_logs() {
  local log
  for log in "$work"/munged.log "$work"/slurmctld.log "$work"/slurmd.log; do
    [[ -f $log ]] && { echo "--- $log (last lines)" >&2; tail -n 20 "$log" >&2; }
  done
  return 0
}

# munge: a key of this test's own and a socket in the scratch folder.
mungekey --create --keyfile="$work/munge/munge.key" >/dev/null || skip "mungekey could not make a key"
munged --force --foreground --socket="$work/munge/socket" --key-file="$work/munge/munge.key" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/seed" --log-file="$work/munged.log" \
  2>>"$work/munged.log" &
daemons+=($!)
for _ in $(seq 50); do [[ -S $work/munge/socket ]] && break; sleep 0.1; done
[[ -S $work/munge/socket ]] || { show_logs; skip "munged did not start"; }

# Ports of this test's own (the machine may run another Slurm): two free ones above 20000.
free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}
host=$(hostname -s)
export SLURM_CONF=$work/slurm.conf
cat >"$SLURM_CONF" <<EOF
ClusterName=growthuqtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
# The PMIx plugin's per-step folders (else in /tmp, where another run of this test would meet them)
TmpFS=$work/tmp
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SchedulerType=sched/builtin
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=10 State=UP
EOF
slurmctld -D -i -f "$SLURM_CONF" >"$work/slurmctld.out" 2>&1 &
daemons+=($!)
slurmd -D -f "$SLURM_CONF" -N "$host" >"$work/slurmd.out" 2>&1 &
daemons+=($!)
node_state=""
for _ in $(seq 100); do
  node_state=$(sinfo -h -N -o %t 2>/dev/null || true)
  [[ $node_state == idle ]] && break
  sleep 0.2
done
if [[ $node_state != idle ]]; then
  cat "$work"/slurmctld.out "$work"/slurmd.out >&2 || true
  show_logs
  skip "the node did not become idle (state '${node_state:-no answer from slurmctld}')"
fi
echo "Slurm is up: node $host, $(sinfo -h -o '%C') CPUs (allocated/idle/other/total)"

# The serial reference.
"$cli" run "$campaign" --quiet --formats csv,hdf5 --out "$work/serial" >"$work/serial.out"

# One batch job per way of starting the processes, written as campaigns/README.md's sbatch example.
submit() {
  local name=$1 launch=$2
  cat >"$work/jobs/$name.sbatch" <<EOF
#!/bin/bash
#SBATCH --job-name=$name
#SBATCH --ntasks=2
#SBATCH --output=$work/jobs/$name.log
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
$launch "$cli" run "$campaign" --quiet --formats csv,hdf5 --out "$work/$name"
EOF
  sbatch --parsable "$work/jobs/$name.sbatch"
}
declare -A jobs
jobs[mpirun]=$(submit mpirun "mpirun --oversubscribe -np 2")
jobs[srun]=$(submit srun "srun -n 2 --mpi=pmix")
jobs[unjoinable]=$(submit unjoinable "srun -n 2 --mpi=none")
jobs[pmi2]=$(submit pmi2 "srun -n 2 --mpi=pmi2")

# Waits for the jobs (they run one after the other on 2 CPUs), then their exit codes.
for _ in $(seq 600); do
  [[ -z $(squeue -h -o %i 2>/dev/null) ]] && break
  sleep 0.2
done
[[ -z $(squeue -h -o %i) ]] || { show_logs; echo "FAIL: the jobs did not finish in 120 s" >&2; exit 1; }
job_state() { scontrol show job "$1" | grep -o 'JobState=[A-Z_]*' | cut -d= -f2; }

failed=0
for name in mpirun srun; do
  state=$(job_state "${jobs[$name]}")
  if [[ $state != COMPLETED ]]; then
    echo "FAIL: the $name job ended $state:" >&2
    cat "$work/jobs/$name.log" >&2
    failed=1
    continue
  fi
  for file in summary.csv samples.csv; do
    if ! cmp -s "$work/serial/$file" "$work/$name/$file"; then
      echo "FAIL: $file of the $name job differs from the serial run's" >&2
      failed=1
    fi
  done
  if ! /usr/bin/python3 "$compare" "$work/serial/results.h5" "$work/$name/results.h5"; then
    echo "FAIL: results.h5 of the $name job differs from the serial run's" >&2
    failed=1
  fi
  echo "$name job: results identical to the serial run"
done

# The unjoinable launch: a failed job, the engine's message once per process, no results.
state=$(job_state "${jobs[unjoinable]}")
log=$work/jobs/unjoinable.log
if [[ $state != FAILED ]]; then
  echo "FAIL: the srun --mpi=none job ended $state, expected FAILED:" >&2
  cat "$log" >&2
  failed=1
elif ! grep -q 'cannot join the other processes' "$log"; then
  echo "FAIL: the srun --mpi=none job did not fail with growthuq's message:" >&2
  cat "$log" >&2
  failed=1
elif [[ $(grep -c 'cannot join the other processes' "$log") != 1 ]]; then
  echo "FAIL: the srun --mpi=none job's message is not there exactly once:" >&2
  cat "$log" >&2
  failed=1
elif [[ -e $work/unjoinable ]]; then
  echo "FAIL: the srun --mpi=none job made $work/unjoinable" >&2
  failed=1
else
  echo "srun --mpi=none job: stopped with: $(grep -m1 'cannot join' "$log")"
fi

# PMI2, which Debian's Open MPI does not speak: MPI_Init itself stops both tasks, before anything
# is written.
state=$(job_state "${jobs[pmi2]}")
if [[ $state != FAILED ]]; then
  echo "FAIL: the srun --mpi=pmi2 job ended $state, expected FAILED:" >&2
  cat "$work/jobs/pmi2.log" >&2
  failed=1
elif [[ -e $work/pmi2 ]]; then
  echo "FAIL: the srun --mpi=pmi2 job made $work/pmi2" >&2
  failed=1
else
  echo "srun --mpi=pmi2 job: stopped by MPI_Init, nothing written"
fi

if ((failed)); then
  show_logs
  exit 1
fi
stop_daemons
daemons=()
rm -rf "$work"
