#!/usr/bin/env bash
# Runs no_flags_in_library.sh on a fixture tree and requires it to fail with
# exactly the report in the fixture's expected.txt: the check must find
# flags in string literals (one line, split over lines, raw) and must not
# flag comments or code.
# Usage: expect_offenders.sh FIXTURE_DIR
set -u
here=$(dirname "$0")
out=$(bash "$here/no_flags_in_library.sh" "$1")
rc=$?
[ $rc -eq 1 ] || { echo "expected exit 1, got $rc:"; echo "$out"; exit 1; }
if ! diff <(echo "$out") "$1/expected.txt"; then
  echo "the report differs from $1/expected.txt (< got, > expected)"
  exit 1
fi
echo "the check reports exactly the planted flags"
