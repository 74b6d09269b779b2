#!/usr/bin/env bash
# The formatting check must fail on a planted mis-formatted line: a copy of
# a formatted file with one line indented wrongly.
# Usage: format_check_finds_planted.sh ROOT
set -u
here=$(dirname "$0")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$1/.clang-format" "$work/"
cp "$1/src/stochtex/report/wav.cpp" "$work/planted.cpp"
sed -i 's/^    out += "RIFF";$/        out +=   "RIFF" ;/' "$work/planted.cpp"
grep -q '^        out +=   "RIFF" ;$' "$work/planted.cpp" || { echo "could not plant the line"; exit 1; }
echo "planted.cpp" >"$work/list.txt"
out=$(bash "$here/format_check.sh" "$work" "$work/list.txt")
rc=$?
[ $rc -eq 1 ] || { echo "expected exit 1 on the planted line, got $rc:"; echo "$out"; exit 1; }
echo "$out" | grep -q "planted.cpp" || { echo "the report does not name planted.cpp:"; echo "$out"; exit 1; }
echo "the check finds the planted line:"
echo "$out"
