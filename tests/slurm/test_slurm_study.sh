#!/bin/bash
# A study through a real one-node Slurm cluster: `maris-cli study submit --engine slurm` writes the cases and
# an sbatch job array and submits it with a dependent collect job; when both are done, study.csv must equal,
# byte for byte, that of a local `study run` of the same study. The cluster is started in a scratch folder
# and its daemons stopped by PID on every exit (tests/slurm/start_cluster.sh, stop_cluster.sh).
#   test_slurm_study.sh MARIS_CLI
# Exit 77 (skipped) without root or without Slurm, except in CI (CI=true), where that is a failure.
set -uo pipefail
maris=${1:?usage: test_slurm_study.sh MARIS_CLI}
here=$(cd "$(dirname "$0")" && pwd)

skip() {
  if [ "${CI:-}" = "true" ]; then
    echo "FAIL (CI=true, so this test may not be skipped): $1" >&2
    exit 1
  fi
  echo "SKIP: $1" >&2
  exit 77
}
[ "$(id -u)" = 0 ] || skip "needs root to start slurmctld, slurmd and munged"
for program in munged slurmctld slurmd sbatch squeue; do
  command -v "$program" >/dev/null || skip "$program is missing (scripts/install-deps.sh installs slurm-wlm and munge)"
done

scratch=$(mktemp -d "${TMPDIR:-/tmp}/maris_slurm.XXXXXX")
cleanup() {
  "$here/stop_cluster.sh" "$scratch"
  if [ "${MARIS_KEEP_SLURM_SCRATCH:-}" = "" ]; then rm -rf "$scratch"; else echo "kept $scratch"; fi
}
trap cleanup EXIT
fail() {
  echo "FAIL: $1" >&2
  for log in "$scratch"/log/*.log "$scratch"/out/slurm/logs/*; do
    [ -f "$log" ] && { echo "--- $log" >&2; tail -n 20 "$log" >&2; }
  done
  exit 1
}

"$here/start_cluster.sh" "$scratch" || fail "the cluster did not start"
export SLURM_CONF="$scratch/slurm.conf"

# 12 riser cantilevers (statics, milliseconds each): 4 array tasks of 3 cases, at most 2 at once.
cat > "$scratch/study.json" <<'JSON'
{"format": "maris-study/1", "name": "slurm test", "base": "riser_cantilever_tip_load",
 "grid": {"geometry.length": {"from": 10, "to": 30, "count": 4}, "section.youngs_modulus": [1.5e11, 2.07e11, 2.5e11]}}
JSON
t0=$(date +%s.%N)
"$maris" study submit "$scratch/study.json" --out "$scratch/out" --engine slurm --cases-per-task 3 --max-parallel 2 \
  --time 00:10:00 --no-plots || fail "study submit failed"
t1=$(date +%s.%N)
array=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["array_job"])' "$scratch/out/slurm/jobs.json")
collect=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["collect_job"])' "$scratch/out/slurm/jobs.json")
[ -n "$array" ] && [ -n "$collect" ] || fail "jobs.json names no jobs"

# Without accounting there is no sacct: a job is done when squeue no longer lists it.
for _ in $(seq 1 600); do
  [ -z "$(squeue -h -j "$array,$collect" 2>/dev/null)" ] && break
  sleep 0.5
done
[ -z "$(squeue -h -j "$array,$collect" 2>/dev/null)" ] && [ -z "$(squeue -h 2>/dev/null)" ] ||
  fail "the jobs did not end within 300 s"
t2=$(date +%s.%N)
[ -f "$scratch/out/study.csv" ] || fail "the collect job wrote no study.csv"
grep -q "12 cases: 12 ok" "$scratch"/out/slurm/logs/collect-*.out || fail "the collect job did not find 12 complete cases"
[ "$(ls "$scratch"/out/slurm/logs/cases-*.out | wc -l)" = 4 ] || fail "expected 4 array task logs"

"$maris" study run "$scratch/study.json" --out "$scratch/local" --jobs 2 --no-plots >/dev/null 2>&1 ||
  fail "the local study run failed"
t3=$(date +%s.%N)
cmp "$scratch/out/study.csv" "$scratch/local/study.csv" || fail "study.csv from Slurm differs from the local run's"
python3 -c "import sys; t0,t1,t2,t3=map(float,sys.argv[1:]); print(f'slurm: submit {t1-t0:.2f} s, submit to collected {t2-t0:.2f} s; local study run {t3-t2:.2f} s')" \
  "$t0" "$t1" "$t2" "$t3"
echo "PASS: 12 cases through Slurm (4 array tasks and a collect job) give the local study.csv"
