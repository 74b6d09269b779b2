#pragma once
// Export of a filtered pattern for engines: the runtime data as files and
// one self-contained GLSL include, so a program that knows nothing of
// stochtex renders Ŝ = H̄(μ̂, σ̂) with `vec4 stochtex_sample(vec2 uv)`.
//
// Files written to the folder (manifest.json's "textures" lists the sampler
// uniforms with their files):
//   manifest.json        parameters and the list of data files (below)
//   stats_x_L.exr        level L of noise x's pyramid: R = E_L, G = V_L (float32)
//   stats_y_L.exr        the same for noise y
//   covariance_L.exr     R = E_L (of x), G = C_L — only with shared offsets
//   table.exr            the prefiltered table: n² layers of Rx × Ry RGB
//                        (half floats by default, manifest "precision"),
//                        layer kx·n + ky in rows [k·Ry, (k+1)·Ry), row j of
//                        a layer holding y = j/(Ry − 1) (T⁻¹ already folded in)
//   stochtex.glsl        the include (no #version line: the host adds it)
//   README.md            how to integrate it, with a table of the files written
//                        and their formats (built from what was written)
#include <string>

#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

struct ExportOptions {
    // The table as half floats: colours in [0, 1] lose at most 2⁻¹² (0.06/255)
    // and the file halves (the smooth table's 100 layers of 256²: 79 → 39 MB raw).
    // The pyramids stay float32: variances go down to ~1e-6.
    bool halfTable = true;
};

// The hand-written pattern shaders' export of a pattern's colours (the
// colormap response; a file's normal map is its program's: exportGraph).
// options.source: Estimators (InputError naming `source` otherwise). The folder is created if missing.
void exportPattern(const Pattern& pattern, const FilterOptions& options, const std::string& dir,
                   const ExportOptions& exportOptions = {});

// The include's text (what exportPattern's stochtex.glsl holds).
std::string exportedShaderInclude();

// A texture graph that is not a pattern H∘N (graph_pattern.h), filtered by
// moment matching: stats_K_L.exr per leaf K (R = E_L, G = V_L),
// table_T.exr per table (the prefiltered layers of its (g, g²) or colour
// table, as table.exr; a field's table in float whatever halfTable says), manifest.json (with "graph": its leaves and tables),
// stochtex.glsl (its generated program, exportedGraphInclude) and README.md.
// options.source: Estimators, the paper estimator (InputError otherwise).
void exportGraph(const GraphPattern& graph, const FilterOptions& options, const std::string& dir,
                 const ExportOptions& exportOptions = {});
// A pattern file's export: exportGraph of the file's program under the
// response (GraphPattern::build), what makeGpuView renders.
void exportPatternSpec(const PatternSpec& spec, const FilterOptions& options, const std::string& dir,
                       const ExportOptions& exportOptions = {});
std::string exportedGraphInclude(const GraphPattern& graph, GraphMoments moments = GraphMoments::Matched,
                                 const LevelAverages& levelAverages = {});

}  // namespace stochtex
