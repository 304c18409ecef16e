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
phase_done() {
  local now
  now=$(date +%s)
  timings+=("$1: $(( now - phase_start )) s")
  phase_start=$now
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
echo "== all tests passed in $(( $(date +%s) - start )) s"
