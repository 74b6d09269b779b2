#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

#include "stochtex/analysis/optical_flow.h"
#include "stochtex/analysis/power_spectrum.h"
#include "stochtex/core/error.h"
#include "test_util.h"

namespace stochtex {
namespace {

using test::example;

// White noise U(0, 1) has the flat spectrum σ² = 1/12 (the normalisation by
// Σw² makes the window's loss of power disappear). 64 instances of 64×64:
// each radial bin of width 1/32 cycle/pixel averages ≥ 8 frequencies × 64
// periodograms, whose relative standard error is ≤ 1/√(512/2) ≈ 6% (the Hann
// window correlates neighbours, halving the independent count): 20% is > 3σ.
TEST(PowerSpectrum, WhiteNoiseIsFlatAtItsVariance) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    SpectrumAccumulator acc(64, 64, SpectrumWindow::Hann);
    for (int i = 0; i < 64; ++i) {
        Image img(64, 64, 1);
        for (float& v : img.data()) v = u(rng);
        acc.add(img);
    }
    const RadialProfile p = radialProfile(acc.mean(), 16);
    ASSERT_GE(p.power.size(), 15u);
    for (size_t b = 1; b < p.power.size(); ++b) EXPECT_NEAR(p.power[b] / (1.0 / 12), 1.0, 0.2) << "bin " << b;
    // Flat in angle too, and its shape says so.
    const SpectrumGeometry s = spectrumGeometry(acc.mean(), 0.05, 0.5);
    EXPECT_LT(s.anisotropy, 1.1);
    const AngularProfile a = angularProfile(acc.mean(), 12, 0.05, 0.5);
    for (double v : a.power) EXPECT_NEAR(v / (1.0 / 12), 1.0, 0.1);
}

// A bi-lobe noise at f0 = 12 cycles per 128-pixel period and θ = 30° peaks at
// radius 12/128 cycle/pixel and orientation 30° (the DFT grid resolves 1/128
// in radius and atan(1/12) ≈ 4.8° in angle at that radius); its second
// moment is stretched along 30°, a ring's is not.
TEST(PowerSpectrum, BiLobePeaksAtItsFrequencyAndOrientation) {
    const Image lobe = example(SpectrumShape::BiLobe, 12, 1.0, 30, 3, 128);
    const Image p = centredPowerSpectrum(lobe, SpectrumWindow::None);
    const SpectrumGeometry s = spectrumGeometry(p);
    EXPECT_NEAR(s.peakRadius, 12.0 / 128, 1.5 / 128);
    EXPECT_NEAR(s.peakOrientationDeg, 30, 5);
    EXPECT_NEAR(s.orientationDeg, 30, 2);
    EXPECT_GT(s.anisotropy, 10);
    EXPECT_NEAR(s.meanRadius, 12.0 / 128, 1.0 / 128);
    const Image ring = example(SpectrumShape::Ring, 12, 1.0, 0, 3, 128);
    EXPECT_LT(spectrumGeometry(centredPowerSpectrum(ring, SpectrumWindow::None)).anisotropy, 1.3);
    // The display image: the lobes are its brightest points.
    const Image shown = logSpectrumImage(p);
    const int x = 64 + int(std::lround(12 * std::cos(M_PI / 6))), y = 64 - int(std::lround(12 * std::sin(M_PI / 6)));
    float around = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) around = std::max(around, shown.at(x + dx, y + dy));
    EXPECT_GT(around, 0.9f);
    EXPECT_EQ(shown.at(64, 64), 0.0f);
}

TEST(PowerSpectrum, BadInputIsRefused) {
    EXPECT_THROW(centredPowerSpectrum(Image(3, 8, 1), SpectrumWindow::Hann), InputError);
    SpectrumAccumulator acc(8, 8, SpectrumWindow::Hann);
    EXPECT_THROW(acc.add(Image(8, 9, 1)), InputError);
    // A constant image has no shape, and says so without dividing by zero.
    Image flat(16, 16, 1);
    for (float& v : flat.data()) v = 0.5f;
    const SpectrumGeometry s = spectrumGeometry(centredPowerSpectrum(flat, SpectrumWindow::Hann));
    EXPECT_EQ(s.anisotropy, 1.0);
    EXPECT_EQ(s.meanRadius, 0.0);
}

