// stochtex reproduce: the paper's accuracy evidence, one command each —
// Table 1 (estimator errors), Figure 4 (filtered vs reference images and
// error maps), Figures 7–9 (colormap layouts, palettes, noise spectra) — and
// `all`, which runs them and writes an index.html.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "common.h"
#include "pattern_sheet.h"
#include "stochtex/analysis/estimator_error.h"
#include "stochtex/analysis/plot.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/presets.h"
#include "report.h"

namespace stochtex::cli {
namespace fs = std::filesystem;

namespace {

std::string path(const std::string& dir, const std::string& file) { return (fs::path(dir) / file).string(); }

// The two noises of Table 1 (the paper describes them only as "a low
// frequency isotropic noise and a high frequency anisotropic noise"):
// 512² examples, N_x and N_y of the same spectrum with different seeds.
const char* kTableNoises[2][2] = {
    {"low frequency isotropic", R"({"type": "spectrum", "size": 512, "components": [{"shape": "lowpass", "cutoff": 8}]})"},
    {"high frequency anisotropic",
     R"({"type": "spectrum", "size": 512, "components": [{"shape": "bilobe", "frequency": 32, "bandwidth": 3, "orientation": 30}]})"}};

Pattern tablePattern(int which, uint32_t seed) {
    const std::string text = std::string("{\"name\": \"table1\", \"seed\": ") + std::to_string(seed) +
                             ", \"noise_x\": " + kTableNoises[which][1] + ", \"noise_y\": " + kTableNoises[which][1] +
                             ", \"colormap\": {\"type\": \"gaussian\"}}";
    const std::string source = std::string("<table 1 noise: ") + kTableNoises[which][0] + ">";
    return Pattern::build(parsePatternSpec(JsonReader(JsonReader::parse(text, source), source), "."));
}

struct Table1Options {
    EstimatorErrorOptions errors;
    uint32_t seed = 1;
};

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

struct Table1Result {
    std::vector<EstimatorError> rows[2];  // low, high
    std::string markdown;
    std::vector<Figure> figures;
};

constexpr int kTableExampleSize = 512;  // the "size" of kTableNoises

Table1Result runTable1(const Table1Options& o, const std::string& dir) {
    validateEstimatorErrorOptions(o.errors, kTableExampleSize);
    ensureFolder(dir);
    Table1Result res;
    std::ostringstream csv;
    csv << "noise,footprint,estimator,mu_abs,mu_rel,sigma_abs,sigma_rel,mean_mu,mean_sigma,values\n";
    for (int which = 0; which < 2; ++which) {
        std::fprintf(stderr, "table1: %s noise (building the 512² examples)\n", kTableNoises[which][0]);
        const Pattern p = tablePattern(which, o.seed);
        res.rows[which] = measureEstimatorErrors(p.noises(), p.gridDensity(), o.errors, [&](int k) {
            std::fprintf(stderr, "\r  footprint %d/%zu", k, o.errors.footprints.size());
        });
        std::fprintf(stderr, "\n");
        for (const auto& r : res.rows[which])
            csv << (which == 0 ? "low" : "high") << ',' << r.footprint << ',' << r.estimator << ',' << r.muAbs << ','
                << r.muRel << ',' << r.sigmaAbs << ',' << r.sigmaRel << ',' << r.meanMu << ',' << r.meanSigma << ','
                << r.values << '\n';
    }
    writeFileAtomic(path(dir, "table1.csv"), csv.str());

    // Markdown laid out like the paper's table: one block per estimator.
    std::ostringstream md;
    auto cell = [](double a, double r) {
        char b[48];
        std::snprintf(b, sizeof b, "%.4f (%.4f)", a, r);
        return std::string(b);
    };
    for (const char* est : {"paper", "deliot-heitz", "global"}) {
        md << "\n**Estimator: " << est << "** (" << o.errors.count << " footprints per size × 2 components)\n\n"
           << "| footprint | low freq. μ̂ | low freq. σ̂ | high freq. μ̂ | high freq. σ̂ |\n|---|---|---|---|---|\n";
        for (size_t i = 0; i < res.rows[0].size(); ++i) {
            const auto& a = res.rows[0][i];
            if (a.estimator != est) continue;
            const auto& b = res.rows[1][i];
            md << "| " << a.footprint << "×" << a.footprint << " | " << cell(a.muAbs, a.muRel) << " | "
               << cell(a.sigmaAbs, a.sigmaRel) << " | " << cell(b.muAbs, b.muRel) << " | " << cell(b.sigmaAbs, b.sigmaRel)
               << " |\n";
        }
    }
    md << "\n**Published (Grenier et al. 2022, Table 1), paper's estimator**\n\n"
       << "| footprint | low freq. μ̂ | low freq. σ̂ | high freq. μ̂ | high freq. σ̂ |\n|---|---|---|---|---|\n";
    for (const auto& p : kPublished)
        md << "| " << p.footprint << "×" << p.footprint << " | " << cell(p.v[0], p.v[1]) << " | " << cell(p.v[2], p.v[3])
           << " | " << cell(p.v[4], p.v[5]) << " | " << cell(p.v[6], p.v[7]) << " |\n";
    res.markdown = md.str();
    writeFileAtomic(path(dir, "table1.md"), "# Table 1: estimator errors (absolute (relative) mean errors)\n" + md.str());

    // Error vs footprint, log scale, ours beside the published numbers.
    for (int which = 0; which < 2; ++which)
        for (int moment = 0; moment < 2; ++moment) {
            std::vector<PlotSeries> series;
            const std::array<float, 3> colours[3] = {{0.1f, 0.3f, 0.8f}, {0.85f, 0.45f, 0.1f}, {0.5f, 0.5f, 0.5f}};
            int c = 0;
            for (const char* est : {"paper", "deliot-heitz", "global"}) {
                PlotSeries s{std::string("ours, ") + est, {}, {}, colours[c++]};
                for (const auto& r : res.rows[which])
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
            lo.title = std::string(kTableNoises[which][0]) + ": mean |" + (moment == 0 ? "mu" : "sigma") + " error|";
            lo.xLabel = "footprint side (texels)";
            lo.yLabel = "mean absolute error";
            lo.logX = lo.logY = true;
            const std::string file = std::string("table1_") + (which == 0 ? "low" : "high") + "_" +
                                     (moment == 0 ? "mu" : "sigma") + ".png";
            writeImage(path(dir, file), linePlot(series, lo));
            res.figures.push_back({file, lo.title + " vs footprint size (log-log), ours and the published Table 1"});
        }
    return res;
}

struct Figure4Options {
    std::string preset = "camouflage";
    int size = 512;
    int referenceSamples = 64;
    std::vector<int> footprints{1, 2, 4, 8, 16, 32, 64, 128};
    FilterMode mode = FilterMode::Smooth;
};

struct Figure4Result {
    std::vector<Figure> figures;
    std::string markdown;
};

Figure4Result runFigure4(const Figure4Options& o, const std::string& dir) {
    const PatternSpec spec = loadPreset(o.preset);
    if (o.size < 16 || o.size > 4096) throw InputError("--size must be in [16, 4096]");
    ensureFolder(dir);
    const Pattern pattern = Pattern::build(spec);
    struct Column {
        int footprint;
        Image reference, exact, estimated, errExact, errEstimated;
        double meanExact = 0, meanEstimated = 0;
    };
    std::vector<Column> cols;
    auto errorMap = [](const Image& a, const Image& b, double& mean) {
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
    };
    for (int s : o.footprints) {
        std::fprintf(stderr, "figure4: footprint %d² — reference, exact statistics, estimators\n", s);
        Camera cam;
        cam.view.width = cam.view.height = o.size;
        cam.view.scale = s;
        Column c;
        c.footprint = s;
        FilterOptions fo;
        fo.referenceMaxSamples = o.referenceSamples;
        fo.mode = FilterMode::Reference;
        c.reference = FilteredPattern(pattern, fo).render(cam);
        fo.mode = FilterMode::Exact;
        c.exact = FilteredPattern(pattern, fo).render(cam);
        fo.mode = o.mode;
        c.estimated = FilteredPattern(pattern, fo).render(cam);
        c.errExact = errorMap(c.exact, c.reference, c.meanExact);
        c.errEstimated = errorMap(c.estimated, c.reference, c.meanEstimated);
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

    std::ostringstream csv, md;
    csv << "footprint,mean_error_exact_stats,mean_error_estimators\n";
    md << "| footprint | mean ‖Ŝ(μ, Σ) − S̄‖₂ (exact statistics) | mean ‖Ŝ(μ̂, Σ̂) − S̄‖₂ (estimators) |\n|---|---|---|\n";
    const int thumb = std::min(o.size, 192);
    std::vector<std::vector<Image>> rows(5);
    std::vector<std::vector<std::string>> captions(5);
    // Sheet captions are drawn with ASCII-only fonts.
    const char* rowNames[5] = {"reference", "exact stats", "error, exact", "estimators", "error, estim."};
    for (const auto& c : cols) {
        csv << c.footprint << ',' << c.meanExact << ',' << c.meanEstimated << '\n';
        char row[160];
        std::snprintf(row, sizeof row, "| %d² | %.4f | %.4f |\n", c.footprint, c.meanExact, c.meanEstimated);
        md << row;
        const std::string tag = "fp" + std::to_string(c.footprint);
        writeImage(path(dir, tag + "_reference.png"), c.reference);
        writeImage(path(dir, tag + "_exact.png"), c.exact);
        writeImage(path(dir, tag + "_estimated.png"), c.estimated);
        const Image* images[5] = {&c.reference, &c.exact, &c.errExact, &c.estimated, &c.errEstimated};
        for (int r = 0; r < 5; ++r) {
            const bool isError = r == 2 || r == 4;
            const Image shown = isError ? colourise(*images[r], 0.0, vmax, HeatPalette::Viridis) : *images[r];
            if (isError) writeImage(path(dir, tag + (r == 2 ? "_error_exact.png" : "_error_estimated.png")), shown);
            rows[size_t(r)].push_back(resizeSmooth(shown, thumb, thumb));
            captions[size_t(r)].push_back(std::string(rowNames[r]) + " " + std::to_string(c.footprint) + "x" +
                                          std::to_string(c.footprint));
        }
    }
    rows.push_back({colourLegend(0.0, vmax, HeatPalette::Viridis,
                                 "error ||S^ - S-||_2 (RGB), one scale for every error map")});
    captions.push_back({""});
    writeImage(path(dir, "figure4.png"), sheet(rows, captions));
    writeFileAtomic(path(dir, "figure4.csv"), csv.str());

    PlotSeries a{"exact statistics (eq. 5)", {}, {}, {0.1f, 0.6f, 0.2f}}, b{"estimators (eq. 5, 8, 12)", {}, {}, {0.1f, 0.3f, 0.8f}};
    for (const auto& c : cols) {
        a.x.push_back(c.footprint);
        a.y.push_back(c.meanExact);
        b.x.push_back(c.footprint);
        b.y.push_back(c.meanEstimated);
    }
    LinePlotOptions lo;
    lo.title = "Figure 4: mean error vs footprint (" + o.preset + ")";
    lo.xLabel = "footprint side (texels)";
    lo.yLabel = "mean ||S^ - S-||2";
    lo.logX = true;
    writeImage(path(dir, "figure4_errors.png"), linePlot({a, b}, lo));
    Figure4Result res;
    res.figures.push_back({"figure4.png", "Figure 4 (" + o.preset + ", " + std::to_string(o.size) +
                                              "² per footprint): rows = reference S̄ (≤ " +
                                              std::to_string(o.referenceSamples) +
                                              "² samples per pixel), Ŝ with exact μ, Σ, its error, Ŝ with the "
                                              "estimators, its error; columns = footprint 1 … 128²."});
    res.figures.push_back({"figure4_errors.png", "Mean error per footprint (log scale in the footprint)."});
    res.markdown = md.str();
    return res;
}

// Figures 7–9: each a sheet of four presets (pattern, colormap, where N
// falls, the two noises).
struct PaperFigure {
    const char* file;
    const char* title;
    std::array<const char*, 4> presets, captions;
};
const PaperFigure kFigures[3] = {
    {"figure7.png", "Figure 7: colormap layouts (same noises)",
     {"borders", "concentric", "bands", "oblique-blots"},
     {"(a) colours on the borders", "(b) concentric regions", "(c) 1D horizontal bands", "(d) oblique boundaries"}},
    {"figure8.png", "Figure 8: palettes (similar layouts)",
     {"weld", "camouflage", "marble", "bordered-blots"},
     {"(a) three weld colours", "(b) camouflage", "(c) marble strands", "(d) bordered blots"}},
    {"figure9.png", "Figure 9: noise spectra",
     {"weld", "low-high", "iso-aniso", "woven"},
     {"(a) two low-frequency isotropic", "(b) low + high frequency", "(c) isotropic + anisotropic",
      "(d) two orientations"}},
};

std::vector<Figure> runFigures79(int size, const std::string& dir) {
    ensureFolder(dir);
    std::vector<Figure> out;
    for (const auto& f : kFigures) {
        std::fprintf(stderr, "%s\n", f.title);
        std::vector<std::vector<Image>> rows(2);
        std::vector<std::vector<std::string>> captions(2);
        for (size_t i = 0; i < 4; ++i) {
            const PatternSpec spec = loadPreset(f.presets[i]);
            const PatternSheet ps = patternSheet(Pattern::build(spec), spec.scale, size, f.presets[i]);
            rows[i / 2].push_back(ps.sheet);
            captions[i / 2].push_back(f.captions[i]);
        }
        writeImage(path(dir, f.file), sheet(rows, captions));
        out.push_back({f.file, f.title});
    }
    return out;
}

}  // namespace

void registerReproduce(CLI::App& app) {
    struct Args {
        std::string dir;
        Table1Options table;
        Figure4Options figure4;
        std::string figure4Mode = "smooth";
        int sheetSize = 384;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("reproduce", "Regenerate the paper's evidence: table1, figure4, figures7-9, all");
    cmd->require_subcommand(1);
    auto addCommon = [&](CLI::App* sub) {
        sub->add_option("-o,--output", args->dir, "Output folder")->required();
        addThreadsFlag(*sub, args->threads);
    };
    auto addTable = [&](CLI::App* sub) {
        sub->add_option("--count", args->table.errors.count, "Random footprints per size");
        sub->add_option("--footprints", args->table.errors.footprints, "Footprint sides in texels")->delimiter(',');
        sub->add_option("--seed", args->table.seed, "Seed of the noises (footprint centres use --footprint-seed)");
        sub->add_option("--footprint-seed", args->table.errors.seed, "Seed of the footprint centres");
    };
    auto addFigure4 = [&](CLI::App* sub) {
        sub->add_option("--preset", args->figure4.preset, "Pattern of Figure 4");
        sub->add_option("--size", args->figure4.size, "Image size per footprint");
        sub->add_option("--reference-samples", args->figure4.referenceSamples, "Max reference samples per axis");
        sub->add_option("--filter", args->figure4Mode, "Table used with the estimators: smooth or paper");
    };
    auto* table1 = cmd->add_subcommand("table1", "Table 1: mean errors of μ̂ and σ̂ against exact footprint statistics");
    addCommon(table1);
    addTable(table1);
    auto* figure4 = cmd->add_subcommand("figure4", "Figure 4: reference, exact-statistics and estimated filtering");
    addCommon(figure4);
    addFigure4(figure4);
    auto* figures79 = cmd->add_subcommand("figures7-9", "Figures 7–9: colormap layouts, palettes, noise spectra");
    addCommon(figures79);
    figures79->add_option("--size", args->sheetSize, "Pattern size in each sheet");
    auto* all = cmd->add_subcommand("all", "Everything above, with an index.html");
    addCommon(all);
    addTable(all);
    addFigure4(all);

    auto prepare = [args] {
        args->figure4.mode = parseFilterMode(args->figure4Mode);
        if (args->figure4.mode != FilterMode::Smooth && args->figure4.mode != FilterMode::Paper)
            throw InputError("--filter: figure 4 compares the estimators through a table: smooth or paper");
        if (args->figure4.referenceSamples < 1 || args->figure4.referenceSamples > 4096)
            throw InputError("--reference-samples must be in [1, 4096]");
        if (args->sheetSize < 64 || args->sheetSize > 2048) throw InputError("--size must be in [64, 2048]");
        (void)loadPreset(args->figure4.preset);  // unknown preset: fail before any work
        validateEstimatorErrorOptions(args->table.errors, kTableExampleSize);
        if (args->figure4.size < 16 || args->figure4.size > 4096) throw InputError("--size must be in [16, 4096]");
        for (int s : args->figure4.footprints)
            if (s < 1) throw InputError("figure 4: footprints must be ≥ 1");
    };
    table1->callback([args, prepare] {
        prepare();
        ThreadLimit limit(args->threads);
        const Table1Result r = runTable1(args->table, args->dir);
        std::printf("%s\nwrote table1.csv, table1.md and plots to %s\n", r.markdown.c_str(), args->dir.c_str());
    });
    figure4->callback([args, prepare] {
        prepare();
        ThreadLimit limit(args->threads);
        const Figure4Result r = runFigure4(args->figure4, args->dir);
        std::printf("%s\nwrote figure4.png, figure4.csv and the images to %s\n", r.markdown.c_str(), args->dir.c_str());
    });
    figures79->callback([args, prepare] {
        prepare();
        ThreadLimit limit(args->threads);
        runFigures79(args->sheetSize, args->dir);
        std::printf("wrote figure7.png, figure8.png, figure9.png to %s\n", args->dir.c_str());
    });
    all->callback([args, prepare] {
        prepare();
        ThreadLimit limit(args->threads);
        const auto start = std::chrono::steady_clock::now();
        auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
        const Table1Result t = runTable1(args->table, path(args->dir, "table1"));
        const double tTable = elapsed();
        const Figure4Result f4 = runFigure4(args->figure4, path(args->dir, "figure4"));
        const double tFigure4 = elapsed();
        const std::vector<Figure> f79 = runFigures79(args->sheetSize, path(args->dir, "figures7-9"));
        const double total = elapsed();
        std::ostringstream html;
        html << "<!doctype html><html><head><meta charset='utf-8'><title>stochtex: paper reproduction</title>"
                "<style>body{font-family:sans-serif;max-width:1300px;margin:2em auto;color:#222}"
                "figure{display:inline-block;margin:0 1em 1.5em 0;vertical-align:top;max-width:100%}"
                "img{max-width:100%}figcaption{max-width:640px;font-size:90%}table{border-collapse:collapse;margin:.5em 0 1.5em}"
                "td,th{border:1px solid #bbb;padding:.25em .6em;text-align:right}</style></head><body>"
                "<h1>Colour-mapped noise vector fields: reproduction of the paper's evidence</h1>"
                "<p>Generated by <code>stochtex reproduce all</code> in "
             << int(total) << " s (Table 1: " << int(tTable) << " s, Figure 4: " << int(tFigure4 - tTable)
             << " s, Figures 7–9: " << int(total - tFigure4) << " s).</p>"
             << "<h2>Table 1: estimator errors</h2><p>Absolute (relative) mean errors of μ̂ and σ̂ against the exact "
                "footprint statistics of the tiled noise, over random square footprints. Noises: low frequency "
                "isotropic = low-pass, cut-off 8 cycles per period; high frequency anisotropic = bi-lobe, 32 cycles "
                "per period, bandwidth 3, 30°; 512² examples. <a href='table1/table1.csv'>table1.csv</a></p>"
             << markdownToHtml(t.markdown) << htmlFigures("table1/", t.figures)
             << "<h2>Figure 4: filtering approximations against the reference</h2>" << markdownToHtml(f4.markdown)
             << htmlFigures("figure4/", f4.figures) << "<h2>Figures 7–9: colormap layout, palette, spectra</h2>"
             << htmlFigures("figures7-9/", f79) << "</body></html>\n";
        writeFileAtomic(path(args->dir, "index.html"), html.str());
        std::printf("wrote %s (%.0f s)\n", path(args->dir, "index.html").c_str(), total);
    });
}

}  // namespace stochtex::cli
