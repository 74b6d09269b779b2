#pragma once
// The pattern rendered by the GLSL implementation (drawn by GpuView).
// Unfiltered (S = H ∘ N): the examples, T⁻¹ tables and colormap are uploaded
// once. Filtered (paper / smooth, Ŝ = H̄(μ̂, σ̂)): the statistics pyramids as
// mip levels and the prefiltered table as a texture array (every σ layer at
// the colormap's full resolution).
#include <memory>

#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/gpu_view.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/pattern/pattern.h"

namespace stochtex {

class GpuPattern final : public GpuView {
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
    ~GpuPattern() override;

    // Makes `program` current and binds every texture of the pattern to it
    // (both the unfiltered and the filtered sets: a program ignores what it
    // lacks) and its parameters' buffer to its PatternParameters block. For
    // programs of other recipes (the scene).
    void bind(unsigned program) const override;
    // The estimators and a response (else the unfiltered S = H ∘ N).
    bool filtered() const override;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stochtex
