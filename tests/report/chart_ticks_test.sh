#!/usr/bin/env bash
# A report page's charts as a reader sees them, in headless Chromium: the
# flow study of the zoom texture plots its expansion rate, nearly constant;
# after the page's own scripts ran, a script appended here reads every
# chart's y tick labels (Chart.instances). The y axis must start at 0, as in
# the PNG (Chart.js alone fitted the last digits of a constant and showed a
# fall), and no label may carry Chart.js's float noise (0.000000001).
# Usage: chart_ticks_test.sh STOCHTEX_BINARY. Exit 77 (ctest: skipped)
# when Chromium is not installed (tests/lib/chromium.sh).
set -u
bin=$1
source "$(dirname "$0")/../lib/chromium.sh"

"$bin" flow -o "$work/fl" --frames 4 --size 64 zoom >"$work/out.txt" 2>&1 || fail "flow: $(cat "$work/out.txt")"
grep -q "stochtex-chart" "$work/fl/index.html" || fail "the flow page has no chart"
sed 's|</body>|<pre id="ticks"></pre><script>document.getElementById("ticks").textContent=Object.values(Chart.instances).map(function(c){return c.scales.y.ticks.map(function(t){return t.label;}).join(" ");}).join("\\n");</script></body>|' \
  "$work/fl/index.html" >"$work/fl/probe.html"
dump_dom "file://$work/fl/probe.html" 3000 "$work/dom.html"
ticks=$(pre_text ticks "$work/dom.html" | grep -v '<')
echo "$ticks"
[ -n "$ticks" ] || fail "no chart drew ticks"
while read -r line; do
  [ -z "$line" ] && continue
  first=${line%% *}
  [ "$first" = "0" ] || fail "a y axis does not start at 0: $line"
  echo "$line" | grep -qE '0\.0000' && fail "a tick label carries float noise: $line"
done <<<"$ticks"
echo "chart ticks: every y axis from 0, labels in the PNG's format"
