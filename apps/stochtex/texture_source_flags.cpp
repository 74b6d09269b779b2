#include "texture_source_flags.h"

#include <memory>

#include "common.h"
#include "marble_flags.h"
#include "shadertoy_flags.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/cpu_renderer.h"
#include "zoom_flags.h"

namespace stochtex::cli {

namespace {

// A ShaderToy program's frames (docs/SHADERTOY.md): the study's window is
// centred in the frame; instance i sets the program's instance uniform.
void addShadertoySource(CLI::App& cmd, const SourceStudy& study) {
    struct Args {
        std::string program;
        ShadertoyFlags flags;
    };
    auto args = std::make_shared<Args>();
    auto* st = cmd.add_subcommand("shadertoy",
                                  "A ShaderToy program's Image pass (a folder or manifest, docs/SHADERTOY.md); "
                                  "the window is centred in the frame");
    st->add_option("program", args->program, "The program's folder or manifest")->required();
    addShadertoyFlags(*st, args->flags);
    st->callback([args, study, st] {
        const ShadertoySpec spec = loadShadertoy(args->program);
        const ShadertoySettings settings = shadertoySettings(*st, args->flags);
        auto context = GlContext::headless();
        ShadertoyHost host(spec, *context, settings);
        const ShadertoySource source(host);
        // Linear: a program's frames are display codes already, shown as they are
        // (as `shadertoy --analyse` shows them).
        study(source, {spec.name + " (ShaderToy program)", false, 0, 0, 0, Transfer::Linear,
                       settings.startTime + args->flags.firstFrame / settings.fps});
    });
}

}  // namespace

void addTextureSourceCommands(CLI::App& cmd, SourceStudy study) {
    cmd.require_subcommand(1);
    auto files = std::make_shared<std::vector<std::string>>();
    auto* images = cmd.add_subcommand("images", "Image files (PNG, EXR, JPEG): frames of a sequence, in order");
    images->add_option("files", *files, "The images, all of one size")->required()->check(CLI::ExistingFile);
    images->callback([files, study] {
        std::vector<Image> frames;
        for (const std::string& f : *files) frames.push_back(readImage(f));
        const ImageSequenceSource source(std::move(frames));
        study(source, {std::to_string(files->size()) + " image file(s)", true, source.frames(), source.width(),
                       source.height(), Transfer::Linear});
    });

    struct PatternArgs {
        PatternSource source;
        ViewFlags view;
        FilterOptions options;
    };
    auto p = std::make_shared<PatternArgs>();
    p->options.use(parseFilter("none"));
    auto* pattern = cmd.add_subcommand("pattern",
                                       "A pattern seen in the zoom view; instance i moves the window "
                                       "(another draw of the tile offsets)");
    addPatternSource(*pattern, p->source);
    addViewFlags(*pattern, p->view);
    addFilterFlag(*pattern, p->options, "none | paper | smooth | exact | reference");
    pattern->callback([p, pattern, study] {
        refuseUnusedFilterFlags(*pattern, p->options);
        const PatternSpec spec = loadPatternSource(*pattern, p->source, p->options);
        Camera camera;
        camera.view = makeView(spec, p->view);
        const std::unique_ptr<ViewRenderer> renderer = makeCpuRenderer(spec, p->options);
        const CameraSource source(*renderer, camera);
        study(source, {spec.name + ", filter " + filterLabel(p->options), false, 0, 0, 0, Transfer::Srgb});
    });

    auto zoom = std::make_shared<ZoomFlags>();
    auto* z = cmd.add_subcommand("zoom",
                                 "The stationary zoom texture (thesis eq. 2.1); instance i = white-noise "
                                 "lattice i");
    addZoomFlags(*z, *zoom);
    z->callback([zoom, study] {
        const ZoomSource source(makeZoomParams(*zoom), makeZoomBase(*zoom));
        study(source, {"zoom texture, n = " + std::to_string(source.params().layers), false, 0, 0, 0, Transfer::Linear,
                       source.params().time});
    });

    auto marble = std::make_shared<MarbleParams>();
    auto* m = cmd.add_subcommand("marble", "The marble texture (thesis eq. 2.29); instance i = the noises of seed i");
    addMarbleFlags(*m, *marble, true);
    m->callback([marble, study] {
        const MarbleSource source(*marble);
        study(source, {"marble texture, " + enumName(kMarbleLayerNames, marble->layer) + ", " +
                           enumName(kMarbleScalingNames, marble->scaling) + " scaling",
                       false, 0, 0, 0, Transfer::Linear});
    });

    addShadertoySource(cmd, study);
}

void addWindowSizeFlag(CLI::App& cmd, WindowSizeFlag& flag, const std::string& what) {
    flag.option = cmd.add_option("--size", flag.size, what + " N or W,H (image files: their size)")
                      ->delimiter(',')
                      ->expected(1, 2);
}

SourceRegion studyRegion(const WindowSizeFlag& flag, const SourceInfo& info, const std::string& onImages) {
    if (info.images) {
        refuseWithoutEffect(flag.option, false, onImages);
        return {info.width, info.height, 0, 0};
    }
    return SourceRegion::centred(flag.size[0], flag.size.size() > 1 ? flag.size[1] : flag.size[0]);
}

}  // namespace stochtex::cli
