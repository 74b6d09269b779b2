#include "stochtex/studies/zoom_studies.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stochtex/analysis/contrast.h"
#include "stochtex/analysis/correlation_accumulator.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/instance_statistics.h"

namespace stochtex {

namespace {

// A size × size map of f(x, y), rows in parallel.
template <class F>
Image map(int size, F&& f) {
    Image out(size, size, 1, Image::Uninitialized{});
    parallelRows(size, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < size; ++x) out.at(x, y) = float(f(x, y));
    });
    return out;
}

}  // namespace

CorrelationMeasurement measureCorrelation(const TextureSource& source, const CorrelationMeasureOptions& o) {
    if (o.size < 4 || o.size > 1024)
        throw InputError("correlation: size must be in [4, 1024], got " + std::to_string(o.size));
    if (o.instances < 2) throw InputError("correlation: needs at least 2 instances");
    CorrelationMeasurement m;
    if (const auto stats = source.statistics(o.time)) {
        const double x0 = o.x0, y0 = o.y0;
        m.analyticRadial = map(o.size, [&](int x, int y) { return stats->correlation(x0 + x, y0, x0 + y, y0); });
        m.analyticNonRadial = map(o.size, [&](int x, int y) { return stats->correlation(x0 + x, y0, x0 + x, y0 + y); });
    }
    const int px = o.pointX < 0 ? o.size / 2 : o.pointX, py = o.pointY < 0 ? o.size / 2 : o.pointY;
    if (px >= o.size || py >= o.size)
        throw InputError("correlation: the reference point (" + std::to_string(px) + ", " + std::to_string(py) +
                         ") lies outside the " + std::to_string(o.size) + "-pixel window");
    InstanceStatisticsOptions s;
    s.region = {o.size, o.size, o.x0, o.y0};
    s.time = o.time;
    s.instances = o.instances;
    s.pointX = px;
    s.pointY = py;
    s.referenceRow = 0;
    s.probeRow = 0;
    const CorrelationAccumulator acc = instanceStatistics(source, s);
    m.measuredRadial = acc.probeCorrelation();
    m.measuredNonRadial = acc.correlationWithRow();
    m.measuredPoint = acc.correlationWithPoint();
    return m;
}

ZoomParams applyVariant(ZoomParams p, ZoomVariant v) {
    p.scaling = v == ZoomVariant::Sliding ? ZoomScaling::Sliding : ZoomScaling::Exponential;
    p.offsets = v == ZoomVariant::Simple   ? ZoomOffsets::Simple
                : v == ZoomVariant::Random ? ZoomOffsets::Hashed
                                           : ZoomOffsets::None;
    return p;
}

namespace {

// A correlation map as a heat map with axes in pixels from the zoom centre.
Image correlationPlot(const Image& c, const std::string& title, const std::string& xl, const std::string& yl,
                      double vmin = -1, double vmax = 1) {
    HeatmapOptions o;
    o.title = title;
    o.xLabel = xl;
    o.yLabel = yl;
    o.vmin = vmin;
    o.vmax = vmax;
    o.xMax = c.width();
    o.yMax = c.height();
    o.cell = std::max(1, 256 / std::max(c.width(), c.height()));
    return heatmapPlot(c, o);
}

// The raw colour-mapped values (no axes), y up like the plots, for grids.
Image colourised(const Image& c, int size) {
    Image flipped(c.width(), c.height(), 1, Image::Uninitialized{});
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x) flipped.at(x, c.height() - 1 - y) = c.at(x, y);
    return resizeNearest(colourise(flipped, -1.0, 1.0, HeatPalette::Diverging), size, size);
}

double meanAbs(const Image& a, const Image& b, double* maxOut = nullptr) {
    double s = 0, m = 0;
    for (size_t i = 0; i < a.data().size(); ++i) {
        const double d = std::abs(double(a.data()[i]) - b.data()[i]);
        s += d;
        m = std::max(m, d);
    }
    if (maxOut) *maxOut = m;
    return s / double(a.data().size());
}

Image difference(const Image& a, const Image& b) {
    Image d(a.width(), a.height(), 1, Image::Uninitialized{});
    for (size_t i = 0; i < a.data().size(); ++i) d.data()[i] = a.data()[i] - b.data()[i];
    return d;
}

}  // namespace

