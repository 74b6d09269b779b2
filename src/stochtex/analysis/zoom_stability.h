#pragma once
// Temporal stability of a zoom sequence: how much a pattern changes between
// consecutive frames once the zoom itself is compensated. Flicker (aliasing,
// popping between filter levels) shows up as a large difference; a properly
// filtered sequence changes only as much as its blur does.
#include <functional>
#include <vector>

#include "stochtex/image/image.h"

namespace stochtex {

// Frames zoom about the image centre: a pixel p of a frame with scale s
// (texels per pixel) sees texel c + (p − centre)·s. Frame b (scale sb) is
// resampled bilinearly into frame a's pixels (scale sa) and the mean absolute
// difference over all channels is taken where the warped position lies inside b.
double compensatedZoomDifference(const Image& a, double sa, const Image& b, double sb);

struct ZoomStability {
    std::vector<double> scales;       // per frame
    std::vector<double> differences;  // frame k vs k + 1 (size frames − 1)
    double mean = 0;                  // mean of differences
    double max = 0;
};

// The stability of a sequence from its scales and consecutive differences,
// accumulated in order as a ZoomSequenceMeter does (the same mean and max,
// bit for bit): what joins a sequence measured in parts.
ZoomStability zoomStabilityOf(std::vector<double> scales, const std::vector<double>& differences);

// The mean of values summed in order (0 for none): a meter's meanAccuracy.
double orderedMean(const std::vector<double>& values);

// The scale of frame k of `frames` geometric from `from` to `to`.
double zoomSequenceScale(int k, int frames, double from, double to);

// Renders `frames` frames with scales geometric from `from` to `to` and
// measures consecutive compensated differences. render(scale) gives a frame.
ZoomStability measureZoomStability(const std::function<Image(double)>& render, int frames, double from, double to,
                                   const std::function<void(int)>& progress = {});

// A zoom sequence measured against its ground truth (the converged S̄ of
// each frame), one frame at a time (it keeps two frames, whatever the
// length). Per consecutive pair: the compensated difference of the frames
// themselves ("image change", the measure above) and of their error frames
// frame − truth ("error flicker"); per frame: the accuracy
// mean |frame − truth|. Image change rewards blur (a constant grey image
// scores 0); error flicker does not: a blurred or constant sequence's error
// moves with the truth it misses, so only frames that follow the truth
// from one frame to the next score low.
class ZoomSequenceMeter {
public:
    // frame and truth: the same size and channels (std::invalid_argument otherwise).
    void add(const Image& frame, const Image& truth, double scale);

    const ZoomStability& imageChange() const { return change_; }
    const ZoomStability& errorFlicker() const { return flicker_; }
    const std::vector<double>& accuracy() const { return accuracy_; }  // per frame
    double meanAccuracy() const;

private:
    Image frame_, error_;  // the previous frame and its error frame
    ZoomStability change_, flicker_;
    std::vector<double> accuracy_;
};

}  // namespace stochtex
