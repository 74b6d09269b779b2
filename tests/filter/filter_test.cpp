#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"
#include "stochtex/filter/footprint.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/filter/pyramid.h"
#include "stochtex/noise/spectrum.h"
#include "test_util.h"

using namespace stochtex;

namespace {

using test::example;

const double kDensity = kDefaultGridDensity;

// Equal seeds declare the pair Shared (the covariance tests need it).
TiledField noisePair(const Image& ex, const Image& ey, uint32_t sx, uint32_t sy) {
    return TiledField({TilingBlendingNoise(std::make_shared<const NoiseExample>(ex), sx),
                       TilingBlendingNoise(std::make_shared<const NoiseExample>(ey), sy)},
                      GridLayout::plane(kDensity), sx == sy ? OffsetSharing::Shared : OffsetSharing::Independent);
}

}  // namespace

TEST(StatsPyramid, LevelsAreExactBlockStatistics) {
    const Image e = example(SpectrumShape::LowPass, 8, 0, 0, 3, 64);
    const StatsPyramid p(e);
    ASSERT_EQ(p.levels(), 7);  // 64, 32, ..., 1
    const ChannelStats global = channelStats(e);
    EXPECT_NEAR(p.mean(6, 0, 0), global.mean, 1e-6);
    EXPECT_NEAR(p.moment(6, 0, 0), global.stddev * global.stddev, 1e-6);
    EXPECT_EQ(p.moment(0, 5, 9), 0.0f);
    // Level 3 texel (2, 5) covers level-0 texels [16,24) × [40,48).
    double s = 0, s2 = 0;
    for (int y = 40; y < 48; ++y)
        for (int x = 16; x < 24; ++x) {
            s += e.at(x, y);
            s2 += double(e.at(x, y)) * e.at(x, y);
        }
    const double mean = s / 64, var = s2 / 64 - mean * mean;
    EXPECT_NEAR(p.mean(3, 2, 5), mean, 1e-6);
    EXPECT_NEAR(p.moment(3, 2, 5), var, 1e-6);
    // Within-texel variance grows with the level and ends at the global variance.
    for (int l = 1; l < p.levels(); ++l) EXPECT_GT(p.averageMoment(l), p.averageMoment(l - 1));
    // The layout uploaded to GL (RG) and exported (RGB): mean, moment, zeros.
    const Image rgb = p.interleavedLevel(3, 3);
    ASSERT_EQ(rgb.width(), 8);
    ASSERT_EQ(rgb.channels(), 3);
    EXPECT_EQ(rgb.at(2, 5, 0), p.mean(3, 2, 5));
    EXPECT_EQ(rgb.at(2, 5, 1), p.moment(3, 2, 5));
    EXPECT_EQ(rgb.at(2, 5, 2), 0.0f);
}

// Every level against its definition in double on random texels, for an
// example whose mean (0.9) dwarfs its spread (±0.002), where mip(E²) − E_l²
// in float would lose every digit of V_l. Tolerances: means within 2 float
// ulps of 1, variances within 1e-4 relative, covariances within 1e-4 of
// √(V_l V'_l) (a covariance may cancel to near 0).
TEST(StatsPyramid, EveryLevelEqualsItsBruteForceDefinitionOnRandomTexels) {
    const int n = 256;
    Image a(n, n, 1), b(n, n, 1);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            a.at(x, y) = 0.9f + 0.002f * (2.0f * unit(rng) - 1.0f);
            b.at(x, y) = 0.5f * a.at(x, y) + 0.4f * unit(rng);
        }
    const StatsPyramid va(a), cab = StatsPyramid::covariance(a, b);
    ASSERT_EQ(va.levels(), 9);
    for (int l = 1; l < va.levels(); ++l)
        for (uint32_t k = 0; k < 6; ++k) {
            const int side = n >> l, w = 1 << l;
            const int tx = int(rng() % uint32_t(side)), ty = int(rng() % uint32_t(side));
            double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
            for (int y = ty * w; y < (ty + 1) * w; ++y)
                for (int x = tx * w; x < (tx + 1) * w; ++x) {
                    sa += a.at(x, y);
                    sb += b.at(x, y);
                }
            const double ma = sa / (w * w), mb = sb / (w * w);
            for (int y = ty * w; y < (ty + 1) * w; ++y)
                for (int x = tx * w; x < (tx + 1) * w; ++x) {
                    saa += (a.at(x, y) - ma) * (a.at(x, y) - ma);
                    sbb += (b.at(x, y) - mb) * (b.at(x, y) - mb);
                    sab += (a.at(x, y) - ma) * (b.at(x, y) - mb);
                }
            const double var = saa / (w * w), varB = sbb / (w * w), cov = sab / (w * w);
            SCOPED_TRACE("level " + std::to_string(l) + " texel " + std::to_string(tx) + "," + std::to_string(ty));
            EXPECT_NEAR(va.mean(l, tx, ty), ma, 1.2e-7);
            EXPECT_NEAR(va.moment(l, tx, ty), var, 1e-4 * var + 1e-12);
            EXPECT_NEAR(cab.mean(l, tx, ty), ma, 1.2e-7);
            EXPECT_NEAR(cab.moment(l, tx, ty), cov, 1e-4 * std::sqrt(var * varB) + 1e-12);
        }
}

