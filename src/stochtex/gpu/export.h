#pragma once
// Export of a file's filtered program for engines: the runtime data as
// files and one self-contained GLSL include, so a program that knows
// nothing of stochtex renders it with `vec4 stochtex_sample(vec2 uv)`.
//
// Files written to the folder (manifest.json's "textures" lists the sampler
// uniforms with their files and the GL format to upload each as):
//   manifest.json        parameters and the list of data files (below)
//   stats_K_L.exr        level L of leaf K's pyramid: R = E_L, G = V_L (float32,
//                        or half with the half format)
//   covariance_P_L.exr   R = E_L (of the pair's first leaf), G = C_L — the
//                        pairs whose covariance a lean op reads
//   table_T.exr          prefiltered table T: n² layers of Rx × Ry RGB
//                        (half floats by default for a colour table, manifest
//                        "precision"), layer kx·n + ky in rows [k·Ry, (k+1)·Ry),
//                        row j of a layer holding y = j/(Ry − 1) (T⁻¹ folded in)
//   stochtex.glsl        the include (no #version line: the host adds it)
//   README.md            how to integrate it, with a table of the files written
//                        and their formats (built from what was written)
// The 8-bit format (the paper's §5 layout) writes instead, per leaf pair P,
// stats_P_L.png: RGBA8 (E_x, E_y, V_x, V_y), each channel coded over its
// level's range (the codes are constants of stochtex.glsl and in the
// manifest); covariance_P_L.png: G = C_L coded likewise; and each colour
// table as table_T.png, 8-bit sRGB codes of its linear colours (uploaded as
// an sRGB texture, texelFetch returns linear). A field's (g, g²) table is
// never half (a rounded g would move across the next table's edges): 16-bit
// codes of [0, 1] in a PNG with the 8-bit format where it lies in [0, 1],
// float EXR otherwise.
#include <string>
#include <vector>

#include "stochtex/core/enum_names.h"

#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

// How the data is stored: float (pyramids float32, the colour tables as
// halfTable says), half (pyramids and colour tables half floats) or 8-bit.
enum class ExportFormat { Float, Half, Rgba8 };
extern const EnumNames<ExportFormat> kExportFormatNames;

// A format's size and the accuracy it costs, for the export README and the
// test that holds each format to it: the largest and mean |Δ| of the
// rendered linear RGB against the float export (with its float table), over
// the presets and scales ExportFormats.RenderWithinTheirStatedAccuracy
// renders (tests/gpu/export_test.cpp prints each measurement).
struct ExportFormatAccuracy {
    ExportFormat format;
    const char* storage;  // what each texel costs on the GPU
    double maxError;      // bounds of |Δ| in linear RGB: the largest,
    double p99Error;      // the 99th percentile (of pixel channels)
    double meanError;     // and the mean
};
extern const std::vector<ExportFormatAccuracy> kExportFormatAccuracy;

struct ExportOptions {
    ExportFormat format = ExportFormat::Float;
    // With the float format, the colour tables as half floats: colours in
    // [0, 1] lose at most 2⁻¹² (0.06/255) and the file halves (the smooth
    // table's 100 layers of 256²: 79 → 39 MB raw). The pyramids stay
    // float32: variances go down to ~1e-6.
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
