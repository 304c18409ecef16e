#!/usr/bin/env bash
# Builds the Debian packages (maris-cli, maris) from an existing Release build and checks them:
#   lintian reports no error and no warning; the files a desktop reads validate (desktop entry, AppStream);
#   both packages unpacked into an empty root, maris-cli from there answers --help, list and scenes and
#   runs one built-in scenario of every scene (its PNG plots included, drawn by the plot renderer module that
#   maris-cli loads: maris-cli itself links no Qt), maris answers --help;
#   `apt-get install --simulate` of the .deb files resolves on this system, and maris-cli pulls no VTK.
# Usage: scripts/ci_package_check.sh [BUILD_DIR]     (default build/release, configured with the release preset)
# Prints one summary line; exits non-zero on any problem.
set -uo pipefail
started=$SECONDS
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=$(realpath -m "${1:-$source_dir/build/release}")
work=$(mktemp -d "${TMPDIR:-/tmp}/maris-package-check.XXXXXX")
trap 'rm -rf "$work"' EXIT
problems=()
problem() { problems+=("$1"); echo "ci_package_check: FAIL: $1" >&2; }
step() { echo "== $*"; }

finish() {
  local seconds=$((SECONDS - started))
  if [ ${#problems[@]} -eq 0 ]; then
    echo "ci_package_check: OK: ${packages_built:-0} packages, lintian clean, ${scenes_run:-0} scenes run from the unpacked maris-cli, apt resolves (${seconds} s)"
    exit 0
  fi
  echo "ci_package_check: FAILED (${#problems[@]} problems, ${seconds} s): $(IFS='; '; echo "${problems[*]}")"
  exit 1
}

if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  problem "$build_dir is not a configured build directory (run: cmake --preset release)"
  finish
fi
bash "$source_dir/scripts/install-deps.sh" >/dev/null || { problem "install-deps.sh failed"; finish; }

gui=OFF
grep -q '^MARIS_BUILD_GUI:BOOL=ON' "$build_dir/CMakeCache.txt" && gui=ON
targets=(maris-cli)
[ "$gui" = ON ] && targets+=(maris)
step "build ${targets[*]} in $build_dir"
cmake --build "$build_dir" --target "${targets[@]}" || { problem "build of ${targets[*]} failed"; finish; }

step "cpack -G DEB"
debs_dir=$work/debs
(cd "$build_dir" && cpack -G DEB -B "$debs_dir" >"$work/cpack.log" 2>&1) || {
  cat "$work/cpack.log"
  problem "cpack failed"
  finish
}
shopt -s nullglob
debs=("$debs_dir"/*.deb)
packages_built=${#debs[@]}
expected=1
[ "$gui" = ON ] && expected=2
[ "$packages_built" -eq "$expected" ] || problem "expected $expected .deb files, cpack made $packages_built"
for deb in "${debs[@]}"; do
  echo "$(basename "$deb"): $(du -h "$deb" | cut -f1)"
done
cli_deb=("$debs_dir"/maris-cli_*.deb)
gui_deb=("$debs_dir"/maris_*.deb)
[ ${#cli_deb[@]} -eq 1 ] || { problem "no maris-cli_<version>_<arch>.deb"; finish; }

step "lintian"
# As root lintian only notes that it runs as root; --fail-on makes any error or warning fatal.
if ! lintian --fail-on error,warning --display-level '>=info' "${debs[@]}" 2>&1 | tee "$work/lintian.log"; then
  problem "lintian reports errors or warnings (above)"
fi

step "unpack into an empty root"
root=$work/root
mkdir -p "$root"
for deb in "${debs[@]}"; do dpkg-deb -x "$deb" "$root" || problem "dpkg-deb -x $(basename "$deb") failed"; done
cli=$root/usr/bin/maris-cli
[ -x "$cli" ] || { problem "the package has no usr/bin/maris-cli"; finish; }
for f in copyright changelog.Debian.gz; do
  [ -f "$root/usr/share/doc/maris-cli/$f" ] || problem "maris-cli lacks /usr/share/doc/maris-cli/$f"
done
if [ "$gui" = ON ]; then
  desktop-file-validate "$root/usr/share/applications/maris.desktop" || problem "desktop-file-validate maris.desktop"
  for f in "$root"/usr/share/metainfo/*.metainfo.xml; do
    appstreamcli validate --no-net "$f" || problem "appstreamcli validate $(basename "$f")"
  done
  "$root/usr/bin/maris" --help >/dev/null || problem "maris --help from the package failed"
fi

step "maris-cli from the unpacked root"
echo "maris-cli Depends: $(dpkg-deb --field "${cli_deb[0]}" Depends)"
if dpkg-deb --field "${cli_deb[0]}" Depends | grep -qi vtk || readelf -d "$cli" | grep -qi 'NEEDED.*vtk'; then
  problem "maris-cli depends on VTK"
fi
# maris-cli itself links no Qt; its plot renderer is a module it loads only to write PNGs.
if readelf -d "$cli" | grep -qi 'NEEDED.*\(qt\|qcustomplot\)'; then
  problem "maris-cli links Qt (its plots belong in the renderer module)"
fi
if [ "$gui" = ON ]; then
  renderer=$(find "$root/usr/lib" -name maris_plot_renderer.so 2>/dev/null | head -n 1)
  [ -n "$renderer" ] || problem "the maris-cli package has no maris_plot_renderer.so"
  [ -z "$renderer" ] || echo "plot renderer: ${renderer#"$root"}"
fi
"$cli" --help >/dev/null || problem "maris-cli --help failed"
"$cli" list >"$work/list.txt" || problem "maris-cli list failed"
"$cli" scenes >"$work/scenes.txt" || problem "maris-cli scenes failed"
scenes_run=0
while read -r scene _; do
  [ -n "$scene" ] || continue
  # The scene's "<scene>_default" scenario if there is one, else its first in the list.
  names=$(awk -v s="$scene" 'NR > 1 && $2 == s { print $1 }' "$work/list.txt")
  name=$(grep -x "${scene}_default" <<<"$names" || head -n 1 <<<"$names")
  if [ -z "$name" ]; then
    problem "scene $scene has no built-in scenario"
    continue
  fi
  out=$work/run/$scene
  t0=$SECONDS
  if "$cli" run "$name" --out "$out" >"$work/run_$scene.log" 2>&1; then
    pngs=("$out"/*.png)
    echo "$scene: $name ran in $((SECONDS - t0)) s, $(ls "$out" | wc -l) files (${#pngs[@]} PNG)"
    [ -f "$out/summary.json" ] || problem "$name wrote no summary.json"
    [ "$gui" = OFF ] || [ ${#pngs[@]} -gt 0 ] || problem "$name wrote no PNG plot"
    scenes_run=$((scenes_run + 1))
  else
    tail -n 20 "$work/run_$scene.log"
    problem "maris-cli run $name failed"
  fi
done <"$work/scenes.txt"
[ "$scenes_run" -gt 0 ] || problem "no scene was run"

step "apt-get install --simulate"
if apt-get install --simulate -q "${cli_deb[0]}" >"$work/apt_cli.txt" 2>&1; then
  echo "maris-cli: $(grep -c '^Inst ' "$work/apt_cli.txt") packages to install here"
else
  cat "$work/apt_cli.txt"
  problem "apt-get install --simulate maris-cli does not resolve"
fi
if [ "$gui" = ON ] && [ ${#gui_deb[@]} -eq 1 ]; then
  if apt-get install --simulate -q "${cli_deb[0]}" "${gui_deb[0]}" >"$work/apt_gui.txt" 2>&1; then
    echo "maris + maris-cli: $(grep -c '^Inst ' "$work/apt_gui.txt") packages to install"
  else
    cat "$work/apt_gui.txt"
    problem "apt-get install --simulate maris does not resolve"
  fi
fi
finish
