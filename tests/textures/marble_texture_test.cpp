// The marble texture (textures/marble_texture.h, kernel/marble.glsl): the
// gradient noise's defining properties, the blended fix's continuity and
// contrast (eq. 2.24), and the source's determinism and refusals.
#include "stochtex/textures/marble_texture.h"

#include <gtest/gtest.h>

#include <cmath>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/kernel/marble.h"

namespace stochtex {
namespace {

using kernel::vec2;

kernel::Marble marble(int scaling, float level = 4.0f) {
    return {vec2(0.1f, 0.0f), 6.0f, level, 0.0f, 0.0f, 0.0f, scaling, 7u};
}

TEST(GradientNoise, IsZeroOnTheLatticeBoundedAndCentred) {
    double sum = 0, sumSq = 0, largest = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const float x = -500.0f + 1000.0f * kernel::unitFloat(kernel::pcg3d(kernel::uvec3(uint32_t(i), 1u, 2u)).x);
        const float y = -500.0f + 1000.0f * kernel::unitFloat(kernel::pcg3d(kernel::uvec3(uint32_t(i), 3u, 4u)).x);
        const double v = kernel::gradientNoise(vec2(x, y), 11u);
        sum += v, sumSq += v * v, largest = std::max(largest, std::abs(v));
    }
    for (int i = -20; i <= 20; i += 3)
        EXPECT_EQ(kernel::gradientNoise(vec2(float(i), float(2 * i - 5)), 11u), 0.0f) << i;
    EXPECT_LE(largest, 1.0);
    EXPECT_GT(largest, 0.7);  // the √2 scale makes it span most of [−1, 1]
    // Mean 0 (the gradients' directions are uniform); 2·10⁵ samples of a
    // field correlated over ~1 cell in a 10³-cell square: |mean| ≪ 0.02.
    EXPECT_NEAR(sum / n, 0.0, 0.02);
    EXPECT_GT(sumSq / n, 0.05);
}

TEST(GradientNoise, IsContinuousAndDependsOnTheSeed) {
    double maxStep = 0, seedDiff = 0;
    for (int i = 0; i < 4000; ++i) {
        const vec2 p(0.013f * float(i) - 17.0f, 0.007f * float(i) + 3.0f);
        maxStep = std::max(maxStep, double(std::abs(kernel::gradientNoise(p + vec2(1e-3f, 0.0f), 5u) -
                                                    kernel::gradientNoise(p, 5u))));
        seedDiff += std::abs(kernel::gradientNoise(p, 5u) - kernel::gradientNoise(p, 6u));
    }
    // Its gradient is a few units at most (unit gradients, a fade of slope
    // ≤ 15/8, the √2 scale): a step of 10⁻³ moves it by less than 0.006.
    EXPECT_LT(maxStep, 0.006);
    EXPECT_GT(seedDiff / 4000, 0.1);
}

TEST(MarbleKernel, BlendedScalesAreContinuousWhereLCrossesAnInteger) {
    // l from just below to just above 5: the weight of scale 2⁵ goes from 1
    // (upper field of the lower pair) to 1 (lower field of the upper pair).
    for (int scaling : {kernel::kMarbleBlended, kernel::kMarbleBlendedCorrected})
        for (bool cells : {false, true})
            for (int i = 0; i < 200; ++i) {
                const vec2 x(3.7f * float(i) - 300.0f, 1.9f * float(i) - 150.0f);
                const float below = kernel::scaledField(marble(scaling), x, 5.0f - 1e-5f, cells);
                const float above = kernel::scaledField(marble(scaling), x, 5.0f, cells);
                EXPECT_NEAR(below, above, 1e-3f) << "scaling " << scaling << " cells " << cells << " i " << i;
            }
}

// Halfway between two integer scales the plain blend of two independent
// fields has (½)² + (½)² = ½ of their variance; the corrected blend divides
// by √½ and keeps all of it (eq. 2.24 for zero-mean fields). Cell noise is
// uniform in [−1, 1): variance 1/3.
TEST(MarbleKernel, CorrectedBlendKeepsTheContrastThePlainBlendLoses) {
    for (int scaling : {kernel::kMarbleContinuous, kernel::kMarbleBlended, kernel::kMarbleBlendedCorrected}) {
        double sumSq = 0;
        int n = 0;
        for (int y = 0; y < 400; ++y)
            for (int x = 0; x < 400; ++x, ++n) {
                const float v = kernel::scaledField(marble(scaling), vec2(8.0f * float(x), 8.0f * float(y)), 2.5f, true);
                sumSq += double(v) * v;
            }
        const double ratio = sumSq / n / (1.0 / 3.0);
        EXPECT_NEAR(ratio, scaling == kernel::kMarbleBlended ? 0.5 : 1.0, 0.05) << "scaling " << scaling;
    }
}

TEST(MarbleSource, IsDeterministicForAnyThreadCountAndSeededPerInstance) {
    MarbleParams p;
    p.levelRate = 0.5;
    const MarbleSource source(p);
    const SourceRegion region = SourceRegion::centred(64, 48);
    Image one;
    {
        ThreadLimit limit(1);
        one = source.render(region, 0.3, 2);
    }
    const Image many = source.render(region, 0.3, 2);
    ASSERT_EQ(one.width(), 64);
    ASSERT_EQ(one.height(), 48);
    double diff = 0, other = 0, lo = 1, hi = 0;
    const Image instance3 = source.render(region, 0.3, 3);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            diff += std::abs(one.at(x, y) - many.at(x, y));
            other += std::abs(one.at(x, y) - instance3.at(x, y));
            lo = std::min(lo, double(one.at(x, y)));
            hi = std::max(hi, double(one.at(x, y)));
        }
    EXPECT_EQ(diff, 0.0);
    EXPECT_GT(other / (64 * 48), 0.05);
    EXPECT_GE(lo, 0.0);
    EXPECT_LE(hi, 1.0);
    EXPECT_GT(hi - lo, 0.8);  // bands from dark to light
}

