// The window of `stochtex view`. Wheel: zoom about the cursor; drag: pan;
// 1/2/3: filter none/paper/smooth; L: colours or the normal map's LEAN
// shading (a pattern with a normal_map); V: zoom or plane view; Up/Down: tilt; D:
// footprints from the camera's Jacobian or the rasterizer's derivatives; Esc: quit.
#include "view_window.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/render_target.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/texture_graph.h"

namespace stochtex::cli {

namespace {

struct ViewerState {
    Camera camera;
    std::string filter = "smooth";  // a name of kFilterNames
    ResponseKind response = ResponseKind::PrefilteredColormap;
    bool hasNormalMap = false;  // whether L may switch to the lean response
    GpuPattern::Derivatives derivatives = GpuPattern::Derivatives::Camera;
    double cursorX = 0, cursorY = 0;
    bool dragging = false;
};

void onScroll(GLFWwindow* w, double, double dy) {
    auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(w));
    // Zoom about the cursor: the texel under it stays put. The window shows
    // image rows top down (showTopDown), as its cursor rows go.
    const double px = s->cursorX, py = s->cursorY;
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
        s->camera.view.offsetV -= (y - s->cursorY) * s->camera.view.scale;
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
        case GLFW_KEY_1: s->filter = "none"; break;
        case GLFW_KEY_2: s->filter = "paper"; break;
        case GLFW_KEY_3: s->filter = "smooth"; break;
        case GLFW_KEY_L:
            if (s->hasNormalMap)
                s->response = s->response == ResponseKind::Lean ? ResponseKind::PrefilteredColormap : ResponseKind::Lean;
            break;
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

// The frame is drawn into `target` as `render` draws it (linear light, image
// row y in GL row y); the "display" program turns it over for the window,
// whose GL row 0 is at the bottom, and encodes it to the sRGB codes a PNG of
// `render` holds.
class Display {
public:
    Display() : program_(buildProgram("display")), vao_(gl::newVertexArray()) {}
    void show(const RenderTarget& target) const {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, target.width(), target.height());
        glUseProgram(program_.id());
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, target.texture());
        glUniform1i(glGetUniformLocation(program_.id(), "uImage"), 0);
        glBindVertexArray(vao_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

private:
    gl::Program program_;
    gl::VertexArray vao_;
};

// What the window shows: its back buffer before the swap, top row first.
Image readWindow(int w, int h) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    return readBoundFramebufferRgb(w, h, RenderTarget::Rows::TopDown);
}

}  // namespace

namespace {

// The GPU renderer of one filter mode (the window builds one per mode, on first use).
using RendererFactory = std::function<std::unique_ptr<GpuView>(GlContext&, const FilterOptions&)>;

int runWindow(const RendererFactory& makeRenderer, bool hasNormalMap, const std::string& name,
              const ViewWindowOptions& options) {
    ViewerState state;
    state.camera = options.camera;
    // The filter's name without the response (L switches that).
    state.filter = filterName(
        FilterOptions{}.use({options.filter.source, {ResponseKind::PrefilteredColormap, options.filter.response.prefilter}}));
    state.response = options.filter.response.kind;
    state.hasNormalMap = hasNormalMap;
    auto context = GlContext::window(state.camera.view.width, state.camera.view.height, "stochtex view");
    auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
    glfwSetWindowUserPointer(window, &state);
    glfwSetScrollCallback(window, onScroll);
    glfwSetCursorPosCallback(window, onCursor);
    glfwSetMouseButtonCallback(window, onButton);
    glfwSetKeyCallback(window, onKey);
    std::map<std::pair<std::string, ResponseKind>, std::unique_ptr<GpuView>> renderers;  // built on first use
    std::unique_ptr<RenderTarget> target;                          // rebuilt when the window's size changes
    const Display display;
    int frame = 0;
    auto last = std::chrono::steady_clock::now();
    double fps = 0;
    while (!context->shouldClose() && (options.frames == 0 || frame < options.frames)) {
        int fw = 0, fh = 0;
        context->framebufferSize(fw, fh);
        state.camera.view.width = std::max(fw, 1);
        state.camera.view.height = std::max(fh, 1);
        auto& r = renderers[{state.filter, state.response}];
        if (!r) {
            FilterOptions o = options.filter;
            const bool covariance = o.response.covariance;
            o.use(parseFilter(state.filter));
            o.response.kind = state.response;
            o.response.covariance = covariance;
            r = makeRenderer(*context, o);
        }
        const int w = state.camera.view.width, h = state.camera.view.height;
        if (!target || target->width() != w || target->height() != h)
            target = std::make_unique<RenderTarget>(w, h, false);
        target->bind();
        r->setDerivatives(state.derivatives);
        r->drawView(state.camera);
        display.show(*target);
        ++frame;
        if (!options.screenshot.empty() && (options.frames == 0 || frame == options.frames))
            writeImage(options.screenshot, readWindow(w, h), kNoTransfer);  // sRGB codes already
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        fps = fps == 0 ? 1.0 / std::max(dt, 1e-6) : 0.9 * fps + 0.1 / std::max(dt, 1e-6);
        char title[200];
        std::snprintf(title, sizeof title,
                      "stochtex view - %s - %s%s - %s view - %s derivatives - scale %.3g - %.0f fps", name.c_str(),
                      state.filter == "none" ? "unfiltered" : state.filter.c_str(),
                      state.response == ResponseKind::Lean ? " LEAN normals" : "",
                      enumName(Camera::kKindNames, state.camera.kind).c_str(),
                      enumName(kGpuDerivativesNames, state.derivatives).c_str(), state.camera.view.scale, fps);
        context->setTitle(title);
        context->swapAndPoll();
    }
    return frame;
}

}  // namespace

int runViewWindow(const PatternSpec& spec, const ViewWindowOptions& options) {
    if (needsGraphEvaluator(spec)) {
        const GraphPattern graph = GraphPattern::build(spec);
        checkGraphTextureUnits(graph, true);  // the window switches to filtered modes: refuse before it opens
        return runWindow([&](GlContext& c, const FilterOptions& o) { return std::make_unique<GpuGraph>(graph, c, o); },
                         false, spec.name, options);
    }
    const Pattern pattern = Pattern::build(spec);
    return runWindow([&](GlContext& c, const FilterOptions& o) { return std::make_unique<GpuPattern>(pattern, c, o); },
                     pattern.normalMap() != nullptr, spec.name, options);
}

}  // namespace stochtex::cli
