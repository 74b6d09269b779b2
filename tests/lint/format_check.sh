#!/usr/bin/env bash
# The formatting ratchet: every file named in LIST (paths relative to ROOT;
# '#' lines are comments) must be as clang-format formats it with the
# tree's .clang-format. Prints the offending files with clang-format's first
# complaint for each and exits 1; exits 2 if clang-format is missing.
# Usage: format_check.sh ROOT LIST
set -u
root=$1
list=$2
command -v clang-format >/dev/null || { echo "clang-format is not installed (scripts/install-deps.sh installs it)"; exit 2; }
offenders=0
files=()
while IFS= read -r file; do
  case "$file" in '' | '#'*) continue ;; esac
  [ -f "$root/$file" ] || { echo "$file: listed but missing"; offenders=$((offenders + 1)); continue; }
  files+=("$file")
done <"$list"
# One clang-format for every file (a process per file took 13 s for 352):
# its complaints are "FILE:LINE:COL: error: ..." lines, each followed by the
# source line and a caret; the first of each file is printed.
if [ ${#files[@]} -gt 0 ] && ! out=$(cd "$root" && clang-format --dry-run --Werror "${files[@]}" 2>&1); then
  first=$(echo "$out" | awk -F: '/^[^ :]+:[0-9]+:[0-9]+: error: / && !seen[$1]++ { print; n = 2; next } n > 0 { print; n-- }')
  [ -n "$first" ] || first=$out  # not a complaint (clang-format itself failed): show it
  echo "$first"
  bad=$(echo "$out" | awk -F: '/^[^ :]+:[0-9]+:[0-9]+: error: / { print $1 }' | sort -u | wc -l)
  offenders=$((offenders + (bad > 0 ? bad : 1)))
fi
if [ "$offenders" -gt 0 ]; then
  echo "$offenders of the listed files are not formatted: run clang-format -i on them"
  exit 1
fi
echo "${#files[@]} listed files are formatted"
