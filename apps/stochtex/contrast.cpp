// stochtex contrast: linear, polynomial and sigmoid contrast correction of the
// zoom texture (thesis section 2.4, Figure 2.6).
#include <cstdio>

#include "common.h"
#include "stochtex/core/parallel.h"
#include "zoom_studies.h"

namespace stochtex::cli {

void registerContrast(CLI::App& app) {
    struct Args {
        ZoomFlags zoom;
        ContrastStudy study;
        std::string dir;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("contrast", "Contrast corrections of the zoom texture with their histograms, "
                                               "curves and clamped-pixel percentages");
    cmd->add_option("-o,--output", args->dir, "Output folder")->required();
    cmd->add_option("--size", args->study.size, "Texture size in pixels");
    cmd->add_option("--layers", args->study.layers, "Number of layers n (Figure 2.6 uses 16)");
    addZoomFlags(*cmd, args->zoom, false);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        ThreadLimit limit(args->threads);
        const StudyOutput out = runContrastStudy(args->zoom, args->study, args->dir);
        std::printf("%s\nwrote figure2_6.png, the corrected textures and contrast.csv to %s\n", out.table.c_str(),
                    args->dir.c_str());
    });
}

}  // namespace stochtex::cli
