// The gather floor of the SIMD evaluator (issue 33, item 4): the time of
// gathering N 64-bit texel pairs and nothing else, in the same vectors the
// evaluator uses (Highway, dispatched to the machine's widest target), from
// an L2-resident grid. The evaluator's benchmarks divide their time by this
// floor for the pairs they gather, measured in the same run.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gather_floor.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <chrono>
#include <cstdint>
#include <vector>

#include "gather_floor.h"

HWY_BEFORE_NAMESPACE();
namespace stochtex::bench::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

double GatherPairsImpl(const float* grid, int gridFloats, long long pairs) {
    const hn::ScalableTag<double> dd;
    const hn::RebindToSigned<decltype(dd)> di;
    const size_t n = hn::Lanes(dd);
    const double* base = reinterpret_cast<const double*>(grid);
    // Offsets that wander through the grid like a row of tiles: a stride of
    // a few texels per lane, wrapped into the grid (whole pairs inside it).
    const auto limit = hn::Set(di, int64_t(gridFloats - 2) * 4);
    const auto step = hn::Set(di, int64_t(n) * 12);
    auto offsets = hn::Mul(hn::Iota(di, 0), hn::Set(di, 12));
    auto acc = hn::Zero(dd);
    const auto t0 = std::chrono::steady_clock::now();
    for (long long i = 0; i < pairs; i += (long long)n) {
        acc = hn::Add(acc, hn::GatherOffset(dd, base, offsets));
        offsets = hn::Add(offsets, step);
        offsets = hn::IfThenElse(hn::Lt(offsets, limit), offsets, hn::Sub(offsets, limit));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    volatile double sink = hn::GetLane(acc);
    (void)sink;
    return seconds;
}

}  // namespace stochtex::bench::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace stochtex::bench {

HWY_EXPORT(GatherPairsImpl);

double gatherFloorSeconds(long long pairs) {
    static const std::vector<float> grid(258 * 258, 0.5f);  // a 256² example's padded grid: 260 KB
    return HWY_DYNAMIC_DISPATCH(GatherPairsImpl)(grid.data(), int(grid.size()), pairs);
}

}  // namespace stochtex::bench
#endif
