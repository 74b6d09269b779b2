#!/usr/bin/env bash
# End-to-end checks of the stochtex CLI: success paths write what they say,
# bad input exits with code 2, prints one clear message naming the input,
# and leaves no output (or temporary) file behind.
# Usage: cli_test.sh CASE STOCHTEX_BINARY SOURCE_DIR [IMAGE_COMPARE_BINARY]
# CASE names one case_* function below; tests/CMakeLists.txt registers each
# as the ctest test cli.CASE, so a new case_* function is a new test.
set -u
name=$1
bin=$2
src=$3
compare=${4:-}  # tests/cli/image_compare.cpp: prints "mean M flipped F" in 8-bit steps
work=$(mktemp -d)
xvfb_pid=
trap 'rm -rf "$work"; [ -z "$xvfb_pid" ] || kill "$xvfb_pid" 2>/dev/null' EXIT
failures=0

# One virtual display for a case's windows, started on first use: xvfb-run
# per command started and cleaned up a server each time, and its clean-up
# now and then failed with exit 5 ("problem while cleaning up"), failing a
# check that had passed. Sets `display` (e.g. ":99").
display=
start_xvfb() {
  [ -n "$display" ] && return
  Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$work/display.txt" >/dev/null 2>&1 &
  xvfb_pid=$!
  for _ in $(seq 100); do [ -s "$work/display.txt" ] && break; sleep 0.1; done
  display=":$(head -1 "$work/display.txt")"
  [ "$display" != ":" ] || { echo "FAIL: Xvfb did not start"; exit 1; }
}

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_ok DESCRIPTION FILE-THAT-MUST-EXIST -- command...
expect_ok() {
  local what=$1 file=$2; shift 3
  local rc=0
  "$@" >"$work/out.txt" 2>"$work/err.txt" || rc=$?
  if [ "$rc" -ne 0 ]; then
    fail "$what: exit $rc ($(cat "$work/err.txt"))"; return
  fi
  [ -z "$file" ] || [ -s "$file" ] || fail "$what: $file not written"
}

# expect_bad DESCRIPTION FILE-THAT-MUST-NOT-EXIST MESSAGE-FRAGMENT -- command...
expect_bad() {
  local what=$1 file=$2 fragment=$3; shift 4
  "$@" >"$work/out.txt" 2>"$work/err.txt"
  local rc=$?
  [ $rc -eq 2 ] || fail "$what: exit code $rc, expected 2"
  grep -qF -- "$fragment" "$work/err.txt" || fail "$what: message lacks '$fragment': $(cat "$work/err.txt")"
  [ "$(wc -l <"$work/err.txt")" -le 2 ] || fail "$what: more than one message: $(cat "$work/err.txt")"
  [ ! -e "$file" ] || fail "$what: $file was left behind"
  if ls -a "$(dirname "$file")" 2>/dev/null | grep -qE '\.tmp(\.(mp4|webm|gif))?$'; then fail "$what: temporary file left behind"; fi
}

out=$work/out
mkdir -p "$out"

# An exemplar image as noise (Gaussianized), and an image colormap: a pattern
# file whose images are written by the noise and colormap commands.
make_exemplar() {
  "$bin" noise '{"type":"spectrum","size":64,"seed":3,"components":[{"shape":"ring","frequency":8,"bandwidth":2}]}' -o "$out/noise.png" >/dev/null || fail "make_exemplar: noise"
  "$bin" colormap --preset marble -o "$out/cm.png" --resolution 64 >/dev/null || fail "make_exemplar: colormap"
  cat >"$work/exemplar.json" <<JSON
{"noise_x": {"type": "image", "path": "out/noise.png"},
 "noise_y": {"type": "image", "path": "out/noise.png", "gaussianize": false},
 "colormap": {"type": "image", "path": "out/cm.png"}, "size": 64}
JSON
}

# --- help on every command ---
case_help() {
  for c in render gallery noise colormap presets nodes zoom correlation contrast analyze stimuli marble spectrum flow coherence fractalize reproduce scene view bake bake-image web; do
    "$bin" $c --help >/dev/null 2>&1 || fail "$c --help exits non-zero"
  done
  # Usage names the command as a person types it, not the binary's path.
  "$bin" render --help | grep -q "^Usage: stochtex render " || fail "render --help: Usage does not read 'stochtex render'"
  "$bin" --help | grep -q "^Usage: stochtex " || fail "--help: Usage does not read 'stochtex'"
}

# --- success paths ---
case_render() {
  expect_ok "render preset" "$out/camo.png" -- "$bin" render --preset camouflage -o "$out/camo.png" --size 64
  expect_ok "render exr" "$out/camo.exr" -- "$bin" render --preset camouflage -o "$out/camo.exr" --size 32,24
  expect_ok "render file" "$out/file.png" -- "$bin" render "$src/data/presets/woven.json" -o "$out/file.png" --size 48 --scale 2 --offset 10,-3.5
  expect_ok "render 1 thread" "$out/t1.png" -- "$bin" render --preset marble -o "$out/t1.png" --size 128 -j 1
  expect_ok "render 2 threads" "$out/t2.png" -- "$bin" render --preset marble -o "$out/t2.png" --size 128 -j 2
  cmp -s "$out/t1.png" "$out/t2.png" || fail "render differs between 1 and 2 threads"
  expect_ok "render other seed" "$out/s2.png" -- "$bin" render --preset marble -o "$out/s2.png" --size 128 --seed 99
  cmp -s "$out/t1.png" "$out/s2.png" && fail "different seeds gave identical images"
  # The normal map of a pattern, shaded (LEAN), unfiltered and filtered, and the variant without covariance.
  expect_ok "render lean none" "$out/lean_none.png" -- "$bin" render --preset lean-ridges --response lean --filter none --view plane --tilt 70 --size 64,40 -o "$out/lean_none.png"
  grep -q "filter none/lean" "$work/out.txt" || fail "render lean: the report does not name the response: $(cat "$work/out.txt")"
  expect_ok "render lean smooth" "$out/lean_smooth.png" -- "$bin" render --preset lean-ridges --response lean --filter smooth --view plane --tilt 70 --size 64,40 -o "$out/lean_smooth.png"
  expect_ok "render lean no cov" "$out/lean_nocov.png" -- "$bin" render --preset lean-ridges --response lean --no-covariance --filter smooth --view plane --tilt 70 --size 64,40 -o "$out/lean_nocov.png"
  cmp -s "$out/lean_none.png" "$out/lean_smooth.png" && fail "render lean: filtered and unfiltered shading are identical"
  cmp -s "$out/lean_smooth.png" "$out/lean_nocov.png" && fail "render lean: the covariance changes nothing"
}

case_noise() {
  expect_ok "noise inline" "$out/noise.png" -- "$bin" noise '{"type":"spectrum","size":64,"seed":3,"components":[{"shape":"ring","frequency":8,"bandwidth":2}]}' -o "$out/noise.png" --spectrum "$out/spec.png"
  [ -s "$out/spec.png" ] || fail "noise --spectrum not written"
  # What noise writes, render takes: a size the filtered paths cannot use is refused here.
  expect_bad "noise npot" "$out/n48.png" "/size: must be a power of two" -- "$bin" noise '{"type":"spectrum","size":48,"components":[{"shape":"lowpass","cutoff":4}]}' -o "$out/n48.png"
  # A 24-pixel exemplar is resampled to 32 for filtering, and says so.
  expect_ok "exemplar 24" "$out/e24.png" -- "$bin" render --preset gaussian --size 24 -o "$out/e24.png"
  printf '{"noise_x":{"type":"image","path":"e24.png"},"noise_y":{"type":"image","path":"e24.png"},"colormap":{"type":"gaussian"}}' >"$out/npot.json"
  expect_ok "npot exemplar smooth" "$out/npot.png" -- "$bin" render --pattern "$out/npot.json" --size 32 --filter smooth -o "$out/npot.png"
  grep -q "resampled from 24x24 to 32x32" "$work/err.txt" || fail "npot exemplar: no resampling note: $(cat "$work/err.txt")"
}

case_colormap() {
  expect_ok "colormap preset" "$out/cm.png" -- "$bin" colormap --preset marble -o "$out/cm.png" --resolution 64
  expect_ok "colormap inline" "$out/cm2.png" -- "$bin" colormap '{"type":"phasor","profile":"square","duty":0.3}' -o "$out/cm2.png"
}

case_presets() {
  expect_ok "presets" "" -- "$bin" presets
  grep -q "camouflage" "$work/out.txt" || fail "presets does not list camouflage"
}

case_gallery() {
  expect_ok "gallery" "$out/gal/index.html" -- "$bin" gallery -o "$out/gal" --size 64 --preset gaussian --preset woven
  [ -s "$out/gal/woven-sheet.png" ] || fail "gallery sheet missing"
  # A pattern with a normal map shows its LEAN shading beside the colours: a
  # sheet one pattern wider (PNG width: bytes 16-19 of the IHDR).
  expect_ok "gallery lean" "$out/gal/lean-ridges-sheet.png" -- "$bin" gallery -o "$out/gal" --size 64 --preset lean-ridges
  w=$(od -An -tu1 -j16 -N4 "$out/gal/lean-ridges-sheet.png" | awk '{print $1*16777216+$2*65536+$3*256+$4}')
  [ "$w" -eq 192 ] || fail "gallery lean-ridges sheet is $w wide, expected 192 (pattern, LEAN shading, H and N)"
  # The user's own files, a graph among them.
  expect_ok "gallery of files" "$out/galf/painted-bumps-sheet.png" -- "$bin" gallery -o "$out/galf" --size 64 "$src/data/graphs/painted-bumps.json" "$src/data/presets/woven.json"
  [ -s "$out/galf/woven-sheet.png" ] || fail "gallery of files: woven sheet missing"
  grep -q "painted-bumps" "$out/galf/index.html" || fail "gallery of files: index.html lacks painted-bumps"
  expect_bad "gallery of a missing file" "$out/galm/index.html" "nope.json" -- "$bin" gallery -o "$out/galm" "$work/nope.json"
}

# Filtered rendering: every mode, both views.
case_filter() {
  for f in none paper smooth; do
    expect_ok "filter $f" "$out/f-$f.png" -- "$bin" render --preset marble -o "$out/f-$f.png" --size 32 --scale 8 --filter $f
  done
  for f in exact reference; do  # the filters that sample the footprint
    expect_ok "filter $f" "$out/f-$f.png" -- "$bin" render --preset marble -o "$out/f-$f.png" --size 32 --scale 8 --filter $f --reference-samples 16
  done
  expect_ok "plane view" "$out/plane.png" -- "$bin" render --preset camouflage -o "$out/plane.png" --size 48 --view plane --tilt 70 --filter smooth --aniso 8
  expect_ok "deliot-heitz" "$out/dh.png" -- "$bin" render --preset camouflage -o "$out/dh.png" --size 32 --scale 16 --filter paper --estimator deliot-heitz
}

case_exemplar() {
  make_exemplar
  expect_ok "exemplar pattern" "$out/ex.png" -- "$bin" render "$work/exemplar.json" -o "$out/ex.png"
}

case_stability() {
  expect_ok "stability" "$out/stab/stability-frames.csv" -- "$bin" stability --preset marble -o "$out/stab" --frames 3 --size 16 --to 8 --filters none,smooth --write-frames
  [ -s "$out/stab/smooth-002.png" ] || fail "stability: frames not written"
  [ "$(wc -l <"$out/stab/stability.csv")" -eq 3 ] || fail "stability.csv: expected a header and 2 rows"
  # A filter over the estimators is measured once per --estimators name, its frames named so.
  expect_ok "stability per estimator" "$out/stabe/stability.csv" -- "$bin" stability --preset gaussian -o "$out/stabe" --frames 2 --size 16 --to 4 --filters none,smooth --estimators paper,sub-probes-4x4 --write-frames
  grep -q "^smooth/sub-probes-4x4," "$out/stabe/stability.csv" || fail "stability: no row for smooth/sub-probes-4x4: $(cat "$out/stabe/stability.csv")"
  [ "$(wc -l <"$out/stabe/stability.csv")" -eq 4 ] || fail "stability per estimator: expected a header and 3 rows"
  [ -s "$out/stabe/smooth-sub-probes-4x4-001.png" ] || fail "stability per estimator: frames not written: $(ls "$out/stabe")"
  expect_bad "stability bad estimator" "$out/stabeb" '--estimators: estimator must be paper, deliot-heitz, sub-probes, sub-probes-4x4 or sub-probes-8x8-fine-means, got "nosuch"' -- "$bin" stability --preset gaussian -o "$out/stabeb" --estimators nosuch
  expect_bad "stability repeated estimator" "$out/stabec" "--estimators: estimators must name each estimator once, got paper twice" -- "$bin" stability --preset gaussian -o "$out/stabec" --estimators paper,sub-probes,paper
  expect_bad "stability estimators without effect" "$out/stabed" "--estimators: has no effect without a filter over the estimators (paper, smooth)" -- "$bin" stability --preset gaussian -o "$out/stabed" --filters none,exact --estimators sub-probes
}

# --- thesis studies (small) ---
case_zoom() {
  expect_ok "zoom frames" "$out/zoom/frame_0002.png" -- "$bin" zoom -o "$out/zoom" --frames 3 --size 64 --layers 4 --offsets hashed --no-video
}

case_correlation() {
  expect_ok "correlation" "$out/corr/figure2_10.png" -- "$bin" correlation -o "$out/corr" --variant fixed,random --layers-list 4 --instances 16 --size 16
  grep -q "^random,4,16," "$out/corr/correlation.csv" || fail "correlation.csv lacks the random,n=4 row"
}

case_contrast() {
  expect_ok "contrast" "$out/contrast/figure2_6.png" -- "$bin" contrast -o "$out/contrast" --size 64 --layers 8
  grep -q "^sigmoid,0," "$out/contrast/contrast.csv" || fail "contrast.csv: the sigmoid should clamp 0% of pixels"
  # --time is the zoom's t: another time (not a multiple of the layers' period H/n) is another texture.
  expect_ok "contrast at a time" "$out/contrast_t/contrast.csv" -- "$bin" contrast -o "$out/contrast_t" --size 64 --layers 8 --time 0.06
  cmp -s "$out/contrast/contrast.csv" "$out/contrast_t/contrast.csv" && fail "contrast --time 0.06 measured the texture at t = 0"
}

# Spectra and optical flow of the three kinds of source (issue 14 items 1, 3).
case_spectrum() {
  expect_ok "spectrum zoom" "$out/sp/index.html" -- "$bin" spectrum -o "$out/sp" --instances 4 --size 64 zoom --layers 3
  grep -q "^4," "$out/sp/spectrum.csv" || fail "spectrum.csv: not 4 frames: $(cat "$out/sp/spectrum.csv")"
  expect_ok "spectrum pattern" "$out/sp2/spectrum.png" -- "$bin" spectrum -o "$out/sp2" --size 64 pattern --preset woven
  # --size W,H (the window flag spectrum, flow and coherence share): the frame shown is that window.
  expect_ok "spectrum W,H" "$out/sp6/frame.png" -- "$bin" spectrum -o "$out/sp6" --size 40,24 zoom --layers 3
  local dims
  dims=$(od -An -tu1 -j16 -N8 "$out/sp6/frame.png" | awk '{print $3*256+$4 "x" $7*256+$8}')
  [ "$dims" = 40x24 ] || fail "spectrum --size 40,24: frame.png is $dims"
  # Image files: a bi-lobe noise written by `noise`, its anisotropy far above 1.
  "$bin" noise '{"type":"spectrum","size":64,"seed":2,"components":[{"shape":"bilobe","frequency":8,"bandwidth":1,"orientation":45}]}' -o "$out/lobe.png" >/dev/null
  expect_ok "spectrum images" "$out/sp3/radial.csv" -- "$bin" spectrum -o "$out/sp3" --window none images "$out/lobe.png"
  awk -F, 'NR==2 && !($4 > 5) {exit 1}' "$out/sp3/spectrum.csv" || fail "bi-lobe image: anisotropy not > 5: $(cat "$out/sp3/spectrum.csv")"
  expect_bad "spectrum images size" "$out/sp4" "--size: has no effect on image files" -- "$bin" spectrum -o "$out/sp4" --size 32 images "$out/lobe.png"
  expect_bad "spectrum no source" "$out/sp5" "A subcommand is required" -- "$bin" spectrum -o "$out/sp5"
}

case_coherence() {
  expect_ok "coherence zoom" "$out/co/index.html" -- "$bin" coherence -o "$out/co" --size 48 --frames 6 --step 0.25 --layers-list 3,8 zoom --base-size 128
  [ "$(wc -l <"$out/co/frames.csv")" -eq 7 ] || fail "coherence: frames.csv lacks a row per frame"
  grep -q "^8," "$out/co/layers.csv" || fail "coherence: layers.csv lacks n = 8"
  [ -s "$out/co/layers.png" ] && [ -s "$out/co/frames.png" ] || fail "coherence: figures missing"
  expect_ok "coherence pattern" "$out/co2/coherence.csv" -- "$bin" coherence -o "$out/co2" --size 32 --frames 2 pattern --preset marble
  expect_bad "coherence layers on a pattern" "$out/co3" "--layers-list: has no effect without the zoom texture" -- "$bin" coherence -o "$out/co3" --size 32 --layers-list 3 pattern --preset marble
  expect_bad "coherence one frame" "$out/co4" "--frames: frames must be in [2, 10000], got 1" -- "$bin" coherence -o "$out/co4" --frames 1 zoom
  # Every parameter is checked before the output folder is made, the layer counts included.
  expect_bad "coherence layer count" "$out/co5" "--layers-list: layersList must be in [1, 64] each, got 0" -- "$bin" coherence -o "$out/co5" --size 32 --frames 2 --layers-list 0 zoom
  "$bin" render --preset marble --size 16 -o "$out/f.png" >/dev/null || fail "coherence: render an image"
  expect_bad "coherence images size" "$out/co6" "--size: has no effect on image files (each file is a frame)" -- "$bin" coherence -o "$out/co6" --size 32 images "$out/f.png"
}

