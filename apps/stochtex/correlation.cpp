// stochtex correlation: the correlation plots of thesis Figures 2.8–2.10,
// analytic (eq. 2.11) and measured over N instances, for a grid of variants.
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/studies/zoom_studies.h"
#include "zoom_flags.h"

namespace stochtex::cli {

void registerCorrelation(CLI::App& app) {
    auto args = std::make_shared<ZoomStudyArgs<CorrelationStudyOptions>>();
    auto* cmd = app.add_subcommand("correlation",
                                   "Correlation plots Corr[I(x,0), I(y,0)] and Corr[I(x,0), I(x,y)] of the zoom "
                                   "texture: analytic, measured over instances, and their difference");
    addOutputFolderFlag(*cmd, args->dir);
    addCorrelationStudyFlags(*cmd, args->study);
    addZoomStudyFlags(*cmd, *args, false);
    cmd->callback([args] {
        ThreadLimit limit(args->threads);
        CorrelationStudyOptions o = args->study;
        o.zoom = makeZoomParams(args->zoom);
        o.base = makeZoomBase(args->zoom);
        validateCorrelationStudy(o);
        ensureFolder(args->dir);
        ProgressLine progress("correlation");
        const CorrelationStudyResult r = correlationStudy(o, progress.callback());
        progress.finish();
        writeReport(args->dir, correlationReport(r, o));
        std::printf("%s\nwrote %zu figures, figure2_10.png, correlation.csv and index.html to %s\n",
                    r.table.markdown().c_str(), r.figures.size(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
