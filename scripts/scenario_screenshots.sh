#!/usr/bin/env bash
# Shoots the window with every built-in scenario at one window size, for looking the program over at the size a
# user has (clipped labels, overlapping text, empty views): `maris --screenshot` runs each scenario off-screen
# under Xvfb and saves OUT_DIR/<scenario>.png. The pictures are for reading, not for the repository (the guide's
# own pictures are made by scripts/guide_screenshots.sh).
#
# Usage: scripts/scenario_screenshots.sh OUT_DIR [WxH] [BUILD_DIR] [SCENARIO...]
#   WxH        window size (default 1366x768, the most common laptop screen)
#   BUILD_DIR  default build/release; needs BUILD_DIR/app/maris and BUILD_DIR/app/maris-cli
#   SCENARIO   only these (default: all of them, as `maris-cli list` names them)
# Needs xvfb-run (package xvfb). Exits non-zero if a screenshot failed, after trying the others.
set -euo pipefail

[ $# -ge 1 ] || { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$1"
size="${2:-1366x768}"
build="${3:-build/release}"
shift $(( $# < 3 ? $# : 3 ))
case "$build" in /*) ;; *) [ -d "$build" ] || build="$root/$build" ;; esac
maris="$build/app/maris"
cli="$build/app/maris-cli"
for exe in "$maris" "$cli"; do
  [ -x "$exe" ] || { echo "scenario_screenshots.sh: no $exe (build the targets maris and maris-cli)" >&2; exit 1; }
done
command -v xvfb-run >/dev/null || { echo "scenario_screenshots.sh: xvfb-run is missing (package xvfb)" >&2; exit 1; }
[[ "$size" =~ ^[0-9]+x[0-9]+$ ]] || { echo "scenario_screenshots.sh: size $size is not WxH" >&2; exit 1; }

if [ $# -gt 0 ]; then
  scenarios=("$@")
else
  # `maris-cli list`: one scenario a line, its name first.
  mapfile -t scenarios < <("$cli" list | awk 'NF && $1 ~ /^[a-z0-9_]+$/ {print $1}')
fi
mkdir -p "$out"
failed=0
for s in "${scenarios[@]}"; do
  echo "== $s"
  if ! QT_QPA_PLATFORM=xcb LC_ALL=C.UTF-8 xvfb-run -a -s "-screen 0 1920x1200x24" \
       "$maris" --screenshot "$out/$s.png" --scenario "$s" --size "$size"; then
    echo "scenario_screenshots.sh: $s failed" >&2
    failed=1
  fi
done
echo "wrote ${#scenarios[@]} pictures to $out ($size)"
exit "$failed"
