#pragma once
// Several frame studies of one texture source on one page (issue "The
// workbench": `stochtex shadertoy PROG --analyse spectrum,flow,coherence`):
// the power spectrum of the first frame, the optical flow and the temporal
// coherence of the frames, each the very study its own command runs
// (spectrumStudy, flowStudy, temporalCoherenceStudy), over one window and
// one run of frames; the flow-compensated flicker of the frames
// (analysis/flicker.h); and the statistics over instances at the first
// frame's time (thesis §3.3, the statistical accumulator): per-pixel mean
// and variance and the correlation with a picked point.
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "stochtex/analysis/flicker.h"
#include "stochtex/core/enum_names.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

enum class FrameAnalysis { Spectrum, Flow, Coherence, Flicker, Statistics };
inline const EnumNames<FrameAnalysis> kFrameAnalysisNames{{"spectrum", FrameAnalysis::Spectrum},
                                                          {"flow", FrameAnalysis::Flow},
                                                          {"coherence", FrameAnalysis::Coherence},
                                                          {"flicker", FrameAnalysis::Flicker},
                                                          {"statistics", FrameAnalysis::Statistics}};

struct FrameAnalysisOptions {
    std::vector<FrameAnalysis> analyses;  // at least one, each once
    SourceRegion region = SourceRegion::centred(256, 256);
    double time = 0, timeStep = 1.0 / 30;     // frame k at time + k·timeStep
    int frames = 8;                           // flow, coherence and flicker: 2…10000 frames
    int instances = 64;                       // statistics: instances 0…N−1, 2…100000
    int pointX = -1, pointY = -1;             // statistics: the correlation's point in window pixels; −1: the centre
    Transfer frameTransfer = Transfer::Srgb;  // how the frames are shown (Srgb: linear-light colour renders)
    std::string sourceName;                   // the report's title names it
};
// InputError naming the parameter (analyses, and each study's own checks,
// with the source's checkWindow at every frame), before any work.
void validateFrameAnalysis(const FrameAnalysisOptions& options, const TextureSource* source = nullptr);

struct FrameAnalysisResult {
    std::vector<Figure> figures;                        // every study's, their file names distinct
    std::vector<std::pair<std::string, Table>> tables;  // CSV file name, table
    Report report;                                      // one section per study: every figure and table
    std::string markdown;                               // the studies' summaries, for a terminal
};
FrameAnalysisResult frameAnalysis(const TextureSource& source, const FrameAnalysisOptions& options,
                                  const StudyProgress& progress = {});

// The flicker of a run in parts, for runs split over processes
// (stochtex/dask.py): pairs [first, first + count) (pair k: frame k → k + 1),
// each part rendering its own frames (frame `first` again for its first
// pair; a source renders a time the same wherever it is asked). Parts that
// cover every pair in order, joined by flickerFromPairs, give exactly
// frameAnalysis' flicker section.
struct FlickerPairs {
    int first = 0;
    std::vector<FlickerMeasure> measures;  // per pair, in order
    Image worstMap;                        // the residual map of the part's first pair of largest residual
};
// InputError naming first or count for pairs outside the run (and the
// flow study's checks of the frames).
FlickerPairs flickerPairs(const TextureSource& source, const FrameAnalysisOptions& options, int first, int count,
                          const Progress& progress = {});
// frameAnalysis with analyses {flicker}, from its pairs (InputError naming
// "parts" unless they cover every pair in order).
FrameAnalysisResult flickerFromPairs(const FrameAnalysisOptions& options, std::span<const FlickerPairs> parts);

}  // namespace stochtex
