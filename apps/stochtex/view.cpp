// stochtex view: an interactive window on a pattern, rendered by the GLSL
// implementation. Wheel: zoom about the cursor; drag: pan; 1/2/3: filter
// none/paper/smooth; V: zoom or plane view; Up/Down: tilt; D: footprints
// from the camera's Jacobian or the rasterizer's derivatives; Esc: quit.
// --frames N --screenshot FILE renders N frames, saves the last, and exits
// (how the tests try the window under Xvfb).
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/gpu_pattern.h"
#include "stochtex/image/image_io.h"

namespace stochtex::cli {

namespace {

struct ViewerState {
    Camera camera;
    FilterMode mode = FilterMode::Smooth;
    GpuPattern::Derivatives derivatives = GpuPattern::Derivatives::Camera;
    double cursorX = 0, cursorY = 0;
    bool dragging = false;
};

void onScroll(GLFWwindow* w, double, double dy) {
    auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(w));
    // Zoom about the cursor: the texel under it stays put. GL rows go up,
    // window rows down.
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(w, &fw, &fh);
    const double px = s->cursorX, py = fh - s->cursorY;
    View& v = s->camera.view;
    const double factor = std::pow(1.15, -dy);
    const double next = std::clamp(v.scale * factor, 1.0 / 64.0, 4096.0);
    v.offsetU += px * (v.scale - next);
    v.offsetV += py * (v.scale - next);
    v.scale = next;
}

void onCursor(GLFWwindow* w, double x, double y) {
    auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(w));
    if (s->dragging) {
        s->camera.view.offsetU -= (x - s->cursorX) * s->camera.view.scale;
        s->camera.view.offsetV += (y - s->cursorY) * s->camera.view.scale;
    }
    s->cursorX = x;
    s->cursorY = y;
}

void onButton(GLFWwindow* w, int button, int action, int) {
    auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(w));
    if (button == GLFW_MOUSE_BUTTON_LEFT) s->dragging = action == GLFW_PRESS;
}

void onKey(GLFWwindow* w, int key, int, int action, int) {
    if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
    auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(w));
    switch (key) {
        case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(w, GLFW_TRUE); break;
        case GLFW_KEY_1: s->mode = FilterMode::None; break;
        case GLFW_KEY_2: s->mode = FilterMode::Paper; break;
        case GLFW_KEY_3: s->mode = FilterMode::Smooth; break;
        case GLFW_KEY_V:
            s->camera.kind = s->camera.kind == Camera::Kind::Zoom ? Camera::Kind::Plane : Camera::Kind::Zoom;
            break;
        case GLFW_KEY_D:
            s->derivatives = s->derivatives == GpuPattern::Derivatives::Camera ? GpuPattern::Derivatives::Rasterizer
                                                                               : GpuPattern::Derivatives::Camera;
            break;
        case GLFW_KEY_UP: s->camera.tiltDeg = std::min(89.0, s->camera.tiltDeg + 2.0); break;
        case GLFW_KEY_DOWN: s->camera.tiltDeg = std::max(0.0, s->camera.tiltDeg - 2.0); break;
        default: break;
    }
}

const char* modeName(FilterMode m) {
    return m == FilterMode::None ? "unfiltered" : m == FilterMode::Paper ? "paper" : "smooth";
}

}  // namespace

