#!/usr/bin/env bash
# Fresh-clone check: the committed tree builds and passes its ship and repository tests from a clone in an
# empty temporary folder, with nothing beside it (no data, papers or tools outside the repository).
#   scripts/ci_fresh_clone_check.sh            clone HEAD of this checkout
# Builds maris-cli and test_engine_ship (Release, no GUI, no benches) with the compiler cache when ccache is
# installed (CCACHE_BASEDIR is the clone, so objects built from another checkout of the same sources hit),
# runs ctest -R '^(ship|repo)\.' and a maris-cli run of a built-in ship scenario there, then removes the
# folder. Exits non-zero on any failure.
set -euo pipefail
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
commit="$(git -C "$source_dir" rev-parse HEAD)"
jobs="${MARIS_CI_JOBS:-$(nproc)}"
start=$(date +%s)

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
clone="$scratch/maris"

echo "== fresh clone of $commit into $clone"
git clone --quiet --no-checkout "$source_dir" "$clone"
git -C "$clone" checkout --quiet --detach "$commit"
if [ -n "$(git -C "$source_dir" status --porcelain --untracked-files=no)" ]; then
  echo "note: $source_dir has uncommitted changes; only the committed tree is checked"
fi
# Nothing may sit beside the clone: the folder holds the clone alone.
[ "$(ls -A "$scratch")" = "maris" ] || { echo "the scratch folder is not empty beside the clone"; exit 1; }

cd "$clone"
export CCACHE_BASEDIR="$clone" CCACHE_NOHASHDIR=true
echo "== configure (Release, no GUI, no benches)"
cmake --preset release -DMARIS_BUILD_GUI=OFF -DMARIS_BUILD_BENCH=OFF -DMARIS_WERROR=ON >/dev/null
echo "== build maris-cli and test_engine_ship"
cmake --build build/release -j "$jobs" --target maris-cli test_engine_ship
echo "== tests"
ctest --test-dir build/release -R '^(ship|repo)\.' -j "$jobs" --output-on-failure --timeout 600
echo "== maris-cli run ship_series60"
./build/release/app/maris-cli run ship_series60 --out "$scratch/out" >/dev/null 2>"$scratch/cli.log" ||
  { cat "$scratch/cli.log"; echo "maris-cli run ship_series60 failed"; exit 1; }

echo "== fresh-clone check passed in $(( $(date +%s) - start )) s"
