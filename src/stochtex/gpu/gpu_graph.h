#pragma once
// A texture graph rendered by one generated GLSL program (issue "Texture
// graphs"): the graph's program of operations (pattern/graph_pattern.h) is
// written out as GLSL that calls the kernel's functions — tiling and
// blending of each leaf, the footprint statistics of each pair of leaves
// (the kernel's estimator loop, kernel/estimate.glsl, over the texel source
// this chunk defines: a branch per pair's pyramids), table lookups, the
// prefiltered tables' lookup and each op's kernel file (pattern/ops/,
// included) through the table lookups this chunk defines for
// ops/op_host.glsl's OpContext — in the CPU evaluator's order, so that
// the GPU's colours are the CPU's within float rounding. Seeds, means and
// parameters are constants of the program; examples, pyramids and tables
// are textures.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/gpu_view.h"
#include "stochtex/kernel/pattern_params.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

// The generated chunk: the pattern's two colour functions for the graph,
// `vec3 unfilteredColour(vec2 uv)` (the point values) and `vec3
// filteredColour(vec2 uv, vec2 jx, vec2 jy)` (the estimators and the
// prefiltered tables), which the pattern's main files call (pattern.frag,
// filtered.frag, the compute kernels, scene.frag), and the samplers they read
// (uGraphExampleK, uGraphInverseK, uGraphStatsK per leaf; uGraphTableK and
// uGraphPrefilteredK per table the unfiltered or the filtered program reads,
// GraphPattern::readsTable), with the footprint estimator `estimator`
// says (the paper's by default).
using LevelAverages = std::vector<std::vector<kernel::vec3>>;
struct GraphEstimator {
    // Per leaf pair, per level (FootprintEstimator::levelAverages): the
    // Deliot–Heitz baseline, the averages constants of the program; empty:
    // the texels' own variances.
    LevelAverages levelAverages;
    int subProbes = 1;       // per side of each probe (the sub-probes estimators: subProbesOf)
    bool fineMeans = false;  // sub-probes' means from finer reads (fineMeansOf)
    // How the pyramids' texels code the statistics (StatsCoding,
    // gpu/shaders/filtering.glsl), per leaf pair then level: empty, the
    // float data GpuGraph uploads; the export's 8-bit format fills it.
    struct LevelCoding {
        std::array<float, 4> offset{0, 0, 0, 0};  // of (E_x, E_y, V_x, V_y)
        std::array<float, 4> scale{1, 1, 1, 1};
        std::array<float, 2> covariance{0, 1};  // (offset, scale) of C
    };
    std::vector<std::vector<LevelCoding>> pyramidCoding;
    // One RGBA pyramid per pair, (E_x, E_y, V_x, V_y) (the paper's layout):
    // sampler uGraphPairStatsP replaces the leaves' uGraphStatsK.
    bool packedPairs = false;
};
std::string graphProgramSource(const GraphPattern& graph, GraphMoments moments = GraphMoments::Matched,
                               const GraphEstimator& estimator = {});
// The PatternParameters block's values (kernel/pattern_params.h) for a
// graph under `options`: what GpuGraph uploads and the web page embeds.
kernel::PatternParams patternParams(const GraphPattern& graph, const FilterOptions& options);
// The estimator `options` choose, for graphProgramSource: the level averages
// [DH19] from the filtered graph's estimators when it is Deliot–Heitz.
GraphEstimator graphEstimator(const FilteredGraph& filtered, const FilterOptions& options);

// The textures the graph's program samples (graphProgramSource declares
// them): the point set (examples, T⁻¹ LUTs, the tables the unfiltered
// program reads) and, with `filtered`, the statistics (a pyramid per leaf,
// or per pair where `packedPairs`), covariance pyramids and the tables the
// filtered program reads (GraphPattern::readsTable).
int graphTextureUnits(const GraphPattern& graph, bool filtered, bool packedPairs, GraphMoments moments);
// InputError when the graph's program needs more textures than a fragment
// shader has units (16) (graphTextureUnits, a pyramid per leaf).
void checkGraphTextureUnits(const GraphPattern& graph, bool filtered, GraphMoments moments = GraphMoments::Matched);

class GpuGraph final : public GpuView {
public:
    // options.source: Point or Estimators (InputError naming `source`
    // otherwise), either variance estimator; InputError when the graph needs
    // more textures than a fragment shader has units (16). Data is copied
    // to the GPU: the graph need not outlive this object.
    // With `parts`, the estimators, prefiltered tables and atlases built
    // before from the same inputs are taken from it (PartCache).
    GpuGraph(const GraphPattern& graph, GlContext& context, const FilterOptions& options,
             GraphMoments moments = GraphMoments::Matched, PartCache* parts = nullptr);
    ~GpuGraph() override;

    // Binds the graph's textures (the point set, and the filtered set when
    // filtering), its parameters and the sky colour to `program`.
    void bind(unsigned program) const override;
    bool filtered() const override;

private:
    // The filtered graph (pyramids, tables, sky, level averages) is built
    // before the program, which takes the averages as constants.
    GpuGraph(const GraphPattern& graph, GlContext& context, const FilterOptions& options, GraphMoments moments,
             std::shared_ptr<const FilteredGraph> filtered, PartCache* parts);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The GPU view of a pattern file: GpuGraph running the file's program under
// the options' response (GraphPattern::build; what it is built from is not
// kept). With `parts`, every part built before from the same inputs is taken
// from it, and the new ones kept there (the workbench's edits).
std::unique_ptr<GpuView> makeGpuView(const PatternSpec& spec, GlContext& context, const FilterOptions& options,
                                     PartCache* parts = nullptr);

// The same on a headless OpenGL context of its own (GlContext::headless),
// run as `pipeline` with footprints from `derivatives`: the GPU's
// ViewRenderer for a pattern file (render --gpu, bake-image --gpu).
std::unique_ptr<ViewRenderer> makeGpuRenderer(const PatternSpec& spec, const FilterOptions& options,
                                              GpuView::Pipeline pipeline = GpuView::Pipeline::Fragment,
                                              GpuView::Derivatives derivatives = GpuView::Derivatives::Camera);

}  // namespace stochtex
