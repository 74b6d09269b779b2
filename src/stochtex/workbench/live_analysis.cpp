#include "stochtex/workbench/live_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "stochtex/analysis/flicker.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/flow_study.h"
#include "stochtex/studies/spectrum_study.h"

namespace stochtex {

namespace {

// Frames held in memory as a texture source: time 0 is `first`, time 1
// `second`; source pixel (0, 0) is a frame's top-left pixel. Static over
// instances (the studies here take one instance).
class HeldFrames : public TextureSource {
public:
    HeldFrames(const Image& first, const Image& second) : first_(first), second_(second) {}
    int channels() const override { return first_.channels(); }
    Image render(const SourceRegion& region, double time, int) const override {
        const Image& f = time < 0.5 ? first_ : second_;
        if (region.width != f.width() || region.height != f.height() || region.x0 != 0 || region.y0 != 0)
            throw std::logic_error("live analysis: held frames are analysed whole");
        return f;
    }

private:
    const Image& first_;
    const Image& second_;
};

const Image& figure(const std::vector<Figure>& figures, const std::string& file) {
    for (const Figure& f : figures)
        if (f.file == file) return f.image;
    throw std::logic_error("live analysis: the study made no " + file);
}

}  // namespace

LiveAnalysisResult liveSpectrum(const Image& frame) {
    SpectrumStudyOptions o;
    o.region = {frame.width(), frame.height(), 0, 0};
    const SpectrumStudyResult s = spectrumStudy(HeldFrames(frame, frame), o);
    LiveAnalysisResult r;
    r.image = toRgb(figure(s.figures, "spectrum.png"));
    const SpectrumGeometry& g = s.geometry;
    char text[400];
    std::snprintf(text, sizeof text,
                  "peak |f| %.4f cycles/pixel at %.1f°\nanisotropy λ₁/λ₂ %.2f along %.1f°\nmean |f| %.4f\n"
                  "angular max/min %.2f",
                  g.peakRadius, g.peakOrientationDeg, g.anisotropy, g.orientationDeg, g.meanRadius, g.angularMaxMin);
    r.summary = text;
    for (double p : s.radial.power) r.profile.push_back(float(std::log10(std::max(p, 1e-30))));
    r.profileLabel = "log10 radial power, |f| 0 to 0.5";
    return r;
}

LiveAnalysisResult liveFlow(const Image& previous, const Image& current) {
    FlowStudyOptions o;
    o.region = {current.width(), current.height(), 0, 0};
    o.time = 0;
    o.timeStep = 1;
    o.frames = 2;
    o.method = FlowMethod::Dis;
    const FlowStudyResult s = flowStudy(HeldFrames(previous, current), o);
    LiveAnalysisResult r;
    r.image = toRgb(figure(s.figures, "flow_colour.png"));
    const FlowSummary& m = s.mean;
    char text[400];
    std::snprintf(text, sizeof text,
                  "mean vector (%.3f, %.3f) px/frame\nmean |v| %.3f px/frame\noutward fraction %.2f\n"
                  "expansion rate %.4f /frame",
                  m.meanU, m.meanV, m.meanMagnitude, m.outwardFraction, m.expansionRate);
    r.summary = text;
    return r;
}

namespace {

// A map of one-channel values as colours over [lo, hi], with an alpha that
// grows with |value − zero| to 1 at the range's far end: the colour map's
// zero is see-through in an overlay (a static pattern's flicker map, 0
// everywhere, tinted the whole picture with the map's dark end).
Image colouredMap(const Image& values, double lo, double hi, HeatPalette palette, double zero) {
    const Image rgb = colourise(values, lo, hi, palette);
    Image out(rgb.width(), rgb.height(), 4, Image::Uninitialized{});
    const double reach = std::max(hi - zero, zero - lo);
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x) {
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = rgb.at(x, y, c);
            const double v = values.at(x, y);  // not finite (no flow there): see-through
            out.at(x, y, 3) = std::isfinite(v) ? float(std::clamp(std::abs(v - zero) / reach, 0.0, 1.0)) : 0.0f;
        }
    return out;
}

}  // namespace

LiveAnalysisResult liveFlicker(const Image& previous, const Image& current) {
    Image map;
    const FlickerMeasure m = flowCompensatedFlicker(previous, current, &map);
    LiveAnalysisResult r;
    // The scale's top: 4× the mean residual, and at least 2 codes, so that a
    // still frame's rounding noise is not stretched over the whole map.
    r.image = colouredMap(map, 0, std::max(2.0 / 255.0, 4 * m.residual), HeatPalette::Viridis, 0);
    char text[300];
    std::snprintf(text, sizeof text, "residual %.4f (codes)\ncontrast %.4f\nresidual / contrast %.3f", m.residual,
                  m.contrast, m.relative);
    r.summary = text;
    return r;
}

LiveCorrelation::LiveCorrelation(int width, int height, int pointX, int pointY)
    : width_(width), height_(height), pointX_(pointX), pointY_(pointY),
      accumulator_(width, height, pointX, pointY, pointY, pointY) {}

void LiveCorrelation::add(const Image& sample) { accumulator_.add(sample.channels() == 1 ? sample : toGray(sample)); }

LiveAnalysisResult LiveCorrelation::result(LiveStatistic shown) const {
    LiveAnalysisResult r;
    if (count() < 2) {
        r.image = Image(width_, height_, 3, 0.5f);
        r.summary = "collecting samples…";
        return r;
    }
    const Image mean = accumulator_.mean(), variance = accumulator_.variance();
    const ChannelStats m = channelStats(mean), v = channelStats(variance);
    switch (shown) {
        case LiveStatistic::Correlation:
            r.image = colouredMap(accumulator_.correlationWithPoint(), -1, 1, HeatPalette::Diverging, 0);
            break;
        case LiveStatistic::Mean: r.image = colourise(mean, 0, 1, HeatPalette::Viridis); break;
        case LiveStatistic::Variance:
            r.image = colouredMap(variance, 0, std::max(1e-6, v.mean + 3 * v.stddev), HeatPalette::Viridis, 0);
            break;
    }
    char text[400];
    std::snprintf(text, sizeof text,
                  "%d samples\nCorr with (%d, %d): blue −1, white 0, red +1\nmean %.4f (spread %.4f over the "
                  "picture)\nvariance %.5f (spread %.5f)",
                  count(), pointX_, pointY_, m.mean, m.stddev, v.mean, v.stddev);
    r.summary = text;
    return r;
}

}  // namespace stochtex