std::span<const OptionMember<CorrelationStudyOptions>> correlationStudyMembers() {
    using O = CorrelationStudyOptions;
    static const OptionMember<O> members[] = {
        {"instances", "Instances N of the statistical accumulator", 2, 1000000, &O::instances},
        {"plotSize", "Extent of the correlation plots in pixels from the zoom centre", 4, 1024, &O::size},
    };
    return members;
}

void validateCorrelationStudy(const CorrelationStudyOptions& o) {
    ZoomSource(o.zoom, o.base);
    checkMembers(o, correlationStudyMembers());
    if (o.layers.empty() || o.variants.empty()) throw InputError("correlation: no variants or layer counts");
    for (int n : o.layers)
        if (n < 1 || n > 1024)
            throw InputError::parameter("layersList", "must hold layer counts in [1, 1024], got " + std::to_string(n));
}

CorrelationStudyResult correlationStudy(const CorrelationStudyOptions& o, const StudyProgress& progress) {
    validateCorrelationStudy(o);
    CorrelationStudyResult out;
    out.table.columns = {{"variant", "variant", ""},
                         {"layers", "n", ""},
                         {"instances", "N", ""},
                         {"mean_abs_diff_radial", "mean abs(analytic − measured), radial", ""},
                         {"max_abs_diff_radial", "max", ""},
                         {"mean_abs_diff_nonradial", "mean, non-radial", ""},
                         {"max_offdiagonal_analytic", "max off-diagonal correlation (analytic)", ""}};
    const int size = o.size, cell = 128;
    std::vector<std::vector<Image>> grid;
    std::vector<std::vector<std::string>> captions;
    std::vector<Figure> plots;
    const size_t total = o.variants.size() * o.layers.size();
    size_t done = 0;
    for (ZoomVariant variant : o.variants) {
        grid.emplace_back();
        captions.emplace_back();
        const std::string vname = enumName(kZoomVariantNames, variant);
        for (int n : o.layers) {
            ZoomParams p = applyVariant(o.zoom, variant);
            p.layers = n;
            const ZoomSource source(p, o.base);
            const std::string name = vname + "_n" + std::to_string(n);
            if (progress)
                progress(double(done) / double(total), "correlation " + name + " (" + std::to_string(done + 1) + "/" +
                                                           std::to_string(total) + "): analytic plots, then " +
                                                           std::to_string(o.instances) + " instances");
            ++done;
            const CorrelationMeasurement m = measureCorrelation(source, {size, o.instances, p.time});
            double maxDiff = 0, offDiagonal = 0;
            const double diff = meanAbs(m.analyticRadial, m.measuredRadial, &maxDiff);
            const double diffNonRadial = meanAbs(m.analyticNonRadial, m.measuredNonRadial);
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x)
                    if (std::abs(x - y) > 4)
                        offDiagonal = std::max(offDiagonal, double(std::abs(m.analyticRadial.at(x, y))));
            out.table.add({vname, TableCell::integer(n), TableCell::integer(o.instances), TableCell::value(diff),
                           TableCell::value(maxDiff, "%.3f"), TableCell::value(diffNonRadial),
                           TableCell::value(offDiagonal, "%.3f")});

            const std::string xs = "x (pixels from centre)", ys = "y", yc = "y (pixels from centre)";
            const Image instance = source.render(SourceRegion::centred(2 * size, 2 * size), p.time, 0);
            plots.push_back({name + "_analytic.png",
                             correlationPlot(m.analyticRadial, "Corr[I(x,0), I(y,0)] analytic, " + name, xs, ys),
                             "Analytic radial correlation, " + name});
            plots.push_back({name + "_measured.png",
                             correlationPlot(m.measuredRadial,
                                             "measured over " + std::to_string(o.instances) + " instances", xs, ys),
                             "Measured radial correlation, " + name});
            plots.push_back({name + "_difference.png",
                             correlationPlot(difference(m.analyticRadial, m.measuredRadial), "analytic - measured", xs,
                                             ys, -0.2, 0.2),
                             "Analytic − measured, " + name});
            plots.push_back({name + "_nonradial.png",
                             correlationPlot(m.analyticNonRadial, "Corr[I(x,0), I(x,y)] analytic", xs, yc),
                             "Analytic non-radial correlation, " + name});
            plots.push_back({name + "_nonradial_measured.png",
                             correlationPlot(m.measuredNonRadial, "Corr[I(x,0), I(x,y)] measured", xs, yc), ""});
            plots.push_back({name + "_point.png",
                             correlationPlot(m.measuredPoint,
                                             "Corr with the point (" + std::to_string(size / 2) + "," +
                                                 std::to_string(size / 2) + "), measured",
                                             "x", "y"),
                             "Measured correlation with one point, " + name});
            plots.push_back({name + "_instance.png", instance, ""});
            Image cellImage(3 * cell, cell, 3);
            paste(cellImage, toRgb(resizeSmooth(instance, cell, cell)), 0, 0);
            paste(cellImage, colourised(m.analyticRadial, cell), cell, 0);
            paste(cellImage, colourised(m.measuredRadial, cell), 2 * cell, 0);
            grid.back().push_back(cellImage);
            captions.back().push_back(vname + ", n = " + std::to_string(n));
        }
    }
    std::string names;
    for (ZoomVariant v : o.variants) names += (names.empty() ? "" : ", ") + enumName(kZoomVariantNames, v);
    out.figures.push_back({"figure2_10.png", sheet(grid, captions),
                           "Figure 2.10 layout: rows = variants (" + names +
                               "), columns = layer counts. Each cell: one instance, the analytic Corr[I(x,0), I(y,0)] "
                               "and the measured one (blue −1, white 0, red +1; origin bottom-left)."});
    for (auto& f : plots) out.figures.push_back(std::move(f));
    return out;
}

