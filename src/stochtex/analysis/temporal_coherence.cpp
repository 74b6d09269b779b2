#include "stochtex/analysis/temporal_coherence.h"

#include <cmath>
#include <string>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

double relativeSpread(const std::vector<double>& v) {
    double mean = 0, m2 = 0;
    for (double x : v) mean += x;
    mean /= double(v.size());
    for (double x : v) m2 += (x - mean) * (x - mean);
    return mean != 0 ? std::sqrt(m2 / double(v.size())) / std::abs(mean) : 0.0;
}

}  // namespace

TemporalCoherenceMeter::TemporalCoherenceMeter(int radialBins, SpectrumWindow window) : bins_(radialBins), window_(window) {
    if (radialBins < 4 || radialBins > 4096)
        throw InputError::parameter("radialBins", "must be in [4, 4096], got " + std::to_string(radialBins));
}

void TemporalCoherenceMeter::add(const Image& frame, double time) {
    const Image gray = frame.channels() == 1 ? frame : toGray(frame);
    if (frames_.empty()) {
        width_ = gray.width();
        height_ = gray.height();
    } else if (gray.width() != width_ || gray.height() != height_) {
        throw InputError("temporal coherence: frame " + std::to_string(frames_.size()) + " is " +
                         std::to_string(gray.width()) + "x" + std::to_string(gray.height()) + ", the first was " +
                         std::to_string(width_) + "x" + std::to_string(height_));
    }
    FrameAppearance a;
    a.time = time;
    double sum = 0, sum2 = 0;
    for (float v : gray.data()) sum += v;
    a.mean = sum / double(gray.data().size());
    for (float v : gray.data()) sum2 += (v - a.mean) * (v - a.mean);
    a.contrast = std::sqrt(sum2 / double(gray.data().size()));
    const Image spectrum = centredPowerSpectrum(gray, window_);
    a.meanFrequency = spectrumGeometry(spectrum, 0.0, 0.5).meanRadius;
    a.radial = radialProfile(spectrum, bins_);
    frames_.push_back(std::move(a));
}

TemporalCoherence TemporalCoherenceMeter::result() const {
    if (frames_.size() < 2)
        throw InputError("temporal coherence needs at least 2 frames, got " + std::to_string(frames_.size()));
    TemporalCoherence r;
    r.frames = frames_;
    std::vector<double> contrast, scale;
    for (const FrameAppearance& f : frames_) {
        contrast.push_back(f.contrast);
        scale.push_back(f.meanFrequency);
    }
    for (size_t k = 0; k < frames_.size(); ++k) {
        r.meanContrast += contrast[k] / double(frames_.size());
        r.meanFrequency += scale[k] / double(frames_.size());
    }
    const double pairs = double(frames_.size() - 1);
    for (size_t k = 0; k + 1 < frames_.size(); ++k) {
        const FrameAppearance &a = frames_[k], &b = frames_[k + 1];
        r.meanChange += std::abs(b.mean - a.mean) / pairs;
        r.contrastChange += (r.meanContrast > 0 ? std::abs(b.contrast - a.contrast) / r.meanContrast : 0.0) / pairs;
        r.scaleChange +=
            (r.meanFrequency > 0 ? std::abs(b.meanFrequency - a.meanFrequency) / r.meanFrequency : 0.0) / pairs;
        double change = 0;
        int bins = 0;
        for (size_t i = 0; i < a.radial.power.size(); ++i) {
            // Empty bins (no frequency falls in them on a small frame) and a
            // zero power (a constant frame) carry no spectrum to compare.
            if (!(a.radial.power[i] > 0) || !(b.radial.power[i] > 0)) continue;
            change += std::abs(std::log10(b.radial.power[i]) - std::log10(a.radial.power[i]));
            ++bins;
        }
        r.spectrumChange += (bins ? change / bins : 0.0) / pairs;
    }
    r.scaleVariation = relativeSpread(scale);
    r.contrastVariation = relativeSpread(contrast);
    return r;
}

}  // namespace stochtex
