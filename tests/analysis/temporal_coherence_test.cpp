// Temporal coherence (thesis §2.1.1): per-frame appearance and its change
// over a sequence, on synthetic sequences and on the zoom texture.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "stochtex/analysis/temporal_coherence.h"
#include "stochtex/core/error.h"
#include "stochtex/studies/temporal_coherence_study.h"
#include "test_util.h"

namespace stochtex {
namespace {

Image whiteNoise(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Image img(n, n, 1);
    for (float& v : img.data()) v = u(rng);
    return img;
}

// A 3×3 box blur (periodic): the same noise with its high frequencies cut.
Image boxBlur(const Image& a) {
    Image b(a.width(), a.height(), 1);
    const int w = a.width(), h = a.height();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) s += a.at((x + dx + w) % w, (y + dy + h) % h);
            b.at(x, y) = float(s / 9.0);
        }
    return b;
}

// A still sequence does not move; each figure is the frame's own.
TEST(TemporalCoherence, AStillSequenceHoldsStill) {
    TemporalCoherenceMeter m(16, SpectrumWindow::Hann);
    const Image f = whiteNoise(64, 3);
    for (int k = 0; k < 5; ++k) m.add(f, 0.5 * k);
    const TemporalCoherence c = m.result();
    ASSERT_EQ(c.frames.size(), 5u);
    EXPECT_EQ(c.meanChange, 0.0);
    EXPECT_EQ(c.contrastChange, 0.0);
    EXPECT_EQ(c.scaleChange, 0.0);
    EXPECT_EQ(c.spectrumChange, 0.0);
    EXPECT_NEAR(c.scaleVariation, 0.0, 1e-12);
    EXPECT_NEAR(c.frames[0].mean, 0.5, 0.01);                  // U(0, 1) over 4096 pixels: σ/√n = 0.0045
    EXPECT_NEAR(c.frames[0].contrast, std::sqrt(1.0 / 12), 0.01);  // σ = 0.2887
    // White noise: the power-weighted mean |f| over the disc |f| ≤ 0.5 of a
    // flat spectrum is 2/3 · 0.5 = 1/3 (the Hann window smears it a little).
    EXPECT_NEAR(c.frames[0].meanFrequency, 1.0 / 3.0, 0.03);
    EXPECT_DOUBLE_EQ(c.frames[4].time, 2.0);
    // The sequence's means are the frame's own (1e-15: five divided terms summed).
    EXPECT_NEAR(c.meanContrast, c.frames[0].contrast, 1e-15);
    EXPECT_NEAR(c.meanFrequency, c.frames[0].meanFrequency, 1e-15);
}

// Fresh white noise every frame keeps its look (only the realisation
// changes); alternating sharp and blurred noise loses its high frequencies
// every other frame — the thesis's n = 3 symptom — and the scale figures see it.
TEST(TemporalCoherence, LosingHighFrequenciesIsALossOfCoherence) {
    TemporalCoherenceMeter fresh(16, SpectrumWindow::Hann), blinking(16, SpectrumWindow::Hann);
    for (int k = 0; k < 8; ++k) {
        const Image f = whiteNoise(64, 10 + k);
        fresh.add(f, k);
        blinking.add(k % 2 ? boxBlur(f) : f, k);
    }
    const TemporalCoherence a = fresh.result(), b = blinking.result();
    EXPECT_LT(a.scaleVariation, 0.03);  // one realisation's mean |f| varies by ~1%
    EXPECT_GT(b.scaleVariation, 0.25);  // the blur halves the mean |f|
    EXPECT_GT(b.scaleChange, 10 * a.scaleChange);
    EXPECT_GT(b.contrastChange, 10 * a.contrastChange);
    EXPECT_GT(b.spectrumChange, 3 * a.spectrumChange);
    EXPECT_LT(std::abs(b.meanChange), 0.02);  // the blur keeps the mean
    // The means over the sequence, which the relative changes divide by:
    // halfway between the sharp and the blurred frames' (1e-12: float sums).
    double contrast = 0, frequency = 0;
    for (const FrameAppearance& f : b.frames) contrast += f.contrast, frequency += f.meanFrequency;
    EXPECT_NEAR(b.meanContrast, contrast / 8, 1e-12);
    EXPECT_NEAR(b.meanFrequency, frequency / 8, 1e-12);
    EXPECT_LT(b.meanContrast, b.frames[0].contrast);
    EXPECT_GT(b.meanContrast, b.frames[1].contrast);
}

TEST(TemporalCoherence, ErrorsNameTheProblem) {
    EXPECT_EQ(test::inputErrorOf([] { TemporalCoherenceMeter(2, SpectrumWindow::Hann); }).parameter(), "radialBins");
    TemporalCoherenceMeter m(8, SpectrumWindow::Hann);
    m.add(whiteNoise(32, 1), 0);
    EXPECT_THROW(m.result(), InputError);  // one frame
    EXPECT_THROW(m.add(whiteNoise(16, 1), 1), InputError);
    TemporalCoherenceOptions o;
    o.times = {0.0};
    EXPECT_EQ(test::inputErrorOf([&] { validateTemporalCoherence(o); }).parameter(), "frames");
    o.times = {0.0, std::nan("")};
    EXPECT_EQ(test::inputErrorOf([&] { validateTemporalCoherence(o); }).parameter(), "time");
    o.times = {0.0, 1.0};
    o.region.width = 4;
    EXPECT_EQ(test::inputErrorOf([&] { validateTemporalCoherence(o); }).parameter(), "size");
}

