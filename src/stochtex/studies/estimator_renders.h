#pragma once
// What each footprint estimator costs in the rendered image (issue 32's
// render-error table): per pattern and view, mean ‖Ŝ − S̄‖₂ (linear RGB, over
// the pixels) of the filtered render with each estimator of
// kVarianceEstimatorNames against the supersampled reference S̄, beside the
// exact footprint statistics' error (the floor an estimator can reach: what
// remains is the response's, eq. 5 or the LEAN lobe) and the pixel centres'
// (no filtering). A pattern with a normal map is rendered through its LEAN
// response, any other through the prefiltered colormap; views are zooms at
// the given scales and, optionally, the perspective plane.
#include <span>
#include <string>
#include <vector>

#include "stochtex/core/progress.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "stochtex/report/page.h"
#include "stochtex/report/report.h"
#include "stochtex/report/table.h"

namespace stochtex {

struct EstimatorRendersOptions {
    // Presets (a graph and a LEAN normal map among them).
    std::vector<std::string> presets{"marble", "woven", "phasor-stripes", "figure14", "lean-ridges"};
    std::vector<double> scales{2, 8, 32, 128};  // zoom views, texels per pixel
    bool plane = true;                          // and the plane view (tiltDeg, planeScale at the centre)
    double tiltDeg = 70, planeScale = 2;
    int size = 128;             // image side (ranges: estimatorRendersMembers())
    int referenceSamples = 64;  // per axis: the cap of S̄ and of the exact statistics
    // S̄ and the exact statistics are rendered at the fewest samples (up to
    // the cap) that move them by less than this when doubled
    // (studies/reference_samples.h).
    double referenceTolerance = 5e-4;
    int aniso = 8;
    PrefilterMode prefilter = PrefilterMode::Smooth;
};
// The entries of EstimatorRendersOptions' numbers (its check; the CLI's flags).
std::span<const OptionMember<EstimatorRendersOptions>> estimatorRendersMembers();
// InputError naming the option (an unknown preset, an empty list, a scale out of range …).
void validateEstimatorRenders(const EstimatorRendersOptions& options);

struct EstimatorRendersRow {
    std::string pattern;
    std::string view;  // "zoom ×8", "plane 70°"
    double scale = 0;  // zoom: texels per pixel; the plane: 0
    double none = 0, exact = 0;
    std::vector<double> estimators;  // per kVarianceEstimatorNames entry
    int referenceSamples = 0, exactSamples = 0;
    double referenceChange = 0, exactChange = 0;
};
struct EstimatorRendersResult {
    std::vector<EstimatorRendersRow> rows;  // by pattern, then view
    Table table;                            // estimators.csv
    std::vector<Figure> figures;            // per pattern: error against scale, one line per estimator
};
EstimatorRendersResult estimatorRenders(const EstimatorRendersOptions& options, const Progress& progress = {});
Report estimatorRendersReport(const EstimatorRendersResult& result);

}  // namespace stochtex