// `next` = `prev` warped so that the content at p moves to c + s·(p − c) + d
// (periodic bicubic: the example tiles).
Image moved(const Image& prev, double s, double dx, double dy) {
    const int w = prev.width(), h = prev.height();
    const double cx = 0.5 * w, cy = 0.5 * h;
    cv::Mat src(h, w, CV_32F, const_cast<float*>(prev.data().data())), mapX(h, w, CV_32F), mapY(h, w, CV_32F), dst;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            mapX.at<float>(y, x) = float(cx + (x - dx - cx) / s);
            mapY.at<float>(y, x) = float(cy + (y - dy - cy) / s);
        }
    cv::remap(src, dst, mapX, mapY, cv::INTER_CUBIC, cv::BORDER_WRAP);
    Image out(w, h, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) out.at(x, y) = dst.at<float>(y, x);
    return out;
}

// A translation by (2.5, −1.25) px of a smooth noise is recovered by each
// method within 0.1 px on average (measured: ≤ 0.01) away from the borders.
TEST(OpticalFlow, RecoversATranslation) {
    const Image a = example(SpectrumShape::LowPass, 12, 0, 0, 5, 256);
    const Image b = moved(a, 1.0, 2.5, -1.25);
    for (FlowMethod m : {FlowMethod::Farneback, FlowMethod::Dis, FlowMethod::LucasKanade}) {
        const FlowSummary s = summariseFlow(flowVectors(a, b, m, 8, 32), 128, 128);
        SCOPED_TRACE(enumName(kFlowMethodNames, m));
        EXPECT_GT(s.vectors, 300);
        EXPECT_NEAR(s.meanU, 2.5, 0.1);
        EXPECT_NEAR(s.meanV, -1.25, 0.1);
        EXPECT_NEAR(s.expansionRate, 0.0, 0.003);
    }
}

// A zoom by s = 1.04 about the centre moves p by 0.04·(p − c): every method
// measures the expansion rate 0.04 within 0.004 and sees (almost) every
// moving vector point outward; a zoom out reverses the sign.
TEST(OpticalFlow, RecoversAZoom) {
    const Image a = example(SpectrumShape::LowPass, 12, 0, 0, 5, 256);
    const Image in = moved(a, 1.04, 0, 0), out = moved(a, 1 / 1.04, 0, 0);
    for (FlowMethod m : {FlowMethod::Farneback, FlowMethod::Dis, FlowMethod::LucasKanade}) {
        SCOPED_TRACE(enumName(kFlowMethodNames, m));
        const FlowSummary s = summariseFlow(flowVectors(a, in, m, 8, 32), 128, 128);
        EXPECT_NEAR(s.expansionRate, 0.04, 0.004);
        EXPECT_GT(s.outwardFraction, 0.95);
        EXPECT_NEAR(s.meanU, 0.0, 0.1);
        const FlowSummary back = summariseFlow(flowVectors(a, out, m, 8, 32), 128, 128);
        EXPECT_NEAR(back.expansionRate, 1 / 1.04 - 1, 0.004);
        EXPECT_LT(back.outwardFraction, 0.05);
    }
}

TEST(OpticalFlow, ColoursAndArrows) {
    // A uniform flow to the right is red (hue 0°), upward (v < 0) is hue 90°.
    Image right(16, 16, 2), up(16, 16, 2);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            right.at(x, y, 0) = 1.0f;
            up.at(x, y, 1) = -1.0f;
        }
    const Image r = flowColourImage(right), u = flowColourImage(up);
    EXPECT_NEAR(r.at(3, 3, 0), 1.0f, 1e-5);
    EXPECT_NEAR(r.at(3, 3, 1), 0.0f, 1e-5);
    EXPECT_NEAR(u.at(3, 3, 0), 0.5f, 1e-5);  // hue 90°: (½, 1, 0)
    EXPECT_NEAR(u.at(3, 3, 1), 1.0f, 1e-5);
    const Image arrows = flowArrowsImage(Image(32, 32, 1), {{16, 16, 5, 0}}, 2.0);
    EXPECT_EQ(arrows.channels(), 3);
    EXPECT_GT(arrows.at(22, 16, 0), 0.9f);  // on the arrow, 10 px long
    EXPECT_EQ(arrows.at(5, 5, 0), 0.25f);   // the dimmed black frame elsewhere
    EXPECT_THROW(denseFlow(Image(16, 16, 1), Image(17, 16, 1), FlowMethod::Dis), InputError);
    EXPECT_THROW(denseFlow(Image(8, 8, 1), Image(8, 8, 1), FlowMethod::Dis), InputError);
}

}  // namespace
}  // namespace stochtex
