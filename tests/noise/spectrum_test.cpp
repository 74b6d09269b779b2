#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "stochtex/noise/normal.h"
#include "stochtex/noise/spectrum.h"
#include "test_util.h"

using namespace stochtex;

namespace {

SpectrumSpec spec(SpectrumShape shape, double f, double b, double theta, uint32_t seed = 7, int size = 256) {
    return test::spectrumSpec(shape, f, b, theta, seed, size);
}

// Power-weighted mean radius of the spectrum (over all frequencies).
double meanRadius(const Image& p) {
    const int n = p.width();
    double sum = 0, wsum = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double r = std::hypot(fftFrequency(x, n), fftFrequency(y, n));
            sum += r * p.at(x, y);
            wsum += p.at(x, y);
        }
    return sum / wsum;
}

// Orientation (degrees, screen convention, modulo 180) of the dominant axis
// of the power spectrum, from its second-moment tensor.
double dominantOrientation(const Image& p) {
    const int n = p.width();
    double suu = 0, svv = 0, suv = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double fu = fftFrequency(x, n), fv = -double(fftFrequency(y, n));  // y up on screen
            suu += fu * fu * p.at(x, y);
            svv += fv * fv * p.at(x, y);
            suv += fu * fv * p.at(x, y);
        }
    double deg = 0.5 * std::atan2(2 * suv, suu - svv) * 180.0 / std::numbers::pi;
    if (deg < 0) deg += 180.0;
    return deg;
}

double angleDistance(double a, double b) {
    double d = std::fmod(std::abs(a - b), 180.0);
    return std::min(d, 180.0 - d);
}

}  // namespace

TEST(Normal, QuantileInvertsCdf) {
    for (double x : {-5.0, -3.0, -1.2, 0.0, 0.3, 2.5, 4.0}) EXPECT_NEAR(normalQuantile(normalCdf(x)), x, 1e-9);
    EXPECT_NEAR(normalQuantile(0.975), 1.959963984540054, 1e-12);
}

TEST(Normal, HashedGaussianHasUnitMoments) {
    double s = 0, s2 = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double g = hashedGaussian(uint32_t(i % 1000), uint32_t(i / 1000), 99);
        s += g;
        s2 += g * g;
    }
    EXPECT_NEAR(s / n, 0.0, 0.01);      // 4.5 standard errors
    EXPECT_NEAR(s2 / n, 1.0, 0.015);
}

TEST(Spectrum, ExampleHasRequestedMeanAndStd) {
    struct Case {
        SpectrumShape shape;
        double f, b, theta, mean, stddev;
    };
    for (const Case& c : {Case{SpectrumShape::LowPass, 8, 0, 0, 0.5, 1.0 / 6.0},
                          Case{SpectrumShape::Ring, 16, 3, 0, 0.4, 0.1},
                          Case{SpectrumShape::BiLobe, 20, 2, 30, 0.55, 0.2},
                          Case{SpectrumShape::LowPass, 4, 0, 0, 0.5, 0.25}}) {
        SpectrumSpec s = spec(c.shape, c.f, c.b, c.theta);
        s.mean = c.mean;
        s.stddev = c.stddev;
        const Image e = synthesizeExample(s);
        const ChannelStats st = channelStats(e);
        EXPECT_NEAR(st.mean, c.mean, 0.01 * c.mean);
        EXPECT_NEAR(st.stddev, c.stddev, 0.01 * c.stddev);
        for (float v : e.data()) {
            ASSERT_GE(v, 0.0f);
            ASSERT_LE(v, 1.0f);
        }
    }
}

TEST(Spectrum, RingPeaksAtRequestedFrequency) {
    for (double f : {10.0, 24.0, 40.0}) {
        const Image p = powerSpectrum(synthesizeExample(spec(SpectrumShape::Ring, f, 2.0, 0)));
        EXPECT_NEAR(meanRadius(p), f, 1.0) << "f = " << f;
    }
}

TEST(Spectrum, BiLobePeaksAtRequestedFrequencyAndOrientation) {
    for (double theta : {0.0, 30.0, 75.0, 135.0}) {
        const Image p = powerSpectrum(synthesizeExample(spec(SpectrumShape::BiLobe, 20.0, 2.0, theta)));
        EXPECT_NEAR(meanRadius(p), 20.0, 1.0) << "theta = " << theta;
        EXPECT_LT(angleDistance(dominantOrientation(p), theta), 3.0) << "theta = " << theta;
        // The strongest single frequency lies in one of the two lobes.
        const int n = p.width();
        int bx = 0, by = 0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                if (p.at(x, y) > p.at(bx, by)) bx = x, by = y;
        const double fu = fftFrequency(bx, n), fv = -double(fftFrequency(by, n));
        const double t = theta * std::numbers::pi / 180.0;
        const double along = std::abs(fu * std::cos(t) + fv * std::sin(t));
        const double across = std::abs(-fu * std::sin(t) + fv * std::cos(t));
        EXPECT_NEAR(along, 20.0, 6.0);  // within 3 bandwidths
        EXPECT_LT(across, 6.0);
    }
}

TEST(Spectrum, LowPassConcentratesPowerBelowCutoff) {
    const Image p = powerSpectrum(synthesizeExample(spec(SpectrumShape::LowPass, 6.0, 0, 0)));
    // For a 2D Gaussian power profile, the mean radius is fc·√(π/2).
    EXPECT_NEAR(meanRadius(p), 6.0 * std::sqrt(std::numbers::pi / 2), 0.6);
}

TEST(Spectrum, SameSeedSameExampleOtherSeedDiffers) {
    const Image a = synthesizeExample(spec(SpectrumShape::Ring, 12, 3, 0, 5));
    const Image b = synthesizeExample(spec(SpectrumShape::Ring, 12, 3, 0, 5));
    const Image c = synthesizeExample(spec(SpectrumShape::Ring, 12, 3, 0, 6));
    EXPECT_EQ(a.data(), b.data());
    EXPECT_NE(a.data(), c.data());
}

TEST(Spectrum, QuadraturePairIsUncorrelatedWithSameSpectrum) {
    SpectrumSpec s = spec(SpectrumShape::BiLobe, 16, 2, 40);
    const Image a = synthesizeExample(s);
    s.quadrature = true;
    const Image b = synthesizeExample(s);
    const ChannelStats sa = channelStats(a), sb = channelStats(b);
    double cov = 0;
    for (size_t i = 0; i < a.data().size(); ++i) cov += (a.data()[i] - sa.mean) * (b.data()[i] - sb.mean);
    cov /= double(a.data().size());
    EXPECT_LT(std::abs(cov / (sa.stddev * sb.stddev)), 0.03);
    EXPECT_NEAR(meanRadius(powerSpectrum(b)), meanRadius(powerSpectrum(a)), 0.2);
    // A quadrature pair has a nearly constant local amplitude: the squared
    // envelope varies far less than the signal itself (no zero crossings
    // together).
    double bothNearMean = 0;
    for (size_t i = 0; i < a.data().size(); ++i)
        if (std::abs(a.data()[i] - sa.mean) < 0.02 && std::abs(b.data()[i] - sb.mean) < 0.02) bothNearMean += 1;
    EXPECT_LT(bothNearMean / double(a.data().size()), 0.01);
}
