// stochtex contrast: linear, polynomial and sigmoid contrast correction of the
// zoom texture (thesis section 2.4, Figure 2.6).
#include <cstdio>

#include "common.h"
#include "stochtex/core/parallel.h"
#include "zoom_flags.h"

namespace stochtex::cli {

void registerContrast(CLI::App& app) {
    auto args = std::make_shared<ZoomStudyArgs<ContrastStudyOptions>>();
    args->zoom.params.layers = 16;  // Figure 2.6
    auto* cmd = app.add_subcommand("contrast",
                                   "Contrast corrections of the zoom texture with their histograms, "
                                   "curves and clamped-pixel percentages");
    addOutputFolderFlag(*cmd, args->dir);
    addParameterOptions(*cmd, contrastStudyMembers(), args->study);
    addZoomStudyFlags(*cmd, *args, true);
    cmd->callback([args] {
        ThreadLimit limit(args->threads);
        const ZoomParams zoom = makeZoomParams(args->zoom);
        const ContrastStudyResult r = zoomContrastStudy(zoom, makeZoomBase(args->zoom), args->study);
        const std::vector<std::string> files = writeReport(args->dir, contrastReport(r, zoom.layers));
        std::printf("%s\nwrote %s to %s\n", r.table.markdown().c_str(), listNames(files).c_str(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
