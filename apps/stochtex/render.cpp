// stochtex render: the unfiltered pattern S = H ∘ N, one sample per pixel.
#include <cstdio>

#include "common.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"

namespace stochtex::cli {

void registerRender(CLI::App& app) {
    struct Args {
        PatternSource source;
        ViewFlags view;
        std::string output;
        int bits = 8;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("render", "Render a pattern to PNG or EXR");
    addPatternSource(*cmd, args->source);
    addViewFlags(*cmd, args->view);
    cmd->add_option("-o,--output", args->output, "Output image (.png or .exr)")->required();
    cmd->add_option("--bits", args->bits, "PNG bit depth")->check(CLI::IsMember({8, 16}));
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        checkImageOutput(args->output);
        const PatternSpec spec = loadPatternSource(args->source);
        const View view = makeView(spec, args->view);
        ThreadLimit limit(args->threads);
        const Pattern pattern = Pattern::build(spec);
        const Image image = pattern.render(view);
        writeImage(args->output, image, WriteOptions{args->bits});
        std::printf("wrote %s (%dx%d, %s, scale %g texels/pixel)\n", args->output.c_str(), view.width, view.height,
                    spec.name.c_str(), view.scale);
    });
}

}  // namespace stochtex::cli