TEST(MarbleSource, StretchFormulaMatchesTheKernelLevel) {
    // marbleLevelSlope is ∂l/∂x of the kernel's l, whose finite difference
    // it must match (the study's stretch, 1 − x ln 2 ∂l/∂x, rests on it).
    MarbleParams p;
    p.levelAmplitude = 1.5;
    p.levelPeriod = 192;
    p.levelRate = 0.25;
    const kernel::Marble m = kernelMarble(p, 0);
    const auto level = [&](double x, double t) { return double(kernel::marbleLevel(m, kernel::vec2(float(x), 0.0f), float(t))); };
    for (double x : {-100.0, -37.5, 0.0, 12.0, 90.0}) {
        // h = 0.5: the central difference's truncation, n q³ h² / 6 ≈ 2e-6, and
        // float rounding of l, 2⁻²³ · 4 / (2h) ≈ 5e-7, both under the tolerance.
        const double h = 0.5;
        EXPECT_NEAR((level(x + h, 0) - level(x - h, 0)) / (2 * h), marbleLevelSlope(p, x), 1e-5) << x;
    }
    EXPECT_NEAR(level(0, 2), p.level + p.levelAmplitude + 2 * p.levelRate, 1e-6);
    EXPECT_NEAR(level(96, 0), p.level - p.levelAmplitude, 1e-5);  // half a period: the cosine's trough
}

TEST(MarbleSource, RefusesParametersAndWindowsOutOfRange) {
    const auto parameterOf = [](const MarbleParams& p) {
        try {
            validateMarbleParams(p);
        } catch (const InputError& e) {
            return e.parameter();
        }
        return std::string();
    };
    MarbleParams p;
    p.bandPeriod = 0;
    EXPECT_EQ(parameterOf(p), "bandPeriod");
    p = {};
    p.level = std::nan("");
    EXPECT_EQ(parameterOf(p), "level");
    p = {};
    p.levelRate = 1e9;
    EXPECT_EQ(parameterOf(p), "levelRate");
    p = {};
    p.levelRate = 10;
    const MarbleSource source(p);
    // t = 10 puts l at 105: out of the kernel's range (no float-cast overflow).
    try {
        source.render(SourceRegion::centred(8, 8), 10, 0);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("spans [104, 106], outside [-8, 40]"), std::string::npos) << e.what();
    }
    EXPECT_THROW(source.render({8, 8, 1e7, 0}, 0, 0), InputError);
    EXPECT_THROW(source.render(SourceRegion::centred(8, 8), std::nan(""), 0), InputError);
}

}  // namespace
}  // namespace stochtex
