#!/usr/bin/env bash
# Runs a check (no_flags_in_library.sh, no_hand_built_flag_errors.sh) on a
# fixture tree and requires it to fail with exactly the report in the
# fixture's expected.txt: the check must find what is planted there and
# nothing in its comments or its allowed code.
# Usage: expect_offenders.sh CHECK FIXTURE_DIR
set -u
here=$(dirname "$0")
check=$1
shift
out=$(bash "$here/$check" "$1")
rc=$?
[ $rc -eq 1 ] || { echo "expected exit 1, got $rc:"; echo "$out"; exit 1; }
if ! diff <(echo "$out") "$1/expected.txt"; then
  echo "the report differs from $1/expected.txt (< got, > expected)"
  exit 1
fi
echo "the check reports exactly the planted flags"
