#include "stochtex/pattern/graph_nodes.h"

#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/ops/ops.h"
#include "stochtex/pattern/pattern_members.h"

namespace stochtex {

const std::vector<NodeInfo>& graphNodes() {
    using json = nlohmann::json;
    static const std::vector<NodeInfo> nodes = [] {
        std::vector<NodeInfo> n = {
        {"spectral_noise", NodeKind::SpectralNoise, "source",
         "A periodic Gaussian example synthesised from a power spectrum (paper §3), tiled and blended",
         {},
         PortType::Field,
         {patternMembers().noiseSize,
          {"seed", ParamType::Seed, "Seed of the white noise (default: from the graph seed and the node id)", json()},
          patternMembers().noiseMean,
          patternMembers().noiseStddev,
          {"quadrature", ParamType::Boolean, "The Hilbert partner of the same white noise (a phase shift of π/2)", false},
          {"components", ParamType::Components, "Spectrum components: lowpass, ring or bilobe (docs/PATTERNS.md)",
           json(), 0, 0, json::parse(R"([{"shape": "lowpass", "cutoff": 8}])")}}},
        {"exemplar", NodeKind::Exemplar, "source", "An image as the example (periodic), tiled and blended",
         {},
         PortType::Field,
         {{"path", ParamType::Path, "The image (1 channel or colour, taken as gray), relative to the graph file", json()},
          {"gaussianize", ParamType::Boolean,
           "Blend the histogram-transformed exemplar and map back (paper §5); such a field feeds a transfer "
           "function directly, not a linear node",
           true}}},
        {"tiled_field", NodeKind::TiledField, "source",
         "An image of K channels (1 to 4) as K examples tiled and blended with the same tiles and weights: a "
         "noise vector field (paper eq. 7) whose channels keep their correlations; channel nodes read them",
         {},
         PortType::Channels,
         {{"path", ParamType::Path, "The image (1 to 4 channels), relative to the graph file", json()},
          {"transfer", ParamType::Choice,
           "How its codes become values: auto (srgb, but linear for a float file such as EXR), srgb (colour channels "
           "decoded to linear light; alpha stays data) or linear (as data)",
           "auto", 0, 0, nullptr, {"auto", "srgb", "linear"}},
          {"gaussianize", ParamType::Boolean,
           "Blend each channel's histogram-transformed example and map back (paper §5); such a channel feeds a "
           "transfer function directly, not a linear node",
           true}}},
        {"channel", NodeKind::Channel, "linear",
         "One channel of a tiled field, on the tiles every channel of that field shares",
         {{"field", PortType::Channels, "The tiled field"}},
         PortType::Field,
         {{"index", ParamType::Integer, "The channel, from 0 (red, green, blue, alpha of a colour image)", 0, 0, 3}}},
        {"derivative", NodeKind::Derivative, "linear",
         "Directional derivative of a field, exact on its example (spectral), rescaled about a mean",
         {{"input", PortType::Field, "The field"}},
         PortType::Field,
         {{"angle", ParamType::Number, "Direction, degrees from +u towards +v", 0, -360, 360},
          {"mean", ParamType::Number, "Mean of the result", 0.5, 0, 1},
          {"stddev", ParamType::Number, "Standard deviation of the result", 1.0 / 6.0, 1e-4, 0.5}}},
        {"transform", NodeKind::Transform, "linear",
         "The field seen through a transform of uv: input(scale · R(angle) · uv + offset), tiles and all",
         {{"input", PortType::Field, "The field"}},
         PortType::Field,
         {{"angle", ParamType::Number, "Rotation, degrees from +u towards +v", 0, -360, 360},
          {"scale", ParamType::Number, "Scale of uv (2: features half as large)", 1, 1.0 / 64, 64},
          {"offset_u", ParamType::Number, "Offset along u, example periods", 0, -1e4, 1e4},
          {"offset_v", ParamType::Number, "Offset along v, example periods", 0, -1e4, 1e4}}},
    };
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
