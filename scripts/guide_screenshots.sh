#!/usr/bin/env bash
# Makes every picture of the user guide (docs/guide/images/*.png) with the application itself:
# `maris --screenshot` runs a built-in scenario off-screen (under Xvfb) and saves the window. The guide's
# pictures are therefore regenerated from the program, never drawn by hand. Writes
# docs/guide/images/MANIFEST.txt, one line per picture:
#   FILE SHA256 maris --screenshot docs/guide/images/FILE --scenario NAME ...
# (the exact arguments), which the test repo.guide_images checks against the files and the guide's text.
#
# Usage: scripts/guide_screenshots.sh [BUILD_DIR]     (default build/release; needs BUILD_DIR/app/maris)
# Needs xvfb-run (package xvfb); optipng, when installed, recompresses the pictures losslessly.
# The list of pictures is SHOTS below: add a line there, rerun, and reference the file from the guide.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build/release}"
case "$build" in /*) ;; *) [ -d "$build" ] || build="$root/$build" ;; esac
[ -d "$build" ] || { echo "guide_screenshots.sh: no build folder $build" >&2; exit 1; }
build="$(cd "$build" && pwd)"  # absolute: maris runs from the repository's root below
maris="$build/app/maris"
[ -x "$maris" ] || { echo "guide_screenshots.sh: no $maris (build the target maris first)" >&2; exit 1; }
command -v xvfb-run >/dev/null || { echo "guide_screenshots.sh: xvfb-run is missing (package xvfb)" >&2; exit 1; }

images_rel="docs/guide/images"
images="$root/$images_rel"
size="1400x900"

# FILE | maris options after --screenshot FILE (the window size is added to every line)
SHOTS=(
  "riser_default_displacement.png|--scenario riser_default --tab probe_displacement"
  "riser_default_stress_profile.png|--scenario riser_default --tab profile_t24_stress"
  "riser_jonswap_fatigue.png|--scenario riser_jonswap_sea --tab fatigue_life"
  "riser_case3_mode4.png|--scenario riser_paper_case3_pretensioned --time 3.25 --tab frequency_vs_pretension"
  "wec_default_rao.png|--scenario wec_default --tab pitch_rao"
  "wec_default_hinge_history.png|--scenario wec_default --tab hinge_fx_history"
  "wec_two_floats_rao.png|--scenario wec_two_floats --tab pitch_rao"
  "wec_irregular_spectra.png|--scenario wec_irregular --tab hinge_reaction_spectra"
  "ship_default_wave_resistance.png|--scenario ship_default --tab wave_resistance_coefficient"
  "ship_kcs_total_resistance.png|--scenario ship_kcs --tab total_resistance_coefficient"
  "ship_default_wave_spectrum.png|--scenario ship_default --tab wave_spectrum"
  "tether_default_features.png|--scenario tether_default --tab features"
  "tether_sim3_cable_deviation.png|--scenario tether_sim3_moving_leader --tab cable_deviation"
  "tether_model_error_eigenvalues.png|--scenario tether_model_error --tab eigenvalues"
  "fiv_calibrated_amplitude.png|--scenario fiv_calibrated --tab amplitude_ratio"
  "fiv_calibrated_power.png|--scenario fiv_calibrated --tab power"
  "fiv_hysteresis.png|--scenario fiv_galloping_hysteresis --tab amplitude_hysteresis"
  "seismic_default_amplification.png|--scenario seismic_default --tab amplification"
  "seismic_default_spectral_lines.png|--scenario seismic_default --tab spectral_ratio_lines_x"
  "seismic_box_verification.png|--scenario seismic_verification_box --tab verification"
)

mkdir -p "$images"
manifest_tmp="$(mktemp "$images/.MANIFEST.XXXXXX")"
trap 'rm -f "$manifest_tmp"' EXIT
{
  echo "# Pictures of the user guide, made by scripts/guide_screenshots.sh (do not edit by hand)."
  echo "# FILE SHA256 COMMAND (run from the repository's root under xvfb-run with QT_QPA_PLATFORM=xcb)"
} >"$manifest_tmp"

wanted=()
for shot in "${SHOTS[@]}"; do
  file="${shot%%|*}"
  read -r -a options <<<"${shot#*|}"
  wanted+=("$file")
  args=(--screenshot "$images_rel/$file" "${options[@]}" --size "$size")
  echo "== $file: maris ${args[*]}"
  # Relative paths, so that the manifest names no folder of this machine.
  (cd "$root" && QT_QPA_PLATFORM=xcb LC_ALL=C.UTF-8 \
     xvfb-run -a -s "-screen 0 1920x1200x24" "$maris" "${args[@]}")
  if command -v optipng >/dev/null; then optipng -quiet -o2 -strip all "$images/$file"; fi
  sum="$(sha256sum "$images/$file" | cut -d' ' -f1)"
  echo "$file $sum maris ${args[*]}" >>"$manifest_tmp"
done

# Pictures no longer in SHOTS would be hand-kept leftovers: remove them.
for png in "$images"/*.png; do
  [ -e "$png" ] || continue
  name="$(basename "$png")"
  keep=0
  for w in "${wanted[@]}"; do [ "$w" = "$name" ] && keep=1; done
  if [ "$keep" = 0 ]; then echo "removing $images_rel/$name (not in SHOTS)"; rm -f "$png"; fi
done

chmod 644 "$manifest_tmp"
mv "$manifest_tmp" "$images/MANIFEST.txt"
trap - EXIT
echo "wrote ${#SHOTS[@]} pictures and $images_rel/MANIFEST.txt"
