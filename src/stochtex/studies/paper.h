#pragma once
// The paper's accuracy evidence (Grenier et al. 2022) as data: Table 1
// (estimator errors), Figure 4 (filtered vs reference images and error
// maps), Figures 7–9 (colormap layouts, palettes, noise spectra). Each
// returns tables and images; writing them is the caller's (report/).
#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "stochtex/analysis/estimator_error.h"
#include "stochtex/core/progress.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/report/page.h"
#include "stochtex/report/report.h"
#include "stochtex/report/table.h"

namespace stochtex {

// How far a study is (core/progress.h; may be empty).
using StudyProgress = Progress;

// The two noises of Table 1 (the paper describes them only as "a low
// frequency isotropic noise and a high frequency anisotropic noise"):
// 512² examples, N_x and N_y of the same spectrum with different seeds.
constexpr int kTable1ExampleSize = 512;
const char* table1NoiseName(int which);  // 0: low, 1: high
PatternSpec table1PatternSpec(int which, uint32_t seed);

struct Table1Options {
    EstimatorErrorOptions errors;
    uint32_t seed = 1;  // of the noises (footprint centres: errors.seed)
};
// InputError for unusable options (count, footprints).
void validateTable1(const Table1Options& options);

struct Table1Result {
    std::array<std::vector<EstimatorError>, 2> rows;  // low, high; ordered as measureEstimatorErrors
    Table data;                                       // one row per noise × footprint × estimator (table1.csv)
    std::vector<Table> tables;    // the paper's layout: one per estimator, then the published numbers
    std::vector<Figure> figures;  // mean error vs footprint, ours and published
};
Table1Result table1(const Table1Options& options, const StudyProgress& progress = {});
// The tables and figures of Table 1 from its rows, as table1 makes them
// (a Dask run measures the rows in chunks: stochtex/dask.py).
Table1Result table1FromRows(std::array<std::vector<EstimatorError>, 2> rows, const Table1Options& options);
// The pair of leaves whose estimators Table 1 measures: noise `which` (0:
// low, 1: high) with the noises' seed.
TiledField table1Field(int which, uint32_t seed);
// Its report: the paper's layout and the published numbers on the page,
// table1.csv (every row), table1.md and the plots.
Report table1Report(const Table1Result& result);

struct Figure4Options {
    PatternSpec pattern;  // the paper uses the camouflage preset
    std::string name = "camouflage";
    int size = 512;             // image side per footprint (ranges: figure4Members())
    int referenceSamples = 64;  // per axis: the cap
    // The reference and the exact statistics are rendered at the fewest
    // samples (up to the cap) that move them by less than this when doubled
    // (studies/reference_samples.h): mean ‖·‖₂, linear RGB.
    double referenceTolerance = 5e-4;
    std::vector<int> footprints{1, 2, 4, 8, 16, 32, 64, 128};
    // The response of the estimated statistics (the exact ones go through
    // the smooth table, as in the paper's Fig. 4b).
    ResponseOptions response;
    // Which figure this is: the file names' prefix and the titles (figure4,
    // figure11).
    std::string figure = "figure4";
    // Ŝ with the exact statistics and its error (Figure 4's rows 2–3;
    // Figure 11 shows only S̄, Ŝ(μ̂, Σ̂) and the error).
    bool exactStatistics = true;
    // Where set, the colour the pattern fades to as the footprint grows (a
    // phasor profile's mean): the mean distances of S̄ and Ŝ to it per footprint.
    std::optional<Rgb> fadesTo;
};
// The entries of Figure4Options' numbers (its check; the CLI's flags).
std::span<const OptionMember<Figure4Options>> figure4Members();
void validateFigure4(const Figure4Options& options);

struct Figure4Column {
    int footprint = 0;
    double meanErrorExact = 0, meanErrorEstimated = 0;  // mean ‖Ŝ − S̄‖₂ over the pixels (RGB)
    double meanErrorNone = 0;                           // mean ‖S − S̄‖₂: the pixel centres, unfiltered
    // mean ‖Ŝ(μ̂, Σ̂) − S̄‖₂ with each estimator of kVarianceEstimatorNames
    // after the paper's (meanErrorEstimated): deliot-heitz, sub-probes, sub-probes-4x4,
    // sub-probes-8x8-fine-means.
    std::vector<double> meanErrorOtherEstimators;
    // With fadesTo: mean ‖S̄ − m‖₂ and ‖Ŝ(μ̂, Σ̂) − m‖₂ over the pixels.
    double meanFadeReference = 0, meanFadeEstimated = 0;
    // The samples per axis the reference (exact statistics) were rendered
    // with, and how much they moved on doubling them.
    int referenceSamples = 0, exactSamples = 0;
    double referenceChange = 0, exactChange = 0;
};
struct Figure4Result {
    std::vector<Figure4Column> columns;
    Table table;                  // <figure>.csv and the summary
    std::vector<Figure> figures;  // <figure>.png, <figure>_errors.png, then the images per footprint
};
Figure4Result figure4(const Figure4Options& options, const StudyProgress& progress = {});
// Its report: <figure>.csv and the figures (figure: figure4, figure11).
Report figure4Report(const Figure4Result& result, const std::string& figure);

// Per pixel ‖a − b‖₂ over RGB (a 1-channel image), and its mean.
Image errorMap(const Image& a, const Image& b, double& mean);

// Which estimators of kVarianceEstimatorNames a table compares: all of them
// (the render-error table), or those after the paper's, which Figures 4, 11
// and 14 give a column each beside their own paper-estimator column.
enum class EstimatorSet { All, AfterPaper };
// estimatorErrors renders the camera with each of the set (filter as given,
// statistics from the estimators) and returns mean ‖Ŝ − S̄‖₂ against the
// reference, in kVarianceEstimatorNames' order; estimatorColumns appends
// their table columns, keyed keyPrefix + the name in snake case and
// captioned caption(name). `parts`: the study's PartCache, if it keeps one.
std::vector<double> estimatorErrors(const GraphPattern& pattern, FilterOptions filter, const Camera& camera,
                                    const Image& reference, EstimatorSet set, PartCache* parts = nullptr);
void estimatorColumns(Table& table, const std::string& keyPrefix,
                      const std::function<std::string(const std::string&)>& caption, EstimatorSet set);

// Figure 11: Figure 4's comparison for the phasor sine pattern
// (phasor-stripes): S̄, Ŝ(μ̂, Σ̂) and ‖Ŝ − S̄‖₂ per footprint, fading to the
// profile's mean colour. The defaults; size, samples, footprints and the
// response may be changed before calling figure4.
Figure4Options figure11Options();

// Figures 7–9: each a sheet of four presets (pattern, colormap, where N
// falls, the two noises), `size` pixels per pattern, [64, 2048]. Figures 7
// and 8 compare colormaps, so their four panels share one pair of noises
// (those of the first preset, panel a) under each preset's colormap; Figure
// 9 compares noises, so each panel is its preset as it is.
struct PaperFigurePanel {
    std::string preset, caption;
    PatternSpec spec;  // what the panel shows (for 7 and 8: panel a's noises, this preset's colormap)
};
// Figure 10 (studies/phasor_figures.h) is a sheet of four presets too: the
// phasor variants, each as it is.
// figure: 7 to 10 (InputError otherwise).
std::vector<PaperFigurePanel> paperFigurePanels(int figure);
// One figure's sheet, `size` pixels per pattern (not validated here).
Figure paperFigureSheet(int figure, int size, const StudyProgress& progress = {});
void validateFigures7to9(int size);
std::vector<Figure> figures7to9(int size, const StudyProgress& progress = {});
Report figures7to9Report(const std::vector<Figure>& sheets);

}  // namespace stochtex
