#pragma once
// The mapping of output pixels to texture space that every unfiltered
// render and the zoom camera use, and the caps on an output's size. Its own
// unit, below the pattern file's parser and every evaluator, so both can
// speak of a view without including each other.

#include <array>

#include "stochtex/core/enum_names.h"
#include "stochtex/kernel/camera.h"

namespace stochtex {

constexpr int kMaxOutputSide = 16384;
constexpr long long kMaxOutputPixels = 8192LL * 8192LL;
// A view rendered in bands of rows (bake-image, Renderer.bake, a
// distributed bake) holds one band at a time, rendered in tiles of at most
// kMaxOutputSide columns (renderRows): its sides are capped by the image
// files it is written to (PNG and EXR here, 65536), its pixels not at all,
// and a band by kMaxBandPixels (bandRows).
constexpr int kMaxBakedSide = 65536;
constexpr long long kMaxBandPixels = 16384LL * 256;
enum class ViewUse { Render, BandedBake };
// The scales (example texels per output pixel) a view may have. Above 1e6 a
// pixel covers a 4096² example 244 times over; below 1e-6 a 16384-pixel
// image spans a sixtieth of a texel, and a scale near the smallest double
// rounds every pixel's uv to the same point (a zero-sized footprint).
constexpr double kMinViewScale = 1e-6, kMaxViewScale = 1e6;
struct ParamInfo;
// A view's scale as a parameter entry: the range above, default 1.
// validateView checks by it; the pattern file's "scale" is it with a drag
// range (patternMembers). (The commands' --scale, "default: the pattern's",
// is still declared by hand.)
const ParamInfo& viewScaleParam();

// Maps output pixels to texture space: pixel (px, py) covers example texels
// offset + (p + ½)·scale, i.e. uv = (offset + (p + ½)·scale) / W (pixelUv).
struct View {
    int width = 512, height = 512;
    double scale = 1.0;               // example texels per output pixel
    double offsetU = 0, offsetV = 0;  // in example texels
};

// uv of the centre of pixel (px, py), invW = 1/W: the kernel's zoomUv
// (kernel/camera.glsl), the mapping the shaders use, in double.
inline std::array<double, 2> pixelUv(const View& view, double invW, int px, int py) {
    const kernel::coord2 uv = kernel::zoomUv(kernel::coord2(px + 0.5, py + 0.5),
                                             kernel::coord2(view.offsetU, view.offsetV), view.scale, invW);
    return {uv.x, uv.y};
}

// Which CPU code evaluates the pixels (issue 33): the SIMD lanes, or the
// scalar kernel — the reference they are tested against, one pixel at a
// time, which the tests and benchmarks compare them with.
enum class CpuKernel { Simd, Scalar };
inline const EnumNames<CpuKernel> kCpuKernelNames{{"simd", CpuKernel::Simd}, {"scalar", CpuKernel::Scalar}};

// The view of the same uv for a program whose first example has
// `toExampleSize` texels, `view` being for one of `fromExampleSize` (a
// view's scale and offset are in texels of its program's example).
inline View sameUvView(View view, int fromExampleSize, int toExampleSize) {
    const double texels = double(toExampleSize) / double(fromExampleSize);
    view.scale *= texels;
    view.offsetU *= texels;
    view.offsetV *= texels;
    return view;
}

// Checks a view against the output caps; InputError::parameter naming size,
// scale or offset otherwise.
void validateView(const View& view, ViewUse use = ViewUse::Render);

}  // namespace stochtex
