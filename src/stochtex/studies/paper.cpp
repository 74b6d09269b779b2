#include "stochtex/studies/paper.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stochtex/analysis/plot.h"
#include "stochtex/core/error.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/studies/pattern_sheet.h"

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
const char* kEstimators[3] = {"paper", "deliot-heitz", "global"};

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

Table1Result table1(const Table1Options& o, const StudyProgress& progress) {
    validateTable1(o);
    Table1Result res;
    res.data.columns = {{"noise", "noise", ""},          {"footprint", "footprint", "texels"},
                        {"estimator", "estimator", ""},  {"mu_abs", "mean |μ̂ − μ|", ""},
                        {"mu_rel", "mean |μ̂ − μ|/|μ|", ""}, {"sigma_abs", "mean |σ̂ − σ|", ""},
                        {"sigma_rel", "mean |σ̂ − σ|/σ", ""}, {"mean_mu", "mean μ", ""},
                        {"mean_sigma", "mean σ", ""},     {"values", "values", ""}};
    for (int which = 0; which < 2; ++which) {
        // Steps of one noise: building its examples, then each footprint size.
        const Progress noise =
            progressPart(progress, which, 2, std::string("table1: ") + kTableNoiseNames[which] + " noise");
        const int steps = 1 + int(o.errors.footprints.size());
        if (noise) noise(0.0, "building the 512² examples");
        const Pattern p = Pattern::build(table1PatternSpec(which, o.seed));
        res.rows[size_t(which)] = measureEstimatorErrors(p.tiledField(), o.errors, [&](int k) {
            if (noise) noise(double(1 + k) / steps, "footprint " + std::to_string(k) + "/" + std::to_string(steps - 1));
        });
        for (const auto& r : res.rows[size_t(which)])
            res.data.add({which == 0 ? "low" : "high", TableCell::integer(r.footprint), r.estimator,
                          TableCell::value(r.muAbs), TableCell::value(r.muRel), TableCell::value(r.sigmaAbs),
                          TableCell::value(r.sigmaRel), TableCell::value(r.meanMu), TableCell::value(r.meanSigma),
                          TableCell::integer(r.values)});
    }

    // Laid out like the paper's table: one block per estimator.
    for (const char* est : kEstimators) {
        Table t = paperLayout(std::string("Estimator: ") + est,
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
            const std::array<float, 3> colours[3] = {{0.1f, 0.3f, 0.8f}, {0.85f, 0.45f, 0.1f}, {0.5f, 0.5f, 0.5f}};
            int c = 0;
            for (const char* est : kEstimators) {
                PlotSeries s{std::string("ours, ") + est, {}, {}, colours[c++]};
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
            const std::string file = std::string("table1_") + (which == 0 ? "low" : "high") + "_" +
                                     (moment == 0 ? "mu" : "sigma") + ".png";
            res.figures.push_back({file, linePlot(series, lo),
                                   lo.title + " vs footprint size (log-log), ours and the published Table 1",
                                   LineChart{series, lo}});
        }
    return res;
}

void validateFigure4(const Figure4Options& o) {
    if (o.size < 16 || o.size > 4096) throw InputError("figure 4: size must be in [16, 4096], got " + std::to_string(o.size));
    if (o.referenceSamples < 1 || o.referenceSamples > 4096)
        throw InputError("figure 4: referenceSamples must be in [1, 4096], got " + std::to_string(o.referenceSamples));
    if (o.footprints.empty()) throw InputError("figure 4: no footprints");
    for (int s : o.footprints)
        if (s < 1) throw InputError("figure 4: footprints must be ≥ 1");
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

Figure4Result figure4(const Figure4Options& o, const StudyProgress& progress) {
    validateFigure4(o);
    const Pattern pattern = Pattern::build(o.pattern);
    struct Column {
        Figure4Column numbers;
        Image reference, exact, estimated, errExact, errEstimated;
    };
    std::vector<Column> cols;
    for (int s : o.footprints) {
        const Progress part = progressPart(progress, int(cols.size()), int(o.footprints.size()),
                                           "figure4: footprint " + std::to_string(s) + "²");
        Camera cam;
        cam.view.width = cam.view.height = o.size;
        cam.view.scale = s;
        Column c;
        c.numbers.footprint = s;
        FilterOptions fo;
        fo.referenceMaxSamples = o.referenceSamples;
        // The two brute-force renders take nearly all the time, about equally.
        c.reference = FilteredPattern(pattern, fo.use(parseFilter("reference")))
                          .render(cam, progressPart(part, 0.0, 0.5, "reference"));
        c.exact = FilteredPattern(pattern, fo.use(parseFilter("exact")))
                      .render(cam, progressPart(part, 0.5, 1.0, "exact statistics"));
        fo.source = StatisticsSource::Estimators;
        fo.response = o.response;
        c.estimated = FilteredPattern(pattern, fo).render(cam);
        c.errExact = errorMap(c.exact, c.reference, c.numbers.meanErrorExact);
        c.errEstimated = errorMap(c.estimated, c.reference, c.numbers.meanErrorEstimated);
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
    res.table.columns = {{"footprint", "footprint", ""},
                         {"mean_error_exact_stats", "mean ‖Ŝ(μ, Σ) − S̄‖₂ (exact statistics)", ""},
                         {"mean_error_estimators", "mean ‖Ŝ(μ̂, Σ̂) − S̄‖₂ (estimators)", ""}};
    const int thumb = std::min(o.size, 192);
    std::vector<std::vector<Image>> rows(5);
    std::vector<std::vector<std::string>> captions(5);
    std::vector<Figure> images;
    const char* rowNames[5] = {"reference", "exact stats", "error, exact", "estimators", "error, estim."};
    const char* rowFiles[5] = {"_reference.png", "_exact.png", "_error_exact.png", "_estimated.png",
                               "_error_estimated.png"};
    for (const auto& c : cols) {
        const int s = c.numbers.footprint;
        TableCell fp(std::to_string(s) + "²");
        fp.number = s;
        res.table.add({fp, TableCell::value(c.numbers.meanErrorExact), TableCell::value(c.numbers.meanErrorEstimated)});
        res.columns.push_back(c.numbers);
        const std::string tag = "fp" + std::to_string(s);
        const Image* shown[5] = {&c.reference, &c.exact, &c.errExact, &c.estimated, &c.errEstimated};
        for (int r = 0; r < 5; ++r) {
            const bool isError = r == 2 || r == 4;
            // Figures hold display codes (report/page.h): renders are encoded, error maps drawn so.
            Image img = isError ? colourise(*shown[r], 0.0, vmax, HeatPalette::Viridis) : srgbFromLinear(*shown[r]);
            rows[size_t(r)].push_back(resizeSmooth(img, thumb, thumb));
            captions[size_t(r)].push_back(std::string(rowNames[r]) + " " + std::to_string(s) + "²");
            images.push_back({tag + rowFiles[r], std::move(img), ""});
        }
    }
    rows.push_back({colourLegend(0.0, vmax, HeatPalette::Viridis,
                                 "error ‖Ŝ − S̄‖₂ (RGB), one scale for every error map")});
    captions.push_back({""});

    PlotSeries a{"exact statistics (eq. 5)", {}, {}, {0.1f, 0.6f, 0.2f}}, b{"estimators (eq. 5, 8, 12)", {}, {}, {0.1f, 0.3f, 0.8f}};
    for (const auto& c : res.columns) {
        a.x.push_back(c.footprint);
        a.y.push_back(c.meanErrorExact);
        b.x.push_back(c.footprint);
        b.y.push_back(c.meanErrorEstimated);
    }
    LinePlotOptions lo;
    lo.title = "Figure 4: mean error vs footprint (" + o.name + ")";
    lo.xLabel = "footprint side (texels)";
    lo.yLabel = "mean ‖Ŝ − S̄‖₂";
    lo.logX = true;
    res.figures.push_back({"figure4.png", sheet(rows, captions),
                           "Figure 4 (" + o.name + ", " + std::to_string(o.size) + "² per footprint): rows = reference S̄ (≤ " +
                               std::to_string(o.referenceSamples) +
                               "² samples per pixel), Ŝ with exact μ, Σ, its error, Ŝ with the "
                               "estimators, its error; columns = footprint 1 … 128²."});
    res.figures.push_back({"figure4_errors.png", linePlot({a, b}, lo),
                           "Mean error per footprint (log scale in the footprint).", LineChart{{a, b}, lo}});
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
const PaperFigure kFigures[3] = {
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
};

}  // namespace

std::vector<PaperFigurePanel> paperFigurePanels(int figure) {
    const PaperFigure* f = nullptr;
    for (const auto& k : kFigures)
        if (k.number == figure) f = &k;
    if (!f) throw InputError::parameter("figure", "must be 7, 8 or 9, got " + std::to_string(figure));
    std::vector<PaperFigurePanel> panels;
    panels.reserve(4);
    for (size_t i = 0; i < 4; ++i) {
        PatternSpec spec = loadPreset(f->presets[i]);
        if (f->sameNoises && i > 0) {
            // Panel a's spec with this preset's colormap, and panel a's noises
            // themselves (not rebuilt), so only H differs.
            const PaperFigurePanel& a = panels.front();
            ColormapSpec colormap = std::move(spec.colormap);
            spec = a.spec;
            spec.name = f->presets[i];
            spec.colormap = std::move(colormap);
            Pattern pattern = a.pattern.withColormap(buildColormap(spec.colormap));
            panels.push_back({f->presets[i], f->captions[i], std::move(spec), std::move(pattern)});
        } else {
            Pattern pattern = Pattern::build(spec);
            panels.push_back({f->presets[i], f->captions[i], std::move(spec), std::move(pattern)});
        }
    }
    return panels;
}

void validateFigures7to9(int size) {
    if (size < 64 || size > 2048) throw InputError("figures 7-9: size must be in [64, 2048], got " + std::to_string(size));
}

std::vector<Figure> figures7to9(int size, const StudyProgress& progress) {
    validateFigures7to9(size);
    std::vector<Figure> out;
    for (const auto& f : kFigures) {
        const Progress part = progressPart(progress, int(out.size()), int(std::size(kFigures)), f.title);
        std::vector<std::vector<Image>> rows(2);
        std::vector<std::vector<std::string>> captions(2);
        const std::vector<PaperFigurePanel> panels = paperFigurePanels(f.number);
        for (size_t i = 0; i < panels.size(); ++i) {
            if (part) part(double(i) / double(panels.size()), "");
            const PaperFigurePanel& p = panels[i];
            rows[i / 2].push_back(patternSheet(p.pattern, p.spec.scale, size, p.preset).sheet);
            captions[i / 2].push_back(p.caption);
        }
        out.push_back({f.file, sheet(rows, captions), f.title});
    }
    return out;
}

}  // namespace stochtex
