#!/usr/bin/env bash
# The videos stochtex writes play in a browser: `zoom` writes NAME.mp4
# (H.264) and NAME.webm (VP9), and a page in headless Chromium plays each in
# a <video>; after a second of (virtual) time the page reports currentTime
# and any media error. An MPEG-4 Part 2 file, what stochtex wrote before,
# fails here with MEDIA_ERR_SRC_NOT_SUPPORTED. The animated GIF and WebP
# must decode in an <img> at the written size.
# Usage: video_playback_test.sh STOCHTEX_BINARY. Exit 77 (ctest: skipped)
# when Chromium is not installed (tests/lib/chromium.sh).
set -u
bin=$1
source "$(dirname "$0")/../lib/chromium.sh"

for ext in mp4 webm gif webp; do
  "$bin" zoom --frames 48 --fps 24 --size 96,64 -o "$work/zoom.$ext" >"$work/out.txt" 2>&1 || fail "zoom -o zoom.$ext: $(cat "$work/out.txt")"
done
cat >"$work/page.html" <<'HTML'
<html><body>
<video id="mp4" src="zoom.mp4" muted autoplay></video>
<video id="webm" src="zoom.webm" muted autoplay></video>
<img id="gif" src="zoom.gif"><img id="webp" src="zoom.webp">
<pre id="result">pending</pre>
<script>
const lines = {};
for (const id of ["mp4", "webm"]) {
  const v = document.getElementById(id);
  v.addEventListener("error", () => { lines[id] = id + " error " + (v.error ? v.error.code : "?"); });
  v.play().catch(e => { lines[id] = id + " error " + e.name; });
}
setTimeout(() => {
  for (const id of ["mp4", "webm"]) {
    const v = document.getElementById(id);
    if (!lines[id]) lines[id] = id + " time " + v.currentTime.toFixed(2) + " duration " + v.duration.toFixed(2) + " size " + v.videoWidth + "x" + v.videoHeight;
  }
  for (const id of ["gif", "webp"]) {
    const i = document.getElementById(id);
    lines[id] = id + " size " + i.naturalWidth + "x" + i.naturalHeight + (i.complete ? " complete" : " loading");
  }
  document.getElementById("result").textContent = ["mp4", "webm", "gif", "webp"].map(k => lines[k]).join("\n");
}, 1000);
</script></body></html>
HTML
dump_dom "file://$work/page.html" 3000 "$work/dom.html" --autoplay-policy=no-user-gesture-required
result=$(pre_text result "$work/dom.html")
echo "$result"
for id in mp4 webm; do
  line=$(echo "$result" | grep "^$id ")
  echo "$line" | grep -q " size 96x64$" || fail "$id does not play: $line"
  # 48 frames at 24 fps: 2 s long; after 1 s of playback the time has advanced.
  echo "$line" | awk '{ exit !($3 > 0.2 && $5 > 1.9 && $5 < 2.1) }' || fail "$id: time did not advance or wrong duration: $line"
done
for id in gif webp; do
  echo "$result" | grep -qx "$id size 96x64 complete" || fail "$id does not decode: $(echo "$result" | grep "^$id ")"
done
echo "video playback: mp4 (H.264) and webm (VP9) play, gif and webp decode"
