#pragma once
// Texture graphs (issue "Texture graphs"; paper §7 and Figure 14): a pattern
// file may describe its pattern as nodes and edges instead of
// {noise_x, noise_y, colormap}:
//   { "name", "seed", "size", "scale", "offsets", "grid_density",
//     "nodes": { ID: { "type": NODE, PORT: ID, ..., PARAM: value, ... }, ... },
//     "output": ID }
// Node types, ports and parameters come from graph_nodes.h; every error
// names the JSON pointer of the value at fault (an unknown node type, port
// or parameter, an edge to a missing node, a colour where a field is
// expected, a missing input, a cycle, a parameter out of range).
//
// Evaluation folds the linear part into the examples (a linear map of a
// tiled field is the tiled field of the mapped example, with the same tiles
// and blend weights), so a graph "linear part → colormap" compiles to a
// plain pattern file's program, two leaves → colormap (GraphPattern;
// docs/GRAPHS.md).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "stochtex/noise/example.h"
#include "stochtex/pattern/graph_nodes.h"
#include "stochtex/pattern/node_info.h"
#include "stochtex/pattern/pattern_parts.h"
#include "stochtex/pattern/uv_transform.h"

namespace stochtex {

class PartCache;  // pattern/part_cache.h

constexpr int kMaxGraphNodes = 256;
// The examples a graph builds hold at most this many texels in all (four of
// 4096²): each node's example is built once and kept while the graph is
// built, with the pyramids, tables and synthesis buffers of what is rendered
// about 24 bytes a texel (2^28 texels took 6.4 GB, as the hostile-input issue
// measured it), so ≈ 1.6 GB at most by that rate.
constexpr long long kMaxGraphExampleTexels = 1ll << 26;
// The spectral noises of a graph cost at most this many component
// evaluations in all (components × size², summed; one noise may cost 2^28,
// noise/spectrum.h): two such noises, ≈ 6 s of synthesis on one core.
constexpr long long kMaxGraphSynthesisWork = 1ll << 29;

struct TextureGraph {
    std::vector<GraphNode> nodes;  // every node after its inputs
    std::string output;            // the node whose colour is the pattern
    const GraphNode& node(const std::string& id) const;
};

// Parses and checks the graph members ("nodes", "output") of a pattern file.
TextureGraph parseTextureGraph(const JsonReader& r, const std::filesystem::path& baseDir);

// The transform of a linear field node. InputError naming the node where a
// derivative reads a transformed field (put the transform after it) or a
// sum reads two fields under different transforms.
UvTransform graphNodeTransform(const TextureGraph& graph, const std::string& id, const std::string& context);

// The tiles a linear field node is tiled with, as a key: the id of its
// tiled_field when every source it reads is a channel of that one tiled
// field (all such nodes share the field's tiles), else the node's own id.
std::string graphTileGroup(const TextureGraph& graph, const std::string& id);

// The seed of a source node without an explicit one: from the pattern seed
// and the node's id (so adding or renaming another node changes nothing).
uint32_t graphNodeSeed(uint32_t patternSeed, const std::string& id);

// The example of any linear field node (NodeInfo::linear), linear nodes folded in (1 channel, W×W;
// a Gaussianized exemplar's values are T(E)). Each node is built once, so a
// node feeding many is not rebuilt for each (time linear in the nodes).
NoiseExample buildGraphField(const TextureGraph& graph, const std::string& id, uint32_t patternSeed,
                             const std::string& context);
// The examples of several linear field nodes, each node built once for all;
// with `parts`, every linear node is a kept part: a node whose nodes
// upstream are those of a kept one is not built again (their texels still
// count against the examples' budget).
std::vector<std::shared_ptr<const NoiseExample>> buildGraphFields(const TextureGraph& graph,
                                                                  const std::vector<std::string>& ids,
                                                                  uint32_t patternSeed, const std::string& context,
                                                                  PartCache* parts = nullptr);

}  // namespace stochtex
