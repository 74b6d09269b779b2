#include "stochtex/studies/flow_study.h"

#include <cmath>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/report/plot.h"

namespace stochtex {

std::span<const OptionMember<FlowStudyOptions>> flowStudyMembers() {
    using O = FlowStudyOptions;
    static const OptionMember<O> members[] = {
        {"frames", "Frames (image files: all)", 2, 10000, &O::frames},
        {"timeStep", "Time between frames (image files: one file per frame)", -1e9, 1e9, &O::timeStep, "dt"},
        {"step", "Grid of the vectors, pixels (at most the window's side)", 1, 4096, &O::step},
        {"arrowScale", "Arrows drawn this many times their length", 1e-3, 1000, &O::arrowScale},
        {"instance", "The source's instance", 0, 1000000, &O::instance},
    };
    return members;
}

void validateFlowStudy(const FlowStudyOptions& o, const TextureSource* source) {
    const SourceRegion& r = o.region;
    if (r.width < 16 || r.height < 16 || r.width > 4096 || r.height > 4096)
        throw InputError::parameter(
            "size", "must be 16…4096 pixels a side, got " + std::to_string(r.width) + "×" + std::to_string(r.height));
    checkMembers(o, flowStudyMembers());
    if (!std::isfinite(o.time) || !std::isfinite(o.time + o.timeStep * o.frames))
        throw InputError::parameter("time", "the frame times must be finite");
    if (o.step > std::min(r.width, r.height))
        throw InputError::parameter("step", "must be at most the window's side, got " + std::to_string(o.step));
    if (o.margin < 0 || 2 * o.margin >= std::min(r.width, r.height))
        throw InputError::parameter("margin", "must leave part of the window, got " + std::to_string(o.margin));
    if (source) {
        for (int k = 0; k < o.frames; ++k) source->checkWindow(o.region, o.time + k * o.timeStep);
        source->checkInstances(o.instance + 1);
    }
}

namespace {

void addSummaryRow(Table& t, const std::string& pair, const FlowSummary& s) {
    t.add({pair, TableCell::integer(s.vectors), TableCell::value(s.meanU), TableCell::value(s.meanV),
           TableCell::value(s.meanMagnitude), TableCell::value(s.meanRadial),
           TableCell::value(s.outwardFraction, "%.3f"), TableCell::value(s.expansionRate, "%.5f")});
}

}  // namespace

FlowStudyResult flowStudy(const TextureSource& source, const FlowStudyOptions& o, const StudyProgress& progress,
                          const FlowFrameSink& onFrame) {
    validateFlowStudy(o, &source);
    const SourceRegion& region = o.region;
    double cx = o.centreX, cy = o.centreY;
    if (std::isnan(cx) || std::isnan(cy)) {
        const double ox = -region.x0, oy = -region.y0;  // where the source's origin falls in the window
        const bool inside = ox >= 0 && oy >= 0 && ox < region.width && oy < region.height;
        cx = inside ? ox : 0.5 * region.width;
        cy = inside ? oy : 0.5 * region.height;
    }
    FlowStudyResult r;
    r.summary.columns = {{"pair", "frames", ""},
                         {"vectors", "vectors", ""},
                         {"mean_u", "mean u", "px"},
                         {"mean_v", "mean v", "px"},
                         {"mean_magnitude", "mean |flow|", "px"},
                         {"mean_radial", "mean outward", "px"},
                         {"outward_fraction", "outward fraction", ""},
                         {"expansion_rate", "expansion rate", "per frame"}};
    const bool dense = o.method != FlowMethod::LucasKanade;
    Image prev = source.render(region, o.time, o.instance), first = prev, firstFlow;
    if (onFrame) onFrame(0, prev);
    std::vector<FlowVector> firstVectors;
    for (int k = 0; k + 1 < o.frames; ++k) {
        if (progress)
            progress(double(k) / (o.frames - 1), "pair " + std::to_string(k + 1) + "/" + std::to_string(o.frames - 1));
        Image next = source.render(region, o.time + (k + 1) * o.timeStep, o.instance);
        if (onFrame) onFrame(k + 1, next);
        std::vector<FlowVector> v;
        if (dense) {
            Image flow = denseFlow(prev, next, o.method);
            v = sampleFlow(flow, o.step, o.margin);
            if (k == 0) firstFlow = std::move(flow);
        } else {
            v = flowVectors(prev, next, o.method, o.step, o.margin);
        }
        r.pairs.push_back(summariseFlow(v, cx, cy));
        if (k == 0) firstVectors = std::move(v);
        addSummaryRow(r.summary, std::to_string(k) + "→" + std::to_string(k + 1), r.pairs.back());
        prev = std::move(next);
    }
    for (const FlowSummary& s : r.pairs) {
        r.mean.vectors += s.vectors;
        r.mean.meanU += s.meanU / r.pairs.size();
        r.mean.meanV += s.meanV / r.pairs.size();
        r.mean.meanMagnitude += s.meanMagnitude / r.pairs.size();
        r.mean.meanRadial += s.meanRadial / r.pairs.size();
        r.mean.outwardFraction += s.outwardFraction / r.pairs.size();
        r.mean.expansionRate += s.expansionRate / r.pairs.size();
    }
    addSummaryRow(r.summary, "mean", r.mean);

    const std::string method = enumName(kFlowMethodNames, o.method);
    char numbers[200];
    std::snprintf(numbers, sizeof numbers,
                  "mean outward motion %.3f px, %.0f%% of moving vectors outward, expansion rate %.4f per frame",
                  r.pairs[0].meanRadial, 100 * r.pairs[0].outwardFraction, r.pairs[0].expansionRate);
    if (dense)
        r.figures.push_back(
            {"flow_colour.png", flowColourImage(firstFlow),
             "Flow of frames 0→1 (" + method +
                 "): direction as hue (right red, up yellow-green, left cyan, down violet), magnitude as "
                 "brightness (the largest is full)."});
    r.figures.push_back({"flow_arrows.png",
                         flowArrowsImage(encodeTransfer(first, o.frameTransfer), firstVectors, o.arrowScale),
                         "Flow vectors of frames 0→1 (" + method + ", every " + std::to_string(o.step) +
                             " px, drawn ×" + TableCell::value(o.arrowScale, "%g").text + "): " + numbers + "."});
    if (r.pairs.size() >= 2) {
        PlotSeries s{"expansion rate", {}, {}, {0.1f, 0.3f, 0.8f}};
        for (size_t k = 0; k < r.pairs.size(); ++k) {
            s.x.push_back(double(k));
            s.y.push_back(r.pairs[k].expansionRate);
        }
        LinePlotOptions po;
        po.title = "Expansion rate per frame pair";
        po.xLabel = "pair k (frames k → k + 1)";
        po.yLabel = "outward motion / distance";
        r.figures.push_back(
            chartFigure("expansion.png", {{s}, po},
                        "The least-squares rate k of outward motion ≈ k·distance from the centre: positive for "
                        "content moving outward (a zoom in), 0 for a fixed texture."));
    }
    return r;
}

Report flowReport(const FlowStudyResult& r, const std::string& sourceName, bool video) {
    Report report = sectionReport("Optical flow: " + sourceName, {{"flow.csv", r.summary}}, r.figures);
    if (video) report.sections.front().videos = {{"frames", "The frames analysed"}};
    return report;
}

}  // namespace stochtex