TEST(StatsPyramid, IsTheSameForAnyThreadCount) {
    const Image e = example(SpectrumShape::LowPass, 8, 0, 0, 3, 256),
                f = example(SpectrumShape::LowPass, 8, 0, 0, 4, 256);
    const auto levelsOf = [&](int threads) {
        ThreadLimit limit(threads);
        const StatsPyramid v(e), c = StatsPyramid::covariance(e, f);
        std::vector<Image> out;
        for (int l = 0; l < v.levels(); ++l) {
            out.push_back(v.interleavedLevel(l, 2));
            out.push_back(c.interleavedLevel(l, 2));
        }
        return out;
    };
    const std::vector<Image> one = levelsOf(1), all = levelsOf(0);
    ASSERT_EQ(one.size(), all.size());
    for (size_t i = 0; i < one.size(); ++i)
        EXPECT_TRUE(std::equal(one[i].data().begin(), one[i].data().end(), all[i].data().begin())) << i;
}

TEST(Footprint, IsotropicAndAnisotropicProbesFollowTheOpenGlRule) {
    Jacobian j;
    j.dudx = 32.0 / 256;  // 32 texels along x
    j.dvdy = 4.0 / 256;   // 4 texels along y
    const Footprint iso = makeFootprint(0.5, 0.5, j, 256, 8, 1);
    ASSERT_EQ(iso.count(), 1);
    EXPECT_FLOAT_EQ(iso.probe(0).lod, 5.0f);
    const Footprint a16 = makeFootprint(0.5, 0.5, j, 256, 8, 16);
    ASSERT_EQ(a16.count(), 8);
    EXPECT_FLOAT_EQ(a16.probe(0).lod, 2.0f);  // log2(32 / 8)
    double su = 0;
    for (int k = 0; k < a16.count(); ++k) {
        EXPECT_DOUBLE_EQ(a16.probe(k).v, 0.5);
        EXPECT_FLOAT_EQ(a16.probe(k).weight, 1.0f / 8);
        su += a16.probe(k).u;
    }
    EXPECT_NEAR(su / 8, 0.5, 1e-12);
    EXPECT_NEAR(a16.probe(7).u - a16.probe(0).u, j.dudx * 7.0 / 8.0, 1e-12);
    const Footprint a4 = makeFootprint(0.5, 0.5, j, 256, 8, 4);
    ASSERT_EQ(a4.count(), 4);
    EXPECT_FLOAT_EQ(a4.probe(0).lod, 3.0f);  // log2(32 / 4)
    // Magnification clamps to level 0; huge footprints to the top level.
    j.dudx = j.dvdy = 0.1 / 256;
    EXPECT_FLOAT_EQ(makeFootprint(0, 0, j, 256, 8, 1).probe(0).lod, 0.0f);
    j.dudx = j.dvdy = 10.0;
    EXPECT_FLOAT_EQ(makeFootprint(0, 0, j, 256, 8, 1).probe(0).lod, 8.0f);
}

