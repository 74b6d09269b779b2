// stochtex correlation: the correlation plots of thesis Figures 2.8–2.10,
// analytic (eq. 2.11) and measured over N instances, for a grid of variants.
#include <cstdio>

#include "common.h"
#include "stochtex/core/parallel.h"
#include "zoom_studies.h"

namespace stochtex::cli {

void registerCorrelation(CLI::App& app) {
    struct Args {
        ZoomFlags zoom;
        CorrelationStudy study;
        std::string dir;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("correlation",
                                   "Correlation plots Corr[I(x,0), I(y,0)] and Corr[I(x,0), I(x,y)] of the zoom "
                                   "texture: analytic, measured over instances, and their difference");
    cmd->add_option("-o,--output", args->dir, "Output folder")->required();
    cmd->add_option("--variant", args->study.variants, "Variants: sliding, fixed, simple, random (repeatable)")
        ->delimiter(',');
    cmd->add_option("--layers-list", args->study.layers, "Layer counts n, e.g. 16,8,4,2")->delimiter(',');
    cmd->add_option("--instances", args->study.instances, "Instances N of the statistical accumulator");
    cmd->add_option("--size", args->study.size, "Plot extent in pixels from the zoom centre");
    addZoomFlags(*cmd, args->zoom, false);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        ThreadLimit limit(args->threads);
        const StudyOutput out = runCorrelationStudy(args->zoom, args->study, args->dir);
        std::printf("%s\nwrote %zu figures, figure2_10.png and correlation.csv to %s\n", out.table.c_str(),
                    out.figures.size(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
