#pragma once
// Tiling and blending of a row of pixels in SIMD lanes (issue 33: the
// evaluator near the gather limit). The pixels of a zoom row share v, so
// the row is split once into the triangle grid's cells (in double lanes, as
// TriangleGridRow does per pixel) and every leaf is then blended a vector of
// pixels at a time: stencil, vertex hashes, tile offsets, the texels of
// each tile's bilinear lookup (each lane's adjacent floats loaded and
// transposed, or gathered), eq. 7 and T⁻¹ — each
// the kernel's formula (kernel/grid.glsl, hash.glsl, lookup.glsl) in its
// order of operations, written in Highway ops and dispatched at run time to
// the widest vectors the CPU has (SSSE3, SSE4, AVX2, AVX-512; a one-lane
// fallback elsewhere). A vector whose lanes all see one triangle (four in
// five at one texel a pixel, where a tile spans tens of pixels; fewer
// zoomed out) takes its tiles from the scalar kernel, each lattice vertex's
// hashed once per row, and keeps them while they last. The
// scalar kernel stays the reference: tests/noise/ holds the lanes to
// TilingBlendingNoise::blend within 1e-5 (on AVX2 they are bit-identical).
#include <cstdint>
#include <vector>

#include "stochtex/noise/tiling_blending.h"

