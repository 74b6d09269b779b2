#include "stochtex/pattern/graph_nodes.h"

#include "stochtex/noise/spectrum.h"

namespace stochtex {

const char* portTypeName(PortType t) { return t == PortType::Field ? "field" : "colour"; }

const char* paramTypeName(ParamType t) {
    switch (t) {
        case ParamType::Number: return "number";
        case ParamType::Integer: return "integer";
        case ParamType::Boolean: return "boolean";
        case ParamType::Seed: return "seed";
        case ParamType::Path: return "path";
        case ParamType::Components: return "components";
        case ParamType::Colormap: break;
    }
    return "colormap";
}

const std::vector<NodeInfo>& graphNodes() {
    using json = nlohmann::json;
    static const std::vector<NodeInfo> nodes = {
        {"spectral_noise", NodeKind::SpectralNoise, "source",
         "A periodic Gaussian example synthesised from a power spectrum (paper §3), tiled and blended",
         {},
         PortType::Field,
         {{"size", ParamType::Integer, "Example side, texels (a power of two)", 256, 8, kMaxExampleSize},
          {"seed", ParamType::Seed, "Seed of the white noise (default: from the graph seed and the node id)", json()},
          {"mean", ParamType::Number, "Mean of the example", 0.5, 0, 1},
          {"stddev", ParamType::Number, "Standard deviation of the example", 1.0 / 6.0, 1e-4, 0.5},
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
        {"derivative", NodeKind::Derivative, "linear",
         "Directional derivative of a field, exact on its example (spectral), rescaled about a mean",
         {{"input", PortType::Field, "The field"}},
         PortType::Field,
         {{"angle", ParamType::Number, "Direction, degrees from +u towards +v", 0, -360, 360},
          {"mean", ParamType::Number, "Mean of the result", 0.5, 0, 1},
          {"stddev", ParamType::Number, "Standard deviation of the result", 1.0 / 6.0, 1e-4, 0.5}}},
        {"affine", NodeKind::Affine, "linear", "scale · field + offset",
         {{"input", PortType::Field, "The field"}},
         PortType::Field,
         {{"scale", ParamType::Number, "Factor", 1, -100, 100}, {"offset", ParamType::Number, "Added", 0, -100, 100}}},
        {"sum", NodeKind::Sum, "linear", "weight_a · a + weight_b · b, two fields with examples of one size",
         {{"a", PortType::Field, "First field"}, {"b", PortType::Field, "Second field"}},
         PortType::Field,
         {{"weight_a", ParamType::Number, "Weight of a", 0.5, -100, 100},
          {"weight_b", ParamType::Number, "Weight of b", 0.5, -100, 100}}},
        {"colormap", NodeKind::Colormap, "transfer", "The 2D transfer function H: colour = H(x, y) (paper eq. 1)",
         {{"x", PortType::Field, "N_x, the colormap's horizontal coordinate"},
          {"y", PortType::Field, "N_y, the colormap's vertical coordinate"}},
         PortType::Colour,
         {{"colormap", ParamType::Colormap, "A COLORMAP: analytic, phasor, image or painted (docs/PATTERNS.md)",
           json(), 0, 0, json::parse(R"({"type": "gaussian"})")}}},
    };
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

nlohmann::json sampleNodeGraph(const NodeInfo& node, const std::string& exemplarPath) {
    using json = nlohmann::json;
    const auto withParams = [&](const NodeInfo& info) {
        json j = {{"type", info.name}};
        for (const ParamInfo& p : info.params)
            if (p.type == ParamType::Path) j[p.name] = exemplarPath;
            else if (p.fallback.is_null() && !p.sample.is_null()) j[p.name] = p.sample;
        return j;
    };
    json nodes = json::object();
    json self = withParams(node);
    for (const PortInfo& in : node.inputs) {
        nodes["in_" + in.name] = withParams(*findGraphNode("spectral_noise"));
        self[in.name] = "in_" + in.name;
    }
    nodes["node"] = self;
    std::string output = "node";
    if (node.output == PortType::Field) {
        json colormap = withParams(*findGraphNode("colormap"));
        colormap["x"] = "node";
        colormap["y"] = "node";
        nodes["colour"] = colormap;
        output = "colour";
    }
    return {{"name", "sample-" + node.name}, {"size", 64}, {"nodes", nodes}, {"output", output}};
}

}  // namespace stochtex
