#pragma once
// Temporal coherence of an animation (thesis §2.1.1, Figures 2.4 and 2.16):
// how much a texture's appearance moves from one frame to the next. Each
// frame is one realisation (averaging over time would smooth out what is
// measured, as the thesis notes) described by its mean, its contrast (the
// standard deviation of its values), its radial power spectrum
// (analysis/power_spectrum.h) and its dominant scale, the power-weighted
// mean spatial frequency |f| of that spectrum in cycles per pixel (§2.1.1
// sees coherence lost in frames whose high frequencies fade: their mean
// frequency drops). Consecutive frames are compared, and each figure's
// spread over the whole sequence is reported.
#include <vector>

#include "stochtex/analysis/power_spectrum.h"
#include "stochtex/image/image.h"

namespace stochtex {

struct FrameAppearance {
    double time = 0;
    double mean = 0, contrast = 0;  // of the gray values
    double meanFrequency = 0;       // Σ P |f| / Σ P over 0 < |f| ≤ 0.5, cycles per pixel
    RadialProfile radial;
};

struct TemporalCoherence {
    std::vector<FrameAppearance> frames;
    // Means over the frames, the references of the relative figures below:
    double meanContrast = 0;   // of contrast
    double meanFrequency = 0;  // of meanFrequency (the sequence's dominant scale)
    // Means over consecutive pairs (k, k + 1) of the change of each figure:
    double meanChange = 0;      // |Δ mean|
    double contrastChange = 0;  // |Δ contrast| / (mean contrast of the sequence)
    double scaleChange = 0;     // |Δ meanFrequency| / (mean meanFrequency)
    double spectrumChange = 0;  // mean over the radial bins of |Δ log10 P|
    // Over the whole sequence: standard deviation / mean of the dominant
    // scale and of the contrast (0 for a texture whose look holds still).
    double scaleVariation = 0, contrastVariation = 0;
};

// Streaming: keeps each frame's few figures and radial profile, not the frames.
class TemporalCoherenceMeter {
public:
    // radialBins ≥ 4 (InputError naming radialBins otherwise).
    TemporalCoherenceMeter(int radialBins, SpectrumWindow window);
    // A frame (colour frames are made gray first) of the sequence's size at
    // `time`; InputError if its size differs from the first frame's.
    void add(const Image& frame, double time);
    int count() const { return int(frames_.size()); }
    // The figures above; InputError if fewer than two frames were added.
    TemporalCoherence result() const;

private:
    int bins_;
    SpectrumWindow window_;
    int width_ = 0, height_ = 0;
    std::vector<FrameAppearance> frames_;
};

}  // namespace stochtex
