#include "stochtex/studies/frame_analysis.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "stochtex/analysis/flicker.h"
#include "stochtex/core/error.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/flow_study.h"
#include "stochtex/studies/instance_statistics.h"
#include "stochtex/studies/spectrum_study.h"
#include "stochtex/studies/temporal_coherence_study.h"

namespace stochtex {

namespace {

SpectrumStudyOptions spectrumOptions(const FrameAnalysisOptions& o) {
    SpectrumStudyOptions s;
    s.region = o.region;
    s.times = {o.time};
    s.frameTransfer = o.frameTransfer;
    return s;
}

FlowStudyOptions flowOptions(const FrameAnalysisOptions& o) {
    FlowStudyOptions f;
    f.region = o.region;
    f.time = o.time;
    f.timeStep = o.timeStep;
    f.frames = o.frames;
    f.method = FlowMethod::Dis;  // dense and robust on smooth procedural motion (MarbleStudyOptions says why)
    f.frameTransfer = o.frameTransfer;
    return f;
}

TemporalCoherenceOptions coherenceOptions(const FrameAnalysisOptions& o) {
    TemporalCoherenceOptions c;
    c.region = o.region;
    c.times = evenTimes(o.time, o.timeStep, o.frames);
    c.frameTransfer = o.frameTransfer;
    return c;
}

bool has(const FrameAnalysisOptions& o, FrameAnalysis a) {
    return std::find(o.analyses.begin(), o.analyses.end(), a) != o.analyses.end();
}

InstanceStatisticsOptions statisticsOptions(const FrameAnalysisOptions& o) {
    InstanceStatisticsOptions s;
    s.region = o.region;
    s.time = o.time;
    s.instances = o.instances;
    s.pointX = o.pointX;
    s.pointY = o.pointY;
    return s;
}

struct Section {
    std::string title;
    std::vector<std::pair<std::string, Table>> tables;  // the first is the summary shown
    std::vector<Figure> figures;
};

// The flicker section from the pairs' measures (every pair of the run, in
// order) and the worst pair's map.
Section flickerSection(const FrameAnalysisOptions& o, std::span<const FlickerPairs> parts) {
    Section s{"Flicker: change between frames that the optical flow does not explain", {}, {}};
    Table perPair, summary;
    perPair.columns = {{"pair", "frames", ""},
                       {"residual", "residual", "codes"},
                       {"contrast", "contrast", "codes"},
                       {"relative", "residual / contrast", ""}};
    std::vector<double> pairs, relative;
    double worst = -1, sumResidual = 0, sumContrast = 0;
    const Image* worstMap = nullptr;
    int worstPair = 0, next = 0;
    for (const FlickerPairs& part : parts) {
        if (part.first != next)
            throw InputError::parameter("parts", "must cover pairs 0…" + std::to_string(o.frames - 2) + " in order");
        for (size_t i = 0; i < part.measures.size(); ++i) {
            const int k = part.first + int(i) + 1;  // pair k − 1 → k
            const FlickerMeasure& m = part.measures[i];
            perPair.add({TableCell(std::to_string(k - 1) + "→" + std::to_string(k)), TableCell::value(m.residual),
                         TableCell::value(m.contrast), TableCell::value(m.relative)});
            pairs.push_back(k - 1);
            relative.push_back(m.relative);
            sumResidual += m.residual;
            sumContrast += m.contrast;
            // The first pair of the largest residual, as one pass over the run finds it.
            if (m.residual > worst) worst = m.residual, worstMap = &part.worstMap, worstPair = k - 1;
        }
        next += int(part.measures.size());
    }
    if (next != o.frames - 1 || !worstMap)
        throw InputError::parameter(
            "parts", "cover pairs 0…" + std::to_string(next - 1) + " of the run's " + std::to_string(o.frames - 1));
    const int n = o.frames - 1;
    const double meanContrast = sumContrast / n;
    summary.columns = {{"pairs", "pairs", ""},
                       {"residual", "mean residual", "codes"},
                       {"contrast", "mean contrast", "codes"},
                       {"relative", "residual / contrast", ""}};
    summary.add({TableCell::integer(n), TableCell::value(sumResidual / n), TableCell::value(meanContrast),
                 TableCell::value(relativeFlicker(sumResidual / n, meanContrast))});
    s.tables = {{"flicker.csv", summary}, {"flicker_pairs.csv", perPair}};
    PlotSeries series{"residual / contrast", pairs, relative, {0.8f, 0.2f, 0.1f}};
    LinePlotOptions po;
    po.title = "Flicker per pair of frames";
    po.xLabel = "pair (frame k → k + 1)";
    po.yLabel = "residual / contrast";
    s.figures.push_back(
        chartFigure("flicker.png", {{series}, po},
                    "The next frame warped back by the optical flow (DIS) and subtracted: what motion does not "
                    "explain, relative to the frames' contrast (blur lowers both)."));
    s.figures.push_back(
        {"flicker_map.png",
         windowMap(*worstMap, o.region,
                   "Residual of pair " + std::to_string(worstPair) + "→" + std::to_string(worstPair + 1), 0,
                   std::max(1e-6, 4.0 * worst), HeatPalette::Viridis),
         "Where the worst pair flickers: the per-pixel residual (grey: no flow target inside the frame)."});
    return s;
}

// Instances 0…N−1 at the first frame's time through the correlation accumulator.
Section statisticsSection(const TextureSource& source, const FrameAnalysisOptions& o, const Progress& progress) {
    const InstanceStatisticsOptions options = statisticsOptions(o);
    InstanceStatisticsSummary summary =
        summarizeInstanceStatistics(instanceStatistics(source, options, progress), options.region);
    return {std::move(summary.title), {{"statistics.csv", std::move(summary.summary)}}, std::move(summary.figures)};
}

}  // namespace

void validateFrameAnalysis(const FrameAnalysisOptions& o, const TextureSource* source) {
    if (o.analyses.empty())
        throw InputError::parameter("analyses",
                                    "must name at least one of " + canonicalNames(kFrameAnalysisNames, ", "));
    for (size_t k = 0; k < o.analyses.size(); ++k)
        if (std::count(o.analyses.begin(), o.analyses.end(), o.analyses[k]) > 1)
            throw InputError::parameter("analyses", "names " + enumName(kFrameAnalysisNames, o.analyses[k]) + " twice");
    if (has(o, FrameAnalysis::Spectrum)) validateSpectrumStudy(spectrumOptions(o), source);
    if (has(o, FrameAnalysis::Flow)) validateFlowStudy(flowOptions(o), source);
    if (has(o, FrameAnalysis::Coherence)) validateTemporalCoherence(coherenceOptions(o), source);
    if (has(o, FrameAnalysis::Flicker)) validateFlowStudy(flowOptions(o), source);  // the same frames, the same flow
    if (has(o, FrameAnalysis::Statistics)) validateInstanceStatistics(statisticsOptions(o), source);
}

FlickerPairs flickerPairs(const TextureSource& source, const FrameAnalysisOptions& o, int first, int count,
                          const Progress& progress) {
    validateFlowStudy(flowOptions(o), &source);  // the same frames, the same flow
    if (first < 0 || first >= o.frames - 1)
        throw InputError::parameter(
            "first", "must be in [0, " + std::to_string(o.frames - 2) + "], got " + std::to_string(first));
    if (count < 1 || count > o.frames - 1 - first)
        throw InputError::parameter("count", "must keep the pairs within the run's " + std::to_string(o.frames - 1) +
                                                 ", got " + std::to_string(count) + " from pair " +
                                                 std::to_string(first));
    FlickerPairs out;
    out.first = first;
    double worst = -1;
    Image previous = source.render(o.region, o.time + first * o.timeStep, 0);
    for (int k = first + 1; k <= first + count; ++k) {
        if (progress) progress(double(k - 1 - first) / count, "frame " + std::to_string(k + 1));
        Image next = source.render(o.region, o.time + k * o.timeStep, 0);
        Image map;
        out.measures.push_back(flowCompensatedFlicker(previous, next, &map));
        if (out.measures.back().residual > worst) worst = out.measures.back().residual, out.worstMap = std::move(map);
        previous = std::move(next);
    }
    return out;
}

FrameAnalysisResult flickerFromPairs(const FrameAnalysisOptions& options, std::span<const FlickerPairs> parts) {
    FrameAnalysisOptions o = options;
    o.analyses = {FrameAnalysis::Flicker};
    validateFrameAnalysis(o);
    const Section s = flickerSection(o, parts);
    FrameAnalysisResult r;
    r.report.title = "Frame studies: " + o.sourceName;
    r.tables = s.tables;
    r.figures = s.figures;
    ReportSection section;
    section.heading = s.title;
    section.figures = s.figures;
    for (size_t t = 0; t < s.tables.size(); ++t)
        section.tables.push_back({s.tables[t].first, s.tables[t].second, t == 0});
    r.report.sections.push_back(std::move(section));
    r.markdown = s.title + "\n" + s.tables.front().second.markdown() + "\n";
    return r;
}

FrameAnalysisResult frameAnalysis(const TextureSource& source, const FrameAnalysisOptions& o,
                                  const StudyProgress& progress) {
    validateFrameAnalysis(o, &source);
    FrameAnalysisResult r;
    r.report.title = "Frame studies: " + o.sourceName;
    const int n = int(o.analyses.size());
    // A study's section: its first table on the page, every table (added to
    // r.tables before) as its CSV, its figures.
    size_t written = 0;
    const auto add = [&](const std::string& title, const Table& summary, const std::vector<Figure>& figures) {
        r.figures.insert(r.figures.end(), figures.begin(), figures.end());
        ReportSection s;
        s.heading = title;
        s.figures = figures;
        for (size_t t = written; t < r.tables.size(); ++t)
            s.tables.push_back({r.tables[t].first, r.tables[t].second, t == written});
        written = r.tables.size();
        r.report.sections.push_back(std::move(s));
        r.markdown += title + "\n" + summary.markdown() + "\n";
    };
    for (int k = 0; k < n; ++k) {
        const Progress part = progressPart(progress, k, n, enumName(kFrameAnalysisNames, o.analyses[size_t(k)]));
        switch (o.analyses[size_t(k)]) {
            case FrameAnalysis::Spectrum: {
                const SpectrumStudyResult s = spectrumStudy(source, spectrumOptions(o), part);
                r.tables.push_back({"spectrum.csv", s.summary});
                r.tables.push_back({"radial.csv", s.profile});
                add("Power spectrum (the first frame)", s.summary, s.figures);
                break;
            }
            case FrameAnalysis::Flow: {
                const FlowStudyResult f = flowStudy(source, flowOptions(o), part);
                r.tables.push_back({"flow.csv", f.summary});
                add("Optical flow (DIS) between consecutive frames", f.summary, f.figures);
                break;
            }
            case FrameAnalysis::Coherence: {
                const TemporalCoherenceResult c = temporalCoherenceStudy(source, coherenceOptions(o), part);
                r.tables.push_back({"coherence.csv", c.summary});
                r.tables.push_back({"coherence_frames.csv", c.perFrame});
                add("Temporal coherence of the frames", c.summary, c.figures);
                break;
            }
            case FrameAnalysis::Flicker:
            case FrameAnalysis::Statistics: {
                const bool flicker = o.analyses[size_t(k)] == FrameAnalysis::Flicker;
                const FlickerPairs pairs = flicker ? flickerPairs(source, o, 0, o.frames - 1, part) : FlickerPairs{};
                const Section s = flicker ? flickerSection(o, {&pairs, 1}) : statisticsSection(source, o, part);
                r.tables.insert(r.tables.end(), s.tables.begin(), s.tables.end());
                add(s.title, s.tables.front().second, s.figures);
                break;
            }
        }
    }
    return r;
}

}  // namespace stochtex
