// Figures 10 and 11 (paper §6.4): the phasor variants and the procedural
// comparison; the filtering of the phasor sine pattern.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/studies/paper.h"
#include "stochtex/studies/phasor_figures.h"

namespace stochtex {
namespace {

// Both fields of the comparison carry the requested wave: the spectral
// centroid of each pattern's fundamental lobe is at the frequency within 8%
// and the orientation within 4° (one realisation's lobe scatters by a few
// percent; measured at 128²: 24 cycles, 30° → ours 23.7, 31.2°, procedural
// 24.6, 29.5°; 12 cycles, −45° → 11.7, −47.1° and 11.7, −44.7°), and the two
// lobes' spreads agree within 30% (measured 8%): the paper's field and the
// procedural one look alike at the same parameters.
TEST(PhasorFigures, Figure10ComparesTwoFieldsAtTheSameFrequencyAndOrientation) {
    Figure10Options o;
    o.size = 64;
    o.comparisonSize = 128;
    const Figure10Result r = figure10(o);
    ASSERT_EQ(r.figures.size(), 2u);
    EXPECT_EQ(r.figures[0].file, "figure10.png");
    EXPECT_EQ(r.figures[1].file, "figure10_comparison.png");
    EXPECT_EQ(r.table.rows.size(), 2u);
    for (const SpectralCentroid& c : r.centroids) {
        EXPECT_NEAR(c.frequency, 24.0, 0.08 * 24.0) << c.frequency;
        EXPECT_NEAR(c.orientation, 30.0, 4.0) << c.orientation;
    }
    EXPECT_NEAR(r.centroids[1].spread / r.centroids[0].spread, 1.0, 0.3);
    // Another wave: both follow it.
    o.field.frequency = 12;
    o.field.orientation = -45;
    const Figure10Result other = figure10(o);
    for (const SpectralCentroid& c : other.centroids) {
        EXPECT_NEAR(c.frequency, 12.0, 0.08 * 12.0) << c.frequency;
        EXPECT_NEAR(c.orientation, -45.0, 4.0) << c.orientation;
    }
}

TEST(PhasorFigures, Figure10RefusesBadParameters) {
    const auto parameterOf = [](Figure10Options o) {
        try {
            validateFigure10(o);
        } catch (const InputError& e) {
            return e.parameter();
        }
        return std::string();
    };
    Figure10Options o;
    o.field.frequency = 0;
    EXPECT_EQ(parameterOf(o), "frequency");
    o = {};
    o.field.bandwidth = -2;
    EXPECT_EQ(parameterOf(o), "bandwidth");
    o = {};
    o.comparisonSize = 8;
    EXPECT_EQ(parameterOf(o), "comparisonSize");
    EXPECT_THROW(figure10(o), InputError);
}

// Figure 11: the phasor sine pattern fades to its profile's mean colour as
// the footprint grows. m is the mean of linear(½ + ½ sin φ) over a period
// (sRGB decoded; computed here independently, 10⁵ points). At a footprint of
// 64 texels (6 periods of the 24-cycle noise) S̄ and Ŝ are within 0.02 of m
// (RGB 2-norm, mean over pixels; measured 0.0072 and 0.0008), from 0.55 at
// footprint 1 where the stripes are sharp; Ŝ stays within 0.02 of S̄ there
// (measured 0.0072).
TEST(PhasorFigures, Figure11FadesToTheProfilesMean) {
    Figure4Options o = figure11Options();
    EXPECT_EQ(o.figure, "figure11");
    EXPECT_FALSE(o.exactStatistics);
    ASSERT_TRUE(o.fadesTo.has_value());
    double m = 0;
    for (int k = 0; k < 100000; ++k)
        m += linearFromSrgb(float(0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * (k + 0.5) / 100000.0)));
    m /= 100000.0;
    for (float c : *o.fadesTo) EXPECT_NEAR(c, m, 1e-5);

    o.size = 32;
    o.referenceSamples = 16;
    o.footprints = {1, 16, 64};
    const Figure4Result r = figure4(o);
    ASSERT_EQ(r.columns.size(), 3u);
    const Figure4Column &near = r.columns[0], &far = r.columns[2];
    EXPECT_GT(near.meanFadeReference, 0.3);
    EXPECT_GT(near.meanFadeEstimated, 0.3);
    EXPECT_LT(far.meanFadeReference, 0.02);
    EXPECT_LT(far.meanFadeEstimated, 0.02);
    EXPECT_LT(far.meanErrorEstimated, 0.02);
    // The pixel centres keep the stripes' full contrast where S̄ has faded.
    EXPECT_GT(far.meanErrorNone, 0.3);
    for (size_t i = 1; i < r.columns.size(); ++i) {
        EXPECT_LT(r.columns[i].meanFadeReference, r.columns[i - 1].meanFadeReference);
        EXPECT_LT(r.columns[i].meanFadeEstimated, r.columns[i - 1].meanFadeEstimated);
    }
    // Rows: reference, estimated, error (no exact statistics): 3 images per footprint.
    EXPECT_EQ(r.figures.size(), 2u + 3u * 3u);
    EXPECT_EQ(r.figures[0].file, "figure11.png");
    // The pixel centres' error, the paper estimator's, one per estimator after
    // it (kVarianceEstimatorNames' order), the fades, then the reference's
    // samples and its change on doubling them.
    std::vector<std::string> keys, expected{"footprint", "mean_error_none", "mean_error_estimators"};
    for (const TableColumn& c : r.table.columns) keys.push_back(c.key);
    for (size_t e = 1; e < kVarianceEstimatorNames.size(); ++e) {
        std::string key = "mean_error_" + kVarianceEstimatorNames[e].first;
        std::replace(key.begin(), key.end(), '-', '_');
        expected.push_back(key);
    }
    for (const char* key : {"mean_fade_reference", "mean_fade_estimators", "reference_samples", "reference_change"})
        expected.push_back(key);
    EXPECT_EQ(keys, expected);
    EXPECT_NE(std::find(keys.begin(), keys.end(), "mean_error_sub_probes"), keys.end());
    for (const Figure4Column& c : r.columns) {
        EXPECT_TRUE(c.referenceSamples == 8 || c.referenceSamples == 16) << c.footprint << ": " << c.referenceSamples;
        EXPECT_EQ(c.exactSamples, 0);  // Figure 11 renders no exact statistics
    }
}

}  // namespace
}  // namespace stochtex
