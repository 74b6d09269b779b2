#include "stochtex/studies/paper.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/pattern_sheet.h"
#include "stochtex/studies/reference_samples.h"

namespace stochtex {

namespace {

const char* kTableNoiseNames[2] = {"low frequency isotropic", "high frequency anisotropic"};

// Paper Table 1 (Grenier et al. 2022), absolute (relative) mean errors of
// the paper's estimator, for the side-by-side comparison.
struct PublishedRow {
    int footprint;
    double v[8];  // low: μ abs, μ rel, σ abs, σ rel; high: the same
};
const PublishedRow kPublished[] = {
    {2, {0.0108, 0.0230, 0.0014, 0.3269, 0.0455, 0.0910, 0.0111, 0.3973}},
    {4, {0.0181, 0.0383, 0.0027, 0.2902, 0.1131, 0.2261, 0.0283, 0.4534}},
    {8, {0.0330, 0.0698, 0.0056, 0.3085, 0.1018, 0.2035, 0.0394, 0.3345}},
    {16, {0.0453, 0.0959, 0.0117, 0.3265, 0.0322, 0.0643, 0.0459, 0.2820}},
    {32, {0.0818, 0.1732, 0.0248, 0.3660, 0.0063, 0.0127, 0.0477, 0.2793}},
    {64, {0.0851, 0.1801, 0.0355, 0.3194, 0.0017, 0.0033, 0.0441, 0.2493}},
    {128, {0.0619, 0.1310, 0.0344, 0.2444, 0.0005, 0.0009, 0.0342, 0.1882}},
};
// measureEstimatorErrors' rows: kVarianceEstimatorNames, then "global" (so
// a new estimator gets its block and its curve without an edit here).
std::vector<std::string> tableEstimators() {
    std::vector<std::string> names;
    for (const auto& [name, estimator] : kVarianceEstimatorNames) names.push_back(name);
    names.emplace_back("global");
    return names;
}

// "abs (rel)" as the paper prints its cells.
TableCell errorCell(double a, double r) {
    char b[48];
    std::snprintf(b, sizeof b, "%.4f (%.4f)", a, r);
    return TableCell(b);
}

Table paperLayout(const std::string& title, const std::string& note) {
    Table t;
    t.title = title;
    t.note = note;
    t.columns = {{"footprint", "footprint", ""},
                 {"low_mu", "low freq. μ̂", ""},
                 {"low_sigma", "low freq. σ̂", ""},
                 {"high_mu", "high freq. μ̂", ""},
                 {"high_sigma", "high freq. σ̂", ""}};
    return t;
}

std::string squareName(int s) { return std::to_string(s) + "×" + std::to_string(s); }

}  // namespace

const char* table1NoiseName(int which) { return kTableNoiseNames[which]; }

PatternSpec table1PatternSpec(int which, uint32_t seed) {
    PatternSpec spec;
    spec.name = "table1";
    spec.seed = seed;
    SpectrumComponent c;
    if (which == 0) {
        c.shape = SpectrumShape::LowPass;
        c.frequency = 8;
    } else {
        c.shape = SpectrumShape::BiLobe;
        c.frequency = 32;
        c.bandwidth = 3;
        c.orientation = 30;
    }
    for (auto& n : spec.noise) {
        n.source = NoiseSpec::Source::Spectrum;
        n.spectrum.size = kTable1ExampleSize;
        n.spectrum.components = {c};
    }
    spec.colormap.source = ColormapSpec::Source::Analytic;
    spec.colormap.analytic = AnalyticColormap::Gaussian;
    return spec;
}

void validateTable1(const Table1Options& o) { validateEstimatorErrorOptions(o.errors, kTable1ExampleSize); }

TiledField table1Field(int which, uint32_t seed) {
    // The file's program: its one pair of leaves is N.
    return GraphPattern::build(table1PatternSpec(which, seed)).leafPairs().front();
}

Table1Result table1(const Table1Options& o, const StudyProgress& progress) {
    validateTable1(o);
    std::array<std::vector<EstimatorError>, 2> rows;
    for (int which = 0; which < 2; ++which) {
        // Steps of one noise: building its examples, then each footprint size.
        const Progress noise =
            progressPart(progress, which, 2, std::string("table1: ") + kTableNoiseNames[which] + " noise");
        const int steps = 1 + int(o.errors.footprints.size());
        if (noise) noise(0.0, "building the 512² examples");
        rows[size_t(which)] = measureEstimatorErrors(table1Field(which, o.seed), o.errors, [&](int k) {
            if (noise) noise(double(1 + k) / steps, "footprint " + std::to_string(k) + "/" + std::to_string(steps - 1));
        });
    }
    return table1FromRows(std::move(rows), o);
}

Table1Result table1FromRows(std::array<std::vector<EstimatorError>, 2> rows, const Table1Options& o) {
    validateTable1(o);
    const size_t expected = o.errors.footprints.size() * EstimatorErrorSampler::estimators().size();
    if (rows[0].size() != expected || rows[1].size() != expected)
        throw std::invalid_argument("table1FromRows: expected " + std::to_string(expected) + " rows per noise, got " +
                                    std::to_string(rows[0].size()) + " and " + std::to_string(rows[1].size()));
    Table1Result res;
    res.rows = std::move(rows);
    res.data.columns = {{"noise", "noise", ""},
                        {"footprint", "footprint", "texels"},
                        {"estimator", "estimator", ""},
                        {"mu_abs", "mean |μ̂ − μ|", ""},
                        {"mu_rel", "mean |μ̂ − μ|/|μ|", ""},
                        {"sigma_abs", "mean |σ̂ − σ|", ""},
                        {"sigma_rel", "mean |σ̂ − σ|/σ", ""},
                        {"mean_mu", "mean μ", ""},
                        {"mean_sigma", "mean σ", ""},
                        {"values", "values", ""}};
    for (int which = 0; which < 2; ++which)
        for (const auto& r : res.rows[size_t(which)])
            res.data.add({which == 0 ? "low" : "high", TableCell::integer(r.footprint), r.estimator,
                          TableCell::value(r.muAbs), TableCell::value(r.muRel), TableCell::value(r.sigmaAbs),
                          TableCell::value(r.sigmaRel), TableCell::value(r.meanMu), TableCell::value(r.meanSigma),
                          TableCell::integer(r.values)});

    // Laid out like the paper's table: one block per estimator.
    for (const std::string& est : tableEstimators()) {
        Table t = paperLayout("Estimator: " + est,
                              "(" + std::to_string(o.errors.count) + " footprints per size × 2 components)");
        for (size_t i = 0; i < res.rows[0].size(); ++i) {
            const auto& a = res.rows[0][i];
            if (a.estimator != est) continue;
            const auto& b = res.rows[1][i];
            t.add({squareName(a.footprint), errorCell(a.muAbs, a.muRel), errorCell(a.sigmaAbs, a.sigmaRel),
                   errorCell(b.muAbs, b.muRel), errorCell(b.sigmaAbs, b.sigmaRel)});
        }
        res.tables.push_back(std::move(t));
    }
    Table pub = paperLayout("Published (Grenier et al. 2022, Table 1), paper's estimator", "");
    for (const auto& p : kPublished)
        pub.add({squareName(p.footprint), errorCell(p.v[0], p.v[1]), errorCell(p.v[2], p.v[3]),
                 errorCell(p.v[4], p.v[5]), errorCell(p.v[6], p.v[7])});
    res.tables.push_back(std::move(pub));

    // Error vs footprint, log scale, ours beside the published numbers.
    for (int which = 0; which < 2; ++which)
        for (int moment = 0; moment < 2; ++moment) {
            std::vector<PlotSeries> series;
            const std::array<float, 3> colours[5] = {{0.1f, 0.3f, 0.8f},
                                                     {0.85f, 0.45f, 0.1f},
                                                     {0.75f, 0.15f, 0.55f},
                                                     {0.5f, 0.5f, 0.5f},
                                                     {0.2f, 0.7f, 0.8f}};
            size_t c = 0;
            for (const std::string& est : tableEstimators()) {
                PlotSeries s{"ours, " + est, {}, {}, colours[c++ % 5]};
                for (const auto& r : res.rows[size_t(which)])
                    if (r.estimator == est) {
                        s.x.push_back(r.footprint);
                        s.y.push_back(moment == 0 ? r.muAbs : r.sigmaAbs);
                    }
                series.push_back(s);
            }
            PlotSeries pub{"published (paper)", {}, {}, {0.1f, 0.6f, 0.2f}};
            for (const auto& p : kPublished)
                if (std::find(o.errors.footprints.begin(), o.errors.footprints.end(), p.footprint) !=
                    o.errors.footprints.end()) {
                    pub.x.push_back(p.footprint);
                    pub.y.push_back(p.v[which * 4 + moment * 2]);
                }
            series.push_back(pub);
            LinePlotOptions lo;
            lo.title = std::string(kTableNoiseNames[which]) + ": mean |" + (moment == 0 ? "μ̂" : "σ̂") + " error|";
            lo.xLabel = "footprint side (texels)";
            lo.yLabel = "mean absolute error";
            lo.logX = lo.logY = true;
            const std::string file =
                std::string("table1_") + (which == 0 ? "low" : "high") + "_" + (moment == 0 ? "mu" : "sigma") + ".png";
            res.figures.push_back(chartFigure(
                file, {series, lo}, lo.title + " vs footprint size (log-log), ours and the published Table 1"));
        }
    return res;
}

std::span<const OptionMember<Figure4Options>> figure4Members() {
    using O = Figure4Options;
    static const OptionMember<O> members[] = {
        {"size", "Image size per footprint", 16, 4096, &O::size},
        {"referenceSamples", "Max reference samples per axis", 1, 4096, &O::referenceSamples},
    };
    return members;
}

void validateFigure4(const Figure4Options& o) {
    const std::string what = o.figure == "figure4" ? "figure 4" : o.figure;
    checkMembers(o, figure4Members());
    validateReferenceTolerance(o.referenceTolerance);
    if (o.footprints.empty()) throw InputError(what + ": no footprints");
    for (int s : o.footprints)
        if (s < 1 || s > 65536) throw InputError(what + ": footprints must be in [1, 65536], got " + std::to_string(s));
}

Image errorMap(const Image& a, const Image& b, double& mean) {
    Image e(a.width(), a.height(), 1, Image::Uninitialized{});
    double s = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            double d2 = 0;
            for (int c = 0; c < 3; ++c) d2 += std::pow(double(a.at(x, y, c)) - b.at(x, y, c), 2);
            e.at(x, y) = float(std::sqrt(d2));
            s += e.at(x, y);
        }
    mean = s / double(a.pixelCount());
    return e;
}

