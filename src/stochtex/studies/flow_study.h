#pragma once
// Optical flow of any texture source's frames (thesis §2.8, Figures 2.24 and
// 2.25): consecutive frames of a window at t₀, t₀ + Δt, …, the flow of each
// pair (analysis/optical_flow.h), the numbers of the motion about a centre
// (mean vector, outward fraction, expansion rate) per pair and on average,
// and figures: the flow as colour, arrows on the first frame, and the
// expansion rate over the pairs.
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "stochtex/analysis/optical_flow.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

struct FlowStudyOptions {
    SourceRegion region = SourceRegion::centred(256, 256);  // 16…4096 pixels a side
    double time = 0, timeStep = 1.0 / 30;                   // frame k at time + k·timeStep
    int frames = 2;
    int instance = 0;
    FlowMethod method = FlowMethod::Farneback;
    int step = 16;    // vectors on a grid of `step` pixels…
    int margin = 16;  // …at least `margin` pixels inside the window
    // The centre of the radial figures in window pixels; NaN: the source's
    // origin (0, 0) where the window holds it (the zoom centre), else the
    // window's centre.
    double centreX = std::numeric_limits<double>::quiet_NaN(), centreY = std::numeric_limits<double>::quiet_NaN();
    double arrowScale = 4;                      // arrows drawn this many times their length
    Transfer frameTransfer = Transfer::Linear;  // as SpectrumStudyOptions::frameTransfer
};
// The entries of FlowStudyOptions' numbers (its check; the CLI's flags).
std::span<const OptionMember<FlowStudyOptions>> flowStudyMembers();
// InputError naming the parameter; with a source, also its checkWindow at
// every frame's time. Before any work.
void validateFlowStudy(const FlowStudyOptions& options, const TextureSource* source = nullptr);

struct FlowStudyResult {
    std::vector<FlowSummary> pairs;  // pair k: frames k → k + 1
    FlowSummary mean;                // the pairs' figures averaged
    Table summary;                   // flow.csv: one row per pair, then the mean
    std::vector<Figure> figures;     // flow_colour.png (dense methods), flow_arrows.png, expansion.png (≥ 2 pairs)
};
// onFrame(k, frame) sees every frame analysed, in order (for a video of them).
using FlowFrameSink = std::function<void(int, const Image&)>;
FlowStudyResult flowStudy(const TextureSource& source, const FlowStudyOptions& options,
                          const StudyProgress& progress = {}, const FlowFrameSink& onFrame = {});
// Its report (flow.csv and the figures), titled by the source's name; with
// `video`, the preview of the frames' video ("frames", written by the caller).
Report flowReport(const FlowStudyResult& result, const std::string& sourceName, bool video = false);

}  // namespace stochtex
