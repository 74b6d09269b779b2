#include "stochtex/studies/artifact_report.h"

// The report page of the procedural textures' artifacts (`stochtex
// analyze`): the zoom texture's sliding, contrast, correlation, spectrum,
// flow and coherence, the image bases, the marble texture and the stimuli
// on one page, each part's files written as soon as the part is done.
#include <algorithm>
#include <string>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/report/frame_sequence.h"
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

void validateArtifactReport(const ArtifactReportOptions& options) {
    validateCorrelationStudy(options.correlation);
    validateContrastStudy(options.contrast);
    validateZoomParams(contrastZoom(options));
    if (options.frameSize < 16 || options.frameSize > 2048)
        throw InputError::parameter("frameSize", "must be in [16, 2048], got " + std::to_string(options.frameSize));
    validateSpectrumStudy(spectrumOptions(options));
    validateFlowStudy(flowOptions(options));
    const LayerCoherenceOptions c = coherenceOptions(options);
    validateTemporalCoherence(c.frames);
    if (c.layers.empty()) throw InputError::parameter("coherenceLayers", "must name at least one layer count");
    for (int n : c.layers)
        if (n < 1 || n > 64)
            throw InputError::parameter("coherenceLayers", "must hold layer counts in [1, 64], got " + std::to_string(n));
    if (!options.imageBases.empty()) validateImageBaseStudy(options.imageBase, options.imageBases);
    validateMarbleStudy(options.marble);
    validateStimulusSet(options.stimuli);
}

