#pragma once
// What a linear node (a source or a linear operator of fields) is given to
// fold itself into an example (NodeInfo::fold) and to say which transform
// of uv it is seen through (NodeInfo::seenThrough). The graph builder
// (texture_graph.cpp) fills these; each node's own file (fields/, and the
// ops affine and sum) reads them. A new linear node is its file in fields/,
// one line in fields/fields.h and its file in pattern/CMakeLists.txt.
#include <cstdint>
#include <functional>
#include <string>

#include "stochtex/noise/example.h"
#include "stochtex/pattern/node_info.h"
#include "stochtex/pattern/uv_transform.h"

namespace stochtex {

struct FieldFold {
    const GraphNode& node;
    std::string where;      // "CONTEXT: node \"ID\"", for errors
    std::function<uint32_t()> defaultSeed;  // a source's seed when the node sets none (graphNodeSeed)
    // An input's example, refused with an InputError naming the node when it
    // is a Gaussianized exemplar (whose field is not linear in its example).
    std::function<NoiseExample(const std::string& port)> linearInput;
    // An input's example as it is (a transform passes it on).
    std::function<NoiseExample(const std::string& port)> input;
    // The node an input port reads.
    std::function<const GraphNode&(const std::string& port)> inputNode;
    double number(const char* name) const { return node.numbers.at(name); }
};

struct FieldSight {
    const GraphNode& node;
    std::string where;  // "CONTEXT: node \"ID\" (TYPE)", for errors
    std::function<UvTransform(const std::string& port)> input;  // the transform an input is seen through
    double number(const char* name) const { return node.numbers.at(name); }
};

// The transform an input port's field is seen through, passed on (affine,
// a derivative's check aside).
inline UvTransform inputSight(const FieldSight& s) { return s.input("input"); }

}  // namespace stochtex
