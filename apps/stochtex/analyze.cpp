// stochtex analyze: one report page on the stationary zoom texture's
// artifacts — sliding, contrast loss and its corrections, correlation — with
// every image and table of the `zoom`, `contrast` and `correlation` studies.
#include <chrono>
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "zoom_flags.h"

namespace stochtex::cli {

void registerAnalyze(CLI::App& app) {
    auto args = std::make_shared<ZoomStudyArgs<ArtifactReportOptions>>();
    auto* cmd = app.add_subcommand("analyze", "Report page (index.html) on the zoom texture's artifacts: sliding, "
                                              "contrast loss and corrections, correlation plots");
    addOutputFolderFlag(*cmd, args->dir, "Output folder (index.html and the figures)");
    addCorrelationStudyFlags(*cmd, args->study.correlation, "--plot-size", false);
    cmd->add_option("--size", args->study.contrast.size, "Size of the contrast-correction textures")
        ->capture_default_str();
    addZoomStudyFlags(*cmd, *args, false);
    cmd->callback([args] {
        ThreadLimit limit(args->threads);
        const auto start = std::chrono::steady_clock::now();
        ArtifactReportOptions options = args->study;
        options.correlation.zoom = makeZoomParams(args->zoom);
        options.correlation.base = makeZoomBase(args->zoom);
        ProgressLine progress("analyze");
        writeArtifactReport(args->dir, options, progress.callback());
        progress.finish();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("wrote %s/index.html (%.1f s)\n", args->dir.c_str(), seconds);
    });
}

}  // namespace stochtex::cli
