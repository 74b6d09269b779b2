#pragma once
// Flicker of a zoom-out sequence, per filter: each filter renders the same
// frames (scales geometric from `from` to `to`, zooming about texel (0, 0)),
// and so does the ground truth, S̄ supersampled with `truthSamples` per axis
// (ZoomSequenceMeter, analysis/zoom_stability.h). Per filter: the
// zoom-compensated change of the frames ("image change", which blur wins),
// the same difference of the error frames frame − truth ("error flicker",
// which only a sequence that follows the truth wins), and the accuracy
// mean |frame − truth|. Frames are rendered one index at a time for every
// filter, so memory stays at two frames per filter.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "stochtex/analysis/zoom_stability.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"

namespace stochtex {

struct StabilityStudyOptions {
    std::vector<FilterOptions> filters;  // one measurement each
    // The numbers, their meanings and ranges: stabilityStudyMembers().
    int frames = 64;
    int size = 128;
    double from = 1, to = 128;
    // The ground truth: the reference S̄ with at most this many samples per
    // axis and pixel, twice the stability command's reference.
    int truthSamples = 64;
};
// The entries of StabilityStudyOptions' numbers (checked by
// validateStabilityStudy; the CLI's flags).
std::span<const OptionMember<StabilityStudyOptions>> stabilityStudyMembers();

struct StabilityMeasurement {
    ZoomStability imageChange;     // consecutive frames, zoom undone
    ZoomStability errorFlicker;    // consecutive error frames (frame − truth), zoom undone
    std::vector<double> accuracy;  // per frame: mean |frame − truth|
    double meanAccuracy = 0;
};

struct StabilityStudyResult {
    std::vector<StabilityMeasurement> measurements;  // per filter, in order
    Table summary;                                   // filter; image change, error flicker (mean, max); accuracy (mean)
    Table perFrame;  // filter, frame, scale, accuracy; image change and error flicker from the previous frame
    std::vector<Figure> figures;  // error flicker and accuracy per frame, per filter (line plots)
};

// The filters a study measures: each filter that reads the estimators
// (paper, smooth) once per estimator, in order, the others once. InputError
// naming "estimators" when it is empty or names one twice.
std::vector<FilterOptions> filtersPerEstimator(std::span<const FilterOptions> filters,
                                               std::span<const VarianceEstimator> estimators);

// The filters a study of `pattern` measures: a filter per name (kFilterNames)
// over `base` (its aniso, reference samples), by filtersPerEstimator over
// `estimators`, or where none are given the pattern file's estimator, else
// paper. InputError naming "filters" or "estimators".
std::vector<FilterOptions> stabilityFilters(const PatternSpec& pattern, std::span<const std::string> filters,
                                            std::span<const VarianceEstimator> estimators, const FilterOptions& base);

// The name of each filter's frame sequence (FrameSequenceSet's files
// <name>.mp4, <name>-NNN.png): the filter's label with '/' as '-', in order.
std::vector<std::string> stabilitySequenceNames(std::span<const FilterOptions> filters);

// InputError naming the parameter (filters, frames, size, from, to, truthSamples).
void validateStabilityStudy(const StabilityStudyOptions& options);

// onFrame(filter index, frame index, frame) sees every rendered frame (not
// the truth's).
using StabilityFrameSink = std::function<void(size_t, int, const Image&)>;
StabilityStudyResult stabilityStudy(const GraphPattern& pattern, const StabilityStudyOptions& options,
                                    const StudyProgress& progress = {}, const StabilityFrameSink& onFrame = {});

// A study in parts (frame ranges), for runs split over processes
// (stochtex/dask.py): what frames [first, first + count) measure, per
// filter: the accuracy of each frame and, for each frame k ≥ 1 of the range,
// the image change and error flicker of the pair (k − 1, k) (frame first − 1
// is rendered again for the range's first pair: rendering is deterministic,
// so it is the frame the previous range rendered).
struct StabilityFrames {
    int first = 0, count = 0;
    std::vector<std::vector<double>> accuracy, imageChange, errorFlicker;  // per filter
};
// The filters and the ground truth of a study, built once (one PartCache),
// measuring any range of its frames. `pattern` must outlive it.
class StabilitySampler {
public:
    StabilitySampler(const GraphPattern& pattern, const StabilityStudyOptions& options);
    ~StabilitySampler();
    // InputError naming "first" or "count" for a range outside 0…frames − 1.
    StabilityFrames frames(int first, int count, const StudyProgress& progress = {},
                           const StabilityFrameSink& onFrame = {}) const;

private:
    StabilityStudyOptions options_;
    PartCache cache_;
    std::vector<std::unique_ptr<FilteredGraph>> filters_;
    std::unique_ptr<FilteredGraph> truth_;
};
// The study from parts that cover frames 0…frames − 1 in order (InputError
// naming "parts" otherwise): exactly stabilityStudy's result.
StabilityStudyResult stabilityFromFrames(const StabilityStudyOptions& options, std::span<const StabilityFrames> parts);
// Its report: stability.csv, stability-frames.csv (not on the page) and the
// plots, titled by the pattern's name.
Report stabilityReport(const StabilityStudyResult& result, const std::string& patternName);

}  // namespace stochtex
