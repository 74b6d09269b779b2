# What the headless-Chromium page tests share; sourced by each, after it set
# nothing. It gives:
#   $chromium, or exit 77 (ctest: skipped) when Chromium is not installed
#     (scripts/install-deps.sh installs it);
#   $work, a scratch folder removed on exit;
#   fail MESSAGE: prints FAIL: MESSAGE and exits 1;
#   dump_dom URL BUDGET_MS OUT [FLAG...]: the page's DOM into OUT after
#     BUDGET_MS of virtual time (its timers run without waiting), as root
#     (--no-sandbox) with its profile in $work; a failed run fails the test;
#   pre_text ID DOM: the text of the page's <pre id="ID"> in the DOM file.
chromium=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chromium" ] || { echo "chromium not installed: skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
dump_dom() {
  local url=$1 budget=$2 out=$3
  shift 3
  timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --user-data-dir="$work/profile" "$@" \
    --virtual-time-budget="$budget" --dump-dom "$url" >"$out" 2>"$work/chromium.txt" \
    || fail "chromium exit $?: $(tail -5 "$work/chromium.txt")"
}
pre_text() {
  sed -n "/<pre id=\"$1\">/,/<\/pre>/p" "$2" | sed -e "s/.*<pre id=\"$1\">//" -e 's/<\/pre>.*//'
}
