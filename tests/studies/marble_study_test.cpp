// The marble study (studies/marble_study.h, thesis §2.7.2 and §2.8): the
// artifacts of the continuous scaling, measured, and their absence with the
// blended fix, at a reduced size.
#include "stochtex/studies/marble_study.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "stochtex/core/error.h"

namespace stochtex {
namespace {

// The default texture and frames (the stretch crosses 0 inside them), fewer
// seeds and frames.
MarbleStudyOptions smallStudy() {
    MarbleStudyOptions o;
    o.instances = 256;
    o.spectrumInstances = 4;
    o.frames = 6;
    return o;
}

// Row `row` of a table, column `key`, as a number.
double cell(const Table& t, size_t row, const std::string& key) {
    for (size_t c = 0; c < t.columns.size(); ++c)
        if (t.columns[c].key == key) return t.rows.at(row).at(c).number.value();
    ADD_FAILURE() << "no column " << key;
    return NAN;
}

const MarbleStudyResult& result() {
    static const MarbleStudyResult r = marbleStudy(smallStudy());
    return r;
}

TEST(MarbleStudy, ReferencePointIsWhereTheScalingShearsTheNoise) {
    const MarbleStudyOptions o = smallStudy();
    const MarbleStudyResult& r = result();
    // x = −period/4 (|∂l/∂x| largest), y = (256 − 96)/4.
    EXPECT_EQ(r.pointX, -32.0);
    EXPECT_EQ(r.pointY, 40.0);
    EXPECT_DOUBLE_EQ(r.pointAnisotropy, marbleAnisotropy(o.marble, -32, 40));
    EXPECT_GT(r.pointAnisotropy, 3.0);
    // Only scaled where l is flat (x = 0, 64: ∂l/∂x = 0), the folds infinite.
    EXPECT_NEAR(marbleAnisotropy(o.marble, 0, 50), 1.0, 1e-12);
    EXPECT_NEAR(marbleAnisotropy(o.marble, 64, -50), 1.0, 1e-9);
}

TEST(MarbleStudy, ScalingStepAloneIsElongatedOnlyWithTheContinuousScaling) {
    // Rows: marble × scalings, scaling-only × scalings, base noise.
    const Table& t = result().correlation;
    ASSERT_EQ(t.rows.size(), 5u);
    // The scaled cell is about σ₁/σ₂ longer than wide (the tent correlation
    // of a randomly placed cell, thresholded at ½, is a slanted
    // parallelogram of that ratio).
    const double expected = result().pointAnisotropy;
    EXPECT_NEAR(cell(t, 2, "elongation"), expected, 0.3 * expected);  // scaling-only, continuous
    // Blended-corrected: square cells of two scales, mixed by a weight that
    // varies along x (measured 1.63).
    EXPECT_LT(cell(t, 3, "elongation"), 2.0);
    EXPECT_GT(cell(t, 2, "elongation"), 1.5 * cell(t, 3, "elongation"));
    EXPECT_GT(cell(t, 0, "elongation"), 2.0 * cell(t, 1, "elongation"));  // the marble's vein too
}

TEST(MarbleStudy, GradientNoiseHasAntiCorrelatedLobesTheScalingStepHasNot) {
    // 256 seeds: a standard error of 1/16 per value, which a cell keeps
    // whole; 4 of them bound the scaling step's estimator noise. The base
    // gradient noise's lobes are far below.
    const Table& t = result().correlation;
    EXPECT_LT(cell(t, 4, "anti_correlation"), -0.5);
    EXPECT_GT(cell(t, 2, "anti_correlation"), -0.25);
    EXPECT_GT(cell(t, 3, "anti_correlation"), -0.25);
    EXPECT_LT(cell(t, 4, "anti_correlation"), cell(t, 2, "anti_correlation") - 0.3);
}

TEST(MarbleStudy, StretchingMakesTheSpectrumAnisotropic) {
    // Rows: (marble, scaled noise) × scalings. The base noise is round
    // (λ₁/λ₂ ≈ 1.07 over 16 seeds); the blended scales vary along x, which
    // leaves some anisotropy (≈ 1.3), far from the stretched noise's.
    const Table& t = result().spectra;
    ASSERT_EQ(t.rows.size(), 4u);
    EXPECT_GT(cell(t, 1, "anisotropy"), 2.0 * cell(t, 3, "anisotropy"));  // scaled noise
    EXPECT_LT(cell(t, 3, "anisotropy"), 1.45);
    EXPECT_GT(cell(t, 0, "anisotropy"), 1.5 * cell(t, 2, "anisotropy"));  // the marble (Figure 2.22)
}

TEST(MarbleStudy, ContinuousScalingSlidesOutwardTheFixDoesNot) {
    // Rows: marble × scalings, scaled noise × scalings.
    const Table& t = result().sliding;
    ASSERT_EQ(t.rows.size(), 4u);
    const double rate = cell(t, 0, "scaling_rate");
    EXPECT_NEAR(rate, std::exp2(1.0 / 24) - 1, 1e-12);
    // The scaled noise alone moves at the scaling's rate (Farnebäck within 25 %)…
    EXPECT_NEAR(cell(t, 2, "expansion_rate"), rate, 0.25 * rate);
    // …the marble more slowly (its bands stay) but outward…
    EXPECT_GT(cell(t, 0, "expansion_rate"), 0.4 * rate);
    EXPECT_GT(cell(t, 0, "outward_fraction"), 0.8);
    // …and with the fix neither moves.
    EXPECT_LT(std::abs(cell(t, 1, "expansion_rate")), 0.15 * rate);
    EXPECT_LT(std::abs(cell(t, 3, "expansion_rate")), 0.15 * rate);
}

TEST(MarbleStudy, RefusesBadOptionsNamingTheParameter) {
    const auto parameterOf = [](const MarbleStudyOptions& o) {
        try {
            validateMarbleStudy(o);
        } catch (const InputError& e) {
            return e.parameter();
        }
        return std::string("(none)");
    };
    MarbleStudyOptions o = smallStudy();
    EXPECT_EQ(parameterOf(o), "(none)");
    o.correlationSize = 300;
    EXPECT_EQ(parameterOf(o), "correlationSize");
    o = smallStudy();
    o.scalings.clear();
    EXPECT_EQ(parameterOf(o), "scalings");
    o = smallStudy();
    o.slideRate = 50;
    o.frames = 100;
    EXPECT_EQ(parameterOf(o), "slideRate");
    o = smallStudy();
    o.marble.distortion = INFINITY;
    EXPECT_EQ(parameterOf(o), "distortion");
}

}  // namespace
}  // namespace stochtex
