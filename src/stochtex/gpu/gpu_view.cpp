#include "stochtex/gpu/gpu_view.h"

#include <epoxy/gl.h>

#include <chrono>

#include "stochtex/core/error.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/render_target.h"
#include "stochtex/gpu/uploads.h"

namespace stochtex {

namespace {

// Raised by setDerivatives and setPipeline, whichever of the pair comes second.
InputError rasterizerNeedsFragments() {
    return InputError::parameter("derivatives",
                                 "must be camera with the compute pipeline (compute shaders have no dFdx), got rasterizer");
}

}  // namespace

GpuView::GpuView(GlContext& context, Recipes recipes, int exampleSize)
    : recipes_(std::move(recipes)), exampleSize_(exampleSize), device_(context.describe()) {
    context.makeCurrent();
    hasCompute_ = context.hasCompute();
    program_ = buildProgram(recipes_.fragment, recipes_.generated);
    vao_ = gl::newVertexArray();
}

GpuView::~GpuView() = default;

gl::Program GpuView::sceneProgram() const { return buildProgram(recipes_.scene, recipes_.generated); }

void GpuView::setDerivatives(Derivatives d) {
    if (d == Derivatives::Rasterizer && pipeline_ == Pipeline::Compute) throw rasterizerNeedsFragments();
    derivatives_ = d;
}

void GpuView::setPipeline(Pipeline p) {
    if (p == Pipeline::Compute) {
        if (!hasCompute_) throw GpuUnavailable("the compute pipeline needs OpenGL 4.3 (compute shaders)");
        if (derivatives_ == Derivatives::Rasterizer) throw rasterizerNeedsFragments();
        if (!kernelProgram_) kernelProgram_ = buildProgram(recipes_.compute, recipes_.generated);
    }
    pipeline_ = p;
}

Image GpuView::render(const View& view) const {
    Camera camera;
    camera.view = view;
    return render(camera);
}

Image GpuView::render(const Camera& camera, const Progress&) const {
    validateCamera(camera);
    const View& view = camera.view;
    // Framebuffer row y is image row y: the shader maps fragment y to v the
    // way the CPU maps image rows.
    const RenderTarget target(view.width, view.height, false);
    drawOrDispatch(camera);
    Image out = target.readRgb(RenderTarget::Rows::AsDrawn);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

void GpuView::setViewUniforms(unsigned program, const Camera& camera) const {
    bind(program);
    setCameraUniforms(program, camera, derivatives_ == Derivatives::Rasterizer);
}

void GpuView::drawView(const Camera& camera) const {
    setViewUniforms(program_.id(), camera);
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GpuView::drawOrDispatch(const Camera& camera) const {
    if (pipeline_ == Pipeline::Fragment) return drawView(camera);
    // The kernel writes the texture attached to the bound framebuffer.
    GLint target = 0;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                          &target);
    setViewUniforms(kernelProgram_.id(), camera);
    glBindImageTexture(0, GLuint(target), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint((camera.view.width + 7) / 8), GLuint((camera.view.height + 7) / 8), 1);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

double GpuView::secondsPerFrame(const Camera& camera, int frames) const {
    validateCamera(camera);
    if (frames < 1) throw InputError::parameter("frames", "must be >= 1, got " + std::to_string(frames));
    double seconds = 0;
    const RenderTarget target(camera.view.width, camera.view.height, false);
    {
        // Warm-up, at least 0.3 s: drivers finish compiling and uploading at
        // the first draw, and a GPU that idled (during a read-back, say)
        // needs a while at full load to raise its clocks again (an H100
        // measured right after idling ran at 345 of 1980 MHz).
        using clock = std::chrono::steady_clock;
        const auto warm = clock::now();
        do {
            drawOrDispatch(camera);
            glFinish();
        } while (std::chrono::duration<double>(clock::now() - warm).count() < 0.3);
        const auto start = clock::now();
        for (int f = 0; f < frames; ++f) drawOrDispatch(camera);
        glFinish();
        seconds = std::chrono::duration<double>(clock::now() - start).count();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return seconds / frames;
}

}  // namespace stochtex
