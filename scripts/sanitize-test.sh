#!/usr/bin/env bash
# The sanitizer part of `make test` (docs/TESTING.md, "Sanitizers"): the clang
# build of build-fuzz/ (ASan + UBSan, float-cast-overflow included, every
# report fatal) runs the unit tests of the modules a user's input reaches
# (tests/sanitized_subset.cmake), then each fuzz target for SECONDS from its
# seeds and regression corpus, so a crash or undefined behaviour that the
# stored inputs or a few seconds of mutation reach fails the tests.
#
#   scripts/sanitize-test.sh [SECONDS]     # default 5 s per fuzz target
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-5}
build=${BUILD_DIR:-build-fuzz}
export BUILD_DIR=$build
bash scripts/fuzz.sh 0
# OpenCV's error log would flood the output (the messages are checked by cli.bad_input).
OPENCV_LOG_LEVEL=SILENT ctest --test-dir "$build" -L sanitized --output-on-failure -j "$(nproc)"
bash scripts/fuzz.sh "$seconds"
