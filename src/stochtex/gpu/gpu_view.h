#pragma once
// A GPU view (GpuGraph, a file's program, is the one today): a program of the recipe table (gpu/
// programs.h) drawn over a camera's view, as fragments over a full-screen
// triangle or as a compute kernel, into a float target read back, or into
// the framebuffer bound now (a window's). A derived class owns the textures
// and parameters the program reads and binds them (bind).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "stochtex/core/enum_names.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/gl_objects.h"
#include "stochtex/image/image.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/view_renderer.h"

namespace stochtex {

// Whether the GPU programs have this statistics source: the point and the
// estimators (exact statistics and the reference are the CPU's studies).
// The one statement of the refusal: the GPU hosts refuse the others with an
// InputError naming `source`, and the commands offer only these.
inline bool gpuHasSource(StatisticsSource source) {
    return source == StatisticsSource::Point || source == StatisticsSource::Estimators;
}

class GpuView : public ViewRenderer {
public:
    // The recipes of the fragment and the compute program (built on first
    // use) and the generated chunks by stem.
    struct Recipes {
        std::string fragment, compute, scene;
        std::vector<std::pair<std::string, std::string>> generated;
        bool shadesLight = false;  // shadesLight()
    };

    virtual ~GpuView();
    GpuView(const GpuView&) = delete;
    GpuView& operator=(const GpuView&) = delete;

    // Where the built-in cameras' footprints come from: their exact Jacobian
    // (the default; what the CPU uses, so the two agree) or the rasterizer's
    // dFdx/dFdy of uv, as an engine gets them on arbitrary geometry.
    enum class Derivatives { Camera, Rasterizer };
    void setDerivatives(Derivatives d);
    // How render() and secondsPerFrame() run the shader: as a fragment shader
    // over a full-screen triangle (the default; what a display or an engine
    // does) or as a compute kernel (GLSL 4.30; GpuUnavailable without 4.3),
    // which reaches every shader unit of GPUs with few graphics units.
    // Compute footprints are always the camera's Jacobian.
    enum class Pipeline { Fragment, Compute };
    void setPipeline(Pipeline p);

    // The camera mapping of the CPU's render (zoom or plane); RGB float.
    // No progress: a GPU frame is one draw.
    Image render(const Camera& camera, const Progress& progress = {}) const override;
    Image render(const View& view) const;  // zoom
    int exampleSize() const override { return exampleSize_; }
    std::string device() const override { return device_; }
    // Draws the camera's view into the framebuffer bound now (a window's),
    // over the current viewport; no read-back.
    void drawView(const Camera& camera) const;
    // Seconds per frame of render()'s work without the read-back: `frames`
    // draws (or dispatches) into render()'s float target after a warm-up of
    // at least 0.3 s, timed from submission to glFinish. Wall clock, not a GL_TIME_ELAPSED
    // query: llvmpipe's queries end before its rasterizer threads do. For
    // throughput benchmarks.
    double secondsPerFrame(const Camera& camera, int frames) const;

    // Makes `program` current and binds every texture the view's program
    // reads, its parameters' buffer and the sky colour. Also for programs of
    // other recipes (the scene's).
    virtual void bind(unsigned program) const = 0;
    // The estimators and prefiltered tables (else the point values).
    virtual bool filtered() const = 0;
    // Whether the program lights its own colour (the lean response, a
    // program with a lean op): a scene gives it the light and the eye in the
    // surface's frame and draws its colour as it is, unlit again.
    bool shadesLight() const { return recipes_.shadesLight; }
    // The program that draws this view's pattern on a mesh (scene.frag),
    // with the same chunks; needs the context current.
    gl::Program sceneProgram() const;

protected:
    // Makes the context current and builds the fragment program.
    GpuView(GlContext& context, Recipes recipes, int exampleSize);

private:
    void setViewUniforms(unsigned program, const Camera& camera) const;
    // drawView, or the compute kernel into the bound framebuffer's texture.
    void drawOrDispatch(const Camera& camera) const;
    Recipes recipes_;
    int exampleSize_;
    std::string device_;
    gl::Program program_, kernelProgram_;
    gl::VertexArray vao_;
    bool hasCompute_ = false;
    Pipeline pipeline_ = Pipeline::Fragment;
    Derivatives derivatives_ = Derivatives::Camera;
};

// Names of the GPU's choices, as the CLI spells them.
inline const EnumNames<GpuView::Derivatives> kGpuDerivativesNames{{"camera", GpuView::Derivatives::Camera},
                                                                  {"rasterizer", GpuView::Derivatives::Rasterizer}};
inline const EnumNames<GpuView::Pipeline> kGpuPipelineNames{{"fragment", GpuView::Pipeline::Fragment},
                                                            {"compute", GpuView::Pipeline::Compute}};

}  // namespace stochtex
