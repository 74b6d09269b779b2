// stochtex web: a self-contained WebGL2 page of a pattern (gpu/web_page.h)
// — open index.html from disk or serve the folder.
#include <cstdio>

#include "common.h"
#include "stochtex/gpu/web_page.h"

namespace stochtex::cli {

void registerWeb(CLI::App& app) {
    struct Args {
        PatternSource source;
        ViewFlags view;
        Camera camera;
        FilterOptions options;
        ResponseFlags response;
        std::string dir;
    };
    auto args = std::make_shared<Args>();
    args->options.use(parseFilter("smooth"));
    auto* cmd = app.add_subcommand("web",
                                   "Write a WebGL2 page of the pattern (index.html, page.js, data.js): real-time zoom, "
                                   "pan, filters and the plane view in a browser, from disk or any server");
    addPatternSource(*cmd, args->source);
    addOutputFolderFlag(*cmd, args->dir, "Output folder");
    addViewFlags(*cmd, args->view);
    addCameraFlags(*cmd, args->camera);
    addFilterFlag(*cmd, args->options, "The starting filter: none | paper | smooth (the page switches)",
                  gpuFilterNames());
    addAnisoFlag(*cmd, args->options.aniso);
    addEstimatorFlag(*cmd, args->options);
    addResponseFlags(*cmd, args->response);
    cmd->callback([args, cmd] {
        applyResponseFlags(*cmd, args->response, args->options);
        refuseUnusedFilterFlags(*cmd, args->options);
        const PatternSpec spec = loadPatternSource(*cmd, args->source, args->options);
        WebPageOptions web;
        web.options = args->options;
        web.camera = args->camera;
        web.camera.view = makeView(spec, args->view);
        web.sourceText = patternSourceText(args->source);
        writeWebPage(spec, web, args->dir);
        std::printf("wrote %s/index.html (%s, %dx%d %s view, filter %s): open it in a browser, from disk or a server\n",
                    args->dir.c_str(), spec.name.c_str(), web.camera.view.width, web.camera.view.height,
                    enumName(Camera::kKindNames, web.camera.kind).c_str(), filterLabel(args->options).c_str());
    });
}

}  // namespace stochtex::cli
