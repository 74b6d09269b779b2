// stochtex analyze: one report page on the artifacts of procedural textures
// — the zoom texture's sliding, contrast loss and its corrections,
// correlation, spectrum, optical flow and temporal coherence, image bases,
// the marble texture and the perception stimuli — with every image and table
// of the `zoom`, `contrast`, `correlation`, `spectrum`, `flow`, `coherence`,
// `fractalize`, `marble` and `stimuli` studies.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/frame_sequence.h"
#include "stochtex/studies/artifact_report.h"
#include "zoom_flags.h"

namespace stochtex::cli {

void registerAnalyze(CLI::App& app) {
    auto args = std::make_shared<ZoomStudyArgs<ArtifactReportOptions>>();
    auto* cmd = app.add_subcommand("analyze",
                                   "Report page (index.html) on the zoom texture's artifacts: sliding, "
                                   "contrast loss and corrections, correlation plots, spectrum, optical "
                                   "flow, temporal coherence, the marble texture, perception stimuli");
    addOutputFolderFlag(*cmd, args->dir, "Output folder (index.html and the figures)");
    addCorrelationStudyFlags(*cmd, args->study.correlation, "--plot-size", false);
    addParameterOptions(*cmd, contrastStudyMembers(), args->study.contrast);
    addMemberOption(*cmd, optionMember(artifactReportMembers(), "frameSize"), args->study);
    cmd->add_option("--coherence-layers", args->study.coherenceLayers, "Layer counts n of the temporal-coherence curve")
        ->delimiter(',');
    auto images = std::make_shared<std::vector<std::string>>();
    cmd->add_option("--images", *images,
                    "Image textures for the image-base part (Figures 2.15, 2.17; e.g. "
                    "data/textures/*.png)");
    addZoomStudyFlags(*cmd, *args, false);
    cmd->callback([args, images] {
        ThreadLimit limit(args->threads);
        const auto start = std::chrono::steady_clock::now();
        ArtifactReportOptions options = args->study;
        options.correlation.zoom = makeZoomParams(args->zoom);
        options.correlation.base = makeZoomBase(args->zoom);
        for (const std::string& f : *images) options.imageBases.push_back({f, readImage(f)});
        options = withDerivedParts(std::move(options));
        validateArtifactReport(options);
        ensureFolder(args->dir + "/marble");
        FrameSequenceSet videos(args->dir + "/marble", marbleVideoNames(options.marble), options.marble.size,
                                options.marble.size,
                                {true, false, std::min(30.0, 1.0 / options.marble.timeStep), Transfer::Linear});
        ProgressLine progress("analyze");
        const Report report = artifactReport(options, progress.callback(),
                                             [&](size_t v, int k, const Image& frame) { videos.write(v, k, frame); });
        videos.finish();
        progress.finish();
        writeReport(args->dir, report);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("wrote %s/index.html (%.1f s)\n", args->dir.c_str(), seconds);
    });
}

}  // namespace stochtex::cli