TEST(FootprintEstimator, LevelZeroTexelIsTheUnfilteredNoise) {
    const auto n = noisePair(example(SpectrumShape::LowPass, 8, 0, 0, 1, 128),
                             example(SpectrumShape::Ring, 12, 3, 0, 2, 128), 5, 6);
    const FootprintEstimator est(n, false);
    for (int i = 0; i < 50; ++i) {
        const double u = 0.37 * i - 3.1, v = 0.11 * i + 0.7;
        const auto t = est.texel(u, v, 0, VarianceEstimator::Paper);
        EXPECT_EQ(t.mean[0], n.channel(0).blend(triangleGrid(u, v), periodFraction(u), periodFraction(v)));
        EXPECT_EQ(t.mean[1], n.channel(1).blend(triangleGrid(u, v), periodFraction(u), periodFraction(v)));
        EXPECT_EQ(t.var[0], 0.0f);
    }
}

// estimate's single-texel shortcut returns what the kernel's loop returns,
// bit for bit (every level, every estimator, with and without the
// covariance pyramid); footprints with a fractional level or several probes
// go through the loop itself.
TEST(FootprintEstimator, SingleTexelShortcutIsTheKernelLoopBitForBit) {
    const Image e = example(SpectrumShape::LowPass, 6, 0, 0, 4, 128);
    const auto same = [](const FootprintStats& a, const FootprintStats& b) {
        return a.mean == b.mean && a.varX == b.varX && a.varY == b.varY && a.cov == b.cov;
    };
    for (const bool covariance : {false, true}) {
        const auto n = noisePair(e, example(SpectrumShape::Ring, 12, 3, 0, 2, 128), 5, covariance ? 5 : 6);
        const FootprintEstimator est(n, covariance);
        int covariances = 0;
        for (const VarianceEstimator mode :
             {VarianceEstimator::Paper, VarianceEstimator::DeliotHeitz, VarianceEstimator::SubProbes}) {
            int shortcuts = 0;
            for (int i = 0; i < 200; ++i) {
                Jacobian j;  // 2^(i mod 9) texels a pixel (levels 0–7, then clamped at the top), or a fraction
                j.dudx = j.dvdy = std::ldexp(1.0, i % 9) / 128.0 * (i % 4 == 3 ? 1.37 : 1.0);
                if (i % 5 == 4) j.dvdx = 0.8 * j.dudx;  // anisotropic: several probes
                const Footprint f = makeFootprint(0.173 * i - 5.3, 0.061 * i + 2.9, j, 128, est.maxLod(), 8);
                const kernel::ProbeLevels levels = kernel::probeLevels(f.layout.lod, est.maxLod(), f.layout.count);
                // The shortcut's own condition (sub-probes: only a magnified pixel or one at the top level).
                const bool shortcut = kernel::isSingleTexel(f.layout.count, levels.frac) &&
                                      kernel::subProbesPerSide(f.layout, subProbesOf(mode), est.maxLod()) == 1;
                shortcuts += shortcut;
                const FootprintStats a = est.estimate(f, mode), b = est.kernelEstimate(f, mode);
                EXPECT_TRUE(same(a, b)) << "footprint " << i << ", level " << f.layout.lod;
                covariances += a.cov != 0.0f;
                // At the top level a footprint covers the example: sub-probes read its whole statistics too.
                if (mode == VarianceEstimator::SubProbes && f.layout.count == 1 &&
                    f.layout.lod == float(est.maxLod())) {
                    EXPECT_TRUE(same(a, est.estimate(f, VarianceEstimator::Paper))) << "footprint " << i;
                }
            }
            // The shortcut is taken, so the comparison covers it.
            EXPECT_GT(shortcuts, mode == VarianceEstimator::SubProbes ? 20 : 50)
                << enumName(kVarianceEstimatorNames, mode);
        }
        if (covariance) {
            EXPECT_GT(covariances, 300);  // and reads the covariance pyramid (0 at level 0)
        }
    }
}