namespace {

// kVarianceEstimatorNames lists the paper's estimator first.
size_t firstOf(EstimatorSet set) { return set == EstimatorSet::All ? 0 : 1; }

}  // namespace

std::vector<double> estimatorErrors(const GraphPattern& pattern, FilterOptions filter, const Camera& camera,
                                    const Image& reference, EstimatorSet set, PartCache* parts) {
    filter.source = StatisticsSource::Estimators;
    std::vector<double> errors;
    for (size_t e = firstOf(set); e < kVarianceEstimatorNames.size(); ++e) {
        filter.estimator = kVarianceEstimatorNames[e].second;
        (void)errorMap(FilteredGraph(pattern, filter, GraphMoments::Matched, parts).render(camera), reference,
                       errors.emplace_back());
    }
    return errors;
}

void estimatorColumns(Table& table, const std::string& keyPrefix,
                      const std::function<std::string(const std::string&)>& caption, EstimatorSet set) {
    for (size_t e = firstOf(set); e < kVarianceEstimatorNames.size(); ++e) {
        const std::string& name = kVarianceEstimatorNames[e].first;
        std::string key = keyPrefix + name;
        std::replace(key.begin(), key.end(), '-', '_');
        table.columns.push_back({key, caption(name), ""});
    }
}

namespace {

// Mean over the pixels of ‖a − c‖₂ (RGB).
double meanDistance(const Image& a, const Rgb& c) {
    double s = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            double d2 = 0;
            for (int k = 0; k < 3; ++k) d2 += std::pow(double(a.at(x, y, k)) - c[size_t(k)], 2);
            s += std::sqrt(d2);
        }
    return s / double(a.pixelCount());
}

