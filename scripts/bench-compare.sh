#!/usr/bin/env bash
# Times two builds of stochtex_bench against each other: runs the benchmarks
# matching FILTER with the OLD and the NEW binary in turn (old, new, old,
# new, ...) ROUNDS times and prints, per benchmark, the median real time of
# each and the median of the per-round ratios new/old. Alternating keeps the
# ratio meaningful on a shared machine whose speed drifts.
#   scripts/bench-compare.sh OLD_BENCH NEW_BENCH 'BM_RenderUnfiltered|BM_FilteredVsUnfiltered' [ROUNDS=5]
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 OLD_BENCH NEW_BENCH FILTER [ROUNDS]" >&2
  exit 2
fi
old=$1 new=$2 filter=$3 rounds=${4:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for ((r = 0; r < rounds; ++r)); do
  for side in old new; do
    bin=$old
    [ "$side" = new ] && bin=$new
    # Console lines: NAME TIME UNIT CPU UNIT ITERATIONS [COUNTERS] (CSV aborts
    # when benchmarks have different counters).
    "$bin" --benchmark_filter="$filter" --benchmark_color=false 2>/dev/null |
      awk -v side="$side" -v round="$r" '$1 ~ /^BM_/ && $3 ~ /^(ns|us|ms|s)$/ {
        ms = $2 * ($3 == "ns" ? 1e-6 : $3 == "us" ? 1e-3 : $3 == "s" ? 1e3 : 1)
        print side, round, $1, ms }' \
        >>"$tmp/times"
  done
done
echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%F), rounds: $rounds"
printf '%-62s %12s %12s %10s\n' benchmark "old (ms)" "new (ms)" new/old
awk '
  function median(a, n,   i, j, t) {
    for (i = 2; i <= n; ++i) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; --j) a[j + 1] = a[j]; a[j + 1] = t }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
  }
  { t[$1, $2, $3] = $4; names[$3] = 1; if ($2 + 1 > rounds) rounds = $2 + 1 }
  END {
    for (name in names) {
      n = 0
      for (r = 0; r < rounds; ++r)
        if (("old", r, name) in t && ("new", r, name) in t) {
          ++n; o[n] = t["old", r, name]; w[n] = t["new", r, name]; q[n] = w[n] / o[n]
        }
      if (n) printf "%-62s %12.3f %12.3f %10.3f\n", name, median(o, n), median(w, n), median(q, n)
    }
  }' "$tmp/times" | sort