TEST(TiledField, SharedOffsetsNeedOneSeedAndCovarianceNeedsSharedOffsets) {
    const Image e = example(SpectrumShape::LowPass, 6, 0, 0, 4, 64);
    const auto noise = [&](uint32_t seed) {
        return TilingBlendingNoise(std::make_shared<const NoiseExample>(e), seed);
    };
    EXPECT_EQ(test::inputErrorOf([&] {
                  TiledField({noise(1), noise(2)}, GridLayout::plane(kDensity), OffsetSharing::Shared);
              }).parameter(),
              "offsets");
    const TiledField independent({noise(1), noise(1)}, GridLayout::plane(kDensity), OffsetSharing::Independent);
    EXPECT_FALSE(independent.shared());
    EXPECT_EQ(test::inputErrorOf([&] { FootprintEstimator(independent, true); }).parameter(), "covariance");
    EXPECT_EQ(test::inputErrorOf([&] {
                  TiledField({}, GridLayout::plane(kDensity), OffsetSharing::Independent);
              }).parameter(),
              "channels");
    const TiledField three({noise(1), noise(1), noise(1)}, GridLayout::plane(kDensity), OffsetSharing::Shared);
    EXPECT_EQ(three.channelCount(), 3);
    EXPECT_EQ(test::inputErrorOf([&] { FootprintEstimator(three, true); }).parameter(), "field");
}

TEST(FootprintEstimator, CovarianceOfANoiseWithItselfIsItsVariance) {
    const Image e = example(SpectrumShape::LowPass, 6, 0, 0, 4, 128);
    const auto n = noisePair(e, e, 9, 9);  // E' = E, shared offsets
    const FootprintEstimator est(n, true);
    for (int i = 0; i < 40; ++i) {
        Jacobian j;
        j.dudx = (1 + i) / 128.0;
        j.dvdx = 0.3 * (1 + i) / 128.0;
        j.dvdy = (1 + i % 7) / 128.0;
        const FootprintStats s = est.estimate(makeFootprint(0.1 * i, 0.07 * i, j, 128, est.maxLod(), 8));
        EXPECT_FLOAT_EQ(s.cov, s.varX);
        EXPECT_FLOAT_EQ(s.varX, s.varY);
        EXPECT_GT(s.varX, 0.0f);
    }
}

// Mean absolute error of μ̂_x and σ̂_x against brute-force statistics over
// random footprints of a given size in texels (isotropic or 4–8:1 anisotropic).
struct Errors {
    double mu = 0, sigma = 0, sigmaDh = 0;
};

static Errors measure(const TiledField& n, int size, bool aniso, int count) {
    const FootprintEstimator est(n, false);
    const int w = est.exampleSize();
    Errors e;
    for (int i = 0; i < count; ++i) {
        const UInt3 h = pcg3d({uint32_t(i), uint32_t(size), aniso ? 7u : 3u});
        const double u = unitFloat(h.x) * 10, v = unitFloat(h.y) * 10;
        Jacobian j;
        if (aniso) {
            const double angle = unitFloat(h.z) * 3.14159, ratio = 4.0 + 4.0 * unitFloat(h.x ^ h.y);
            j.dudx = size * std::cos(angle) / w;
            j.dvdx = size * std::sin(angle) / w;
            j.dudy = -size / ratio * std::sin(angle) / w;
            j.dvdy = size / ratio * std::cos(angle) / w;
        } else {
            j.dudx = j.dvdy = double(size) / w;
        }
        const FootprintStats exact = bruteForceStats(n, u, v, j, 256);
        const Footprint f = makeFootprint(u, v, j, w, est.maxLod(), aniso ? 16 : 1);
        const FootprintStats paper = est.estimate(f), dh = est.estimate(f, VarianceEstimator::DeliotHeitz);
        e.mu += std::abs(paper.mean[0] - exact.mean[0]);
        e.sigma += std::abs(paper.sigmaX() - exact.sigmaX());
        e.sigmaDh += std::abs(dh.sigmaX() - exact.sigmaX());
    }
    e.mu /= count;
    e.sigma /= count;
    e.sigmaDh /= count;
    return e;
}

