#pragma once
// The pattern S = H ∘ N rendered by the GLSL implementation: the examples,
// T⁻¹ tables and colormap are uploaded once; each render draws one
// fragment per pixel into a float framebuffer and reads it back.
#include <memory>

#include "stochtex/gpu/gl_context.h"
#include "stochtex/pattern/pattern.h"

namespace stochtex {

class GpuPattern {
public:
    // Needs `context` current; the pattern must outlive nothing (data is copied).
    GpuPattern(const Pattern& pattern, GlContext& context);
    ~GpuPattern();
    GpuPattern(const GpuPattern&) = delete;
    GpuPattern& operator=(const GpuPattern&) = delete;

    // Unfiltered, the same view mapping as Pattern::render; RGB float.
    Image render(const View& view);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stochtex