void registerView(CLI::App& app) {
    struct Args {
        PatternSource source;
        std::string filter = "smooth", camera = "zoom", screenshot;
        std::vector<int> size{960, 640};
        double scale = 1.0, tilt = 60.0;
        int aniso = 8, frames = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("view", "Interactive window (GLSL): wheel zooms, drag pans, 1/2/3 filter "
                                           "none/paper/smooth, V zoom/plane, Up/Down tilt, D camera/rasterizer "
                                           "derivatives, Esc quits");
    addPatternSource(*cmd, args->source);
    cmd->add_option("--filter", args->filter, "Starting mode: none | paper | smooth");
    cmd->add_option("--view", args->camera, "Starting view: zoom | plane");
    cmd->add_option("--scale", args->scale, "Starting scale (texels per pixel)");
    cmd->add_option("--tilt", args->tilt, "Plane tilt, degrees");
    cmd->add_option("--aniso", args->aniso, "Anisotropic probes K (1..16)");
    cmd->add_option("--size", args->size, "Window size: N or W,H")->delimiter(',')->expected(1, 2);
    cmd->add_option("--frames", args->frames, "Quit after this many frames (0: when the window closes)")
        ->check(CLI::Range(0, 1000000));
    cmd->add_option("--screenshot", args->screenshot, "Save the last frame to this PNG/EXR");
    cmd->callback([args] {
        if (!args->screenshot.empty()) checkImageOutput(args->screenshot);
        const int w = args->size[0], h = args->size.size() > 1 ? args->size[1] : args->size[0];
        if (w < 16 || h < 16 || w > 8192 || h > 8192) throw InputError("--size must be in [16, 8192] per side");
        ViewerState state;
        state.mode = parseFilterMode(args->filter);
        if (state.mode != FilterMode::None && state.mode != FilterMode::Paper && state.mode != FilterMode::Smooth)
            throw InputError("--filter: the viewer shows none, paper or smooth");
        if (args->camera == "plane") state.camera.kind = Camera::Kind::Plane;
        else if (args->camera != "zoom") throw InputError("--view: unknown \"" + args->camera + "\" (expected zoom or plane)");
        state.camera.view.width = w;
        state.camera.view.height = h;
        state.camera.view.scale = args->scale;
        state.camera.tiltDeg = args->tilt;
        validateCamera(state.camera);
        if (args->aniso < 1 || args->aniso > kMaxAnisotropy) throw InputError("--aniso must be in [1, 16]");
        const PatternSpec spec = loadPatternSource(args->source);
        const Pattern pattern = Pattern::build(spec);
        auto context = GlContext::window(w, h, "stochtex view");
        auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
        glfwSetWindowUserPointer(window, &state);
        glfwSetScrollCallback(window, onScroll);
        glfwSetCursorPosCallback(window, onCursor);
        glfwSetMouseButtonCallback(window, onButton);
        glfwSetKeyCallback(window, onKey);
        std::map<FilterMode, std::unique_ptr<GpuPattern>> renderers;  // built on first use
        int frame = 0;
        auto last = std::chrono::steady_clock::now();
        double fps = 0;
        while (!context->shouldClose() && (args->frames == 0 || frame < args->frames)) {
            int fw = 0, fh = 0;
            context->framebufferSize(fw, fh);
            state.camera.view.width = std::max(fw, 1);
            state.camera.view.height = std::max(fh, 1);
            auto& r = renderers[state.mode];
            if (!r) {
                FilterOptions o;
                o.mode = state.mode;
                o.aniso = args->aniso;
                r = std::make_unique<GpuPattern>(pattern, *context, o);
            }
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, state.camera.view.width, state.camera.view.height);
            r->setDerivatives(state.derivatives);
            r->drawView(state.camera);
            ++frame;
            if (!args->screenshot.empty() && (args->frames == 0 || frame == args->frames)) {
                // Read the back buffer before swapping; GL row 0 is the bottom.
                const int vw = state.camera.view.width, vh = state.camera.view.height;
                std::vector<float> rgb(size_t(vw) * size_t(vh) * 3);
                glPixelStorei(GL_PACK_ALIGNMENT, 1);
                glReadBuffer(GL_BACK);
                glReadPixels(0, 0, vw, vh, GL_RGB, GL_FLOAT, rgb.data());
                Image shot(vw, vh, 3, Image::Uninitialized{});
                for (int y = 0; y < vh; ++y)
                    std::copy_n(rgb.data() + size_t(vh - 1 - y) * size_t(vw) * 3, size_t(vw) * 3, shot.row(y));
                writeImage(args->screenshot, shot);
            }
            const auto now = std::chrono::steady_clock::now();
            const double dt = std::chrono::duration<double>(now - last).count();
            last = now;
            fps = fps == 0 ? 1.0 / std::max(dt, 1e-6) : 0.9 * fps + 0.1 / std::max(dt, 1e-6);
            char title[200];
            std::snprintf(title, sizeof title, "stochtex view - %s - %s - %s view - %s derivatives - scale %.3g - %.0f fps",
                          spec.name.c_str(), modeName(state.mode),
                          state.camera.kind == Camera::Kind::Zoom ? "zoom" : "plane",
                          state.derivatives == GpuPattern::Derivatives::Camera ? "camera" : "rasterizer",
                          state.camera.view.scale, fps);
            context->setTitle(title);
            context->swapAndPoll();
        }
        if (!args->screenshot.empty()) std::printf("wrote %s after %d frames\n", args->screenshot.c_str(), frame);
    });
}

}  // namespace stochtex::cli
