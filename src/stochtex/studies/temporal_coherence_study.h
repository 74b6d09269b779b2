#pragma once
// Temporal coherence of any texture source over time (thesis §2.1.1,
// Figures 2.4 and 2.16; analysis/temporal_coherence.h), and the thesis's
// observation that the zoom texture needs enough layers to keep its look —
// n = 3 loses coherence where n = 8 keeps it — as a measured curve over n.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "stochtex/analysis/temporal_coherence.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

struct TemporalCoherenceOptions {
    SourceRegion region = SourceRegion::centred(256, 256);  // 8…2048 pixels a side
    std::vector<double> times;                              // the frames, in order: 2…10000 finite times
    int instance = 0;                                       // one realisation (averaging would hide what is measured)
    int radialBins = 32;
    SpectrumWindow window = SpectrumWindow::Hann;
    Transfer frameTransfer = Transfer::Linear;  // how the frames are shown (Srgb: linear-light colour)
};
// The entries of TemporalCoherenceOptions' numbers (its check; the CLI's flags).
std::span<const OptionMember<TemporalCoherenceOptions>> temporalCoherenceMembers();
// InputError naming the parameter (region, times, instance, radialBins).
// With a source, also its checkWindow at every frame's time.
void validateTemporalCoherence(const TemporalCoherenceOptions& options, const TextureSource* source = nullptr);
// `count` times from `start`, `step` apart.
std::vector<double> evenTimes(double start, double step, int count);

struct TemporalCoherenceResult {
    TemporalCoherence coherence;
    Table summary;   // one row: the changes and variations
    Table perFrame;  // time, mean, contrast, mean frequency
    std::vector<Figure>
        figures;  // appearance.png (contrast and dominant scale over time), frames.png (frames and spectra)
};
TemporalCoherenceResult temporalCoherenceStudy(const TextureSource& source, const TemporalCoherenceOptions& options,
                                               const StudyProgress& progress = {});

// The zoom texture of `zoom`'s parameters and base with each layer count n.
struct LayerCoherenceOptions {
    std::vector<int> layers{2, 3, 4, 5, 6, 8, 10};  // 1…64 each
    TemporalCoherenceOptions frames;
};
struct LayerCoherenceResult {
    std::vector<TemporalCoherence> perLayers;  // in the order of options.layers
    Table table;                               // n, the changes and variations
    std::vector<Figure> figures;               // layers.png, the curves over n
};
// InputError naming the parameter (as validateTemporalCoherence, and
// layersList), before any work.
void validateLayerCoherence(const LayerCoherenceOptions& options);
LayerCoherenceResult layerCoherenceStudy(const ZoomSource& zoom, const LayerCoherenceOptions& options,
                                         const StudyProgress& progress = {});

// The `coherence` report of one source: temporalCoherenceStudy of its frames
// and, given layer counts, layerCoherenceStudy of the zoom texture over them.
struct CoherenceReportOptions {
    TemporalCoherenceOptions frames;
    std::vector<int> layers;  // layer counts n, 1…64 each (the source is then a ZoomSource); empty: no curve over n
    std::string sourceName;   // the report's title names it
};
// InputError naming the parameter (region, times, …, layersList), with the
// source's checkWindow at every frame's time; before any work.
void validateCoherenceReport(const CoherenceReportOptions& options, const TextureSource& source);
struct CoherenceReport {
    TemporalCoherenceResult frames;
    std::optional<LayerCoherenceResult> layers;  // with options.layers
    // coherence.csv, frames.csv (not on the page), the frames' figures; then
    // the curve over n (layers.csv, appearance.png, frames.png, layers.png).
    Report report;
};
CoherenceReport coherenceReport(const TextureSource& source, const CoherenceReportOptions& options,
                                const StudyProgress& progress = {});

}  // namespace stochtex
