#include "stochtex/pattern/texture_graph.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <set>

#include "stochtex/core/budget.h"
#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/pattern/fields/field_node.h"
#include "stochtex/pattern/part_cache.h"

namespace stochtex {

namespace {

bool validId(const std::string& id) {
    if (id.empty() || id.size() > 64) return false;
    return std::all_of(id.begin(), id.end(),
                       [](char c) { return std::isalnum((unsigned char)c) || c == '_' || c == '-'; });
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
        const bool known =
            key == "type" ||
            std::any_of(info.inputs.begin(), info.inputs.end(), [&](const PortInfo& p) { return p.name == key; }) ||
            std::any_of(info.params.begin(), info.params.end(), [&](const ParamInfo& p) { return p.name == key; });
        if (known) continue;
        std::string names;
        for (const PortInfo& p : info.inputs) names += (names.empty() ? "" : ", ") + p.name;
        for (const ParamInfo& p : info.params) names += (names.empty() ? "" : ", ") + p.name;
        n.at(key).fail("a " + type + " node has no port or parameter \"" + key + "\"; it has: " + names);
    }
    for (const PortInfo& p : info.inputs) {
        if (!n.has(p.name))
            n.fail("a " + type + " node needs its input \"" + p.name + "\" (a " + portTypeName(p.type) + ")");
        g.inputs[p.name] = n.at(p.name).string();
    }
    for (const ParamInfo& p : info.params) {
        const bool required = p.fallback.is_null();
        if (required && p.type != ParamType::Seed && !n.has(p.name))
            n.fail("a " + type + " node needs \"" + p.name + "\"");
        switch (p.type) {
            case ParamType::Number: g.numbers[p.name] = n.number(p.name, p.fallback.get<double>(), p.min, p.max); break;
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
                for (size_t i = 0; i < count; ++i)
                    g.noise.spectrum.components.push_back(parseSpectrumComponent(comps.at(i)));
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
    // A source's example description, as a pattern file's noise.
    if (info.parsed) info.parsed(g, n);
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
        nodes.fail("has " + std::to_string(nodes.value().size()) + " nodes, more than " +
                   std::to_string(kMaxGraphNodes));
    std::map<std::string, GraphNode> byId;
    for (const auto& [id, value] : nodes.value().items()) {
        (void)value;
        byId.emplace(id, parseNode(nodes.at(id), id, baseDir));
    }
    // The spectral noises' memory and synthesis work, before any is built:
    // each is within its own budget, but 16 of them at 4096² with 16 ring
    // components took 7 minutes and 6.4 GB for a 16² render.
    long long texels = 0, work = 0;
    for (const auto& [id, g] : byId) {
        if (g.info->inputs.empty() && g.noise.source == NoiseSpec::Source::Spectrum && g.info->linear() &&
            !g.noise.spectrum.components.empty()) {
            const long long area = (long long)g.noise.spectrum.size * g.noise.spectrum.size;
            texels += area;
            work += area * (long long)g.noise.spectrum.components.size();
            if (texels > budgeted(kMaxGraphExampleTexels))
                nodes.at(id).failOverBudget(
                    "the graph's spectral noises hold " + std::to_string(texels) + " texels up to here; at most " +
                    std::to_string(budgeted(kMaxGraphExampleTexels)) + " in all: use smaller or fewer noises");
            if (work > budgeted(kMaxGraphSynthesisWork))
                nodes.at(id).failOverBudget("the graph's spectral noises cost " + std::to_string(work) +
                                            " component evaluations up to here; at most " +
                                            std::to_string(budgeted(kMaxGraphSynthesisWork)) +
                                            " in all (components × size², summed): use fewer "
                                            "components or smaller noises");
        }
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
    if (!g.info->linear()) throw std::logic_error("graphNodeTransform: node " + id + " is not linear in its sources");
    const FieldSight sight{g, context + ": node \"" + id + "\" (" + g.info->name + ")", [&](const std::string& port) {
                               return nodeTransform(graph, g.inputs.at(port), context, memo);
                           }};
    const UvTransform r = g.info->seenThrough ? g.info->seenThrough(sight) : UvTransform{};
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
        if (g.info->output == PortType::Channels)
            fields.insert(n);  // a tiled field
        else if (g.info->inputs.empty())
            otherSource = true;
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

// Examples built so far, by node id, and the texels of every node counted
// (built, or kept in a PartCache), in all; the PartCache, if any.
struct FieldCache {
    std::map<std::string, std::shared_ptr<const NoiseExample>> built;
    std::map<std::string, long long> counted;
    long long texels = 0;
    PartCache* parts = nullptr;
};

// Counts node `id`'s texels once against the graph's examples' budget.
void countTexels(FieldCache& cache, const std::string& id, long long texels, const std::string& context) {
    if (!cache.counted.emplace(id, texels).second) return;
    cache.texels += texels;
    if (cache.texels > budgeted(kMaxGraphExampleTexels))
        throw InputError::overBudget("", context + ": the graph's examples hold more than " +
                                             std::to_string(budgeted(kMaxGraphExampleTexels)) +
                                             " texels in all (at node \"" + id + "\"); use smaller or fewer examples");
}

NoiseExample buildField(const TextureGraph& graph, const std::string& id, uint32_t patternSeed,
                        const std::string& context, FieldCache& cache);

// Node `id`'s example, built once per build; with a PartCache, every linear
// node is a kept part (keyed by itself and the nodes upstream, in id order,
// which it folds), so an edit rebuilds the nodes it changed and those
// downstream of them, and the texels of a kept node's subgraph still count.
std::shared_ptr<const NoiseExample> buildFieldOnce(const TextureGraph& graph, const std::string& id,
                                                   uint32_t patternSeed, const std::string& context,
                                                   FieldCache& cache) {
    if (const auto it = cache.built.find(id); it != cache.built.end()) return it->second;
    const auto build = [&] {
        auto e = std::make_shared<const NoiseExample>(buildField(graph, id, patternSeed, context, cache));
        countTexels(cache, id, (long long)e->size() * e->size(), context);
        return e;
    };
    std::shared_ptr<const NoiseExample> e;
    if (!cache.parts) {
        e = build();
    } else {
        PartCache::FieldKey key{{}, patternSeed, context};
        std::set<std::string> upstream;
        for (std::vector<std::string> todo{id}; !todo.empty();) {
            const std::string n = todo.back();
            todo.pop_back();
            if (!upstream.insert(n).second) continue;
            for (const auto& [port, from] : graph.node(n).inputs) todo.push_back(from);
        }
        for (const std::string& n : upstream) key.nodes.push_back(graph.node(n));
        const PartCache::Field f = cache.parts->field(key, [&] {
            PartCache::Field built{build(), {}};
            for (const std::string& n : upstream)
                if (const auto it = cache.counted.find(n); it != cache.counted.end())
                    built.texels.emplace_back(n, it->second);
            return built;
        });
        for (const auto& [node, texels] : f.texels) countTexels(cache, node, texels, context);
        e = f.example;
    }
    cache.built.emplace(id, e);
    return e;
}

NoiseExample buildField(const TextureGraph& graph, const std::string& id, uint32_t patternSeed,
                        const std::string& context, FieldCache& cache) {
    const GraphNode& g = graph.node(id);
    const std::string where = context + ": node \"" + id + "\"";
    // A linear node's input: its example values, which must be the field's own.
    const auto linearInput = [&](const std::string& port) {
        NoiseExample e = *buildFieldOnce(graph, g.inputs.at(port), patternSeed, context, cache);
        if (e.gaussianized())
            throw InputError(where + " (" + g.info->name + "): its input \"" + g.inputs.at(port) +
                             "\" is a Gaussianized exemplar, whose field is not linear in its example; set "
                             "\"gaussianize\": false on its exemplar or tiled_field to use it here");
        return e;
    };
    if (!g.info->linear())
        throw std::logic_error("buildGraphField: node " + id + " is not a field linear in its sources");
    const FieldFold fold{
        g,
        where,
        [&] { return graphNodeSeed(patternSeed, id); },
        linearInput,
        [&](const std::string& port) { return *buildFieldOnce(graph, g.inputs.at(port), patternSeed, context, cache); },
        [&](const std::string& port) -> const GraphNode& { return graph.node(g.inputs.at(port)); }};
    NoiseExample e = g.info->fold(fold);
    // Linear nodes in a chain multiply their scales (20 affines at scale 100
    // overflowed float and rendered black, exit 0): refused at the node where
    // the field leaves the range its float moments hold.
    checkPixelRange(e.values(), where + " (" + g.info->name + ")", -kMaxFieldValue, kMaxFieldValue, "its field's");
    return e;
}

}  // namespace

NoiseExample buildGraphField(const TextureGraph& graph, const std::string& id, uint32_t patternSeed,
                             const std::string& context) {
    FieldCache cache;
    return *buildFieldOnce(graph, id, patternSeed, context, cache);
}

std::vector<std::shared_ptr<const NoiseExample>> buildGraphFields(const TextureGraph& graph,
                                                                  const std::vector<std::string>& ids,
                                                                  uint32_t patternSeed, const std::string& context,
                                                                  PartCache* parts) {
    FieldCache cache;
    cache.parts = parts;
    std::vector<std::shared_ptr<const NoiseExample>> out;
    for (const std::string& id : ids) out.push_back(buildFieldOnce(graph, id, patternSeed, context, cache));
    return out;
}

}  // namespace stochtex