// "figure11" → "Figure 11".
std::string figureTitle(const std::string& figure) {
    return figure.rfind("figure", 0) == 0 ? "Figure " + figure.substr(6) : figure;
}

}  // namespace

Figure4Options figure11Options() {
    Figure4Options o;
    o.pattern = loadPreset("phasor-stripes");
    o.name = "phasor-stripes";
    o.figure = "figure11";
    o.exactStatistics = false;
    o.fadesTo = buildPhasorProfile(o.pattern.colormap).mean();
    return o;
}

Figure4Result figure4(const Figure4Options& o, const StudyProgress& progress) {
    validateFigure4(o);
    const GraphPattern pattern = GraphPattern::build(o.pattern);  // the file's program: a plain pattern or a graph
    // Its tables and pyramids, built once for every render of the figure
    // (a graph's beta-axis tables take a second or more each).
    PartCache partCache;
    struct Column {
        Figure4Column numbers;
        Image reference, exact, estimated, errExact, errEstimated;
    };
    std::vector<Column> cols;
    for (int s : o.footprints) {
        const Progress part = progressPart(progress, int(cols.size()), int(o.footprints.size()),
                                           o.figure + ": footprint " + std::to_string(s) + "²");
        Camera cam;
        cam.view.width = cam.view.height = o.size;
        cam.view.scale = s;
        Column c;
        c.numbers.footprint = s;
        FilterOptions fo;
        fo.referenceMaxSamples = o.referenceSamples;
        // The brute-force renders take nearly all the time, about equally;
        // each at the fewest samples that have converged.
        const double referenceShare = o.exactStatistics ? 0.5 : 1.0;
        fo.use(parseFilter("reference"));
        fo = atConvergedSamples(pattern, fo, cam, o.referenceTolerance, c.numbers.referenceSamples,
                                c.numbers.referenceChange, &partCache);
        c.reference = FilteredGraph(pattern, fo, GraphMoments::Matched, &partCache)
                          .render(cam, progressPart(part, 0.0, referenceShare, "reference"));
        if (o.exactStatistics) {
            fo.referenceMaxSamples = o.referenceSamples;
            fo.use(parseFilter("exact"));
            fo = atConvergedSamples(pattern, fo, cam, o.referenceTolerance, c.numbers.exactSamples,
                                    c.numbers.exactChange, &partCache);
            c.exact = FilteredGraph(pattern, fo, GraphMoments::Matched, &partCache)
                          .render(cam, progressPart(part, 0.5, 1.0, "exact statistics"));
        }
        fo.source = StatisticsSource::Estimators;
        fo.response = o.response;
        c.estimated = FilteredGraph(pattern, fo, GraphMoments::Matched, &partCache).render(cam);
        if (o.exactStatistics) c.errExact = errorMap(c.exact, c.reference, c.numbers.meanErrorExact);
        c.errEstimated = errorMap(c.estimated, c.reference, c.numbers.meanErrorEstimated);
        c.numbers.meanErrorOtherEstimators =
            estimatorErrors(pattern, fo, cam, c.reference, EstimatorSet::AfterPaper, &partCache);
        // Not filtering at all: the pixel centres, what filtering must beat.
        (void)errorMap(
            FilteredGraph(pattern, fo.use(parseFilter("none")), GraphMoments::Matched, &partCache).render(cam),
            c.reference, c.numbers.meanErrorNone);
        if (o.fadesTo) {
            c.numbers.meanFadeReference = meanDistance(c.reference, *o.fadesTo);
            c.numbers.meanFadeEstimated = meanDistance(c.estimated, *o.fadesTo);
        }
        cols.push_back(std::move(c));
    }
    // One colour scale for every error map: the 99.5th percentile of all.
    std::vector<float> all;
    for (const auto& c : cols) {
        all.insert(all.end(), c.errExact.data().begin(), c.errExact.data().end());
        all.insert(all.end(), c.errEstimated.data().begin(), c.errEstimated.data().end());
    }
    std::nth_element(all.begin(), all.begin() + ptrdiff_t(all.size() * 995 / 1000), all.end());
    const double vmax = std::max(1e-3, double(all[all.size() * 995 / 1000]));

    Figure4Result res;
    const std::string title = figureTitle(o.figure);
    res.table.columns = {{"footprint", "footprint", ""},
                         {"mean_error_none", "mean ‖S − S̄‖₂ (none: pixel centres)", ""}};
    if (o.exactStatistics)
        res.table.columns.push_back({"mean_error_exact_stats", "mean ‖Ŝ(μ, Σ) − S̄‖₂ (exact statistics)", ""});
    res.table.columns.push_back({"mean_error_estimators", "mean ‖Ŝ(μ̂, Σ̂) − S̄‖₂ (estimators)", ""});
    estimatorColumns(
        res.table, "mean_error_",
        [](const std::string& name) { return "mean ‖Ŝ(μ̂, Σ̂) − S̄‖₂ (" + name + " estimator)"; },
        EstimatorSet::AfterPaper);
    if (o.fadesTo) {
        res.table.columns.push_back({"mean_fade_reference", "mean ‖S̄ − m‖₂ (m: the profile's mean)", ""});
        res.table.columns.push_back({"mean_fade_estimators", "mean ‖Ŝ(μ̂, Σ̂) − m‖₂", ""});
    }
    // How good the brute-force images are: their samples, and how far they
    // moved when the samples doubled (studies/reference_samples.h).
    res.table.columns.push_back({"reference_samples", "S̄: samples per pixel", ""});
    res.table.columns.push_back({"reference_change", "S̄: change on doubling them", ""});
    if (o.exactStatistics) {
        res.table.columns.push_back({"exact_samples", "exact statistics: samples per pixel", ""});
        res.table.columns.push_back({"exact_change", "exact statistics: change on doubling them", ""});
    }
    const int thumb = std::min(o.size, 192);
    // Rows of the sheet: reference, [exact, its error,] estimated, its error.
    std::vector<int> shownRows = o.exactStatistics ? std::vector<int>{0, 1, 2, 3, 4} : std::vector<int>{0, 3, 4};
    std::vector<std::vector<Image>> rows(shownRows.size());
    std::vector<std::vector<std::string>> captions(shownRows.size());
    std::vector<Figure> images;
    const char* rowNames[5] = {"reference", "exact stats", "error, exact", "estimators", "error, estim."};
    const char* rowFiles[5] = {"_reference.png", "_exact.png", "_error_exact.png", "_estimated.png",
                               "_error_estimated.png"};
    for (const auto& c : cols) {
        const int s = c.numbers.footprint;
        TableCell fp(std::to_string(s) + "²");
        fp.number = s;
        std::vector<TableCell> cells{fp, TableCell::value(c.numbers.meanErrorNone)};
        if (o.exactStatistics) cells.push_back(TableCell::value(c.numbers.meanErrorExact));
        cells.push_back(TableCell::value(c.numbers.meanErrorEstimated));
        for (const double error : c.numbers.meanErrorOtherEstimators) cells.push_back(TableCell::value(error));
        if (o.fadesTo) {
            cells.push_back(TableCell::value(c.numbers.meanFadeReference));
            cells.push_back(TableCell::value(c.numbers.meanFadeEstimated));
        }
        cells.push_back(TableCell::integer((long long)c.numbers.referenceSamples * c.numbers.referenceSamples));
        cells.push_back(TableCell::value(c.numbers.referenceChange, "%.5f"));
        if (o.exactStatistics) {
            cells.push_back(TableCell::integer((long long)c.numbers.exactSamples * c.numbers.exactSamples));
            cells.push_back(TableCell::value(c.numbers.exactChange, "%.5f"));
        }
        res.table.add(std::move(cells));
        res.columns.push_back(c.numbers);
        const std::string tag = "fp" + std::to_string(s);
        const Image* shown[5] = {&c.reference, &c.exact, &c.errExact, &c.estimated, &c.errEstimated};
        for (size_t i = 0; i < shownRows.size(); ++i) {
            const int r = shownRows[i];
            const bool isError = r == 2 || r == 4;
            // Figures hold display codes (report/page.h): renders are encoded, error maps drawn so.
            Image img = isError ? colourise(*shown[r], 0.0, vmax, HeatPalette::Viridis) : srgbFromLinear(*shown[r]);
            rows[i].push_back(resizeSmooth(img, thumb, thumb));
            captions[i].push_back(std::string(rowNames[r]) + " " + std::to_string(s) + "²");
            images.push_back({tag + rowFiles[r], std::move(img), ""});
        }
    }
    rows.push_back(
        {colourLegend(0.0, vmax, HeatPalette::Viridis, "error ‖Ŝ − S̄‖₂ (RGB), one scale for every error map")});
    captions.push_back({""});

    PlotSeries a{"exact statistics (eq. 5)", {}, {}, {0.1f, 0.6f, 0.2f}},
        b{"estimators (eq. 5, 8, 12)", {}, {}, {0.1f, 0.3f, 0.8f}},
        none{"none (pixel centres)", {}, {}, {0.6f, 0.6f, 0.6f}};
    for (const auto& c : res.columns) {
        none.x.push_back(c.footprint);
        none.y.push_back(c.meanErrorNone);
        a.x.push_back(c.footprint);
        a.y.push_back(c.meanErrorExact);
        b.x.push_back(c.footprint);
        b.y.push_back(c.meanErrorEstimated);
    }
    std::vector<PlotSeries> series{none};
    if (o.exactStatistics) series.push_back(a);
    series.push_back(b);
    LinePlotOptions lo;
    lo.title = title + ": mean error vs footprint (" + o.name + ")";
    lo.xLabel = "footprint side (texels)";
    lo.yLabel = "mean ‖Ŝ − S̄‖₂";
    lo.logX = true;
    const std::string rowList = o.exactStatistics
                                    ? "reference S̄ (≤ " + std::to_string(o.referenceSamples) +
                                          "² samples per pixel), Ŝ with exact μ, Σ, its error, Ŝ with the "
                                          "estimators, its error"
                                    : "reference S̄ (≤ " + std::to_string(o.referenceSamples) +
                                          "² samples per pixel), Ŝ(μ̂, Σ̂) with the estimators, the "
                                          "error ‖Ŝ − S̄‖₂";
    res.figures.push_back({o.figure + ".png", sheet(rows, captions),
                           title + " (" + o.name + ", " + std::to_string(o.size) + "² per footprint): rows = " +
                               rowList + "; columns = footprint " + std::to_string(o.footprints.front()) + " … " +
                               std::to_string(o.footprints.back()) + "²."});
    res.figures.push_back(
        chartFigure(o.figure + "_errors.png", {series, lo}, "Mean error per footprint (log scale in the footprint)."));
    for (auto& f : images) res.figures.push_back(std::move(f));
    return res;
}

