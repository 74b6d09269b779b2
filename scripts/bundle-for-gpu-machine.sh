#!/bin/bash
# Packs stochtex_bench and stochtex_tests with the shared libraries they need
# into DIR, for a GPU machine that lacks Debian's packages (the measurements
# in docs/measurements/ were taken this way). Debian's OpenCV imgcodecs pulls
# in GDAL and ~150 MB of libraries; the GPU benchmarks and parity tests do no
# image file IO, so a stand-in imgcodecs that throws is packed instead.
#
#   scripts/bundle-for-gpu-machine.sh DIR
#   (on the GPU machine, in the repository root)
#   LD_LIBRARY_PATH=DIR/lib DIR/bin/stochtex_bench --benchmark_filter=GpuShaderThroughput
#   LD_LIBRARY_PATH=DIR/lib DIR/bin/stochtex_tests --gtest_filter='Gpu.*:-Gpu.ShadersValidate*:Gpu.Gaussianized*'
#
# The machine needs glvnd's libEGL/libGL (Debian's libegl1, libglvnd0,
# libgl1, libglx0, libopengl0 unpacked with dpkg -x) beside its vendor driver.
set -euo pipefail
out=${1:?usage: $0 DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(mktemp -d)
trap 'rm -rf "$build"' EXIT
# --as-needed: only the libraries whose symbols are used become dependencies.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXE_LINKER_FLAGS=-Wl,--as-needed >/dev/null
cmake --build "$build" -j"$(nproc)" --target stochtex_bench stochtex_tests
mkdir -p "$out/bin" "$out/lib"
cp "$build/bin/stochtex_bench" "$build/bin/stochtex_tests" "$out/bin/"
strip "$out/bin/"*
cat > "$build/imgcodecs_standin.cpp" <<'CPP'
#include <opencv2/core.hpp>
#include <stdexcept>
namespace cv {
Mat imdecode(InputArray, int) { throw std::runtime_error("image decoding is not in the GPU-machine bundle"); }
bool imencode(const String&, InputArray, std::vector<uchar>&, const std::vector<int>&) {
    throw std::runtime_error("image encoding is not in the GPU-machine bundle");
}
}  // namespace cv
CPP
g++ -O1 -shared -fPIC -I/usr/include/opencv4 "$build/imgcodecs_standin.cpp" -o "$out/lib/libopencv_imgcodecs.so.406" \
    -Wl,-soname,libopencv_imgcodecs.so.406 -lopencv_core
# Every other library the two programs load (resolved with the stand-in, so
# GDAL's closure stays out), except glibc, libstdc++ and the GL dispatch
# libraries: the machine's own.
for bin in "$out/bin/"*; do LD_LIBRARY_PATH="$out/lib" ldd "$bin"; done | awk '/=> \//{print $3}' | sort -u |
    while read -r lib; do
        case $(basename "$lib") in
            libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|ld-linux*|libstdc++*|libgcc_s*|libGL*|libEGL*|libOpenGL*) ;;
            *) [[ $lib == "$out/lib/"* ]] || cp -L "$lib" "$out/lib/" ;;
        esac
    done
echo "bundle in $out ($(du -sh "$out" | cut -f1))"
