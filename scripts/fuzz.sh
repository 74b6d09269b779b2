#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan, STOCHTEX_FUZZ=ON) in their
# own build folder and runs each for SECONDS (docs/TESTING.md, "Fuzzing"):
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]      # default 60 s, every target
#
# SECONDS 0 only configures and builds (the fuzz targets and the sanitizer
# build's unit tests, tests/sanitized; scripts/sanitize-test.sh runs those).
#
# One fuzzing process at a time. New inputs go to $BUILD_DIR/corpus/TARGET
# (kept between runs); a finding is written to $BUILD_DIR/findings/TARGET/
# and makes the script exit 1 after the other targets have run. Environment:
# BUILD_DIR (build-fuzz), FUZZ_SEED (1: a fixed seed, so a run repeats),
# CXX (clang++-14), FUZZ_FLAGS (more libFuzzer flags).
set -uo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(pattern_json noise_spec colormap_spec image pipeline graph shadertoy_manifest mesh)
build=${BUILD_DIR:-build-fuzz}
cxx=${CXX:-clang++-14}

case $seconds in
  '' | *[!0-9]*) echo "fuzz.sh: SECONDS must be a whole number, got \"$seconds\"" >&2; exit 2 ;;
esac

launcher=()
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1 with line tables: what ASan's authors advise for usable speed and
# reports with file:line; per file it compiles 13–30% faster than -O2 -g
# (measured: studies/paper.cpp, tests/pattern/graph_pattern_test.cpp), and
# make test builds it on every clean clone.
cmake -S . -B "$build" -DSTOCHTEX_FUZZ=ON -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  "${launcher[@]}" >/dev/null || exit 1
cmake --build "$build" -j "$(nproc)" --target fuzz-targets stochtex_sanitized_tests || exit 1
[ "$seconds" -eq 0 ] && exit 0

# OpenCV's error log would flood the output; the messages users see are checked elsewhere (cli.bad_input).
export OPENCV_LOG_LEVEL=SILENT
status=0
for t in "${targets[@]}"; do
  binary=$build/bin/fuzz_$t
  [ -x "$binary" ] || { echo "fuzz.sh: unknown target \"$t\"" >&2; exit 2; }
  mkdir -p "$build/corpus/$t" "$build/findings/$t"
  IFS=';' read -r -a seeds <"$build/fuzz/$t.corpus"
  log=$build/findings/$t.log
  dict=()
  [ "$t" != image ] && [ "$t" != graph ] && dict=(-dict=tests/fuzz/json.dict)  # those two read no JSON
  # -max_len: a pattern file is a few kB; longer inputs only slow the search.
  # shellcheck disable=SC2086
  "$binary" -max_total_time="$seconds" -seed="${FUZZ_SEED:-1}" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/findings/$t/" "${dict[@]}" ${FUZZ_FLAGS:-} \
    "$build/corpus/$t" "${seeds[@]}" >"$log" 2>&1
  rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  if [ $rc -eq 0 ]; then
    echo "fuzz $t: ${runs:-?} executions in $seconds s, no finding"
  else
    status=1
    echo "fuzz $t: FINDING after ${runs:-?} executions (exit $rc); log $log, input in $build/findings/$t/:"
    grep -E '^(SUMMARY|fuzz: |==[0-9]+==ERROR)' "$log" | head -5 | sed 's/^/  /'
  fi
done
exit $status
