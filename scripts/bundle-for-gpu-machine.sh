#!/bin/bash
# Packs stochtex_bench (and with BUNDLE_TESTS=1 stochtex_tests) with the
# shared libraries they need into DIR, for a GPU machine that lacks Debian's
# packages (the measurements in docs/measurements/ were taken this way).
# stochtex_tests links FFmpeg, plplot and pango directly (~150 MB with their
# closures): pack it only where the machine's call carries that much.
#
#   scripts/bundle-for-gpu-machine.sh DIR [BASE_COMMIT]
#
# With BASE_COMMIT, that commit's stochtex_bench is built too (in a git
# worktree) and packed as bin/stochtex_bench_base, so that old and new can be
# timed in turn on the GPU machine (scripts/gpu-machine-compare.sh). With
# BUNDLE_BUILD=PATH, an existing build folder configured with
# -DCMAKE_EXE_LINKER_FLAGS=-Wl,--as-needed is reused for the current tree,
# and with BUNDLE_BASE_BUILD=PATH one of BASE_COMMIT's tree for the base.
#
#   (on the GPU machine, in the repository root)
#   LD_LIBRARY_PATH=DIR/lib DIR/bin/stochtex_bench --benchmark_filter=GpuShaderThroughput
#   LD_LIBRARY_PATH=DIR/lib DIR/bin/stochtex_tests --gtest_filter='Gpu.*:-Gpu.ShadersValidate*:Gpu.Gaussianized*'
#   (BUNDLE_TESTS=1)
#
# The machine needs glvnd's libEGL/libGL (Debian's libegl1, libglvnd0,
# libgl1, libglx0, libopengl0 unpacked with dpkg -x) beside its vendor driver.
set -euo pipefail
out=${1:?usage: $0 DIR [BASE_COMMIT]}
base=${2:-}
root=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
cleanup() {
    [[ -z $base ]] || git -C "$root" worktree remove --force "$scratch/base-tree" 2>/dev/null || true
    rm -rf "$scratch"
}
trap cleanup EXIT
# --as-needed: only the libraries whose symbols are used become dependencies.
configure() { cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXE_LINKER_FLAGS=-Wl,--as-needed >/dev/null; }
build=${BUNDLE_BUILD:-$scratch/build}
[[ -n ${BUNDLE_BUILD:-} ]] || configure "$root" "$build"
programs=(stochtex_bench)
[[ ${BUNDLE_TESTS:-0} == 0 ]] || programs+=(stochtex_tests)
cmake --build "$build" -j"$(nproc)" --target "${programs[@]}"
mkdir -p "$out/bin" "$out/lib"
for p in "${programs[@]}"; do cp "$build/bin/$p" "$out/bin/"; done
if [[ -n $base ]]; then
    base_build=${BUNDLE_BASE_BUILD:-$scratch/base-build}
    if [[ -z ${BUNDLE_BASE_BUILD:-} ]]; then
        git -C "$root" worktree add --detach "$scratch/base-tree" "$base" >/dev/null
        configure "$scratch/base-tree" "$base_build"
    fi
    cmake --build "$base_build" -j"$(nproc)" --target stochtex_bench
    cp "$base_build/bin/stochtex_bench" "$out/bin/stochtex_bench_base"
    git -C "$root" rev-parse "$base" >"$out/base_commit"
fi
git -C "$root" rev-parse HEAD >"$out/commit"
strip "$out/bin/"*
# OpenCV's image-file and video modules pull in GDAL, FFmpeg and their
# codecs (~200 MB, over what a device call carries); the GPU benchmarks and
# parity tests read and write no files, so each is packed as a stand-in that
# exports the symbols the programs import from it, each aborting with its
# name if called. (The symbols are unversioned, so the loader takes them.)
for module in imgcodecs videoio; do
    real=$(ldconfig -p | awk -v l="libopencv_$module.so.406" '$1 == l {print $NF; exit}')
    stub=$scratch/$module.c
    echo '#include <stdio.h>
#include <stdlib.h>
static void absent(const char* s) { fprintf(stderr, "%s: not in the GPU-machine bundle\n", s); abort(); }' >"$stub"
    comm -12 <(for bin in "$out/bin/"*; do nm -D --undefined-only "$bin" | awk '{print $2}'; done | sort -u) \
        <(nm -D --defined-only "$real" | awk '{print $3}' | sort -u) |
        awk '{printf "void s%d(void) __asm__(\"%s\");\nvoid s%d(void) { absent(\"%s\"); }\n", NR, $1, NR, $1}' >>"$stub"
    gcc -O1 -shared -fPIC "$stub" -o "$out/lib/libopencv_$module.so.406" -Wl,-soname,"libopencv_$module.so.406"
done
# Every other library the programs load (resolved with the stand-ins, so
# their closures stay out), except glibc, libstdc++ and the GL dispatch
# libraries: the machine's own.
lib=$(cd "$out/lib" && pwd)
for bin in "$out/bin/"*; do LD_LIBRARY_PATH="$lib" ldd "$bin"; done | awk '/=> \//{print $3}' | sort -u |
    while read -r l; do
        case $(basename "$l") in
            libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|ld-linux*|libstdc++*|libgcc_s*|libGL*|libEGL*|libOpenGL*) ;;
            *) [[ $l == "$lib/"* ]] || cp -L "$l" "$lib/" ;;
        esac
    done
echo "bundle in $out ($(du -sh "$out" | cut -f1))"
