// ColormapTable::sampleRow: a row of table lookups, the taps in SIMD lanes
// and the blends two pixels at a time (texel_pairs.h, which includes
// colormap.h, hence a file of its own).
#include <algorithm>
#include <cstring>

#include "stochtex/noise/tiling_blending_lanes.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/texel_pairs.h"

namespace stochtex {

namespace {

using Texel = ColormapTable::Texel;

// The blends of a row's taps (entry, tx, ty per pixel) in a table `width`
// entries wide, two pixels at a time (texel_pairs.h), each pair's entries
// prefetched kPrefetchAhead pixels before their blend when `prefetch`;
// tx and ty have two floats past count (splatPair). A pixel's result is
// stored as its four floats, its alpha on the next pixel's red, which that
// pixel's store overwrites next; the last pixel's three floats alone.
[[gnu::always_inline]] inline void blendTapsBody(const Texel* texels, size_t width, const int32_t* entry,
                                                 const float* tx, const float* ty, size_t count, bool prefetch,
                                                 float* rgb) {
    constexpr size_t kAhead = ColormapTable::kPrefetchAhead;
    size_t k = 0;
    for (; k + 1 < count; k += 2) {
        if (prefetch && k + 1 + kAhead < count) {
            ColormapTable::prefetchTexels(texels + entry[k + kAhead], width);
            ColormapTable::prefetchTexels(texels + entry[k + 1 + kAhead], width);
        }
        const texel_pairs::TexelPair c =
            texel_pairs::blendTexelPair(texels + entry[k], width, texels + entry[k + 1], width,
                                        texel_pairs::splatPair(tx + k), texel_pairs::splatPair(ty + k));
        const Texel first = texel_pairs::lowOf(c), second = texel_pairs::highOf(c);
        std::memcpy(rgb + 3 * k, &first, sizeof first);
        if (k + 2 < count)
            std::memcpy(rgb + 3 * k + 3, &second, sizeof second);
        else
            texel_pairs::storeRgb(second, rgb + 3 * k + 3);
    }
    if (k < count)
        texel_pairs::storeRgb(ColormapTable::blendTexels(texels + entry[k], width, tx[k], ty[k]), rgb + 3 * k);
}
STOCHTEX_AVX2_COMPILATION void blendTapsAvx2(const Texel* texels, size_t width, const int32_t* entry, const float* tx,
                                             const float* ty, size_t count, bool prefetch, float* rgb) {
    blendTapsBody(texels, width, entry, tx, ty, count, prefetch, rgb);
}
void blendTapsBaseline(const Texel* texels, size_t width, const int32_t* entry, const float* tx, const float* ty,
                       size_t count, bool prefetch, float* rgb) {
    blendTapsBody(texels, width, entry, tx, ty, count, prefetch, rgb);
}

}  // namespace

size_t ColormapTable::sampleRow(const float* x, const float* y, size_t stride, float* rgb, size_t count) const {
    // In chunks whose taps stay in L1 beside the table's lines.
    constexpr size_t kChunk = 256;
    int32_t entry[kChunk];
    // Two floats past the taps, as the pairs' weights are read four at a time (splatPair).
    float tx[kChunk + 2] = {}, ty[kChunk + 2] = {};
    size_t inLanes = 0;
    const bool prefetch = bytes() > kPrefetchedBytes;
    const auto blendTaps = texel_pairs::useAvx2Compilation() ? blendTapsAvx2 : blendTapsBaseline;
    for (size_t k0 = 0; k0 < count; k0 += kChunk) {
        const size_t n = std::min(kChunk, count - k0);
        const size_t lanes =
            tableTapsLanes(x + k0 * stride, y + k0 * stride, stride, width_, height_, n, entry, tx, ty);
        inLanes += lanes;
        blendTaps(rgba_.data(), size_t(width_), entry, tx, ty, lanes, prefetch, rgb + k0 * 3);
        for (size_t k = k0 + lanes; k < k0 + n; ++k) {
            const Rgb c = sample(x[k * stride], y[k * stride]);
            std::copy(c.begin(), c.end(), rgb + k * 3);
        }
    }
    return inLanes;
}

}  // namespace stochtex
