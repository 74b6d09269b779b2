#pragma once
// Figure 12 of the paper (§6.5): LEAN mapping of a procedural Gaussian
// normal map on a plane seen in perspective, four variants against the
// supersampled reference, as data (tables and images; writing them is the
// caller's).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "stochtex/core/progress.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/report/page.h"
#include "stochtex/report/report.h"
#include "stochtex/report/table.h"

namespace stochtex {

// The variants of Figure 12, each a FilterOptions value over the lean response.
enum class LeanVariant {
    Reference,     // S̄: the unfiltered shading (base lobe at each point's slope) supersampled over the footprint
    Ours,          // μ̂, σ̂², ĉov of the slopes (eq. 9, 14, 18) in the lobe
    NoCovariance,  // the same without ĉov (the slopes treated as independent, Fig. 12d)
    DeliotHeitz,   // one constant variance per LOD and no covariance [DH19] (Fig. 12a)
    SubProbes,     // ours with the sub-probes estimator (issue 32)
    SubProbes4x4,  // ours with the sub-probes-4x4 estimator (issue 32)
    SubProbes8x8FineMeans,  // ours with the sub-probes-8x8-fine-means estimator (issue 32)
    Exact,  // the exact footprint moments of the slopes in the lobe: what estimators can reach (issue 32)
};
// A variant's name (file names, the CSV), its caption in the figure and
// what it changes in the lean filter options.
struct LeanVariantInfo {
    LeanVariant variant;
    const char* name;
    const char* caption;
    void (*apply)(FilterOptions&);
};
// In the figure's order: the reference, then the variants it is compared with.
extern const std::array<LeanVariantInfo, 8> kLeanVariants;
// The filter options of a variant (aniso and reference samples as given).
FilterOptions leanVariantOptions(const LeanVariantInfo& variant, int aniso, int referenceSamples);

struct Figure12Options {
    PatternSpec pattern;  // with a normal map (the lean-ridges preset)
    std::string name = "lean-ridges";
    int width = 640, height = 400;  // the global view, [32, 4096] each
    double scale = 0.5;             // camera: texels per pixel at the view's centre at tilt 0
    double tiltDeg = 70, fovDeg = 50;
    int aniso = 8;
    int referenceSamples = 48;  // per axis (range: figure12Members())
    // The mid-distance crop, as fractions of the global view [x0, y0, x1, y1].
    std::array<double, 4> crop{0.3, 0.42, 0.7, 0.62};
};
// The entries of Figure12Options' numbers that have one (its check; the CLI's flags).
std::span<const OptionMember<Figure12Options>> figure12Members();
// InputError naming the parameter (size, referenceSamples, crop, …) or, for
// a pattern without a normal map, the pattern.
void validateFigure12(const Figure12Options& options);

struct Figure12Row {
    LeanVariant variant = LeanVariant::Ours;
    double meanErrorGlobal = 0, meanErrorCrop = 0;  // mean ‖variant − reference‖₂ (RGB, linear)
};
struct Figure12Result {
    std::vector<Figure12Row> rows;  // every variant after the reference, in kLeanVariants' order
    Table table;                    // figure12.csv
    std::vector<Figure> figures;    // figure12.png, then each variant's view, crop and error maps
};
Figure12Result figure12(const Figure12Options& options, const Progress& progress = {});
// Its report: figure12.csv and the figures.
Report figure12Report(const Figure12Result& result);

}  // namespace stochtex