namespace {

// Figures 7–9: each a sheet of four presets.
struct PaperFigure {
    int number;
    const char* file;
    const char* title;
    bool sameNoises;  // the panels differ only in H (panel a's noises throughout)
    std::array<const char*, 4> presets, captions;
};
const PaperFigure kFigures[4] = {
    {7,
     "figure7.png",
     "Figure 7: colormap layouts (same noises)",
     true,
     {"borders", "concentric", "bands", "oblique-blots"},
     {"(a) colours on the borders", "(b) concentric regions", "(c) 1D horizontal bands", "(d) oblique boundaries"}},
    {8,
     "figure8.png",
     "Figure 8: palettes (same noises)",
     true,
     {"weld", "camouflage", "marble", "bordered-blots"},
     {"(a) three weld colours", "(b) camouflage", "(c) marble strands", "(d) bordered blots"}},
    {9,
     "figure9.png",
     "Figure 9: noise spectra",
     false,
     {"weld", "low-high", "iso-aniso", "woven"},
     {"(a) two low-frequency isotropic", "(b) low + high frequency", "(c) isotropic + anisotropic",
      "(d) two orientations"}},
    {10,
     "figure10.png",
     "Figure 10: phasor noise as a special case (N = a quadrature pair, H = P ∘ atan2)",
     false,
     {"phasor-stripes", "phasor-sawtooth", "phasor-square", "phasor-colour"},
     {"(a) bi-lobe noises, sine profile", "(b) sawtooth profile", "(c) sum of two bi-lobes, square profile (duty 0.35)",
      "(d) three-channel colour profile"}},
};
constexpr int kFirstPaperFigure = 7, kLastPaperFigure = 10;

}  // namespace

