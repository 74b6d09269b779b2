// stochtex view: an interactive window on a pattern, rendered by the GLSL
// implementation (view_window.cpp has the controls).
// --frames N --screenshot FILE renders N frames, saves the last, and exits
// (how the tests try the window under Xvfb).
#include <algorithm>
#include <cstdio>

#include "common.h"
#include "view_window.h"

namespace stochtex::cli {

void registerView(CLI::App& app) {
    struct Args {
        PatternSource source;
        ViewWindowOptions window;
        ResponseFlags response;
        std::vector<int> size{960, 640};
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("view", "Interactive window (GLSL): wheel zooms, drag pans, 1/2/3 filter "
                                           "none/paper/smooth, L colours/LEAN normals, V zoom/plane, Up/Down tilt, D camera/rasterizer "
                                           "derivatives, Esc quits");
    ViewWindowOptions& w = args->window;
    addPatternSource(*cmd, args->source);
    addFilterFlag(*cmd, w.filter, "Starting mode: none | paper | smooth");
    addCameraFlags(*cmd, w.camera, false);
    cmd->add_option("--scale", w.camera.view.scale, "Starting scale (texels per pixel)");
    addAnisoFlag(*cmd, w.filter.aniso);
    addResponseFlags(*cmd, args->response);
    cmd->add_option("--size", args->size, "Window size: N or W,H")->delimiter(',')->expected(1, 2);
    cmd->add_option("--frames", w.frames, "Quit after this many frames (0: when the window closes)")
        ->check(CLI::Range(0, 1000000));
    cmd->add_option("--screenshot", w.screenshot, "Save the last frame to this PNG/EXR");
    cmd->callback([args, cmd] {
        applyResponseFlags(*cmd, args->response, args->window.filter);
        ViewWindowOptions o = args->window;
        if (!o.screenshot.empty()) checkImageOutput(o.screenshot);
        o.camera.view.width = args->size[0];
        o.camera.view.height = args->size.size() > 1 ? args->size[1] : args->size[0];
        if (std::min(o.camera.view.width, o.camera.view.height) < 16 ||
            std::max(o.camera.view.width, o.camera.view.height) > 8192)
            throw InputError("--size must be in [16, 8192] per side");
        if (!isGpuFilter(o.filter)) throw InputError("--filter: the viewer shows none, paper or smooth");
        validateCamera(o.camera);
        if (o.filter.aniso < 1 || o.filter.aniso > kMaxAnisotropy) throw InputError("--aniso must be in [1, 16]");
        const PatternSpec spec = loadPatternSource(args->source, FilterOptions{}.use(parseFilter("smooth")));
        const int frames = runViewWindow(spec, o);
        if (!o.screenshot.empty()) std::printf("wrote %s after %d frames\n", o.screenshot.c_str(), frames);
    });
}

}  // namespace stochtex::cli
