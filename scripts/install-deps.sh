#!/usr/bin/env bash
# Installs the Debian 12 packages Maris needs to build, test and run (uses sudo when not root).
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config lld
  qt6-base-dev libqt6opengl6-dev libqt6svg6-dev qt6-qpa-plugins
  libvtk9-dev libeigen3-dev libfftw3-dev libqcustomplot-dev nlohmann-json3-dev libcli11-dev
  libspectra-dev
  libgtest-dev
  xvfb xauth
  file lintian appstream desktop-file-utils
  python3 locales
  slurm-wlm munge
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