// Bounds: about twice the errors measured for these noises and seeds (60 or
// 40 footprints per size; measured on 2026-11-23: low-frequency μ̂ 0.0002,
// 0.0045, 0.039, 0.027 and σ̂ 0.0070, 0.0061, 0.022, 0.021 for sizes 1, 4, 16,
// 64; high-frequency μ̂ ≤ 0.017, 0.017, 0.0094, 0.0009 and σ̂ ≤ 0.016, 0.032,
// 0.029, 0.019 for 2, 8, 32, 128). The paper's Table 1 has the same orders of
// magnitude (μ̂ up to 0.085 / 0.11, σ̂ up to 0.036 / 0.048). At one texel σ̂
// is 0 by construction (V_0 = 0) while the bilinear noise still varies a
// little inside the texel, hence the σ̂ bound there.
struct Bound {
    int size;
    double mu, sigma;
};

// Asserts the bounds for every footprint size and footprint shape, and that
// per-texel variances (paper) beat one constant per LOD (Deliot–Heitz).
static void checkBounds(const TiledField& n, std::initializer_list<Bound> bounds, std::initializer_list<bool> shapes,
                        int count) {
    double paperSigma = 0, dhSigma = 0;
    for (const Bound& b : bounds)
        for (bool aniso : shapes) {
            const Errors e = measure(n, b.size, aniso, count);
            EXPECT_LT(e.mu, b.mu) << "footprint " << b.size << (aniso ? " aniso" : "");
            EXPECT_LT(e.sigma, b.sigma) << "footprint " << b.size << (aniso ? " aniso" : "");
            paperSigma += e.sigma;
            dhSigma += e.sigmaDh;
        }
    EXPECT_LT(paperSigma, dhSigma);
}

TEST(FootprintEstimator, LowFrequencyIsotropicNoiseErrorsAreBounded) {
    const auto n = noisePair(example(SpectrumShape::LowPass, 4, 0, 0, 10, 256),
                             example(SpectrumShape::LowPass, 4, 0, 0, 11, 256), 77, 78);
    checkBounds(n, {{1, 0.001, 0.014}, {4, 0.01, 0.012}, {16, 0.08, 0.045}, {64, 0.06, 0.045}}, {false}, 60);
}

TEST(FootprintEstimator, HighFrequencyAnisotropicNoiseErrorsAreBounded) {
    const auto n = noisePair(example(SpectrumShape::BiLobe, 32, 2, 30, 12, 256),
                             example(SpectrumShape::BiLobe, 32, 2, 120, 13, 256), 79, 80);
    checkBounds(n, {{2, 0.035, 0.035}, {8, 0.035, 0.065}, {32, 0.02, 0.06}, {128, 0.003, 0.04}}, {false, true}, 40);
}

// The 8-bit packing (paper §5) changes the estimates by about its
// quantisation step: means by ≤ 1/510, σ̂ by a few thousandths.
TEST(FootprintEstimator, EightBitPackingLossIsSmall) {
    const auto n = noisePair(example(SpectrumShape::LowPass, 8, 0, 0, 31, 256),
                             example(SpectrumShape::Ring, 20, 3, 0, 32, 256), 3, 4);
    const FootprintEstimator full(n, false), packed(n, false, true);
    double dmu = 0, dsigma = 0, maxMu = 0;
    const int count = 2000;
    for (int i = 0; i < count; ++i) {
        const UInt3 h = pcg3d({uint32_t(i), 5, 6});
        Jacobian j;
        j.dudx = j.dvdy = std::exp2(7.0 * unitFloat(h.z)) / 256.0;  // 1 to 128 texels
        const Footprint f = makeFootprint(unitFloat(h.x) * 4, unitFloat(h.y) * 4, j, 256, full.maxLod(), 1);
        const FootprintStats a = full.estimate(f), b = packed.estimate(f);
        dmu += std::abs(a.mean[0] - b.mean[0]);
        maxMu = std::max(maxMu, double(std::abs(a.mean[0] - b.mean[0])));
        dsigma += std::abs(a.sigmaX() - b.sigmaX());
    }
    EXPECT_LT(maxMu, 1.5 / 255.0);  // rounding of three tiles, weights Σw ≤ √3
    EXPECT_LT(dmu / count, 1.0 / 510.0);
    EXPECT_LT(dsigma / count, 0.004);
    EXPECT_GT(dmu, 0.0);  // the packing is really applied
}
