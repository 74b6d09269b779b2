#pragma once
// The pattern rendered by the GLSL implementation. Unfiltered (S = H ∘ N):
// the examples, T⁻¹ tables and colormap are uploaded once. Filtered
// (paper / smooth, Ŝ = H̄(μ̂, σ̂)): the statistics pyramids as mip levels and
// the prefiltered table as a texture array (every σ layer at the colormap's
// full resolution), footprints from the rasterizer's derivatives. Each
// render draws one fragment per pixel into a float framebuffer and reads it
// back.
#include <memory>

#include "stochtex/gpu/gl_context.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/pattern/pattern.h"

namespace stochtex {

class GpuPattern {
public:
    // Data is copied to the GPU: the pattern need not outlive this object.
    // options.source: Point or Estimators (InputError naming `source`
    // otherwise); any response kind (its GLSL chunk: gpu/programs.h).
    GpuPattern(const Pattern& pattern, GlContext& context, const FilterOptions& options = unfiltered());
    static FilterOptions unfiltered() {
        FilterOptions o;
        o.source = StatisticsSource::Point;
        return o;
    }
    ~GpuPattern();
    GpuPattern(const GpuPattern&) = delete;
    GpuPattern& operator=(const GpuPattern&) = delete;

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

    // The camera mapping of FilteredPattern::render (zoom or plane); RGB float.
    // Footprints come from the rasterizer's derivatives of uv.
    Image render(const Camera& camera);
    Image render(const View& view);  // zoom
    // Draws the camera's view into the framebuffer bound now (a window's),
    // over the current viewport; no read-back.
    void drawView(const Camera& camera);
    // Seconds per frame of render()'s work without the read-back: `frames`
    // draws (or dispatches) into render()'s float target after a warm-up of
    // at least 0.3 s, timed from submission to glFinish. Wall clock, not a GL_TIME_ELAPSED
    // query: llvmpipe's queries end before its rasterizer threads do. For
    // throughput benchmarks.
    double secondsPerFrame(const Camera& camera, int frames);

    // Makes `program` current and binds every texture of the pattern to it
    // (both the unfiltered and the filtered sets: a program ignores what it
    // lacks) and its parameters' buffer to its PatternParameters block. For
    // programs of other recipes (the scene).
    void bind(unsigned program) const;
    // The estimators and a response (else the unfiltered S = H ∘ N).
    bool filtered() const;
    // Whose shader chunk the programs of other recipes must assemble
    // (buildProgram's response).
    ResponseKind responseKind() const;

private:
    void setViewUniforms(unsigned program, const Camera& camera) const;
    // drawView, or the compute kernel into the bound framebuffer's texture.
    void drawOrDispatch(const Camera& camera);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Names of the GPU's choices, as the CLI spells them.
inline const EnumNames<GpuPattern::Derivatives> kGpuDerivativesNames{{"camera", GpuPattern::Derivatives::Camera},
                                                                     {"rasterizer", GpuPattern::Derivatives::Rasterizer}};
inline const EnumNames<GpuPattern::Pipeline> kGpuPipelineNames{{"fragment", GpuPattern::Pipeline::Fragment},
                                                               {"compute", GpuPattern::Pipeline::Compute}};

}  // namespace stochtex