std::vector<PaperFigurePanel> paperFigurePanels(int figure) {
    const PaperFigure* f = nullptr;
    for (const auto& k : kFigures)
        if (k.number == figure) f = &k;
    if (!f)
        throw InputError::parameter("figure", "must be in [" + std::to_string(kFirstPaperFigure) + ", " +
                                                  std::to_string(kLastPaperFigure) + "], got " +
                                                  std::to_string(figure));
    std::vector<PaperFigurePanel> panels;
    panels.reserve(4);
    for (size_t i = 0; i < 4; ++i) {
        PatternSpec spec = loadPreset(f->presets[i]);
        if (f->sameNoises && i > 0) {
            // Panel a's spec with this preset's colormap: its program has panel
            // a's noises (the same seeds and tiles), so only H differs.
            const PaperFigurePanel& a = panels.front();
            ColormapSpec colormap = std::move(spec.colormap);
            spec = a.spec;
            spec.name = f->presets[i];
            spec.colormap = std::move(colormap);
        }
        panels.push_back({f->presets[i], f->captions[i], std::move(spec)});
    }
    return panels;
}

void validateFigures7to9(int size) {
    if (size < 64 || size > 2048)
        throw InputError("figures 7-9: size must be in [64, 2048], got " + std::to_string(size));
}