std::span<const OptionMember<ContrastStudyOptions>> contrastStudyMembers() {
    using O = ContrastStudyOptions;
    static const OptionMember<O> members[] = {
        {"size", "Side of the contrast-correction textures in pixels, centred on the zoom centre", 8, 8192, &O::size},
    };
    return members;
}

void validateContrastStudy(const ContrastStudyOptions& o) { checkMembers(o, contrastStudyMembers()); }

ContrastTargets zoomContrastTargets(const ZoomSource& source, int size) {
    const LatticeTexture& base = source.firstLattice();
    ContrastTargets t{base.mean(), base.variance(), Image(size, size, 1, Image::Uninitialized{})};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) t.reference.at(x, y) = base.at(x, y);
    return t;
}

namespace {

// A 360×240 plot over x ∈ [0, 1] (intensities), the size of every panel of
// the contrast sheets.
LinePlotOptions unitAxes(const std::string& title, const std::string& xLabel, const std::string& yLabel) {
    LinePlotOptions o;
    o.title = title;
    o.xLabel = xLabel;
    o.yLabel = yLabel;
    o.width = 360;
    o.height = 240;
    o.xMin = 0;
    o.xMax = 1;
    return o;
}

Image histogramPlot(const Image& img, const std::string& title) {
    const std::vector<double> h = histogram(img, 64);
    PlotSeries s;
    s.bars = true;
    for (size_t i = 0; i < h.size(); ++i) {
        s.x.push_back((double(i) + 0.5) / 64.0);
        s.y.push_back(h[i]);
    }
    return linePlot({s}, unitAxes(title, "intensity", "fraction of pixels"));
}

// Axes of every correction-curve plot: I ∈ [0, 1] → h(I), room for clamping.
LinePlotOptions curveAxes(const std::string& title) {
    LinePlotOptions o = unitAxes(title, "I", "h(I)");
    o.yMin = -0.5;
    o.yMax = 1.5;
    return o;
}

}  // namespace

