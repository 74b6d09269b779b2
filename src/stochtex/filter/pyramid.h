#pragma once
// MIP pyramids of footprint statistics of a noise example (paper eq. 10, 16).
//
// For a power-of-two example E (W = 2^L) and level l (texels of 2^l × 2^l):
//   E_l  = box average of E over the texel                      (means)
//   V_l  = mip_l(E²) − E_l²   = mean of (E − E_l)² over the texel (eq. 10)
//   C_l  = mip_l(E E') − E_l E'_l                               (eq. 16)
// Each level is built from the one below by the exact pairwise update of
// centred moments (Chan, Golub & LeVeque): for the four children i of a
// texel, E_{l+1} = avg E_{l,i} and
//   C_{l+1} = avg C_{l,i} + avg (E_{l,i} − E_{l+1})(E'_{l,i} − E'_{l+1}),
// so V_l and C_l are the exact footprint statistics of level 0, computed in
// float without the cancellation of mip(E²) − E_l² (docs/MATH.md). Level L
// is 1×1: the global mean / variance. Each level is stored once, as the
// interleaved (mean, moment) grid the lookups read. Levels 0–5 are built
// tile by tile (32² level-0 texels, in cache), the rest a level at a time,
// in parallel by rows of tiles or texels (the same floats for any thread
// count).
#include <vector>

#include "stochtex/noise/example.h"
#include "stochtex/noise/periodic_grid.h"

namespace stochtex {

class StatsPyramid {
public:
    StatsPyramid() = default;
    // Means and variances of one example.
    explicit StatsPyramid(const Image& example);
    // Covariances C_l of a pair of examples of the same size (the mean
    // channel then holds the first example's E_l).
    static StatsPyramid covariance(const Image& e, const Image& eprime);

    int levels() const { return int(grids_.size()); }  // L + 1
    // Level l as one grid of (mean, moment) pairs: moment = variance V_l, or
    // covariance C_l for a covariance pyramid. One lookup reads both.
    const BasicPeriodicGrid<2>& level(int l) const { return grids_[size_t(l)]; }
    // Texel (x, y) of level l.
    float mean(int l, int x, int y) const { return grids_[size_t(l)].texel(x, y)[0]; }
    float moment(int l, int x, int y) const { return grids_[size_t(l)].texel(x, y)[1]; }
    // Level l as one image for upload or export: channel 0 = mean, channel 1
    // = moment, any further channel 0 (channels in [2, 4]).
    Image interleavedLevel(int l, int channels) const;
    // Average of the moment over the whole example: the Deliot–Heitz
    // constant within-texel variance of level l.
    float averageMoment(int l) const { return averageMoment_[size_t(l)]; }

    // The paper's 8-bit storage (§5): means rounded to 1/255, moments stored
    // ×16 (variances stay below 0.05) and rounded to 1/255, i.e. steps of
    // 1/4080. Negative moments (covariances) are clamped to 0 by 8-bit unorm,
    // so only variance pyramids should be packed.
    StatsPyramid quantized8() const;

    // Bytes held by the lookup grids (floats, padded).
    size_t bytes() const;

private:
    // Levels 0..L from level 0 of (a, b): a's means, and b's where it is
    // another example (nullptr: b = a).
    void build(const Image& a, const Image* b);
    std::vector<BasicPeriodicGrid<2>> grids_;
    std::vector<float> averageMoment_;
};

// True for 1, 2, 4, 8, ...
inline bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

}  // namespace stochtex