case_fractalize() {
  # The shipped textures are what the script makes.
  bash "$src/scripts/make-textures.sh" "$bin" "$out/tex" >/dev/null 2>&1 || fail "make-textures.sh failed"
  for f in "$src"/data/textures/*.png; do cmp -s "$f" "$out/tex/$(basename "$f")" || fail "data/textures: $(basename "$f") differs from what make-textures.sh writes"; done
  expect_ok "fractalize" "$out/fr/figure2_17.png" -- "$bin" fractalize "$src/data/textures/stone.png" "$src/data/textures/weld.png" -o "$out/fr" --size 32 --instances 16
  [ "$(wc -l <"$out/fr/fractalize.csv")" -eq 3 ] || fail "fractalize: the CSV lacks a row per image"
  expect_bad "fractalize one instance" "$out/fr2" "--instances: instances must be in [2, 100000], got 1" -- "$bin" fractalize "$src/data/textures/stone.png" -o "$out/fr2" --instances 1
  expect_bad "fractalize missing image" "$out/fr3" "nope.png: no such image file" -- "$bin" fractalize "$work/nope.png" -o "$out/fr3"
}

case_flow() {
  expect_ok "flow zoom" "$out/fl/flow_arrows.png" -- "$bin" flow -o "$out/fl" --frames 3 --dt 0.05 --size 64 --step 8 --video zoom --layers 4
  [ -s "$out/fl/frames.mp4" ] && [ -s "$out/fl/frames.webp" ] || fail "flow --video: frames.mp4 or frames.webp missing"
  grep -q "<img src='frames.webp'>" "$out/fl/index.html" || fail "flow --video: index.html does not show the preview"
  # The zoom texture zooms in at rate 1 per time unit: ~0.05 per frame, outward.
  awk -F, '$1=="mean" && !($8 > 0.03 && $8 < 0.07) {exit 1}' "$out/fl/flow.csv" || fail "flow zoom: expansion rate off: $(cat "$out/fl/flow.csv")"
  "$bin" render --preset marble --size 64 -o "$out/f0.png" >/dev/null
  "$bin" render --preset marble --size 64 --offset 2,0 -o "$out/f1.png" >/dev/null
  expect_ok "flow images" "$out/fl2/flow.csv" -- "$bin" flow -o "$out/fl2" --method dis --step 8 images "$out/f0.png" "$out/f1.png"
  expect_bad "flow one image" "$out/fl3" "images: the flow needs at least 2 image files" -- "$bin" flow -o "$out/fl3" images "$out/f0.png"
  expect_bad "flow bad method" "$out/fl4" "--method" -- "$bin" flow -o "$out/fl4" --method magic zoom
}

case_analyze() {
  expect_ok "analyze" "$out/an/index.html" -- "$bin" analyze -o "$out/an" --instances 8 --plot-size 16 --layers-list 4 --size 64 --frame-size 32 --coherence-layers 3,8
  grep -q "figure2_10.png" "$out/an/index.html" || fail "analyze: index.html lacks the correlation sheet"
  for f in spectrum/spectrum.png flow/flow_arrows.png coherence/layers.png coherence/frames.png; do
    grep -q "$f" "$out/an/index.html" || fail "analyze: index.html lacks $f"
  done
  grep -q "Figure 2.25" "$out/an/index.html" || fail "analyze: the flow section names no thesis figure"
  for f in marble/stretching.png marble/correlation.png marble/spectra.png marble/sliding_continuous.webp stimuli/stimuli.png stimuli/experiment.html; do
    grep -q "$f" "$out/an/index.html" || fail "analyze: index.html lacks $f"
    [ -s "$out/an/$f" ] || fail "analyze: $f not written"
  done
  grep -q "Figures 2.23–2.24" "$out/an/index.html" || fail "analyze: the marble section names no thesis figure"
  expect_ok "analyze with images" "$out/an3/images/figure2_15.png" -- "$bin" analyze -o "$out/an3" --instances 8 --plot-size 16 --layers-list 4 --size 64 --frame-size 32 --coherence-layers 3 --images "$src/data/textures/stone.png"
  # No wall-clock time on the page: a second run writes identical files.
  "$bin" analyze -o "$out/an2" --instances 8 --plot-size 16 --layers-list 4 --size 64 --frame-size 32 --coherence-layers 3,8 >/dev/null 2>&1
  diff -r "$out/an" "$out/an2" >/dev/null || fail "analyze: two runs wrote different files"
}

# --- the perception experiment (thesis 2.6.2) ---
case_stimuli() {
  expect_ok "stimuli" "$out/st/experiment.html" -- "$bin" stimuli -o "$out/st" --size 32 --tiles 4,8,16 --correlations 0,0.5,1 --repeats 2 --seed 5 -j 1
  [ "$(ls "$out/st"/*.png | wc -l)" -eq 18 ] || fail "stimuli: not 18 PNGs: $(ls "$out/st")"
  [ "$(wc -l <"$out/st/stimuli.csv")" -eq 19 ] || fail "stimuli.csv: not 18 rows"
  head -1 "$out/st/stimuli.csv" | grep -qx "trial,stimulus,w,correlation,alpha,repeat,seed" || fail "stimuli.csv header: $(head -1 "$out/st/stimuli.csv")"
  grep -q ",w16_c1_r2.png,16,1,1,2," "$out/st/stimuli.csv" || fail "stimuli.csv lacks w16_c1_r2.png with alpha 1"
  grep -q ",w8_c0.5_r1.png,8,0.5,0.5,1," "$out/st/stimuli.csv" || fail "stimuli.csv lacks w8_c0.5_r1.png with alpha 0.5"
  [ "$(grep -o 'data:image/png;base64,' "$out/st/experiment.html" | wc -l)" -eq 18 ] || fail "experiment.html does not embed 18 images"
  expect_ok "stimuli 2 threads" "$out/st2/experiment.html" -- "$bin" stimuli -o "$out/st2" --size 32 --tiles 4,8,16 --correlations 0,0.5,1 --repeats 2 --seed 5 -j 2
  diff -r "$out/st" "$out/st2" >/dev/null || fail "stimuli: 1 and 2 threads wrote different files"
  expect_ok "stimuli other seed" "$out/st3/stimuli.csv" -- "$bin" stimuli -o "$out/st3" --size 32 --tiles 4,8,16 --correlations 0,0.5,1 --repeats 2 --seed 6
  cmp -s "$out/st/stimuli.csv" "$out/st3/stimuli.csv" && fail "stimuli: another seed gave the same trial order"
  cmp -s "$out/st/w8_c0.5_r1.png" "$out/st3/w8_c0.5_r1.png" && fail "stimuli: another seed gave the same image"
  # Analysis: w 8 at correlation 0: 1 of 2 yes; at 1: 2 of 2 (Wilson 95 %: [0.34238, 1]).
  printf 'trial,stimulus,w,correlation,alpha,answer,response_time_ms,shown_ms\n1,a.png,8,0,0,yes,400,1000\n2,b.png,8,1,1,yes,300,1000\n3,c.png,8,0,0,no,500,1000\n4,d.png,8,1,1,yes,350,1000\n' >"$work/answers.csv"
  expect_ok "stimuli analyse" "$out/an/index.html" -- "$bin" stimuli --analyse "$work/answers.csv" -o "$out/an"
  grep -qx "8,0,2,1,0.5,0.0945312,0.905469" "$out/an/detection.csv" || fail "detection.csv lacks 8,0 at 1 of 2: $(cat "$out/an/detection.csv")"
  grep -qx "8,1,2,2,1,0.34238,1" "$out/an/detection.csv" || fail "detection.csv lacks 8,1 at 2 of 2: $(cat "$out/an/detection.csv")"
  for f in detection.png detection_w8.png detection.md; do [ -s "$out/an/$f" ] || fail "analyse: $f not written"; done
}

case_marble() {
  expect_ok "marble" "$out/mb/index.html" -- "$bin" marble -o "$out/mb" --size 64 --correlation-size 32 --instances 32 --spectrum-instances 2 --frames 4 --step 8 -j 1
  for f in stretching.png stretch.png correlation.png spectra.png sliding_expansion.png sliding_continuous_flow_arrows.png \
           sliding_continuous.mp4 sliding_continuous.webp sliding_blended-corrected.mp4 sliding_blended-corrected.webp \
           correlation.csv spectra.csv sliding.csv; do
    [ -s "$out/mb/$f" ] || fail "marble: $f not written"
  done
  grep -q "<img src='sliding_continuous.webp'>" "$out/mb/index.html" || fail "marble: index.html does not show the preview"
  grep -q "Figure 2.22" "$out/mb/index.html" || fail "marble: the spectra section names no thesis figure"
  head -1 "$out/mb/sliding.csv" | grep -qx "layer,scaling,mean_magnitude,mean_radial,outward_fraction,expansion_rate,scaling_rate" || fail "sliding.csv header: $(head -1 "$out/mb/sliding.csv")"
  expect_ok "marble 2 threads" "$out/mb2/index.html" -- "$bin" marble -o "$out/mb2" --size 64 --correlation-size 32 --instances 32 --spectrum-instances 2 --frames 4 --step 8 -j 2
  for f in correlation.csv spectra.csv sliding.csv stretching.png correlation.png; do
    cmp -s "$out/mb/$f" "$out/mb2/$f" || fail "marble: $f differs between 1 and 2 threads"
  done
  # The texture as a source of the frame studies.
  expect_ok "spectrum marble" "$out/ms/spectrum.csv" -- "$bin" spectrum -o "$out/ms" --size 64 marble --layer scaled-noise --scaling blended
  expect_ok "flow marble" "$out/mf/flow.csv" -- "$bin" flow -o "$out/mf" --size 64 --frames 3 --step 8 marble --level-amplitude 0 --level-rate 1
  awk -F, '$1=="mean" && !($8 > 0.015 && $8 < 0.04) {exit 1}' "$out/mf/flow.csv" || fail "flow marble: expansion rate off 2^(1/30) - 1: $(cat "$out/mf/flow.csv")"
  expect_bad "marble bad scaling" "$out/mb3" "--scalings" -- "$bin" marble -o "$out/mb3" --scalings stretchy
  expect_bad "marble correlation window" "$out/mb4" "--correlation-size: correlationSize must not exceed size (64), got 96" -- "$bin" marble -o "$out/mb4" --size 64
  expect_bad "marble band period" "$out/mb5" "--band-period: bandPeriod must be in [1, 1e+06], got 0" -- "$bin" marble -o "$out/mb5" --band-period 0
  # --point sets two parameters; the binding names the flag for both.
  expect_bad "marble point far away" "$out/mb7" "--point: pointY must be within 2¹⁹ pixels of the origin, got 1e+07" -- "$bin" marble -o "$out/mb7" --point 0,1e7
  expect_bad "marble source time" "$out/mb6" "marble texture: at time 1 the noise scale exponent l = m + n cos(q x) + r t spans [119, 121]" -- "$bin" flow -o "$out/mb6" --size 48 --frames 2 --dt 1 --step 8 marble --level-rate 100 --level 20
}

case_graph() {
  # A graph file is a pattern file: the camouflage preset as a graph renders byte-identical to it.
  expect_ok "render graph" "$out/g.png" -- "$bin" render "$src/data/graphs/camouflage.json" --size 96 -o "$out/g.png"
  expect_ok "render preset" "$out/p.png" -- "$bin" render --preset camouflage --size 96 -o "$out/p.png"
  cmp -s "$out/g.png" "$out/p.png" || fail "graph: data/graphs/camouflage.json differs from the camouflage preset"
  expect_ok "render derivative graph filtered" "$out/d.png" -- "$bin" render "$src/data/graphs/derivative-ridges.json" --size 64 --filter smooth --scale 4 -o "$out/d.png"
  expect_ok "bake graph" "$out/bk/manifest.json" -- "$bin" bake "$src/data/graphs/derivative-ridges.json" -o "$out/bk"
  "$bin" nodes | grep -q "^derivative (linear; input: field → field)" || fail "nodes: derivative not listed"
  "$bin" nodes --json | grep -q '"type": "spectral_noise"' || fail "nodes --json: spectral_noise not listed"
  printf '{"nodes": {"a": {"type": "affine", "input": "b"}, "b": {"type": "affine", "input": "a"}, "c": {"type": "colormap", "x": "a", "y": "b", "colormap": {"type": "gaussian"}}}, "output": "c"}' >"$work/cycle.json"
  expect_bad "graph cycle" "$out/cy.png" "cycle.json: /nodes/" -- "$bin" render "$work/cycle.json" -o "$out/cy.png"
  grep -q "closes a cycle" "$work/err.txt" || fail "graph cycle: message lacks 'closes a cycle': $(cat "$work/err.txt")"
  printf '{"nodes": {"c": {"type": "colormap", "x": "c", "y": "c", "colormap": {"type": "gaussian"}}}, "output": "c"}' >"$work/colour.json"
  expect_bad "graph colour into a field" "$out/co.png" "colour.json: /nodes/c/x: expects a field, but \"c\" (colormap) gives a colour" -- "$bin" render "$work/colour.json" -o "$out/co.png"
  # Non-linear nodes before the output (Figure 14): evaluated per pixel, filtered by moment matching.
  for node in colormap_field curve mix; do "$bin" nodes | grep -q "^$node (" || fail "nodes: $node not listed"; done
  expect_ok "render figure14" "$out/f14.png" -- "$bin" render --preset figure14 --size 48 -o "$out/f14.png"
  expect_ok "render figure14 smooth" "$out/f14s.png" -- "$bin" render --preset figure14 --size 48 --scale 8 --filter smooth -o "$out/f14s.png"
  expect_ok "render figure14 reference" "$out/f14r.png" -- "$bin" render --preset figure14 --size 32 --scale 8 --filter reference --reference-samples 8 -o "$out/f14r.png"
  expect_ok "render figure14 on the GPU" "$out/f14g.png" -- "$bin" render --preset figure14 --size 48 --scale 8 --filter smooth --gpu -o "$out/f14g.png"
  expect_ok "render figure14 on the GPU, compute" "$out/f14c.png" -- "$bin" render --preset figure14 --size 48 --scale 8 --filter smooth --gpu --pipeline compute -o "$out/f14c.png"
  expect_ok "figure14 in a scene" "$out/f14sc.png" -- "$bin" scene --preset figure14 --filter smooth --size 64 -o "$out/f14sc.png"
  expect_ok "stability of figure14" "$out/f14st/stability.csv" -- "$bin" stability -o "$out/f14st" --preset figure14 --frames 2 --size 16 --filters none,smooth --truth-samples 4
  expect_ok "figure14 in figure 4" "$out/f14f4/figure4.csv" -- "$bin" reproduce figure4 -o "$out/f14f4" --preset figure14 --size 16 --reference-samples 4
  expect_ok "bake figure14" "$out/bk14/stochtex.glsl" -- "$bin" bake --preset figure14 --filter smooth -o "$out/bk14"
  grep -q '"uniform": "uGraphPrefiltered1"' "$out/bk14/manifest.json" || fail "bake figure14: manifest lacks the second table's sampler"
  grep -q "vec3 filteredColour(vec2 uv, vec2 jx, vec2 jy)" "$out/bk14/stochtex.glsl" || fail "bake figure14: the include lacks the graph's program"
  expect_bad "figure14 lean" "$out/f14l.png" "response" -- "$bin" render --preset figure14 --filter smooth --response lean -o "$out/f14l.png"
  printf '{"nodes": {"a": {"type": "spectral_noise", "size": 32, "components": [{"shape": "lowpass", "cutoff": 2}]}, "k": {"type": "curve", "input": "a", "points": [[0, 0], [0, 1]]}, "c": {"type": "colormap", "x": "k", "y": "a", "colormap": {"type": "gaussian"}}}, "output": "c"}' >"$work/curve.json"
  expect_bad "graph bad curve" "$out/cu.png" "curve.json: /nodes/k/points/1/0: x must increase" -- "$bin" render "$work/curve.json" -o "$out/cu.png"
  expect_ok "reproduce figure14" "$out/rf14/figure14.csv" -- "$bin" reproduce figure14 -o "$out/rf14" --size 24 --footprints 1,16 --reference-samples 8
  [ -s "$out/rf14/figure14_filtering.png" ] || fail "reproduce figure14: figure14_filtering.png not written"
  grep -q "^16," "$out/rf14/figure14.csv" || fail "reproduce figure14: no row for footprint 16: $(cat "$out/rf14/figure14.csv")"
  expect_ok "reproduce estimators" "$out/rest/estimators.csv" -- "$bin" reproduce estimators -o "$out/rest" --presets woven --scales 2,8 --size 24 --reference-samples 8 --no-plane
  grep -q "^woven,zoom ×8,8," "$out/rest/estimators.csv" || fail "reproduce estimators: no row for woven at ×8: $(cat "$out/rest/estimators.csv")"
  head -1 "$out/rest/estimators.csv" | grep -q "mean_error_sub_probes_4x4" || fail "reproduce estimators: no column for sub-probes-4x4"
  [ -s "$out/rest/estimators_woven.png" ] || fail "reproduce estimators: estimators_woven.png not written"
  expect_bad "estimators unknown preset" "$out/resb/estimators.csv" '--presets: presets must name known presets (stochtex presets lists them), got "nosuch"' -- "$bin" reproduce estimators -o "$out/resb" --presets nosuch
  # A colour exemplar as one 3-channel tiled field, the albedo of a lean node.
  for node in tiled_field channel compose lean; do "$bin" nodes | grep -q "^$node (" || fail "nodes: $node not listed"; done
  expect_ok "render painted-bumps" "$out/pb.png" -- "$bin" render "$src/data/graphs/painted-bumps.json" --size 64 --view plane --filter smooth -o "$out/pb.png"
  expect_ok "render painted-bumps on the GPU" "$out/pbg.png" -- "$bin" render "$src/data/graphs/painted-bumps.json" --size 64 --view plane --filter smooth --gpu -o "$out/pbg.png"
  expect_ok "bake painted-bumps" "$out/bkpb/manifest.json" -- "$bin" bake "$src/data/graphs/painted-bumps.json" -o "$out/bkpb"
  grep -q '"uniform": "uGraphCov' "$out/bkpb/manifest.json" || fail "bake painted-bumps: manifest lacks the slopes' covariance sampler"
  printf '{"nodes": {"t": {"type": "tiled_field", "path": "%s"}, "k": {"type": "channel", "field": "t", "index": 2}, "c": {"type": "colormap", "x": "k", "y": "k", "colormap": {"type": "gaussian"}}}, "output": "c"}' "$src/data/textures/stone.png" >"$work/channel.json"
  expect_bad "graph missing channel" "$out/ch.png" "stone.png has 1 channel; there is no channel 2" -- "$bin" render "$work/channel.json" -o "$out/ch.png"
}

case_shadertoy() {
  # A two-pass program with feedback: buffer A counts frames, the image shows it beside a gradient.
  mkdir -p "$work/st"
  printf 'void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0) + vec4(1.0, 0.0, 0.0, 0.0); }\n' >"$work/st/a.glsl"
  printf 'void mainImage(out vec4 c, in vec2 p) { vec2 uv = p / iResolution.xy; c = vec4(uv, texelFetch(iChannel0, ivec2(p), 0).x / 10.0, 1.0); }\n' >"$work/st/image.glsl"
  printf '{"name": "counter", "passes": {"buffer_a": {"code": "a.glsl", "channels": [{"type": "buffer", "buffer": "a"}]}, "image": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "a"}]}}}' >"$work/st/shadertoy.json"
  expect_ok "shadertoy frame" "$out/st.png" -- "$bin" shadertoy "$work/st" --size 32,16 --frames 4 -o "$out/st.png"
  expect_ok "shadertoy sheet" "$out/sts.png" -- "$bin" shadertoy "$work/st" --size 32,16 --frames 5 --sheet -o "$out/sts.png"
  expect_ok "shadertoy video" "$out/st.mp4" -- "$bin" shadertoy "$work/st" --size 32,16 --frames 8 --fps 24 -o "$out/st.mp4"
  expect_ok "shadertoy frames" "$out/stf/frame_0002.png" -- "$bin" shadertoy "$work/st" --size 32,16 --frames 3 -o "$out/stf"
  # The output's extension says what is written: one file each, no folder.
  for ext in gif webp webm; do
    expect_ok "shadertoy -o st.$ext" "$out/st.$ext" -- "$bin" shadertoy "$work/st" --size 32,16 --frames 6 --fps 24 -o "$out/st.$ext"
    [ -f "$out/st.$ext" ] || fail "shadertoy -o st.$ext: not a file"
  done
  head -c 6 "$out/st.gif" | grep -q "GIF89a" || fail "shadertoy -o st.gif: not a GIF89a"
  head -c 16 "$out/st.webp" | grep -q "WEBPVP8X" || fail "shadertoy -o st.webp: not an extended (animated) WebP"
  expect_bad "shadertoy unknown extension" "$out/st.avi" "st.avi: expected an image (.png" -- "$bin" shadertoy "$work/st" --size 32,16 --frames 2 -o "$out/st.avi"
  expect_bad "zoom unknown extension" "$out/z.mov" "cannot write frames as \".mov\"" -- "$bin" zoom --frames 2 --size 16 -o "$out/z.mov"
  "$bin" shadertoy "$work/st" --size 32,16 --frames 7 --inspect buffer_a:3,4 >"$work/inspect.txt" 2>&1 || fail "shadertoy inspect: $(cat "$work/inspect.txt")"
  grep -q "^buffer_a (3, 4) at iFrame 6: 7 0 0 0$" "$work/inspect.txt" || fail "shadertoy inspect: $(cat "$work/inspect.txt")"
  # Events on a timeline, with ShaderToy's click semantics: a buffer counts "just clicked" frames (w > 0),
  # held frames (z > 0) and frames with space pressed; --event and --input give the same run.
  mkdir -p "$work/clicks"
  printf 'void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(0), 0) + vec4(iMouse.w > 0.0 ? 1.0 : 0.0, iMouse.z > 0.0 ? 1.0 : 0.0, texelFetch(iChannel1, ivec2(32, 1), 0).x, 0.0); }\n' >"$work/clicks/a.glsl"
  printf 'void mainImage(out vec4 c, in vec2 p) { c = iMouse; }\n' >"$work/clicks/image.glsl"
  printf '{"passes": {"buffer_a": {"code": "a.glsl", "channels": [{"type": "buffer", "buffer": "a"}, {"type": "keyboard"}]}, "image": {"code": "image.glsl"}}}' >"$work/clicks/shadertoy.json"
  "$bin" shadertoy "$work/clicks" --size 8,8 --frames 10 --event 2:mousedown:3,4 --event 0.1s:mouseup --event 8:mousedown:1,2 --event 3:keydown:32 --inspect buffer_a:0,0 >"$work/clicks.txt" 2>&1 || fail "shadertoy events: $(cat "$work/clicks.txt")"
  grep -q "^buffer_a (0, 0) at iFrame 9: 2 6 1 0$" "$work/clicks.txt" || fail "shadertoy events: want 2 clicks, 6 held frames, 1 press: $(cat "$work/clicks.txt")"
  printf '[{"frame": 2, "mousedown": [3, 4]}, {"frame": 3, "keydown": 32}, {"time": 0.1, "mouseup": true}, {"frame": 8, "mousedown": [1, 2]}]' >"$work/clicks.json"
  "$bin" shadertoy "$work/clicks" --size 8,8 --frames 10 --input "$work/clicks.json" --inspect buffer_a:0,0 >"$work/clicks2.txt" 2>&1 || fail "shadertoy --input: $(cat "$work/clicks2.txt")"
  grep -q "^buffer_a (0, 0) at iFrame 9: 2 6 1 0$" "$work/clicks2.txt" || fail "shadertoy --input: $(cat "$work/clicks2.txt")"
  expect_bad "shadertoy bad event" "$out/ste.png" "--event: event \"2:click:1,1\": expected FRAME:EVENT" -- "$bin" shadertoy "$work/clicks" --event 2:click:1,1 -o "$out/ste.png"
  printf '[{"frame": 4, "keydown": 32}, {"frame": 2, "keyup": 32}]' >"$work/back.json"
  expect_bad "shadertoy timeline going back" "$out/ste.png" "back.json: /1: frames never go back" -- "$bin" shadertoy "$work/clicks" --input "$work/back.json" -o "$out/ste.png"
  # ShaderToy's export format runs as published, and --convert writes it as a folder that runs the same.
  printf '{"Shader": {"info": {"name": "exported"}, "renderpass": [{"type": "buffer", "name": "Buffer A", "code": "void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0) + vec4(1.0, 0.5, 0.0, 0.0); }", "inputs": [{"id": "4dXGR8", "ctype": "buffer", "channel": 0}], "outputs": [{"id": "4dXGR8"}]}, {"type": "image", "name": "Image", "code": "void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0); }", "inputs": [{"id": 257, "src": "/media/previz/buffer00.png", "ctype": "buffer", "channel": 0}], "outputs": [{"id": 37}]}]}}' >"$work/exported.json"
  "$bin" shadertoy "$work/exported.json" --size 8,8 --frames 4 --inspect image:2,2 >"$work/exp.txt" 2>&1 || fail "shadertoy export: $(cat "$work/exp.txt")"
  grep -q "^image (2, 2) at iFrame 3: 4 2 0 0$" "$work/exp.txt" || fail "shadertoy export: $(cat "$work/exp.txt")"
  expect_ok "shadertoy --convert" "$out/conv/shadertoy.json" -- "$bin" shadertoy "$work/exported.json" --convert "$out/conv"
  "$bin" shadertoy "$out/conv" --size 8,8 --frames 4 --inspect image:2,2 >"$work/conv.txt" 2>&1 || fail "shadertoy converted: $(cat "$work/conv.txt")"
  grep -q "^image (2, 2) at iFrame 3: 4 2 0 0$" "$work/conv.txt" || fail "shadertoy converted: $(cat "$work/conv.txt")"
  expect_bad "shadertoy --convert onto its own files" "" "--convert: output $out/conv/" -- "$bin" shadertoy "$work/exported.json" --convert "$out/conv"
  expect_bad "shadertoy --convert with -o" "$out/conv2.png" "--convert: writes the program and runs nothing" -- "$bin" shadertoy "$work/exported.json" --convert "$out/conv2" -o "$out/conv2.png"
  # A sound pass written as WAV: a 440 Hz tone reads its peak at 440 Hz.
  mkdir -p "$work/snd"
  printf 'void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }\n' >"$work/snd/image.glsl"
  printf 'vec2 mainSound(int s, float t) { return vec2(0.5 * sin(6.2831853 * 440.0 * t)); }\n' >"$work/snd/sound.glsl"
  "$bin" shadertoy "$work/snd" --sound "$out/tone.wav" --sound-seconds 2 >"$work/snd.txt" 2>&1 || fail "shadertoy --sound: $(cat "$work/snd.txt")"
  sed -n 's/.*spectrum peak at \([0-9.]*\) Hz.*/\1/p' "$work/snd.txt" | awk '{ exit !($1 > 439.5 && $1 < 440.5) }' || fail "shadertoy --sound: want a peak at 440 +- 0.5 Hz: $(cat "$work/snd.txt")"
  [ "$(stat -c %s "$out/tone.wav")" = "$((44 + 2 * 2 * 88200))" ] || fail "shadertoy --sound: tone.wav has $(stat -c %s "$out/tone.wav") bytes, want 352844"
  expect_bad "shadertoy --sound without a sound pass" "$out/none.wav" "--sound: sound counter has no sound pass" -- "$bin" shadertoy "$work/st" --sound "$out/none.wav"
  expect_bad "shadertoy --sound not wav" "$out/tone.mp3" "--sound: writes a .wav file" -- "$bin" shadertoy "$work/snd" --sound "$out/tone.mp3"
  printf 'void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(nope);\n}\n' >"$work/st/broken.glsl"
  printf '{"passes": {"image": {"code": "broken.glsl"}}}' >"$work/broken.json"
  cp "$work/st/broken.glsl" "$work/broken.glsl"
  expect_bad "shadertoy compile error" "$out/stb.png" "broken.glsl:2" -- "$bin" shadertoy "$work/broken.json" -o "$out/stb.png"
  expect_bad "shadertoy no output" "" "nothing to do: give -o/--output, --inspect, --sound or --convert" -- "$bin" shadertoy "$work/st"
  expect_bad "shadertoy inspect pass" "" "--inspect: pass \"buffer_c\" names no pass of counter" -- "$bin" shadertoy "$work/st" --inspect buffer_c:1,1
  expect_ok "spectrum of a shadertoy frame" "$out/sts/index.html" -- "$bin" spectrum -o "$out/sts" --size 64 shadertoy "$src/data/shadertoy/swirl" --size 96,80 --first-frame 120
  [ -s "$out/sts/spectrum.csv" ] || fail "spectrum of a shadertoy frame: spectrum.csv not written"
  # A program as a study's source: the study's --dt sets the time step, not the program's --fps.
  expect_bad "flow time step of a program source" "$out/stdt" "--dt: timeStep must be in [-1e+09, 1e+09], got 2e+09" -- "$bin" flow -o "$out/stdt" --size 32 --dt 2e9 shadertoy "$src/data/shadertoy/swirl" --size 64,48
  expect_bad "spectrum window outside the frame" "$out/stw" "--size: size of the window, 128x128 at (-64, -64) from the centre, exceeds the 96x80 frame" -- "$bin" spectrum -o "$out/stw" --size 128 shadertoy "$src/data/shadertoy/swirl" --size 96,80
  expect_ok "shadertoy with a pattern" "$out/stp.png" -- "$bin" shadertoy "$src/data/shadertoy/pattern-zoom" --size 64,36 --time 5 -o "$out/stp.png"
  # A program without an instance uniform has one instance: averaging it with itself is refused.
  expect_bad "spectrum over instances of a program without them" "$out/sti" "--instances: instances must be 1: swirl has no instance uniform" -- "$bin" spectrum -o "$out/sti" --size 64 --instances 4 shadertoy "$src/data/shadertoy/swirl" --size 96,80
  expect_ok "shadertoy analysis" "$out/sta/index.html" -- "$bin" shadertoy "$src/data/shadertoy/swirl" --size 96,64 --analyse spectrum,flow,coherence --frames 4 --first-frame 120 -o "$out/sta"
  for f in spectrum.png flow_arrows.png appearance.png flow.csv coherence.csv; do [ -s "$out/sta/$f" ] || fail "shadertoy analysis: $f not written"; done
  grep -q "Optical flow (DIS)" "$out/sta/index.html" || fail "shadertoy analysis: index.html lacks the flow section"
  # Statistics over instances: 8x8 cells of hashed grey per instance (the
  # instance uniform), blinking every other frame. The correlation with the
  # centre pixel (32, 24) is 1 on its cell (64 pixels) and ~0 elsewhere;
  # the blink is flicker no motion explains.
  mkdir -p "$work/cells"
  cat >"$work/cells/image.glsl" <<'GLSL'
float cell(vec2 c) { return fract(sin(dot(c + float(uSeed) * vec2(17.0, 31.0), vec2(12.9898, 78.233))) * 43758.5453); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = vec2(fragCoord.x, iResolution.y - fragCoord.y);  // rows down, as the studies count them
    float v = cell(floor(p / 8.0));
    if (iFrame % 2 == 1) v = 1.0 - v;
    fragColor = vec4(vec3(v), 1.0);
}
GLSL
  printf '{"name": "cells", "uniforms": {"uSeed": {"type": "int"}}, "instance": "uSeed", "passes": {"image": {"code": "image.glsl"}}}' >"$work/cells/shadertoy.json"
  expect_ok "shadertoy statistics and flicker" "$out/stc/index.html" -- "$bin" shadertoy "$work/cells" --size 64,48 --analyse statistics,flicker --frames 4 --instances 200 -o "$out/stc"
  for f in statistics.csv statistics_mean.png statistics_variance.png statistics_correlation.png flicker.csv flicker_pairs.csv flicker.png flicker_map.png; do
    [ -s "$out/stc/$f" ] || fail "shadertoy statistics and flicker: $f not written"
  done
  awk -F, 'NR == 2 { exit !($1 == 200 && $5 == 64) }' "$out/stc/statistics.csv" || fail "shadertoy statistics: want 200 instances and a 64-pixel cell: $(cat "$out/stc/statistics.csv")"
  awk -F, 'NR == 2 { exit !($4 > 0.2) }' "$out/stc/flicker.csv" || fail "shadertoy flicker: the blink reads no flicker: $(cat "$out/stc/flicker.csv")"
  expect_bad "statistics without an instance uniform" "$out/stn" "--instances: instances must be 1: counter has no instance uniform" -- "$bin" shadertoy "$work/st" --analyse statistics -o "$out/stn"
  expect_bad "instances without statistics" "$out/stn" "--instances: has no effect without statistics" -- "$bin" shadertoy "$work/cells" --analyse flicker --instances 8 -o "$out/stn"
  expect_bad "point outside" "$out/stn" "--point: point (99, 2) lies outside the 64x48 window" -- "$bin" shadertoy "$work/cells" --size 64,48 --analyse statistics --point 99,2 -o "$out/stn"
  expect_bad "shadertoy analysis unknown" "$out/stu" "--analyse: unknown study \"fft\"" -- "$bin" shadertoy "$work/st" --analyse fft -o "$out/stu"
  expect_bad "shadertoy first frame alone" "$out/stff.png" "--first-frame: has no effect without --analyse" -- "$bin" shadertoy "$work/st" --first-frame 3 -o "$out/stff.png"
  expect_bad "shadertoy no frames" "$out/stz" "--frames: must be in [1, 1000000], got 0" -- "$bin" shadertoy "$work/st" --frames 0 -o "$out/stz"
  expect_bad "shadertoy inspect outside" "$out/sti.png" "--inspect: pixel (99, 1) is outside the 32x16 frame" -- "$bin" shadertoy "$work/st" --size 32,16 --inspect image:99,1 -o "$out/sti.png"
  # Flags that set a parameter of another name (bindParameter): --size sets
  # width and height, --time startTime.
  expect_bad "shadertoy height 0" "$out/sth.png" "--size: height must be in [1, 8192], got 0" -- "$bin" shadertoy "$work/st" --size 32,0 -o "$out/sth.png"
  expect_bad "shadertoy negative time" "$out/stt.png" "--time: startTime must be in [0, 1e6] s, got -1" -- "$bin" shadertoy "$work/st" --time -1 -o "$out/stt.png"
  expect_bad "shadertoy key code" "$out/stk.png" "--keys: keys must be key codes 0–255 (JavaScript keyCode), got 300" -- "$bin" shadertoy "$work/st" --keys 65,300 -o "$out/stk.png"
  expect_bad "shadertoy analysis twice" "$out/sta2" "--analyse: analyses names flow twice" -- "$bin" shadertoy "$work/st" --analyse flow,flow -o "$out/sta2"
  expect_bad "shadertoy date" "$out/std.png" "--date: expected YYYY-MM-DD" -- "$bin" shadertoy "$work/st" --date yesterday -o "$out/std.png"
}