ContrastStudyResult contrastStudy(const TextureSource& source, const ContrastTargets& targets,
                                  const ContrastStudyOptions& o) {
    validateContrastStudy(o);
    if (source.channels() != 1) throw InputError("contrast study: the source must have 1 channel");
    const auto stats = source.statistics(o.time);
    if (!stats) throw InputError("contrast study: the source has no analytic variance to correct with");
    const SourceRegion region = SourceRegion::centred(o.size, o.size);
    const Image texture = source.render(region, o.time, 0);
    Image varR(o.size, o.size, 1, Image::Uninitialized{});
    parallelRows(o.size, [&](int y0, int y1) {
        for (int py = y0; py < y1; ++py)
            for (int px = 0; px < o.size; ++px)
                varR.at(px, py) = float(stats->variance(region.x0 + px, region.y0 + py));
    });
    const double mu = targets.mean, vf = targets.variance;
    std::vector<float> sorted(varR.data().begin(), varR.data().end());
    std::nth_element(sorted.begin(), sorted.begin() + ptrdiff_t(sorted.size() / 2), sorted.end());
    const double medianVar = sorted[sorted.size() / 2];

    ContrastStudyResult out;
    out.table.columns = {{"method", "image", ""},
                         {"clamped_percent", "clamped pixels", "%"},
                         {"non_monotone_percent", "h' < 0 somewhere (polynomial)", "%"},
                         {"mean", "mean", ""},
                         {"stddev", "std", ""}};
    // Clamping applies to the corrections, the validity condition to the polynomial: elsewhere "—".
    auto addRow = [&](const std::string& name, const Image& img, TableCell clamped, TableCell invalid) {
        const ChannelStats s = channelStats(img);
        out.table.add(
            {name, std::move(clamped), std::move(invalid), TableCell::value(s.mean), TableCell::value(s.stddev)});
    };
    std::vector<Image> textures{texture}, histograms, curves;
    std::vector<std::string> names{"uncorrected"};
    if (!targets.reference.empty())
        addRow("white noise (base)", targets.reference, TableCell::none(), TableCell::none());
    addRow("uncorrected", texture, TableCell::none(), TableCell::none());
    histograms.push_back(histogramPlot(texture, "uncorrected"));
    curves.push_back(
        linePlot({PlotSeries{"identity", {0, 1}, {0, 1}, {0.3f, 0.3f, 0.3f}}}, curveAxes("no correction")));
    std::vector<Figure> corrected;
    for (ContrastMethod m : {ContrastMethod::Linear, ContrastMethod::Polynomial, ContrastMethod::Sigmoid}) {
        const std::string name = contrastMethodName(m);
        const ContrastResult r = correctContrast(m, texture, varR, mu, vf);
        corrected.push_back({"corrected_" + name + ".png", r.image, ""});
        if (m == ContrastMethod::Polynomial)
            corrected.push_back({"polynomial_non_monotone.png", r.invalid,
                                 "Pixels where the polynomial's h' < 0 somewhere on [0, 1] (white): eq. 2.17's "
                                 "validity condition fails."});
        addRow(name, r.image, TableCell::percent(r.clampedPercent),
               m == ContrastMethod::Polynomial ? TableCell::percent(r.invalidPercent) : TableCell::none());
        textures.push_back(r.image);
        char clamped[32];
        std::snprintf(clamped, sizeof clamped, "%.1f%% clamped", r.clampedPercent);
        names.push_back(name + " (" + clamped + ")");
        histograms.push_back(histogramPlot(r.image, name));
        // The correction curve at the median pixel variance, with its
        // clamping intervals shaded.
        PlotSeries s{name, {}, {}, {0.8f, 0.2f, 0.1f}};
        LinePlotOptions po = curveAxes(name + " at the median pixel variance");
        for (int i = 0; i <= 200; ++i) {
            const double x = i / 200.0;
            s.x.push_back(x);
            s.y.push_back(correctContrast(m, x, mu, vf, medianVar));
        }
        double start = -1;
        for (size_t i = 0; i < s.x.size(); ++i) {
            const bool outside = s.y[i] < 0 || s.y[i] > 1;
            if (outside && start < 0) start = s.x[i];
            if ((!outside || i + 1 == s.x.size()) && start >= 0) {
                po.bands.push_back({start, s.x[i]});
                start = -1;
            }
        }
        curves.push_back(linePlot({s}, po));
    }
    const int thumb = 240;
    std::vector<Image> row1;
    for (const Image& t : textures) {
        Image small = toRgb(resizeNearest(t, thumb, thumb));
        // Inset: the reference (the raw white noise), as in Figure 2.6.
        if (!targets.reference.empty())
            paste(small, toRgb(resizeNearest(targets.reference, thumb / 4, thumb / 4)), 0, 0);
        row1.push_back(small);
    }
    out.figures.push_back({"figure2_6.png", sheet({row1, histograms, curves}, {names, {}, {}}),
                           "Figure 2.6 layout: the texture and its linear, polynomial and sigmoid corrections (inset: "
                           "the reference, e.g. the raw white noise), their histograms, and each correction curve h at "
                           "the median pixel variance (red bands: inputs that get clamped)."});
    for (auto& f : corrected) out.figures.push_back(std::move(f));
    out.figures.push_back({"texture.png", texture, ""});
    if (!targets.reference.empty()) out.figures.push_back({"white_noise.png", targets.reference, ""});
    return out;
}

