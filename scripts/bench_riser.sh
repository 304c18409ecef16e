#!/usr/bin/env bash
# Riser work-precision benchmark, meant for a quiet machine: builds the Release bench (and
# the PNG tool when the build has the GUI), runs it on one core, and writes
#   docs/riser_work_precision.csv   every row (Maris CSV layout)
#   docs/riser_work_precision.md    markdown tables: right-hand-side cost against n (linear growth),
#                                   case 5 at n = 100, error and cost against n; load average noted
#   docs/riser_work_precision.log   the bench's own output
#   docs/images/riser_work_precision_case5.png, _cable3d.png, _case5_n.png   (GUI build only)
# Usage: scripts/bench_riser.sh [quick]
#   default: rhs cost for n = 10..1000; case 5 (36 s) for n = 10..100; the 3D cable (10 s) for n = 10, 20
#            (its torsion limit makes each doubling of n cost 4x): ≈ 8-10 min on one core of a quiet machine
#   quick:   case 5 over 3.6 s with n ≤ 20, cable n = 10, to check the pipeline (≈ 1 min; errors meaningless)
# Environment: MARIS_BENCH_BUILD (default build/release; configured as Release if missing),
#              MARIS_BENCH_OUT (default docs), MARIS_BENCH_NMAX (case 5, default 100; 200 adds the n = 200
#              rows, several minutes), MARIS_BENCH_CABLE_NMAX (default 20; 50: +5 min),
#              MARIS_BENCH_NLIST / MARIS_BENCH_CABLE_NLIST: comma lists of n to run instead (e.g. 400); then
#              only those rows are (re)computed and merged into the existing CSV (same key replaced), the .md
#              tables and PNGs are redrawn from the whole CSV and the log is appended to,
#              MARIS_BENCH_ROW_BUDGET: CPU seconds per run above which a run is skipped with a note giving
#              its estimated cost (default 180), MARIS_BENCH_ESTIMATE_ONLY=1: print the estimates only,
#              MARIS_BENCH_RERUN_SKIPPED=1: run only the rows the CSV has as skipped for cost or lacks (with a
#              larger MARIS_BENCH_ROW_BUDGET; MARIS_BENCH_REFERENCE_BUDGET=180 keeps the same-n references),
#              MARIS_BENCH_PLOT_CASE5_N / MARIS_BENCH_PLOT_CABLE_N: n of the per-n PNGs (default 100 and 50).
# Example (the n = 400 rows): MARIS_BENCH_NLIST=400 MARIS_BENCH_CABLE_NLIST=100,200,400 scripts/bench_riser.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build=${MARIS_BENCH_BUILD:-build/release}
out=${MARIS_BENCH_OUT:-docs}
n_max=${MARIS_BENCH_NMAX:-100}
cable_n_max=${MARIS_BENCH_CABLE_NMAX:-20}
end_time=36
if [ "${1:-}" = "quick" ]; then n_max=20; cable_n_max=10; end_time=3.6; fi

[ -f "$build/CMakeCache.txt" ] || cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
grep -q "CMAKE_BUILD_TYPE:STRING=Release" "$build/CMakeCache.txt" || { echo "$build is not a Release build" >&2; exit 2; }
targets=(bench_riser_work_precision)
with_plot=0
if grep -q "MARIS_BUILD_GUI:BOOL=ON" "$build/CMakeCache.txt"; then targets+=(work_precision_plot); with_plot=1; fi
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"

mkdir -p "$out/images"
csv="$out/riser_work_precision.csv"
start=$(date +%s)
# One core: the bench is single-threaded; pinning keeps it from migrating between the two cores.
runner=()
command -v taskset > /dev/null && runner=(taskset -c 0)
log=("$out/riser_work_precision.log")
tee_args=()
if [ -n "${MARIS_BENCH_NLIST:-}${MARIS_BENCH_CABLE_NLIST:-}" ]; then
  tee_args=(-a)  # a merged run: earlier runs' logs stay
  # Only the listed cases run (an empty list leaves that case's rows as they are).
  [ -n "${MARIS_BENCH_NLIST:-}" ] || export MARIS_BENCH_NLIST=""
  [ -n "${MARIS_BENCH_CABLE_NLIST:-}" ] || export MARIS_BENCH_CABLE_NLIST=""
fi
{ echo "# $(date -u '+%Y-%m-%d %H:%M UTC') run: NMAX=$n_max CABLE_NMAX=$cable_n_max NLIST=${MARIS_BENCH_NLIST-} CABLE_NLIST=${MARIS_BENCH_CABLE_NLIST-} budget=${MARIS_BENCH_ROW_BUDGET:-180} s; load average $(cut -d' ' -f1-3 /proc/loadavg)"
  "${runner[@]}" "$build/bench/bench_riser_work_precision" "$csv" "$n_max" "$end_time" all "$cable_n_max"
  echo "# load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"; } | tee "${tee_args[@]}" "${log[@]}"
echo "bench: $(( $(date +%s) - start )) s wall"

if [ "$with_plot" = 1 ]; then
  export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}
  scripts/riser_work_precision_plots.sh "$build" "$csv" "$out/images" "${MARIS_BENCH_PLOT_CASE5_N:-100}" \
    "${MARIS_BENCH_PLOT_CABLE_N:-50}"
else
  echo "no GUI in $build: PNGs skipped (scripts/riser_work_precision_plots.sh GUI_BUILD redraws them from the CSV)"
fi
echo "written: $csv, $out/riser_work_precision.md, $out/riser_work_precision.log"