case_bad_stimuli_flags() {
  expect_bad "tile not dividing size" "$out/sb1" "--tiles: tiles must hold tile sizes that divide size = 32, got 5" -- "$bin" stimuli -o "$out/sb1" --size 32 --tiles 4,5
  expect_bad "tile 0" "$out/sb2" "--tiles: tiles must hold tile sizes that divide size = 32, got 0" -- "$bin" stimuli -o "$out/sb2" --size 32 --tiles 0
  expect_bad "correlation above 1" "$out/sb3" "--correlations: correlations must hold values in [0, 1], got 1.5" -- "$bin" stimuli -o "$out/sb3" --size 32 --correlations 0,1.5
  expect_bad "no repeats" "$out/sb4" "--repeats: repeats must be in [1, 1000], got 0" -- "$bin" stimuli -o "$out/sb4" --repeats 0
  expect_bad "zero duration" "$out/sb5" "--duration-ms: durationMs must be in [1, 60000], got 0" -- "$bin" stimuli -o "$out/sb5" --duration-ms 0
  expect_bad "mean 1" "$out/sb6" "--mean: mean must be in (0, 1), got 1" -- "$bin" stimuli -o "$out/sb6" --mean 1
  expect_bad "analyse missing" "$out/sb7" "$work/nothere.csv: cannot read the answers file" -- "$bin" stimuli --analyse "$work/nothere.csv" -o "$out/sb7"
  printf 'trial,w,correlation,answer\n1,8,0.5,yes\n2,8,0.5,perhaps\n' >"$work/bad.csv"
  expect_bad "analyse bad answer" "$out/sb8" "$work/bad.csv:3: answer must be yes or no, got \"perhaps\"" -- "$bin" stimuli --analyse "$work/bad.csv" -o "$out/sb8"
  printf 'trial,w,answer\n1,8,yes\n' >"$work/bad2.csv"
  expect_bad "analyse no correlation column" "$out/sb9" "$work/bad2.csv:1: no column \"correlation\"" -- "$bin" stimuli --analyse "$work/bad2.csv" -o "$out/sb9"
  expect_bad "analyse with a stimulus flag" "$out/sb10" "--tiles: has no effect with --analyse" -- "$bin" stimuli --analyse "$work/bad.csv" --tiles 8 -o "$out/sb10"
}

# --- paper reproduction (reduced) ---
case_reproduce() {
  expect_ok "reproduce table1" "$out/rep/table1.md" -- "$bin" reproduce table1 -o "$out/rep" --count 20 --footprints 2,16
  grep -q "^high,16,global," "$out/rep/table1.csv" || fail "table1.csv lacks the high/16/global row"
  expect_ok "reproduce figures7-9" "$out/rep/figure9.png" -- "$bin" reproduce figures7-9 -o "$out/rep" --size 64
  expect_ok "reproduce figure12" "$out/rep/figure12.csv" -- "$bin" reproduce figure12 -o "$out/rep" --size 64 --reference-samples 4
  grep -q "^deliot-heitz," "$out/rep/figure12.csv" || fail "reproduce figure12: the CSV lacks the Deliot-Heitz row"
  expect_ok "reproduce all" "$out/all/index.html" -- "$bin" reproduce all -o "$out/all" --count 10 --footprints 2,4 --size 32 --reference-samples 8
  grep -q "figure4/figure4.png" "$out/all/index.html" || fail "reproduce all: index.html lacks figure 4"
  grep -q "figure11/figure11.png" "$out/all/index.html" || fail "reproduce all: index.html lacks figure 11"
  grep -q "figure14/figure14_filtering.png" "$out/all/index.html" || fail "reproduce all: index.html lacks figure 14"
  for part in "Table 1" "Figure 4" "Figures 7–9" "Figure 10" "Figure 11" "Figure 12" "Figure 14"; do
    grep -q "^$part: [0-9]* s, wrote $out/all/" "$work/out.txt" || fail "reproduce all: no line for $part: $(cat "$work/out.txt")"
  done
  [ -s "$out/all/figure10/figure10_comparison.png" ] || fail "reproduce all: figure 10's comparison not written"
}

