#pragma once
// Paper Figure 14 and what §7 leaves open: a texture graph that cascades
// operation nodes (directional derivatives of a Gaussian noise, then two 2D
// transfer functions), its stages, and how well it is filtered when the
// intermediate field is not Gaussian (pattern/graph_pattern.h).
//
// Per footprint (a zoom-out by that many texels per pixel), against the
// supersampled reference S̄:
//   none      — the graph at pixel centres (aliases);
//   mean-only — the estimators, with the intermediate field passed on by its
//               mean alone (σ = 0 into the second table): what filtering the
//               last transfer function alone amounts to;
//   matched, exact statistics — moment matching on the leaves' exact
//               footprint statistics: the error of the approximation itself;
//   matched   — moment matching on the estimators' statistics (real time).
#include <span>
#include <string>
#include <vector>

#include "stochtex/core/progress.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "stochtex/report/page.h"
#include "stochtex/report/report.h"
#include "stochtex/report/table.h"

namespace stochtex {

struct Figure14Options {
    PatternSpec pattern;  // a graph; figure14Options() loads the preset figure14
    std::string name = "figure14";
    int size = 256;             // image side per footprint (ranges: figure14Members())
    int referenceSamples = 64;  // per axis: the cap
    // The reference and the exact statistics are rendered at the fewest
    // samples (up to the cap) that move them by less than this when doubled
    // (studies/reference_samples.h).
    double referenceTolerance = 5e-4;
    std::vector<int> footprints{1, 2, 4, 8, 16, 32, 64};
    PrefilterMode prefilter = PrefilterMode::Smooth;
};
// The defaults with the preset figure14.
Figure14Options figure14Options();
// The entries of Figure14Options' numbers (its check; the CLI's flags).
std::span<const OptionMember<Figure14Options>> figure14Members();
// InputError for unusable options (sizes, footprints, a pattern that is not a graph).
void validateFigure14(const Figure14Options& options);

// Mean ‖· − S̄‖₂ over the pixels (linear RGB) per method.
struct Figure14Column {
    int footprint = 0;
    double none = 0, meanOnly = 0, matchedExact = 0, matched = 0;
    // matched with each estimator of kVarianceEstimatorNames after the
    // paper's (matched): deliot-heitz, sub-probes, sub-probes-4x4,
    // sub-probes-8x8-fine-means.
    std::vector<double> matchedOtherEstimators;
    // The samples per axis of the reference and the exact statistics, and how
    // much each moved on doubling them.
    int referenceSamples = 0, exactSamples = 0;
    double referenceChange = 0, exactChange = 0;
};
struct Figure14Result {
    std::vector<Figure14Column> columns;
    Table table;                  // figure14.csv
    std::vector<Figure> figures;  // figure14.png (the stages), figure14_filtering.png, figure14_errors.png, then the
                                  // images per footprint
};
Figure14Result figure14(const Figure14Options& options, const Progress& progress = {});
// Its report: figure14.csv and the figures.
Report figure14Report(const Figure14Result& result);

}  // namespace stochtex
