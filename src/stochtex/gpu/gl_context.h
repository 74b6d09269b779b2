#pragma once
// An OpenGL 3.3+ core context, through libepoxy: headless — EGL on the
// device platform (a vendor GPU driver) or Mesa's surfaceless platform
// (llvmpipe on machines without a GPU), rendering to framebuffer objects —
// or a GLFW window.
#include <memory>
#include <stdexcept>
#include <string>

namespace stochtex {

// The machine has no usable OpenGL (no EGL display, no 3.3 core context).
class GpuUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class GlContext {
public:
    // Creates and makes current a headless context; GpuUnavailable if none.
    static std::unique_ptr<GlContext> headless();
    // A visible window of width × height with its own context, made current;
    // GpuUnavailable without a display.
    static std::unique_ptr<GlContext> window(int width, int height, const std::string& title);
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    void makeCurrent();

    // Window contexts only (no-ops / false for headless ones).
    bool shouldClose() const;
    void swapAndPoll();
    void setTitle(const std::string& title);
    void framebufferSize(int& width, int& height) const;
    // The GLFW window (GLFWwindow*), for input callbacks; null if headless.
    void* nativeWindow() const;
    // OpenGL 4.3 or newer: compute shaders (GpuView::Pipeline::Compute).
    bool hasCompute() const;
    // "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string describe() const;

private:
    GlContext() = default;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stochtex
