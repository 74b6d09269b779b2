#include <gtest/gtest.h>

#include <cmath>

#include "stochtex/core/hash.h"
#include "stochtex/noise/gaussianize.h"

using namespace stochtex;

namespace {
// A strongly non-Gaussian exemplar: bimodal, skewed values.
Image bimodal(int n) {
    Image img(n, n, 1);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const UInt3 h = pcg3d({uint32_t(x), uint32_t(y), 3});
            const float u = unitFloat(h.x), t = unitFloat(h.y);
            img.at(x, y) = u < 0.3f ? 0.1f + 0.1f * t * t : 0.7f + 0.25f * t;
        }
    return img;
}
}  // namespace

TEST(HistogramTransform, ForwardIsGaussian) {
    const Image e = bimodal(128);
    const HistogramTransform t = HistogramTransform::fit(e);
    const Image g = t.forward(e);
    const ChannelStats s = channelStats(g);
    EXPECT_NEAR(s.mean, 0.5, 1e-3);
    EXPECT_NEAR(s.stddev, 1.0 / 6.0, 2e-3);  // clamping at ±3σ trims ~0.3% of values
    // Median of a Gaussian is its mean.
    std::vector<float> v(g.data().begin(), g.data().end());
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    EXPECT_NEAR(v[v.size() / 2], 0.5, 1e-3);
}

TEST(HistogramTransform, InverseUndoesForward) {
    const Image e = bimodal(128);
    const HistogramTransform t = HistogramTransform::fit(e);
    const Image g = t.forward(e);
    double err = 0;
    for (size_t i = 0; i < e.data().size(); ++i) err += std::abs(t.inverse(g.data()[i]) - e.data()[i]);
    err /= double(e.data().size());
    EXPECT_LT(err, 0.005);
    // The inverse is monotonic and spans the exemplar's range.
    const auto& lut = t.inverseLut();
    for (size_t k = 1; k < lut.size(); ++k) ASSERT_GE(lut[k], lut[k - 1]);
    EXPECT_NEAR(lut.front(), 0.1f, 0.01f);
    EXPECT_NEAR(lut.back(), 0.95f, 0.01f);
}
