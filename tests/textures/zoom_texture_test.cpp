#include "stochtex/textures/zoom_texture.h"

#include <gtest/gtest.h>

#include <cmath>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "test_util.h"

namespace stochtex {
namespace {

ZoomParams params(ZoomScaling s, ZoomOffsets o, int n = 8, double t = 0.37) {
    ZoomParams p;
    p.layers = n;
    p.scaling = s;
    p.offsets = o;
    p.time = t;
    return p;
}

TEST(ZoomTexture, LayersFollowEquations22And25WithANormalisedEnvelope) {
    for (ZoomScaling s : {ZoomScaling::Sliding, ZoomScaling::Exponential})
        for (double t : {0.0, 0.37, 5.3}) {
            const auto layers = zoomLayers(params(s, ZoomOffsets::None, 8, t), 64, 64);
            ASSERT_EQ(layers.size(), 8u);
            double sum = 0;
            for (size_t i = 0; i < layers.size(); ++i) {
                sum += layers[i].weight;
                const double phase = double(i) * 2.0 / 8.0;
                const double m =
                    std::fmod(std::fmod(s == ZoomScaling::Sliding ? phase - t : t - phase, 2.0) + 2.0, 2.0);
                EXPECT_NEAR(layers[i].scale, s == ZoomScaling::Sliding ? m : 2.0 * std::exp(-m), 1e-12);
            }
            EXPECT_NEAR(sum, 1.0, 1e-12);
        }
}

// Eq. 2.5's point: a texture point at screen position u moves with speed
// du/dt = −u a'/a, so the relative speed −a'/a must be the same for every
// layer; with the sliding scales (eq. 2.2) it is 1/a_i, different per layer.
TEST(ZoomTexture, ExponentialScalesGiveEveryLayerTheSameScreenSpeed) {
    const double t = 0.61, dt = 1e-5;
    auto relativeSpeeds = [&](ZoomScaling s) {
        const auto before = zoomLayers(params(s, ZoomOffsets::None, 8, t - dt), 64, 64);
        const auto after = zoomLayers(params(s, ZoomOffsets::None, 8, t + dt), 64, 64);
        const auto now = zoomLayers(params(s, ZoomOffsets::None, 8, t), 64, 64);
        std::vector<double> v;
        for (size_t i = 0; i < now.size(); ++i) {
            const double da = (after[i].scale - before[i].scale) / (2 * dt);
            if (std::abs(da) > 1e3) continue;  // the layer wrapped inside [t − dt, t + dt]
            v.push_back(-da / now[i].scale);
        }
        return v;
    };
    const auto fixed = relativeSpeeds(ZoomScaling::Exponential);
    ASSERT_GE(fixed.size(), 7u);
    for (double v : fixed) EXPECT_NEAR(v, 1.0, 1e-6);
    const auto sliding = relativeSpeeds(ZoomScaling::Sliding);
    const auto [lo, hi] = std::minmax_element(sliding.begin(), sliding.end());
    EXPECT_GT(*hi - *lo, 1.0) << "sliding layers should move at different screen speeds";
}

TEST(ZoomTexture, RenderMatchesPointwiseEvaluationForEveryVariant) {
    const LatticeTexture f = LatticeTexture::whiteNoise(48, 40, 7);
    for (ZoomOffsets o : {ZoomOffsets::None, ZoomOffsets::Simple, ZoomOffsets::Hashed, ZoomOffsets::SinHash})
        for (LatticeInterpolation m : {LatticeInterpolation::Nearest, LatticeInterpolation::Linear}) {
            ZoomParams p = params(ZoomScaling::Exponential, o);
            p.interpolation = m;
            const ZoomRegion region = ZoomRegion::centred(33, 21);
            const Image img = renderZoom(f, p, region);
            const auto layers = zoomLayers(p, f.width(), f.height());
            for (int y = 0; y < region.height; y += 5)
                for (int x = 0; x < region.width; x += 4)
                    ASSERT_EQ(img.at(x, y), float(evaluateZoom(f, layers, m, region.x0 + x, region.y0 + y)))
                        << "pixel " << x << "," << y;
        }
}

TEST(ZoomTexture, IdenticalForAnyThreadCount) {
    const LatticeTexture f = LatticeTexture::whiteNoise(64, 64, 3);
    const ZoomParams p = params(ZoomScaling::Sliding, ZoomOffsets::Hashed);
    Image one;
    {
        ThreadLimit limit(1);
        one = renderZoom(f, p, ZoomRegion::centred(100, 70));
    }
    const Image all = renderZoom(f, p, ZoomRegion::centred(100, 70));
    EXPECT_EQ(one.data(), all.data());
}

TEST(ZoomTexture, WhiteNoiseLatticeHasTheModelStatistics) {
    const LatticeTexture f = LatticeTexture::whiteNoise(256, 256, 11);
    double s = 0, s2 = 0;
    for (int j = 0; j < 256; ++j)
        for (int i = 0; i < 256; ++i) {
            s += f.at(i, j);
            s2 += double(f.at(i, j)) * f.at(i, j);
        }
    const double n = 65536, m = s / n;
    EXPECT_NEAR(m, f.mean(), 0.005);                   // σ/√n = 0.0011
    EXPECT_NEAR(s2 / n - m * m, f.variance(), 0.002);  // 1/12 = 0.0833
    EXPECT_EQ(f.at(-1, 300), f.at(255, 44));           // periodic
}

TEST(ZoomTexture, BadParametersAreInputErrors) {
    ZoomParams p;
    p.layers = 0;
    EXPECT_THROW(zoomLayers(p, 8, 8), InputError);
    p = ZoomParams{};
    p.maxScale = 0;
    EXPECT_THROW(zoomLayers(p, 8, 8), InputError);
    p.maxScale = std::nan("");
    EXPECT_THROW(zoomLayers(p, 8, 8), InputError);
    EXPECT_THROW(LatticeTexture::whiteNoise(0, 8, 1), InputError);
    EXPECT_THROW(parseZoomOffsets("random"), InputError);
}

TEST(ZoomTexture, ErrorsNameTheParameterAndTheValue) {
    ZoomParams p;
    p.layers = 0;
    InputError e = test::inputErrorOf([&] { validateZoomParams(p); });
    EXPECT_EQ(e.parameter(), "layers");
    EXPECT_STREQ(e.what(), "layers must be in [1, 1024], got 0");
    p = ZoomParams{};
    p.envelopeSigma = -0.25;
    e = test::inputErrorOf([&] { validateZoomParams(p); });
    EXPECT_EQ(e.parameter(), "envelopeSigma");
    EXPECT_STREQ(e.what(), "envelopeSigma must be in [1e-06, 1e+06], got -0.25");
    e = test::inputErrorOf([] { parseZoomOffsets("random"); });
    EXPECT_EQ(e.parameter(), "offsets");
    EXPECT_STREQ(e.what(), "offsets must be none, simple, hashed or sin-hash, got \"random\"");
}

}  // namespace
}  // namespace stochtex
