#!/usr/bin/env bash
# The first README command: install, build in Release, run the main job.
# With a display: the desktop application. Without one: maris-cli on the default scenario,
# writing its results to a folder it prints (replacing the previous run there).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j "$(nproc)"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec ./build/release/app/maris "$@"
else
  echo "no display: running the default scenario headless"
  exec ./build/release/app/maris-cli run "$(./build/release/app/maris-cli default)" --out maris-results/default --force "$@"
fi
