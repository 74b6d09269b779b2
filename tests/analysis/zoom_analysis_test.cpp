// The zoom texture's analytic statistics (eq. 2.11, Table 2.3) against the
// statistical accumulator, and the contrast corrections of section 2.4.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "stochtex/analysis/contrast.h"
#include "stochtex/analysis/correlation_accumulator.h"
#include "stochtex/textures/zoom_statistics.h"
#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"

namespace stochtex {
namespace {

constexpr int kInstances = 512;
constexpr int kBase = 128;

ZoomParams variant(ZoomScaling s, ZoomOffsets o, int n) {
    ZoomParams p;
    p.scaling = s;
    p.offsets = o;
    p.layers = n;
    p.time = 0.41;
    return p;
}

// Frames of the region x ∈ [0, size), y ∈ [0, size) from the zoom centre
// (row 0 is the horizontal axis through the centre), one per instance.
CorrelationAccumulator accumulate(const ZoomParams& p, int size, int instances = kInstances) {
    CorrelationAccumulator acc(size, size, size / 2, 0, 0, 0);
    const ZoomRegion region{size, size, 0.0, 0.0};
    for (int k = 0; k < instances; ++k)
        acc.add(renderZoom(LatticeTexture::whiteNoise(kBase, kBase, deriveSeed(99, uint32_t(k))), p, region));
    return acc;
}

double meanAbsDifference(const Image& a, const Image& b) {
    double s = 0;
    for (size_t i = 0; i < a.data().size(); ++i) s += std::abs(double(a.data()[i]) - b.data()[i]);
    return s / double(a.data().size());
}

TEST(ZoomStatistics, MeasuredMeanAndVarianceMatchTable23) {
    const ZoomParams p = variant(ZoomScaling::Exponential, ZoomOffsets::None, 8);
    const int size = 48;
    const CorrelationAccumulator acc = accumulate(p, size);
    const ZoomStatistics stats(p, kBase, kBase);
    const Image mean = acc.mean(), var = acc.variance();
    const double sigmaF2 = 1.0 / 12.0;
    double ratioSum = 0, ratioDev = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double analytic = sigmaF2 * stats.varianceFactor(x, y);
            // Mean: within 5 standard errors σ_r/√N at every pixel.
            ASSERT_NEAR(mean.at(x, y), 0.5, 5.0 * std::sqrt(analytic / kInstances)) << x << "," << y;
            const double r = var.at(x, y) / analytic;
            ratioSum += r;
            ratioDev += std::abs(r - 1.0);
        }
    const double n = double(size) * size;
    // The sample variance of N = 512 near-Gaussian values has a relative
    // standard error √(2/N) = 6%: per pixel |ratio − 1| averages ≈ 5%, and
    // pixels share lattice values, so the average ratio is only loosely
    // pinned (bound 3%).
    EXPECT_LT(ratioDev / n, 0.08);
    EXPECT_NEAR(ratioSum / n, 1.0, 0.03);
    // And the contrast loss itself: α(x, x) < 1 away from a lattice point.
    EXPECT_LT(stats.varianceFactor(10.3, 4.7), 0.5);
}

// Figure 2.10: analytic and measured radial correlation plots agree, for
// each variant, to within 0.05 on average over N = 512 instances (the
// estimator's own noise is ≈ (1 − ρ²)/√N ≤ 0.044).
TEST(ZoomStatistics, AnalyticAndMeasuredCorrelationAgreeForEveryVariant) {
    const int size = 48;
    struct V {
        ZoomScaling s;
        ZoomOffsets o;
    };
    for (V v : {V{ZoomScaling::Sliding, ZoomOffsets::None}, V{ZoomScaling::Exponential, ZoomOffsets::None},
                V{ZoomScaling::Exponential, ZoomOffsets::Simple}, V{ZoomScaling::Exponential, ZoomOffsets::Hashed}})
        for (int n : {8, 3}) {
            const ZoomParams p = variant(v.s, v.o, n);
            const ZoomStatistics stats(p, kBase, kBase);
            const CorrelationAccumulator acc = accumulate(p, size);
            const double radial = meanAbsDifference(stats.radialCorrelation(size), acc.probeCorrelation());
            const double nonRadial = meanAbsDifference(stats.nonRadialCorrelation(size), acc.correlationWithRow());
            EXPECT_LT(radial, 0.05) << "n = " << n << ", offsets " << int(v.o) << ", scaling " << int(v.s);
            EXPECT_LT(nonRadial, 0.05) << "n = " << n << ", offsets " << int(v.o) << ", scaling " << int(v.s);
            EXPECT_GT(radial, 0.0);  // a measurement, not a copy
        }
}

// Off the diagonal band (the interpolation kernel's own correlation),
// hashed offsets leave no correlation while unshifted layers echo.
TEST(ZoomStatistics, HashedOffsetsRemoveTheEchoes) {
    auto offDiagonalMax = [](const Image& c) {
        double m = 0;
        for (int y = 0; y < c.height(); ++y)
            for (int x = 0; x < c.width(); ++x)
                if (std::abs(x - y) > 4) m = std::max(m, double(std::abs(c.at(x, y))));
        return m;
    };
    const int size = 128;
    const ZoomStatistics hashed(variant(ZoomScaling::Exponential, ZoomOffsets::Hashed, 8), 512, 512);
    const ZoomStatistics none(variant(ZoomScaling::Exponential, ZoomOffsets::None, 8), 512, 512);
    EXPECT_LT(offDiagonalMax(hashed.radialCorrelation(size)), 0.05);
    EXPECT_GT(offDiagonalMax(none.radialCorrelation(size)), 0.3);
    // Measured too (N = 512, smaller frame): the mean |Corr| off the band.
    const CorrelationAccumulator acc = accumulate(variant(ZoomScaling::Exponential, ZoomOffsets::Hashed, 8), 40);
    const Image c = acc.probeCorrelation();
    double s = 0;
    int k = 0;
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x)
            if (std::abs(x - y) > 4) {
                s += std::abs(c.at(x, y));
                ++k;
            }
    EXPECT_LT(s / k, 0.05);
}