void writeArtifactReport(const std::string& dir, const ArtifactReportOptions& options, const StudyProgress& progress) {
    validateArtifactReport(options);
    const CorrelationStudyOptions& correlation = options.correlation;
    // Three parts; the correlation plots (many instances) take most of the time.
    const Progress zoomPart = progressPart(progress, 0.0, 0.05, "zoom frames and layer scales");
    const Progress contrastPart = progressPart(progress, 0.05, 0.15, "contrast corrections");
    const Progress framePart = progressPart(progress, 0.6, 0.85, "spectrum, flow, temporal coherence");
    if (zoomPart) zoomPart(0.0, "");
    const std::vector<Figure> zoom = slidingStudy(correlation.zoom, correlation.base);
    ensureFolder(dir + "/zoom");
    writeFigures(dir + "/zoom", zoom);

    if (contrastPart) contrastPart(0.0, "");
    const ContrastStudyResult contrast =
        writeZoomContrastStudy(contrastZoom(options), correlation.base, options.contrast, dir + "/contrast");

    const CorrelationStudyResult corr = correlationStudy(correlation, progressPart(progress, 0.15, 0.6));
    ensureFolder(dir + "/correlation");
    writeFigures(dir + "/correlation", corr.figures);
    writeText(dir + "/correlation", "correlation.csv", corr.table.csv());

    // The frame analyses of the zoom texture (thesis §2.1.1, 2.7, 2.8).
    const ZoomSource source(correlation.zoom, correlation.base);
    const SpectrumStudyResult spectrum = spectrumStudy(source, spectrumOptions(options), progressPart(framePart, 0.0, 0.2, "spectrum"));
    ensureFolder(dir + "/spectrum");
    writeFigures(dir + "/spectrum", spectrum.figures);
    writeText(dir + "/spectrum", "spectrum.csv", spectrum.summary.csv());
    const FlowStudyResult flow = flowStudy(source, flowOptions(options), progressPart(framePart, 0.2, 0.4, "optical flow"));
    ensureFolder(dir + "/flow");
    writeFigures(dir + "/flow", flow.figures);
    writeText(dir + "/flow", "flow.csv", flow.summary.csv());
    const LayerCoherenceOptions coherenceRun = coherenceOptions(options);
    const TemporalCoherenceResult coherence = temporalCoherenceStudy(source, coherenceRun.frames, progressPart(framePart, 0.4, 0.55, "temporal coherence"));
    const LayerCoherenceResult layers = layerCoherenceStudy(source, coherenceRun, progressPart(framePart, 0.55, 1.0, "coherence over n"));
    ensureFolder(dir + "/coherence");
    writeFigures(dir + "/coherence", coherence.figures);
    writeFigures(dir + "/coherence", layers.figures);
    writeText(dir + "/coherence", "coherence.csv", coherence.summary.csv());
    writeText(dir + "/coherence", "layers.csv", layers.table.csv());

    std::string imageSection;
    if (!options.imageBases.empty()) {
        const ImageBaseStudyResult images = imageBaseStudy(options.imageBases, options.imageBase);
        ensureFolder(dir + "/images");
        writeFigures(dir + "/images", images.figures);
        writeText(dir + "/images", "fractalize.csv", images.table.csv());
        imageSection = "<h2>Image textures as the base (section 2.7.1, Figures 2.15 and 2.17)</h2>\n<p>Each image's "
                       "correlation with a point over its periodic translations, then the zoom texture over it "
                       "without and with hashed offsets: regular structures echo (ghosting).</p>" +
                       images.table.html() + htmlFigures("images/", images.figures);
    }

    // The marble texture, with a video of each sliding sequence.
    ensureFolder(dir + "/marble");
    FrameSequenceSet videos(dir + "/marble", marbleVideoNames(options.marble), options.marble.size, options.marble.size,
                            {true, false, std::min(30.0, 1.0 / options.marble.timeStep), Transfer::Linear});
    const MarbleStudyResult marble =
        marbleStudy(options.marble, progressPart(progress, 0.85, 0.97, "marble"),
                    [&](size_t v, int k, const Image& frame) { videos.write(v, k, frame); });
    videos.finish();
    writeFigures(dir + "/marble", marble.figures);
    writeText(dir + "/marble", "correlation.csv", marble.correlation.csv());
    writeText(dir + "/marble", "spectra.csv", marble.spectra.csv());
    writeText(dir + "/marble", "sliding.csv", marble.sliding.csv());

    // The perception stimuli: an overview and the experiment page.
    if (progress) progress(0.97, "stimuli");
    const StimulusOverview stimuli = stimulusOverview(options.stimuli);
    const StimulusSet set = stimulusSet(options.stimuli);
    ensureFolder(dir + "/stimuli");
    writeFigures(dir + "/stimuli", {stimuli.sheet});
    writeText(dir + "/stimuli", "overview.csv", stimuli.table.csv());
    writeText(dir + "/stimuli", "experiment.html", set.page);

    // The plots of each variant at the first layer count.
    const std::string firstLayers = std::to_string(correlation.layers.front());
    std::vector<Figure> firstN;
    for (const auto& f : corr.figures)
        if (f.file.find("_n" + firstLayers + "_") != std::string::npos) firstN.push_back(f);
    const std::string body =
        "<h1>Stationary zoom texture: artifacts and fixes</h1><p>I(x) = &Sigma;<sub>i</sub> A(a<sub>i</sub>) "
        "g(a<sub>i</sub> x + o<sub>i</sub>) (Tavernier 2017, eq. 2.1) over a white-noise lattice; statistics are "
        "over the space of lattice realisations. Generated by <code>stochtex analyze</code>.</p>\n"
        "<h2>Sliding (section 2.2)</h2>\n" + htmlFigures("zoom/", zoom) +
        "<h2>Contrast loss and its corrections (section 2.4)</h2>\n<p>Var I(x) = &sigma;<sub>f</sub>&sup2; "
        "&alpha;(x, x) &lt; &sigma;<sub>f</sub>&sup2;: the blend loses contrast. Each correction uses the "
        "per-pixel analytic variance (n = " + std::to_string(options.contrastLayers) + ").</p>" +
        contrast.table.html() + htmlFigures("contrast/", contrast.figures) +
        "<h2>Correlation (section 2.5)</h2>\n<p>Mean |analytic &minus; measured| over the plots, and the largest "
        "analytic correlation away from the diagonal band |x &minus; y| &le; 4 (the interpolation kernel's own "
        "correlation). Hashed (random) offsets remove the echoes.</p>" +
        corr.table.html() + htmlFigures("correlation/", corr.figures, 1) + "<h3>Each variant at n = " + firstLayers +
        "</h3>\n" + htmlFigures("correlation/", firstN) +
        "<p>All plots for every n are in <a href='correlation/'>correlation/</a> (<a "
        "href='correlation/correlation.csv'>correlation.csv</a>).</p>" +
        "<h2>Power spectrum (section 2.1.1, Figures 2.4 and 2.22)</h2>\n<p>The mean periodogram of " +
        std::to_string(options.spectrumInstances) + " instances of the zoom texture (n = " +
        std::to_string(correlation.zoom.layers) + "): flat like white noise where the layers keep the noise's scale.</p>" +
        spectrum.summary.html() + htmlFigures("spectrum/", spectrum.figures) +
        "<h2>Optical flow (section 2.8, Figure 2.25)</h2>\n<p>Farnebäck's dense flow between consecutive frames "
        "(1/30 apart): the zoom texture's motion is an outward expansion about the zoom centre, whatever its "
        "other artifacts (the thesis's remark on Figure 2.25).</p>" +
        flow.summary.html() + htmlFigures("flow/", flow.figures) +
        "<h2>Temporal coherence (section 2.1.1, Figures 2.4 and 2.16)</h2>\n<p>Per frame: mean, contrast, "
        "dominant scale (the spectrum's power-weighted mean |f|) and radial spectrum, over " +
        std::to_string(options.coherenceFrames) + " frames of two zoom periods; then the same for each layer "
        "count n: too few layers lose coherence.</p>" +
        coherence.summary.html() + htmlFigures("coherence/", coherence.figures) + layers.table.html() +
        htmlFigures("coherence/", layers.figures) + imageSection +
        "<h2>The marble texture (sections 2.7.2 and 2.8, Figures 1.6, 2.19–2.24)</h2>\n<p>I(x) = pattern(a&middot;x + "
        "b noise(x / 2<sup>l</sup>)) (eq. 2.29) over a gradient noise, with the noise scale's exponent l varying "
        "in space (stretching) or in time (sliding); the continuous scaling against the fix by blended integer "
        "scales. Files in <a href='marble/'>marble/</a>.</p>\n" + marbleSectionHtml(marble, "marble/", true) +
        "<h2>Perception stimuli (section 2.6.2, Figures 2.13–2.14)</h2>\n<p>Tiled white noise whose tiles correlate "
        "by a chosen amount; the experiment shows each for " + std::to_string(options.stimuli.durationMs) +
        " ms and asks whether a repeating pattern was seen: open <a href='stimuli/experiment.html'>"
        "stimuli/experiment.html</a> in a browser and turn its answers into detection rates with the "
        "stimuli command's analysis (docs/EXPERIMENT.md).</p>\n" + stimuli.table.html() + htmlFigures("stimuli/", {stimuli.sheet});
    writeText(dir, "index.html", htmlPage("stochtex: zoom texture artifacts", body));
}

}  // namespace stochtex
