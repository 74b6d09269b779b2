#include "zoom_studies.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "stochtex/analysis/contrast.h"
#include "stochtex/analysis/correlation_accumulator.h"
#include "stochtex/analysis/plot.h"
#include "stochtex/analysis/zoom_statistics.h"
#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/image/image_io.h"

namespace stochtex::cli {
namespace fs = std::filesystem;

void addZoomFlags(CLI::App& cmd, ZoomFlags& f, bool withLayers) {
    if (withLayers) cmd.add_option("--layers", f.layers, "Number of layers n (eq. 2.1)");
    cmd.add_option("--max-scale", f.maxScale, "Maximum scale H");
    cmd.add_option("--time", f.time, "Time t (first frame)");
    cmd.add_option("--envelope-sigma", f.envelopeSigma, "Width of the Gaussian envelope A around a = 1");
    cmd.add_option("--scaling", f.scaling, "sliding (eq. 2.2) or exponential (eq. 2.5, no sliding)");
    cmd.add_option("--offsets", f.offsets, "Layer offsets: none, simple, hashed (pcg3d) or sin-hash (eq. 2.23)");
    cmd.add_option("--interpolation", f.interpolation, "Base lattice reconstruction: nearest or linear");
    cmd.add_option("--base", f.base, "Base texture: 'white' (white noise) or a grayscale image file");
    cmd.add_option("--base-size", f.baseSize, "Period of the white-noise lattice")->check(CLI::Range(2, 16384));
    cmd.add_option("--seed", f.seed, "Seed of the white noise (instance k uses a seed derived from it)");
}

ZoomParams makeZoomParams(const ZoomFlags& f) {
    ZoomParams p;
    p.layers = f.layers;
    p.maxScale = f.maxScale;
    p.time = f.time;
    p.envelopeSigma = f.envelopeSigma;
    p.scaling = parseZoomScaling(f.scaling);
    p.offsets = parseZoomOffsets(f.offsets);
    p.interpolation = parseLatticeInterpolation(f.interpolation);
    p.offsetSeed = f.seed;
    validateZoomParams(p);
    return p;
}

LatticeTexture makeBase(const ZoomFlags& f, int instance) {
    if (f.base == "white") return LatticeTexture::whiteNoise(f.baseSize, f.baseSize, deriveSeed(f.seed, uint32_t(instance)));
    return LatticeTexture::fromImage(toGray(readImage(f.base)));
}

namespace {

std::string path(const std::string& dir, const std::string& file) { return (fs::path(dir) / file).string(); }

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

struct Variant {
    ZoomScaling scaling;
    ZoomOffsets offsets;
};
Variant parseVariant(const std::string& v) {
    if (v == "sliding") return {ZoomScaling::Sliding, ZoomOffsets::None};
    if (v == "fixed") return {ZoomScaling::Exponential, ZoomOffsets::None};
    if (v == "simple") return {ZoomScaling::Exponential, ZoomOffsets::Simple};
    if (v == "random") return {ZoomScaling::Exponential, ZoomOffsets::Hashed};
    throw InputError("--variant: unknown \"" + v + "\" (expected sliding, fixed, simple or random)");
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

void validateStudy(const ZoomFlags& flags, const CorrelationStudy& study) {
    makeZoomParams(flags);
    if (flags.base != "white") makeBase(flags);
    if (study.instances < 2 || study.instances > 1000000) throw InputError("--instances must be in [2, 1e6]");
    if (study.size < 4 || study.size > 1024) throw InputError("--size must be in [4, 1024] for correlation plots");
    if (study.layers.empty() || study.variants.empty()) throw InputError("correlation: no variants or layer counts");
    for (const auto& v : study.variants) parseVariant(v);
    for (int n : study.layers)
        if (n < 1 || n > 1024) throw InputError("--layers-list: every n must be in [1, 1024] (got " + std::to_string(n) + ")");
}

void validateStudy(const ZoomFlags& flags, const ContrastStudy& study) {
    ZoomFlags f = flags;
    f.layers = study.layers;
    makeZoomParams(f);
    if (flags.base != "white") makeBase(flags);
    if (study.size < 8 || study.size > 8192) throw InputError("--size must be in [8, 8192]");
}

StudyOutput runCorrelationStudy(const ZoomFlags& flags, const CorrelationStudy& study, const std::string& dir) {
    validateStudy(flags, study);
    std::vector<Variant> variants;
    for (const auto& v : study.variants) variants.push_back(parseVariant(v));
    ensureFolder(dir);

    StudyOutput out;
    std::ostringstream csv, table;
    csv << "variant,layers,instances,mean_abs_diff_radial,max_abs_diff_radial,mean_abs_diff_nonradial,"
           "max_offdiagonal_analytic\n";
    table << "| variant | n | mean abs(analytic − measured), radial | max | mean, non-radial | max off-diagonal "
             "correlation (analytic) |\n|---|---|---|---|---|---|\n";
    const int size = study.size, cell = 128;
    std::vector<std::vector<Image>> grid;
    std::vector<std::vector<std::string>> captions;
    const size_t total = variants.size() * study.layers.size();
    size_t done = 0;
    for (size_t vi = 0; vi < variants.size(); ++vi) {
        grid.emplace_back();
        captions.emplace_back();
        for (int n : study.layers) {
            ZoomFlags f = flags;
            f.layers = n;
            ZoomParams p = makeZoomParams(f);
            p.scaling = variants[vi].scaling;
            p.offsets = variants[vi].offsets;
            const std::string name = study.variants[vi] + "_n" + std::to_string(n);
            std::fprintf(stderr, "[%zu/%zu] %s: analytic plots, then %d instances\n", ++done, total, name.c_str(),
                         study.instances);
            const LatticeTexture first = makeBase(f, 0);
            const ZoomStatistics stats(p, first.width(), first.height());
            const Image radial = stats.radialCorrelation(size), nonRadial = stats.nonRadialCorrelation(size);
            // Frames cover x, y ∈ [0, size) from the centre; row 0 is the
            // horizontal axis through it; the reference point of the
            // point map sits in the middle of the frame.
            CorrelationAccumulator acc(size, size, size / 2, size / 2, 0, 0);
            const ZoomRegion region{size, size, 0.0, 0.0};
            for (int k = 0; k < study.instances; ++k) acc.add(renderZoom(makeBase(f, k), p, region));
            const Image measured = acc.probeCorrelation(), measuredNonRadial = acc.correlationWithRow();
            double maxDiff = 0, offDiagonal = 0;
            const double diff = meanAbs(radial, measured, &maxDiff);
            const double diffNonRadial = meanAbs(nonRadial, measuredNonRadial);
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x)
                    if (std::abs(x - y) > 4) offDiagonal = std::max(offDiagonal, double(std::abs(radial.at(x, y))));
            csv << study.variants[vi] << ',' << n << ',' << study.instances << ',' << diff << ',' << maxDiff << ','
                << diffNonRadial << ',' << offDiagonal << '\n';
            char row[256];
            std::snprintf(row, sizeof row, "| %s | %d | %.4f | %.3f | %.4f | %.3f |\n", study.variants[vi].c_str(), n, diff,
                          maxDiff, diffNonRadial, offDiagonal);
            table << row;

            const std::string xs = "x (pixels from centre)", ys = "y";
            writeImage(path(dir, name + "_analytic.png"),
                       correlationPlot(radial, "Corr[I(x,0), I(y,0)] analytic, " + name, xs, ys));
            writeImage(path(dir, name + "_measured.png"),
                       correlationPlot(measured, "measured over " + std::to_string(study.instances) + " instances", xs, ys));
            writeImage(path(dir, name + "_difference.png"),
                       correlationPlot(difference(radial, measured), "analytic - measured", xs, ys, -0.2, 0.2));
            writeImage(path(dir, name + "_nonradial.png"),
                       correlationPlot(nonRadial, "Corr[I(x,0), I(x,y)] analytic", xs, "y (pixels from centre)"));
            writeImage(path(dir, name + "_nonradial_measured.png"),
                       correlationPlot(measuredNonRadial, "Corr[I(x,0), I(x,y)] measured", xs, "y (pixels from centre)"));
            writeImage(path(dir, name + "_point.png"),
                       correlationPlot(acc.correlationWithPoint(), "Corr with the point (" + std::to_string(size / 2) +
                                                                       "," + std::to_string(size / 2) + "), measured",
                                       "x", "y"));
            const Image instance = renderZoom(first, p, ZoomRegion::centred(2 * size, 2 * size));
            writeImage(path(dir, name + "_instance.png"), instance);
            Image cellImage(3 * cell, cell, 3);
            paste(cellImage, toRgb(resizeSmooth(instance, cell, cell)), 0, 0);
            paste(cellImage, colourised(radial, cell), cell, 0);
            paste(cellImage, colourised(measured, cell), 2 * cell, 0);
            grid.back().push_back(cellImage);
            captions.back().push_back(study.variants[vi] + ", n = " + std::to_string(n));
            out.figures.push_back({name + "_analytic.png", "Analytic radial correlation, " + name});
            out.figures.push_back({name + "_measured.png", "Measured radial correlation, " + name});
            out.figures.push_back({name + "_difference.png", "Analytic − measured, " + name});
            out.figures.push_back({name + "_nonradial.png", "Analytic non-radial correlation, " + name});
            out.figures.push_back({name + "_point.png", "Measured correlation with one point, " + name});
        }
    }
    writeImage(path(dir, "figure2_10.png"), sheet(grid, captions));
    out.figures.insert(out.figures.begin(),
                       {"figure2_10.png",
                        "Figure 2.10 layout: rows = variants (" + [&] {
                            std::string s;
                            for (const auto& v : study.variants) s += (s.empty() ? "" : ", ") + v;
                            return s;
                        }() + "), columns = layer counts. Each cell: one instance, the analytic Corr[I(x,0), I(y,0)] "
                              "and the measured one (blue −1, white 0, red +1; origin bottom-left)."});
    writeFileAtomic(path(dir, "correlation.csv"), csv.str());
    out.table = table.str();
    return out;
}

StudyOutput runContrastStudy(const ZoomFlags& flags, const ContrastStudy& study, const std::string& dir) {
    validateStudy(flags, study);
    ZoomFlags f = flags;
    f.layers = study.layers;
    const ZoomParams p = makeZoomParams(f);
    ensureFolder(dir);
    const LatticeTexture base = makeBase(f, 0);
    const ZoomRegion region = ZoomRegion::centred(study.size, study.size);
    std::fprintf(stderr, "contrast: rendering %dx%d, n = %d, and its analytic variance\n", study.size, study.size,
                 p.layers);
    const Image texture = renderZoom(base, p, region);
    const ZoomStatistics stats(p, base.width(), base.height());
    Image varR = stats.varianceFactorImage(region);
    for (float& v : varR.data()) v *= float(base.variance());
    const double mu = base.mean(), vf = base.variance();

    // A raw lattice of the same size as the reference inset of Figure 2.6.
    Image raw(study.size, study.size, 1, Image::Uninitialized{});
    for (int y = 0; y < study.size; ++y)
        for (int x = 0; x < study.size; ++x) raw.at(x, y) = base.at(x, y);
    std::vector<float> sorted(varR.data().begin(), varR.data().end());
    std::nth_element(sorted.begin(), sorted.begin() + ptrdiff_t(sorted.size() / 2), sorted.end());
    const double medianVar = sorted[sorted.size() / 2];

    StudyOutput out;
    std::ostringstream csv, table;
    csv << "method,clamped_percent,non_monotone_percent,mean,stddev\n";
    table << "| image | clamped pixels | h' < 0 somewhere (polynomial) | mean | std |\n|---|---|---|---|---|\n";
    auto addRow = [&](const std::string& name, const Image& img, double clamped, double invalid) {
        const ChannelStats s = channelStats(img);
        csv << name << ',' << clamped << ',' << invalid << ',' << s.mean << ',' << s.stddev << '\n';
        char row[200];
        std::snprintf(row, sizeof row, "| %s | %.2f%% | %.2f%% | %.4f | %.4f |\n", name.c_str(), clamped, invalid, s.mean,
                      s.stddev);
        table << row;
    };
    std::vector<Image> textures{texture}, histograms, curves;
    std::vector<std::string> names{"uncorrected"};
    addRow("white noise (base)", raw, 0, 0);
    addRow("uncorrected", texture, 0, 0);
    auto histogramPlot = [&](const Image& img, const std::string& title) {
        const std::vector<double> h = histogram(img, 64);
        PlotSeries s;
        s.bars = true;
        for (size_t i = 0; i < h.size(); ++i) {
            s.x.push_back((double(i) + 0.5) / 64.0);
            s.y.push_back(h[i]);
        }
        LinePlotOptions o;
        o.title = title;
        o.xLabel = "intensity";
        o.yLabel = "fraction of pixels";
        o.width = 360;
        o.height = 240;
        o.xMin = 0;
        o.xMax = 1;
        return linePlot({s}, o);
    };
    histograms.push_back(histogramPlot(texture, "uncorrected"));
    // Axes of every correction-curve plot: I ∈ [0, 1] → h(I), room for clamping.
    auto curveAxes = [](const std::string& title) {
        LinePlotOptions o;
        o.title = title;
        o.xLabel = "I";
        o.yLabel = "h(I)";
        o.width = 360;
        o.height = 240;
        o.xMin = 0;
        o.xMax = 1;
        o.yMin = -0.5;
        o.yMax = 1.5;
        return o;
    };
    curves.push_back(linePlot({PlotSeries{"identity", {0, 1}, {0, 1}, {0.3f, 0.3f, 0.3f}}}, curveAxes("no correction")));
    for (ContrastMethod m : {ContrastMethod::Linear, ContrastMethod::Polynomial, ContrastMethod::Sigmoid}) {
        const std::string name = contrastMethodName(m);
        const ContrastResult r = correctContrast(m, texture, varR, mu, vf);
        writeImage(path(dir, "corrected_" + name + ".png"), r.image);
        if (m == ContrastMethod::Polynomial) writeImage(path(dir, "polynomial_non_monotone.png"), r.invalid);
        addRow(name, r.image, r.clampedPercent, r.invalidPercent);
        textures.push_back(r.image);
        names.push_back(name + " (" + [&] {
            char b[32];
            std::snprintf(b, sizeof b, "%.1f%% clamped", r.clampedPercent);
            return std::string(b);
        }() + ")");
        histograms.push_back(histogramPlot(r.image, name));
        // The correction curve at the median pixel variance, with its
        // clamping intervals shaded.
        PlotSeries s{name, {}, {}, {0.8f, 0.2f, 0.1f}};
        LinePlotOptions o = curveAxes(name + " at the median pixel variance");
        for (int i = 0; i <= 200; ++i) {
            const double x = i / 200.0;
            s.x.push_back(x);
            s.y.push_back(correctContrast(m, x, mu, vf, medianVar));
        }
        double start = -1;
        for (size_t i = 0; i < s.x.size(); ++i) {
            const bool out = s.y[i] < 0 || s.y[i] > 1;
            if (out && start < 0) start = s.x[i];
            if ((!out || i + 1 == s.x.size()) && start >= 0) {
                o.bands.push_back({start, s.x[i]});
                start = -1;
            }
        }
        curves.push_back(linePlot({s}, o));
    }
    writeImage(path(dir, "texture.png"), texture);
    writeImage(path(dir, "white_noise.png"), raw);
    const int thumb = 240;
    std::vector<Image> row1;
    for (const Image& t : textures) {
        Image small = toRgb(resizeNearest(t, thumb, thumb));
        // Inset: the raw white noise, as in Figure 2.6.
        paste(small, toRgb(resizeNearest(raw, thumb / 4, thumb / 4)), 0, 0);
        row1.push_back(small);
    }
    writeImage(path(dir, "figure2_6.png"), sheet({row1, histograms, curves}, {names, {}, {}}));
    writeFileAtomic(path(dir, "contrast.csv"), csv.str());
    out.figures.push_back({"figure2_6.png",
                           "Figure 2.6 layout (n = " + std::to_string(p.layers) +
                               "): the zoom texture and its linear, polynomial and sigmoid corrections (inset: the raw "
                               "white noise), their histograms, and each correction curve h at the median pixel "
                               "variance (red bands: inputs that get clamped)."});
    out.figures.push_back({"polynomial_non_monotone.png", "Pixels where the polynomial's h' < 0 somewhere on [0, 1] "
                                                          "(white): eq. 2.17's validity condition fails."});
    out.table = table.str();
    return out;
}

}  // namespace stochtex::cli