# Figures 10 and 11 (phasor noise), reduced: their files, their numbers, and
# bad parameters refused before any output.
case_reproduce_phasor() {
  expect_ok "reproduce figure10" "$out/f10/figure10_comparison.png" -- "$bin" reproduce figure10 -o "$out/f10" --size 64 --comparison-size 96
  [ -s "$out/f10/figure10.png" ] || fail "figure10: figure10.png not written"
  # The same files for any thread count.
  "$bin" reproduce figure10 -o "$out/f10j1" --size 64 --comparison-size 96 --threads 1 >/dev/null 2>&1 || fail "figure10 --threads 1"
  diff -r "$out/f10" "$out/f10j1" >/dev/null || fail "figure10: 1 thread and all threads wrote different files"
  # Both fields' spectral centroids near the requested 24 cycles per period.
  awk -F, 'NR > 1 && ($2 < 22 || $2 > 26) { bad = 1 } END { exit bad }' "$out/f10/figure10.csv" \
    || fail "figure10.csv: a centroid far from 24 cycles: $(cat "$out/f10/figure10.csv")"
  expect_ok "reproduce figure11" "$out/f11/figure11.png" -- "$bin" reproduce figure11 -o "$out/f11" --size 24 --reference-samples 16 --footprints 1,64
  [ -s "$out/f11/fp64_error_estimated.png" ] || fail "figure11: the error map per footprint not written"
  # The pattern fades to the profile's mean: at footprint 64, Ŝ within 0.02 of it, S̄ too.
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; r = col["mean_fade_reference"]; e = col["mean_fade_estimators"]; if (!r || !e) bad = 1 }
    NR == 3 && ($r > 0.02 || $e > 0.02) { bad = 1 } NR == 2 && $e < 0.3 { bad = 1 } END { exit bad }' "$out/f11/figure11.csv" \
    || fail "figure11.csv: no fade to the profile's mean: $(cat "$out/f11/figure11.csv")"
  expect_bad "figure10 zero frequency" "$out/pbad1" "--frequency: frequency must be in (0, 10000], got 0" -- "$bin" reproduce figure10 -o "$out/pbad1" --frequency 0
  expect_bad "figure10 negative bandwidth" "$out/pbad2" "--bandwidth: bandwidth must be in (0, 10000], got -1" -- "$bin" reproduce figure10 -o "$out/pbad2" --bandwidth -1
  expect_bad "figure11 estimators only" "$out/pbad3" "--filter: filter must be paper or smooth, got \"reference\"" -- "$bin" reproduce figure11 -o "$out/pbad3" --filter reference
  expect_bad "figure11 zero tolerance" "$out/pbad5" "--reference-tolerance: referenceTolerance must be in (0, 0.1], got 0" -- "$bin" reproduce figure11 -o "$out/pbad5" --reference-tolerance 0
  expect_bad "figure14 huge tolerance" "$out/pbad6" "--reference-tolerance: referenceTolerance must be in (0, 0.1], got 0.5" -- "$bin" reproduce figure14 -o "$out/pbad6" --reference-tolerance 0.5
  expect_bad "figure11 zero footprint" "$out/pbad4" "figure11: footprints must be in [1, 65536], got 0" -- "$bin" reproduce figure11 -o "$out/pbad4" --footprints 0
  # A profile image must be one row (W×1).
  "$bin" noise '{"type":"spectrum","size":16,"components":[{"shape":"lowpass","cutoff":4}]}' -o "$out/square.png" >/dev/null || fail "noise for the profile"
  cat >"$work/profile.json" <<JSON
{"noise_x": {"type": "spectrum", "size": 32, "components": [{"shape": "bilobe", "frequency": 4, "bandwidth": 1}]},
 "noise_y": "quadrature", "colormap": {"type": "phasor", "profile": "image", "path": "out/square.png"}, "size": 16}
JSON
  expect_bad "profile image not 1D" "$out/pbad5.png" "square.png: a phasor profile image must be one row over one period (W×1, W in [2, 4096]), got 16x16" -- "$bin" render --pattern "$work/profile.json" -o "$out/pbad5.png"
}

# --- GPU (headless OpenGL: Mesa llvmpipe without a GPU) ---
case_gpu_render() {
  expect_ok "render --gpu" "$out/gpu.png" -- "$bin" render --preset camouflage --gpu --size 96 -o "$out/gpu.png"
  expect_ok "render --gpu --filter smooth" "$out/gpu2.png" -- "$bin" render --preset marble --gpu --filter smooth --scale 8 --size 96 -o "$out/gpu2.png"
  expect_ok "render --gpu plane" "$out/gpu3.png" -- "$bin" render --preset marble --gpu --filter paper --view plane --tilt 70 --aniso 8 --size 96 -o "$out/gpu3.png"
  expect_ok "render --gpu compute" "$out/gpu4.png" -- "$bin" render --preset marble --gpu --pipeline compute --filter smooth --view plane --tilt 70 --aniso 8 --size 96,72 -o "$out/gpu4.png"
  expect_ok "render --gpu rasterizer derivatives" "$out/gpu5.png" -- "$bin" render --preset marble --gpu --derivatives rasterizer --filter smooth --view plane --size 96 -o "$out/gpu5.png"
}

case_view() {
  # The window, under a virtual X server. Mesa's GLX driver leaks a few
  # hundred bytes from a module it has unloaded by exit time, which
  # LeakSanitizer cannot suppress by name: leak checks are off for this run
  # only (sanitizer builds; no effect otherwise).
  start_xvfb
  expect_ok "view under Xvfb" "$out/view.png" -- env ASAN_OPTIONS=detect_leaks=0 DISPLAY="$display" "$bin" view --preset weld --frames 3 --size 160,120 --screenshot "$out/view.png"
  # The window shows what `render` writes for the same view, the right way
  # up: its screenshot (read back from the window's framebuffer) is within
  # 8-bit rounding of the CPU render (0.5/255 mean: the GPU/CPU parity bound),
  # and far from the render turned upside down (≥ 10/255 on these patterns;
  # ~30-60/255 measured).
  [ -n "$compare" ] || { fail "view: no image comparer given"; return; }
  # figure14: a texture graph, drawn by its generated program.
  local p v f
  for p in camouflage figure14; do
  for v in zoom plane; do
    for f in none smooth; do
      local flags=(--preset "$p" --view "$v" --filter "$f" --scale 1.5 --size 96,64)
      # Only where they act (render refuses them elsewhere).
      [ "$v" = plane ] && flags+=(--tilt 60)
      [ "$f" = smooth ] && flags+=(--aniso 4)
      expect_ok "view $p $v $f" "$out/view_${p}_${v}_$f.png" -- env ASAN_OPTIONS=detect_leaks=0 DISPLAY="$display" "$bin" view "${flags[@]}" --frames 2 --screenshot "$out/view_${p}_${v}_$f.png"
      expect_ok "render $p $v $f" "$out/render_${p}_${v}_$f.png" -- "$bin" render "${flags[@]}" -o "$out/render_${p}_${v}_$f.png"
      local d
      d=$("$compare" "$out/view_${p}_${v}_$f.png" "$out/render_${p}_${v}_$f.png") || { fail "view $p $v $f: compare failed"; continue; }
      echo "$d" | awk '{ exit !($2 <= 0.5 && $4 >= 10) }' || fail "view $p $v $f vs render: $d (want mean <= 0.5, flipped >= 10)"
    done
  done
  done
}

