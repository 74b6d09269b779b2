// A reduced `reproduce table1`: shape and sanity of the estimator errors.
#include "stochtex/analysis/estimator_error.h"

#include <gtest/gtest.h>

#include <memory>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "test_util.h"

namespace stochtex {
namespace {

TiledField noises(SpectrumShape shape, double f, double b, double theta) {
    return TiledField(
        {TilingBlendingNoise(std::make_shared<const NoiseExample>(test::example(shape, f, b, theta, 3, 128)), 11),
         TilingBlendingNoise(std::make_shared<const NoiseExample>(test::example(shape, f, b, theta, 4, 128)), 12)},
        kDefaultGridDensity, OffsetSharing::Independent);
}

TEST(EstimatorError, ReducedTable1HasSaneNumbers) {
    EstimatorErrorOptions o;
    o.footprints = {2, 8, 32};
    o.count = 150;
    for (const auto& pair : {noises(SpectrumShape::LowPass, 6, 0, 0), noises(SpectrumShape::BiLobe, 16, 2, 30)}) {
        const auto rows = measureEstimatorErrors(pair, o);
        ASSERT_EQ(rows.size(), 9u);  // 3 sizes × (paper, deliot-heitz, global)
        for (size_t i = 0; i < rows.size(); ++i) {
            const EstimatorError& r = rows[i];
            EXPECT_EQ(r.footprint, o.footprints[i / 3]);
            EXPECT_EQ(r.values, 300);
            for (double v : {r.muAbs, r.muRel, r.sigmaAbs, r.sigmaRel}) EXPECT_GE(v, 0.0);
            // Relative errors are absolute errors over references of known
            // size: μ ≈ ½ (so rel ≈ 2·abs), and σ ≤ 1/6.
            EXPECT_NEAR(r.meanMu, 0.5, 0.1);
            EXPECT_GT(r.muRel, 1.2 * r.muAbs);
            EXPECT_LT(r.muRel, 3.5 * r.muAbs + 1e-12);
            EXPECT_GE(r.sigmaRel, r.sigmaAbs / (1.0 / 6.0) * 0.5);
        }
        // Small footprints: both estimators beat "use the global mean and
        // variance" by a wide margin.
        const EstimatorError &paper = rows[0], &dh = rows[1], &global = rows[2];
        EXPECT_EQ(paper.estimator, "paper");
        EXPECT_EQ(global.estimator, "global");
        EXPECT_LT(paper.muAbs, 0.5 * global.muAbs);
        EXPECT_LT(paper.sigmaAbs, 0.5 * global.sigmaAbs);
        EXPECT_LT(dh.muAbs, 0.5 * global.muAbs);
        // The paper's per-texel variances beat one constant per level.
        EXPECT_LT(paper.sigmaAbs, dh.sigmaAbs);
    }
}

TEST(EstimatorError, IndependentOfThreadCount) {
    EstimatorErrorOptions o;
    o.footprints = {4};
    o.count = 40;
    const auto pair = noises(SpectrumShape::LowPass, 6, 0, 0);
    std::vector<EstimatorError> one;
    {
        ThreadLimit limit(1);
        one = measureEstimatorErrors(pair, o);
    }
    const auto all = measureEstimatorErrors(pair, o);
    for (size_t i = 0; i < all.size(); ++i) {
        EXPECT_EQ(one[i].muAbs, all[i].muAbs);
        EXPECT_EQ(one[i].sigmaRel, all[i].sigmaRel);
    }
    o.count = 0;
    const InputError e = test::inputErrorOf([&] { measureEstimatorErrors(pair, o); });
    EXPECT_EQ(e.parameter(), "count");
    EXPECT_STREQ(e.what(), "count must be in [1, 1e6], got 0");
}

TEST(EstimatorError, NeedsTwoChannels) {
    const TiledField pair = noises(SpectrumShape::LowPass, 6, 0, 0);
    const TiledField one({pair.channel(0)}, kDefaultGridDensity, OffsetSharing::Independent);
    EXPECT_THROW(measureEstimatorErrors(one, EstimatorErrorOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace stochtex