TEST(CorrelationAccumulator, IndependentOfThreadCountAndChecksFrames) {
    const ZoomParams p = variant(ZoomScaling::Sliding, ZoomOffsets::Hashed, 5);
    CorrelationAccumulator one(30, 20, 3, 4, 0, 2), all(30, 20, 3, 4, 0, 2);
    for (int k = 0; k < 6; ++k) {
        const Image f = renderZoom(LatticeTexture::whiteNoise(32, 32, uint32_t(k)), p, ZoomRegion{30, 20, 0, 0});
        {
            ThreadLimit limit(1);
            one.add(f);
        }
        all.add(f);
    }
    EXPECT_EQ(one.correlationWithPoint().data(), all.correlationWithPoint().data());
    EXPECT_EQ(one.probeCorrelation().data(), all.probeCorrelation().data());
    EXPECT_THROW(one.add(Image(10, 10, 1)), InputError);
    EXPECT_THROW(CorrelationAccumulator(10, 10, 10, 0, 0, 0), InputError);
}

TEST(Contrast, PolynomialSolvesEquation218) {
    for (double mu : {0.5, 0.4})
        for (double vr : {0.01, 0.03, 0.07}) {
            const double vf = 1.0 / 12.0;
            const CubicCorrection h = CubicCorrection::solve(mu, vf, vr);
            EXPECT_NEAR(h.b + h.c + h.d, 1.0, 1e-12);                                             // h(1) = 1
            EXPECT_NEAR(h.derivative(mu), std::sqrt(vf / vr), 1e-12);                              // h'(μ)
            EXPECT_NEAR(mu * h.b + (mu * mu + vr) * h.c + (mu * mu * mu + 3 * mu * vr) * h.d, mu, 1e-12);  // E
            EXPECT_EQ(h(0.0), 0.0);
        }
    // Section 2.4.2: for μ = ½ the cubic is monotone iff σ_r² ≥ 4/9 σ_f².
    EXPECT_TRUE(CubicCorrection::solve(0.5, 1.0 / 12, 0.46 / 12).monotone());
    EXPECT_FALSE(CubicCorrection::solve(0.5, 1.0 / 12, 0.40 / 12).monotone());
}

TEST(Contrast, SigmoidMapsTheUnitIntervalOntoItselfWithTheRightSlope) {
    for (double ratio : {1.3, 2.0, 4.0}) {  // σ_f/σ_r
        const double vf = 1.0 / 12, vr = vf / (ratio * ratio);
        double prev = -1;
        for (int i = 0; i <= 1000; ++i) {
            const double v = correctContrast(ContrastMethod::Sigmoid, i / 1000.0, 0.5, vf, vr);
            ASSERT_GE(v, 0.0);
            ASSERT_LE(v, 1.0);
            ASSERT_GE(v, prev);
            prev = v;
        }
        const double e = 1e-6;
        const double slope = (correctContrast(ContrastMethod::Sigmoid, 0.5 + e, 0.5, vf, vr) -
                              correctContrast(ContrastMethod::Sigmoid, 0.5 - e, 0.5, vf, vr)) / (2 * e);
        EXPECT_NEAR(slope, ratio, 1e-4);
        EXPECT_NEAR(correctContrast(ContrastMethod::Sigmoid, 1.0, 0.5, vf, vr), 1.0, 1e-12);
    }
}

// Figure 2.6's comparison on a 256² zoom texture with n = 16: the linear
// correction restores the variance but clamps; the polynomial clamps fewer
// pixels; the sigmoid never clamps.
TEST(Contrast, LinearRestoresVarianceAndClampsMoreThanPolynomialWhileSigmoidNeverClamps) {
    const ZoomParams p = variant(ZoomScaling::Exponential, ZoomOffsets::Hashed, 16);
    const ZoomRegion region = ZoomRegion::centred(256, 256);
    const LatticeTexture f = LatticeTexture::whiteNoise(256, 256, 5);
    const Image texture = renderZoom(f, p, region);
    const ZoomStatistics stats(p, f.width(), f.height());
    Image varR = stats.varianceFactorImage(region);
    for (float& v : varR.data()) v *= float(f.variance());
    const ContrastResult lin = correctContrast(ContrastMethod::Linear, texture, varR, 0.5, f.variance());
    const ContrastResult poly = correctContrast(ContrastMethod::Polynomial, texture, varR, 0.5, f.variance());
    const ContrastResult sig = correctContrast(ContrastMethod::Sigmoid, texture, varR, 0.5, f.variance());
    EXPECT_GT(lin.clampedPercent, 5.0);
    EXPECT_LT(poly.clampedPercent, lin.clampedPercent);
    EXPECT_EQ(sig.clampedPercent, 0.0);
    // Unclamped linear values have the base variance (σ_f² = 1/12) on average.
    double s = 0, s2 = 0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            const double v = correctContrast(ContrastMethod::Linear, texture.at(x, y), 0.5, f.variance(), varR.at(x, y));
            s += v;
            s2 += v * v;
        }
    const double n = 65536, m = s / n;
    EXPECT_NEAR(s2 / n - m * m, f.variance(), 0.1 * f.variance());
    EXPECT_NEAR(m, 0.5, 0.02);
}

}  // namespace
}  // namespace stochtex
