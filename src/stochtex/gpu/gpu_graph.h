#pragma once
// A texture graph rendered by one generated GLSL program (issue "Texture
// graphs"): the graph's program of operations (pattern/graph_pattern.h) is
// written out as GLSL that calls the kernel's functions — tiling and
// blending of each leaf, the footprint statistics of each pair of leaves
// (filtering.glsl's pairStatistics), table lookups, the prefiltered tables'
// lookup and kernel/graph_ops.glsl — in the CPU evaluator's order, so that
// the GPU's colours are the CPU's within float rounding. Seeds, means and
// parameters are constants of the program; examples, pyramids and tables
// are textures.
#include <memory>
#include <string>

#include "stochtex/gpu/gl_context.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

// The generated chunk: `vec3 graphColour(vec2 uv, vec2 jx, vec2 jy)` and
// the samplers it reads (uGraphLeafK, uGraphInverseK, uGraphTableK).
// filtered: the estimators and prefiltered tables (else the point values).
std::string graphProgramSource(const GraphPattern& graph, bool filtered, GraphMoments moments = GraphMoments::Matched);

class GpuGraph {
public:
    // options.source: Point or Estimators (InputError naming `source`
    // otherwise), the paper estimator only; InputError when the graph needs
    // more textures than a fragment shader has units (16). Data is copied
    // to the GPU: the graph need not outlive this object.
    GpuGraph(const GraphPattern& graph, GlContext& context, const FilterOptions& options,
             GraphMoments moments = GraphMoments::Matched);
    ~GpuGraph();
    GpuGraph(const GpuGraph&) = delete;
    GpuGraph& operator=(const GpuGraph&) = delete;

    // The camera mapping of FilteredGraph::render; RGB float. Footprints
    // are the camera's exact Jacobian.
    Image render(const Camera& camera);
    // Draws into the framebuffer bound now, over the current viewport.
    void drawView(const Camera& camera);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stochtex
