#!/usr/bin/env bash
# Repository hygiene: no file of the source tree may point at material outside it or at the project's
# development process. Fails, listing file:line, on
#   - paths to reading material beside the checkout (a "shared" folder of papers, research notes, data, tools),
#   - references to internal research notes (by section or acceptance-test number): cite the papers,
#     books and data sets themselves,
#   - issue or session numbers (development diary; history lives in git),
#   - absolute paths of a development machine (home, root or work folders).
# Usage: check_tree.sh SOURCE_DIR. Scans the files git knows (tracked, or untracked and not ignored) when
# SOURCE_DIR is a git checkout, else every file below it except build folders.
# The patterns use character classes so that this file does not match itself. LICENSE is the GPL's text,
# kept verbatim, and is not scanned.
set -euo pipefail
src="${1:?usage: check_tree.sh SOURCE_DIR}"
cd "$src"

patterns=(
  '[.][.]/s[h]ared'
  's[h]ared/(papers|research|data|tools)'
  '(^|[^A-Za-z_])(papers|r[e]search)/[A-Za-z0-9_]+[.](txt|md)'
  '(^|[^A-Za-z])[Bb]r[i]efs?([^A-Za-z]|$)'
  '[Ss]e[s]sions? [0-9]'
  '[Ii]s[s]ues? ([0-9]|#[0-9])'
  '(^|[ (])#[0-9]+([^0-9A-Za-z]|$)'
  '/(w[o]rk|h[o]me|r[o]ot)/'
)
regex="$(IFS='|'; echo "${patterns[*]}")"

list_files() {
  if command -v git >/dev/null 2>&1 && [ "$(git rev-parse --show-toplevel 2>/dev/null)" = "$(pwd -P)" ]; then
    git ls-files -z --cached --others --exclude-standard
  else
    find . \( -name .git -o -name 'build' -o -name 'build-*' -o -name 'build_*' \) -prune -o -type f -print0
  fi
}

hits="$(list_files | while IFS= read -r -d '' f; do [ -f "$f" ] && [ "${f#./}" != LICENSE ] && printf '%s\0' "$f"; done |
          xargs -0 -r grep -nHIE -- "$regex" || true)"
if [ -n "$hits" ]; then
  echo "Files of the source tree name insider material: cite the sources themselves (authors, title, journal,"
  echo "year, DOI); no issue or session numbers, no internal research notes, no paths outside the tree:"
  printf '%s\n' "$hits"
  echo "$(printf '%s\n' "$hits" | wc -l) offending line(s)"
  exit 1
fi
echo "no insider references in $(list_files | tr -cd '\0' | wc -c) files"
