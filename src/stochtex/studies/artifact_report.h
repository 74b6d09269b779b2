#pragma once
// The report page of the thesis's studies (`stochtex analyze`): the zoom
// texture's studies (zoom_studies.h), its frame analyses, the image bases,
// the marble texture and the perception stimuli, in one page.
#include <span>
#include <string>
#include <vector>

#include "stochtex/pattern/param_info.h"
#include "stochtex/studies/image_base_study.h"
#include "stochtex/studies/marble_study.h"
#include "stochtex/studies/stimuli.h"
#include "stochtex/studies/zoom_studies.h"

namespace stochtex {

// --- the report page of the three studies (`stochtex analyze`) ---

struct ArtifactReportOptions {
    CorrelationStudyOptions correlation;  // its zoom texture and base feed every part
    ContrastStudyOptions contrast;
    int contrastLayers = 16;  // n of the contrast part (Figure 2.6 uses 16)
    // The frame analyses of the zoom texture (spectrum over instances,
    // optical flow, temporal coherence and its curve over n), on frames of
    // frameSize² centred on the zoom centre.
    // The numbers' ranges: artifactReportMembers().
    int frameSize = 256;
    int spectrumInstances = 16;
    std::vector<int> coherenceLayers{2, 3, 4, 6, 8, 12};  // each [1, 64]
    int coherenceFrames = 32;
    // Image textures as the base (Figures 2.15–2.17; none: the part is left out).
    std::vector<ImageBase> imageBases;
    ImageBaseStudyOptions imageBase;
    // The marble texture (§2.7.2, 2.8; Figures 2.19–2.24) and the perception
    // stimuli (§2.6.2; Figures 2.13–2.14, with the experiment page).
    MarbleStudyOptions marble;
    StimulusSetOptions stimuli;
};
// The entries of ArtifactReportOptions' own numbers (its check; the CLI's flags).
std::span<const OptionMember<ArtifactReportOptions>> artifactReportMembers();
// The options with the parts that follow the others set from them: the
// image-base part on the correlation's zoom texture with 8 layers (Figure
// 2.17) and its instance count; the marble at frameSize (its correlation
// window 3/8 of it, its flow step 1/16) and the same instance count. Each
// within its own entry's range: a frame size or an instance count past a
// part's range sets that part at its end.
ArtifactReportOptions withDerivedParts(ArtifactReportOptions options);
// InputError for unusable settings, before any work.
void validateArtifactReport(const ArtifactReportOptions& options);
// Runs sliding, contrast, correlation, spectrum, flow, temporal coherence,
// the image bases, the marble texture and the stimuli and returns their
// report: each part's files in its folder (zoom, contrast, correlation,
// spectrum, flow, coherence, images, marble, stimuli with experiment.html),
// one page with every figure and table, each section naming the thesis
// figure it reproduces. marbleFrames receives the marble's sliding
// sequences (marbleVideoNames), which the caller writes as videos into
// marble/; the page then shows them. No wall-clock time is in the report,
// so two runs write identical files.
Report artifactReport(const ArtifactReportOptions& options, const StudyProgress& progress = {},
                      const MarbleFrameSink& marbleFrames = {});

}  // namespace stochtex