namespace stochtex {

// A row's arrays are padded to whole vectors of the widest target
// (AVX-512: 16 floats), so a lane loop never needs a tail.
constexpr int kMaxFloatLanes = 16;
inline int paddedLaneCount(int count) { return (count + kMaxFloatLanes - 1) / kMaxFloatLanes * kMaxFloatLanes; }

// The triangle grid along one row of pixels: pixel p at
// u = (offset + (p + ½)·scale)·invW (kernel::zoomUv, in double) and the
// row's v.
struct GridRowLanes {
    // Fills the arrays for pixels 0..count−1 (and the padding lanes past them).
    // `grid` on the plane (a periodic grid's vertices are reduced by the
    // scalar kernel only: std::logic_error).
    void compute(double offset, double scale, double invW, double v, int count, const GridLayout& grid = GridLayout{});
    int count = 0;
    // Per pixel: the cell's x id (wrapped to 32 bits), the fraction of the
    // skewed x in it, and u reduced to one period (periodFraction).
    std::vector<uint32_t> cellX;
    std::vector<float> fx, fu;
    // Per row: the cell's y id, the fraction of the skewed y, v reduced to one period.
    uint32_t cellY = 0;
    float fy = 0, fv = 0;
};

// N(u) in the noise's output space (T⁻¹ applied for a Gaussianized
// exemplar) at every pixel of the row: out[p] for p < paddedLaneCount(row.count).
void blendRowLanes(const TilingBlendingNoise& noise, const GridRowLanes& row, float* out);
// The same in the example's own space (no T⁻¹): the means of level 0 of
// the noise's statistics pyramid, the example's texels (their variances
// are 0), as the filtered zoom reads them at one texel per pixel.
void blendExampleRowLanes(const TilingBlendingNoise& noise, const GridRowLanes& row, float* out);

// Eq. 8 and 12 on a level of the noise's statistics pyramid (mean and
// variance per texel, filter/pyramid.h) at every pixel of the row: N̂_l and
// σ̂²_l with the stencil at the pixel, as FootprintEstimator::probeTexels
// computes them for one texel footprint.
void blendRowLanes(const TilingBlendingNoise& noise, const BasicPeriodicGrid<2>& level, const GridRowLanes& row,
                   float* mean, float* variance);
// The same on two levels at once (a zoom between levels): the stencil and
// the tiles' hashes computed once for both.
void blendRowLanes(const TilingBlendingNoise& noise, const BasicPeriodicGrid<2>& lower,
                   const BasicPeriodicGrid<2>& upper, const GridRowLanes& row, float* meanLower, float* varianceLower,
                   float* meanUpper, float* varianceUpper);

// kernel::tableTap in lanes for a 2D table lookup at each of the values
// x[k·stride], y[k·stride] (stride 1 or 3: the first channel of vec3 rows)
// in a width × height table (both ≥ 2): entry[k] = j·width + i of the lower
// corner and its weights tx[k], ty[k]. Fills whole vectors only and returns
// how many values it did (the caller taps the rest with the kernel); reads
// nothing past the last value it fills (with stride 3, its vec3).
size_t tableTapsLanes(const float* x, const float* y, size_t stride, int width, int height, size_t count,
                      int32_t* entry, float* tx, float* ty);

// The lookups of a prefiltered colormap whose two axes are Gaussian, in
// lanes: kernel::tableLayerBlend at the means (mx, my) and deviations
// (sx, sy) of count pixels, then kernel::tableTap on each axis of the
// layers it blends. Layer (kx, ky) of the table is widths[kx] × heights[ky]
// entries (both ≥ 2; PrefilteredColormap stores a layer coarser along an
// axis as that axis's σ grows). Per pixel k: the layers (kx0, ky0) and
// (kx1, ky1) and the weights fx, fy of kx1 and ky1 (kernel::levelBlend);
// the x taps (entry, weight) in the columns kx0 and kx1, the y taps in the
// rows ky0 and ky1.
// Arrays of a fixed size in one object, so a loop over its pixels
// addresses every field from one register (fourteen pointers of their own
// would not stay in registers).
struct LayerTapsLanes {
    static constexpr size_t kCapacity = 256;  // pixels per call
    alignas(64) std::array<int32_t, kCapacity> kx0, ky0, kx1, ky1, ix0, ix1, iy0, iy1;
    alignas(64) std::array<float, kCapacity> fx, fy, tx0, tx1, ty0, ty1;
    // The same taps as a blend reads them, so that it does no index
    // arithmetic of its own: each corner's layer (kx · levels + ky) and
    // entry in it (row · width + column), for (x0, y0), (x1, y0), (x0, y1)
    // and (x1, y1); the widths of columns kx0 and kx1 (the rows' strides);
    // and layer (kx0, ky0)'s entry count.
    alignas(64) std::array<int32_t, kCapacity> layer00, layer10, layer01, layer11;
    alignas(64) std::array<int32_t, kCapacity> entry00, entry10, entry01, entry11;
    alignas(64) std::array<int32_t, kCapacity> width0, width1, entries00;
};
// Fills whole vectors only and returns how many pixels it did (the caller
// does the rest with the kernel); count ≤ kCapacity, levels ≥ 1. The paper mode's level is
// read off the float's exponent, as the kernel does, and is the kernel's
// exactly; the smooth mode's log2 takes the exponent from the float too
// (exact at the levels) and the log2 of the mantissa from Highway, so a
// level weight between levels may differ from the kernel's by a few ulps.
size_t layerTapsLanes(const float* mx, const float* my, const float* sx, const float* sy, size_t count, bool paper,
                      int levels, const int32_t* widths, const int32_t* heights, LayerTapsLanes& out);

// One probe's footprint moments over its two levels, along one axis, at
// each of count pixels, and the prefiltered table's coordinates from them:
// the kernel's momentsResult(momentsAddProbe(momentsAbout(lo's mean), …))
// with the level weights w0, w1 (kernel::ProbeLevels; l1 is read where
// w1 > 0), then mean[k] = μ̂ and sigma[k] = momentSigma of σ̂² clamped at
// 0, as a plain program's lookup reads them — the kernel's operations in
// its order, so its values bit for bit. Does whole vectors only and
// returns how many pixels it did.
size_t probeMomentsLanes(const float* meanLo, const float* varLo, const float* meanHi, const float* varHi, float w0,
                         float w1, size_t count, float* mean, float* sigma);

// The name of the vector target the lanes run on here ("AVX2", …).
const char* laneTargetName();
// The floats in one of its vectors (AVX2: 8; the one-lane fallback: 1).
size_t laneTargetFloatLanes();

}  // namespace stochtex
