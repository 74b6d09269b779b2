// Partly correlated tiled white noise (thesis eq. 2.24–2.28): α from the
// correlation, the measured tile-to-tile correlation, the contrast
// correction's mean and variance, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/noise/tiled_white_noise.h"

namespace stochtex {
namespace {

TEST(TiledWhiteNoise, AlphaFromCorrelationInvertsEq228) {
    // Hand values: c = α²/(α² + (1 − α)²) gives c(½) = ½, c(⅔) = (4/9)/(5/9) = 0.8, c(⅓) = (1/9)/(5/9) = 0.2.
    EXPECT_NEAR(blendAlphaForCorrelation(0.5), 0.5, 1e-15);
    EXPECT_NEAR(blendAlphaForCorrelation(0.8), 2.0 / 3.0, 1e-15);
    EXPECT_NEAR(blendAlphaForCorrelation(0.2), 1.0 / 3.0, 1e-15);
    EXPECT_EQ(blendAlphaForCorrelation(0.0), 0.0);
    EXPECT_EQ(blendAlphaForCorrelation(1.0), 1.0);
    EXPECT_NEAR(tileCorrelation(2.0 / 3.0), 0.8, 1e-15);
    for (double c = 0.0; c <= 1.0; c += 0.05) EXPECT_NEAR(tileCorrelation(blendAlphaForCorrelation(c)), c, 1e-12) << c;
    for (double bad : {-0.01, 1.01, std::nan("")}) {
        try {
            blendAlphaForCorrelation(bad);
            FAIL() << "no error for " << bad;
        } catch (const InputError& e) {
            EXPECT_EQ(e.parameter(), "correlation");
        }
    }
}

// Pearson correlation of the pixel pairs (x, y), (x + dx, y) for x, y in
// [0, tile): one pair per position of one tile, so within an image every
// pair has its own X and Y values and pairs are independent.
struct PairSums {
    double n = 0, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    void add(double a, double b) { n += 1, sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b; }
    double correlation() const {
        const double ma = sa / n, mb = sb / n;
        return (sab / n - ma * mb) / std::sqrt((saa / n - ma * ma) * (sbb / n - mb * mb));
    }
};

TEST(TiledWhiteNoise, MeasuredTileToTileCorrelationIsEq228) {
    // 128² images of 64² tiles, 16 seeds: N = 16 · 64² = 65536 independent
    // pairs. The normal-theory standard deviation of a sample correlation is
    // (1 − ρ²)/√N (≤ 0.0039 here); a simulation of this blend of uniform
    // variables (300 replicates of 4096 pairs) measured 0.80–1.06 times it, so
    // 5 of them is a tolerance this fixed seed cannot miss by chance.
    const int size = 128, tile = 64, seeds = 16;
    for (double c : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        PairSums repeat, half;  // one tile apart, and half a tile apart (not a period: no correlation)
        for (uint32_t seed = 0; seed < seeds; ++seed) {
            const Image z = tiledWhiteNoise({size, tile, blendAlphaForCorrelation(c), 1000 + seed});
            for (int y = 0; y < tile; ++y)
                for (int x = 0; x < tile; ++x) {
                    repeat.add(z.at(x, y), z.at(x + tile, y));
                    if (x < tile / 2) half.add(z.at(x, y), z.at(x + tile / 2, y));
                }
        }
        const double tolerance = 5.0 * (1.0 - c * c) / std::sqrt(repeat.n) + 1e-6;  // 1e-6: float values at c = 1
        EXPECT_NEAR(repeat.correlation(), c, tolerance) << "c = " << c;
        EXPECT_NEAR(half.correlation(), 0.0, 5.0 / std::sqrt(half.n)) << "c = " << c;
        std::printf("c = %.2f: measured %.4f (tolerance %.4f), half a tile %.4f\n", c, repeat.correlation(), tolerance,
                    half.correlation());
    }
}

TEST(TiledWhiteNoise, ContrastCorrectionKeepsMeanAndVariance) {
    // One tile as large as the image: every pixel's X and Y are independent,
    // so N = 512² samples are i.i.d. Mean 0 ± 5σ/√N; variance 1/3 ± 5σ²√2/√N
    // (the sample variance's deviation is σ²√((κ − 1)/N) and the blend's
    // kurtosis κ lies between the uniform's 1.8 and the normal's 3). Without
    // the correction (eq. 2.24's denominator) α = ½ would halve the variance.
    const int size = 512;
    const double n = double(size) * size, sigma2 = kTiledWhiteNoiseVariance;
    for (double alpha : {0.0, 0.3, 0.5, 0.8, 1.0}) {
        const Image z = tiledWhiteNoise({size, size, alpha, 7});
        double s = 0, ss = 0, maxAbs = 0;
        for (float v : z.data()) s += v, ss += double(v) * v, maxAbs = std::max(maxAbs, std::fabs(double(v)));
        const double mean = s / n, variance = ss / n - mean * mean;
        EXPECT_NEAR(mean, 0.0, 5.0 * std::sqrt(sigma2 / n)) << alpha;
        EXPECT_NEAR(variance, sigma2, 5.0 * sigma2 * std::sqrt(2.0 / n)) << alpha;
        EXPECT_LE(maxAbs, tiledWhiteNoiseBound(alpha) + 1e-6) << alpha;
        std::printf("alpha = %.1f: mean %+.5f, variance / (1/3) = %.4f\n", alpha, mean, variance / sigma2);
    }
    EXPECT_NEAR(tiledWhiteNoiseBound(0.5), std::sqrt(2.0), 1e-15);
}

TEST(TiledWhiteNoise, SameSeedSameImageAtAnyThreadCount) {
    const TiledWhiteNoiseOptions o{96, 24, 0.6, 42};
    Image one, two;
    {
        ThreadLimit limit(1);
        one = tiledWhiteNoise(o);
    }
    {
        ThreadLimit limit(2);
        two = tiledWhiteNoise(o);
    }
    EXPECT_TRUE(one.data() == two.data());
    TiledWhiteNoiseOptions other = o;
    other.seed = 43;
    EXPECT_FALSE(tiledWhiteNoise(other).data() == one.data());
    // α = 1: the tile alone, repeated exactly.
    const Image tiled = tiledWhiteNoise({96, 24, 1.0, 5});
    EXPECT_EQ(tiled.at(3, 7), tiled.at(3 + 48, 7 + 72));
}

TEST(TiledWhiteNoise, RefusesBadParameters) {
    auto parameterOf = [](const TiledWhiteNoiseOptions& o) {
        try {
            tiledWhiteNoise(o);
        } catch (const InputError& e) {
            return e.parameter();
        }
        return std::string("(none)");
    };
    EXPECT_EQ(parameterOf({64, 0, 0.5, 0}), "tile");
    EXPECT_EQ(parameterOf({64, 65, 0.5, 0}), "tile");
    EXPECT_EQ(parameterOf({0, 1, 0.5, 0}), "size");
    EXPECT_EQ(parameterOf({64, 8, 1.5, 0}), "alpha");
}

}  // namespace
}  // namespace stochtex
