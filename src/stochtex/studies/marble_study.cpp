#include "stochtex/studies/marble_study.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "stochtex/analysis/correlation_shape.h"
#include "stochtex/core/error.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/flow_study.h"
#include "stochtex/studies/spectrum_study.h"
#include "stochtex/studies/zoom_studies.h"

namespace stochtex {

namespace {

MarbleParams panel(const MarbleStudyOptions& o, MarbleScaling scaling, MarbleLayer layer) {
    MarbleParams p = o.marble;
    p.scaling = scaling;
    p.layer = layer;
    p.levelRate = 0;
    return p;
}

MarbleParams slidingPanel(const MarbleStudyOptions& o, MarbleScaling scaling, MarbleLayer layer) {
    MarbleParams p = panel(o, scaling, layer);
    p.levelAmplitude = 0;
    p.levelRate = o.slideRate;
    return p;
}

std::string scalingName(MarbleScaling s) { return enumName(kMarbleScalingNames, s); }
std::string layerName(MarbleLayer l) { return enumName(kMarbleLayerNames, l); }

// The default reference point (MarbleStudyOptions::pointX, pointY).
std::array<double, 2> referencePoint(const MarbleStudyOptions& o) {
    const double reach = 0.5 * (o.size - o.correlationSize);
    const double x = std::isnan(o.pointX) ? std::clamp(-0.25 * o.marble.levelPeriod, -reach, reach) : o.pointX;
    const double y = std::isnan(o.pointY) ? 0.5 * reach : o.pointY;
    return {x, y};
}

Image correlationPanel(const Image& c, const std::string& title, double x0, double y0) {
    HeatmapOptions h;
    h.title = title;
    h.xLabel = "x (pixels from the origin)";
    h.yLabel = "y (pixels from the origin)";
    h.xMin = x0;
    h.xMax = x0 + c.width();
    h.yMin = y0;
    h.yMax = y0 + c.height();
    h.yUp = false;  // rows as in the frames: y down
    h.cell = std::max(1, 256 / c.width());
    return heatmapPlot(c, h);
}

}  // namespace

std::span<const OptionMember<MarbleStudyOptions>> marbleStudyMembers() {
    using O = MarbleStudyOptions;
    static const OptionMember<O> members[] = {
        {"size", "Frames of N×N pixels centred on the origin", 32, 1024, &O::size},
        {"correlationSize", "Correlation window around the point, pixels (at most the size)", 16, 512,
         &O::correlationSize},
        {"instances", "Seeds per correlation map", 16, 100000, &O::instances},
        {"spectrumInstances", "Seeds per spectrum", 1, 1000, &O::spectrumInstances},
        {"slideRate", "Sliding: r in l = m + r t", -100, 100, &O::slideRate},
        {"frames", "Sliding frames", 2, 2000, &O::frames},
        {"timeStep", "Time between sliding frames", 1e-4, 10, &O::timeStep, "dt"},
        {"flowStep", "Pixels between flow vectors (at most half the size)", 4, 512, &O::flowStep, "step"},
    };
    return members;
}

void validateMarbleStudy(const MarbleStudyOptions& o) {
    validateMarbleParams(o.marble);
    if (o.scalings.empty()) throw InputError::parameter("scalings", "must name at least one scaling");
    checkMembers(o, marbleStudyMembers());
    if (o.correlationSize > o.size)
        throw InputError::parameter("correlationSize", "must not exceed size (" + std::to_string(o.size) + "), got " +
                                                           std::to_string(o.correlationSize));
    if (!std::isnan(o.pointX) && !(std::abs(o.pointX) <= 1 << 19))
        throw InputError::parameter("pointX", "must be within 2¹⁹ pixels of the origin, got " + formatValue(o.pointX));
    if (!std::isnan(o.pointY) && !(std::abs(o.pointY) <= 1 << 19))
        throw InputError::parameter("pointY", "must be within 2¹⁹ pixels of the origin, got " + formatValue(o.pointY));
    if (o.flowStep > o.size / 2)
        throw InputError::parameter("flowStep", "must be at most half the size (" + std::to_string(o.size / 2) +
                                                    "), got " + std::to_string(o.flowStep));
    // The sliding law must keep l in the kernel's range over every frame.
    const double end = o.marble.level + o.slideRate * o.timeStep * (o.frames - 1);
    if (end < -8 || end > 40)
        throw InputError::parameter("slideRate",
                                    "takes l to " + formatValue(end) + " by the last frame, outside [-8, 40]");
}

double marbleAnisotropy(const MarbleParams& p, double x, double y) {
    const double dl = marbleLevelSlope(p, x);
    const double s = 1 - x * std::numbers::ln2 * dl, g = -y * std::numbers::ln2 * dl;
    // Singular values of [[s, 0], [g, 1]]: from the trace and determinant of JᵀJ.
    const double t = s * s + g * g + 1, d = s * s;
    const double root = std::sqrt(std::max(0.0, t * t - 4 * d));
    const double small = 0.5 * (t - root);
    return small > 0 ? std::sqrt((0.5 * (t + root)) / small) : std::numeric_limits<double>::infinity();
}

namespace {

// Stretching: the texture and its steps per scaling, and the anisotropy of
// the scaled noise coordinates with the reference point.
void stretchingPart(const MarbleStudyOptions& o, MarbleStudyResult& r) {
    const SourceRegion frame = SourceRegion::centred(o.size, o.size);
    std::vector<std::vector<Image>> rows;
    std::vector<std::vector<std::string>> captions;
    const MarbleLayer shown[3] = {MarbleLayer::Marble, MarbleLayer::ScaledNoise, MarbleLayer::ScalingOnly};
    for (MarbleScaling s : o.scalings) {
        rows.emplace_back();
        captions.emplace_back();
        for (MarbleLayer layer : shown) {
            rows.back().push_back(MarbleSource(panel(o, s, layer)).render(frame, 0, 0));
            captions.back().push_back(layerName(layer) + ", " + scalingName(s));
        }
    }
    rows.push_back({MarbleSource(panel(o, MarbleScaling::Continuous, MarbleLayer::BaseNoise)).render(frame, 0, 0)});
    captions.push_back({"base-noise: the gradient noise at 2^m, before any scaling"});
    r.figures.push_back({"stretching.png", sheet(rows, captions),
                         "The marble texture I(x) = ½ + ½ sin(a·x + b noise(x / 2^l)), l = m + n cos(q x) (eq. 2.29), "
                         "and its steps: the scaled noise, and white noise constant on each cell of the scaled lattice "
                         "(the scaling step alone). One row per scaling; frames centred on the origin."});

    const auto [px, py] = referencePoint(o);
    r.pointX = px;
    r.pointY = py;
    r.pointAnisotropy = marbleAnisotropy(o.marble, px, py);
    std::vector<PlotSeries> curves;
    for (double y : {0.0, py}) {
        PlotSeries c{"continuous, y = " + TableCell::value(y, "%g").text, {}, {}, seriesColour(curves.size())};
        for (int k = 0; k <= 512; ++k) {
            const double x = -0.5 * o.size + o.size * k / 512.0;
            c.x.push_back(x);
            c.y.push_back(std::min(20.0, marbleAnisotropy(o.marble, x, y)));
        }
        curves.push_back(std::move(c));
    }
    curves.push_back({"blended (any y)", {-0.5 * o.size, 0.5 * o.size}, {1.0, 1.0}, seriesColour(2)});
    LinePlotOptions so;
    so.title = "Anisotropy of the scaled noise coordinates";
    so.xLabel = "x (pixels from the origin)";
    so.yLabel = "σ₁/σ₂ of ∂u/∂x (clipped at 20)";
    so.logY = true;
    so.bands = {{px - 1, px + 1}};
    r.figures.push_back(
        chartFigure("stretch.png", {curves, so},
                    "How much the scaling u = x / 2^l(x) stretches the noise: the ratio of the singular values of "
                    "its Jacobian, along the axis y = 0 and along the reference point's row. It is infinite at "
                    "the folds, where 1 − x ln 2 ∂l/∂x = 0 and the texture is mirrored, and grows with |y| where "
                    "l changes (a shear). The shaded band marks the correlation's reference point (x = " +
                        TableCell::value(px, "%.1f").text +
                        ", σ₁/σ₂ = " + TableCell::value(r.pointAnisotropy, "%.2f").text + ")."));
}

// Correlation over seeds around the reference point, per layer and scaling.
void correlationPart(const MarbleStudyOptions& o, const Progress& progress, MarbleStudyResult& r) {
    r.correlation.title = "Correlation around the reference point";
    r.correlation.note = "over " + std::to_string(o.instances) +
                         " seeds; the correlated region is Corr ≥ 0.5 connected "
                         "to the point; the anti-correlation is the lowest 5×5 mean of the map. Each value has a "
                         "standard error of about 1/√N = " +
                         TableCell::value(1 / std::sqrt(double(o.instances)), "%.3f").text +
                         ", which the scaling-only maps keep whole (a cell is one value, so the 5×5 mean does not "
                         "reduce it): their anti-correlation is that error, the base noise's is its lobes. The "
                         "continuous scaling's anisotropy σ₁/σ₂ at the point is " +
                         TableCell::value(r.pointAnisotropy, "%.2f").text +
                         ": its cells are about that much longer than wide";
    r.correlation.columns = {{"layer", "layer", ""},
                             {"scaling", "scaling", ""},
                             {"area", "correlated area", "px"},
                             {"elongation", "elongation", ""},
                             {"orientation", "major axis", "°"},
                             {"anti_correlation", "anti-correlation", ""}};
    const int half = o.correlationSize / 2;
    CorrelationMeasureOptions cm;
    cm.size = o.correlationSize;
    cm.instances = o.instances;
    cm.x0 = std::floor(r.pointX) - half;
    cm.y0 = std::floor(r.pointY) - half;
    struct Map {
        MarbleLayer layer;
        MarbleScaling scaling;
    };
    std::vector<Map> maps;
    for (MarbleScaling s : o.scalings) maps.push_back({MarbleLayer::Marble, s});
    for (MarbleScaling s : o.scalings) maps.push_back({MarbleLayer::ScalingOnly, s});
    maps.push_back({MarbleLayer::BaseNoise, MarbleScaling::Continuous});
    std::vector<std::vector<Image>> rows;
    std::vector<std::vector<std::string>> captions;
    for (size_t k = 0; k < maps.size(); ++k) {
        if (progress) progress(double(k) / maps.size(), layerName(maps[k].layer));
        const MarbleSource source(panel(o, maps[k].scaling, maps[k].layer));
        const Image c = measureCorrelation(source, cm).measuredPoint;
        const CorrelationShape shape = correlationShape(c, half, half);
        const bool base = maps[k].layer == MarbleLayer::BaseNoise;
        const std::string scaling = base ? "—" : scalingName(maps[k].scaling);
        r.correlation.add({layerName(maps[k].layer), scaling, TableCell::integer(shape.area),
                           TableCell::value(shape.elongation, "%.2f"), TableCell::value(shape.orientationDeg, "%.0f"),
                           TableCell::value(shape.antiCorrelation, "%.3f")});
        const std::string title = layerName(maps[k].layer) + (base ? "" : ", " + scaling);
        if (k == 0 || maps[k].layer != maps[k - 1].layer) {
            rows.emplace_back();
            captions.emplace_back();
        }
        rows.back().push_back(correlationPanel(c, "Corr with the point, " + title, cm.x0, cm.y0));
        captions.back().push_back(title);
    }
    r.figures.push_back({"correlation.png", sheet(rows, captions),
                         "Correlation over seeds of every pixel with the reference point (" +
                             TableCell::value(r.pointX, "%.1f").text + ", " + TableCell::value(r.pointY, "%.1f").text +
                             ") at the window's centre (Figures 2.19–2.21): the marble, the scaling step alone (white "
                             "cell noise through the same scaling: no lobes of its own, so what is elongated is the "
                             "artifact) and the base gradient noise, whose negative lobes the marble inherits."});
}

// Spectra of the marble and of the scaled noise, per scaling.
void spectraPart(const MarbleStudyOptions& o, const Progress& progress, MarbleStudyResult& r) {
    r.spectra.title = "Power spectra";
    r.spectra.note = "mean periodogram of " + std::to_string(o.spectrumInstances) + " seeds, Hann window";
    r.spectra.columns = {{"layer", "layer", ""},
                         {"scaling", "scaling", ""},
                         {"anisotropy", "anisotropy λ₁/λ₂", ""},
                         {"orientation", "major axis", "°"},
                         {"angular_max_min", "angular max/min", ""},
                         {"mean_radius", "mean |f|", "cycles/pixel"}};
    std::vector<std::vector<Image>> rows;
    std::vector<std::vector<std::string>> captions;
    SpectrumStudyOptions so;
    so.region = SourceRegion::centred(o.size, o.size);
    so.instances = o.spectrumInstances;
    int done = 0;
    for (MarbleScaling s : o.scalings) {
        rows.emplace_back();
        captions.emplace_back();
        for (MarbleLayer layer : {MarbleLayer::Marble, MarbleLayer::ScaledNoise}) {
            const SpectrumStudyResult sp =
                spectrumStudy(MarbleSource(panel(o, s, layer)), so,
                              progressPart(progress, double(done) / (2 * o.scalings.size()),
                                           double(done + 1) / (2 * o.scalings.size()), layerName(layer)));
            ++done;
            const SpectrumGeometry& g = sp.geometry;
            r.spectra.add({layerName(layer), scalingName(s), TableCell::value(g.anisotropy, "%.3f"),
                           TableCell::value(g.orientationDeg, "%.1f"), TableCell::value(g.angularMaxMin, "%.3f"),
                           TableCell::value(g.meanRadius)});
            rows.back().push_back(logSpectrumImage(sp.spectrum));
            captions.back().push_back(layerName(layer) + ", " + scalingName(s) +
                                      ": λ₁/λ₂ = " + TableCell::value(g.anisotropy, "%.2f").text);
        }
    }
    r.figures.push_back({"spectra.png", sheet(rows, captions),
                         "Power spectra (log scale over 4 decades, zero frequency at the centre; Figure 2.22). The "
                         "bands put two peaks on the axis of a; stretching adds a direction of its own to the "
                         "scaled noise, whose spectrum is round without it."});
}

// Sliding: l grows with t; the flow of the marble (videos, figures) and of the scaled noise.
void slidingPart(const MarbleStudyOptions& o, const Progress& progress, const MarbleFrameSink& onFrame,
                 MarbleStudyResult& r) {
    r.sliding.title = "Sliding: optical flow while l grows with time";
    r.sliding.note = "l = m + r t, r = " + formatValue(o.slideRate) +
                     " per time unit, Δt = " + formatValue(o.timeStep) + ", " +
                     enumName(kFlowMethodNames, o.flowMethod) +
                     " flow averaged over the frame pairs; a texture scaled about the origin moves outward at the rate "
                     "2^(rΔt) − 1 (the scaled noise); the marble's bands do not move";
    r.sliding.columns = {{"layer", "layer", ""},
                         {"scaling", "scaling", ""},
                         {"mean_magnitude", "mean |flow|", "px"},
                         {"mean_radial", "mean outward", "px"},
                         {"outward_fraction", "outward fraction", ""},
                         {"expansion_rate", "expansion rate", "per frame"},
                         {"scaling_rate", "scaling's rate", "per frame"}};
    const double scalingRate = std::exp2(o.slideRate * o.timeStep) - 1;
    FlowStudyOptions fo;
    fo.region = SourceRegion::centred(o.size, o.size);
    fo.frames = o.frames;
    fo.timeStep = o.timeStep;
    fo.step = o.flowStep;
    fo.margin = o.flowStep;
    fo.method = o.flowMethod;
    std::vector<PlotSeries> expansion;
    const size_t runs = 2 * o.scalings.size();
    for (size_t k = 0; k < runs; ++k) {
        // The marble under each scaling (videos, figures), then the scaled noise alone.
        const MarbleLayer layer = k < o.scalings.size() ? MarbleLayer::Marble : MarbleLayer::ScaledNoise;
        const MarbleScaling s = o.scalings[k % o.scalings.size()];
        const bool marble = layer == MarbleLayer::Marble;
        const std::string video = "sliding_" + scalingName(s);
        const FlowStudyResult f = flowStudy(
            MarbleSource(slidingPanel(o, s, layer)), fo,
            progressPart(progress, double(k) / runs, double(k + 1) / runs, layerName(layer) + ", " + scalingName(s)),
            [&](int i, const Image& img) {
                if (marble && onFrame) onFrame(k, i, img);
            });
        r.sliding.add({layerName(layer), scalingName(s), TableCell::value(f.mean.meanMagnitude),
                       TableCell::value(f.mean.meanRadial), TableCell::value(f.mean.outwardFraction, "%.3f"),
                       TableCell::value(f.mean.expansionRate, "%.5f"), TableCell::value(scalingRate, "%.5f")});
        PlotSeries e{layerName(layer) + ", " + scalingName(s), {}, {}, seriesColour(k)};
        for (size_t p = 0; p < f.pairs.size(); ++p) {
            e.x.push_back(double(p));
            e.y.push_back(f.pairs[p].expansionRate);
        }
        expansion.push_back(std::move(e));
        if (!marble) continue;
        for (const Figure& fig : f.figures)
            if (fig.file != "expansion.png")
                r.figures.push_back({video + "_" + fig.file, fig.image, scalingName(s) + " scaling. " + fig.caption});
    }
    LinePlotOptions eo;
    eo.title = "Expansion rate per frame pair";
    eo.xLabel = "pair k (frames k → k + 1)";
    eo.yLabel = "outward motion / distance";
    r.figures.push_back(
        chartFigure("sliding_expansion.png", {expansion, eo},
                    "The least-squares rate of outward motion per frame pair. With the continuous scaling the "
                    "scaled noise slides outward at about the scaling's own rate (" +
                        TableCell::value(scalingRate, "%.4f").text +
                        " per frame) and the marble, whose bands stay, more slowly; with the blended scales "
                        "nothing moves: the two fields cross-fade in place."));
}

}  // namespace

std::vector<std::string> marbleVideoNames(const MarbleStudyOptions& o) {
    std::vector<std::string> names;
    for (MarbleScaling s : o.scalings) names.push_back("sliding_" + scalingName(s));
    return names;
}

MarbleStudyResult marbleStudy(const MarbleStudyOptions& o, const StudyProgress& progress,
                              const MarbleFrameSink& onFrame) {
    validateMarbleStudy(o);
    MarbleStudyResult r;
    r.videos = marbleVideoNames(o);
    if (progress) progress(0.0, "stretching");
    stretchingPart(o, r);
    correlationPart(o, progressPart(progress, 0.05, 0.55, "correlation"), r);
    spectraPart(o, progressPart(progress, 0.55, 0.7, "spectra"), r);
    slidingPart(o, progressPart(progress, 0.7, 1.0, "sliding"), onFrame, r);
    return r;
}

Report marbleReport(const MarbleStudyResult& r, bool videos) {
    Report report;
    report.title = "The marble texture (thesis eq. 2.29)";
    ReportSection stretching, correlation, spectra, sliding;
    stretching.heading = "Stretching (section 2.7.2, Figures 1.6 and 2.19)";
    correlation.heading = "Correlation (Figures 2.19–2.21)";
    correlation.tables = {{"correlation.csv", r.correlation}};
    spectra.heading = "Power spectra (Figure 2.22)";
    spectra.tables = {{"spectra.csv", r.spectra}};
    sliding.heading = "Sliding and optical flow (section 2.8, Figures 2.23–2.24)";
    sliding.tables = {{"sliding.csv", r.sliding}};
    if (videos)
        for (const std::string& v : r.videos) sliding.videos.push_back({v, htmlEscape(v)});
    for (const Figure& f : r.figures) {
        if (f.file == "stretching.png" || f.file == "stretch.png")
            stretching.figures.push_back(f);
        else if (f.file == "correlation.png")
            correlation.figures.push_back(f);
        else if (f.file == "spectra.png")
            spectra.figures.push_back(f);
        else
            sliding.figures.push_back(f);
    }
    report.sections = {stretching, correlation, spectra, sliding};
    return report;
}

}  // namespace stochtex
