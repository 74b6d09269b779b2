// A reduced `reproduce table1`: shape and sanity of the estimator errors.
#include "stochtex/analysis/estimator_error.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/texture_graph.h"
#include "stochtex/studies/paper.h"
#include "test_util.h"

namespace stochtex {
namespace {

TiledField noises(SpectrumShape shape, double f, double b, double theta) {
    return TiledField(
        {TilingBlendingNoise(std::make_shared<const NoiseExample>(test::example(shape, f, b, theta, 3, 128)), 11),
         TilingBlendingNoise(std::make_shared<const NoiseExample>(test::example(shape, f, b, theta, 4, 128)), 12)},
        GridLayout{}, OffsetSharing::Independent);
}

// The row of an estimator at a footprint side.
const EstimatorError& rowOf(const std::vector<EstimatorError>& rows, int footprint, const std::string& estimator) {
    for (const EstimatorError& e : rows)
        if (e.footprint == footprint && e.estimator == estimator) return e;
    throw std::runtime_error("no row " + estimator + " at " + std::to_string(footprint));
}

// The errors on one of Table 1's noises (0: low-pass, 1: bi-lobe; seed 1)
// at these footprint sides, `count` footprints each.
std::vector<EstimatorError> table1Errors(int which, std::vector<int> footprints, int count = 300) {
    EstimatorErrorOptions o;
    o.footprints = std::move(footprints);
    o.count = count;
    return measureEstimatorErrors(GraphPattern::build(table1PatternSpec(which, 1)).leafPairs().front(), o);
}

TEST(EstimatorError, ReducedTable1HasSaneNumbers) {
    EstimatorErrorOptions o;
    o.footprints = {2, 8, 32};
    o.count = 150;
    for (const auto& pair : {noises(SpectrumShape::LowPass, 6, 0, 0), noises(SpectrumShape::BiLobe, 16, 2, 30)}) {
        const auto rows = measureEstimatorErrors(pair, o);
        // 3 sizes × (kVarianceEstimatorNames, global), by size.
        const size_t perSize = kVarianceEstimatorNames.size() + 1;
        ASSERT_EQ(rows.size(), 3 * perSize);
        for (size_t i = 0; i < rows.size(); ++i) {
            const EstimatorError& r = rows[i];
            EXPECT_EQ(r.footprint, o.footprints[i / perSize]);
            EXPECT_EQ(r.estimator, i % perSize < kVarianceEstimatorNames.size()
                                       ? kVarianceEstimatorNames[i % perSize].first
                                       : std::string("global"));
            EXPECT_EQ(r.values, 300);
            // At 2 texels the 8×8 fine-mean sub-probes read level 0 at the
            // centres of an 8×8 grid over the footprint: the exact
            // statistics' own samples (8 per axis at least), so only float
            // rounding tells them apart (docs/RESULTS.md).
            if (r.estimator == "sub-probes-8x8-fine-means" && r.footprint == 2) {
                EXPECT_LT(r.muAbs, 1e-6);
                EXPECT_LT(r.sigmaRel, 1e-5);
                continue;
            }
            // No error at all would mean an estimate compared with itself.
            for (double v : {r.muAbs, r.muRel, r.sigmaAbs, r.sigmaRel}) EXPECT_GT(v, 1e-6);
            // Relative errors are absolute errors over references of known
            // size: μ ≈ ½ (so rel ≈ 2·abs), and σ ≤ 1/6.
            EXPECT_NEAR(r.meanMu, 0.5, 0.1);
            EXPECT_GT(r.muRel, 1.2 * r.muAbs);
            EXPECT_LT(r.muRel, 3.5 * r.muAbs + 1e-12);
            EXPECT_GE(r.sigmaRel, r.sigmaAbs / (1.0 / 6.0) * 0.5);
        }
        // Small footprints: both estimators beat "use the global mean and
        // variance" by a wide margin.
        const EstimatorError &paper = rowOf(rows, 2, "paper"), &dh = rowOf(rows, 2, "deliot-heitz"),
                             &global = rowOf(rows, 2, "global");
        EXPECT_LT(paper.muAbs, 0.5 * global.muAbs);
        EXPECT_LT(paper.sigmaAbs, 0.5 * global.sigmaAbs);
        EXPECT_LT(dh.muAbs, 0.5 * global.muAbs);
        // The paper's per-texel variances beat one constant per level.
        EXPECT_LT(paper.sigmaAbs, dh.sigmaAbs);
    }
}

// Issue 32's first estimator: each probe as 2×2 probes one level finer
// brings the spread of the footprint's values over its sub-squares into σ̂²
// (eq. 12 leaves it out: a footprint's three tiles are coherent over less
// than their wavelength). On Table 1's two noises (512² examples, 300
// footprints per size, measured 2026-12-05: σ̂ rel. 0.13/0.35 and 0.10/0.39
// low, 0.15/0.63 and 0.15/0.59 high at 2² and 4²), it at least halves the
// paper estimator's σ̂ error at 2–8 texels, and the mean error with it.
TEST(EstimatorError, SubProbesHalveTheSigmaErrorAtSmallFootprints) {
    const std::vector<int> footprints{2, 4, 8};
    for (int which = 0; which < 2; ++which) {
        const std::vector<EstimatorError> rows = table1Errors(which, footprints);
        for (const int f : footprints) {
            const EstimatorError &paper = rowOf(rows, f, "paper"), &sub = rowOf(rows, f, "sub-probes");
            EXPECT_LT(sub.sigmaRel, 0.5 * paper.sigmaRel) << table1NoiseName(which) << " " << f;
            EXPECT_LT(sub.muAbs, 0.5 * paper.muAbs) << table1NoiseName(which) << " " << f;
        }
    }
}

// The 4×4 sub-probes reach farther: Table 1's σ̂ target (at most half the
// paper's error) from 2 to 32 texels on the low-pass noise and to 16 on the
// bi-lobe (1000 footprints, docs/RESULTS.md: 0.07–0.42× and 0.04–0.45×);
// here at 16 and 32 texels, 300 footprints (the 2×2 sub-probes do not halve
// it at 32 on the low-pass noise, nor at 16 on the bi-lobe).
TEST(EstimatorError, SubProbes4x4HalveTheSigmaErrorUpTo32Texels) {
    const std::vector<int> footprints{16, 32};
    for (int which = 0; which < 2; ++which) {
        const std::vector<EstimatorError> rows = table1Errors(which, footprints);
        for (const int f : footprints) {
            if (which == 1 && f == 32) continue;  // the bi-lobe at 32 texels: 0.84× (docs/RESULTS.md)
            const double paper = rowOf(rows, f, "paper").sigmaRel, sub4 = rowOf(rows, f, "sub-probes-4x4").sigmaRel;
            std::printf("%s %d: sigma rel paper %.3f sub-probes-4x4 %.3f (%.2f)\n", table1NoiseName(which), f, paper,
                        sub4, sub4 / paper);
            EXPECT_LT(sub4, 0.5 * paper) << table1NoiseName(which) << " " << f;
        }
    }
}

// Sub-probes with fine means (8×8 sub-probes, each one's mean from 2×2
// reads one level finer, its variance at its square's level): on 1000
// footprints (docs/RESULTS.md) the σ̂ error is 0.00–0.21× the paper's from 2
// to 32 texels on both noises — issue 32's halving, where the 4×4
// sub-probes left the bi-lobe at 32 texels at 0.84× — and 0.52–0.68× at
// 64–128, where the 4×4 sub-probes' is above the paper's on the low-pass
// noise (1.11–1.26×); μ̂ is never worse than the paper's (a sub-probe mean
// read log2 √3 levels finer aliased there: 3.5× the paper's on the bi-lobe
// at 128). Here 300 footprints at 32, 64 and 128 texels.
TEST(EstimatorError, FineMeanSubProbesHalveThePaperAt32AndBeatItTo128Texels) {
    const std::vector<int> footprints{32, 64, 128};
    for (int which = 0; which < 2; ++which) {
        const std::vector<EstimatorError> rows = table1Errors(which, footprints);
        for (const int f : footprints) {
            const EstimatorError &paper = rowOf(rows, f, "paper"), &fine = rowOf(rows, f, "sub-probes-8x8-fine-means");
            const double sub4 = rowOf(rows, f, "sub-probes-4x4").sigmaRel;
            std::printf(
                "%s %d: sigma rel paper %.3f sub-probes-4x4 %.3f fine means %.3f (%.2f); mu abs paper %.5f "
                "fine means %.5f\n",
                table1NoiseName(which), f, paper.sigmaRel, sub4, fine.sigmaRel, fine.sigmaRel / paper.sigmaRel,
                paper.muAbs, fine.muAbs);
            const std::string where = std::string(table1NoiseName(which)) + " " + std::to_string(f);
            EXPECT_LT(fine.sigmaRel, 0.85 * paper.sigmaRel) << where;
            EXPECT_LT(fine.muAbs, 1.1 * paper.muAbs) << where;
            if (f == 32) {
                EXPECT_LT(fine.sigmaRel, 0.4 * paper.sigmaRel) << where;
                EXPECT_LT(fine.sigmaRel, 0.5 * sub4) << where;
            }
            if (f == 64 && which == 0) {
                EXPECT_LT(fine.sigmaRel, 0.6 * sub4) << where;
            }
        }
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
    const TiledField one({pair.channel(0)}, GridLayout{}, OffsetSharing::Independent);
    EXPECT_THROW(measureEstimatorErrors(one, EstimatorErrorOptions{}), std::invalid_argument);
}

// The folded derivative is an example like any other, so the paper's
// estimators hold on it with the errors they have on spectral noises: over
// 300 random footprints per size, μ̂ within 0.06 and σ̂ within 65 % of the
// exact footprint statistics on average (the ranges of Table 1's two noises
// at every size, docs/RESULTS.md), σ̂ better than Deliot–Heitz's constant
// variance, and both far better than no filtering data at small footprints.
TEST(EstimatorError, GraphDerivativeFieldIsFilteredLikeAnyExample) {
    const std::string text =
        R"({"size": 32, "nodes": {)" +
        std::string(
            R"("h": {"type": "spectral_noise", "size": 128, "seed": 9, "components": [{"shape": "ring", "frequency": 6, "bandwidth": 3}]},
        "du": {"type": "derivative", "input": "h", "angle": 0}, "dv": {"type": "derivative", "input": "h", "angle": 90},
        "c": {"type": "colormap", "x": "du", "y": "dv", "colormap": {"type": "gaussian"}})") +
        R"(}, "output": "c"})";
    const GraphPattern p =
        GraphPattern::build(parsePatternSpec(JsonReader(JsonReader::parse(text, "g.json"), "g.json"), "."));
    EstimatorErrorOptions o;
    o.footprints = {2, 4, 16, 64};
    o.count = 300;
    o.maxSamplesPerAxis = 128;
    const std::vector<EstimatorError> rows = measureEstimatorErrors(p.leafPairs().front(), o);
    for (int f : o.footprints) {
        const EstimatorError &paper = rowOf(rows, f, "paper"), &dh = rowOf(rows, f, "deliot-heitz"),
                             &global = rowOf(rows, f, "global");
        EXPECT_LT(paper.muAbs, 0.06) << "footprint " << f;
        EXPECT_LT(paper.sigmaRel, 0.65) << "footprint " << f;
        EXPECT_LE(paper.sigmaAbs, dh.sigmaAbs) << "footprint " << f;
        if (f <= 4) {
            EXPECT_LT(paper.muAbs, 0.5 * global.muAbs) << "footprint " << f;
        }
    }
}

}  // namespace
}  // namespace stochtex
