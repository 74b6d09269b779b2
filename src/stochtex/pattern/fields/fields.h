#pragma once
// The linear field nodes that are no ops: the sources and the linear
// operators that only fold (texture_graph.h). Each is one file here that
// describes the node (its NodeInfo, with its fold, seenThrough and parsed
// hooks, fields/field_node.h) and one line below; affine and sum, which are
// ops too, carry their hooks in their op files (ops/).
#include <vector>

#include "stochtex/pattern/node_info.h"

namespace stochtex {

NodeInfo spectralNoiseNode();
NodeInfo exemplarNode();
NodeInfo tiledFieldNode();
NodeInfo channelNode();
NodeInfo derivativeNode();
NodeInfo transformNode();

// In the order `stochtex nodes` lists them, before the ops.
inline std::vector<NodeInfo> fieldNodeInfos() {
    return {spectralNoiseNode(), exemplarNode(), tiledFieldNode(), channelNode(), derivativeNode(), transformNode()};
}

}  // namespace stochtex
