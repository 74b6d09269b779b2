// stochtex fractalize: image files as the base of the stationary zoom
// texture (thesis §2.7.1, Figures 2.15–2.17): each image's correlation
// around a point, and the zoom texture over it without and with hashed
// offsets, with theirs.
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/studies/image_base_study.h"

namespace stochtex::cli {

void registerFractalize(CLI::App& app) {
    struct Args {
        std::vector<std::string> files;
        ImageBaseStudyOptions study;
        std::string dir;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    args->study.zoom.layers = 8;  // Figure 2.17
    auto* cmd = app.add_subcommand("fractalize",
                                   "Image textures as the zoom texture's base (thesis Figures 2.15-2.17): "
                                   "correlation maps of each image and of the zoom texture over it "
                                   "(e.g. data/textures/*.png)");
    cmd->add_option("images", args->files, "Image files (colour: gray by 0.21r + 0.72g + 0.07b)")->required();
    addOutputFolderFlag(*cmd, args->dir);
    for (const char* name : {"layers", "maxScale"})
        addMemberOption(*cmd, optionMember(zoomParamsMembers(), name), args->study.zoom);
    addParameterOptions(*cmd, imageBaseStudyMembers(), args->study);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        std::vector<ImageBase> images;
        for (const std::string& f : args->files) images.push_back({f, readImage(f)});
        validateImageBaseStudy(args->study, images);
        ThreadLimit limit(args->threads);
        ensureFolder(args->dir);
        ProgressLine progress("fractalize");
        const ImageBaseStudyResult r = imageBaseStudy(images, args->study, progress.callback());
        progress.finish();
        const std::vector<std::string> files = writeReport(args->dir, imageBaseReport(r));
        std::printf("%s\nwrote %s to %s\n", r.table.markdown().c_str(), listNames(files).c_str(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
