// stochtex coherence: how much a texture's look moves from frame to frame —
// mean, contrast, dominant scale and radial spectrum per frame (thesis
// §2.1.1, Figures 2.4 and 2.16) — of image files, a pattern or the zoom
// texture; with --layers-list, the zoom texture's curve over n.
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/studies/temporal_coherence_study.h"
#include "texture_source_flags.h"

namespace stochtex::cli {

void registerCoherence(CLI::App& app) {
    struct Args {
        CoherenceReportOptions study;
        WindowSizeFlag window;
        int frames = 32;
        double step = 0.0625;
        std::string dir;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("coherence",
                                   "Temporal coherence: per-frame mean, contrast, dominant scale and "
                                   "spectrum, and their change over time: coherence [flags] "
                                   "images|pattern|zoom|marble|shadertoy ...");
    cmd->fallthrough();
    addOutputFolderFlag(*cmd, args->dir);
    addWindowSizeFlag(*cmd, args->window, "Frame size");
    const CLI::Option* frames =
        cmd->add_option("--frames", args->frames, "Frames, from the source's time on")->capture_default_str();
    const CLI::Option* step = cmd->add_option("--step", args->step, "Time between frames")->capture_default_str();
    const CLI::Option* layers =
        cmd->add_option("--layers-list", args->study.layers, "zoom: measure each layer count n (the curve over n)")
            ->delimiter(',');
    addMemberOption(*cmd, optionMember(temporalCoherenceMembers(), "radialBins"), args->study.frames);
    addThreadsFlag(*cmd, args->threads);
    addTextureSourceCommands(*cmd, [args, frames, step, layers](const TextureSource& source, const SourceInfo& info) {
        CoherenceReportOptions o = args->study;
        o.frames.frameTransfer = info.transfer;
        o.sourceName = info.name;
        const std::string onImages = "on image files (each file is a frame)";
        o.frames.region = studyRegion(args->window, info, onImages);
        for (const CLI::Option* f : {frames, step}) refuseWithoutEffect(f, !info.images, onImages);
        o.frames.times = info.images ? evenTimes(0, 1, info.frames) : evenTimes(info.time, args->step, args->frames);
        refuseWithoutEffect(layers, dynamic_cast<const ZoomSource*>(&source) != nullptr,
                            "without the zoom texture (n is its number of layers)");
        validateCoherenceReport(o, source);
        ThreadLimit limit(args->threads);
        ensureFolder(args->dir);
        ProgressLine progress("coherence");
        const CoherenceReport r = coherenceReport(source, o, progress.callback());
        progress.finish();
        if (r.layers) std::printf("%s", r.layers->table.markdown().c_str());
        const std::vector<std::string> files = writeReport(args->dir, r.report);
        std::printf("%s\nwrote %s to %s\n", r.frames.summary.markdown().c_str(), listNames(files).c_str(),
                    args->dir.c_str());
    });
}

}  // namespace stochtex::cli
