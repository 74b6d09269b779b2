#pragma once
// The workbench's live analyses of the frames it shows (thesis ch. 3, GLcv):
// the power spectrum of the frame, the optical flow from the previous frame
// to this one, the flicker motion does not explain, and the correlation of every pixel with a picked point over
// samples (a pattern's instances, a program's frames). Spectrum and flow
// are the studies' own functions (spectrumStudy, flowStudy) fed with the
// frames through a texture source, so the window shows what the `spectrum`
// and `flow` commands write; the correlation is the CorrelationAccumulator
// that `correlation` uses, fed one sample at a time.
#include <string>
#include <vector>

#include "stochtex/analysis/correlation_accumulator.h"
#include "stochtex/core/enum_names.h"
#include "stochtex/image/image.h"

namespace stochtex {

enum class LiveAnalysisKind { Spectrum, Flow, Flicker, Correlation };
inline const EnumNames<LiveAnalysisKind> kLiveAnalysisNames{{"spectrum", LiveAnalysisKind::Spectrum},
                                                           {"flow", LiveAnalysisKind::Flow},
                                                           {"flicker", LiveAnalysisKind::Flicker},
                                                           {"correlation", LiveAnalysisKind::Correlation}};

struct LiveAnalysisResult {
    // Display codes, the frame's size, row 0 at the top: RGB, or RGBA for a
    // map over the frame whose alpha is the value's strength (0 where the
    // colour map shows zero), so that an overlay shows the frame there.
    Image image;
    std::string summary;  // the study's numbers, one line each
    std::vector<float> profile;  // a curve to plot beside it (spectrum: log10 radial power), may be empty
    std::string profileLabel;
};

// The spectrum study of one frame (Hann window, the whole frame): its
// spectrum.png figure and shape figures. Frames of 4…4096 pixels a side.
LiveAnalysisResult liveSpectrum(const Image& frame);
// The flow study (DIS) from `previous` to `current` (same size, ≥ 16 a
// side): its dense flow colour figure and the motion's numbers.
LiveAnalysisResult liveFlow(const Image& previous, const Image& current);

// The flicker from `previous` to `current` (analysis/flicker.h): the
// per-pixel residual after the flow's compensation (viridis, 0 to 4× its
// mean) and the residual, contrast and their ratio.
LiveAnalysisResult liveFlicker(const Image& previous, const Image& current);

// What the accumulator over samples shows: every pixel's correlation with
// the reference point (blue–white–red over [−1, 1]), or its mean or
// variance (viridis; the mean over [0, 1], the variance up to its mean
// plus three standard deviations over the picture).
enum class LiveStatistic { Correlation, Mean, Variance };
inline const EnumNames<LiveStatistic> kLiveStatisticNames{{"correlation", LiveStatistic::Correlation},
                                                          {"mean", LiveStatistic::Mean},
                                                          {"variance", LiveStatistic::Variance}};

// The statistical accumulator over the samples added (gray of each), live.
class LiveCorrelation {
public:
    LiveCorrelation(int width, int height, int pointX, int pointY);
    void add(const Image& sample);
    int count() const { return accumulator_.count(); }
    int width() const { return width_; }
    int height() const { return height_; }
    int pointX() const { return pointX_; }
    int pointY() const { return pointY_; }
    // Needs 2 samples at least (else a gray image and a note).
    LiveAnalysisResult result(LiveStatistic shown = LiveStatistic::Correlation) const;

private:
    int width_, height_, pointX_, pointY_;
    CorrelationAccumulator accumulator_;
};

}  // namespace stochtex
