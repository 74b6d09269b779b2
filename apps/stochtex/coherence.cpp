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
        TemporalCoherenceOptions study;
        std::vector<int> size{256}, layers;
        int frames = 32;
        double step = 0.0625;
        std::string dir;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("coherence", "Temporal coherence: per-frame mean, contrast, dominant scale and "
                                                "spectrum, and their change over time: coherence [flags] "
                                                "images|pattern|zoom|marble ...");
    cmd->fallthrough();
    addOutputFolderFlag(*cmd, args->dir);
    const CLI::Option* size = cmd->add_option("--size", args->size, "Frame size N or W,H (image files: their size)")->delimiter(',')->expected(1, 2);
    const CLI::Option* frames = cmd->add_option("--frames", args->frames, "Frames, from the source's time on")->capture_default_str();
    const CLI::Option* step = cmd->add_option("--step", args->step, "Time between frames")->capture_default_str();
    const CLI::Option* layers = cmd->add_option("--layers-list", args->layers, "zoom: measure each layer count n (the curve over n)")->delimiter(',');
    cmd->add_option("--radial-bins", args->study.radialBins, "Bins of the radial spectra")->capture_default_str();
    addThreadsFlag(*cmd, args->threads);
    addTextureSourceCommands(*cmd, [args, size, frames, step, layers](const TextureSource& source, const SourceInfo& info) {
        TemporalCoherenceOptions o = args->study;
        o.frameTransfer = info.transfer;
        if (info.images) {
            for (const CLI::Option* f : {size, frames, step}) refuseWithoutEffect(f, false, "on image files (each file is a frame)");
            o.region = {info.width, info.height, 0, 0};
            o.times = evenTimes(0, 1, info.frames);
        } else {
            o.region = SourceRegion::centred(args->size[0], args->size.size() > 1 ? args->size[1] : args->size[0]);
            o.times = evenTimes(info.time, args->step, args->frames);
        }
        const auto* zoom = dynamic_cast<const ZoomSource*>(&source);
        refuseWithoutEffect(layers, zoom != nullptr, "without the zoom texture (n is its number of layers)");
        validateTemporalCoherence(o, &source);
        ThreadLimit limit(args->threads);
        ensureFolder(args->dir);
        ProgressLine progress("coherence");
        const TemporalCoherenceResult r = temporalCoherenceStudy(source, o, progress.callback());
        std::string body = "<h1>Temporal coherence: " + htmlEscape(info.name) + "</h1>" + r.summary.html() +
                           htmlFigures("", r.figures);
        std::vector<Figure> figures = r.figures;
        if (!args->layers.empty()) {
            LayerCoherenceOptions lo{args->layers, o};
            const LayerCoherenceResult l = layerCoherenceStudy(*zoom, lo, progress.callback());
            writeText(args->dir, "layers.csv", l.table.csv());
            body += "<h2>Over the number of layers n (thesis Figure 2.4)</h2>" + l.table.html() + htmlFigures("", l.figures);
            figures.insert(figures.end(), l.figures.begin(), l.figures.end());
            std::printf("%s", l.table.markdown().c_str());
        }
        progress.finish();
        writeFigures(args->dir, figures);
        writeText(args->dir, "coherence.csv", r.summary.csv());
        writeText(args->dir, "frames.csv", r.perFrame.csv());
        writeText(args->dir, "index.html", htmlPage("Temporal coherence: " + info.name, body));
        std::printf("%s\nwrote coherence.csv, frames.csv, the figures and index.html to %s\n",
                    r.summary.markdown().c_str(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
