#include "stochtex/studies/artifact_report.h"

// The report page of the procedural textures' artifacts (`stochtex
// analyze`): the zoom texture's sliding, contrast, correlation, spectrum,
// flow and coherence, the image bases, the marble texture and the stimuli
// on one page, each part's files written as soon as the part is done.
#include <algorithm>
#include <string>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/studies/flow_study.h"
#include "stochtex/studies/spectrum_study.h"
#include "stochtex/studies/temporal_coherence_study.h"
#include "stochtex/studies/zoom_studies.h"
#include "stochtex/textures/zoom_texture.h"

namespace stochtex {

namespace {

ZoomParams contrastZoom(const ArtifactReportOptions& options) {
    ZoomParams p = options.correlation.zoom;
    p.layers = options.contrastLayers;
    return p;
}

SpectrumStudyOptions spectrumOptions(const ArtifactReportOptions& o) {
    SpectrumStudyOptions s;
    s.region = SourceRegion::centred(o.frameSize, o.frameSize);
    s.times = {o.correlation.zoom.time};
    s.instances = o.spectrumInstances;
    return s;
}

FlowStudyOptions flowOptions(const ArtifactReportOptions& o) {
    FlowStudyOptions f;
    f.region = SourceRegion::centred(o.frameSize, o.frameSize);
    f.time = o.correlation.zoom.time;
    f.frames = 3;
    f.step = std::max(8, o.frameSize / 16);
    f.margin = f.step;
    return f;
}

LayerCoherenceOptions coherenceOptions(const ArtifactReportOptions& o) {
    LayerCoherenceOptions c;
    c.layers = o.coherenceLayers;
    c.frames.region = SourceRegion::centred(o.frameSize, o.frameSize);
    c.frames.times = evenTimes(o.correlation.zoom.time, 2.0 / o.coherenceFrames, o.coherenceFrames);
    return c;
}

}  // namespace

std::span<const OptionMember<ArtifactReportOptions>> artifactReportMembers() {
    using O = ArtifactReportOptions;
    static const OptionMember<O> members[] = {
        {"frameSize", "Frame side of the spectrum, flow and coherence parts", 32, 2048, &O::frameSize},
        {"spectrumInstances", "Instances averaged by the spectrum part", 1, 100000, &O::spectrumInstances},
        {"coherenceFrames", "Frames of the temporal-coherence part, over two periods of the zoom", 2, 10000,
         &O::coherenceFrames},
    };
    return members;
}

ArtifactReportOptions withDerivedParts(ArtifactReportOptions o) {
    const auto within = [](int v, const auto& members, const char* name) {
        const ParamInfo& p = optionMember(members, name).info;
        return std::clamp(v, int(p.min), int(p.max));
    };
    o.imageBase.zoom = o.correlation.zoom;
    o.imageBase.zoom.layers = 8;  // Figure 2.17
    o.imageBase.instances = within(o.correlation.instances, imageBaseStudyMembers(), "instances");
    const auto& marble = marbleStudyMembers();
    o.marble.size = within(o.frameSize, marble, "size");
    o.marble.correlationSize = within(o.marble.size * 3 / 8, marble, "correlationSize");
    o.marble.instances = within(o.correlation.instances, marble, "instances");
    o.marble.flowStep = within(o.marble.size / 16, marble, "flowStep");
    return o;
}

void validateArtifactReport(const ArtifactReportOptions& options) {
    validateCorrelationStudy(options.correlation);
    validateContrastStudy(options.contrast);
    validateZoomParams(contrastZoom(options));
    checkMembers(options, artifactReportMembers());
    validateSpectrumStudy(spectrumOptions(options));
    validateFlowStudy(flowOptions(options));
    const LayerCoherenceOptions c = coherenceOptions(options);
    validateTemporalCoherence(c.frames);
    if (c.layers.empty()) throw InputError::parameter("coherenceLayers", "must name at least one layer count");
    for (int n : c.layers)
        if (n < 1 || n > 64)
            throw InputError::parameter("coherenceLayers",
                                        "must hold layer counts in [1, 64], got " + std::to_string(n));
    if (!options.imageBases.empty()) validateImageBaseStudy(options.imageBase, options.imageBases);
    validateMarbleStudy(options.marble);
    validateStimulusSet(options.stimuli);
}

Report artifactReport(const ArtifactReportOptions& options, const StudyProgress& progress,
                      const MarbleFrameSink& marbleFrames) {
    validateArtifactReport(options);
    const CorrelationStudyOptions& correlation = options.correlation;
    // Three parts; the correlation plots (many instances) take most of the time.
    const Progress zoomPart = progressPart(progress, 0.0, 0.05, "zoom frames and layer scales");
    const Progress contrastPart = progressPart(progress, 0.05, 0.15, "contrast corrections");
    const Progress framePart = progressPart(progress, 0.6, 0.85, "spectrum, flow, temporal coherence");
    Report report;
    report.title = "Stationary zoom texture: artifacts and fixes";
    report.html =
        "<p>I(x) = &Sigma;<sub>i</sub> A(a<sub>i</sub>) g(a<sub>i</sub> x + o<sub>i</sub>) (Tavernier 2017, "
        "eq. 2.1) over a white-noise lattice; statistics are over the space of lattice realisations. "
        "Generated by <code>stochtex analyze</code>.</p>";
    if (zoomPart) zoomPart(0.0, "");
    appendReport(report, slidingReport(slidingStudy(correlation.zoom, correlation.base)), "zoom");

    if (contrastPart) contrastPart(0.0, "");
    const ContrastStudyResult contrast = zoomContrastStudy(contrastZoom(options), correlation.base, options.contrast);
    appendReport(report, contrastReport(contrast, options.contrastLayers), "contrast");

    const CorrelationStudyResult corr = correlationStudy(correlation, progressPart(progress, 0.15, 0.6));
    appendReport(report, correlationReport(corr, correlation), "correlation");

    // The frame analyses of the zoom texture (thesis §2.1.1, 2.7, 2.8).
    const ZoomSource source(correlation.zoom, correlation.base);
    const SpectrumStudyResult spectrum =
        spectrumStudy(source, spectrumOptions(options), progressPart(framePart, 0.0, 0.2, "spectrum"));
    appendReport(report, spectrumReport(spectrum, "the zoom texture"), "spectrum",
                 "Power spectrum (section 2.1.1, Figures 2.4 and 2.22)",
                 "<p>The mean periodogram of " + std::to_string(options.spectrumInstances) +
                     " instances of the zoom texture (n = " + std::to_string(correlation.zoom.layers) +
                     "): flat like white noise where the layers keep the noise's scale.</p>");
    const FlowStudyResult flow =
        flowStudy(source, flowOptions(options), progressPart(framePart, 0.2, 0.4, "optical flow"));
    appendReport(report, flowReport(flow, "the zoom texture"), "flow", "Optical flow (section 2.8, Figure 2.25)",
                 "<p>Farnebäck's dense flow between consecutive frames (1/30 apart): the zoom texture's motion is an "
                 "outward expansion about the zoom centre, whatever its other artifacts (the thesis's remark on "
                 "Figure 2.25).</p>");
    CoherenceReportOptions coherence;
    const LayerCoherenceOptions coherenceRun = coherenceOptions(options);
    coherence.frames = coherenceRun.frames;
    coherence.layers = coherenceRun.layers;
    coherence.sourceName = "the zoom texture";
    const CoherenceReport coherent =
        coherenceReport(source, coherence, progressPart(framePart, 0.4, 1.0, "temporal coherence"));
    appendReport(report, coherent.report, "coherence", "Temporal coherence (section 2.1.1, Figures 2.4 and 2.16)",
                 "<p>Per frame: mean, contrast, dominant scale (the spectrum's power-weighted mean |f|) and radial "
                 "spectrum, over " +
                     std::to_string(options.coherenceFrames) +
                     " frames of two zoom periods; then the same for each layer count n: too few layers lose "
                     "coherence.</p>");

    if (!options.imageBases.empty())
        appendReport(report, imageBaseReport(imageBaseStudy(options.imageBases, options.imageBase)), "images");

    // The marble texture, its sliding sequences as videos where the caller writes them.
    const MarbleStudyResult marble =
        marbleStudy(options.marble, progressPart(progress, 0.85, 0.97, "marble"), marbleFrames);
    appendReport(report, marbleReport(marble, bool(marbleFrames)), "marble",
                 "The marble texture (sections 2.7.2 and 2.8, Figures 1.6, 2.19–2.24)",
                 "<p>I(x) = pattern(a&middot;x + b noise(x / 2<sup>l</sup>)) (eq. 2.29) over a gradient noise, with "
                 "the noise scale's exponent l varying in space (stretching) or in time (sliding); the continuous "
                 "scaling against the fix by blended integer scales.</p>");

    // The perception stimuli: an overview and the experiment page.
    if (progress) progress(0.97, "stimuli");
    appendReport(report, stimulusOverviewReport(stimulusOverview(options.stimuli), stimulusSet(options.stimuli)),
                 "stimuli", "Perception stimuli (section 2.6.2, Figures 2.13–2.14)",
                 "<p>Tiled white noise whose tiles correlate by a chosen amount; the experiment shows each for " +
                     std::to_string(options.stimuli.durationMs) +
                     " ms and asks whether a repeating pattern was seen: open <a href='stimuli/experiment.html'>"
                     "stimuli/experiment.html</a> in a browser and turn its answers into detection rates with the "
                     "stimuli command's analysis (docs/EXPERIMENT.md).</p>");
    return report;
}

}  // namespace stochtex
