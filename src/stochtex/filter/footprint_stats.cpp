#include "stochtex/filter/footprint_stats.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/kernel/moments.h"

namespace stochtex {

static std::atomic<uint64_t> nextEstimatorId{1};

FootprintEstimator::FootprintEstimator(const TiledField& field, bool covariance, bool pack8)
    : grid_(field.grid()), size_(field.exampleSize()), id_(nextEstimatorId++) {
    if (field.channelCount() != 2)
        throw InputError::parameter("field",
                                    "must have 2 channels (N_x, N_y), got " + std::to_string(field.channelCount()));
    if (covariance && !field.shared())
        throw InputError::parameter("covariance",
                                    "needs a field with shared offsets (tiles of N_x and N_y independent)");
    noises_ = {field.channel(0), field.channel(1)};
    for (size_t a = 0; a < 2; ++a) {
        pyramids_[a] = StatsPyramid(noises_[a].example().values());
        if (pack8) pyramids_[a] = pyramids_[a].quantized8();
    }
    if (covariance)
        covariance_ = std::make_unique<StatsPyramid>(
            StatsPyramid::covariance(noises_[0].example().values(), noises_[1].example().values()));
}

namespace {

// The kernel's texel source on the CPU (kernel/estimate.glsl): the
// estimator's pyramids. Found by argument-dependent lookup from
// kernel::footprintEstimate.
struct EstimatorTexels {
    const FootprintEstimator* estimator;
};
[[gnu::always_inline]] inline kernel::ProbeTexels probeTexels(EstimatorTexels s, kernel::coord2 uv,
                                                              kernel::ProbeLevels levels) {
    return s.estimator->probeTexels(uv, levels);
}
inline kernel::vec3 levelAverages(EstimatorTexels s, int level) { return s.estimator->levelAverages(level); }

}  // namespace

FootprintEstimator::TexelStats FootprintEstimator::texel(double u, double v, int level, VarianceEstimator mode) const {
    kernel::ProbeLevels one{};
    one.l0 = one.l1 = level;
    one.w0 = 1.0f;
    TexelStats t = probeTexels(kernel::coord2(u, v), one).lo;
    if (mode == VarianceEstimator::DeliotHeitz)
        t = kernel::deliotHeitzTexel(t, levelAverages(level), bool(covariance_));
    return t;
}

kernel::vec3 FootprintEstimator::levelAverages(int level) const {
    return kernel::vec3(pyramids_[0].averageMoment(level), pyramids_[1].averageMoment(level),
                        covariance_ ? covariance_->averageMoment(level) : 0.0f);
}

kernel::ProbeTexels FootprintEstimator::probeTexels(kernel::coord2 uv, const kernel::ProbeLevels& levels) const {
    const double u = uv.x, v = uv.y;
    // Probes of neighbouring pixels often share v (a zoom's scanline): the
    // grid row and v's period fraction are then reused (pure memoisation).
    struct RowMemo {
        double v = std::numeric_limits<double>::quiet_NaN();
        GridLayout grid;
        TriangleGridRow row{0.0, GridLayout{}};
        float fv = 0;
    };
    thread_local RowMemo memo;
    if (!(memo.v == v && memo.grid == grid_)) memo = RowMemo{v, grid_, TriangleGridRow(v, grid_), periodFraction(v)};
    const BlendStencil s = memo.row.stencil(u);
    const float fu = periodFraction(u), fv = memo.fv;
    // Neighbouring pixels mostly see the same tiles on the same scanline:
    // each thread remembers, per level modulo 4, the last tiles' rows (their
    // offsets hashed, their rows located) and reuses them when nothing they
    // depend on changed. Pure memoisation: results are identical. A slot per
    // level, not per trilinear half: the sub-probes with fine means read
    // three consecutive levels in turn (their squares' two, the finer one),
    // which two slots would rehash at every read.
    struct Slot {
        uint64_t owner = 0;  // FootprintEstimator::id_ (addresses can be reused)
        kernel::uvec2 cell{0u, 0u};
        bool upper = false;
        int level = -1;
        float fv = -1.0f;
        std::array<TilingBlendingNoise::TileRows, 3> rows;  // noise x, noise y, covariance
    };
    thread_local std::array<Slot, 4> cache;
    // The tiles' offsets depend on the triangle alone, not on v or the
    // level: a footprint's sub-probes, each at its own v, mostly share it.
    struct OffsetMemo {
        uint64_t owner = 0;
        kernel::uvec2 cell{0u, 0u};
        bool upper = false;
        std::array<TilingBlendingNoise::Offsets, 2> offsets;
    };
    thread_local OffsetMemo offsetMemo;
    kernel::ProbeTexels out{};
    const int count = levels.w1 > 0.0f ? 2 : 1;
    for (int k = 0; k < count; ++k) {
        const int level = k == 0 ? levels.l0 : levels.l1;
        TexelStats& t = k == 0 ? out.lo : out.hi;
        Slot& slot = cache[size_t(level) & 3u];
        if (slot.owner != id_ || slot.level != level || slot.fv != fv || slot.cell != s.cell || slot.upper != s.upper) {
            if (offsetMemo.owner != id_ || offsetMemo.cell != s.cell || offsetMemo.upper != s.upper) {
                for (size_t a = 0; a < 2; ++a) offsetMemo.offsets[a] = noises_[a].offsets(s);
                offsetMemo.owner = id_;
                offsetMemo.cell = s.cell;
                offsetMemo.upper = s.upper;
            }
            for (size_t a = 0; a < 2; ++a)
                slot.rows[a] = noises_[a].tileRows(offsetMemo.offsets[a], fv, pyramids_[a].level(level));
            if (covariance_) slot.rows[2] = noises_[0].tileRows(offsetMemo.offsets[0], fv, covariance_->level(level));
            slot.owner = id_;
            slot.cell = s.cell;
            slot.upper = s.upper;
            slot.level = level;
            slot.fv = fv;
        }
        for (size_t a = 0; a < 2; ++a) {
            const TilingBlendingNoise& noise = noises_[a];
            const BasicPeriodicGrid<2>& grid = pyramids_[a].level(level);
            // One lookup per tile reads E_l and V_l together.
            const auto e = noise.tileValues<2>(slot.rows[a], fu, grid);
            // Eq. 8: the same blend as the unfiltered noise, on level l;
            // eq. 12: tiles assumed uncorrelated, weights constant over P.
            t.mean[int(a)] = TilingBlendingNoise::mix<2>(s, e, noise.example().mean(), 0);
            t.var[int(a)] = kernel::blendVariance(s.w, TilingBlendingNoise::channel<2>(e, 1));
        }
        t.cov = 0.0f;
        if (covariance_) {
            const auto c = noises_[0].tileValues<2>(slot.rows[2], fu, covariance_->level(level));
            t.cov = kernel::blendVariance(s.w, TilingBlendingNoise::channel<2>(c, 1));  // eq. 17
        }
    }
    return out;
}

// flatten: inlining the texel fetches and the lookups into the per-pixel
// call cuts its instructions by ~12% (measured with callgrind).
__attribute__((flatten)) FootprintStats FootprintEstimator::estimate(const Footprint& f, VarianceEstimator mode) const {
    // The single texel's shortcut skips the loop's sums (10 % of a paper
    // zoom's render time at scale 8; docs/PERFORMANCE.md).
    const kernel::ProbeLevels levels = kernel::probeLevels(f.layout.lod, maxLod(), f.layout.count);
    if (kernel::isSingleTexel(f.layout.count, levels.frac) &&
        kernel::subProbesPerSide(f.layout, subProbesOf(mode), maxLod()) == 1) {
        const kernel::FootprintMoments r = kernel::texelMoments(texel(f.u, f.v, levels.l0, mode));
        return FootprintStats{{r.mean.x, r.mean.y}, r.var.x, r.var.y, r.cov};
    }
    return kernelEstimate(f, mode);
}

__attribute__((flatten)) FootprintStats FootprintEstimator::kernelEstimate(const Footprint& f,
                                                                           VarianceEstimator mode) const {
    // The loop, the Deliot–Heitz substitution and the single-texel rule are
    // the kernel's (kernel/estimate.glsl), as in the shaders.
    const kernel::FootprintMoments r = kernel::footprintEstimate(
        EstimatorTexels{this}, kernel::coord2(f.u, f.v), f.layout, maxLod(), mode == VarianceEstimator::DeliotHeitz,
        bool(covariance_), subProbesOf(mode), fineMeansOf(mode));
    return FootprintStats{{r.mean.x, r.mean.y}, r.var.x, r.var.y, r.cov};
}

size_t FootprintEstimator::bytes() const {
    return pyramids_[0].bytes() + pyramids_[1].bytes() + (covariance_ ? covariance_->bytes() : 0);
}

}  // namespace stochtex

