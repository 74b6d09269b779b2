#pragma once
// The nodes of texture graphs (texture_graph.h), each described once: its
// inputs, what it gives, and its parameter table (name, description, type,
// default, range). The table drives the JSON parsing and validation of a
// graph, `stochtex nodes`, and the per-node benchmarks; a new node is a new
// entry here and its operation in texture_graph.cpp.
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

namespace stochtex {

// What flows along an edge: a scalar field, a colour, or a tiled field of
// K channels (tiled_field) whose channels a channel node reads.
enum class PortType { Field, Colour, Channels };
const char* portTypeName(PortType t);

enum class ParamType {
    Number,      // a finite number in [min, max]
    Integer,     // an integer in [min, max]
    Boolean,
    Seed,        // an integer in [0, 2³² − 1]; unset: derived from the graph's seed and the node's id
    Path,        // an image file, relative to the graph file's folder
    Components,  // spectrum components, as a pattern file's noise (docs/PATTERNS.md)
    Colormap,    // a COLORMAP object, as a pattern file's (docs/PATTERNS.md)
    Curve,       // [[x, y], ...]: at least 2 points, x strictly increasing in [0, 1]
    Choice,      // one of ParamInfo::choices (a string)
};
const char* paramTypeName(ParamType t);

struct ParamInfo {
    std::string name;
    ParamType type;
    std::string description;
    nlohmann::json fallback;  // the default; null: required (or, for a seed, derived)
    double min = 0, max = 0;  // Number and Integer
    // For a required parameter: a typical value, used where a graph is built
    // from the table alone (sampleNodeGraph). Null for paths (the caller's).
    nlohmann::json sample = nullptr;
    std::vector<std::string> choices = {};  // Choice
};

struct PortInfo {
    std::string name;
    PortType type;
    std::string description;
};

enum class NodeKind {
    SpectralNoise, Exemplar, TiledField, Channel, Derivative, Affine, Sum, Transform,
    Colormap, ColormapField, Curve, Mix, Compose, Lean
};

struct NodeInfo {
    std::string name;  // the JSON "type"
    NodeKind kind;
    std::string category;  // source, linear, transfer, colour, shading
    std::string description;
    std::vector<PortInfo> inputs;
    PortType output;
    std::vector<ParamInfo> params;
};

// Every node, in the order `stochtex nodes` lists them.
const std::vector<NodeInfo>& graphNodes();
// The node called `name`, or null.
const NodeInfo* findGraphNode(const std::string& name);
// Whether a node's output is linear in its sources' examples (sources and
// linear operators), so that it folds into an example.
bool isLinearNode(NodeKind kind);

// The whole table as JSON (for `stochtex nodes --json` and user interfaces):
// [{type, category, description, inputs: [{name, type, description}],
//   output, params: [{name, type, description, default, min, max, choices}]}].
nlohmann::json graphNodesJson();

// The smallest graph file around a node, from the table alone: each field
// input fed by its own spectral_noise (sample parameters), each colour input
// by a colormap of one and a tiled-field input by a tiled_field, the node
// with its defaults and samples (a path reads `exemplarPath`), and a
// colormap reading it when it gives a field (or its first channel, for a
// tiled field). Used by the per-node benchmarks and the test that every node
// builds and renders.
nlohmann::json sampleNodeGraph(const NodeInfo& node, const std::string& exemplarPath);

}  // namespace stochtex
