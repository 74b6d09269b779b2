#include "stochtex/pattern/texture_graph.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <set>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/noise/slopes.h"
#include "stochtex/pattern/ops/colormap_op.h"

namespace stochtex {

namespace {

bool validId(const std::string& id) {
    if (id.empty() || id.size() > 64) return false;
    return std::all_of(id.begin(), id.end(), [](char c) { return std::isalnum((unsigned char)c) || c == '_' || c == '-'; });
}

std::string knownTypes() {
    std::string s;
    for (const NodeInfo& n : graphNodes()) s += (s.empty() ? "" : ", ") + n.name;
    return s;
}

// A curve's points: [[x, y], ...], x strictly increasing in [0, 1].
std::vector<std::array<double, 2>> parseCurve(const JsonReader& r) {
    constexpr size_t kMaxPoints = 1024;
    const size_t count = r.arraySize();
    if (count < 2 || count > kMaxPoints)
        r.fail("a curve needs 2 to " + std::to_string(kMaxPoints) + " points [x, y], got " + std::to_string(count));
    std::vector<std::array<double, 2>> points;
    for (size_t i = 0; i < count; ++i) {
        const JsonReader p = r.at(i);
        if (p.arraySize() != 2) p.fail("a point is [x, y]");
        const double x = p.at(0).number(0, 1), y = p.at(1).number(-100, 100);
        if (!points.empty() && !(x > points.back()[0]))
            p.at(0).fail("x must increase from point to point (after " + std::to_string(points.back()[0]) + ")");
        points.push_back({x, y});
    }
    return points;
}

// One node's members: its type, its input ports, its parameters by the table.
GraphNode parseNode(const JsonReader& n, const std::string& id, const std::filesystem::path& baseDir) {
    if (!validId(id)) n.fail("node ids are 1–64 letters, digits, '_' or '-'");
    if (!n.value().is_object()) n.fail("expected a node object with a \"type\"");
    const std::string type = n.at("type").string();
    GraphNode g;
    g.id = id;
    g.info = findGraphNode(type);
    if (!g.info) n.at("type").fail("unknown node type \"" + type + "\"; known: " + knownTypes());
    const NodeInfo& info = *g.info;
    for (auto item = n.value().begin(); item != n.value().end(); ++item) {
        const std::string key = item.key();  // a plain variable: lambdas below capture it (clang 14)
        const bool known = key == "type" ||
                           std::any_of(info.inputs.begin(), info.inputs.end(), [&](const PortInfo& p) { return p.name == key; }) ||
                           std::any_of(info.params.begin(), info.params.end(), [&](const ParamInfo& p) { return p.name == key; });
        if (known) continue;
        std::string names;
        for (const PortInfo& p : info.inputs) names += (names.empty() ? "" : ", ") + p.name;
        for (const ParamInfo& p : info.params) names += (names.empty() ? "" : ", ") + p.name;
        n.at(key).fail("a " + type + " node has no port or parameter \"" + key + "\"; it has: " + names);
    }
    for (const PortInfo& p : info.inputs) {
        if (!n.has(p.name)) n.fail("a " + type + " node needs its input \"" + p.name + "\" (a " + portTypeName(p.type) + ")");
        g.inputs[p.name] = n.at(p.name).string();
    }
    for (const ParamInfo& p : info.params) {
        const bool required = p.fallback.is_null();
        if (required && p.type != ParamType::Seed && !n.has(p.name)) n.fail("a " + type + " node needs \"" + p.name + "\"");
        switch (p.type) {
            case ParamType::Number:
                g.numbers[p.name] = n.number(p.name, p.fallback.get<double>(), p.min, p.max);
                break;
            case ParamType::Integer:
                g.numbers[p.name] = n.integer(p.name, p.fallback.get<int>(), int(p.min), int(p.max));
                break;
            case ParamType::Boolean: g.numbers[p.name] = n.boolean(p.name, p.fallback.get<bool>()) ? 1 : 0; break;
            case ParamType::Seed:
                if (n.has(p.name)) g.seed = n.at(p.name).uint32();
                break;
            case ParamType::Path: g.noise.image = resolveInputPath(n.at(p.name), baseDir); break;
            case ParamType::Components: {
                const JsonReader comps = n.at(p.name);
                const size_t count = comps.arraySize();
                if (count == 0) comps.fail("needs at least one spectrum component");
                for (size_t i = 0; i < count; ++i) g.noise.spectrum.components.push_back(parseSpectrumComponent(comps.at(i)));
                break;
            }
            case ParamType::Colormap: g.colormap = parseColormapSpec(n.at(p.name), baseDir); break;
            case ParamType::Curve: g.curve = parseCurve(n.at(p.name)); break;
            case ParamType::Colour:
                g.colour = n.has(p.name) ? parseLinearColour(n.at(p.name))
                                         : parseLinearColour(JsonReader(p.fallback, "the default of " + p.name));
                break;
            case ParamType::Choice: {
                const std::string value = n.has(p.name) ? n.at(p.name).string() : p.fallback.get<std::string>();
                const auto it = std::find(p.choices.begin(), p.choices.end(), value);
                if (it == p.choices.end()) {
                    std::string names;
                    for (const std::string& c : p.choices) names += (names.empty() ? "" : ", ") + c;
                    n.at(p.name).fail("unknown value \"" + value + "\"; expected one of " + names);
                }
                g.numbers[p.name] = double(it - p.choices.begin());
                break;
            }
        }
    }
    // The sources' example descriptions, as a pattern file's noises.
    if (info.kind == NodeKind::SpectralNoise) {
        SpectrumSpec& s = g.noise.spectrum;
        g.noise.source = NoiseSpec::Source::Spectrum;
        s.size = int(g.numbers["size"]);
        s.mean = g.numbers["mean"];
        s.stddev = g.numbers["stddev"];
        s.quadrature = g.numbers["quadrature"] != 0;
        g.noise.explicitSeed = g.seed.has_value();
        checkSpectrumSpec(n, s);
    } else if (info.kind == NodeKind::Exemplar || info.kind == NodeKind::TiledField) {
        g.noise.source = NoiseSpec::Source::Image;
        g.noise.gaussianize = g.numbers["gaussianize"] != 0;
        if (info.kind == NodeKind::TiledField && g.numbers["transfer"] != 0)  // 0: auto
            g.noise.transfer = g.numbers["transfer"] == 1 ? Transfer::Srgb : Transfer::Linear;
    }
    return g;
}

}  // namespace

const GraphNode& TextureGraph::node(const std::string& id) const {
    for (const GraphNode& n : nodes)
        if (n.id == id) return n;
    throw std::out_of_range("TextureGraph::node: no node " + id);
}

TextureGraph parseTextureGraph(const JsonReader& r, const std::filesystem::path& baseDir) {
    const JsonReader nodes = r.at("nodes");
    if (!nodes.value().is_object()) nodes.fail("expected an object of nodes by id");
    if (nodes.value().empty()) nodes.fail("needs at least one node");
    if (nodes.value().size() > size_t(kMaxGraphNodes))
        nodes.fail("has " + std::to_string(nodes.value().size()) + " nodes, more than " + std::to_string(kMaxGraphNodes));
    std::map<std::string, GraphNode> byId;
    for (const auto& [id, value] : nodes.value().items()) {
        (void)value;
        byId.emplace(id, parseNode(nodes.at(id), id, baseDir));
    }
    // Edges: each input names a node whose output has the port's type.
    for (const auto& [id, g] : byId)
        for (const PortInfo& p : g.info->inputs) {
            const JsonReader edge = nodes.at(id).at(p.name);
            const std::string& from = g.inputs.at(p.name);
            const auto it = byId.find(from);
            if (it == byId.end()) edge.fail("no node \"" + from + "\"");
            if (it->second.info->output != p.type)
                edge.fail("expects a " + std::string(portTypeName(p.type)) + ", but \"" + from + "\" (" +
                          it->second.info->name + ") gives a " + portTypeName(it->second.info->output));
        }
    // Depth-first order (inputs first); an edge back to a node on the path is a cycle.
    TextureGraph graph;
    std::map<std::string, int> state;  // 1: on the path, 2: done
    std::vector<std::string> path;
    const std::function<void(const std::string&)> visit = [&](const std::string& id) {
        state[id] = 1;
        path.push_back(id);
        const GraphNode& g = byId.at(id);
        for (const PortInfo& p : g.info->inputs) {
            const std::string& from = g.inputs.at(p.name);
            if (state[from] == 1) {
                std::string cycle;
                for (auto it = std::find(path.begin(), path.end(), from); it != path.end(); ++it) cycle += *it + " → ";
                nodes.at(id).at(p.name).fail("closes a cycle: " + cycle + from);
            }
            if (state[from] == 0) visit(from);
        }
        path.pop_back();
        state[id] = 2;
        graph.nodes.push_back(g);
    };
    for (const auto& [id, g] : byId)
        if (state[id] == 0) visit(id);
    const JsonReader out = r.at("output");
    graph.output = out.string();
    const auto it = byId.find(graph.output);
    if (it == byId.end()) out.fail("no node \"" + graph.output + "\"");
    if (it->second.info->output != PortType::Colour)
        out.fail("the output must be a colour, but \"" + graph.output + "\" (" + it->second.info->name + ") gives a " +
                 portTypeName(it->second.info->output));
    return graph;
}

namespace {

UvTransform nodeTransform(const TextureGraph& graph, const std::string& id, const std::string& context,
                          std::map<std::string, UvTransform>& memo) {
    if (const auto it = memo.find(id); it != memo.end()) return it->second;
    const GraphNode& g = graph.node(id);
    const std::string where = context + ": node \"" + id + "\" (" + g.info->name + ")";
    const auto input = [&](const char* port) { return nodeTransform(graph, g.inputs.at(port), context, memo); };
    UvTransform r;
    switch (g.info->kind) {
        case NodeKind::Transform: {
            // input(M_in · (A·uv + b) + t_in): A = scale·R(angle), b = offset.
            const UvTransform in = input("input");
            const double a = g.numbers.at("angle") * std::numbers::pi / 180, k = g.numbers.at("scale");
            const double c = k * std::cos(a), s = k * std::sin(a);
            const std::array<double, 4> m{c, -s, s, c};
            const std::array<double, 2> b{g.numbers.at("offset_u"), g.numbers.at("offset_v")};
            r.m = {in.m[0] * m[0] + in.m[1] * m[2], in.m[0] * m[1] + in.m[1] * m[3], in.m[2] * m[0] + in.m[3] * m[2],
                   in.m[2] * m[1] + in.m[3] * m[3]};
            const std::array<double, 2> mb = in.linear(b[0], b[1]);
            r.t = {mb[0] + in.t[0], mb[1] + in.t[1]};
            break;
        }
        case NodeKind::Derivative:
            if (!input("input").identity())
                throw InputError(where + ": its input is seen through a transform of uv; put the transform after the "
                                         "derivative");
            break;
        case NodeKind::Affine: r = input("input"); break;
        case NodeKind::Sum:
            r = input("a");
            if (!(input("b") == r))
                throw InputError(where + ": its inputs are seen through different transforms of uv; a sum needs one");
            break;
        case NodeKind::SpectralNoise:
        case NodeKind::Exemplar:
        case NodeKind::TiledField:
        case NodeKind::Channel: break;
        case NodeKind::Op: throw std::logic_error("graphNodeTransform: node " + id + " is not linear in its sources");
    }
    memo.emplace(id, r);
    return r;
}

}  // namespace

UvTransform graphNodeTransform(const TextureGraph& graph, const std::string& id, const std::string& context) {
    std::map<std::string, UvTransform> memo;
    return nodeTransform(graph, id, context, memo);
}

std::string graphTileGroup(const TextureGraph& graph, const std::string& id) {
    std::set<std::string> fields, seen;  // the tiled fields upstream, the nodes visited
    bool otherSource = false;
    std::vector<std::string> todo{id};
    while (!todo.empty()) {
        const std::string n = todo.back();
        todo.pop_back();
        if (!seen.insert(n).second) continue;
        const GraphNode& g = graph.node(n);
        if (g.info->kind == NodeKind::TiledField) fields.insert(n);
        else if (g.info->inputs.empty()) otherSource = true;
        for (const auto& [port, from] : g.inputs) todo.push_back(from);
    }
    return fields.size() == 1 && !otherSource ? *fields.begin() : id;
}

uint32_t graphNodeSeed(uint32_t patternSeed, const std::string& id) {
    // FNV-1a of the id, then the kernel's hash with the pattern seed.
    uint32_t h = 2166136261u;
    for (unsigned char c : id) h = (h ^ c) * 16777619u;
    return deriveSeed(patternSeed, h);
}

namespace {

// Examples built so far, by node id, and their texels in all.
struct FieldCache {
    std::map<std::string, NoiseExample> built;
    long long texels = 0;
};

NoiseExample buildField(const TextureGraph& graph, const std::string& id, uint32_t patternSeed,
                        const std::string& context, FieldCache& cache);

NoiseExample buildFieldOnce(const TextureGraph& graph, const std::string& id, uint32_t patternSeed,
                            const std::string& context, FieldCache& cache) {
    if (const auto it = cache.built.find(id); it != cache.built.end()) return it->second;
    NoiseExample e = buildField(graph, id, patternSeed, context, cache);
    cache.texels += (long long)e.size() * e.size();
    if (cache.texels > kMaxGraphExampleTexels)
        throw InputError(context + ": the graph's examples hold more than " + std::to_string(kMaxGraphExampleTexels) +
                         " texels in all (at node \"" + id + "\"); use smaller or fewer examples");
    cache.built.emplace(id, e);
    return e;
}

NoiseExample buildField(const TextureGraph& graph, const std::string& id, uint32_t patternSeed,
                        const std::string& context, FieldCache& cache) {
    const GraphNode& g = graph.node(id);
    const std::string where = context + ": node \"" + id + "\"";
    // A linear node's input: its example values, which must be the field's own.
    const auto linearInput = [&](const std::string& port) {
        NoiseExample e = buildFieldOnce(graph, g.inputs.at(port), patternSeed, context, cache);
        if (e.gaussianized())
            throw InputError(where + " (" + g.info->name + "): its input \"" + g.inputs.at(port) +
                             "\" is a Gaussianized exemplar, whose field is not linear in its example; set "
                             "\"gaussianize\": false on its exemplar or tiled_field to use it here");
        return e;
    };
    const auto number = [&](const char* name) { return g.numbers.at(name); };
    switch (g.info->kind) {
        case NodeKind::SpectralNoise: {
            NoiseSpec ns = g.noise;
            ns.spectrum.seed = g.seed ? *g.seed : graphNodeSeed(patternSeed, id);
            return buildNoiseExample(ns, where);
        }
        case NodeKind::Exemplar: return buildNoiseExample(g.noise, where);
        case NodeKind::Channel: {
            // The tiled field's image, this channel of it (GraphPattern gives
            // every channel of one tiled field the same tiles).
            const GraphNode& field = graph.node(g.inputs.at("field"));
            NoiseSpec ns = field.noise;
            ns.channel = int(number("index"));
            return buildNoiseExample(ns, where + " (channel)");
        }
        case NodeKind::Derivative: {
            const NoiseExample e = linearInput("input");
            const std::array<Image, 2> slopes = spectralSlopes(e.values());
            const double a = number("angle") * std::numbers::pi / 180;
            const float c = float(std::cos(a)), s = float(std::sin(a));
            Image d(e.size(), e.size(), 1, Image::Uninitialized{});
            double sumSq = 0;
            for (size_t i = 0; i < d.data().size(); ++i) {
                d.data()[i] = c * slopes[0].data()[i] + s * slopes[1].data()[i];
                sumSq += double(d.data()[i]) * d.data()[i];
            }
            const double rms = std::sqrt(sumSq / double(d.data().size()));
            if (!(rms > 1e-12)) throw InputError(where + " (derivative): the input is flat along this direction");
            const float gain = float(number("stddev") / rms), mean = float(number("mean"));
            for (float& v : d.data()) v = mean + gain * v;
            return NoiseExample(std::move(d));
        }
        case NodeKind::Affine: {
            const NoiseExample e = linearInput("input");
            Image v = e.values();
            const float scale = float(number("scale")), offset = float(number("offset"));
            for (float& x : v.data()) x = scale * x + offset;
            return NoiseExample(std::move(v));
        }
        case NodeKind::Sum: {
            const NoiseExample a = linearInput("a"), b = linearInput("b");
            if (a.size() != b.size())
                throw InputError(where + " (sum): its inputs' examples are " + std::to_string(a.size()) + " and " +
                                 std::to_string(b.size()) + " texels wide; a sum needs one size");
            Image v = a.values();
            const float wa = float(number("weight_a")), wb = float(number("weight_b"));
            for (size_t i = 0; i < v.data().size(); ++i) v.data()[i] = wa * v.data()[i] + wb * b.values().data()[i];
            return NoiseExample(std::move(v));
        }
        // The same example, seen through another uv (graphNodeTransform).
        case NodeKind::Transform: return buildFieldOnce(graph, g.inputs.at("input"), patternSeed, context, cache);
        case NodeKind::TiledField:  // not a field: its channels are
        case NodeKind::Op: break;
    }
    throw std::logic_error("buildGraphField: node " + id + " is not a field linear in its sources");
}

}  // namespace

NoiseExample buildGraphField(const TextureGraph& graph, const std::string& id, uint32_t patternSeed,
                             const std::string& context) {
    FieldCache cache;
    return buildFieldOnce(graph, id, patternSeed, context, cache);
}

std::vector<NoiseExample> buildGraphFields(const TextureGraph& graph, const std::vector<std::string>& ids,
                                           uint32_t patternSeed, const std::string& context) {
    FieldCache cache;
    std::vector<NoiseExample> out;
    for (const std::string& id : ids) out.push_back(buildFieldOnce(graph, id, patternSeed, context, cache));
    return out;
}

}  // namespace stochtex
