#!/usr/bin/env bash
# The perception experiment's page (stochtex stimuli, experiment.html) run in
# headless Chromium: the page's automated mode (#auto=KEYS) presses Space and
# then each scripted Y / N by dispatching keydown events on document, the
# handler that real key presses reach; --virtual-time-budget lets its timers
# run without waiting, and --dump-dom prints the DOM afterwards. The answers
# CSV in the DOM must have one row per trial, in the order of stimuli.csv
# (the seeded order), with the scripted answers.
# Usage: experiment_page_test.sh STOCHTEX_BINARY. Exit 77 (ctest: skipped)
# when Chromium is not installed (tests/lib/chromium.sh).
set -u
bin=$1
source "$(dirname "$0")/../lib/chromium.sh"

"$bin" stimuli -o "$work/exp" --size 16 --tiles 4,8 --correlations 0,0.5,1 --repeats 2 --seed 11 \
  --duration-ms 1000 --reset-ms 1000 >"$work/out.txt" 2>&1 || fail "stimuli: $(cat "$work/out.txt")"
keys=ynnyyynnnyny  # 12 trials: 2 tile sizes x 3 correlations x 2
dump_dom "file://$work/exp/experiment.html#auto=$keys" 60000 "$work/dom.html"

grep -q "data-state=\"done\"" "$work/dom.html" || fail "the page did not reach its end: $(grep -o 'data-state="[a-z]*"' "$work/dom.html")"
# The <pre id="answers-csv"> block, one line per row.
pre_text answers-csv "$work/dom.html" | grep -v '^$' >"$work/answers.csv"
head -1 "$work/answers.csv" | grep -qx "trial,stimulus,w,correlation,alpha,answer,response_time_ms,shown_ms" \
  || fail "CSV header: $(head -1 "$work/answers.csv")"
rows=$(($(wc -l <"$work/answers.csv") - 1))
[ "$rows" -eq 12 ] || fail "$rows answer rows, expected 12: $(cat "$work/answers.csv")"
# Trial k: the k-th stimulus of stimuli.csv (trial order), its w and correlation, the k-th key.
expected=$(awk -F, -v keys="$keys" 'NR > 1 { a = substr(keys, NR - 1, 1) == "y" ? "yes" : "no"; print $1 "," $2 "," $3 "," $4 "," a }' "$work/exp/stimuli.csv")
got=$(awk -F, 'NR > 1 { print $1 "," $2 "," $3 "," $4 "," $6 }' "$work/answers.csv")
[ "$expected" = "$got" ] || fail "answers differ from the seeded order and the script:
expected:
$expected
got:
$got"
# The order is not the grid's: the seed shuffled it.
grid=$(awk -F, 'NR > 1 { print $3 "," $4 }' "$work/exp/stimuli.csv")
sorted=$(echo "$grid" | sort -t, -k1,1n -k2,2n)
[ "$grid" != "$sorted" ] || fail "trial order equals the grid order: not shuffled"
# Response times and the measured display times are numbers (automated mode: 20 ms each).
awk -F, 'NR > 1 && !($7 ~ /^[0-9]+$/ && $8 ~ /^[0-9]+$/ && $8 >= 15) {exit 1}' "$work/answers.csv" \
  || fail "response_time_ms / shown_ms not whole ms: $(cat "$work/answers.csv")"
# The analysis reads what the page wrote.
"$bin" stimuli --analyse "$work/answers.csv" -o "$work/an" >"$work/out.txt" 2>&1 || fail "analyse: $(cat "$work/out.txt")"
[ "$(wc -l <"$work/an/detection.csv")" -eq 7 ] || fail "detection.csv: $(cat "$work/an/detection.csv")"
echo "experiment page: 12 trials answered in the seeded order"
