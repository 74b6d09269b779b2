#pragma once
// The nodes of texture graphs (texture_graph.h), each described once: its
// inputs, what it gives, and its parameter table (name, description, type,
// default, range). The table drives the JSON parsing and validation of a
// graph, `stochtex nodes`, the workbench's widgets and the per-node
// benchmarks. Every node type is described by its own file: a source or
// linear operator by its file in fields/ (a new one: that file, one line
// in fields/fields.h and one in pattern/CMakeLists.txt), a node evaluated per pixel by its op's (a new op: its
// kernel file, its header and one line in ops/ops.h).
//
// Sources (spectral noise, exemplar, the channels of a K-channel tiled
// field) and linear operators of fields (a directional derivative, an affine
// remap, a weighted sum, a transform of uv; linear maps of Gaussian fields
// are Gaussian, so each folds into the example the field is tiled from) make
// the linear part, which the paper's estimators filter exactly. Transfer
// functions (the 2D colormap H, H read as a field, a 1D curve), the mix of
// colours by a field, a colour from three fields and the LEAN shading of a height field are non-linear:
// a graph with one of them before its output is evaluated per pixel and
// filtered by moment matching (graph_pattern.h).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/pattern/node_info.h"

namespace stochtex {

// Every node, in the order `stochtex nodes` lists them.
const std::vector<NodeInfo>& graphNodes();
// The node called `name`, or null.
const NodeInfo* findGraphNode(const std::string& name);

// The whole table as JSON (for `stochtex nodes --json` and user interfaces):
// [{type, category, description, inputs: [{name, type, description}],
//   output, params: [{name, type, description, default, min, max, choices}]}].
nlohmann::json graphNodesJson();

// The smallest graph file around a node, from the table alone: each field
// input fed by its own spectral_noise (sample parameters), each colour input
// by a colormap of one and a tiled-field input by a tiled_field, the node
// with its defaults and samples (a path reads `exemplarPath`), and a
// colormap reading it when it gives a field (or its first channel, for a
// tiled field), mixed with a noise's colours when it reads no field (a
// constant colour). Used by the per-node benchmarks and the test that every node
// builds and renders.
nlohmann::json sampleNodeGraph(const NodeInfo& node, const std::string& exemplarPath);
// A node of this type as a graph file holds it, its inputs unset: its
// type, and each required parameter at its sample (a path: `imagePath`).
nlohmann::json nodeWithSampleParams(const NodeInfo& node, const std::string& imagePath);

}  // namespace stochtex
