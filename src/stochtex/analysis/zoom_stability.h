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

// Renders `frames` frames with scales geometric from `from` to `to` and
// measures consecutive compensated differences. render(scale) gives a frame.
ZoomStability measureZoomStability(const std::function<Image(double)>& render, int frames, double from, double to,
                                   const std::function<void(int)>& progress = {});

}  // namespace stochtex
