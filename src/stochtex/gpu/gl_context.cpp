#include "stochtex/gpu/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <vector>

namespace stochtex {

struct GlContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    GLFWwindow* window = nullptr;
};

namespace {

// Displays to try, best first: a real device, then Mesa's surfaceless
// platform (software rendering), then the default display.
std::vector<EGLDisplay> candidateDisplays() {
    std::vector<EGLDisplay> out;
    const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const std::string ext = clientExt ? clientExt : "";
    if (ext.find("EGL_EXT_platform_device") != std::string::npos) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count))
            for (EGLint i = 0; i < count; ++i) {
                const EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY) out.push_back(d);
            }
    }
    if (ext.find("EGL_MESA_platform_surfaceless") != std::string::npos) {
        const EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) out.push_back(d);
    }
    const EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY) out.push_back(d);
    return out;
}

}  // namespace

std::unique_ptr<GlContext> GlContext::headless() {
    std::unique_ptr<GlContext> ctx(new GlContext);
    ctx->impl_ = std::make_unique<Impl>();
    std::string tried;
    for (EGLDisplay d : candidateDisplays()) {
        EGLint major = 0, minor = 0;
        if (!eglInitialize(d, &major, &minor)) continue;
        const char* vendor = eglQueryString(d, EGL_VENDOR);
        tried += std::string(tried.empty() ? "" : ", ") + (vendor ? vendor : "?");
        if (!eglBindAPI(EGL_OPENGL_API)) continue;
        // Configless and surfaceless (EGL_KHR_no_config_context,
        // EGL_KHR_surfaceless_context): rendering is to FBOs only. 4.3 core
        // first (compute shaders; some drivers give exactly the version
        // asked for), else 3.3 core.
        EGLContext c = EGL_NO_CONTEXT;
        const EGLint versions[][2] = {{4, 3}, {3, 3}};
        for (const auto& [major, minor] : versions) {
            const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, minor,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
            c = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
            if (c != EGL_NO_CONTEXT) break;
        }
        if (c == EGL_NO_CONTEXT) continue;
        if (!eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) {
            eglDestroyContext(d, c);
            continue;
        }
        ctx->impl_->display = d;
        ctx->impl_->context = c;
        return ctx;
    }
    throw GpuUnavailable("no headless OpenGL 3.3 core context could be created (EGL displays tried: " +
                         (tried.empty() ? std::string("none") : tried) +
                         "); install Mesa (libegl-mesa0, libgl1-mesa-dri) or a GPU driver");
}

std::unique_ptr<GlContext> GlContext::window(int width, int height, const std::string& title) {
    if (!glfwInit()) throw GpuUnavailable("view: GLFW could not start (no display? run under a desktop or xvfb-run)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* w = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!w) {
        glfwTerminate();
        throw GpuUnavailable("view: no OpenGL 3.3 core window could be created");
    }
    glfwMakeContextCurrent(w);
    glfwSwapInterval(1);
    std::unique_ptr<GlContext> ctx(new GlContext);
    ctx->impl_ = std::make_unique<Impl>();
    ctx->impl_->window = w;
    return ctx;
}

bool GlContext::shouldClose() const { return impl_->window && glfwWindowShouldClose(impl_->window); }

void GlContext::swapAndPoll() {
    if (!impl_->window) return;
    glfwSwapBuffers(impl_->window);
    glfwPollEvents();
}

void GlContext::setTitle(const std::string& title) {
    if (impl_->window) glfwSetWindowTitle(impl_->window, title.c_str());
}

void GlContext::framebufferSize(int& width, int& height) const {
    width = height = 0;
    if (impl_->window) glfwGetFramebufferSize(impl_->window, &width, &height);
}

void* GlContext::nativeWindow() const { return impl_->window; }

GlContext::~GlContext() {
    if (impl_ && impl_->window) {
        glfwDestroyWindow(impl_->window);
        glfwTerminate();
        return;
    }
    if (impl_ && impl_->context != EGL_NO_CONTEXT) {
        eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(impl_->display, impl_->context);
    }
}

void GlContext::makeCurrent() {
    if (impl_->window) glfwMakeContextCurrent(impl_->window);
    else eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context);
}

bool GlContext::hasCompute() const { return epoxy_gl_version() >= 43; }

std::string GlContext::describe() const {
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return std::string("OpenGL ") + (version ? version : "?") + ", " + (renderer ? renderer : "?");
}

}  // namespace stochtex
