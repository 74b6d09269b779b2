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
    // options.mode: None, Paper or Smooth (InputError otherwise).
    GpuPattern(const Pattern& pattern, GlContext& context, const FilterOptions& options = unfiltered());
    static FilterOptions unfiltered() {
        FilterOptions o;
        o.mode = FilterMode::None;
        return o;
    }
    ~GpuPattern();
    GpuPattern(const GpuPattern&) = delete;
    GpuPattern& operator=(const GpuPattern&) = delete;

    // The camera mapping of FilteredPattern::render (zoom or plane); RGB float.
    // Footprints come from the rasterizer's derivatives of uv.
    Image render(const Camera& camera);
    Image render(const View& view);  // zoom

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stochtex