// The thesis's observation (§2.1.1, Figure 2.4) as a measurement: the zoom
// texture with n = 3 layers changes its dominant scale and its contrast over
// time much more than with n = 8 (one white-noise instance, 32 frames of
// 256² over two periods of the zoom; measured 0.054 against 0.016 for the
// scale, 0.077 against 0.015 for the contrast). The ring-averaged spectra's
// frame-to-frame change is dominated by the realisation's own noise at this
// size (0.058 against 0.034 decades) and is not asserted.
TEST(TemporalCoherence, ZoomTextureNeedsEnoughLayers) {
    ZoomParams params;
    ZoomBase base;
    base.size = 256;
    const ZoomSource zoom(params, base);
    LayerCoherenceOptions o;
    o.layers = {3, 8};
    o.frames.region = SourceRegion::centred(256, 256);
    o.frames.times = evenTimes(0.0, 1.0 / 16, 32);
    const LayerCoherenceResult r = layerCoherenceStudy(zoom, o);
    ASSERT_EQ(r.perLayers.size(), 2u);
    const TemporalCoherence &n3 = r.perLayers[0], &n8 = r.perLayers[1];
    std::printf("[ info ] n = 3: scale σ/μ %.4f, |Δ log P| %.4f, contrast σ/μ %.4f; n = 8: %.4f, %.4f, %.4f\n",
                n3.scaleVariation, n3.spectrumChange, n3.contrastVariation, n8.scaleVariation, n8.spectrumChange,
                n8.contrastVariation);
    EXPECT_GT(n3.scaleVariation, 2.0 * n8.scaleVariation);
    EXPECT_GT(n3.contrastVariation, 3.0 * n8.contrastVariation);
    ASSERT_EQ(r.table.rows.size(), 2u);
    EXPECT_EQ(r.table.rows[1][0].text, "8");
}

// The coherence command's one call: the study of the frames and, with layer
// counts, the curve over n, the same numbers as the two studies run apart,
// and the page section with both; layer counts need the zoom texture and are
// checked before any work.
TEST(TemporalCoherence, ReportRunsBothStudies) {
    ZoomBase base;
    base.size = 64;
    const ZoomSource zoom(ZoomParams{}, base);
    CoherenceReportOptions o;
    o.frames.region = SourceRegion::centred(32, 32);
    o.frames.times = evenTimes(0.0, 0.25, 3);
    o.layers = {3, 8};
    const CoherenceReport r = coherenceReport(zoom, o);
    const TemporalCoherenceResult alone = temporalCoherenceStudy(zoom, o.frames);
    EXPECT_EQ(r.frames.coherence.scaleVariation, alone.coherence.scaleVariation);  // the same run: exact
    EXPECT_EQ(r.frames.summary.csv(), alone.summary.csv());
    ASSERT_TRUE(r.layers.has_value());
    EXPECT_EQ(r.layers->table.csv(), layerCoherenceStudy(zoom, {o.layers, o.frames}).table.csv());
    ASSERT_EQ(r.report.sections.size(), 2u);
    EXPECT_EQ(r.report.sections[0].figures.size(), 2u);
    ASSERT_EQ(r.report.sections[1].figures.size(), 1u);
    EXPECT_EQ(r.report.sections[1].figures[0].file, "layers.png");
    const std::string page = reportPage(r.report);
    EXPECT_NE(page.find(r.frames.summary.html()), std::string::npos);
    EXPECT_NE(page.find("<h2>Over the number of layers n"), std::string::npos);
    EXPECT_NE(page.find("layers.png"), std::string::npos);
    EXPECT_EQ(page.find(r.frames.perFrame.html()), std::string::npos);  // frames.csv only

    o.layers.clear();
    const CoherenceReport single = coherenceReport(zoom, o);
    EXPECT_FALSE(single.layers.has_value());
    ASSERT_EQ(single.report.sections.size(), 1u);
    EXPECT_EQ(reportPage(single.report).find("layers.png"), std::string::npos);

    o.layers = {0};
    EXPECT_EQ(test::inputErrorOf([&] { validateCoherenceReport(o, zoom); }).parameter(), "layersList");
    const ImageSequenceSource images({whiteNoise(32, 1), whiteNoise(32, 2), whiteNoise(32, 3)});
    o.layers = {3};
    o.frames.region = {32, 32, 0, 0};
    o.frames.times = evenTimes(0, 1, 3);  // image files: frame k at time k
    EXPECT_EQ(test::inputErrorOf([&] { validateCoherenceReport(o, images); }).parameter(), "layersList");
    o.layers.clear();
    EXPECT_NO_THROW(validateCoherenceReport(o, images));
}

}  // namespace
}  // namespace stochtex
