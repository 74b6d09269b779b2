#include "stochtex/studies/temporal_coherence_study.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/report/plot.h"

namespace stochtex {

std::span<const OptionMember<TemporalCoherenceOptions>> temporalCoherenceMembers() {
    using O = TemporalCoherenceOptions;
    static const OptionMember<O> members[] = {
        {"instance", "The source's instance", 0, 1000000, &O::instance},
        {"radialBins", "Bins of the radial spectra", 4, 4096, &O::radialBins},
    };
    return members;
}

void validateTemporalCoherence(const TemporalCoherenceOptions& o, const TextureSource* source) {
    const SourceRegion& r = o.region;
    if (r.width < 8 || r.height < 8 || r.width > 2048 || r.height > 2048)
        throw InputError::parameter(
            "size", "must be in [8, 2048] per side, got " + std::to_string(r.width) + "x" + std::to_string(r.height));
    if (o.times.size() < 2 || o.times.size() > 10000)
        throw InputError::parameter("frames", "must be in [2, 10000], got " + std::to_string(o.times.size()));
    for (double t : o.times)
        if (!std::isfinite(t)) throw InputError::parameter("time", "must be finite, got " + formatValue(t));
    checkMembers(o, temporalCoherenceMembers());
    if (source) {
        for (double t : o.times) source->checkWindow(o.region, t);
        source->checkInstances(o.instance + 1);
    }
}

std::vector<double> evenTimes(double start, double step, int count) {
    std::vector<double> t;
    for (int k = 0; k < count; ++k) t.push_back(start + step * k);
    return t;
}

namespace {

// The frame shown i-th of `keep` spread over n frames.
size_t shownFrame(size_t i, size_t keep, size_t n) { return i * (n - 1) / (keep - 1); }

TemporalCoherence measure(const TextureSource& source, const TemporalCoherenceOptions& o, const StudyProgress& progress,
                          std::vector<Image>* kept, std::vector<size_t>* keptIndex, size_t keep) {
    TemporalCoherenceMeter meter(o.radialBins, o.window);
    const size_t n = o.times.size();
    for (size_t k = 0; k < n; ++k) {
        if (progress) progress(double(k) / double(n), "frame " + std::to_string(k + 1) + "/" + std::to_string(n));
        Image frame = source.render(o.region, o.times[k], o.instance);
        meter.add(frame, o.times[k]);
        // A few frames evenly spread over the sequence, for the figure.
        if (kept && keep > 1)
            for (size_t i = 0; i < keep; ++i)
                if (shownFrame(i, keep, n) == k) {
                    kept->push_back(std::move(frame));
                    keptIndex->push_back(k);
                    break;
                }
    }
    return meter.result();
}

void addCoherenceColumns(Table& t) {
    t.columns.insert(t.columns.end(), {{"mean_change", "|Δ mean|", ""},
                                       {"contrast_change", "|Δ contrast| / contrast", ""},
                                       {"scale_change", "|Δ scale| / scale", ""},
                                       {"spectrum_change", "|Δ log₁₀ P|", "decades"},
                                       {"scale_variation", "scale σ/μ over time", ""},
                                       {"contrast_variation", "contrast σ/μ over time", ""}});
}

std::vector<TableCell> coherenceCells(const TemporalCoherence& c) {
    return {TableCell::value(c.meanChange, "%.5f"),     TableCell::value(c.contrastChange, "%.5f"),
            TableCell::value(c.scaleChange, "%.5f"),    TableCell::value(c.spectrumChange, "%.5f"),
            TableCell::value(c.scaleVariation, "%.5f"), TableCell::value(c.contrastVariation, "%.5f")};
}

}  // namespace

TemporalCoherenceResult temporalCoherenceStudy(const TextureSource& source, const TemporalCoherenceOptions& o,
                                               const StudyProgress& progress) {
    validateTemporalCoherence(o, &source);
    TemporalCoherenceResult r;
    std::vector<Image> shown;
    std::vector<size_t> shownIndex;
    r.coherence = measure(source, o, progress, &shown, &shownIndex, 4);
    const TemporalCoherence& c = r.coherence;
    r.summary.columns = {{"frames", "frames", ""}};
    addCoherenceColumns(r.summary);
    std::vector<TableCell> row{TableCell::integer((long long)c.frames.size())};
    for (TableCell& cell : coherenceCells(c)) row.push_back(std::move(cell));
    r.summary.add(std::move(row));
    r.perFrame.columns = {{"time", "t", ""},
                          {"mean", "mean", ""},
                          {"contrast", "contrast σ", ""},
                          {"mean_frequency", "dominant scale: mean |f|", "cycles/pixel"}};
    PlotSeries contrast{"contrast σ / mean σ", {}, {}, seriesColour(0)},
        scale{"mean |f| / its mean (dominant scale)", {}, {}, seriesColour(1)};
    for (const FrameAppearance& f : c.frames) {
        r.perFrame.add({TableCell::value(f.time, "%g"), TableCell::value(f.mean, "%.5f"),
                        TableCell::value(f.contrast, "%.5f"), TableCell::value(f.meanFrequency, "%.5f")});
        contrast.x.push_back(f.time);
        contrast.y.push_back(c.meanContrast > 0 ? f.contrast / c.meanContrast : 0.0);
        scale.x.push_back(f.time);
        scale.y.push_back(c.meanFrequency > 0 ? f.meanFrequency / c.meanFrequency : 0.0);
    }
    LinePlotOptions po;
    po.title = "Appearance over time (1 = the sequence's mean)";
    po.xLabel = "time t";
    po.yLabel = "relative to the mean over time";
    r.figures.push_back(
        chartFigure("appearance.png", {{contrast, scale}, po},
                    "Contrast and dominant scale of each frame relative to their means over the sequence: flat "
                    "lines are a coherent animation (thesis §2.1.1). Scale σ/μ over time " +
                        TableCell::value(c.scaleVariation, "%.4f").text + ", contrast σ/μ " +
                        TableCell::value(c.contrastVariation, "%.4f").text + "."));
    // Frames beside their spectra, as Figure 2.4.
    std::vector<std::vector<Image>> rows(2);
    std::vector<std::vector<std::string>> captions(2);
    for (const Image& f : shown) {
        const Image gray = f.channels() == 1 ? f : toGray(f);
        rows[0].push_back(encodeTransfer(f, o.frameTransfer));
        rows[1].push_back(logSpectrumImage(centredPowerSpectrum(gray, o.window)));
    }
    for (size_t i = 0; i < shown.size(); ++i) {
        const size_t k = shownIndex[i];
        captions[0].push_back("t = " + TableCell::value(c.frames[k].time, "%g").text);
        captions[1].push_back("spectrum, mean |f| = " + TableCell::value(c.frames[k].meanFrequency, "%.4f").text);
    }
    r.figures.push_back({"frames.png", sheet(rows, captions),
                         "Frames across the sequence and their power spectra (log scale over 4 decades, zero "
                         "frequency at the centre), as the thesis's Figure 2.4."});
    return r;
}

void validateLayerCoherence(const LayerCoherenceOptions& o) {
    validateTemporalCoherence(o.frames);
    if (o.layers.empty()) throw InputError::parameter("layersList", "must name at least one layer count");
    for (int n : o.layers)
        if (n < 1 || n > 64)
            throw InputError::parameter("layersList", "must be in [1, 64] each, got " + std::to_string(n));
}

LayerCoherenceResult layerCoherenceStudy(const ZoomSource& zoom, const LayerCoherenceOptions& o,
                                         const StudyProgress& progress) {
    validateLayerCoherence(o);
    LayerCoherenceResult r;
    r.table.columns = {{"layers", "n", ""}};
    addCoherenceColumns(r.table);
    PlotSeries scale{"dominant scale σ/μ over time", {}, {}, seriesColour(1)},
        contrast{"contrast σ/μ over time", {}, {}, seriesColour(0)},
        spectrum{"|Δ log₁₀ P| between frames (decades)", {}, {}, seriesColour(2)};
    for (size_t i = 0; i < o.layers.size(); ++i) {
        ZoomParams params = zoom.params();
        params.layers = o.layers[i];
        const ZoomSource source(params, zoom.base());
        const Progress part =
            progressPart(progress, int(i), int(o.layers.size()), "n = " + std::to_string(params.layers));
        r.perLayers.push_back(measure(source, o.frames, part, nullptr, nullptr, 0));
        const TemporalCoherence& c = r.perLayers.back();
        std::vector<TableCell> row{TableCell::integer(params.layers)};
        for (TableCell& cell : coherenceCells(c)) row.push_back(std::move(cell));
        r.table.add(std::move(row));
        scale.x.push_back(params.layers);
        scale.y.push_back(c.scaleVariation);
        contrast.x.push_back(params.layers);
        contrast.y.push_back(c.contrastVariation);
        spectrum.x.push_back(params.layers);
        spectrum.y.push_back(c.spectrumChange);
    }
    LinePlotOptions po;
    po.title = "Temporal coherence of the zoom texture over the number of layers n";
    po.xLabel = "layers n";
    po.yLabel = "variation over time";
    po.yMin = 0;
    r.figures.push_back(
        chartFigure("layers.png", {{scale, contrast, spectrum}, po},
                    "How much the zoom texture's look moves over time for each layer count n (" +
                        std::to_string(o.frames.times.size()) + " frames of " + std::to_string(o.frames.region.width) +
                        "×" + std::to_string(o.frames.region.height) +
                        "): the thesis sees n = 3 lose coherence (frames lose their high frequencies) where "
                        "n = 8 keeps it (Figure 2.4)."));
    return r;
}

void validateCoherenceReport(const CoherenceReportOptions& o, const TextureSource& source) {
    validateTemporalCoherence(o.frames, &source);
    if (o.layers.empty()) return;
    if (!dynamic_cast<const ZoomSource*>(&source))
        throw InputError::parameter("layersList", "needs the zoom texture (n is its number of layers)");
    validateLayerCoherence({o.layers, o.frames});
}

CoherenceReport coherenceReport(const TextureSource& source, const CoherenceReportOptions& o,
                                const StudyProgress& progress) {
    validateCoherenceReport(o, source);
    CoherenceReport r;
    r.frames = temporalCoherenceStudy(source, o.frames, progress);
    r.report.title = "Temporal coherence: " + o.sourceName;
    ReportSection frames;
    frames.tables = {{"coherence.csv", r.frames.summary}, {"frames.csv", r.frames.perFrame, false}};
    frames.figures = r.frames.figures;
    r.report.sections.push_back(std::move(frames));
    if (o.layers.empty()) return r;
    r.layers = layerCoherenceStudy(dynamic_cast<const ZoomSource&>(source), {o.layers, o.frames}, progress);
    ReportSection layers;
    layers.heading = "Over the number of layers n (thesis Figure 2.4)";
    layers.tables = {{"layers.csv", r.layers->table}};
    layers.figures = r.layers->figures;
    r.report.sections.push_back(std::move(layers));
    return r;
}

}  // namespace stochtex
