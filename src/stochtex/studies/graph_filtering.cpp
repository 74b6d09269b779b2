#include "stochtex/studies/graph_filtering.h"

#include <algorithm>
#include <array>

#include "stochtex/core/error.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/paper.h"
#include "stochtex/studies/pattern_sheet.h"
#include "stochtex/studies/reference_samples.h"

namespace stochtex {

Figure14Options figure14Options() {
    Figure14Options o;
    o.pattern = loadPreset("figure14");
    return o;
}

std::span<const OptionMember<Figure14Options>> figure14Members() {
    using O = Figure14Options;
    static const OptionMember<O> members[] = {
        {"size", "Image size per footprint", 16, 2048, &O::size},
        {"referenceSamples", "Max reference samples per axis", 1, 4096, &O::referenceSamples},
    };
    return members;
}

void validateFigure14(const Figure14Options& o) {
    if (!o.pattern.graph)
        throw InputError(o.name + ": Figure 14 needs a texture graph (a pattern file with \"nodes\")");
    checkMembers(o, figure14Members());
    validateReferenceTolerance(o.referenceTolerance);
    if (o.footprints.empty() || o.footprints.size() > 12)
        throw InputError::parameter("footprints", "needs 1 to 12 footprints");
    for (const int f : o.footprints)
        if (f < 1 || f > 4096)
            throw InputError::parameter("footprints", "each must be in [1, 4096], got " + std::to_string(f));
}

namespace {

// The methods compared, in the sheet's order after the reference.
struct Method {
    const char* name;
    const char* file;
    StatisticsSource source;
    GraphMoments moments;
};
const std::array<Method, 4> kMethods{{
    {"none", "_none.png", StatisticsSource::Point, GraphMoments::Matched},
    {"mean-only", "_mean_only.png", StatisticsSource::Estimators, GraphMoments::MeanOnly},
    {"matched, exact stats", "_matched_exact.png", StatisticsSource::Exact, GraphMoments::Matched},
    {"matched", "_matched.png", StatisticsSource::Estimators, GraphMoments::Matched},
}};

}  // namespace

Figure14Result figure14(const Figure14Options& o, const Progress& progress) {
    validateFigure14(o);
    const GraphPattern graph = GraphPattern::build(o.pattern);
    // Its tables and pyramids, built once for every render of the figure
    // (its beta-axis tables take a second or more each).
    PartCache partCache;
    struct Column {
        Figure14Column numbers;
        Image reference;
        std::array<Image, 4> images, errors;
    };
    std::vector<Column> cols;
    for (const int s : o.footprints) {
        const Progress part = progressPart(progress, int(cols.size()), int(o.footprints.size()),
                                           "figure14: footprint " + std::to_string(s) + "²");
        Camera cam;
        cam.view.width = cam.view.height = o.size;
        cam.view.scale = s;
        FilterOptions fo;
        fo.referenceMaxSamples = o.referenceSamples;
        fo.response.prefilter = o.prefilter;
        Column c;
        c.numbers.footprint = s;
        // The reference and the exact statistics take nearly all the time,
        // each at the fewest samples that have converged.
        fo.source = StatisticsSource::Reference;
        fo = atConvergedSamples(graph, fo, cam, o.referenceTolerance, c.numbers.referenceSamples,
                                c.numbers.referenceChange, &partCache);
        c.reference = FilteredGraph(graph, fo, GraphMoments::Matched, &partCache)
                          .render(cam, progressPart(part, 0.0, 0.5, "reference"));
        double* errors[4] = {&c.numbers.none, &c.numbers.meanOnly, &c.numbers.matchedExact, &c.numbers.matched};
        for (size_t m = 0; m < kMethods.size(); ++m) {
            fo.source = kMethods[m].source;
            const bool exact = kMethods[m].source == StatisticsSource::Exact;
            if (exact) {
                fo.referenceMaxSamples = o.referenceSamples;
                fo = atConvergedSamples(graph, fo, cam, o.referenceTolerance, c.numbers.exactSamples,
                                        c.numbers.exactChange, &partCache);
            }
            c.images[m] = FilteredGraph(graph, fo, kMethods[m].moments, &partCache)
                              .render(cam, exact ? progressPart(part, 0.5, 1.0, "exact statistics") : Progress{});
            c.errors[m] = errorMap(c.images[m], c.reference, *errors[m]);
        }
        c.numbers.matchedOtherEstimators =
            estimatorErrors(graph, fo, cam, c.reference, EstimatorSet::AfterPaper, &partCache);
        cols.push_back(std::move(c));
    }
    // One colour scale for every error map: the 99.5th percentile of all.
    std::vector<float> all;
    for (const auto& c : cols)
        for (const Image& e : c.errors) all.insert(all.end(), e.data().begin(), e.data().end());
    const size_t at = all.size() * 995 / 1000;
    std::nth_element(all.begin(), all.begin() + ptrdiff_t(at), all.end());
    const double vmax = std::max(1e-3, double(all[at]));

    Figure14Result res;
    res.figures.push_back({"figure14.png", graphSheet(graph, *o.pattern.graph, o.pattern.scale, o.size).sheet,
                           "Figure 14 (" + o.name +
                               "): the graph's stages, left to right: its leaves (the linear part folded into "
                               "examples, fields shown as gray) and each operation node, the last being the pattern, " +
                               std::to_string(o.size) + "² pixels each at the pattern's scale."});
    res.table.columns = {{"footprint", "footprint", ""},
                         {"mean_error_none", "none: mean ‖S − S̄‖₂", ""},
                         {"mean_error_mean_only", "mean-only: mean ‖Ŝ − S̄‖₂", ""},
                         {"mean_error_matched_exact", "matched, exact statistics: mean ‖Ŝ − S̄‖₂", ""},
                         {"mean_error_matched", "matched, estimators: mean ‖Ŝ − S̄‖₂", ""}};
    estimatorColumns(
        res.table, "mean_error_matched_",
        [](const std::string& name) { return "matched, " + name + " estimator: mean ‖Ŝ − S̄‖₂"; },
        EstimatorSet::AfterPaper);
    // How good the brute-force images are (studies/reference_samples.h).
    res.table.columns.push_back({"reference_samples", "S̄: samples per pixel", ""});
    res.table.columns.push_back({"reference_change", "S̄: change on doubling them", ""});
    res.table.columns.push_back({"exact_samples", "exact statistics: samples per pixel", ""});
    res.table.columns.push_back({"exact_change", "exact statistics: change on doubling them", ""});
    const int thumb = std::min(o.size, 128);
    std::vector<std::vector<Image>> rows(1 + 2 * kMethods.size());
    std::vector<std::vector<std::string>> captions(rows.size());
    std::vector<Figure> images;
    std::vector<PlotSeries> series;
    const std::array<Rgb, 4> colours{{{0.6f, 0.6f, 0.6f}, {0.85f, 0.4f, 0.1f}, {0.1f, 0.6f, 0.2f}, {0.1f, 0.3f, 0.8f}}};
    for (size_t m = 0; m < kMethods.size(); ++m) series.push_back({kMethods[m].name, {}, {}, colours[m]});
    for (const auto& c : cols) {
        const int s = c.numbers.footprint;
        const std::string tag = "fp" + std::to_string(s), fp = std::to_string(s) + "²";
        TableCell first(fp);
        first.number = s;
        const double values[4] = {c.numbers.none, c.numbers.meanOnly, c.numbers.matchedExact, c.numbers.matched};
        std::vector<TableCell> cells{first, TableCell::value(values[0]), TableCell::value(values[1]),
                                     TableCell::value(values[2]), TableCell::value(values[3])};
        for (const double error : c.numbers.matchedOtherEstimators) cells.push_back(TableCell::value(error));
        cells.push_back(TableCell::integer((long long)c.numbers.referenceSamples * c.numbers.referenceSamples));
        cells.push_back(TableCell::value(c.numbers.referenceChange, "%.5f"));
        cells.push_back(TableCell::integer((long long)c.numbers.exactSamples * c.numbers.exactSamples));
        cells.push_back(TableCell::value(c.numbers.exactChange, "%.5f"));
        res.table.add(std::move(cells));
        res.columns.push_back(c.numbers);
        // Figures hold display codes (report/page.h): renders are encoded, error maps drawn so.
        Image ref = srgbFromLinear(c.reference);
        rows[0].push_back(resizeSmooth(ref, thumb, thumb));
        captions[0].push_back("reference " + fp);
        images.push_back({tag + "_reference.png", std::move(ref), ""});
        for (size_t m = 0; m < kMethods.size(); ++m) {
            Image img = srgbFromLinear(c.images[m]);
            Image err = colourise(c.errors[m], 0.0, vmax, HeatPalette::Viridis);
            rows[1 + 2 * m].push_back(resizeSmooth(img, thumb, thumb));
            rows[2 + 2 * m].push_back(resizeSmooth(err, thumb, thumb));
            captions[1 + 2 * m].push_back(std::string(kMethods[m].name) + " " + fp);
            captions[2 + 2 * m].push_back("error " + fp);
            images.push_back({tag + kMethods[m].file, std::move(img), ""});
            series[m].x.push_back(s);
            series[m].y.push_back(values[m]);
        }
    }
    rows.push_back(
        {colourLegend(0.0, vmax, HeatPalette::Viridis, "error ‖· − S̄‖₂ (linear RGB), one scale for every map")});
    captions.push_back({""});
    res.figures.push_back(
        {"figure14_filtering.png", sheet(rows, captions),
         "Filtering the graph (" + o.name + ", " + std::to_string(o.size) + "² per footprint, prefiltered tables " +
             enumName(kPrefilterModeNames, o.prefilter) + "): rows = reference S̄ (≤ " +
             std::to_string(o.referenceSamples) +
             "² samples per pixel); then none, mean-only, matched with exact statistics and matched with the "
             "estimators, each above its error; columns = footprint " +
             std::to_string(o.footprints.front()) + " … " + std::to_string(o.footprints.back()) + "²."});
    LinePlotOptions lo;
    lo.title = "Figure 14: mean error vs footprint (" + o.name + ")";
    lo.xLabel = "footprint side (texels)";
    lo.yLabel = "mean ‖· − S̄‖₂";
    lo.logX = true;
    res.figures.push_back(chartFigure("figure14_errors.png", {series, lo},
                                      "Mean error against the reference per footprint (log scale in the footprint)."));
    for (auto& f : images) res.figures.push_back(std::move(f));
    return res;
}

Report figure14Report(const Figure14Result& r) {
    return sectionReport("Figure 14: a texture graph, filtered by moment matching", {{"figure14.csv", r.table}},
                         r.figures);
}

}  // namespace stochtex
