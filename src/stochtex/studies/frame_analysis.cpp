#include "stochtex/studies/frame_analysis.h"

#include <algorithm>

#include "stochtex/core/error.h"
#include "stochtex/studies/flow_study.h"
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

}  // namespace

void validateFrameAnalysis(const FrameAnalysisOptions& o, const TextureSource* source) {
    if (o.analyses.empty()) throw InputError::parameter("analyses", "must name at least one of spectrum, flow, coherence");
    for (size_t k = 0; k < o.analyses.size(); ++k)
        if (std::count(o.analyses.begin(), o.analyses.end(), o.analyses[k]) > 1)
            throw InputError::parameter("analyses", "names " + enumName(kFrameAnalysisNames, o.analyses[k]) + " twice");
    if (has(o, FrameAnalysis::Spectrum)) validateSpectrumStudy(spectrumOptions(o), source);
    if (has(o, FrameAnalysis::Flow)) validateFlowStudy(flowOptions(o), source);
    if (has(o, FrameAnalysis::Coherence)) validateTemporalCoherence(coherenceOptions(o), source);
}

FrameAnalysisResult frameAnalysis(const TextureSource& source, const FrameAnalysisOptions& o, const StudyProgress& progress) {
    validateFrameAnalysis(o, &source);
    FrameAnalysisResult r;
    const int n = int(o.analyses.size());
    const auto add = [&](const std::string& title, const Table& summary, const std::vector<Figure>& figures) {
        r.figures.insert(r.figures.end(), figures.begin(), figures.end());
        r.html += "<h2>" + htmlEscape(title) + "</h2>" + summary.html() + htmlFigures("", figures);
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
        }
    }
    return r;
}

}  // namespace stochtex
