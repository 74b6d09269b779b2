#pragma once
// Flicker of a zoom-out sequence, per filter: each filter renders the same
// frames (scales geometric from `from` to `to`, zooming about texel (0, 0))
// and the zoom-compensated difference between consecutive frames is measured
// (analysis/zoom_stability.h).
#include <functional>
#include <vector>

#include "stochtex/analysis/zoom_stability.h"
#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"

namespace stochtex {

struct StabilityStudyOptions {
    std::vector<FilterOptions> filters;  // one measurement each
    int frames = 64;                     // [2, 1000]
    int size = 128;                      // frame side in pixels, [8, 2048]
    double from = 1, to = 128;           // first and last scale (texels per pixel), finite, (0, 1e6]
};

struct StabilityStudyResult {
    std::vector<ZoomStability> measurements;  // per filter, in order
    Table summary;                            // filter, mean_difference, max_difference
    Table perFrame;                           // filter, frame, scale, difference
};

// InputError naming the parameter (filters, frames, size, from, to).
void validateStabilityStudy(const StabilityStudyOptions& options);

// onFrame(filter index, frame index, frame) sees every rendered frame.
using StabilityFrameSink = std::function<void(size_t, int, const Image&)>;
StabilityStudyResult stabilityStudy(const Pattern& pattern, const StabilityStudyOptions& options,
                                    const StudyProgress& progress = {}, const StabilityFrameSink& onFrame = {});

}  // namespace stochtex
