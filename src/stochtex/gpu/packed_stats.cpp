#include "stochtex/gpu/packed_stats.h"

#include <algorithm>
#include <cmath>

namespace stochtex {

namespace {

// An 8-bit code over a channel's range at one level.
struct CodedRange {
    float lo = 0, hi = 0;
    float code(float v) const { return hi > lo ? std::round(255.0f * (v - lo) / (hi - lo)) / 255.0f : 0.0f; }
    float scale() const { return hi - lo; }
};

// Channel c of every texel of `level` (3 interleaved channels).
CodedRange rangeOf(const Image& level, int c) {
    CodedRange r{level.data()[size_t(c)], level.data()[size_t(c)]};
    for (size_t i = 0; i < level.pixelCount(); ++i) {
        r.lo = std::min(r.lo, level.data()[3 * i + size_t(c)]);
        r.hi = std::max(r.hi, level.data()[3 * i + size_t(c)]);
    }
    return r;
}

}  // namespace

std::array<const StatsPyramid*, 2> pairPyramids(const GraphPattern& graph, const FilteredGraph& filtered, int p) {
    std::array<const StatsPyramid*, 2> pyramids{nullptr, nullptr};
    for (int k = 0; k < graph.leafCount(); ++k)
        if (const auto [pair, channel] = graph.leafLocation(k); pair == p)
            pyramids[size_t(channel)] = &filtered.estimator(pair).pyramid(channel);
    if (!pyramids[1]) pyramids[1] = pyramids[0];
    return pyramids;
}

Image packedPairLevel(const StatsPyramid& x, const StatsPyramid& y, int level, GraphEstimator::LevelCoding& coding) {
    const Image ex = x.interleavedLevel(level, 3), ey = y.interleavedLevel(level, 3);
    const std::array<const Image*, 4> source{&ex, &ey, &ex, &ey};
    const std::array<int, 4> channel{0, 0, 1, 1};  // (E_x, E_y, V_x, V_y)
    std::array<CodedRange, 4> range;
    for (size_t k = 0; k < 4; ++k) {
        range[k] = rangeOf(*source[k], channel[k]);
        coding.offset[k] = range[k].lo;
        coding.scale[k] = range[k].scale();
    }
    Image packed(ex.width(), ex.height(), 4, Image::Uninitialized{});
    for (size_t i = 0; i < packed.pixelCount(); ++i)
        for (size_t k = 0; k < 4; ++k)
            packed.data()[4 * i + k] = range[k].code(source[k]->data()[3 * i + size_t(channel[k])]);
    return packed;
}

Image codedCovarianceLevel(const StatsPyramid& covariance, int level, GraphEstimator::LevelCoding& coding) {
    const Image l = covariance.interleavedLevel(level, 3);
    const CodedRange mean = rangeOf(l, 0), c = rangeOf(l, 1);
    coding.covariance = {c.lo, c.scale()};
    Image coded(l.width(), l.height(), 4);
    for (size_t i = 0; i < coded.pixelCount(); ++i) {
        coded.data()[4 * i] = mean.code(l.data()[3 * i]);
        coded.data()[4 * i + 1] = c.code(l.data()[3 * i + 1]);
        coded.data()[4 * i + 3] = 1.0f;
    }
    return coded;
}

bool fitsUnorm16(const Image& image) {
    return std::all_of(image.data().begin(), image.data().end(), [](float v) { return v >= 0.0f && v <= 1.0f; });
}

}  // namespace stochtex
