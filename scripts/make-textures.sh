#!/usr/bin/env bash
# Regenerates data/textures/: small textures made by stochtex itself (no
# downloads), the base images of `stochtex fractalize` (thesis Figures
# 2.15–2.17). Three are periodic noise examples (they wrap, as a lattice
# should), from stochastic to regular; one is a colour pattern render (it
# does not wrap, and is converted to gray by the thesis's luminosity formula).
#
#   scripts/make-textures.sh [BIN] [OUT]   # BIN: the stochtex binary (build/bin/stochtex), OUT: data/textures
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/bin/stochtex}
out=${2:-data/textures}
mkdir -p "$out"
# stone: isotropic low-pass noise, rich in low frequencies (the thesis's iron / stone).
"$bin" noise '{"type":"spectrum","size":128,"seed":11,"components":[{"shape":"lowpass","cutoff":12},{"shape":"ring","frequency":40,"bandwidth":30,"weight":0.5}]}' -o "$out/stone.png" >/dev/null
# wood: an anisotropic bi-lobe noise, grain along one direction.
"$bin" noise '{"type":"spectrum","size":128,"seed":12,"components":[{"shape":"bilobe","frequency":10,"bandwidth":3,"orientation":80}]}' -o "$out/wood.png" >/dev/null
# cells: a narrow ring, a near-regular cellular structure (the thesis's pebbles / bricks: regular ones ghost).
"$bin" noise '{"type":"spectrum","size":128,"seed":13,"components":[{"shape":"ring","frequency":12,"bandwidth":1}]}' -o "$out/cells.png" >/dev/null
# weld: a colour pattern (a preset), rendered.
"$bin" render --preset weld --size 128 --scale 2 -o "$out/weld.png" >/dev/null
echo "wrote $(ls "$out"/*.png | tr '\n' ' ')"
