#pragma once
// Two RGBA texels side by side in one 32-byte vector of the GCC extension
// (AVX: one register), for the table loops that blend two lookups at once:
// the same tap of two layers of a prefiltered table, or two pixels' taps
// of one colour table. Private to pattern/.
//
// Such a loop is compiled twice, for AVX2 (a vector in one register) and
// for the baseline (two halves), and the AVX2 compilation runs where the
// lanes' dispatched target has at least 8 float lanes, so the tests that
// force Highway's targets one by one (tests/lane_targets.h) run the
// baseline compilation too. Both do the same IEEE multiplies and adds per
// lane (no FMA): their results are bit-identical on every machine. (GCC's
// target_clones would choose by the CPU alone, leaving the baseline
// untested on an AVX2 machine.)
//
// The helpers are always inlined, never called, so GCC's warning that a
// call would pass 32-byte vectors differently without AVX concerns none;
// it is off for the including file, since GCC reports it at the file's end.
#include <cstring>

#include "stochtex/noise/tiling_blending_lanes.h"
#include "stochtex/pattern/colormap.h"

#pragma GCC diagnostic ignored "-Wpsabi"

namespace stochtex::texel_pairs {

#if defined(__x86_64__) && !defined(__clang__)
#define STOCHTEX_AVX2_COMPILATION __attribute__((target("avx2")))
constexpr bool kHasAvx2Compilation = true;
#else
#define STOCHTEX_AVX2_COMPILATION
constexpr bool kHasAvx2Compilation = false;
#endif
inline bool useAvx2Compilation() { return kHasAvx2Compilation && laneTargetFloatLanes() >= 8; }

using Texel = ColormapTable::Texel;
typedef float TexelPair __attribute__((vector_size(32)));
[[gnu::always_inline]] inline TexelPair pairOf(Texel low, Texel high) {
    return __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7);
}
[[gnu::always_inline]] inline TexelPair pairOf(float low, float high) {
    return pairOf(Texel{low, low, low, low}, Texel{high, high, high, high});
}
[[gnu::always_inline]] inline Texel lowOf(TexelPair p) { return __builtin_shufflevector(p, p, 0, 1, 2, 3); }
[[gnu::always_inline]] inline Texel highOf(TexelPair p) { return __builtin_shufflevector(p, p, 4, 5, 6, 7); }

// A texel's RGB at rgb[0..2], touching nothing past them.
[[gnu::always_inline]] inline void storeRgb(const Texel& c, float* rgb) {
    typedef float Float2 __attribute__((vector_size(8)));
    const Float2 rg = __builtin_shufflevector(c, c, 0, 1);
    std::memcpy(rgb, &rg, sizeof rg);
    rgb[2] = c[2];
}

// {w[0] ×4, w[1] ×4}: two lookups' weights, one a texel. Reads w[0..3]
// (one 16-byte load: GCC routes a narrower one through the stack).
[[gnu::always_inline]] inline TexelPair splatPair(const float* w) {
    Texel four;
    std::memcpy(&four, w, sizeof four);
    return __builtin_shufflevector(four, four, 0, 0, 0, 0, 1, 1, 1, 1);
}

// ColormapTable::blendTexels of two lookups at once: a's lower corner at a
// (its rows wa texels apart), b's at b; tx their x weights (a's in the low
// texel, b's in the high one), ty their y weights, a pair likewise or one
// float both share.
template <class Y>
[[gnu::always_inline]] inline TexelPair blendTexelPair(const Texel* a, size_t wa, const Texel* b, size_t wb,
                                                       TexelPair tx, Y ty) {
    return ColormapTable::rowsFirst(pairOf(a[0], b[0]), pairOf(a[1], b[1]), pairOf(a[wa], b[wb]),
                                    pairOf(a[wa + 1], b[wb + 1]), tx, ty);
}

}  // namespace stochtex::texel_pairs
