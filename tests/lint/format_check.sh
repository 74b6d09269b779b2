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
checked=0
while IFS= read -r file; do
  case "$file" in '' | '#'*) continue ;; esac
  [ -f "$root/$file" ] || { echo "$file: listed but missing"; offenders=$((offenders + 1)); continue; }
  checked=$((checked + 1))
  if ! out=$(cd "$root" && clang-format --dry-run --Werror "$file" 2>&1); then
    echo "$out" | head -3
    offenders=$((offenders + 1))
  fi
done <"$list"
if [ "$offenders" -gt 0 ]; then
  echo "$offenders of the listed files are not formatted: run clang-format -i on them"
  exit 1
fi
echo "$checked listed files are formatted"
