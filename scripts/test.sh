#!/usr/bin/env bash
# The second README command: install, build and run every test, in Release and then under
# AddressSanitizer + UndefinedBehaviorSanitizer. Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# ccache (when present) keys on the compiler's command line; relative to this checkout, and without the build
# directory hashed into debug information, a second clone of the same tree hits the first one's cache.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true
jobs="$(nproc)"
start=$(date +%s)

echo "== Release build and tests"
cmake --preset release -DMARIS_WERROR=ON
cmake --build --preset release -j "$jobs"
ctest --preset release -j "$jobs" --timeout 600

echo "== ASan + UBSan build and tests"
cmake --preset asan -DMARIS_WERROR=ON
cmake --build --preset asan -j "$jobs"
ctest --preset asan -j "$jobs" --timeout 1200

echo "== all tests passed in $(( $(date +%s) - start )) s"
