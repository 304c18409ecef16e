#!/bin/bash
# Stops the daemons tests/slurm/start_cluster.sh started in SCRATCH, by the PIDs in their pid files (never by
# name), and waits until they are gone (SIGKILL after 10 s).
scratch=${1:?usage: stop_cluster.sh SCRATCH}
pids=()
for name in slurmd slurmctld munged; do
  file="$scratch/$name.pid"
  [ -s "$file" ] || continue
  pid=$(cat "$file")
  if kill -0 "$pid" 2>/dev/null; then
    kill "$pid" 2>/dev/null && pids+=("$pid")
  fi
done
for _ in $(seq 1 100); do
  alive=0
  for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null && alive=1; done
  [ "$alive" = 0 ] && exit 0
  sleep 0.1
done
for pid in "${pids[@]}"; do kill -9 "$pid" 2>/dev/null; done
exit 0
