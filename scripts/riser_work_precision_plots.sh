#!/usr/bin/env bash
# The three riser work-precision PNGs from an existing bench CSV (no bench run): one series per
# (variant, method) or (method, n), points in cost order, failed rows listed under the plot.
# Usage: scripts/riser_work_precision_plots.sh [BUILD (GUI build, default build/gui)] [CSV (default
#        docs/riser_work_precision.csv)] [IMAGES (default docs/images)] [CASE5_N (100)] [CABLE_N (50)]
# CASE5_N / CABLE_N: the n of the per-n plots (variant × method). The _case5_n plot has every n of J3; its
# error is against the J3 reference at the finest n (CSV column finest_n: 400 for every row).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/gui}
csv=${2:-docs/riser_work_precision.csv}
images=${3:-docs/images}
case5_n=${4:-100}
cable_n=${5:-50}
plot=("$build/bench/work_precision_plot")
[ -x "${plot[0]}" ] || { echo "no ${plot[0]}: build the target work_precision_plot in a GUI build" >&2; exit 2; }
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}
axes=(--x cpu_time --xlabel "CPU time [s]" --ylabel "error [-]" --detail setting)
"${plot[@]}" "$csv" "$images/riser_work_precision_case5.png" "${axes[@]}" --y error_same_n \
  --series variant,method --where case=case5 --where n="$case5_n" \
  --title "Riser case 5, n = $case5_n: CPU time against error (same-n reference)"
"${plot[@]}" "$csv" "$images/riser_work_precision_cable3d.png" "${axes[@]}" --y error_same_n \
  --series variant,method --where case=cable3d --where n="$cable_n" \
  --title "3D cable, n = $cable_n: CPU time against error (same-n reference)"
"${plot[@]}" "$csv" "$images/riser_work_precision_case5_n.png" "${axes[@]}" --y error_finest_n \
  --series method,n --where case=case5 --where variant=J3 \
  --title "Riser case 5, J3: CPU time against error (J3 reference at the finest n, 400: discretisation + time)"