case_workbench() {
  [ -n "$compare" ] || { fail "workbench: no image comparer given"; return; }
  start_xvfb
  local xvfb=(env ASAN_OPTIONS=detect_leaks=0 DISPLAY="$display")
  # A person's session, scripted: zoom about a pixel, switch the filter, edit
  # a colormap colour, save the pattern. The picture then equals `render` of
  # the saved file over the same view: the zoom by 2 about (40, 30) from
  # scale 1.5 leaves scale 0.75 and offset (40, 30) x 0.75.
  cat >"$work/steps.json" <<'JSON'
[{"frame": 1, "zoom": 2, "at": [40, 30]},
 {"frame": 2, "filter": "paper"},
 {"frame": 3, "set": "/colormap/shapes/0/colour", "value": "#d02020"},
 {"frame": 4, "save": "WORK/edited.json"}]
JSON
  sed -i "s|WORK|$work|" "$work/steps.json"
  expect_ok "workbench session" "$out/wb.png" -- "${xvfb[@]}" "$bin" view --preset camouflage --size 96,64 --scale 1.5 --frames 6 --script "$work/steps.json" --screenshot "$out/wb.png"
  [ -s "$work/edited.json" ] || { fail "workbench: the edited pattern was not saved"; return; }
  grep -q '"#d02020"' "$work/edited.json" || fail "workbench: the saved pattern lacks the edited colour"
  local view=(--filter paper --scale 0.75 --offset 30,22.5 --size 96,64)
  expect_ok "render of the saved pattern" "$out/wbr.png" -- "$bin" render "$work/edited.json" "${view[@]}" -o "$out/wbr.png"
  expect_ok "render of the preset" "$out/wbp.png" -- "$bin" render --preset camouflage "${view[@]}" -o "$out/wbp.png"
  local d
  d=$("$compare" "$out/wb.png" "$out/wbr.png") || { fail "workbench: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5 && $4 >= 10) }' || fail "workbench picture vs render of the saved pattern: $d (want mean <= 0.5, flipped >= 10)"
  # The edit shows: the preset's own colours are far from the picture.
  d=$("$compare" "$out/wb.png" "$out/wbp.png") || { fail "workbench: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 >= 5) }' || fail "workbench: the colour edit does not show: $d vs the preset"

  # Keys tapped within one frame are applied (a tap shorter than a frame was
  # lost before): "1" switches to no filtering, which at scale 8 aliases far
  # from the default smooth filter.
  printf '[{"frame": 1, "key": "1"}]' >"$work/keys.json"
  expect_ok "workbench key tap" "$out/wbk.png" -- "${xvfb[@]}" "$bin" view --preset camouflage --size 96,64 --scale 8 --frames 3 --script "$work/keys.json" --screenshot "$out/wbk.png"
  expect_ok "render unfiltered" "$out/wbkn.png" -- "$bin" render --preset camouflage --size 96,64 --scale 8 --filter none -o "$out/wbkn.png"
  expect_ok "render smooth" "$out/wbks.png" -- "$bin" render --preset camouflage --size 96,64 --scale 8 --filter smooth -o "$out/wbks.png"
  d=$("$compare" "$out/wbk.png" "$out/wbkn.png") || { fail "workbench key: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5) }' || fail "workbench after tapping 1 vs render --filter none: $d (want mean <= 0.5)"
  d=$("$compare" "$out/wbk.png" "$out/wbks.png") || { fail "workbench key: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 >= 5) }' || fail "workbench after tapping 1 is still the smooth filter's: $d"
  printf '[{"frame": 1, "key": "ctrl+alt+q"}]' >"$work/badkey.json"
  expect_bad "workbench unknown key" "$out/wbkb.png" "unknown key \"ctrl+alt+q\"" -- "$bin" view --preset camouflage --frames 3 --script "$work/badkey.json" --screenshot "$out/wbkb.png"

  # Undo and redo: a second colour, both edits undone, the first redone: the
  # picture and the saved file are the first edit's again.
  cat >"$work/undo.json" <<'JSON'
[{"frame": 1, "zoom": 2, "at": [40, 30]},
 {"frame": 2, "filter": "paper"},
 {"frame": 3, "set": "/colormap/shapes/0/colour", "value": "#d02020"},
 {"frame": 4, "set": "/colormap/shapes/0/colour", "value": "#2020d0"},
 {"frame": 5, "undo": true}, {"undo": true}, {"frame": 6, "redo": true},
 {"frame": 7, "save": "WORK/undone.json"}]
JSON
  sed -i "s|WORK|$work|" "$work/undo.json"
  expect_ok "workbench undo and redo" "$out/wbu.png" -- "${xvfb[@]}" "$bin" view --preset camouflage --size 96,64 --scale 1.5 --frames 9 --script "$work/undo.json" --screenshot "$out/wbu.png"
  grep -q '"#d02020"' "$work/undone.json" || fail "workbench undo: the saved pattern is not the first edit's"
  d=$("$compare" "$out/wbu.png" "$out/wbr.png") || { fail "workbench undo: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5) }' || fail "workbench after undo and redo vs render of the first edit: $d (want mean <= 0.5)"
  printf '[{"frame": 1, "undo": true}]' >"$work/undo0.json"
  expect_bad "workbench undo with nothing to undo" "$out/wbu0.png" "script: nothing to undo" -- "${xvfb[@]}" "$bin" view --preset camouflage --frames 3 --script "$work/undo0.json" --screenshot "$out/wbu0.png"

  # A ShaderToy program with the spectrum view: paused after iFrame 120, the
  # picture is the spectrum study's figure of that frame, as `spectrum` writes
  # it. (A power spectrum is point-symmetric, so turning it over only mirrors
  # it: the frame below checks the orientation.)
  printf '[{"frame": 121, "pause": true}]' >"$work/pause.json"
  expect_ok "workbench spectrum of a program" "$out/wbs.png" -- "${xvfb[@]}" "$bin" view --shadertoy "$src/data/shadertoy/swirl" --size 96,80 --mode analysis --analysis spectrum --frames 123 --script "$work/pause.json" --screenshot "$out/wbs.png"
  expect_ok "spectrum study of the same frame" "$out/wbss/spectrum.png" -- "$bin" spectrum -o "$out/wbss" --size 96,80 shadertoy "$src/data/shadertoy/swirl" --size 96,80 --first-frame 120
  d=$("$compare" "$out/wbs.png" "$out/wbss/spectrum.png") || { fail "workbench spectrum: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5) }' || fail "workbench spectrum vs the study's: $d (want mean <= 0.5)"
  # The frame itself, in texture mode, is the program's frame as `shadertoy` writes it.
  expect_ok "workbench program frame" "$out/wbt.png" -- "${xvfb[@]}" "$bin" view --shadertoy "$src/data/shadertoy/swirl" --size 96,80 --frames 123 --script "$work/pause.json" --screenshot "$out/wbt.png"
  expect_ok "shadertoy frame 120" "$out/wbt_ref.png" -- "$bin" shadertoy "$src/data/shadertoy/swirl" --size 96,80 --frames 121 -o "$out/wbt_ref.png"
  d=$("$compare" "$out/wbt.png" "$out/wbt_ref.png") || { fail "workbench frame: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5 && $4 >= 10) }' || fail "workbench frame vs shadertoy: $d (want mean <= 0.5, flipped >= 10)"
  # A program's frames are display codes: the spectrum study shows its frame as they are.
  d=$("$compare" "$out/wbss/frame.png" "$out/wbt_ref.png") || { fail "spectrum frame: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5) }' || fail "spectrum's frame.png of a program vs its frame: $d (want mean <= 0.5)"

  # Side by side halves the program's picture: the program runs on at the new
  # size instead of starting again (its grey is iFrame; a restart at frame 10
  # and again at 20 would show iFrame 10, not 30).
  mkdir -p "$work/iframe"
  printf 'void mainImage(out vec4 c, in vec2 p) { c = vec4(vec3(float(iFrame) / 255.0), 1.0); }\n' >"$work/iframe/image.glsl"
  printf '[{"frame": 10, "mode": "side-by-side"}, {"frame": 20, "mode": "texture"}, {"frame": 31, "pause": true}]' >"$work/resize.json"
  expect_ok "workbench program through a resize" "$out/wbrs.png" -- "${xvfb[@]}" "$bin" view --shadertoy "$work/iframe" --size 96,80 --frames 33 --script "$work/resize.json" --screenshot "$out/wbrs.png"
  expect_ok "shadertoy iFrame 30" "$out/wbrs_ref.png" -- "$bin" shadertoy "$work/iframe" --size 96,80 --frames 31 -o "$out/wbrs_ref.png"
  d=$("$compare" "$out/wbrs.png" "$out/wbrs_ref.png") || { fail "workbench resize: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5) }' || fail "workbench program restarted on a resize: $d (want mean <= 0.5)"

  # Mouse steps of a script are the program's iMouse with ShaderToy's click
  # semantics, as --event gives them: the picture shows the counts of
  # clicked and held frames, and matches the shadertoy command's frame.
  mkdir -p "$work/wbclicks"
  printf 'void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(0), 0) + vec4(iMouse.w > 0.0 ? 1.0 : 0.0, iMouse.z > 0.0 ? 1.0 : 0.0, 0.0, 0.0); }\n' >"$work/wbclicks/a.glsl"
  printf 'void mainImage(out vec4 c, in vec2 p) { c = vec4(texelFetch(iChannel0, ivec2(0), 0).xy / vec2(4.0, 16.0), 0.5, 1.0); }\n' >"$work/wbclicks/image.glsl"
  printf '{"passes": {"buffer_a": {"code": "a.glsl", "channels": [{"type": "buffer", "buffer": "a"}]}, "image": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "a"}]}}}' >"$work/wbclicks/shadertoy.json"
  printf '[{"frame": 2, "mousedown": [3, 4]}, {"frame": 4, "mousemove": [5, 6]}, {"frame": 6, "mouseup": true}, {"frame": 8, "mousedown": [1, 2]}, {"frame": 11, "pause": true}]' >"$work/clicks_script.json"
  expect_ok "workbench program clicked by a script" "$out/wbcl.png" -- "${xvfb[@]}" "$bin" view --shadertoy "$work/wbclicks" --size 96,80 --frames 13 --script "$work/clicks_script.json" --screenshot "$out/wbcl.png"
  expect_ok "shadertoy clicked by events" "$out/wbcl_ref.png" -- "$bin" shadertoy "$work/wbclicks" --size 96,80 --frames 11 --event 2:mousedown:3,4 --event 4:mousemove:5,6 --event 6:mouseup --event 8:mousedown:1,2 -o "$out/wbcl_ref.png"
  d=$("$compare" "$out/wbcl.png" "$out/wbcl_ref.png") || { fail "workbench clicks: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5) }' || fail "workbench clicks vs shadertoy events: $d (want mean <= 0.5)"
  # The counts themselves: clicks on frames 2 and 8, the button held on 2–5 and 8–10.
  "$bin" shadertoy "$work/wbclicks" --size 8,8 --frames 11 --event 2:mousedown:3,4 --event 6:mouseup --event 8:mousedown:1,2 --inspect buffer_a:0,0 >"$work/wbclicks.txt" 2>&1 || fail "clicks inspect: $(cat "$work/wbclicks.txt")"
  grep -q "^buffer_a (0, 0) at iFrame 10: 2 7 0 0$" "$work/wbclicks.txt" || fail "clicks inspect: $(cat "$work/wbclicks.txt")"

  # A pattern's spectrum view is the spectrum study of the frame `render --gpu`
  # writes (an oblique pattern, so a frame analysed upside down would show
  # its spectrum mirrored); the sphere is the one `scene` draws.
  expect_ok "workbench spectrum of a pattern" "$out/wbps.png" -- "${xvfb[@]}" "$bin" view --preset oblique-blots --size 128,96 --mode analysis --frames 3 --screenshot "$out/wbps.png"
  expect_ok "render for the spectrum" "$out/wbps.exr" -- "$bin" render --preset oblique-blots --gpu --filter smooth --size 128,96 -o "$out/wbps.exr"
  expect_ok "spectrum of the render" "$out/wbpss/spectrum.png" -- "$bin" spectrum -o "$out/wbpss" images "$out/wbps.exr"
  d=$("$compare" "$out/wbps.png" "$out/wbpss/spectrum.png") || { fail "workbench pattern spectrum: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5 && $4 >= 10) }' || fail "workbench pattern spectrum vs the study's: $d (want mean <= 0.5, flipped >= 10)"
  expect_ok "workbench sphere" "$out/wbsph.png" -- "${xvfb[@]}" "$bin" view --preset marble --view sphere --size 160,120 --frames 3 --screenshot "$out/wbsph.png"
  expect_ok "scene sphere" "$out/wbsphr.png" -- "$bin" scene --preset marble --object sphere --size 160,120 --filter smooth -o "$out/wbsphr.png"
  d=$("$compare" "$out/wbsph.png" "$out/wbsphr.png") || { fail "workbench sphere: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5 && $4 >= 10) }' || fail "workbench sphere vs scene: $d (want mean <= 0.5, flipped >= 10)"
  # The user's mesh (a tetrahedron without uv: triplanar) is the one `scene --mesh` draws.
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' >"$work/wbtetra.obj"
  expect_ok "workbench mesh" "$out/wbmesh.png" -- "${xvfb[@]}" "$bin" view --preset marble --mesh "$work/wbtetra.obj" --size 160,120 --frames 3 --screenshot "$out/wbmesh.png"
  expect_ok "scene mesh for the workbench" "$out/wbmeshr.png" -- "$bin" scene --preset marble --mesh "$work/wbtetra.obj" --size 160,120 --filter smooth -o "$out/wbmeshr.png"
  d=$("$compare" "$out/wbmesh.png" "$out/wbmeshr.png") || { fail "workbench mesh: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5 && $4 >= 2) }' || fail "workbench mesh vs scene: $d (want mean <= 0.5, flipped >= 2)"

  # A texture graph: a node parameter edited (the panel's widgets come from
  # the node table; the script edits through the same call), recorded to an
  # MP4 meanwhile, and the saved graph renders as the window showed it.
  cat >"$work/graph_steps.json" <<JSON
[{"frame": 1, "record": "$out/wbg.mp4"},
 {"frame": 2, "set": "/nodes/du/angle", "value": 45},
 {"frame": 4, "stop_recording": true}, {"save": "$work/graph.json"}]
JSON
  expect_ok "workbench graph edit" "$out/wbg.png" -- "${xvfb[@]}" "$bin" view "$src/data/graphs/derivative-ridges.json" --size 96,64 --filter smooth --frames 5 --script "$work/graph_steps.json" --screenshot "$out/wbg.png"
  [ -s "$out/wbg.mp4" ] || fail "workbench: the recording was not written"
  grep -q '"angle": 45' "$work/graph.json" || fail "workbench: the saved graph lacks the edited angle"
  expect_ok "render of the saved graph" "$out/wbgr.png" -- "$bin" render "$work/graph.json" --filter smooth --size 96,64 -o "$out/wbgr.png"
  expect_ok "render of the graph as shipped" "$out/wbg0.png" -- "$bin" render "$src/data/graphs/derivative-ridges.json" --filter smooth --size 96,64 -o "$out/wbg0.png"
  d=$("$compare" "$out/wbg.png" "$out/wbgr.png") || { fail "workbench graph: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 <= 0.5 && $4 >= 10) }' || fail "workbench graph vs render of the saved graph: $d (want mean <= 0.5, flipped >= 10)"
  d=$("$compare" "$out/wbg.png" "$out/wbg0.png") || { fail "workbench graph: compare failed"; return; }
  echo "$d" | awk '{ exit !($2 >= 5) }' || fail "workbench graph: the angle edit does not show: $d"

  # Bad input: one message, exit 2, no window output.
  printf '[{"frame": 1, "zoom": 2}]' >"$work/bad.json"
  expect_bad "workbench script without at" "$out/wbb.png" "/0: zoom needs \"at\"" -- "$bin" view --preset camouflage --script "$work/bad.json" --screenshot "$out/wbb.png"
  expect_bad "workbench negative frames" "$out/wbf.png" "--frames: frames must be in [0, 1000000], got -1" -- "$bin" view --preset camouflage --frames -1 --screenshot "$out/wbf.png"
  expect_bad "workbench inline JSON" "$out/wbb.png" "pattern: the window edits and saves a file" -- "$bin" view '{"noise_x": {}}' --frames 1 --screenshot "$out/wbb.png"
  printf '[{"frame": 1, "set": "/colormap/shapes/0/colour", "value": "red"}]' >"$work/bad2.json"
  expect_bad "workbench edit the pattern refuses" "$out/wbb.png" "/colormap/shapes/0/colour: invalid colour \"red\"" -- "${xvfb[@]}" "$bin" view --preset camouflage --size 64,48 --frames 3 --script "$work/bad2.json" --screenshot "$out/wbb.png"
  mkdir -p "$work/broken"
  printf 'void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(nope);\n}\n' >"$work/broken/image.glsl"
  expect_bad "workbench program that does not compile" "$out/wbb.png" "image.glsl:2" -- "${xvfb[@]}" "$bin" view --shadertoy "$work/broken" --frames 2 --screenshot "$out/wbb.png"
  expect_bad "workbench program and pattern" "" "give a program or a pattern, not both" -- "$bin" view --preset camouflage --shadertoy "$src/data/shadertoy/swirl"
  expect_bad "workbench screenshot without frames" "$out/wbb.png" "--frames: frames must be given with a screenshot" -- "$bin" view --preset camouflage --screenshot "$out/wbb.png"
  printf '[{"frame": 1, "set": "/seed", "value": 3}]' >"$work/bad3.json"
  expect_bad "workbench edit of a program" "$out/wbb.png" "a ShaderToy program is edited in its files" -- "${xvfb[@]}" "$bin" view --shadertoy "$src/data/shadertoy/swirl" --size 64,48 --frames 3 --script "$work/bad3.json" --screenshot "$out/wbb.png"
}

case_bake() {
  expect_ok "bake" "$out/bake/stochtex.glsl" -- "$bin" bake --preset weld --filter paper -o "$out/bake"
  # A normal map: its lean program, with the slopes' covariance pyramid, the
  # shading in the manifest and in the program, no table, the scene's light documented.
  expect_ok "bake lean" "$out/bakelean/stochtex.glsl" -- "$bin" bake --preset lean-ridges --response lean -o "$out/bakelean"
  [ -s "$out/bakelean/covariance_0_0.exr" ] || fail "bake lean: no covariance pyramid"
  ls "$out/bakelean"/table* >/dev/null 2>&1 && fail "bake lean: a table was written"
  grep -q '"response": "lean"' "$out/bakelean/manifest.json" || fail "bake lean: manifest lacks the response"
  grep -q '"roughness": 0.08' "$out/bakelean/manifest.json" || fail "bake lean: manifest lacks the shading"
  # The program's lean op holds the file's shading (roughness, specular, light) as numbers, within 1e-6.
  grep -o 'opFiltered(LeanParams([^)]*)' "$out/bakelean/stochtex.glsl" | head -1 | sed 's/.*LeanParams(//' |
    awk -F', *' '{ n = split("0.08 0.05 0 -0.8 0.6", w, " "); if (NF < n) exit 1;
                   for (i = 1; i <= n; i++) if (($i - w[i]) ^ 2 > 1e-12) exit 1; found = 1 } END { exit !found }' ||
    fail "bake lean: no lean op with the file's shading"
  grep -q "gLightDirection" "$out/bakelean/README.md" || fail "bake lean: README lacks how to light it"
  # The paper's 8-bit layout: one RGBA8 PNG per leaf pair and level, the table as sRGB codes, the codes in the manifest.
  expect_ok "bake 8bit" "$out/bake8/stats_0_0.png" -- "$bin" bake --preset weld --filter paper --format 8bit -o "$out/bake8"
  [ -s "$out/bake8/table_0.png" ] || fail "bake 8bit: no PNG table"
  ls "$out/bake8"/*.exr >/dev/null 2>&1 && fail "bake 8bit: an EXR was written"
  grep -q '"format": "8bit"' "$out/bake8/manifest.json" || fail "bake 8bit: manifest lacks the format"
  grep -q '"format": "SRGB8"' "$out/bake8/manifest.json" || fail "bake 8bit: manifest lacks the table's GL format"
  grep -q "StatsCoding(offset0\[level\]" "$out/bake8/stochtex.glsl" || fail "bake 8bit: the include lacks the codes"
  expect_bad "bake --table-precision with --format half" "$out/bakeh" "--table-precision: applies to --format float only" -- "$bin" bake --preset weld --format half --table-precision float -o "$out/bakeh"
}

case_bake_image() {
  # Bands streamed into the PNG give the same file as one render of the whole.
  expect_ok "bake-image" "$out/big.png" -- "$bin" bake-image --preset marble --size 200,150 --band 40 --filter smooth --scale 3 -o "$out/big.png"
  expect_ok "render for bake-image" "$out/big_ref.png" -- "$bin" render --preset marble --size 200,150 --filter smooth --scale 3 -o "$out/big_ref.png"
  cmp -s "$out/big.png" "$out/big_ref.png" || fail "bake-image differs from render"
  # A bake holds one band: taller than a render may be (65536 rows), refused only beyond.
  expect_ok "bake-image taller than a render" "$out/tall.png" -- "$bin" bake-image --preset gaussian --size 8,20000 --band 4096 -o "$out/tall.png"
  expect_bad "render as tall" "$out/tall_r.png" "--size: size must be in [1, 16384] per side, got 8x20000" -- "$bin" render --preset gaussian --size 8,20000 -o "$out/tall_r.png"
  expect_bad "bake-image too tall" "$out/tall2.png" "--size: size must be in [1, 65536] per side, got 8x70000" -- "$bin" bake-image --preset gaussian --size 8,70000 -o "$out/tall2.png"
  expect_ok "bake-image --gpu" "$out/bigg.png" -- "$bin" bake-image --preset marble --size 120,90 --band 32 --filter paper --gpu -o "$out/bigg.png"
  expect_ok "bake-image lean" "$out/biglean.png" -- "$bin" bake-image --preset lean-ridges --response lean --size 96,64 --band 24 --filter smooth -o "$out/biglean.png"
  expect_ok "render lean for bake-image" "$out/biglean_ref.png" -- "$bin" render --preset lean-ridges --response lean --size 96,64 --filter smooth -o "$out/biglean_ref.png"
  cmp -s "$out/biglean.png" "$out/biglean_ref.png" || fail "bake-image lean differs from render"
  expect_ok "bake-image --gpu compute" "$out/biggc.png" -- "$bin" bake-image --preset marble --size 120,90 --band 32 --filter paper --gpu --pipeline compute -o "$out/biggc.png"
  # --tileable: whole periods (1.8 asked, 2 made), its report; the GPU's bands alike
  expect_ok "bake-image --tileable" "$out/tile.png" -- "$bin" bake-image --preset camouflage --size 96 --scale 4.8 --band 40 --tileable -o "$out/tile.png"
  grep -q "tileable: 2 x 2 example periods of 256 texels, grid x1.0104 along u" "$work/out.txt" || fail "bake-image --tileable: report: $(cat "$work/out.txt")"
  expect_ok "bake-image --tileable --gpu" "$out/tileg.png" -- "$bin" bake-image --preset camouflage --size 96 --scale 4.8 --tileable --gpu -o "$out/tileg.png"
  # --pbr: the four maps, tileable; refused without a normal map or beside --response
  expect_ok "bake-image --pbr" "$out/mat_normal.png" -- "$bin" bake-image --preset lean-ridges --size 64 --scale 8 --tileable --pbr -o "$out/mat.png"
  for m in albedo normal roughness height; do [ -s "$out/mat_$m.png" ] || fail "bake-image --pbr: mat_$m.png not written"; done
  grep -q "wrote $out/mat_albedo.png, $out/mat_normal.png, $out/mat_roughness.png, $out/mat_height.png" "$work/out.txt" || fail "bake-image --pbr: report: $(cat "$work/out.txt")"
  expect_bad "bake-image --pbr without a normal map" "$out/mat2_albedo.png" "--pbr: needs a pattern with a normal_map (camouflage has none)" -- "$bin" bake-image --preset camouflage --size 32 --pbr -o "$out/mat2.png"
  expect_bad "bake-image --pbr --response" "$out/mat3_albedo.png" "--pbr: writes every response of the PBR set itself; drop --response" -- "$bin" bake-image --preset lean-ridges --size 32 --pbr --response lean -o "$out/mat3.png"
  expect_bad "bake-image --tileable, no whole periods" "$out/tile2.png" "--size: size must cover a whole number of example periods along both axes to tile: 256 × 100 pixels" -- "$bin" bake-image --preset camouflage --size 256,100 --tileable -o "$out/tile2.png"
}

# Output formats by extension (PNG, EXR, JPEG, TIFF), bake-image to EXR, and
# a pattern given inline like noise and colormap specs.
case_output_formats() {
  local r=(render --preset marble --size 64 --filter smooth)
  expect_ok "render png" "$out/f.png" -- "$bin" "${r[@]}" -o "$out/f.png"
  expect_ok "render jpg" "$out/f.jpg" -- "$bin" "${r[@]}" -o "$out/f.jpg"
  expect_ok "render jpeg" "$out/f.JPEG" -- "$bin" "${r[@]}" -o "$out/f.JPEG"
  expect_ok "render tif" "$out/f.tif" -- "$bin" "${r[@]}" -o "$out/f.tif"
  expect_ok "render tiff 16" "$out/f16.tiff" -- "$bin" "${r[@]}" -o "$out/f16.tiff" --bits 16
  # JPEG at quality 95 against the PNG: mean error under 3 8-bit steps (measured 1.87 on this busy pattern).
  local d
  d=$("$compare" "$out/f.png" "$out/f.jpg") || fail "compare jpg"
  awk -v d="${d#mean }" 'BEGIN { split(d, a, " "); exit !(a[1] < 3.0) }' || fail "jpg far from png: $d"
  # TIFF: little-endian TIFF magic; 16 bits hold twice the samples of 8 (LZW may shrink either).
  [ "$(head -c 4 "$out/f.tif" | od -An -tx1 | tr -d ' ')" = 49492a00 ] || fail "f.tif is not a TIFF"
  [ "$(head -c 4 "$out/f16.tiff" | od -An -tx1 | tr -d ' ')" = 49492a00 ] || fail "f16.tiff is not a TIFF"
  [ "$(stat -c %s "$out/f16.tiff")" -gt "$(stat -c %s "$out/f.tif")" ] || fail "16-bit TIFF not larger than 8-bit"
  expect_bad "unknown extension" "$out/f.bmp" "$out/f.bmp: unsupported output format '.bmp' (use .png, .exr, .jpg/.jpeg or .tif/.tiff)" -- "$bin" "${r[@]}" -o "$out/f.bmp"
  expect_bad "no extension" "$out/f" "$out/f: unsupported output format ''" -- "$bin" "${r[@]}" -o "$out/f"
  expect_bad "16-bit jpg" "$out/g.jpg" "$out/g.jpg: JPEG holds 8 bits per channel, got 16" -- "$bin" "${r[@]}" -o "$out/g.jpg" --bits 16
  # bake-image to EXR: linear float, the same values as one render to EXR.
  expect_ok "bake-image exr" "$out/b.exr" -- "$bin" bake-image --preset marble --size 96,70 --band 16 --filter smooth --scale 3 -o "$out/b.exr"
  expect_ok "render exr" "$out/r.exr" -- "$bin" render --preset marble --size 96,70 --filter smooth --scale 3 -o "$out/r.exr"
  d=$("$compare" "$out/b.exr" "$out/r.exr") || fail "compare exr"
  [ "${d%% flipped*}" = "mean 0.0000" ] || fail "bake-image exr differs from render: $d"
  expect_bad "bake-image jpg" "$out/b.jpg" "$out/b.jpg: unsupported output format '.jpg' for an image written in bands (use .png or .exr)" -- "$bin" bake-image --preset marble --size 64 -o "$out/b.jpg"
  # Inline JSON: the same image as the file.
  "$bin" presets --dump woven >"$work/woven.json" || fail "presets --dump"
  expect_ok "render file" "$out/w_file.png" -- "$bin" render "$work/woven.json" --size 48 -o "$out/w_file.png"
  expect_ok "render inline" "$out/w_inline.png" -- "$bin" render "$(cat "$work/woven.json")" --size 48 -o "$out/w_inline.png"
  cmp -s "$out/w_file.png" "$out/w_inline.png" || fail "inline pattern differs from its file"
  expect_ok "render --pattern inline" "$out/w_opt.png" -- "$bin" render --pattern "$(cat "$work/woven.json")" --size 48 -o "$out/w_opt.png"
  cmp -s "$out/w_file.png" "$out/w_opt.png" || fail "--pattern inline differs from its file"
  expect_bad "inline malformed" "$out/w_bad.png" "<inline JSON>: malformed JSON" -- "$bin" render '{"noise_x": ' -o "$out/w_bad.png"
}

case_scene() {
  expect_ok "scene torus" "$out/scene.png" -- "$bin" scene --preset marble --object torus --size 96,64 -o "$out/scene.png"
  # Unfiltered too: its draw used to be refused by GL and the empty frame reported as written.
  expect_ok "scene torus unfiltered" "$out/scene_none.png" -- "$bin" scene --preset marble --object torus --size 96,64 --filter none -o "$out/scene_none.png"
  expect_ok "scene lean" "$out/scene_lean.png" -- "$bin" scene --preset lean-ridges --response lean --object sphere --size 96,64 -o "$out/scene_lean.png"
  expect_ok "scene lean unfiltered" "$out/scene_lean_none.png" -- "$bin" scene --preset lean-ridges --response lean --filter none --object sphere --size 96,64 -o "$out/scene_lean_none.png"
  cmp -s "$out/scene_lean.png" "$out/scene_lean_none.png" && fail "scene lean: filtered and unfiltered are identical"
  # A user's mesh: a tetrahedron without uv (triplanar by default), refused as uv; missing and unknown files refused.
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' >"$work/tetra.obj"
  expect_ok "scene mesh" "$out/scene_mesh.png" -- "$bin" scene --preset marble --mesh "$work/tetra.obj" --size 96,64 -o "$out/scene_mesh.png"
  grep -q "triplanar mapping" "$work/out.txt" || fail "scene mesh: the default mapping of a mesh without uv is not triplanar: $(cat "$work/out.txt")"
  expect_bad "scene mesh as uv" "$out/scene_uv.png" "--mapping: mapping must be triplanar for a mesh without texture coordinates ($work/tetra.obj)" -- "$bin" scene --preset marble --mesh "$work/tetra.obj" --mapping uv -o "$out/scene_uv.png"
  expect_bad "scene missing mesh" "$out/scene_nm.png" "$work/nope.obj: no such mesh file" -- "$bin" scene --preset marble --mesh "$work/nope.obj" -o "$out/scene_nm.png"
  expect_bad "scene mesh and object" "$out/scene_mo.png" "--object excludes --mesh" -- "$bin" scene --preset marble --mesh "$work/tetra.obj" --object torus -o "$out/scene_mo.png"
}

# --- bad input ---
case_bad_input() {
  make_exemplar
  echo '{"noise_x": {"type": "spectrum", ' >"$work/malformed.json"
  expect_bad "malformed JSON" "$out/bad1.png" "malformed.json: malformed JSON" -- "$bin" render "$work/malformed.json" -o "$out/bad1.png"
  expect_bad "unknown preset" "$out/bad2.png" 'unknown preset "nope"' -- "$bin" render --preset nope -o "$out/bad2.png"
  expect_bad "missing pattern file" "$out/bad3.png" "missing.json: no such file" -- "$bin" render "$work/missing.json" -o "$out/bad3.png"
  sed 's#out/noise.png#out/absent.png#' "$work/exemplar.json" >"$work/missing-image.json"
  expect_bad "missing image" "$out/bad4.png" "absent.png: no such image file" -- "$bin" render "$work/missing-image.json" -o "$out/bad4.png"
  echo "not an image" >"$work/out/corrupt.png"
  sed 's#out/noise.png#out/corrupt.png#' "$work/exemplar.json" >"$work/corrupt-image.json"
  expect_bad "corrupt image" "$out/bad5.png" "corrupt.png: not a PNG, OpenEXR or JPEG image" -- "$bin" render "$work/corrupt-image.json" -o "$out/bad5.png"
}

case_bad_render_flags() {
  expect_bad "NaN scale" "$out/bad6.png" "--scale: scale must be in [1e-06, 1e+06], got nan" -- "$bin" render --preset gaussian -o "$out/bad6.png" --scale nan
  expect_bad "negative scale" "$out/bad7.png" "--scale: scale must be in [1e-06, 1e+06], got -2" -- "$bin" render --preset gaussian -o "$out/bad7.png" --scale -2
  expect_bad "negative size" "$out/bad8.png" "--size: size must be in [1, 16384] per side, got -5x-5" -- "$bin" render --preset gaussian -o "$out/bad8.png" --size=-5
  expect_bad "size over cap" "$out/bad9.png" "--size: size must be in [1, 16384] per side, got 100000x100000" -- "$bin" render --preset gaussian -o "$out/bad9.png" --size 100000
  expect_bad "NaN offset" "$out/bad10.png" "--offset: offset must be finite and at most 1e9 texels, got nan,0" -- "$bin" render --preset gaussian -o "$out/bad10.png" --offset nan,0
  expect_bad "bad extension" "$out/bad11.bmp" "unsupported output format" -- "$bin" render --preset gaussian -o "$out/bad11.bmp"
  expect_bad "missing output dir" "$out/nodir/bad12.png" "does not exist" -- "$bin" render --preset gaussian -o "$out/nodir/bad12.png"
  expect_bad "unknown flag" "$out/bad16.png" "--bogus" -- "$bin" render --preset gaussian -o "$out/bad16.png" --bogus
  expect_bad "bad filter" "$out/bad18.png" '--filter: filter must be none, paper, smooth, exact or reference, got "blurry"' -- "$bin" render --preset gaussian -o "$out/bad18.png" --filter blurry
  # Commands that draw with OpenGL take (and list) the three filters it renders.
  expect_bad "scene exact" "$out/bad18b.png" '--filter: filter must be none, paper or smooth, got "exact"' -- "$bin" scene --preset gaussian -o "$out/bad18b.png" --filter exact
  "$bin" scene --help | grep -q -- "--filter ENUM:{none, paper, smooth}" || fail "scene --help: --filter does not list none, paper, smooth"
  expect_bad "lean without a normal map" "$out/bad24.png" "--response: response lean reads a normal map; the pattern has none" -- "$bin" render --preset weld --response lean -o "$out/bad24.png"
  expect_bad "no-covariance without lean" "$out/bad25.png" "--no-covariance: has no effect without --response lean" -- "$bin" render --preset lean-ridges --no-covariance -o "$out/bad25.png"
  expect_bad "bad response" "$out/bad26.png" '--response: response must be prefiltered-colormap, lean, normal, roughness or height, got "bump"' -- "$bin" render --preset lean-ridges --response bump -o "$out/bad26.png"
  expect_bad "aniso zero" "$out/bad19.png" "--aniso: aniso must be in [1, 16], got 0" -- "$bin" render --preset gaussian -o "$out/bad19.png" --filter smooth --aniso 0
  expect_bad "aniso absurd" "$out/bad20.png" "--aniso: aniso must be in [1, 16], got 1000" -- "$bin" render --preset gaussian -o "$out/bad20.png" --filter smooth --aniso 1000
  expect_bad "tilt" "$out/bad21.png" "--tilt: tiltDeg must be in [0, 89] degrees, got 95" -- "$bin" render --preset gaussian -o "$out/bad21.png" --view plane --tilt 95
  # One entry (pattern/camera.h cameraTiltParam) gives every command's --tilt its range, help and error prefix.
  expect_bad "figure12 tilt" "$out/bad21f" "--tilt: tiltDeg must be in [0, 89] degrees, got 95" -- "$bin" reproduce figure12 --tilt 95 -o "$out/bad21f"
  expect_bad "figure12 aniso" "$out/bad21g" "--aniso: aniso must be in [1, 16], got 0" -- "$bin" reproduce figure12 --aniso 0 -o "$out/bad21g"
  "$bin" render --help | grep -q -- "--tilt FLOAT=60 .*degrees, in \[0, 89\]" || fail "render --help does not show --tilt's range from its entry"
  expect_bad "zero scale" "$out/bad22.png" "--scale: scale must be in [1e-06, 1e+06], got 0" -- "$bin" render --preset gaussian -o "$out/bad22.png" --filter smooth --scale 0
  expect_bad "bad view" "$out/bad23.png" '--view: view must be zoom or plane, got "fisheye"' -- "$bin" render --preset gaussian -o "$out/bad23.png" --view fisheye
  # A pattern file's "estimator" is used unless --estimator is given.
  printf '{"estimator": "sub-probes-4x4", "noise_x": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]}, "noise_y": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]}, "colormap": {"type": "gaussian"}}' >"$work/est.json"
  "$bin" render "$work/est.json" --size 32 --scale 4 --filter paper -o "$out/est1.png" | grep -q "filter paper/sub-probes-4x4" || fail "render: the file's estimator not used"
  "$bin" render "$work/est.json" --size 32 --scale 4 --filter paper --estimator paper -o "$out/est2.png" | grep -q "filter paper," || fail "render: --estimator does not override the file's"
  "$bin" bake "$work/est.json" --filter smooth -o "$out/estbake" >/dev/null || fail "bake with the file's estimator"
  grep -q '"filter": "smooth"' "$out/estbake/manifest.json" || fail "bake: the manifest's filter is not the table's name: $(grep filter "$out/estbake/manifest.json")"
  grep -q '"estimator": "sub-probes-4x4"' "$out/estbake/manifest.json" || fail "bake: the file's estimator not exported"
  expect_bad "bad estimator" "$out/bad24.png" '--estimator: estimator must be paper, deliot-heitz, sub-probes, sub-probes-4x4 or sub-probes-8x8-fine-means, got "dh"' -- "$bin" render --preset gaussian -o "$out/bad24.png" --estimator dh
  expect_bad "stability scale" "$out/sbad1" "--from: from must be in [1e-06, 1e+06], got 0" -- "$bin" stability --preset gaussian -o "$out/sbad1" --from 0
  expect_bad "stability denormal scale" "$out/sbad1b" "--from: from must be in [1e-06, 1e+06], got 4.94066e-324" -- "$bin" stability --preset gaussian -o "$out/sbad1b" --from 4.9e-324
  expect_bad "no pattern" "$out/bad17.png" "give a pattern file or --preset" -- "$bin" render -o "$out/bad17.png"
}

case_bad_spec() {
  expect_bad "bad noise spec" "$out/bad13.png" "<inline JSON>: /components/0/frequency: must be in" -- "$bin" noise '{"type":"spectrum","components":[{"shape":"ring","frequency":-1,"bandwidth":2}]}' -o "$out/bad13.png"
  expect_bad "noise size over cap" "$out/bad14.png" "/size: must be in [8, 4096]" -- "$bin" noise '{"type":"spectrum","size":100000,"components":[{"shape":"lowpass","cutoff":4}]}' -o "$out/bad14.png"
  expect_bad "bad colormap" "$out/bad15.png" "/type: unknown value" -- "$bin" colormap '{"type":"rainbow"}' -o "$out/bad15.png"
}

case_bad_study_flags() {
  # Flags described by the library's entries: the range in --help is the one checked.
  expect_bad "zoom base lattice of 1" "$out/zbad0" "--base-size: baseSize must be in [2, 16384], got 1" -- "$bin" zoom -o "$out/zbad0" --base-size 1
  "$bin" zoom --help | grep -qF -- "--base-size INT=512         Period of the white-noise lattice, in [2, 16384]" || fail "zoom --help: --base-size lacks its entry's range"
  expect_bad "colormap resolution 1" "$out/cres.png" "--resolution: resolution must be in [2, 4096], got 1" -- "$bin" colormap --preset marble --resolution 1 -o "$out/cres.png"
  expect_bad "zoom n = 0" "$out/zbad1" "--layers: layers must be in [1, 1024], got 0" -- "$bin" zoom -o "$out/zbad1" --layers 0
  expect_bad "zoom H <= 0" "$out/zbad2" "--max-scale: maxScale must be in [0.001, 1000], got 0" -- "$bin" zoom -o "$out/zbad2" --max-scale 0
  expect_bad "correlation N = 0" "$out/zbad3" "--instances: instances must be in [2, 1000000], got 0" -- "$bin" correlation -o "$out/zbad3" --instances 0
  expect_bad "contrast unreadable base" "$out/zbad4" "nothere.png: no such image file" -- "$bin" contrast -o "$out/zbad4" --base "$work/nothere.png"
  # A float base far out of range rendered black with exit 0 (its moments overflow float).
  expect_bad "zoom base holding 1e20" "$out/zbad8" "large_values.exr: base texture: pixel (3, 5) channel 0 is 1e+20; its values must be in [-65504, 65504]" -- "$bin" zoom -o "$out/zbad8" --size 16 --frames 2 --base "$src/tests/fuzz/images/large_values.exr"
  expect_bad "analyze bad variant n" "$out/zbad5" "--layers-list: layersList must hold layer counts in [1, 1024], got 0" -- "$bin" analyze -o "$out/zbad5" --layers-list 0
  # One library parameter, two flags: each command names its own.
  expect_bad "analyze plot size 0" "$out/zbad6" "--plot-size: plotSize must be in [4, 1024], got 0" -- "$bin" analyze -o "$out/zbad6" --plot-size 0
  expect_bad "correlation plot size 0" "$out/zbad7" "--size: plotSize must be in [4, 1024], got 0" -- "$bin" correlation -o "$out/zbad7" --size 0
  expect_bad "reproduce unknown preset" "$out/rbad1" 'unknown preset "nope"' -- "$bin" reproduce figure4 -o "$out/rbad1" --preset nope
  expect_bad "figure 4 without the estimators" "$out/rbad3" "--filter: filter must be paper or smooth, got \"exact\"" -- "$bin" reproduce figure4 -o "$out/rbad3" --filter exact
  expect_bad "reproduce zero count" "$out/rbad2" "--count: count must be in [1, 1e6], got 0" -- "$bin" reproduce table1 -o "$out/rbad2" --count 0
  expect_bad "figure 12 negative roughness" "$out/rbad4" "--roughness: roughness must be in [0.001, 10], got -0.1" -- "$bin" reproduce figure12 -o "$out/rbad4" --roughness -0.1
  expect_bad "figure 12 without a normal map" "$out/rbad5" "camouflage: figure 12 needs a pattern with a normal_map" -- "$bin" reproduce figure12 -o "$out/rbad5" --preset camouflage
}

case_bad_gpu_flags() {
  expect_bad "gpu with the reference" "$out/gbad.png" "--gpu: the GPU renders --filter none, paper or smooth" -- "$bin" render --preset camouflage --gpu --filter reference -o "$out/gbad.png"
  expect_bad "unknown pipeline" "$out/gbad2.png" '--pipeline: pipeline must be fragment or compute, got "vulkan"' -- "$bin" render --preset camouflage --gpu --pipeline vulkan -o "$out/gbad2.png"
  expect_bad "unknown derivatives" "$out/gbad3.png" '--derivatives: derivatives must be camera or rasterizer, got "dfdx"' -- "$bin" render --preset camouflage --gpu --derivatives dfdx -o "$out/gbad3.png"
  expect_bad "compute with rasterizer derivatives" "$out/gbad4.png" "--derivatives: derivatives must be camera with the compute pipeline" -- "$bin" render --preset camouflage --gpu --filter paper --pipeline compute --derivatives rasterizer -o "$out/gbad4.png"
}

case_bad_export_flags() {
  expect_bad "scene unknown object" "$out/sbad.png" '--object: object must be plane, sphere or torus, got "cube"' -- "$bin" scene --preset marble --object cube -o "$out/sbad.png"
  expect_bad "bake unfiltered" "$out/bbad" "--filter: source must be estimators to export (filter paper or smooth), got point" -- "$bin" bake --preset weld --filter none -o "$out/bbad"
  expect_bad "bake bad precision" "$out/bbad2" '--table-precision: tablePrecision must be half or float, got "double"' -- "$bin" bake --preset weld --table-precision double -o "$out/bbad2"
  expect_bad "web exact filter" "$out/wbad" '--filter: filter must be none, paper or smooth, got "exact"' -- "$bin" web --preset weld --filter exact -o "$out/wbad"
  expect_bad "web tilt beyond the horizon" "$out/wbad2" "--tilt" -- "$bin" web --preset weld --view plane --tilt 95 -o "$out/wbad2"
}

# --- the web page: three files, the program and the data inside (tests/web drives it in Chromium) ---
case_web() {
  expect_ok "web" "$out/web/index.html" -- "$bin" web --preset weld --size 200,120 -o "$out/web"
  for f in page.js data.js; do [ -s "$out/web/$f" ] || fail "web: no $f"; done
  grep -q '^window.STOCHTEX_DATA = {' "$out/web/data.js" || fail "web: data.js does not define the data"
  grep -q '"size":\[200,120\]' "$out/web/data.js" || fail "web: the starting view's size is not in the data"
  grep -q 'src="data.js"' "$out/web/index.html" || fail "web: index.html does not load data.js"
  # Nothing is fetched: a page opened from disk cannot.
  grep -qE 'fetch\(|XMLHttpRequest' "$out/web/page.js" && fail "web: page.js fetches"
  # The page shows the pattern as given: a preset's text, or inline JSON
  # (which it once left empty, reading the argument as a file name).
  grep -qF '"source":"{\n  \"name\": \"weld\"' "$out/web/data.js" || fail "web: the preset's text is not the page's source"
  local inline
  inline=$(sed 's/"name": "weld"/"name": "inline-weld"/' "$src/data/presets/weld.json" | tr -d '\n')
  expect_ok "web, inline JSON" "$out/webi/index.html" -- "$bin" web "$inline" --size 64 -o "$out/webi"
  grep -qF '"source":"{  \"name\": \"inline-weld\"' "$out/webi/data.js" || fail "web: inline JSON is not the page's source"
  return 0
}

# --- hostile JSON and flag values: refused up front, naming the input ---
case_hostile_json() {
  { head -c 100000 /dev/zero | tr '\0' '['; head -c 100000 /dev/zero | tr '\0' ']'; } >"$work/deep.json"
  expect_bad "100k nested arrays" "$out/h1.png" "deep.json: /0/0/0" -- "$bin" render "$work/deep.json" -o "$out/h1.png"
  grep -qF "nested deeper than 64 levels" "$work/err.txt" || fail "deep nesting: $(cat "$work/err.txt")"
  echo '{"name": "x", "seed": 1e400}' >"$work/overflow.json"
  expect_bad "number overflowing a double" "$out/h2.png" "overflow.json: /seed: number 1e400 is out of the range of a double" -- "$bin" render "$work/overflow.json" -o "$out/h2.png"
  echo '{"name": "a", "name": "b"}' >"$work/dup.json"
  expect_bad "duplicate member" "$out/h3.png" 'dup.json: /name: member "name" given twice' -- "$bin" render "$work/dup.json" -o "$out/h3.png"
  expect_bad "unsigned seed shown as written" "$out/h4.png" "/seed: must be in [0, 4294967295], got 18446744073709551615" -- "$bin" noise '{"type":"spectrum","seed":18446744073709551615,"components":[{"shape":"lowpass","cutoff":4}]}' -o "$out/h4.png"
  { printf '{"name": "'; head -c 2000000 /dev/zero | tr '\0' a; printf '"}'; } >"$work/huge.json"
  expect_bad "2 MB pattern file" "$out/h5.png" "huge.json: 2000012 bytes of JSON; the limit is 1048576 bytes" -- "$bin" render "$work/huge.json" -o "$out/h5.png"
  mkdir -p "$work/folder.json"
  expect_bad "folder as pattern" "$out/h6.png" "folder.json: is a folder, not a JSON file" -- "$bin" render "$work/folder.json" -o "$out/h6.png"
  mkdir -p "$out/taken.png"
  expect_bad "output is a folder" "$out/h7.png" "taken.png: is a folder" -- "$bin" render --preset gaussian -o "$out/taken.png"
  expect_bad "bits not a number" "$out/h8.png" '--bits: bits must be 8 or 16, got "abc"' -- "$bin" render --preset gaussian --bits abc -o "$out/h8.png"
  expect_bad "negative seed" "$out/h9.png" '--seed: seed must be an integer in [0, 4294967295], got "-1"' -- "$bin" render --preset gaussian --seed -1 -o "$out/h9.png"
  expect_bad "table1 seed over uint32" "$out/h10" '--seed: seed must be an integer in [0, 4294967295], got "4294967296"' -- "$bin" reproduce table1 --seed 4294967296 -o "$out/h10"
  # The whole uint32 range is a seed, in JSON and on the command line alike.
  expect_ok "largest seed" "$out/h11.png" -- "$bin" render --preset gaussian --seed 4294967295 --size 16 -o "$out/h11.png"
}

# --- hostile graphs (issue "Hostile input on the new surfaces", item 1) ---
# A spectral noise through N transform nodes at scale 64 composes a uv scale
# of 64^N: it crashed every CPU filter and wrote "inf.0" into the GLSL. Each
# path now refuses the node where the chain leaves one node's range.
transform_chain() {  # transform_chain N FILE
  local i previous=n0
  {
    printf '{"name": "chain", "size": 16, "nodes": {"n0": {"type": "spectral_noise", "size": 16, "components": [{"shape": "ring", "frequency": 4, "bandwidth": 1}]}'
    for i in $(seq "$1"); do printf ', "t%d": {"type": "transform", "input": "%s", "scale": 64}' "$i" "$previous"; previous=t$i; done
    printf ', "c": {"type": "colormap", "x": "%s", "y": "n0", "colormap": {"type": "gaussian"}}}, "output": "c"}' "$previous"
  } >"$2"
}
case_hostile_graph() {
  local n f message='chain: node "t2" (transform): /nodes/t2/scale: composed with the transforms it reads, uv is scaled by 4096'
  transform_chain 1 "$work/t1.json"
  expect_ok "one transform at scale 64" "$out/t1.png" -- "$bin" render "$work/t1.json" --size 16 --filter smooth -o "$out/t1.png"
  for n in 5 172; do
    transform_chain "$n" "$work/t$n.json"
    for f in none paper smooth exact; do
      expect_bad "$n transforms, filter $f" "$out/t$n$f.png" "$message" -- timeout 20 "$bin" render "$work/t$n.json" --size 32 --view plane --filter "$f" -o "$out/t$n$f.png"
    done
    expect_bad "$n transforms on the GPU" "$out/t${n}g.png" "$message" -- timeout 20 "$bin" render "$work/t$n.json" --size 32 --filter smooth --gpu -o "$out/t${n}g.png"
    expect_bad "$n transforms baked" "$out/tb$n" "$message" -- timeout 20 "$bin" bake "$work/t$n.json" -o "$out/tb$n"
  done
  # A noise near 100 squared eight times (1e4, then 1e8 past half float, 1e32 past float): per pixel (a white image, exit 0, before the ops' range check).
  local nodes='"n": {"type": "spectral_noise", "size": 16, "components": [{"shape": "ring", "frequency": 4, "bandwidth": 1}]}, "a": {"type": "affine", "input": "n", "scale": 1, "offset": 100}' previous=a i
  for i in 1 2 3 4 5 6 7 8; do nodes="$nodes, \"s$i\": {\"type\": \"square\", \"input\": \"$previous\"}"; previous=s$i; done
  echo "{\"name\": \"squares\", \"size\": 16, \"nodes\": {$nodes, \"c\": {\"type\": \"colormap\", \"x\": \"$previous\", \"y\": \"n\", \"colormap\": {\"type\": \"gaussian\"}}}, \"output\": \"c\"}" >"$work/squares.json"
  for f in none smooth; do
    expect_bad "squares past float, filter $f" "$out/sq$f.png" 'squares: node "s2" (square): its values may reach ' -- timeout 20 "$bin" render "$work/squares.json" --size 16 --filter "$f" -o "$out/sq$f.png"
  done
  expect_bad "squares past float on the GPU" "$out/sqg.png" 'squares: node "s2" (square)' -- timeout 20 "$bin" render "$work/squares.json" --size 16 --gpu -o "$out/sqg.png"
}

# A #line near 2^31: the driver's log numbers lines past an int ("internal error: stoi", exit 1).
case_hostile_shadertoy() {
  mkdir -p "$work/line"
  printf 'void mainImage(out vec4 c, in vec2 p) {\n#line 2147483640\n c = vec4(1);\n\n\n\n\n\n\n\n\n\n c = vec4(undefinedThing);\n}\n' >"$work/line/image.glsl"
  expect_bad "#line past an int" "$out/line.png" "line: pass image does not compile" -- "$bin" shadertoy "$work/line" --size 16 -o "$out/line.png"
  grep -q "undefinedThing" "$work/err.txt" || fail "#line past an int: the compiler's message is lost: $(cat "$work/err.txt")"
  # Channels of 4096² images: 20 of them took ~8 GB; budgeted from the headers before any is read.
  mkdir -p "$work/big"
  "$bin" noise '{"type":"spectrum","size":4096,"components":[{"shape":"lowpass","cutoff":4}]}' -o "$work/big/big.png" >/dev/null || fail "noise 4096"
  printf 'void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p / iResolution.xy); }\n' >"$work/big/image.glsl"
  local big='{"type": "image", "path": "big.png"}'
  printf '{"passes": {"image": {"code": "image.glsl", "channels": [%s, %s, %s, %s]}}}' "$big" "$big" "$big" "$big" >"$work/big/shadertoy.json"
  expect_bad "four 4096² image channels" "$out/big.png" "pass image: channel 3: the channels' textures take 1365 MiB up to here; at most 1024 MiB in all" -- bash -c 'ulimit -v 4194304; exec timeout 20 "$0" "$@"' "$bin" shadertoy "$work/big" --size 16 -o "$out/big.png"
}

# --- budgets (README, "Bad input"): --budget scales them; what only a watchdog
# can bound (a driver's compile or draw, a GPU frame) ends the process with
# exit 2 and the pass named, in about the budget's time ---
case_budgets() {
  expect_bad "a budget factor of 0" "$out/b0.png" "--budget: budget must be in [1/64, 64], got 0" -- "$bin" --budget 0 noise '{"type":"spectrum","size":64,"components":[{"shape":"lowpass","cutoff":4}]}' -o "$out/b0.png"
  local comps='{"shape": "ring", "frequency": 8, "bandwidth": 2}' i
  for i in 1 2 3 4; do comps="$comps, {\"shape\": \"ring\", \"frequency\": $((i + 8)), \"bandwidth\": 2}"; done
  local five="{\"type\": \"spectrum\", \"size\": 1024, \"components\": [$comps]}"
  expect_bad "5 components of 1024² at 1/64 of the budget" "$out/b1.png" "components × size² must be at most 4194304, got 5 × 1024² = 5242880 (--budget 0.0625 allows 0.0625× the budgets; now ×0.015625)" -- "$bin" noise "$five" --budget 0.015625 -o "$out/b1.png"
  expect_ok "the same at 1/32 of the budget" "$out/b2.png" -- "$bin" noise "$five" --budget 0.03125 -o "$out/b2.png"
  # A frame of 60000 iterations a pixel (~6 s at 256² on llvmpipe) under a 1.5 s budget.
  mkdir -p "$work/loop" "$work/macro" "$work/array"
  printf 'void mainImage(out vec4 c, in vec2 p) { float s = p.x; for (int i = 0; i < 60000; i++) { s = fract(s * 1.37 + p.y + sin(s)); } c = vec4(s); }\n' >"$work/loop/image.glsl"
  local start=$SECONDS
  expect_bad "a frame past its time budget" "$out/loop.png" "loop: pass image of frame 0 ran past the frame's time budget of 1.5 s" -- timeout 60 "$bin" shadertoy "$work/loop" --size 512 --budget 0.05 -o "$out/loop.png"
  [ $((SECONDS - start)) -le 20 ] || fail "the frame's budget of 1.5 s ended the run after $((SECONDS - start)) s"
  # Macros that expand to 2^26 terms (38 s and 7 GB in Mesa's preprocessor, then a crash).
  { echo '#define A0 1.0'; for i in $(seq 26); do echo "#define A$i (A$((i - 1)) + A$((i - 1)))"; done
    echo 'void mainImage(out vec4 c, in vec2 p) { c = vec4(A26); }'; } >"$work/macro/image.glsl"
  expect_bad "a macro bomb" "$out/macro.png" "image.glsl + shadertoy_main: the GL driver's compile grew the process's memory by more than its budget of 256 MiB" -- timeout 60 "$bin" shadertoy "$work/macro" --size 16 --budget 0.125 -o "$out/macro.png"
  # An array of 5·10⁷ floats: llvmpipe generates its code at the first draw
  # (18 GB in 2 minutes) on a CPU without AVX-512, at the link on one with it.
  printf 'float big[50000000]; void mainImage(out vec4 c, in vec2 p) { for (int i = 0; i < 100; i++) big[i * int(p.x)] = p.y; c = vec4(big[int(p.x)]); }\n' >"$work/array/image.glsl"
  expect_bad "a huge array" "$out/array.png" "grew the process's memory by more than its budget of 256 MiB" -- timeout 60 "$bin" shadertoy "$work/array" --size 16 --budget 0.125 -o "$out/array.png"
  grep -qE "array: pass image of frame 0, in the GL driver's draw|array/image.glsl \+ shadertoy_main: the GL driver's link" "$work/err.txt" ||
    fail "a huge array: the message names neither the pass nor its shader: $(cat "$work/err.txt")"
}

# --- writes that were lost (issue "Hostile input on the new surfaces", items 4 and 5) ---
case_lost_writes() {
  # Over a file-size limit the MP4 writer was killed by SIGXFSZ (or, with the
  # signal ignored, crashed in a second trailer), leaving its temporary file.
  expect_bad "MP4 over a file-size limit" "$out/big.mp4" "big.mp4: cannot write the video" -- bash -c 'ulimit -f 40; exec "$0" "$@"' "$bin" zoom -o "$out/big.mp4" --size 256 --frames 30
  grep -q "File too large" "$work/err.txt" || fail "MP4 over a file-size limit: the reason is lost: $(cat "$work/err.txt")"
  [ -z "$(ls -A "$out")" ] || fail "MP4 over a file-size limit left: $(ls -A "$out")"
  expect_bad "PNG over a file-size limit" "$out/big.png" "big.png: write failed: File too large" -- bash -c 'ulimit -f 4; exec "$0" "$@"' "$bin" render --preset camouflage --size 512 -o "$out/big.png"
  # A rename over a FIFO (or, as root, a device node) replaced it.
  mkfifo "$work/pipe.png" "$work/pipe.mp4"
  expect_bad "output is a FIFO" "$out/none.png" "pipe.png: is a FIFO; only a regular file is replaced by an output" -- "$bin" render --preset gaussian --size 16 -o "$work/pipe.png"
  expect_bad "video output is a FIFO" "$out/none.png" "pipe.mp4: is a FIFO; only a regular file is replaced by an output" -- "$bin" zoom --size 16 --frames 2 -o "$work/pipe.mp4"
  [ -p "$work/pipe.png" ] && [ -p "$work/pipe.mp4" ] || fail "a FIFO output was replaced"
  # A scripted screenshot into a folder that does not exist exited 0 and said nothing.
  printf '[{"frame": 1, "screenshot": "%s/no/such/folder/shot.png"}]' "$work" >"$work/shot.json"
  expect_bad "workbench screenshot into a missing folder" "$out/wbm.png" "/no/such/folder/shot.png: directory" -- "$bin" view --preset camouflage --frames 3 --script "$work/shot.json" --screenshot "$out/wbm.png"
  grep -q "does not exist" "$work/err.txt" || fail "workbench screenshot: $(cat "$work/err.txt")"
}

# --- work bombs (issue "Hostile input on the new surfaces", item 3): refused before the work,
# under a memory limit (ulimit -v, 4 GiB) and a time limit ---
case_work_bombs() {
  local i comps='{"shape": "ring", "frequency": 8, "bandwidth": 2}' nodes=''
  for i in $(seq 15); do comps="$comps, {\"shape\": \"ring\", \"frequency\": $((i + 8)), \"bandwidth\": 2}"; done
  for i in $(seq 0 15); do nodes="$nodes\"n$i\": {\"type\": \"spectral_noise\", \"size\": 4096, \"components\": [$comps]}, "; done
  printf '{"name": "bomb", "nodes": {%s"c": {"type": "colormap", "x": "n0", "y": "n15", "colormap": {"type": "gaussian"}}}, "output": "c"}' "$nodes" >"$work/bomb.json"
  expect_bad "16 noises of 4096² with 16 rings" "$out/bomb.png" "bomb.json: /nodes/n" -- bash -c 'ulimit -v 4194304; exec timeout 20 "$0" "$@"' "$bin" render "$work/bomb.json" --size 16 -o "$out/bomb.png"
  grep -qE "at most (67108864 in all|536870912 in all)" "$work/err.txt" || fail "graph bomb: $(cat "$work/err.txt")"
  # Answers naming 200 tile sizes (1.6 GB and 201 plots), /dev/zero (bad_alloc), a file over 16 MiB.
  { echo "w,correlation,answer"; for i in $(seq 200); do echo "$((i + 1)),0.5,yes"; done; } >"$work/tiles.csv"
  expect_bad "answers for 200 tile sizes" "$out/ans1" "tiles.csv: answers for 200 tile sizes; at most 32 are analysed" -- bash -c 'ulimit -v 4194304; exec timeout 20 "$0" "$@"' "$bin" stimuli --analyse "$work/tiles.csv" -o "$out/ans1"
  expect_bad "answers from /dev/zero" "$out/ans2" "/dev/zero: more than 16777216 bytes" -- bash -c 'ulimit -v 4194304; exec timeout 20 "$0" "$@"' "$bin" stimuli --analyse /dev/zero -o "$out/ans2"
}

# --- work budget: refused in well under a second, naming the parameter ---
case_work_budget() {
  echo '{"noise_x": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]}, "noise_y": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]}, "colormap": {"type": "ridged", "resolution": 4096}, "size": 32}' >"$work/fine.json"
  expect_bad "colormap too fine to prefilter" "$out/w1.png" "fine.json: /colormap/resolution: resolution must be at most 1024 per side to be prefiltered, got 4096x4096 (--filter smooth)" -- timeout 10 "$bin" render "$work/fine.json" --filter smooth -o "$out/w1.png"
  expect_ok "the same colormap unfiltered" "$out/w2.png" -- "$bin" render "$work/fine.json" --filter none -o "$out/w2.png"
  local discs='{"shape": "disc", "center": [0.5, 0.5], "radius": 0.1, "colour": "#ff0000"}' shapes i
  shapes=$discs
  for i in $(seq 999); do shapes="$shapes, $discs"; done
  echo "{\"type\": \"painted\", \"resolution\": 4096, \"shapes\": [$shapes]}" >"$work/discs.json"
  expect_bad "1000 discs at 4096" "$out/w3.png" "discs.json: /shapes: shapes cost 1000 shape tests" -- timeout 10 "$bin" colormap "$work/discs.json" -o "$out/w3.png"
  local comp='{"shape": "ring", "frequency": 8, "bandwidth": 2}' comps
  comps=$comp
  for i in $(seq 16); do comps="$comps, $comp"; done
  expect_bad "17 components at 4096" "$out/w4.png" "/components: components × size² must be at most 268435456, got 17 × 4096² = 285212672" -- timeout 10 "$bin" noise "{\"type\": \"spectrum\", \"size\": 4096, \"components\": [$comps]}" -o "$out/w4.png"
}

# --- hostile image files: the header is checked before decoding, one message names the file ---
png_signature='\x89\x50\x4e\x47\x0d\x0a\x1a\x0a'
png_iend='\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82'
case_bad_image() {
  make_exemplar
  # 8-bit gray IHDRs with valid CRCs: 20000², 0×0; then 4×4 with its CRC flipped.
  printf "$png_signature"'\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x4e\x20\x00\x00\x4e\x20\x08\x00\x00\x00\x00\xc6\x1b\x19\xe5'"$png_iend" >"$work/huge.png"
  printf "$png_signature"'\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x00\x00\x00\x00\x00\x08\x00\x00\x00\x00\x1e\xe0\x23\xce'"$png_iend" >"$work/zero.png"
  printf "$png_signature"'\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x04\x00\x00\x00\x04\x08\x00\x00\x00\x00\x73\x65\x3e\x5d'"$png_iend" >"$work/crc.png"
  # A valid 1×1 gray PNG.
  printf "$png_signature"'\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x01\x00\x00\x00\x01\x08\x00\x00\x00\x00\x3a\x7e\x9b\x55\x00\x00\x00\x0a\x49\x44\x41\x54\x78\x9c\x63\x68\x00\x00\x00\x82\x00\x81\x77\xcd\x72\xb6'"$png_iend" >"$work/one.png"
  : >"$work/empty.png"
  # With 1 GB of address space a decode of 20000² (400 MB of bytes, 1.6 GB of
  # floats) cannot even start: the header check must answer first. (Skipped
  # under AddressSanitizer, which reserves terabytes of address space.)
  local limit=1000000
  ldd "$bin" 2>/dev/null | grep -q libasan && limit=unlimited
  for f in huge zero crc empty; do
    sed "s#out/noise.png#$work/$f.png#" "$work/exemplar.json" >"$work/$f.json"
  done
  expect_bad "huge exemplar header" "$out/h.png" "huge.png: the image is 20000x20000 pixels; images of at most 16777216 pixels (4096x4096) and 65536 per side are read" -- bash -c "ulimit -v $limit; exec \"\$@\"" _ "$bin" render "$work/huge.json" -o "$out/h.png"
  expect_bad "huge base header" "$out/hz" "huge.png: the image is 20000x20000 pixels" -- bash -c "ulimit -v $limit; exec \"\$@\"" _ "$bin" zoom --base "$work/huge.png" -o "$out/hz"
  expect_bad "0x0 exemplar" "$out/z.png" "zero.png: the image is 0x0 pixels (empty)" -- "$bin" render "$work/zero.json" -o "$out/z.png"
  expect_bad "bad CRC exemplar" "$out/c.png" "crc.png: corrupt PNG (IHDR: CRC error)" -- "$bin" render "$work/crc.json" -o "$out/c.png"
  expect_bad "empty exemplar" "$out/e.png" "empty.png: the file is empty" -- "$bin" render "$work/empty.json" -o "$out/e.png"
  expect_bad "1x1 base" "$out/o" "one.png: base texture: needs at least 2×2 pixels, got 1×1" -- "$bin" zoom --base "$work/one.png" -o "$out/o" --frames 1 --size 8
  expect_bad "folder as base" "$out/d" "out: is a folder, not an image file" -- "$bin" contrast --base "$out" -o "$out/d"
  for f in "$work/err.txt"; do grep -qi "libpng\|OpenCV" "$f" && fail "a library message leaked: $(cat "$f")"; done
}

# --- temporary files: unique, exclusive, removed on failure and on a signal ---
case_bake_image_temp() {
  # A link planted at the old fixed temporary name is never followed.
  echo precious >"$work/victim"
  ln -s "$work/victim" "$out/b.png.tmp"
  expect_ok "bake-image beside a planted link" "$out/b.png" -- "$bin" bake-image --preset marble --size 64 --filter none -o "$out/b.png"
  [ "$(cat "$work/victim")" = precious ] || fail "bake-image wrote through a planted symlink"
  [ -L "$out/b.png" ] && fail "bake-image left a symlink as its output"
  rm "$out/b.png.tmp"
  # Concurrent runs to one path: both succeed and the file is one whole image.
  "$bin" bake-image --preset marble --size 160,120 --band 8 --filter none -o "$out/ref.png" >/dev/null 2>&1 || fail "bake-image reference"
  local pair
  for pair in 1 2 3; do
    "$bin" bake-image --preset marble --size 160,120 --band 8 --filter none -o "$out/c.png" >/dev/null 2>&1 & local p1=$!
    "$bin" bake-image --preset marble --size 160,120 --band 8 --filter none -o "$out/c.png" >/dev/null 2>&1 & local p2=$!
    wait $p1 || fail "concurrent bake-image $pair/1 failed"
    wait $p2 || fail "concurrent bake-image $pair/2 failed"
    cmp -s "$out/c.png" "$out/ref.png" || fail "concurrent bake-image $pair: the output is not the image"
  done
  if ls -a "$out" | grep -q '\.tmp'; then fail "temporary files left: $(ls -a "$out")"; fi
}

# Starts a command in the background, waits until its temporary file exists,
# sends SIGNAL and checks the exit status (128 + signal) and that no temporary
# file is left in FOLDER. Job control on, so SIGINT is not ignored by the job.
# interrupt DESCRIPTION SIGNAL STATUS FOLDER -- command...
interrupt() {
  local what=$1 sig=$2 status=$3 folder=$4; shift 5
  set -m
  "$@" >/dev/null 2>&1 &
  local pid=$! i
  for i in $(seq 200); do
    ls -a "$folder" 2>/dev/null | grep -q '\.tmp' && break
    sleep 0.05
  done
  ls -a "$folder" 2>/dev/null | grep -q '\.tmp' || fail "$what: no temporary file appeared"
  kill -s "$sig" $pid
  wait $pid
  local rc=$?
  set +m
  [ $rc -eq "$status" ] || fail "$what: exit status $rc, expected $status"
  if ls -a "$folder" 2>/dev/null | grep -q '\.tmp'; then fail "$what: temporary file left: $(ls -a "$folder")"; fi
}

case_interrupted() {
  interrupt "bake-image SIGTERM" TERM 143 "$out" -- "$bin" bake-image --preset camouflage --size 4096 --band 16 --threads 1 -o "$out/big.png"
  [ -e "$out/big.png" ] && fail "bake-image SIGTERM: a partial big.png exists"
  interrupt "bake-image SIGINT" INT 130 "$out" -- "$bin" bake-image --preset camouflage --size 4096 --band 16 --threads 1 -o "$out/big.png"
  interrupt "zoom MP4 SIGTERM" TERM 143 "$out" -- "$bin" zoom --frames 100000 --size 256 --threads 1 -o "$out/z.mp4"
  [ -e "$out/z.mp4" ] && fail "zoom SIGTERM: a partial z.mp4 exists"
  # A folder keeps the frames written so far (as --help says), never a temporary file.
  interrupt "zoom folder SIGTERM" TERM 143 "$out/zf" -- "$bin" zoom --frames 100000 --size 256 --threads 1 -o "$out/zf"
  [ -e "$out/zf/zoom.mp4" ] && fail "zoom folder SIGTERM: a partial zoom.mp4 exists"
  "$bin" zoom --help | grep -q "interrupted run leaves the frames" || fail "zoom --help does not say what an interrupted run leaves"
}

# --- zoom: every frame's time checked before anything is written ---
case_zoom_times() {
  expect_bad "zoom last time" "$out/t1" "the last frame would be at t = --time + (frames − 1) / fps × speed = 1000000000.0166667, out of range" -- "$bin" zoom --time 1e9 --frames 3 --size 8 -o "$out/t1"
  expect_bad "zoom speed" "$out/t2" "out of range: time must be in [-1e+09, 1e+09]" -- "$bin" zoom --speed 1e300 --frames 3 --size 8 -o "$out/t2"
  expect_bad "zoom fps" "$out/t3" "out of range: time must be in [-1e+09, 1e+09]" -- "$bin" zoom --fps 1e-300 --frames 3 --size 8 -o "$out/t3"
  expect_bad "zoom fps video" "$out/t4.mp4" "out of range" -- "$bin" zoom --fps 1e-300 --frames 3 --size 8 -o "$out/t4.mp4"
  expect_ok "zoom one frame at the bound" "$out/t5/frame_0000.png" -- "$bin" zoom --time 1e9 --frames 1 --size 8 -o "$out/t5" --no-video
}

# --- video: -o NAME.mp4 on every sequence command ---
case_video() {
  expect_ok "zoom to MP4" "$out/clip.mp4" -- "$bin" zoom --frames 12 --size 64,48 -o "$out/clip.mp4"
  [ -f "$out/clip.mp4" ] && [ "$(ls -A "$out" | tr '\n' ' ')" = "clip.mp4 clip.webp " ] || fail "zoom to MP4 did not write the video and its preview alone: $(ls -A "$out")"
  # The preview is an animated WebP of every frame (RIFF....WEBP with an ANIM chunk).
  head -c 12 "$out/clip.webp" | tail -c 4 | grep -q WEBP && grep -qa ANIM "$out/clip.webp" || fail "clip.webp is not an animated WebP"
  expect_ok "zoom folder with MP4" "$out/zf/zoom.mp4" -- "$bin" zoom --frames 3 --size 32 -o "$out/zf"
  [ -s "$out/zf/frame_0002.png" ] || fail "zoom folder: frames missing"
  expect_ok "stability videos" "$out/st/smooth.mp4" -- "$bin" stability --preset camouflage --frames 4 --size 32 --filters none,smooth --video -o "$out/st"
  [ -s "$out/st/none.mp4" ] && [ -s "$out/st/none.webp" ] || fail "stability: none.mp4 or its preview missing"
  expect_bad "no-video with an MP4" "$out/nv.mp4" "--no-video" -- "$bin" zoom --no-video -o "$out/nv.mp4"
}

# The media codecs (OpenCV's imgcodecs and videoio, FFmpeg's encoders) are a
# plugin beside the binary, loaded by the first file that needs them: the
# binary does not link them, PNG and EXR (our own writers) need no plugin,
# and a JPEG asked of a binary without it fails naming the file it looked
# for, leaving nothing behind.
case_media_plugin() {
  readelf -d "$bin" | grep NEEDED >"$work/needed.txt"
  grep -q "libopencv_core" "$work/needed.txt" || fail "readelf shows no NEEDED libopencv_core: $(cat "$work/needed.txt")"
  for lib in opencv_imgcodecs opencv_videoio libavformat libavcodec libswscale; do
    grep -q "$lib" "$work/needed.txt" && fail "the binary links $lib, which belongs in the media plugin"
  done
  local plugin
  plugin="$(dirname "$bin")/libstochtex_media.so"
  [ -f "$plugin" ] || fail "no $plugin beside the binary"
  readelf -d "$plugin" | grep -q "libopencv_imgcodecs" || fail "the plugin does not link imgcodecs"
  mkdir -p "$work/alone"
  cp "$bin" "$work/alone/stochtex"
  local alone
  alone=$(cd "$work/alone" && pwd -P)  # as /proc/self/exe resolves it
  expect_ok "png without the plugin" "$out/alone.png" -- "$work/alone/stochtex" render --preset camouflage --size 32 -o "$out/alone.png"
  expect_ok "exr without the plugin" "$out/alone.exr" -- "$work/alone/stochtex" render --preset camouflage --size 32 -o "$out/alone.exr"
  "$work/alone/stochtex" render --preset camouflage --size 32 -o "$out/alone.jpg" >"$work/out.txt" 2>"$work/err.txt"
  local rc=$?
  [ $rc -eq 1 ] || fail "jpg without the plugin: exit $rc, expected 1"
  grep -qF "cannot load the media codecs (EXR, JPEG, TIFF, video) from $alone/libstochtex_media.so: cannot open shared object file" "$work/err.txt" ||
    fail "jpg without the plugin: $(cat "$work/err.txt")"
  [ ! -e "$out/alone.jpg" ] || fail "jpg without the plugin: $out/alone.jpg was left behind"
  # With the plugin beside it, the same command writes the JPEG, and the EXR
  # written without it reads back (through the plugin's OpenEXR decoder).
  expect_ok "jpg with the plugin" "$out/with.jpg" -- "$bin" render --preset camouflage --size 32 -o "$out/with.jpg"
  local ring='"type":"spectrum","size":64,"components":[{"shape":"ring","frequency":8,"bandwidth":2}]'
  local pattern="{\"noise_x\":{$ring,\"seed\":3},\"noise_y\":{$ring,\"seed\":4},"
  pattern+="\"colormap\":{\"type\":\"image\",\"path\":\"$out/alone.exr\"},\"size\":64}"
  expect_ok "exr read back" "$out/exr-read.png" -- "$bin" render "$pattern" --size 32 -o "$out/exr-read.png"
}

# --- discoverability: version, typos, defaults, flags that would do nothing ---
case_version() {
  "$bin" --version >"$work/v.txt" 2>&1 || fail "--version exits non-zero"
  grep -qE '^stochtex [0-9]+\.[0-9]+\.[0-9]+( \(git [^)]+\))?$' "$work/v.txt" || fail "--version prints: $(cat "$work/v.txt")"
}

case_typos() {
  expect_bad "mistyped command" "" 'stochtex: error: unknown command "rendr" (did you mean render?)' -- "$bin" rendr --preset marble -o "$out/t.png"
  expect_bad "mistyped subcommand" "" 'stochtex: error: reproduce: unknown command "tabel1" (did you mean table1?)' -- "$bin" reproduce tabel1 -o "$out/t"
  expect_bad "mistyped option" "$out/t.png" "stochtex: error: render: unknown option --frobnicat" -- "$bin" render --preset marble -o "$out/t.png" --frobnicat
  grep -q "did you mean" "$work/err.txt" && fail "--frobnicat is near no option, yet: $(cat "$work/err.txt")"
  expect_bad "near option" "$out/t.png" "stochtex: error: render: unknown option --anisoo (did you mean --aniso?)" -- "$bin" render --preset marble -o "$out/t.png" --filter smooth --anisoo 4
  expect_bad "near option with =" "$out/t.png" "unknown option --filtr (did you mean --filter?)" -- "$bin" render --preset marble -o "$out/t.png" --filtr=smooth
  # Suggestions below the top level too, and for abbreviations; a one-letter
  # option suggests the long option it may stand for, not another letter.
  expect_bad "abbreviated subcommand" "" 'reproduce: unknown command "fig11" (did you mean figure11?)' -- "$bin" reproduce fig11 -o "$out/t"
  expect_bad "mistyped preset" "$out/t.png" 'unknown preset "marbel" (did you mean marble?)' -- "$bin" render --preset marbel -o "$out/t.png"
  expect_bad "mistyped filter" "$out/t.png" 'got "smoth" (did you mean smooth?)' -- "$bin" render --preset marble --filter smoth -o "$out/t.png"
  expect_bad "-V" "" "unknown option -V (did you mean --version?)" -- "$bin" -V
  expect_bad "figure 11 filters" "" 'filter must be paper or smooth, got "exact"' -- "$bin" reproduce figure11 --filter exact -o "$out/t"
  "$bin" reproduce figure11 --help | grep -q "ENUM:{paper, smooth}" || fail "reproduce figure11 --help lists filters it refuses: $("$bin" reproduce figure11 --help | grep -- --filter)"
  # No display is not a bug: exit 2 with the reason.
  expect_bad "view without a display" "" "no display" -- env -u DISPLAY -u WAYLAND_DISPLAY "$bin" view --preset marble --frames 1
  expect_bad "unknown top-level option" "" "stochtex: error: unknown option --frobnicate" -- "$bin" --frobnicate
  # Values are not mistaken for commands or options.
  expect_ok "negative offset and a value like a command" "$out/ok.png" -- "$bin" render --preset marble --size 16 --offset -3,-4 --filter smooth -o "$out/ok.png"
}

case_help_defaults() {
  for c in render bake-image stability bake scene view; do
    "$bin" $c --help >"$work/h.txt" 2>&1 || fail "$c --help exits non-zero"
    grep -E '^ +--aniso ' "$work/h.txt" | grep -qE '=8( |$)' || fail "$c --help: --aniso does not show the one default 8: $(grep -- --aniso "$work/h.txt")"
  done
  "$bin" render --help >"$work/h.txt"
  for flag in "--tilt" "--fov" "--reference-samples" "--bits" "--filter" "--view"; do
    grep -E "^ +$flag " "$work/h.txt" | grep -qE '=[^ ]+( |$)' || fail "render --help: $flag shows no default: $(grep -- "$flag" "$work/h.txt")"
  done
  "$bin" zoom --help >"$work/h.txt"
  grep -E '^ +--frames ' "$work/h.txt" | grep -qE '=60( |$)' || fail "zoom --help: --frames shows no default"
  # Lists read as they are typed; an empty one (the pattern's size) shows nothing.
  "$bin" scene --help | grep -E '^ +--size ' | grep -qE '=768,512( |$)' || fail "scene --help: --size default: $("$bin" scene --help | grep -- --size)"
  "$bin" render --help | grep -E '^ +--size ' | grep -q '=' && fail "render --help: --size shows an empty default"
}

case_no_effect_flags() {
  expect_bad "aniso unfiltered" "$out/n1.png" "--aniso: has no effect with --filter none" -- "$bin" render --preset marble --aniso 4 -o "$out/n1.png"
  expect_bad "aniso reference" "$out/n2.png" "--aniso: has no effect with --filter reference" -- "$bin" render --preset marble --filter reference --aniso 4 -o "$out/n2.png"
  expect_bad "tilt in the zoom view" "$out/n3.png" "--tilt: has no effect in the zoom view" -- "$bin" render --preset marble --tilt 30 -o "$out/n3.png"
  expect_bad "fov in the zoom view" "$out/n4.png" "--fov: has no effect in the zoom view" -- "$bin" render --preset marble --fov 40 -o "$out/n4.png"
  expect_bad "bits with EXR" "$out/n5.exr" "--bits: has no effect with an .exr output" -- "$bin" render --preset marble --bits 16 -o "$out/n5.exr"
  expect_bad "reference samples with smooth" "$out/n6.png" "--reference-samples: has no effect with --filter smooth" -- "$bin" render --preset marble --filter smooth --reference-samples 8 -o "$out/n6.png"
  expect_bad "estimator unfiltered" "$out/n7.png" "--estimator: has no effect with --filter none" -- "$bin" render --preset marble --estimator deliot-heitz -o "$out/n7.png"
  expect_bad "pipeline on the CPU" "$out/n8.png" "--pipeline: has no effect without --gpu" -- "$bin" render --preset marble --pipeline compute -o "$out/n8.png"
  expect_bad "stability aniso" "$out/n9" "--aniso: has no effect without paper or smooth in --filters" -- "$bin" stability --preset marble --filters none,reference --aniso 4 -o "$out/n9"
  expect_bad "bake-image aniso" "$out/n10.png" "--aniso: has no effect with --filter none" -- "$bin" bake-image --preset marble --filter none --aniso 2 -o "$out/n10.png"
  expect_bad "scene aniso" "$out/n11.png" "--aniso: has no effect with --filter none" -- "$bin" scene --preset marble --filter none --aniso 2 -o "$out/n11.png"
  expect_bad "noise bits with EXR" "$out/n12.exr" "--bits: has no effect with an .exr output" -- "$bin" noise '{"type":"spectrum","size":16,"components":[{"shape":"lowpass","cutoff":4}]}' --bits 16 -o "$out/n12.exr"
  # Where they act, the same flags are accepted.
  expect_ok "aniso with smooth, tilt in the plane view" "$out/ok.png" -- "$bin" render --preset marble --size 16 --filter smooth --aniso 4 --view plane --tilt 30 --fov 40 -o "$out/ok.png"
}

# --- progress: a \r line on a terminal only, ended before the report ---
# drawn FILE: FILE holds a \r that is not a terminal's line end (\r\n).
drawn() { sed 's/\r$//' "$1" | grep -q $'\r'; }

case_progress() {
  # Long enough (> 0.5 s) that a terminal gets a progress line.
  local cmd=("$bin" render --preset marble --size 480 --scale 8 --filter reference --reference-samples 64 --threads 1)
  "${cmd[@]}" -o "$out/p1.png" >"$work/o.txt" 2>"$work/e.txt" || fail "render: exit $?"
  [ -s "$work/e.txt" ] && fail "stderr is no terminal, yet: $(cat -A "$work/e.txt")"
  command -v script >/dev/null || { echo "no script(1): terminal checks skipped"; return; }
  # script(1) runs the command on a terminal; its stdout and stderr land in tty.txt.
  script -qec "$(printf '%q ' "${cmd[@]}") -o $out/p2.png" /dev/null >"$work/tty.txt" 2>&1 || fail "render on a terminal: exit $?"
  drawn "$work/tty.txt" || fail "render on a terminal drew no progress line: $(cat -A "$work/tty.txt")"
  grep -qE 'render: [0-9]+%  ETA' "$work/tty.txt" || fail "progress line lacks a percentage and ETA: $(cat -A "$work/tty.txt")"
  # The line is finished (100%, newline) before the report starts a line of its own.
  grep -qE $'render: 100%  done in [0-9]+s *\r$' "$work/tty.txt" || fail "progress line not finished: $(cat -A "$work/tty.txt")"
  tr '\r' '\n' <"$work/tty.txt" | grep -q '^wrote ' || fail "report glued to the progress line: $(cat -A "$work/tty.txt")"
  script -qec "$(printf '%q ' "${cmd[@]}") -o $out/p3.png --quiet" /dev/null >"$work/tty.txt" 2>&1 || fail "render --quiet: exit $?"
  drawn "$work/tty.txt" && fail "--quiet drew a progress line: $(cat -A "$work/tty.txt")"
  # --quiet belongs to stochtex: before the command's name too.
  script -qec "$(printf '%q ' "$bin") -q $(printf '%q ' "${cmd[@]:1}") -o $out/p4.png" /dev/null >"$work/tty.txt" 2>&1 || fail "-q before the command: exit $?"
  drawn "$work/tty.txt" && fail "-q before the command drew a progress line: $(cat -A "$work/tty.txt")"
  [ -s "$out/p4.png" ] || fail "-q before the command: p4.png not written"
}

declare -F "case_$name" >/dev/null || { echo "cli_test.sh: unknown case \"$name\""; exit 2; }
"case_$name"
if [ $failures -ne 0 ]; then
  echo "$failures check(s) of cli.$name failed"
  exit 1
fi
echo "all checks of cli.$name passed"