namespace stochtex {

int bruteForceSamples(const Jacobian& j, int exampleSize, int maxPerAxis, int minPerAxis) {
    const double side = exampleSize * std::max(std::hypot(j.dudx, j.dvdx), std::hypot(j.dudy, j.dvdy));
    const int lo = std::max(1, minPerAxis), hi = std::max(lo, maxPerAxis);
    // (The side is capped before the cast, so that no Jacobian overflows int.)
    return std::clamp(int(std::ceil(2.0 * std::min(1e6, side))), lo, hi);
}

FootprintStats bruteForceStats(const TiledField& field, double u, double v, const Jacobian& j, int maxPerAxis,
                               int minPerAxis) {
    const std::array<const TilingBlendingNoise*, 2> noises = {&field.channel(0), &field.channel(1)};
    const int n = bruteForceSamples(j, field.exampleSize(), maxPerAxis, minPerAxis);
    double m[2] = {0, 0}, m2[2] = {0, 0}, mxy = 0;
    for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a) {
            const double s = (a + 0.5) / n - 0.5, t = (b + 0.5) / n - 0.5;
            const double su = u + s * j.dudx + t * j.dudy, sv = v + s * j.dvdx + t * j.dvdy;
            const BlendStencil st = triangleGrid(su, sv, field.grid());
            const float fu = periodFraction(su), fv = periodFraction(sv);
            const double x = noises[0]->blend(st, fu, fv), y = noises[1]->blend(st, fu, fv);
            m[0] += x;
            m[1] += y;
            m2[0] += x * x;
            m2[1] += y * y;
            mxy += x * y;
        }
    const double inv = 1.0 / (double(n) * n);
    FootprintStats out;
    out.mean = {float(m[0] * inv), float(m[1] * inv)};
    out.varX = float(std::max(0.0, m2[0] * inv - m[0] * inv * m[0] * inv));
    out.varY = float(std::max(0.0, m2[1] * inv - m[1] * inv * m[1] * inv));
    out.cov = float(mxy * inv - m[0] * inv * m[1] * inv);
    return out;
}

}  // namespace stochtex
