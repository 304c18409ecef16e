#!/bin/bash
# Starts a one-node Slurm cluster (MUNGE, slurmctld, slurmd from Debian's slurm-wlm and munge packages) whose
# every file lives in SCRATCH, on ports of its own, so it never touches a system cluster or another test's:
#   tests/slurm/start_cluster.sh SCRATCH      -> SCRATCH/slurm.conf; the daemons' PIDs in SCRATCH/*.pid
#   export SLURM_CONF=SCRATCH/slurm.conf      (sbatch, squeue, sinfo then talk to it)
#   tests/slurm/stop_cluster.sh SCRATCH       stops exactly these daemons, by PID
# Needs root (the daemons run as root; jobs run as the submitting user). Exits 1 with a message on failure.
set -euo pipefail
scratch=${1:?usage: start_cluster.sh SCRATCH}
mkdir -p "$scratch"/{state,spool,log,munge}
chmod 700 "$scratch/munge"
host=$(hostname -s)
cpus=$(nproc)
memory_mib=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 * 8 / 10 ))
# Ports of this cluster: from the shell's PID, so two clusters on one machine do not meet.
controller_port=$(( 20000 + ($$ % 4000) * 2 ))
node_port=$(( controller_port + 1 ))

munged --force --socket="$scratch/munge/munge.socket" --pid-file="$scratch/munged.pid" \
  --log-file="$scratch/log/munged.log" --seed-file="$scratch/munge/munged.seed"

cat > "$scratch/slurm.conf" <<CONF
ClusterName=maris-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$controller_port
SlurmdPort=$node_port
AuthType=auth/munge
AuthInfo=socket=$scratch/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$scratch/state
SlurmdSpoolDir=$scratch/spool
SlurmctldPidFile=$scratch/slurmctld.pid
SlurmdPidFile=$scratch/slurmd.pid
SlurmctldLogFile=$scratch/log/slurmctld.log
SlurmdLogFile=$scratch/log/slurmd.log
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MaxArraySize=100001
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory_mib State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$scratch/slurm.conf"
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
# The node is usable when sinfo reports it idle (a few seconds).
for _ in $(seq 1 60); do
  if sinfo -h -o '%t' 2>/dev/null | grep -q '^idle'; then
    echo "slurm: one node ($host, $cpus CPUs) on ports $controller_port/$node_port, SLURM_CONF=$SLURM_CONF"
    exit 0
  fi
  sleep 0.5
done
echo "slurm: the node did not become idle within 30 s; see $scratch/log" >&2
sinfo >&2 || true
exit 1
