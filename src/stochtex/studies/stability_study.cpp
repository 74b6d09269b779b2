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

std::vector<FilterOptions> stabilityFilters(const PatternSpec& pattern, std::span<const std::string> filters,
                                            std::span<const VarianceEstimator> estimators, const FilterOptions& base) {
    if (filters.empty()) throw InputError::parameter("filters", "must name at least one filter");
    std::vector<FilterOptions> named;
    for (const std::string& name : filters) named.emplace_back(base).use(parseFilter(name));
    const std::vector<VarianceEstimator> fallback{pattern.estimator.value_or(VarianceEstimator::Paper)};
    return filtersPerEstimator(named, estimators.empty() ? std::span<const VarianceEstimator>(fallback) : estimators);
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

StabilitySampler::StabilitySampler(const GraphPattern& pattern, const StabilityStudyOptions& o) : options_(o) {
    validateStabilityStudy(o);
    // The filters that share a table or a pyramid build it once.
    for (const FilterOptions& f : o.filters)
        filters_.push_back(std::make_unique<FilteredGraph>(pattern, f, GraphMoments::Matched, &cache_));
    FilterOptions truthOptions = o.filters.front();
    truthOptions.source = StatisticsSource::Reference;
    truthOptions.referenceMaxSamples = o.truthSamples;
    truth_ = std::make_unique<FilteredGraph>(pattern, truthOptions, GraphMoments::Matched, &cache_);
}

StabilitySampler::~StabilitySampler() = default;

StabilityFrames StabilitySampler::frames(int first, int count, const StudyProgress& progress,
                                         const StabilityFrameSink& onFrame) const {
    const StabilityStudyOptions& o = options_;
    if (first < 0 || first >= o.frames)
        throw InputError::parameter(
            "first", "must be in [0, " + std::to_string(o.frames - 1) + "], got " + std::to_string(first));
    if (count < 1 || count > o.frames - first)
        throw InputError::parameter("count", "must keep the range within the study's " + std::to_string(o.frames) +
                                                 " frames, got " + std::to_string(count) + " from frame " +
                                                 std::to_string(first));
    std::vector<ZoomSequenceMeter> meters(filters_.size());
    const int renders = int(filters_.size()) + 1;
    const int start = std::max(0, first - 1);  // the previous range's last frame, for the first pair
    const int rendered = first + count - start;
    for (int k = start; k < first + count; ++k) {
        Camera cam;
        cam.view.width = cam.view.height = o.size;
        cam.view.scale = zoomSequenceScale(k, o.frames, o.from, o.to);
        // Zoom about a fixed texture point: the view centre stays at texel (0, 0).
        cam.view.offsetU = cam.view.offsetV = -0.5 * o.size * cam.view.scale;
        const auto part = [&](int r, const std::string& what) {
            return progressPart(
                progress, (k - start) * renders + r, rendered * renders,
                "stability: frame " + std::to_string(k + 1) + "/" + std::to_string(o.frames) + ", " + what);
        };
        const Image reference = truth_->render(cam, part(0, "ground truth"));
        for (size_t m = 0; m < filters_.size(); ++m) {
            const Image frame = filters_[m]->render(cam, part(int(m) + 1, filterLabel(o.filters[m])));
            if (onFrame && k >= first) onFrame(m, k, frame);
            meters[m].add(frame, reference, cam.view.scale);
        }
    }
    StabilityFrames out{first, count, {}, {}, {}};
    const size_t skip = size_t(first - start);  // the re-rendered frame's accuracy is the previous range's
    for (const ZoomSequenceMeter& meter : meters) {
        out.accuracy.emplace_back(meter.accuracy().begin() + long(skip), meter.accuracy().end());
        out.imageChange.push_back(meter.imageChange().differences);
        out.errorFlicker.push_back(meter.errorFlicker().differences);
    }
    return out;
}

StabilityStudyResult stabilityStudy(const GraphPattern& pattern, const StabilityStudyOptions& o,
                                    const StudyProgress& progress, const StabilityFrameSink& onFrame) {
    const StabilityFrames all = StabilitySampler(pattern, o).frames(0, o.frames, progress, onFrame);
    return stabilityFromFrames(o, {&all, 1});
}

StabilityStudyResult stabilityFromFrames(const StabilityStudyOptions& o, std::span<const StabilityFrames> parts) {
    validateStabilityStudy(o);
    const size_t filters = o.filters.size();
    std::vector<std::vector<double>> accuracy(filters), change(filters), flicker(filters);
    int next = 0;
    for (const StabilityFrames& p : parts) {
        if (p.first != next || p.accuracy.size() != filters || p.imageChange.size() != filters ||
            p.errorFlicker.size() != filters)
            throw InputError::parameter("parts", "must cover frames 0…" + std::to_string(o.frames - 1) +
                                                     " in order, each with every filter's values");
        const size_t pairs = size_t(p.count) - (p.first == 0 ? 1 : 0);
        for (size_t m = 0; m < filters; ++m) {
            if (p.accuracy[m].size() != size_t(p.count) || p.imageChange[m].size() != pairs ||
                p.errorFlicker[m].size() != pairs)
                throw InputError::parameter("parts", "frames " + std::to_string(p.first) + "… hold " +
                                                         std::to_string(p.accuracy[m].size()) + " accuracies, not " +
                                                         std::to_string(p.count));
            accuracy[m].insert(accuracy[m].end(), p.accuracy[m].begin(), p.accuracy[m].end());
            change[m].insert(change[m].end(), p.imageChange[m].begin(), p.imageChange[m].end());
            flicker[m].insert(flicker[m].end(), p.errorFlicker[m].begin(), p.errorFlicker[m].end());
        }
        next += p.count;
    }
    if (next != o.frames)
        throw InputError::parameter(
            "parts", "cover frames 0…" + std::to_string(next - 1) + " of the study's " + std::to_string(o.frames));
    std::vector<double> scales;
    for (int k = 0; k < o.frames; ++k) scales.push_back(zoomSequenceScale(k, o.frames, o.from, o.to));
    std::vector<std::string> names;
    for (const FilterOptions& f : o.filters) names.push_back(filterLabel(f));

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
    for (size_t m = 0; m < filters; ++m) {
        StabilityMeasurement s{zoomStabilityOf(scales, change[m]), zoomStabilityOf(scales, flicker[m]), accuracy[m],
                               orderedMean(accuracy[m])};
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
                 pair ? TableCell::value(s.imageChange.differences[size_t(k - 1)], "%.5f") : TableCell::none(),
                 pair ? TableCell::value(s.errorFlicker.differences[size_t(k - 1)], "%.5f") : TableCell::none()});
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
