#include "stochtex/pattern/graph_nodes.h"

#include "stochtex/pattern/fields/fields.h"
#include "stochtex/pattern/ops/ops.h"

namespace stochtex {

const std::vector<NodeInfo>& graphNodes() {
    static const std::vector<NodeInfo> nodes = [] {
        std::vector<NodeInfo> n = fieldNodeInfos();
        for (NodeInfo& op : opNodeInfos()) n.push_back(std::move(op));
        return n;
    }();
    return nodes;
}

const NodeInfo* findGraphNode(const std::string& name) {
    for (const NodeInfo& n : graphNodes())
        if (n.name == name) return &n;
    return nullptr;
}

nlohmann::json graphNodesJson() {
    nlohmann::json all = nlohmann::json::array();
    for (const NodeInfo& n : graphNodes()) {
        nlohmann::json inputs = nlohmann::json::array(), params = nlohmann::json::array();
        for (const PortInfo& p : n.inputs)
            inputs.push_back({{"name", p.name}, {"type", portTypeName(p.type)}, {"description", p.description}});
        for (const ParamInfo& p : n.params) {
            nlohmann::json j = {{"name", p.name}, {"type", paramTypeName(p.type)}, {"description", p.description},
                                {"default", p.fallback}};
            if (p.type == ParamType::Number || p.type == ParamType::Integer) j["min"] = p.min, j["max"] = p.max;
            if (p.type == ParamType::Choice) j["choices"] = p.choices;
            params.push_back(std::move(j));
        }
        all.push_back({{"type", n.name},
                       {"category", n.category},
                       {"description", n.description},
                       {"inputs", inputs},
                       {"output", portTypeName(n.output)},
                       {"params", params}});
    }
    return all;
}

nlohmann::json nodeWithSampleParams(const NodeInfo& node, const std::string& imagePath) {
    nlohmann::json j = {{"type", node.name}};
    for (const ParamInfo& p : node.params)
        if (p.type == ParamType::Path) j[p.name] = imagePath;
        else if (p.required() && !p.sample.is_null()) j[p.name] = p.sample;
    return j;
}

nlohmann::json sampleNodeGraph(const NodeInfo& node, const std::string& exemplarPath) {
    using json = nlohmann::json;
    const auto withParams = [&](const NodeInfo& info) { return nodeWithSampleParams(info, exemplarPath); };
    json nodes = json::object();
    json self = withParams(node);
    for (const PortInfo& in : node.inputs) {
        const std::string id = "in_" + in.name;
        self[in.name] = id;
        if (in.type == PortType::Field) {
            nodes[id] = withParams(*findGraphNode("spectral_noise"));
        } else if (in.type == PortType::Channels) {
            nodes[id] = withParams(*findGraphNode("tiled_field"));
        } else {
            json colours = withParams(*findGraphNode("colormap"));
            colours["x"] = colours["y"] = id + "_noise";
            nodes[id] = colours;
            nodes[id + "_noise"] = withParams(*findGraphNode("spectral_noise"));
        }
    }
    nodes["node"] = self;
    // A field (or a tiled field's first channel) shown through a colormap.
    std::string field = "node", output = "node";
    if (node.output == PortType::Channels) {
        json channel = withParams(*findGraphNode("channel"));
        channel["field"] = "node";
        nodes["node_channel"] = channel;
        field = "node_channel";
    }
    if (node.inputs.empty() && node.output == PortType::Colour) {
        // A constant: mixed with a noise's colours, as a texture needs a field.
        json noise = withParams(*findGraphNode("spectral_noise"));
        json colours = withParams(*findGraphNode("colormap"));
        colours["x"] = colours["y"] = "noise";
        json mix = withParams(*findGraphNode("mix"));
        mix["a"] = "node", mix["b"] = "colours", mix["t"] = "noise";
        nodes["noise"] = noise, nodes["colours"] = colours, nodes["mix"] = mix;
        output = "mix";
    }
    if (node.output != PortType::Colour) {
        json colormap = withParams(*findGraphNode("colormap"));
        colormap["x"] = field;
        colormap["y"] = field;
        nodes["colour"] = colormap;
        output = "colour";
    }
    return {{"name", "sample-" + node.name}, {"size", 64}, {"nodes", nodes}, {"output", output}};
}

}  // namespace stochtex
