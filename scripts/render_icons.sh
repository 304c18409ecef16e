#!/usr/bin/env bash
# Renders the application icon packaging/icons/maris.svg to the PNG sizes of the hicolor theme
# (packaging/icons/<N>x<N>/maris.png). The PNGs are committed; rerun this after editing the SVG.
# Needs rsvg-convert (Debian package librsvg2-bin).
set -euo pipefail
cd "$(dirname "$0")/../packaging/icons"
for n in 16 32 48 64 128 256; do
  mkdir -p "${n}x${n}"
  rsvg-convert --width "$n" --height "$n" --format png maris.svg --output "${n}x${n}/maris.png"
done
echo "render_icons: wrote $(ls -d */ | tr -d / | tr '\n' ' ')"
