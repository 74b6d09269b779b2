#include "stochtex/studies/stability_study.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/report/plot.h"

namespace stochtex {

std::span<const OptionMember<StabilityStudyOptions>> stabilityStudyMembers() {
    using O = StabilityStudyOptions;
    static const OptionMember<O> members[] = {
        {"frames", "Number of frames", 2, 1000, &O::frames},
        {"size", "Frame side in pixels", 8, 2048, &O::size},
        {"from", "First scale (texels per pixel)", kMinViewScale, kMaxViewScale, &O::from},
        {"to", "Last scale", kMinViewScale, kMaxViewScale, &O::to},
        {"truthSamples", "Max samples per axis of the ground truth S̄ that errors are measured against", 1, 4096,
         &O::truthSamples},
    };
    return members;
}

std::vector<FilterOptions> filtersPerEstimator(std::span<const FilterOptions> filters,
                                               std::span<const VarianceEstimator> estimators) {
    if (estimators.empty()) throw InputError::parameter("estimators", "must name at least one estimator");
    for (auto e = estimators.begin(); e != estimators.end(); ++e)
        if (std::find(estimators.begin(), e, *e) != e)
            throw InputError::parameter(
                "estimators", "must name each estimator once, got " + enumName(kVarianceEstimatorNames, *e) + " twice");
    std::vector<FilterOptions> measured;
    for (const FilterOptions& f : filters) {
        if (f.source != StatisticsSource::Estimators) {
            measured.push_back(f);
            continue;
        }
        for (const VarianceEstimator e : estimators) measured.emplace_back(f).estimator = e;
    }
    return measured;
}

std::vector<std::string> stabilitySequenceNames(std::span<const FilterOptions> filters) {
    std::vector<std::string> names;
    for (const FilterOptions& f : filters) {
        std::string name = filterLabel(f);
        std::replace(name.begin(), name.end(), '/', '-');
        names.push_back(name);
    }
    return names;
}

void validateStabilityStudy(const StabilityStudyOptions& o) {
    if (o.filters.empty()) throw InputError::parameter("filters", "must name at least one filter");
    checkMembers(o, stabilityStudyMembers());
}

StabilityStudyResult stabilityStudy(const GraphPattern& pattern, const StabilityStudyOptions& o,
                                    const StudyProgress& progress, const StabilityFrameSink& onFrame) {
    validateStabilityStudy(o);
    // The filters that share a table or a pyramid build it once.
    PartCache partCache;
    std::vector<std::unique_ptr<FilteredGraph>> filters;
    std::vector<std::string> names;
    for (const FilterOptions& f : o.filters) {
        filters.push_back(std::make_unique<FilteredGraph>(pattern, f, GraphMoments::Matched, &partCache));
        names.push_back(filterLabel(f));
    }
    FilterOptions truthOptions = o.filters.front();
    truthOptions.source = StatisticsSource::Reference;
    truthOptions.referenceMaxSamples = o.truthSamples;
    const FilteredGraph truth(pattern, truthOptions, GraphMoments::Matched, &partCache);
    std::vector<ZoomSequenceMeter> meters(filters.size());
    const int renders = int(filters.size()) + 1;
    for (int k = 0; k < o.frames; ++k) {
        Camera cam;
        cam.view.width = cam.view.height = o.size;
        cam.view.scale = zoomSequenceScale(k, o.frames, o.from, o.to);
        // Zoom about a fixed texture point: the view centre stays at texel (0, 0).
        cam.view.offsetU = cam.view.offsetV = -0.5 * o.size * cam.view.scale;
        const auto part = [&](int r, const std::string& what) {
            return progressPart(
                progress, k * renders + r, o.frames * renders,
                "stability: frame " + std::to_string(k + 1) + "/" + std::to_string(o.frames) + ", " + what);
        };
        const Image reference = truth.render(cam, part(0, "ground truth"));
        for (size_t m = 0; m < filters.size(); ++m) {
            const Image frame = filters[m]->render(cam, part(int(m) + 1, names[m]));
            if (onFrame) onFrame(m, k, frame);
            meters[m].add(frame, reference, cam.view.scale);
        }
    }

    StabilityStudyResult r;
    r.summary.columns = {{"filter", "filter", ""},
                         {"image_change_mean", "image change, mean |ΔI|", ""},
                         {"image_change_max", "image change, max", ""},
                         {"error_flicker_mean", "error flicker, mean |ΔE|", ""},
                         {"error_flicker_max", "error flicker, max", ""},
                         {"accuracy_mean", "mean |I − S̄|", ""}};
    r.perFrame.columns = {{"filter", "filter", ""},    {"frame", "frame", ""},       {"scale", "scale", ""},
                          {"accuracy", "|I − S̄|", ""}, {"image_change", "|ΔI|", ""}, {"error_flicker", "|ΔE|", ""}};
    PlotSeries flickerSeries, accuracySeries;
    std::vector<PlotSeries> flickerPlot, accuracyPlot;
    for (size_t m = 0; m < filters.size(); ++m) {
        StabilityMeasurement s{meters[m].imageChange(), meters[m].errorFlicker(), meters[m].accuracy(),
                               meters[m].meanAccuracy()};
        r.summary.add({names[m], TableCell::value(s.imageChange.mean, "%.5f"),
                       TableCell::value(s.imageChange.max, "%.5f"), TableCell::value(s.errorFlicker.mean, "%.5f"),
                       TableCell::value(s.errorFlicker.max, "%.5f"), TableCell::value(s.meanAccuracy, "%.5f")});
        PlotSeries flicker{names[m], {}, {}, seriesColour(m)}, accuracy{names[m], {}, {}, seriesColour(m)};
        for (int k = 0; k < o.frames; ++k) {
            const double scale = s.imageChange.scales[size_t(k)];
            const bool pair = k > 0;
            r.perFrame.add(
                {names[m], TableCell::integer(k), TableCell::value(scale, "%g"),
                 TableCell::value(s.accuracy[size_t(k)], "%.5f"),
                 pair ? TableCell::value(s.imageChange.differences[size_t(k - 1)], "%.5f") : TableCell(""),
                 pair ? TableCell::value(s.errorFlicker.differences[size_t(k - 1)], "%.5f") : TableCell("")});
            accuracy.x.push_back(scale);
            accuracy.y.push_back(s.accuracy[size_t(k)]);
            if (!pair) continue;
            flicker.x.push_back(scale);
            flicker.y.push_back(s.errorFlicker.differences[size_t(k - 1)]);
        }
        flickerPlot.push_back(flicker);
        accuracyPlot.push_back(accuracy);
        r.measurements.push_back(std::move(s));
    }
    LinePlotOptions fo;
    fo.title = "Error flicker: |ΔE| between consecutive frames, E = frame − S̄";
    fo.xLabel = "scale (texels per pixel)";
    fo.yLabel = "mean |ΔE|";
    fo.logX = true;
    r.figures.push_back(
        chartFigure("error_flicker.png", {flickerPlot, fo},
                    "Error flicker per frame: the zoom-compensated change of the error frames (frame − ground "
                    "truth S̄, " +
                        std::to_string(o.truthSamples) +
                        " samples per axis at most). Low only where a "
                        "filter follows the truth from frame to frame."));
    LinePlotOptions ao = fo;
    ao.title = "Accuracy: mean |frame − S̄| per frame";
    ao.yLabel = "mean |I − S̄|";
    r.figures.push_back(chartFigure("accuracy.png", {accuracyPlot, ao}, "Accuracy per frame: mean |frame − S̄|."));
    return r;
}

Report stabilityReport(const StabilityStudyResult& r, const std::string& patternName) {
    return sectionReport("Temporal stability under a zoom: " + patternName,
                         {{"stability.csv", r.summary}, {"stability-frames.csv", r.perFrame, false}}, r.figures);
}

}  // namespace stochtex