Figure paperFigureSheet(int figure, int size, const StudyProgress& progress) {
    const std::vector<PaperFigurePanel> panels = paperFigurePanels(figure);
    const PaperFigure* f = nullptr;
    for (const auto& k : kFigures)
        if (k.number == figure) f = &k;
    std::vector<std::vector<Image>> rows(2);
    std::vector<std::vector<std::string>> captions(2);
    for (size_t i = 0; i < panels.size(); ++i) {
        if (progress) progress(double(i) / double(panels.size()), panels[i].preset);
        const PaperFigurePanel& p = panels[i];
        rows[i / 2].push_back(patternSheet(p.spec, p.spec.scale, size, p.preset).sheet);
        captions[i / 2].push_back(p.caption);
    }
    return {f->file, sheet(rows, captions), f->title};
}

std::vector<Figure> figures7to9(int size, const StudyProgress& progress) {
    validateFigures7to9(size);
    std::vector<Figure> out;
    for (int figure = 7; figure <= 9; ++figure)
        out.push_back(
            paperFigureSheet(figure, size, progressPart(progress, figure - 7, 3, kFigures[size_t(figure - 7)].title)));
    return out;
}

Report table1Report(const Table1Result& r) {
    Report report;
    report.title = "Table 1: estimator errors";
    ReportSection s;
    s.html =
        "<p>Absolute (relative) mean errors of μ̂ and σ̂ against the exact footprint statistics of the tiled "
        "noise, over random square footprints. Noises: low frequency isotropic = low-pass, cut-off 8 cycles "
        "per period; high frequency anisotropic = bi-lobe, 32 cycles per period, bandwidth 3, 30°; 512² "
        "examples.</p>";
    s.tables.push_back({"table1.csv", r.data, false});
    std::string md = "# Table 1: estimator errors (absolute (relative) mean errors)\n";
    for (const Table& t : r.tables) {
        s.tables.push_back({"", t});
        md += "\n" + t.markdown();
    }
    s.files = {{"table1.md", md, ""}};
    s.figures = r.figures;
    report.sections.push_back(std::move(s));
    return report;
}

Report figure4Report(const Figure4Result& r, const std::string& figure) {
    return sectionReport(figure == "figure11" ? "Figure 11: filtering the phasor sine pattern"
                                              : "Figure 4: filtering approximations against the reference",
                         {{figure + ".csv", r.table}}, r.figures);
}

Report figures7to9Report(const std::vector<Figure>& sheets) {
    return sectionReport("Figures 7–9: colormap layout, palette, spectra", {}, sheets);
}

}  // namespace stochtex