std::vector<Figure> slidingStudy(const ZoomParams& params, const ZoomBase& base) {
    std::vector<Figure> out;
    std::vector<Image> row;
    std::vector<std::string> names;
    const std::pair<const char*, ZoomScaling> scalings[2] = {{"sliding", ZoomScaling::Sliding},
                                                             {"exponential", ZoomScaling::Exponential}};
    for (const auto& [name, scaling] : scalings) {
        ZoomParams p = params;
        p.scaling = scaling;
        const ZoomSource source(p, base);
        for (double t : {0.0, 0.5}) {
            row.push_back(source.render(SourceRegion::centred(256, 256), t, 0));
            char c[64];
            std::snprintf(c, sizeof c, "%s, t = %.1f", name, t);
            names.push_back(c);
        }
    }
    out.push_back(
        {"frames.png", sheet({row}, {names}),
         "The zoom texture (n = " + std::to_string(params.layers) +
             ") with sliding scales (eq. 2.2) and with the exponential fix (eq. 2.5), half a time unit apart."});
    std::vector<PlotSeries> series;
    for (const auto& [name, scaling] : scalings) {
        PlotSeries s{std::string(name) + ": layer 0 scale a₀(t)",
                     {},
                     {},
                     scaling == ZoomScaling::Sliding ? std::array<float, 3>{0.8f, 0.2f, 0.1f}
                                                     : std::array<float, 3>{0.1f, 0.3f, 0.8f}};
        ZoomParams p = params;
        p.scaling = scaling;
        for (int i = 0; i <= 400; ++i) {
            p.time = 4.0 * i / 400.0;
            s.x.push_back(p.time);
            s.y.push_back(zoomLayers(p, 2, 2)[0].scale);
        }
        series.push_back(s);
    }
    LinePlotOptions o;
    o.title = "Scale of one layer over time";
    o.xLabel = "t";
    o.yLabel = "a₀";
    out.push_back(
        chartFigure("scales.png", {series, o},
                    "a₀(t): linear ramps (sliding: screen speed 1/a differs per layer) vs exponential decay (every "
                    "layer moves at the same relative speed −a'/a = 1)."));
    return out;
}

ContrastStudyResult zoomContrastStudy(const ZoomParams& params, const ZoomBase& base,
                                      const ContrastStudyOptions& options) {
    validateContrastStudy(options);
    const ZoomSource source(params, base);
    ContrastStudyOptions o = options;
    o.time = params.time;  // the zoom's own t (--time), not a second time beside it
    return contrastStudy(source, zoomContrastTargets(source, o.size), o);
}

Report contrastReport(const ContrastStudyResult& r, int layers) {
    return sectionReport("Contrast loss and its corrections (section 2.4)", {{"contrast.csv", r.table}}, r.figures,
                         "<p>Var I(x) = &sigma;<sub>f</sub>&sup2; &alpha;(x, x) &lt; &sigma;<sub>f</sub>&sup2;: the "
                         "blend loses contrast. Each correction uses the per-pixel analytic variance (n = " +
                             std::to_string(layers) + ").</p>");
}

Report correlationReport(const CorrelationStudyResult& r, const CorrelationStudyOptions& o) {
    Report report;
    report.title = "Correlation (section 2.5)";
    ReportSection all;
    all.html =
        "<p>Mean |analytic &minus; measured| over the plots, and the largest analytic correlation away from the "
        "diagonal band |x &minus; y| &le; 4 (the interpolation kernel's own correlation). Hashed (random) "
        "offsets remove the echoes.</p>";
    all.tables = {{"correlation.csv", r.table}};
    all.figures = r.figures;
    all.figuresShown = 1;  // Figure 2.10; every plot is in the folder
    report.sections.push_back(std::move(all));
    // The plots of each variant at the first layer count.
    const std::string firstLayers = std::to_string(o.layers.front());
    ReportSection first;
    first.heading = "Each variant at n = " + firstLayers;
    for (const Figure& f : r.figures)
        if (f.file.find("_n" + firstLayers + "_") != std::string::npos) first.figures.push_back(f);
    first.htmlAfter = "<p>All plots for every n are in the folder, with correlation.csv.</p>";
    report.sections.push_back(std::move(first));
    return report;
}

Report slidingReport(const std::vector<Figure>& figures) { return sectionReport("Sliding (section 2.2)", {}, figures); }

}  // namespace stochtex
