#!/usr/bin/env bash
# The user guide's pictures were made by scripts/guide_screenshots.sh, not by hand. Fails, naming the file,
# when
#   - a picture referenced from docs/guide/*.md is missing, lies outside docs/guide/images/, or is not listed
#     in docs/guide/images/MANIFEST.txt;
#   - a listed picture's SHA-256 differs from the manifest (edited or replaced after the script made it);
#   - a PNG in docs/guide/images/ is not listed (put there by hand), or a listed one is not a PNG;
#   - a manifest line is not a `maris --screenshot docs/guide/images/FILE ... --scenario NAME` command, or
#     NAME is not a built-in scenario of this build (`maris-cli list`);
#   - a listed picture is referenced by no chapter (dead weight in the repository).
# Needs no display. Usage: check_guide_images.sh SOURCE_DIR MARIS_CLI
set -euo pipefail
src="${1:?usage: check_guide_images.sh SOURCE_DIR MARIS_CLI}"
cli="${2:?usage: check_guide_images.sh SOURCE_DIR MARIS_CLI}"
guide="$src/docs/guide"
manifest="$guide/images/MANIFEST.txt"
problems=()

[ -f "$manifest" ] || { echo "no $manifest: run scripts/guide_screenshots.sh"; exit 1; }
builtins="$("$cli" list | awk '$1 != "NAME" {print $1}')" || { echo "$cli list failed"; exit 1; }
[ -n "$builtins" ] || { echo "$cli list printed no scenarios"; exit 1; }

declare -A listed=()
while IFS= read -r line; do
  case "$line" in '#'* | '') continue ;; esac
  read -r file sum command <<<"$line"
  listed["$file"]="$sum"
  [ -f "$guide/images/$file" ] || { problems+=("MANIFEST.txt lists $file, which does not exist"); continue; }
  actual="$(sha256sum "$guide/images/$file" | cut -d' ' -f1)"
  [ "$actual" = "$sum" ] || problems+=("images/$file: SHA-256 $actual, MANIFEST.txt says $sum (not the script's picture)")
  [ "$(head -c 8 "$guide/images/$file" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] ||
    problems+=("images/$file is not a PNG")
  case "$command" in
    "maris --screenshot docs/guide/images/$file "*) ;;
    *) problems+=("MANIFEST.txt: $file was not made by 'maris --screenshot docs/guide/images/$file': $command") ;;
  esac
  scenario="$(sed -n 's/.*--scenario \([^ ]*\).*/\1/p' <<<"$command")"
  if [ -z "$scenario" ]; then
    problems+=("MANIFEST.txt: $file names no --scenario")
  elif ! grep -qxF -- "$scenario" <<<"$builtins"; then
    problems+=("MANIFEST.txt: $file shows scenario '$scenario', which is not built in (maris-cli list)")
  fi
done <"$manifest"
[ "${#listed[@]}" -gt 0 ] || problems+=("MANIFEST.txt lists no picture")

for png in "$guide"/images/*.png; do
  [ -e "$png" ] || continue
  name="$(basename "$png")"
  [ -n "${listed[$name]+x}" ] || problems+=("images/$name is not in MANIFEST.txt (not made by scripts/guide_screenshots.sh)")
done

declare -A referenced=()
chapters=("$guide"/*.md)
[ -e "${chapters[0]}" ] || { echo "no chapters in $guide"; exit 1; }
for md in "${chapters[@]}"; do
  # Markdown images ![alt](path) and HTML <img src="path">.
  while IFS= read -r ref; do
    [ -n "$ref" ] || continue
    case "$ref" in
      images/*) name="${ref#images/}" ;;
      *) problems+=("$(basename "$md"): picture $ref is not in images/ (only the script's pictures belong in the guide)"); continue ;;
    esac
    referenced["$name"]=1
    if [ ! -f "$guide/images/$name" ]; then
      problems+=("$(basename "$md"): picture $ref does not exist")
    elif [ -z "${listed[$name]+x}" ]; then
      problems+=("$(basename "$md"): picture $ref is not in MANIFEST.txt")
    fi
  done < <(grep -oE '!\[[^]]*\]\([^)]+\)|<img [^>]*src="[^"]+"' "$md" |
             sed -E 's/^!\[[^]]*\]\(([^) ]+).*\)$/\1/; s/^<img [^>]*src="([^"]+)".*/\1/')
done
for name in "${!listed[@]}"; do
  [ -n "${referenced[$name]+x}" ] || problems+=("images/$name is listed but no chapter of docs/guide shows it")
done

if [ "${#problems[@]}" -gt 0 ]; then
  echo "The user guide's pictures do not match scripts/guide_screenshots.sh:"
  printf '  %s\n' "${problems[@]}"
  echo "${#problems[@]} problem(s); rerun scripts/guide_screenshots.sh and commit its output"
  exit 1
fi
echo "${#listed[@]} pictures, each made by scripts/guide_screenshots.sh and shown in docs/guide"
