#pragma once
// Estimators of the mean and covariance of a tiled-and-blended noise vector
// field N = (N_x, N_y) over a pixel footprint, in constant time (paper §4).
//
// For one texel footprint P at level l (weights w_i taken at its centre):
//   N̂_l    = μ + Σ w_i (E_{l,i} − μ)          (eq. 8, mean-centred as eq. 7)
//   σ̂²_l   = Σ w_i² V_{l,i}                    (eq. 12)
//   ĉov_l  = Σ w_i² C_{l,i}   (shared offsets; 0 for independent tiles, eq. 17)
// and for a footprint made of weighted texel footprints (probes × trilinear):
//   μ̂ = Σ w_P N̂,  σ̂² = Σ w_P (N̂² + σ̂²_l) − μ̂²,  ĉov = Σ w_P (N̂ N̂' + ĉov_l) − μ̂ μ̂'
// (eq. 9, 14–15, 18–19). The Deliot–Heitz baseline replaces σ̂²_l by the
// level's average within-texel variance (one constant per LOD).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>

#include "stochtex/core/enum_names.h"
#include "stochtex/filter/footprint.h"
#include "stochtex/filter/pyramid.h"
#include "stochtex/filter/variance_estimator.h"
#include "stochtex/kernel/estimate.h"
#include "stochtex/noise/tiled_field.h"

namespace stochtex {

// Mean and covariance of N over a footprint.
struct FootprintStats {
    std::array<float, 2> mean{};
    float varX = 0, varY = 0, cov = 0;
    float sigmaX() const { return std::sqrt(std::max(varX, 0.0f)); }
    float sigmaY() const { return std::sqrt(std::max(varY, 0.0f)); }
};

class FootprintEstimator {
public:
    // field: two channels (N_x, N_y) whose examples are power-of-two sized.
    // covariance: estimate within-texel covariances from the C_l pyramid
    // (eq. 16–17), which needs a Shared field (InputError `covariance`
    // otherwise); without it they are 0 and the pyramid is not built.
    // pack8: store the mean/variance pyramids with the paper's 8-bit packing.
    FootprintEstimator(const TiledField& field, bool covariance, bool pack8 = false);

    int exampleSize() const { return size_; }
    int maxLod() const { return pyramids_[0].levels() - 1; }

    // μ̂, σ̂², ĉov over the footprint: the kernel's loop (footprintEstimate),
    // or for a single texel (one probe at a whole level: every pixel of a
    // zoom at a power-of-two scale, every magnified pixel; with sub-probes,
    // only a magnified pixel or one at the top level) that texel's
    // statistics directly, which the loop also returns after sums it then
    // drops. kernelEstimate is the loop alone; a test holds the two bit-exact.
    FootprintStats estimate(const Footprint& f, VarianceEstimator mode = VarianceEstimator::Paper) const;
    FootprintStats kernelEstimate(const Footprint& f, VarianceEstimator mode = VarianceEstimator::Paper) const;

    // Statistics of one texel footprint at an integer level (eq. 8, 12, 17).
    using TexelStats = kernel::TexelStats;
    TexelStats texel(double u, double v, int level, VarianceEstimator mode) const;
    // The texel statistics of a probe at uv on levels.l0 and, when its
    // weight is > 0, levels.l1 (the stencil and tile offsets are shared: w_i
    // is taken at the probe centre on every level), with the paper's
    // variances; the kernel's loop (kernel/estimate.glsl) calls it.
    kernel::ProbeTexels probeTexels(kernel::coord2 uv, const kernel::ProbeLevels& levels) const;
    // The level's average within-texel variances and covariance [DH19].
    kernel::vec3 levelAverages(int level) const;

    size_t bytes() const;

    // The statistics pyramids (for uploading to the GPU): means and
    // variances of each noise, and the covariances when offsets are shared.
    const StatsPyramid& pyramid(int axis) const { return pyramids_[size_t(axis)]; }
    const StatsPyramid* covariancePyramid() const { return covariance_.get(); }

private:
    std::array<TilingBlendingNoise, 2> noises_;
    std::array<StatsPyramid, 2> pyramids_;
    std::unique_ptr<StatsPyramid> covariance_;
    GridLayout grid_;
    int size_;
    uint64_t id_;  // identifies this estimator's entries in the per-thread tile cache
};

}  // namespace stochtex

namespace stochtex {
// Exact statistics of N over the parallelogram footprint uv + J·(s, t),
// s, t ∈ [−½, ½], by dense sampling: an n×n grid of cell centres with
// n = clamp(⌈2·(largest side in texels)⌉, minPerAxis, maxPerAxis) — two
// samples per texel of the bilinearly interpolated noise, 8 at least by
// default. Values are in blending space.
FootprintStats bruteForceStats(const TiledField& field, double u, double v, const Jacobian& j, int maxPerAxis = 512,
                               int minPerAxis = 8);
// Samples per axis bruteForceStats uses for this Jacobian (maxPerAxis is
// raised to minPerAxis where it is below).
int bruteForceSamples(const Jacobian& j, int exampleSize, int maxPerAxis, int minPerAxis = 8);
}  // namespace stochtex
