#pragma once
// Export of a file's filtered program for engines: the runtime data as
// files and one self-contained GLSL include, so a program that knows
// nothing of stochtex renders it with `vec4 stochtex_sample(vec2 uv)`.
//
// Files written to the folder (manifest.json's "textures" lists the sampler
// uniforms with their files):
//   manifest.json        parameters and the list of data files (below)
//   stats_K_L.exr        level L of leaf K's pyramid: R = E_L, G = V_L (float32)
//   covariance_P_L.exr   R = E_L (of the pair's first leaf), G = C_L — the
//                        pairs whose covariance a lean op reads
//   table_T.exr          prefiltered table T: n² layers of Rx × Ry RGB
//                        (half floats by default for a colour table, manifest
//                        "precision"), layer kx·n + ky in rows [k·Ry, (k+1)·Ry),
//                        row j of a layer holding y = j/(Ry − 1) (T⁻¹ folded in)
//   stochtex.glsl        the include (no #version line: the host adds it)
//   README.md            how to integrate it, with a table of the files written
//                        and their formats (built from what was written)
#include <string>

#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

struct ExportOptions {
    // The table as half floats: colours in [0, 1] lose at most 2⁻¹² (0.06/255)
    // and the file halves (the smooth table's 100 layers of 256²: 79 → 39 MB raw).
    // The pyramids stay float32: variances go down to ~1e-6.
    bool halfTable = true;
};

// A program (graph_pattern.h), filtered by moment matching: the files above,
// a field's (g, g²) table in float whatever halfTable says, manifest.json
// with "graph": its leaves, tables and lean ops; stochtex.glsl is its
// generated program (exportedGraphInclude).
// options.source: Estimators (InputError otherwise).
void exportGraph(const GraphPattern& graph, const FilterOptions& options, const std::string& dir,
                 const ExportOptions& exportOptions = {});
// A pattern file's export: exportGraph of the file's program under the
// response (GraphPattern::build), what makeGpuView renders.
void exportPatternSpec(const PatternSpec& spec, const FilterOptions& options, const std::string& dir,
                       const ExportOptions& exportOptions = {});
std::string exportedGraphInclude(const GraphPattern& graph, GraphMoments moments = GraphMoments::Matched,
                                 const GraphEstimator& estimator = {});

}  // namespace stochtex
