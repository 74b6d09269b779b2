#pragma once
// A graph node type described once (its ports and parameters: NodeInfo) and
// a node of a graph file as parsed (GraphNode). Plain values only, so that
// the node table (graph_nodes.h), the parser (texture_graph.h) and each op's
// own file (ops/) read them without including each other.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/pattern_file.h"

namespace stochtex {

// What flows along an edge: a scalar field, a colour, or a tiled field of
// K channels (tiled_field) whose channels a channel node reads.
enum class PortType { Field, Colour, Channels };
inline const char* portTypeName(PortType t) {
    if (t == PortType::Field) return "field";
    return t == PortType::Colour ? "colour" : "tiled field";
}

struct PortInfo {
    std::string name;
    PortType type;
    std::string description;
};

class JsonReader;
class NoiseExample;
struct FieldFold;   // fields/field_node.h
struct FieldSight;  // fields/field_node.h
struct GraphNode;
struct UvTransform;

// What the graph parser does with a node: the sources and linear operators
// fold into the examples a graph's leaves are tiled from (they have `fold`;
// texture_graph.h); every other node is an op, evaluated per pixel, which
// `op` names. affine and sum are both: linear over fields that fold, ops
// over the outputs of ops. A node type declares what it does through these
// members, so that no code outside its own file asks which type it is.
struct NodeInfo {
    std::string name;      // the JSON "type"
    std::string category;  // source, linear, transfer, colour, shading
    std::string description;
    std::vector<PortInfo> inputs;
    PortType output;
    std::vector<ParamInfo> params;
    int op = -1;  // an op's index in ops/ops.h's list (OpParams' alternatives); −1: not an op
    // An op's first input port that it reads through the slopes of its field
    // (a lean node's height): the program gives it two leaves, the field's
    // slopes along u and v scaled to the node's "amplitude", on the field's
    // tiles, with their covariance when its "covariance" is on; the op's
    // inputs are those two, then its other ports. Empty: none.
    std::string slopesOf{};
    // A linear node's example from its inputs' (null: not linear, an op only).
    NoiseExample (*fold)(const FieldFold&) = nullptr;
    // The transform of uv a linear node is seen through, from its inputs'
    // (null: none, as a source's).
    UvTransform (*seenThrough)(const FieldSight&) = nullptr;
    // What a source sets up once its parameters are parsed (its NoiseSpec).
    void (*parsed)(GraphNode&, const JsonReader&) = nullptr;
    // Whether the node folds into an example over inputs that fold (affine
    // and sum: only then; over an op's output they are ops).
    bool linear() const { return fold != nullptr; }
};

struct GraphNode {
    std::string id;
    const NodeInfo* info = nullptr;
    std::map<std::string, std::string> inputs;  // port → node id
    std::map<std::string, double> numbers;      // Number, Integer, Boolean (0/1) parameters, defaults filled
    std::optional<uint32_t> seed;               // the Seed parameter when given
    // The offset seed of the node's tiles, where a plain pattern's file fixes
    // it (its normal map's height); no file parameter. Unset: the leaf's.
    std::optional<uint32_t> tileSeed;
    NoiseSpec noise;                           // sources: the example's description
    ColormapSpec colormap;                     // colormap and colormap_field nodes
    std::vector<std::array<double, 2>> curve;  // curve nodes: the points
    Rgb colour{0.0f, 0.0f, 0.0f};              // colour nodes: the colour, linear light
    // Choice parameters: the index of the value in ParamInfo::choices (in numbers).

    // Equal nodes over equal inputs build the same field (PartCache's key).
    bool operator==(const GraphNode&) const = default;
};

}  // namespace stochtex
