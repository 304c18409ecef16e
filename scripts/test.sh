#!/usr/bin/env bash
# The second README command: install, build and run every test, in Release and then under
# AddressSanitizer + UndefinedBehaviorSanitizer, plus the release checks (a fresh clone with nothing
# beside it, the Debian packages). Exits non-zero on any failure; prints the time of each phase.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# ccache (when present) keys on the compiler's command line; relative to this checkout, and without the build
# directory hashed into debug information, a second clone of the same tree hits the first one's cache.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true
jobs="$(nproc)"
start=$(date +%s)
phase_start=$start
timings=()
# CPU seconds (user + system) of every command this script has waited for: on a shared machine the wall time
# of a phase depends on the other load, its CPU time hardly; CPU / cores estimates a quiet machine's wall time.
times_file=$(mktemp)
trap 'rm -f "$times_file"' EXIT
cpu_now() {  # sets cpu_seconds; `times` must run in this shell, not in a $(...) subshell
  local user sys
  times > "$times_file"
  read -r user sys < <(tail -n 1 "$times_file")
  cpu_seconds=$(( $(minutes_seconds "$user") + $(minutes_seconds "$sys") ))
}
minutes_seconds() {  # "1m2.345s" -> 62
  local t=$1 seconds
  seconds=${t#*m}
  seconds=${seconds%s}
  echo $(( ${t%%m*} * 60 + 10#${seconds%.*} ))
}
cpu_now
phase_cpu=$cpu_seconds
phase_done() {
  local now
  now=$(date +%s)
  cpu_now
  timings+=("$1: $(( now - phase_start )) s (CPU $(( cpu_seconds - phase_cpu )) s)")
  phase_start=$now
  phase_cpu=$cpu_seconds
}

echo "== Release build"
cmake --preset release -DMARIS_WERROR=ON
cmake --build --preset release -j "$jobs"
phase_done "Release build"
echo "== Release tests"
ctest --preset release -j "$jobs" --timeout 600
phase_done "Release tests"

if [ -x scripts/ci_fresh_clone_check.sh ] || [ -f scripts/ci_fresh_clone_check.sh ]; then
  echo "== A fresh clone with nothing beside it"
  bash scripts/ci_fresh_clone_check.sh
  phase_done "Fresh clone check"
fi
if [ -f scripts/ci_package_check.sh ]; then
  echo "== Debian packages"
  bash scripts/ci_package_check.sh build/release
  phase_done "Package check"
fi

echo "== ASan + UBSan build"
cmake --preset asan -DMARIS_WERROR=ON
cmake --build --preset asan -j "$jobs"
phase_done "ASan + UBSan build"
echo "== ASan + UBSan tests"
ctest --preset asan -j "$jobs" --timeout 1200
phase_done "ASan + UBSan tests"

echo "== phase times"
printf '   %s\n' "${timings[@]}"
cpu_now
echo "== all tests passed in $(( $(date +%s) - start )) s (CPU $cpu_seconds s on $jobs cores)"
