#include "stochtex/pattern/graph_pattern.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <type_traits>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"
#include "stochtex/filter/pyramid.h"
#include "stochtex/kernel/estimate.h"
#include "stochtex/noise/slopes.h"
#include "stochtex/noise/tiling_blending_lanes.h"
#include "stochtex/pattern/graph_nodes.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

namespace {

using kernel::vec2;
using kernel::vec3;

vec3 toVec(const Rgb& c) { return vec3(c[0], c[1], c[2]); }

Rgb toRgb(const vec3& c) { return {c.x, c.y, c.z}; }

// A field (else a colour) is what the operation gives.
bool givesField(const GraphPattern::Operation& op) { return op.info->output != PortType::Colour; }

// An operation's input slot k, vec3(0) where it has none.
template <class Slots>
vec3 input(const Slots& slots, const std::array<int, 3>& inputs, int k) {
    return inputs[size_t(k)] >= 0 ? slots[size_t(inputs[size_t(k)])] : vec3(0.0f);
}
template <class Slots>
vec3 input(const Slots& slots, const GraphPattern::Operation& op, int k) {
    return input(slots, op.inputs, k);
}

// A field that lies in [0, 1] is filtered as a Beta (kernel
// betaLevelCoordinate) where a table reads it: an op's, never a leaf's (a
// noise, Gaussian by construction). Its bounds may round past 0 or 1 in
// float (½ + ½ sin, a lerp of two ends): it is still bounded.
bool readAsBeta(int slot, int leafCount, float lo, float hi) {
    constexpr float roundingSlack = 1e-5f;
    return slot >= leafCount && lo >= -roundingSlack && hi <= 1.0f + roundingSlack;
}

// A plain pattern's normal map under the lean response as the graph it is:
// its height (as given: a Gaussianized exemplar's slopes would not be its
// own) on the tiles the file has always given it (deriveSeed(seed, 3)), its
// albedo as a colour node, and a lean node with the file's shading. Under
// the normal, roughness and height responses: a surface node on the same
// height, with the file's amplitude and roughness.
TextureGraph plainNormalMapGraph(const PatternSpec& spec, const ResponseOptions& response) {
    if (!spec.normalMap)
        throw InputError::parameter(
            "response", enumName(kResponseKindNames, response.kind) + " reads a normal map; the pattern has none");
    const NormalMapSpec& nm = *spec.normalMap;
    const LeanShading shading = validatedShading(nm.shading);
    TextureGraph graph;
    GraphNode height;
    height.id = "normal_map/height";
    height.noise = nm.height;
    height.noise.gaussianize = false;
    height.info = findGraphNode(nm.height.source == NoiseSpec::Source::Spectrum ? "spectral_noise" : "exemplar");
    height.seed = nm.height.explicitSeed ? nm.height.spectrum.seed : deriveSeed(spec.seed, 102u);
    height.tileSeed = deriveSeed(spec.seed, 3);
    if (response.kind != ResponseKind::Lean) {
        GraphNode surface;
        surface.id = "normal_map";
        surface.info = findGraphNode("surface");
        surface.inputs = {{"height", height.id}, {"value", height.id}};
        surface.numbers = {{"map", surfaceMap(response.kind)},
                           {"amplitude", nm.amplitude},
                           {"roughness", shading.roughness},
                           {"covariance", 0}};
        TextureGraph graph;
        graph.nodes = {std::move(height), std::move(surface)};
        graph.output = "normal_map";
        return graph;
    }
    GraphNode albedo;
    albedo.id = "normal_map/albedo";
    albedo.info = findGraphNode("colour");
    albedo.colour = shading.albedo;
    GraphNode lean;
    lean.id = "normal_map";
    lean.info = findGraphNode("lean");
    lean.inputs = {{"height", height.id}, {"albedo", albedo.id}};
    // A direction's azimuth and elevation in degrees (LeanOp::direction's inverse).
    const auto degrees = [](const std::array<double, 3>& d) {
        return std::array<double, 2>{std::atan2(d[1], d[0]) * 180 / std::numbers::pi,
                                     std::asin(std::clamp(d[2], -1.0, 1.0)) * 180 / std::numbers::pi};
    };
    const auto light = degrees(shading.light);
    const auto view = shading.view ? degrees(*shading.view) : std::array<double, 2>{0, 0};
    lean.numbers = {{"amplitude", nm.amplitude},    {"roughness", shading.roughness},
                    {"specular", shading.specular}, {"light_azimuth", light[0]},
                    {"light_elevation", light[1]},  {"view_azimuth", view[0]},
                    {"view_elevation", view[1]},    {"covariance", response.covariance ? 1 : 0}};
    graph.nodes = {std::move(height), std::move(albedo), std::move(lean)};
    graph.output = "normal_map";
    return graph;
}

// A plain pattern file {noise_x, noise_y, colormap} as the graph it is: its
// two noises as source nodes, seeded as the file says (noiseSeed), and a
// colormap node reading them. Its leaves are tiled with the offset seeds of
// the file's noises 1 and 2 (as every graph's leaves), so the program gives
// the plain pattern's values. Under the lean response: its normal map's graph.
TextureGraph plainPatternGraph(const PatternSpec& spec, const ResponseOptions& response) {
    if (readsNormalMap(response.kind)) return plainNormalMapGraph(spec, response);
    TextureGraph graph;
    const char* ids[2] = {"noise_x", "noise_y"};
    for (int axis = 0; axis < 2; ++axis) {
        GraphNode n;
        n.id = ids[axis];
        n.noise = spec.noise[axis];
        n.info = findGraphNode(n.noise.source == NoiseSpec::Source::Spectrum ? "spectral_noise" : "exemplar");
        n.seed = noiseSeed(spec, axis);
        graph.nodes.push_back(std::move(n));
    }
    GraphNode h;
    h.id = "colormap";
    h.info = findGraphNode("colormap");
    h.inputs = {{"x", ids[0]}, {"y", ids[1]}};
    h.colormap = spec.colormap;
    graph.nodes.push_back(std::move(h));
    graph.output = "colormap";
    return graph;
}

}  // namespace

GraphPattern GraphPattern::build(const PatternSpec& spec, const ResponseOptions& response, PartCache* parts) {
    if (spec.graph && response.kind != ResponseKind::PrefilteredColormap)
        throw InputError::parameter("response",
                                    "a texture graph shades through its own nodes (a lean node for a "
                                    "normal map); the " +
                                        enumName(kResponseKindNames, response.kind) +
                                        " response shades a plain pattern's normal map");
    const TextureGraph plain = spec.graph ? TextureGraph{} : plainPatternGraph(spec, response);
    const TextureGraph& graph = spec.graph ? *spec.graph : plain;
    const std::string& context = spec.name;
    if ((spec.gridPeriods[0] > 0) != (spec.gridPeriods[1] > 0) || spec.gridPeriods[0] < 0 || spec.gridPeriods[1] < 0)
        throw InputError::parameter("gridPeriods", "must be both positive (a tileable pattern) or both 0, got " +
                                                       std::to_string(spec.gridPeriods[0]) + ", " +
                                                       std::to_string(spec.gridPeriods[1]));
    const GridLayout grid = spec.gridPeriods[0] > 0
                                ? GridLayout::periodic(spec.gridDensity, spec.gridPeriods[0], spec.gridPeriods[1])
                                : GridLayout::plane(spec.gridDensity);
    // Which nodes are linear in the sources (fold into an example).
    std::map<std::string, bool> linear;
    for (const GraphNode& g : graph.nodes) {
        bool l = g.info->linear();
        for (const auto& port : g.inputs) l = l && linear.at(port.second);
        linear[g.id] = l;
    }
    // The nodes the output depends on, in the graph's order (inputs first).
    std::set<std::string> needed{graph.output};
    for (auto it = graph.nodes.rbegin(); it != graph.nodes.rend(); ++it)
        if (needed.count(it->id))
            for (const auto& port : it->inputs) needed.insert(port.second);
    // The operations: every needed node that is not linear in the sources;
    // the leaves: the linear nodes they read, in the order first read.
    std::vector<const GraphNode*> ops;
    GraphPattern p;
    for (const GraphNode& g : graph.nodes) {
        if (!needed.count(g.id) || linear.at(g.id)) continue;
        if (g.info->op < 0)  // a linear node (derivative, transform, …) over a field that does not fold
            for (const auto& [port, from] : g.inputs)
                if (!linear.at(from))
                    throw InputError(context + ": node \"" + g.id + "\" (" + g.info->name + "): its input \"" + from +
                                     "\" is not linear in the sources, so it has no example for a " + g.info->name +
                                     " node to read");
        const bool slopes = !g.info->slopesOf.empty();
        if (slopes) {
            const std::string& from = g.inputs.at(g.info->slopesOf);
            if (!linear.at(from))
                throw InputError(context + ": node \"" + g.id + "\" (" + g.info->name + "): its input \"" + from +
                                 "\" is not linear in the sources, so it has no example to take the slopes of");
        }
        ops.push_back(&g);
        for (const PortInfo& port : g.info->inputs) {
            if (port.name == g.info->slopesOf) continue;  // read through its slopes (below)
            const std::string& from = g.inputs.at(port.name);
            if (linear.at(from) && std::find(p.leafIds_.begin(), p.leafIds_.end(), from) == p.leafIds_.end())
                p.leafIds_.push_back(from);
        }
    }
    if (p.leafIds_.empty() &&
        std::none_of(ops.begin(), ops.end(), [](const GraphNode* g) { return !g->info->slopesOf.empty(); }))
        throw InputError(context + ": the output \"" + graph.output +
                         "\" reads no field, so it is one colour everywhere; a texture graph needs a noise (a "
                         "spectral_noise, exemplar or tiled_field node) under its output");
    // Each node that reads a field's slopes (NodeInfo::slopesOf: a lean
    // node's height) gets a pair of leaves after the others ("ID.slope_u",
    // "ID.slope_v"), on the field's tiles.
    const size_t fieldLeaves = p.leafIds_.size();
    std::vector<std::string> fieldIds = p.leafIds_;
    for (const GraphNode* g : ops)
        if (!g->info->slopesOf.empty()) {
            p.leafIds_.push_back(g->id + ".slope_u");
            p.leafIds_.push_back(g->id + ".slope_v");
            fieldIds.push_back(g->inputs.at(g->info->slopesOf));
        }
    // The slope leaves are no nodes of the file: the program's slots can outnumber them.
    if (p.leafIds_.size() + ops.size() > size_t(kMaxGraphNodes))
        throw InputError(context + ": the graph's program needs " + std::to_string(p.leafIds_.size() + ops.size()) +
                         " values per pixel (each lean node adds two slopes), more than " +
                         std::to_string(kMaxGraphNodes) + "; use fewer nodes");
    std::map<std::string, int> slot;
    for (size_t k = 0; k < p.leafIds_.size(); ++k) slot[p.leafIds_[k]] = int(k);
    for (size_t k = 0; k < ops.size(); ++k) slot[ops[k]->id] = int(p.leafIds_.size() + k);

    // The leaves' tiles: the leaves of one tile group (graphTileGroup: the
    // channels of one tiled field; a lean node's slopes and its height) share
    // the offset seed of the group's first leaf k, seeded as a pattern's
    // noise k (deriveSeed(seed, k + 1)); all leaves share the first seed
    // when offsets are shared.
    const std::vector<std::shared_ptr<const NoiseExample>> fields =
        buildGraphFields(graph, fieldIds, spec.seed, context, parts);
    // A plain pattern's two noises are one vector field N on one set of tiles (paper eq. 7).
    if (!spec.graph && !readsNormalMap(response.kind) && fields[0]->size() != fields[1]->size())
        throw InputError(context + ": noise_x is " + std::to_string(fields[0]->size()) +
                         " texels wide but noise_y is " + std::to_string(fields[1]->size()) +
                         "; both examples must have the same size");
    const bool shared = spec.offsets == OffsetMode::Shared;
    std::map<std::string, uint32_t> groupSeed;
    const auto seedOf = [&](const std::string& fieldId, size_t leaf) {
        const std::string group = graphTileGroup(graph, fieldId);
        const std::optional<uint32_t> fixed = graph.node(group).tileSeed;
        return groupSeed.emplace(group, fixed ? *fixed : deriveSeed(spec.seed, shared ? 1u : uint32_t(leaf + 1)))
            .first->second;
    };
    std::vector<NoiseExample> examples;
    std::vector<TilingBlendingNoise> noises;
    std::vector<UvTransform> transforms;
    for (size_t k = 0; k < fieldLeaves; ++k) {
        examples.push_back(*fields[k]);
        noises.emplace_back(fields[k], seedOf(fieldIds[k], k));
        transforms.push_back(graphNodeTransform(graph, fieldIds[k], context));
    }
    std::vector<bool> slopePairCovariance;  // per slope-reading node, in order: whether it reads the slopes' covariance
    for (const GraphNode* g : ops) {
        if (g->info->slopesOf.empty()) continue;
        const size_t k = noises.size();
        const std::string& heightId = g->inputs.at(g->info->slopesOf);
        const std::shared_ptr<const NoiseExample>& heightExample = fields[fieldLeaves + (k - fieldLeaves) / 2];
        const NoiseExample& height = *heightExample;
        const std::string where = context + ": node \"" + g->id + "\" (" + g->info->name + ")";
        if (height.gaussianized())
            throw InputError(
                where + ": its input \"" + heightId +
                "\" is a Gaussianized exemplar, whose field is not "
                "linear in its example; set \"gaussianize\": false on its exemplar or tiled_field to use it here");
        if (!graphNodeTransform(graph, heightId, context).identity())
            throw InputError(where + ": its input \"" + heightId +
                             "\" is seen through a transform of uv, whose slopes "
                             "would be along turned axes; a " +
                             g->info->name + " node needs its " + g->info->slopesOf + " untransformed");
        TiledField slopes;
        try {
            const double amplitude = g->numbers.at("amplitude");
            const uint32_t seed = seedOf(heightId, k);
            const auto build = [&] { return slopeField(height.values(), amplitude, seed, grid); };
            slopes = slopesPart(parts, heightExample, amplitude, seed, grid, build);
        } catch (const InputError& e) {
            throw InputError(where + ": " + e.what());
        }
        for (int c = 0; c < 2; ++c) {
            examples.push_back(slopes.channel(c).example());
            noises.push_back(slopes.channel(c));
            transforms.push_back(UvTransform{});
        }
        slopePairCovariance.push_back(g->numbers.at("covariance") != 0);
    }
    const auto addPair = [&](size_t k, bool pair, bool covariance) {
        const TilingBlendingNoise& second = noises[pair ? k + 1 : k];
        const bool oneSeed = second.offsetSeed() == noises[k].offsetSeed();
        p.leafLocation_.push_back({int(p.pairs_.size()), 0});
        if (pair) p.leafLocation_.push_back({int(p.pairs_.size()), 1});
        p.pairs_.emplace_back(std::vector<TilingBlendingNoise>{noises[k], second}, grid,
                              oneSeed ? OffsetSharing::Shared : OffsetSharing::Independent);
        p.pairTransforms_.push_back(transforms[k]);
        p.pairCovariance_.push_back(covariance);
        p.untransformed_ = p.untransformed_ && transforms[k].identity();
    };
    for (size_t k = 0; k < fieldLeaves;) {
        // Consecutive leaves of one size seen through one transform share a field.
        const bool pair =
            k + 1 < fieldLeaves && examples[k + 1].size() == examples[k].size() && transforms[k + 1] == transforms[k];
        addPair(k, pair, false);
        k += pair ? 2 : 1;
    }
    for (size_t k = fieldLeaves; k < noises.size(); k += 2)
        addPair(k, true, slopePairCovariance[(k - fieldLeaves) / 2]);

    // The program, with its tables.
    const auto gaussianizedLeaf = [&](const std::string& id) -> const NoiseExample* {
        const auto it = slot.find(id);
        if (it == slot.end() || it->second >= p.leafCount()) return nullptr;
        const NoiseExample& e = examples[size_t(it->second)];
        return e.gaussianized() ? &e : nullptr;
    };
    long long tableEntries = 0;
    for (const GraphNode* g : ops) {
        Operation op;
        op.id = g->id;
        op.info = g->info;
        // A node that reads a field's slopes (its first port) reads them along u
        // and v, then its other ports.
        const bool slopes = !g->info->slopesOf.empty();
        if (slopes && (g->info->inputs.empty() || g->info->inputs.front().name != g->info->slopesOf ||
                       g->info->inputs.size() > op.inputs.size() - 1))
            throw std::logic_error("GraphPattern::build: node type " + g->info->name +
                                   " reads the slopes of a port that is not its first, or has too many ports");
        if (slopes) op.inputs[0] = slot.at(g->id + ".slope_u"), op.inputs[1] = slot.at(g->id + ".slope_v");
        for (size_t i = slopes ? 1 : 0; i < g->info->inputs.size(); ++i)
            op.inputs[slopes ? i + 1 : i] = slot.at(g->inputs.at(g->info->inputs[i].name));
        if (const int first = op.inputs[0]; first >= 0 && first < p.leafCount()) {
            const int pair = p.leafLocation_[size_t(first)][0];
            if (p.pairCovariance_[size_t(pair)]) op.covariancePair = pair;
        }
        const size_t tablesBefore = p.tables_.size();
        OpBuild b{*g, [&](const std::string& port) { return gaussianizedLeaf(g->inputs.at(port)); }, p.tables_, -1,
                  parts};
        op.params = bindOp(g->info->op, b);
        op.table = b.table;
        // Only a table folds T⁻¹ in: an op without one cannot read a Gaussianized exemplar.
        for (size_t i = 0; i < g->info->inputs.size() && op.table < 0; ++i) {
            const std::string& from = g->inputs.at(g->info->inputs[i].name);
            if (!(slopes && i == 0) && gaussianizedLeaf(from))
                throw InputError(context + ": node \"" + g->id + "\" (" + g->info->name + "): its input \"" + from +
                                 "\" is a Gaussianized exemplar, whose field only a transfer function reads directly; "
                                 "set \"gaussianize\": false on its exemplar or tiled_field to use it here");
        }
        if (p.tables_.size() > tablesBefore) {
            const ColormapTable& t = p.tables_.back().point;
            tableEntries += (long long)t.resolutionX() * t.resolutionY();
            if (tableEntries > kMaxGraphTableEntries)
                throw InputError(context + ": node \"" + g->id + "\" (" + g->info->name +
                                 "): the graph's tables hold more than " + std::to_string(kMaxGraphTableEntries) +
                                 " entries in all; use lower resolutions or fewer tables");
        }
        p.operations_.push_back(std::move(op));
    }
    planSourceFunctions(p, examples, settleProgramRanges(p, examples, context));
    if (grid.periodic() && !p.untransformed_)
        throw InputError::parameter("gridPeriods", "needs a program whose leaves read uv as it is (" + context +
                                                       " transforms a leaf's uv, whose tiles would not repeat)");
    return p;
}

// The linear nodes' fold checks each example's values; the ops compose them
// per pixel (squares of squares, products of affines), where a value past
// float renders as inf or NaN: black or white with exit 0. Each slot's range
// follows from its inputs' by the op at their ends and their points nearest 0
// (exact for affine, sum, product, square, mix, threshold, compose), a table
// op's also from its entries (curve, colormap), from the leaves' ranges: a
// blend of three tiles lies within √3 of the largest deviation from the
// example's mean. The lean op's specular peak may lie inside its inputs'
// ranges; its colour feeds no field op. The same ranges tell which table
// inputs are bounded fields, filtered as Betas (kernel betaLevelCoordinate): an
// op's field, never a leaf (a noise, Gaussian by construction).
GraphPattern::FieldRanges GraphPattern::settleProgramRanges(GraphPattern& p, const std::vector<NoiseExample>& examples,
                                                            const std::string& context) {
    std::vector<vec3> lo, hi;
    for (const NoiseExample& e : examples) {
        float deviation = 0;
        for (float v : e.values().data()) deviation = std::max(deviation, std::abs(v - e.mean()));
        const float reach = std::sqrt(3.0f) * deviation;
        lo.push_back(vec3(e.toOutput(e.mean() - reach), 0.0f, 0.0f));
        hi.push_back(vec3(e.toOutput(e.mean() + reach), 0.0f, 0.0f));
    }
    kernel::OpContext ctx;
    for (const Operation& op : p.operations_) {
        if (op.table >= 0)
            for (size_t axis = 0; axis < 2; ++axis)
                if (const int s = op.inputs[axis]; s >= 0)
                    p.tables_[size_t(op.table)].beta[axis] =
                        readAsBeta(s, p.leafCount(), lo[size_t(s)].x, hi[size_t(s)].x);
        ctx.table = op.table;
        ctx.pointTable = op.table >= 0 ? &p.tables_[size_t(op.table)].point : nullptr;
        vec3 outLo(INFINITY), outHi(-INFINITY);
        bool finite = true;
        const auto include = [&](const vec3& v) {
            for (int c = 0; c < 3; ++c) {
                finite = finite && std::isfinite(v[c]);
                outLo[c] = std::min(outLo[c], v[c]);
                outHi[c] = std::max(outHi[c], v[c]);
            }
        };
        // Each input at its low end, its high end and its point nearest 0
        // (a square's minimum lies there when its range spans 0).
        for (int k = 0; k < 27; ++k) {
            std::array<vec3, 3> in{};
            for (size_t i = 0, digit = size_t(k); i < 3; ++i, digit /= 3)
                if (const int s = op.inputs[i]; s >= 0) {
                    const vec3 l = lo[size_t(s)], h = hi[size_t(s)];
                    in[i] = digit % 3 == 0 ? l : digit % 3 == 1 ? h : glm::clamp(vec3(0.0f), l, h);
                }
            include(opPoint(op.params, in[0], in[1], in[2], ctx));
        }
        // A table op's values are its entries, wherever they peak (a curve
        // up and down again between its inputs' ends).
        if (op.table >= 0) {
            const ColormapTable& t = p.tables_[size_t(op.table)].point;
            for (int j = 0; j < t.resolutionY(); ++j)
                for (int i = 0; i < t.resolutionX(); ++i) {
                    const Rgb e = t.entry(i, j);
                    include(vec3(e[0], e[1], e[2]));
                }
        }
        const float reach = std::max({-outLo.x, -outLo.y, -outLo.z, outHi.x, outHi.y, outHi.z});
        if (!finite || reach > kMaxFieldValue)
            throw InputError(context + ": node \"" + op.id + "\" (" + op.info->name + "): its values may reach " +
                             (finite ? formatValue(reach) : std::string("beyond float")) +
                             " from its inputs' ranges; a node's values must be in [-" + formatValue(kMaxFieldValue) +
                             ", " + formatValue(kMaxFieldValue) + "] (lower the scales that lead to it)");
        lo.push_back(outLo);
        hi.push_back(outHi);
    }
    FieldRanges ranges;
    for (size_t k = 0; k < lo.size(); ++k) ranges.lo.push_back(lo[k].x), ranges.hi.push_back(hi[k].x);
    return ranges;
}

void GraphPattern::planSourceFunctions(GraphPattern& p, const std::vector<NoiseExample>& examples,
                                       const FieldRanges& ranges) {
    const int leaves = p.leafCount();
    const int slots = leaves + int(p.operations_.size());
    const auto operation = [&](int slot) -> Operation& { return p.operations_[size_t(slot - leaves)]; };
    // Each slot's sources, ascending: itself for a leaf and a root op, none
    // for an op that reads nothing (a colour); and the leaves it reads.
    using Sources = std::vector<int>;
    std::vector<Sources> sources(static_cast<size_t>(slots));
    std::vector<std::set<int>> leavesRead(static_cast<size_t>(slots));
    for (int k = 0; k < leaves; ++k) sources[size_t(k)] = {k}, leavesRead[size_t(k)] = {k};
    const auto inputsOf = [&](int slot) {  // the inputs that are not constants
        std::vector<int> in;
        for (const int i : operation(slot).inputs)
            if (i >= 0 && !sources[size_t(i)].empty()) in.push_back(i);
        return in;
    };
    for (int q = leaves; q < slots; ++q) {
        const Operation& op = operation(q);
        std::set<int> set;
        for (const int i : inputsOf(q)) {
            set.insert(sources[size_t(i)].begin(), sources[size_t(i)].end());
            leavesRead[size_t(q)].insert(leavesRead[size_t(i)].begin(), leavesRead[size_t(i)].end());
        }
        // A source is a field (a colour root, e.g. a lean op's, is read as
        // the ops read colours, not as a distribution), and two sources are
        // independent (no leaf read by both), as the tables' prefilter takes them.
        bool root = set.size() > 2 || opShadesLight(op.params) || op.covariancePair >= 0;
        for (const int s : set) root = root || (s >= leaves && !givesField(operation(s)));
        if (set.size() == 2) {
            const std::set<int>&a = leavesRead[size_t(*set.begin())], &b = leavesRead[size_t(*set.rbegin())];
            root = root || std::any_of(a.begin(), a.end(), [&](int k) { return b.count(k) > 0; });
        }
        sources[size_t(q)] = root ? Sources{q} : Sources(set.begin(), set.end());
    }
    // From the output back: an op's function is planned where the filtered
    // program reads its value — the output, or an input of an op that runs
    // as itself (a root, or an op without a function).
    std::vector<bool> read(static_cast<size_t>(slots), false);
    read[size_t(slots - 1)] = true;
    long long work = 0;  // op evaluations of the functions' tables
    for (int q = slots - 1; q >= leaves; --q) {
        if (!read[size_t(q)]) continue;
        const Sources& src = sources[size_t(q)];
        // An op that reads each of its sources once, directly, is filtered as itself.
        Sources directInputs = inputsOf(q);
        std::sort(directInputs.begin(), directInputs.end());
        const bool runsAsItself = src == Sources{q} || src.empty() || directInputs == src;
        if (!runsAsItself && planSourceFunction(p, examples, ranges, q, src, work)) {
            for (const int s : src) read[size_t(s)] = true;  // a root op must run for its moments
            continue;
        }
        for (const int i : operation(q).inputs)  // constants too
            if (i >= 0) read[size_t(i)] = true;
    }
    for (int q = leaves; q < slots; ++q) operation(q).filteredRead = read[size_t(q)];
}

bool GraphPattern::planSourceFunction(GraphPattern& p, const std::vector<NoiseExample>& examples,
                                      const FieldRanges& ranges, int q, const std::vector<int>& sources,
                                      long long& work) {
    const int leaves = p.leafCount();
    const auto operation = [&](int slot) -> const Operation& { return p.operations_[size_t(slot - leaves)]; };
    const auto isSource = [&](int slot) { return std::find(sources.begin(), sources.end(), slot) != sources.end(); };
    const int first = sources.front();
    const bool oneSource = sources.size() == 1;
    // F's ops: those between q and its sources that q reads.
    std::vector<bool> inF(size_t(q + 1), false);
    inF[size_t(q)] = true;
    for (int c = q; c > first; --c)
        if (inF[size_t(c)] && !isSource(c))
            for (const int i : operation(c).inputs)
                if (i >= 0) inF[size_t(i)] = true;
    Slots values(size_t(p.outputSlot() + 2), vec3(0.0f));
    kernel::OpContext ctx;
    const auto F = [&](float x, float y) {
        values[size_t(first)] = vec3(x, 0.0f, 0.0f);
        values[size_t(sources.back())] = vec3(oneSource ? x : y, 0.0f, 0.0f);
        for (int c = leaves; c <= q; ++c) {  // a colour op F reads may precede its sources
            if (!inF[size_t(c)] || isSource(c)) continue;
            const Operation& op = operation(c);
            ctx.table = op.table;
            ctx.pointTable = op.table >= 0 ? &p.tables_[size_t(op.table)].point : nullptr;
            values[size_t(c)] =
                opPoint(op.params, input(values, op, 0), input(values, op, 1), input(values, op, 2), ctx);
        }
        return values[size_t(q)];
    };
    // Its table spans [0, 1] along each source, as every table: where a
    // source reaches beyond, F must hold its value at the end, checked at 33
    // points beyond each end against the other source at 9 values in
    // [0, 1] and at its own ends (the corners).
    const auto at = [&](size_t axis, float v, float other) { return axis == 0 ? F(v, other) : F(other, v); };
    for (size_t axis = 0; axis < sources.size(); ++axis) {
        const float l = ranges.lo[size_t(sources[axis])], h = ranges.hi[size_t(sources[axis])];
        std::vector<float> others;
        for (int o = 0; o <= 8; ++o) others.push_back(float(o) / 8.0f);
        if (!oneSource) {
            const int other = sources[1 - axis];
            others.push_back(ranges.lo[size_t(other)]);
            others.push_back(ranges.hi[size_t(other)]);
        }
        for (const float other : others)
            for (int k = 0; k <= 32; ++k) {
                const float t = float(k) / 32.0f;
                if (l < 0.0f && at(axis, l * (1.0f - t), other) != at(axis, 0.0f, std::clamp(other, 0.0f, 1.0f)))
                    return false;
                if (h > 1.0f && at(axis, 1.0f + (h - 1.0f) * t, other) != at(axis, 1.0f, std::clamp(other, 0.0f, 1.0f)))
                    return false;
            }
    }
    // Resolution: along a source, the largest of F's tables' (a curve's, a
    // colormap's: a function is sampled as finely as what it reads), 256
    // where F reads none, at most 512 (a two-source table's prefiltered
    // layers grow with its entries); one source: 4 entries per entry of F's
    // finest table (or 1024), within [64, 1024] (cheap).
    int resolution = 0;
    long long entries = 0;
    for (const OpTable& t : p.tables_) entries += (long long)t.point.resolutionX() * t.point.resolutionY();
    for (int c = first + 1; c <= q; ++c)
        if (c >= leaves && inF[size_t(c)] && operation(c).table >= 0) {
            const ColormapTable& t = p.tables_[size_t(operation(c).table)].point;
            resolution = std::max({resolution, t.resolutionX(), t.resolutionY()});
        }
    const int rx = oneSource ? (resolution ? std::clamp(4 * resolution, 64, 1024) : 1024)
                             : std::min(resolution ? std::max(resolution, 2) : 256, 512);
    const int ry = oneSource ? 2 : rx;
    Operation& op = p.operations_[size_t(q - leaves)];
    const bool field = givesField(op);
    const auto gaussianized = [&](size_t axis) -> const NoiseExample* {
        const int s = sources[std::min(axis, sources.size() - 1)];
        return s < leaves && examples[size_t(s)].gaussianized() ? &examples[size_t(s)] : nullptr;
    };
    // In blending space where a source is a Gaussianized leaf (F∘T⁻¹ along it), as the op tables are.
    const bool blends = gaussianized(0) || gaussianized(1);
    // Within the graph's table budget, and in bounded time: the op evaluations
    // of all the functions' tables (a long chain under many functions) at
    // most kMaxFunctionWork; past either the op runs as itself.
    const long long cost = (long long)rx * ry * (blends ? 2 : 1) * std::count(inF.begin(), inF.end(), true);
    if (entries + (long long)rx * ry > kMaxGraphTableEntries || work + cost > kMaxFunctionWork) return false;
    work += cost;
    const auto table = [&](const NoiseExample* ex, const NoiseExample* ey) {
        return tabulate(rx, ry, [&](int i, int j) {
            float x = float(i) / float(rx - 1), y = oneSource ? x : float(j) / float(ry - 1);
            if (ex) x = ex->toOutput(x);
            if (ey) y = ey->toOutput(y);
            const vec3 v = F(x, y);
            return field ? kernel::momentEntry(v.x) : v;
        });
    };
    const ColormapTable point = table(nullptr, nullptr);
    OpTable t{point, blends ? table(gaussianized(0), gaussianized(1)) : point, field};
    for (size_t axis = 0; axis < 2; ++axis) {
        const int s = sources[std::min(axis, sources.size() - 1)];
        t.beta[axis] = readAsBeta(s, leaves, ranges.lo[size_t(s)], ranges.hi[size_t(s)]);
    }
    p.tables_.push_back(std::move(t));
    Operation::SourceFunction f;
    f.table = int(p.tables_.size()) - 1;
    f.inputs = {first, sources.back(), -1};
    if (field)
        f.params = kernel::ColormapFieldParams{0.0f};
    else
        f.params = kernel::ColormapParams{0.0f};
    op.sourceFunction = f;
    return true;
}

bool GraphPattern::readsTable(int table, bool filtered, bool matched) const {
    return std::any_of(operations_.begin(), operations_.end(), [&](const Operation& op) {
        if (!filtered) return op.table == table;
        return runsFiltered(op, matched) && filteredCall(op, matched).table == table;
    });
}

const std::string& GraphPattern::tableNode(int table) const {
    for (const Operation& op : operations_)
        if (op.table == table || (op.sourceFunction && op.sourceFunction->table == table)) return op.id;
    throw std::out_of_range("GraphPattern::tableNode: no table " + std::to_string(table));
}

bool GraphPattern::shadesLight() const {
    return std::any_of(operations_.begin(), operations_.end(),
                       [](const Operation& op) { return opShadesLight(op.params); });
}

const ColormapTable* GraphPattern::plainColormap() const {
    if (operations_.size() != 1 || leafCount() != 2 || pairs_.size() != 1) return nullptr;
    const Operation& op = operations_.front();
    if (!opIsPlainLookup(op.params) || op.inputs[0] != 0 || op.inputs[1] != 1) return nullptr;
    if (leafLocation(0) != std::array<int, 2>{0, 0} || leafLocation(1) != std::array<int, 2>{0, 1}) return nullptr;
    return &tables_[size_t(op.table)].point;
}

Rgb GraphPattern::run(Slots& slots, int lastSlot, const Direction& eye) const {
    runRows(slots.data(), 1, lastSlot, eye);
    return toRgb(slots[size_t(lastSlot)]);
}

void GraphPattern::runRows(vec3* rows, int n, int lastSlot, const Direction& eye) const {
    kernel::OpContext ctx;  // the op's tables themselves (ops/op_host.h)
    ctx.eye = toVec(eye);
    const vec3* zero = rows + size_t(outputSlot() + 1) * size_t(n);
    const auto in = [&](const Operation& op, int k) -> const vec3* {
        const int slot = op.inputs[size_t(k)];
        return slot >= 0 ? rows + size_t(slot) * size_t(n) : zero;
    };
    int out = leafCount();
    for (const Operation& op : operations_) {
        if (out > lastSlot) break;
        ctx.table = op.table;
        ctx.pointTable = op.table >= 0 ? &tables_[size_t(op.table)].point : nullptr;
        opPointRow(op.params, in(op, 0), in(op, 1), in(op, 2), rows + size_t(out) * size_t(n), n, ctx);
        ++out;
    }
}

Rgb GraphPattern::evaluate(double u, double v, int lastSlot, const Direction& eye, Slots& slots) const {
    if (lastSlot < 0) lastSlot = outputSlot();
    if (slots.size() != size_t(outputSlot() + 2)) slots = makeSlots();
    // Untransformed leaves share the stencil at uv.
    const BlendStencil shared = untransformed_ ? triangleGrid(u, v, grid()) : BlendStencil{};
    for (int k = 0; k < leafCount(); ++k) {
        // Each leaf at its pair's uv (the pair's tiles are its own).
        const TilingBlendingNoise& n = leaf(k);
        float b = 0;
        if (untransformed_) {
            b = n.blend(shared, periodFraction(u), periodFraction(v));
        } else {
            const auto [pu, pv] = pairTransforms_[size_t(leafLocation(k)[0])].apply(u, v);
            b = n.blend(triangleGrid(pu, pv, grid()), periodFraction(pu), periodFraction(pv));
        }
        slots[size_t(k)] = vec3(n.example().toOutput(b), 0.0f, 0.0f);
    }
    return run(slots, lastSlot, eye);
}

Rgb GraphPattern::evaluate(double u, double v, int lastSlot, const Direction& eye) const {
    Slots slots;
    return evaluate(u, v, lastSlot, eye, slots);
}

Rgb GraphPattern::fromLeafValues(const std::vector<float>& values) const {
    if (int(values.size()) != leafCount())
        throw std::invalid_argument("GraphPattern::fromLeafValues: " + std::to_string(values.size()) + " values for " +
                                    std::to_string(leafCount()) + " leaves");
    Slots slots = makeSlots();
    for (size_t k = 0; k < values.size(); ++k) slots[k] = vec3(values[k], 0.0f, 0.0f);
    return run(slots, outputSlot(), kFromAbove);
}

Rgb GraphPattern::evaluate(double u, double v) const { return evaluate(u, v, -1, kFromAbove); }

// Walks the view's pixels row-parallel. Untransformed leaves share the
// triangle grid of a row: in SIMD lanes, each leaf is blended a vector of
// pixels at a time (noise/tiling_blending_lanes.h); the colormap of a plain
// program then reads the row's table lookups (their taps in lanes), another
// program's ops run an op at a time over the row (runRows). The scalar
// reference shares one
// stencil per pixel, and as neighbouring pixels on a scanline mostly see
// the same three tiles, redoes the per-tile work of every leaf (hashing the
// offsets, locating the rows to read) only when the tiles change.
Image GraphPattern::renderPixels(const View& view, const Progress& progress, int lastSlot, bool gray,
                                 CpuKernel kernel) const {
    validateView(view);
    Image out(view.width, view.height, 3, Image::Uninitialized{});
    const double invW = 1.0 / double(exampleSize());
    std::vector<const TilingBlendingNoise*> leaves;
    for (int k = 0; k < leafCount(); ++k) leaves.push_back(&leaf(k));
    const ColormapTable* plain = lastSlot == outputSlot() ? plainColormap() : nullptr;
    // A pixel's value as written: a field as gray, clamped to [0, 1].
    const auto put = [&](Rgb c, float* rgb) {
        if (gray) c[0] = c[1] = c[2] = std::clamp(c[0], 0.0f, 1.0f);
        std::copy(c.begin(), c.end(), rgb);
    };
    const auto lanes = [&](int y0, int y1) {
        GridRowLanes grid;
        const size_t width = size_t(view.width), padded = size_t(paddedLaneCount(view.width));
        std::vector<std::vector<float>> values(leaves.size(), std::vector<float>(padded));
        // The program's slots over the row (runRows), the last row vec3(0).
        std::vector<vec3> rows(size_t(outputSlot() + 2) * width, vec3(0.0f));
        for (int py = y0; py < y1; ++py) {
            grid.compute(view.offsetU, view.scale, invW, pixelUv(view, invW, 0, py)[1], view.width, this->grid());
            for (size_t k = 0; k < leaves.size(); ++k) blendRowLanes(*leaves[k], grid, values[k].data());
            float* row = out.row(py);
            if (plain) {
                // A plain program's colormap: the taps in lanes, then per pixel
                // four 16-byte RGBA loads (cheaper than twelve gathers).
                plain->sampleRow(values[0].data(), values[1].data(), 1, row, width);
                continue;
            }
            // A leaf's slot is vec3(value, 0, 0): its zeros were set once,
            // and no op writes a leaf's slot.
            for (size_t k = 0; k < leaves.size(); ++k) {
                vec3* leafRow = rows.data() + k * width;
                const float* value = values[k].data();
                for (size_t px = 0; px < width; ++px) leafRow[px].x = value[px];
            }
            runRows(rows.data(), view.width, lastSlot, kFromAbove);
            const vec3* result = rows.data() + size_t(lastSlot) * width;
            static_assert(sizeof(vec3) == 3 * sizeof(float), "a row of vec3 is a row of RGB floats");
            if (gray)
                for (size_t px = 0; px < width; ++px) put(toRgb(result[px]), row + px * 3);
            else
                std::memcpy(row, result, width * sizeof(vec3));
        }
    };
    const auto scalar = [&](int y0, int y1) {
        Slots slots = makeSlots();
        std::vector<TilingBlendingNoise::TileRows> tiles(leaves.size());
        BlendStencil last{};
        for (int py = y0; py < y1; ++py) {
            const double v = pixelUv(view, invW, 0, py)[1];
            const TriangleGridRow grid(v, this->grid());
            const float fv = periodFraction(v);
            float* row = out.row(py);
            bool valid = false;
            for (int px = 0; px < view.width; ++px) {
                const double u = pixelUv(view, invW, px, py)[0];
                float* rgb = row + size_t(px) * 3;
                if (!untransformed_) {
                    put(evaluate(u, v, lastSlot, kFromAbove, slots), rgb);
                    continue;
                }
                const BlendStencil s = grid.stencil(u);
                if (!valid || !sameTiles(s, last)) {
                    for (size_t k = 0; k < leaves.size(); ++k) tiles[k] = leaves[k]->tileRows(s, fv);
                    valid = true;
                }
                last = s;
                const float fu = periodFraction(u);
                if (plain) {
                    const Rgb c = plain->sample(leaves[0]->example().toOutput(leaves[0]->blend(s, tiles[0], fu)),
                                                leaves[1]->example().toOutput(leaves[1]->blend(s, tiles[1], fu)));
                    std::copy(c.begin(), c.end(), rgb);
                    continue;
                }
                for (size_t k = 0; k < leaves.size(); ++k)
                    slots[k] = vec3(leaves[k]->example().toOutput(leaves[k]->blend(s, tiles[k], fu)), 0.0f, 0.0f);
                put(run(slots, lastSlot, kFromAbove), rgb);
            }
        }
    };
    if (kernel == CpuKernel::Simd && untransformed_ && !grid().periodic())  // the lanes hash the plane's vertices
        parallelRows(view.height, lanes, progress);
    else
        parallelRows(view.height, scalar, progress);
    return out;
}

Image GraphPattern::render(const View& view, const Progress& progress, CpuKernel kernel) const {
    return renderPixels(view, progress, outputSlot(), false, kernel);
}

Image GraphPattern::renderNode(const View& view, const std::string& id) const {
    int slot = -1;
    bool field = true;
    for (int k = 0; k < leafCount(); ++k)
        if (leafIds_[size_t(k)] == id) slot = k;
    for (size_t k = 0; k < operations_.size(); ++k)
        if (operations_[k].id == id) {
            slot = leafCount() + int(k);
            field = givesField(operations_[k]);
        }
    if (slot < 0) throw InputError("node \"" + id + "\" is neither a leaf nor an operation of the graph's program");
    return renderPixels(view, {}, slot, field, CpuKernel::Simd);
}

namespace {

// Mean, variances and covariance of a two-channel field over its whole
// period (its examples' own: tiling and blending keeps them), the
// statistics of an infinite footprint.
FootprintStats fieldStatistics(const TiledField& f) {
    double mean[2] = {0, 0}, m2[3] = {0, 0, 0};
    const auto& x = f.channel(0).example().values().data();
    const auto& y = f.channel(1).example().values().data();
    for (size_t i = 0; i < x.size(); ++i) {
        mean[0] += x[i];
        mean[1] += y[i];
    }
    mean[0] /= double(x.size());
    mean[1] /= double(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
        const double dx = x[i] - mean[0], dy = y[i] - mean[1];
        m2[0] += dx * dx;
        m2[1] += dy * dy;
        m2[2] += dx * dy;
    }
    FootprintStats s;
    s.mean = {float(mean[0]), float(mean[1])};
    s.varX = float(m2[0] / double(x.size()));
    s.varY = float(m2[1] / double(x.size()));
    s.cov = float(m2[2] / double(x.size()));
    return s;
}

// The mean and variance of an example's values (blending space): those of
// its tiled field, whose tiling and blending keeps them.
std::array<double, 2> exampleMoments(const NoiseExample& example) {
    const auto& v = example.values().data();
    double sum = 0, sum2 = 0;
    for (const float x : v) sum += x;
    const double mean = sum / double(v.size());
    for (const float x : v) sum2 += (x - mean) * (x - mean);
    return {mean, sum2 / double(v.size())};
}

}  // namespace

FilteredGraph::FilteredGraph(const GraphPattern& graph, const FilterOptions& options, GraphMoments moments,
                             PartCache* parts)
    : graph_(graph), options_(options), moments_(moments) {
    validateFilterOptions(options);
    for (const TiledField& pair : graph.leafPairs())
        if (!isPowerOfTwo(pair.exampleSize()))
            throw InputError("filtering needs power-of-two example sizes (the MIP pyramids halve them); got " +
                             std::to_string(pair.exampleSize()));
    std::vector<std::array<double, 2>> exact;  // each leaf's mean and variance over its example
    std::vector<std::array<float, 2>> whole;
    for (int k = 0; k < graph.leafCount(); ++k) {
        exact.push_back(exampleMoments(graph.leaf(k).example()));
        whole.push_back({float(exact.back()[0]), float(exact.back()[1])});
    }
    // The covariance of each pair's two examples over the whole period (a lean node's sky).
    std::vector<float> wholeCov;
    for (const TiledField& pair : graph.leafPairs()) wholeCov.push_back(fieldStatistics(pair).cov);
    plain_ = graph.plainColormap() && moments == GraphMoments::Matched;
    // A plain pattern's sky is its average colour E[H(N)] in every mode (H
    // convolved exactly with the whole examples' Gaussian, in blending
    // space), where every filtered mode's ground converges far away.
    const auto plainSky = [&] {
        return convolveColormapNumerically(graph.tables().front().blended, exact[0][0], exact[1][0],
                                           std::sqrt(exact[0][1]), std::sqrt(exact[1][1]));
    };
    // Functions of sources where their tables are prefiltered: moment
    // matching from the estimators or exact statistics (the point source's
    // sky runs the ops themselves, as it always has).
    readsFunctions_ = moments == GraphMoments::Matched && options.source != StatisticsSource::Point;
    bool opsReadTables = false;
    for (int k = 0; k < int(graph.tables().size()); ++k)
        opsReadTables = opsReadTables || graph.readsTable(k, true, false);
    if (options.source == StatisticsSource::Point) {  // nothing to prefilter
        // Without tables the filtered program costs nothing to run on the
        // whole examples' moments (a lean program: the lean response's sky);
        // with them, only the means are at hand.
        std::vector<float> means;
        for (const auto& m : whole) means.push_back(graph.leaf(int(means.size())).example().toOutput(m[0]));
        sky_ = plain_ ? plainSky() : opsReadTables ? graph.fromLeafValues(means) : fromMoments(whole, wholeCov);
        return;
    }
    for (size_t k = 0; k < graph.tables().size(); ++k) {
        const ColormapTable& t = graph.tables()[k].blended;
        try {
            validatePrefilteredResolution(t.resolutionX(), t.resolutionY());
        } catch (const InputError& e) {
            throw InputError("node \"" + graph.tableNode(int(k)) + "\": " + e.what());
        }
        // Only what this program reads: matched, an op's table that its
        // function of sources replaces is not (nor, mean-only, a function's).
        tables_.push_back(graph.readsTable(int(k), true, readsFunctions_)
                              ? prefilteredPart(parts, t, options.response.prefilter, graph.tables()[k].beta)
                              : nullptr);
    }
    sky_ = plain_ ? plainSky() : fromMoments(whole, wholeCov);
    if (options.source == StatisticsSource::Estimators)
        for (size_t k = 0; k < graph.leafPairs().size(); ++k)
            estimators_.push_back(
                estimatorPart(parts, graph.leafPairs()[k], graph.pairCovariance(int(k)), options.pack8));
}

Rgb FilteredGraph::fromMoments(const std::vector<std::array<float, 2>>& leafMoments,
                               const std::vector<float>& pairCovariances, const Direction& eye) const {
    if (int(leafMoments.size()) != graph_.leafCount())
        throw std::invalid_argument("FilteredGraph::fromMoments: " + std::to_string(leafMoments.size()) +
                                    " leaf moments for " + std::to_string(graph_.leafCount()) + " leaves");
    Scratch scratch;
    if (scratch.slots.size() != size_t(graph_.outputSlot() + 2)) scratch.slots = graph_.makeSlots();
    for (size_t k = 0; k < leafMoments.size(); ++k) scratch.slots[k] = vec3(leafMoments[k][0], leafMoments[k][1], 0.0f);
    scratch.covariances = pairCovariances;
    return runFiltered(scratch, eye);
}

Rgb FilteredGraph::runFiltered(Scratch& scratch, const Direction& eye) const {
    // A field's moments in (x, y) of a slot, a colour's mean in all three.
    GraphPattern::Slots& slots = scratch.slots;
    const std::vector<float>& pairCovariances = scratch.covariances;
    kernel::OpContext ctx;  // the op's tables themselves (ops/op_host.h)
    ctx.eye = toVec(eye);
    size_t out = size_t(graph_.leafCount());
    for (const GraphPattern::Operation& op : graph_.operations()) {
        if (!GraphPattern::runsFiltered(op, readsFunctions_)) {  // read by none
            ++out;
            continue;
        }
        const GraphPattern::OpCall call = GraphPattern::filteredCall(op, readsFunctions_);
        ctx.table = call.table;
        ctx.pointTable = call.table >= 0 ? &graph_.tables()[size_t(call.table)].point : nullptr;
        ctx.prefilteredTable =
            call.table >= 0 && size_t(call.table) < tables_.size() ? tables_[size_t(call.table)].get() : nullptr;
        const size_t pair = op.covariancePair >= 0 ? size_t(op.covariancePair) : pairCovariances.size();
        ctx.slopeCov = pair < pairCovariances.size() ? pairCovariances[pair] : 0.0f;
        slots[out] = opFiltered(call.params, input(slots, call.inputs, 0), input(slots, call.inputs, 1),
                                input(slots, call.inputs, 2), ctx);
        // Only the tables make a field non-Gaussian; MeanOnly drops what they add.
        if (givesField(op) && op.table >= 0 && moments_ == GraphMoments::MeanOnly) slots[out].y = 0.0f;
        ++out;
    }
    return toRgb(slots[out - 1]);
}

namespace {

// Where the colormap op's opFiltered reads the prefiltered table for a
// pair's means and variances: (μx, μy, σx, σy).
std::array<float, 4> plainTableCoordinates(float meanX, float meanY, float varX, float varY) {
    return {meanX, meanY, kernel::momentSigma(vec2(meanX, std::max(varX, 0.0f))),
            kernel::momentSigma(vec2(meanY, std::max(varY, 0.0f)))};
}

}  // namespace

Rgb FilteredGraph::plainColour(const FootprintStats& s) const {
    // The colormap op's opFiltered on the pair's moments, without the interpreter.
    const auto [mx, my, sx, sy] = plainTableCoordinates(s.mean[0], s.mean[1], s.varX, s.varY);
    return tables_.front()->sample(mx, my, sx, sy);
}

Rgb FilteredGraph::fromPairStats(Scratch& scratch, const Direction& eye) const {
    if (plain_) return plainColour(scratch.stats.front());
    if (scratch.slots.size() != size_t(graph_.outputSlot() + 2)) scratch.slots = graph_.makeSlots();
    scratch.covariances.clear();
    for (const FootprintStats& s : scratch.stats) scratch.covariances.push_back(s.cov);
    for (int k = 0; k < graph_.leafCount(); ++k) {
        const auto [pair, channel] = graph_.leafLocation(k);
        const FootprintStats& s = scratch.stats[size_t(pair)];
        scratch.slots[size_t(k)] = vec3(s.mean[size_t(channel)], std::max(channel == 0 ? s.varX : s.varY, 0.0f), 0.0f);
    }
    return runFiltered(scratch, eye);
}

namespace {

// A pair's view of uv's footprint: its transform applied to the centre and the Jacobian.
Jacobian transformed(const UvTransform& t, const Jacobian& j) {
    const auto [dudx, dvdx] = t.linear(j.dudx, j.dvdx);
    const auto [dudy, dvdy] = t.linear(j.dudy, j.dvdy);
    Jacobian r = j;
    r.dudx = dudx;
    r.dvdx = dvdx;
    r.dudy = dudy;
    r.dvdy = dvdy;
    return r;
}

}  // namespace

void FilteredGraph::footprints(double u, double v, const Jacobian& j, Scratch& scratch) const {
    scratch.footprints.clear();
    for (size_t k = 0; k < estimators_.size(); ++k) {
        const UvTransform& t = graph_.pairTransform(int(k));
        const auto [pu, pv] = t.apply(u, v);
        const FootprintEstimator& e = *estimators_[k];
        scratch.footprints.push_back(
            makeFootprint(pu, pv, transformed(t, j), e.exampleSize(), e.maxLod(), options_.aniso));
    }
}

Rgb FilteredGraph::shade(Scratch& scratch, const Direction& eye) const {
    scratch.stats.clear();
    for (size_t k = 0; k < estimators_.size(); ++k)
        scratch.stats.push_back(estimators_[k]->estimate(scratch.footprints[k], options_.estimator));
    return fromPairStats(scratch, eye);
}

Rgb FilteredGraph::shade(bool onPlane, double u, double v, const Jacobian& j, const Direction& eye) const {
    Scratch scratch;
    return shade(onPlane, u, v, j, eye, scratch);
}

Rgb FilteredGraph::shade(bool onPlane, double u, double v, const Jacobian& j, const Direction& eye,
                         Scratch& scratch) const {
    if (!onPlane) return sky_;
    switch (options_.source) {
        case StatisticsSource::Point: return graph_.evaluate(u, v, -1, eye, scratch.slots);
        case StatisticsSource::Estimators: footprints(u, v, j, scratch); return shade(scratch, eye);
        case StatisticsSource::Exact: {
            scratch.stats.clear();
            for (size_t k = 0; k < graph_.leafPairs().size(); ++k) {
                const UvTransform& t = graph_.pairTransform(int(k));
                const auto [pu, pv] = t.apply(u, v);
                scratch.stats.push_back(bruteForceStats(graph_.leafPairs()[k], pu, pv, transformed(t, j),
                                                        options_.referenceMaxSamples, options_.referenceMinSamples));
            }
            return fromPairStats(scratch, eye);
        }
        case StatisticsSource::Reference: {
            int size = 0;  // the finest leaf sets the sampling
            for (const TiledField& pair : graph_.leafPairs()) size = std::max(size, pair.exampleSize());
            const int n = bruteForceSamples(j, size, options_.referenceMaxSamples, options_.referenceMinSamples);
            return supersampledAverage(
                u, v, j, n, [&](double pu, double pv) { return graph_.evaluate(pu, pv, -1, eye, scratch.slots); });
        }
    }
    return sky_;
}

Image FilteredGraph::render(const Camera& camera, const Progress& progress) const {
    validateCamera(camera);
    if (options_.source == StatisticsSource::Point && camera.kind == Camera::Kind::Zoom)
        return graph_.render(camera.view, progress, options_.cpuKernel);
    if (options_.source == StatisticsSource::Reference && camera.kind == Camera::Kind::Zoom)
        return renderZoomReference(camera, progress);
    Image out(camera.view.width, camera.view.height, 3, Image::Uninitialized{});
    const int w = graph_.exampleSize();
    // A zoom has one Jacobian for the whole image: its footprints are built
    // once and translated to each pixel.
    const bool oneFootprint = camera.kind == Camera::Kind::Zoom && options_.source == StatisticsSource::Estimators;
    const bool shadesLight = graph_.shadesLight();
    const bool plainEstimate =
        options_.source == StatisticsSource::Estimators && plain_ && graph_.pairTransform(0).identity();
    std::vector<Footprint> shapes;
    if (oneFootprint) {
        double u = 0, v = 0;
        Jacobian j;
        camera.footprint(0, 0, w, u, v, j);
        for (size_t k = 0; k < estimators_.size(); ++k) {  // at the origin of each pair's uv, translated per pixel
            const FootprintEstimator& e = *estimators_[k];
            shapes.push_back(makeFootprint(0.0, 0.0, transformed(graph_.pairTransform(int(k)), j), e.exampleSize(),
                                           e.maxLod(), options_.aniso));
        }
    }
    if (plainEstimate && oneFootprint && options_.cpuKernel == CpuKernel::Simd && !graph_.grid().periodic() &&
        zoomInLanes(shapes.front()))
        return renderZoomInLanes(camera, shapes.front(), progress);
    parallelRows(
        camera.view.height,
        [&](int y0, int y1) {
            // This thread's own copy of what it reads per pixel: writes of
            // another thread to memory beside the shared vector's (its own
            // scratch, allocated next to it) would evict it (false sharing).
            Scratch scratch;
            const std::vector<Footprint> zoomShapes = shapes;
            for (int py = y0; py < y1; ++py)
                for (int px = 0; px < camera.view.width; ++px) {
                    double u = 0, v = 0;
                    Jacobian j;
                    const bool onPlane = camera.footprint(px, py, w, u, v, j);
                    // Only a lean node reads where the eye is.
                    const Direction eye = shadesLight ? camera.viewDirection(px, py) : GraphPattern::kFromAbove;
                    Rgb c;
                    if (!onPlane) {
                        c = sky_;
                    } else if (plainEstimate) {
                        // A plain program: one estimate and one lookup per
                        // pixel, as the interpreter's colormap op would
                        // compute (bit-identical; tested).
                        const FootprintEstimator& e = *estimators_.front();
                        const Footprint f = oneFootprint
                                                ? zoomShapes.front().translated(u, v)
                                                : makeFootprint(u, v, j, e.exampleSize(), e.maxLod(), options_.aniso);
                        c = plainColour(e.estimate(f, options_.estimator));
                    } else if (oneFootprint) {
                        scratch.footprints.clear();
                        for (size_t k = 0; k < zoomShapes.size(); ++k) {
                            const auto [pu, pv] = graph_.pairTransform(int(k)).apply(u, v);
                            scratch.footprints.push_back(zoomShapes[k].translated(pu, pv));
                        }
                        c = shade(scratch, eye);
                    } else {
                        c = shade(true, u, v, j, eye, scratch);
                    }
                    std::copy(c.begin(), c.end(), out.row(py) + size_t(px) * 3);
                }
        },
        progress);
    return out;
}

bool FilteredGraph::zoomInLanes(const Footprint& shape) const {
    const FootprintEstimator& e = *estimators_.front();
    const bool oneLevelVariance =
        options_.estimator == VarianceEstimator::Paper || options_.estimator == VarianceEstimator::DeliotHeitz;
    return shape.layout.count == 1 && oneLevelVariance && !e.covariancePyramid();
}

namespace {

// One pixel of a row whose texel statistics the lanes computed, as the
// kernel's texel source (kernel/estimate.glsl) gives a probe's reads.
struct RowTexels {
    const std::array<std::array<float*, 4>, 2>* rows;  // per level: N̂_x, N̂_y, σ̂²_x, σ̂²_y
    size_t px;
};
kernel::TexelStats rowTexel(const RowTexels& s, int k) {
    const std::array<float*, 4>& r = (*s.rows)[size_t(k)];
    kernel::TexelStats t;
    t.mean = kernel::vec2(r[0][s.px], r[1][s.px]);
    t.var = kernel::vec2(r[2][s.px], r[3][s.px]);
    t.cov = 0.0f;
    return t;
}
kernel::ProbeTexels probeTexels(const RowTexels& s) { return {rowTexel(s, 0), rowTexel(s, 1)}; }

}  // namespace

Image FilteredGraph::renderZoomInLanes(const Camera& camera, const Footprint& shape, const Progress& progress) const {
    const View& view = camera.view;
    const FootprintEstimator& e = *estimators_.front();
    const TiledField& field = graph_.leafPairs().front();
    // The levels the kernel's loop will read: l0, and l1 where it weighs.
    const kernel::ProbeLevels levels = kernel::probeLevels(shape.layout.lod, e.maxLod(), 1);
    const int levelCount = levels.w1 > 0.0f ? 2 : 1;
    const bool single = kernel::isSingleTexel(1, levels.frac);
    // One texel of level 0 (a zoom at one texel per pixel): its mean is the
    // example's texel and its variance 0, so the example's own grid serves,
    // one channel instead of the pyramid's interleaved two (not with 8-bit
    // pyramids, whose means are rounded).
    const bool exampleTexels = single && levels.l0 == 0 && !options_.pack8;
    const kernel::vec3 averageL0 = e.levelAverages(levels.l0), averageL1 = e.levelAverages(levels.l1);
    const std::array<int, 2> level{levels.l0, levels.l1};
    const bool deliotHeitz = options_.estimator == VarianceEstimator::DeliotHeitz;
    const double invW = 1.0 / double(graph_.exampleSize());
    const size_t padded = size_t(paddedLaneCount(view.width));
    Image out(view.width, view.height, 3, Image::Uninitialized{});
    parallelRows(
        view.height,
        [&](int y0, int y1) {
            GridRowLanes grid;
            std::vector<float> buffer(padded * 8);
            // Per pixel: the prefiltered table's coordinates (μx, μy, σx, σy).
            std::array<std::vector<float>, 4> coordinates;
            for (std::vector<float>& c : coordinates) c.resize(size_t(view.width));
            // Per level k: the rows N̂_x, N̂_y, σ̂²_x, σ̂²_y.
            std::array<std::array<float*, 4>, 2> rows{};
            for (size_t k = 0; k < 2; ++k)
                for (size_t a = 0; a < 4; ++a) rows[k][a] = buffer.data() + padded * (4 * k + a);
            for (int py = y0; py < y1; ++py) {
                grid.compute(view.offsetU, view.scale, invW, pixelUv(view, invW, 0, py)[1], view.width, field.grid());
                for (size_t a = 0; a < 2; ++a) {
                    if (exampleTexels)  // the variance rows stay 0
                        blendExampleRowLanes(field.channel(int(a)), grid, rows[0][a]);
                    else if (levelCount == 1)
                        blendRowLanes(field.channel(int(a)), e.pyramid(int(a)).level(level[0]), grid, rows[0][a],
                                      rows[0][2 + a]);
                    else
                        blendRowLanes(field.channel(int(a)), e.pyramid(int(a)).level(level[0]),
                                      e.pyramid(int(a)).level(level[1]), grid, rows[0][a], rows[0][2 + a], rows[1][a],
                                      rows[1][2 + a]);
                }
                if (exampleTexels && !deliotHeitz) {
                    // The kernel's estimate below is then each texel as it
                    // is (texelMoments), its variance the rows' 0, so σ̂ = 0
                    // and the lookups read the rows' means on the table's
                    // layer (0, 0): the same values, without the per-pixel
                    // coordinates (a fifth of this zoom's instructions).
                    tables_.front()->sampleRowWithoutDeviations(rows[0][0], rows[0][1], out.row(py),
                                                                size_t(view.width));
                    continue;
                }
                // The kernel's loop (kernel::footprintEstimate) for one probe
                // at each pixel, its layout the row's: the probe's reads
                // (Deliot–Heitz's variances in place of theirs), eq. 14–15
                // over its two levels, or for a single texel its statistics
                // as they are. Not the loop itself, which redoes the
                // layout's arithmetic at every pixel (this per-pixel work
                // took 2.3x the instructions through it at 4.7 texels a
                // pixel). The row's two choices are template arguments, so
                // each loop is branch-free (and the single texel's
                // vectorises); two levels without Deliot–Heitz go through
                // the same formulas in lanes (probeMomentsLanes, the
                // kernel's values bit for bit), a vector of pixels at a time.
                const auto estimateRow = [&](auto isSingle, auto isDeliotHeitz) {
                    size_t first = 0;  // the first pixel the loop below does
                    if constexpr (!isSingle && !isDeliotHeitz) {
                        const size_t width = size_t(view.width);
                        for (size_t a = 0; a < 2; ++a)
                            first =
                                probeMomentsLanes(rows[0][a], rows[0][2 + a], rows[1][a], rows[1][2 + a], levels.w0,
                                                  levels.w1, width, coordinates[a].data(), coordinates[2 + a].data());
                    }
                    for (size_t px = first; px < size_t(view.width); ++px) {
                        kernel::ProbeTexels t = probeTexels(RowTexels{&rows, px});
                        if constexpr (isDeliotHeitz) t = kernel::deliotHeitzProbe(t, averageL0, averageL1, false);
                        kernel::FootprintMoments r;
                        if constexpr (isSingle)
                            r = kernel::texelMoments(t.lo);
                        else
                            r = kernel::momentsResult(
                                kernel::momentsAddProbe(kernel::momentsAbout(t.lo.mean), t, levels));
                        // plainColour's lookup, done for the whole row below.
                        const std::array<float, 4> at = plainTableCoordinates(r.mean.x, r.mean.y, r.var.x, r.var.y);
                        for (size_t i = 0; i < 4; ++i) coordinates[i][px] = at[i];
                    }
                };
                const std::true_type yes;
                const std::false_type no;
                if (single)
                    deliotHeitz ? estimateRow(yes, yes) : estimateRow(yes, no);
                else
                    deliotHeitz ? estimateRow(no, yes) : estimateRow(no, no);
                tables_.front()->sampleRow(coordinates[0].data(), coordinates[1].data(), coordinates[2].data(),
                                           coordinates[3].data(), out.row(py), size_t(view.width));
            }
        },
        progress);
    return out;
}

}  // namespace stochtex

namespace stochtex {

Image FilteredGraph::renderZoomReference(const Camera& camera, const Progress& progress) const {
    // A zoom's pixel (px, py) covers the texels offset + [p, p + 1)·scale,
    // and shade's n×n cell centres in it are offset + (p·n + a + ½)·scale/n:
    // the centres of the point image at n times the resolution. So the
    // reference is that image box-filtered, rendered by the point loop
    // (tile rows shared along a row, a plain program's one lookup) instead of
    // one program evaluation per sample. Tiles keep the fine image small.
    const int w = graph_.exampleSize();
    double u = 0, v = 0;
    Jacobian j;
    camera.footprint(0, 0, w, u, v, j);
    int size = 0;  // the finest leaf sets the sampling, as in shade
    for (const TiledField& pair : graph_.leafPairs()) size = std::max(size, pair.exampleSize());
    const int n = bruteForceSamples(j, size, options_.referenceMaxSamples, options_.referenceMinSamples);
    const View& view = camera.view;
    const int tile = std::max(1, 1024 / n);  // pixels per tile side: at most 1024² samples a tile
    const int tilesX = (view.width + tile - 1) / tile, tilesY = (view.height + tile - 1) / tile;
    Image out(view.width, view.height, 3, Image::Uninitialized{});
    const double inv = 1.0 / (double(n) * n);
    for (int ty = 0; ty < tilesY; ++ty) {
        for (int tx = 0; tx < tilesX; ++tx) {
            const int x0 = tx * tile, y0 = ty * tile;
            const int tw = std::min(tile, view.width - x0), th = std::min(tile, view.height - y0);
            View fine;
            fine.width = tw * n;
            fine.height = th * n;
            fine.scale = view.scale / n;
            fine.offsetU = view.offsetU + x0 * view.scale;
            fine.offsetV = view.offsetV + y0 * view.scale;
            const Image samples = graph_.render(
                fine, progressPart(progress, ty * tilesX + tx, tilesX * tilesY, "reference"), options_.cpuKernel);
            parallelRows(th, [&](int r0, int r1) {
                for (int py = r0; py < r1; ++py) {
                    float* row = out.row(y0 + py) + size_t(x0) * 3;
                    for (int px = 0; px < tw; ++px) {
                        double acc[3] = {0, 0, 0};
                        for (int b = 0; b < n; ++b) {
                            const float* s = samples.row(py * n + b) + size_t(px) * size_t(n) * 3;
                            for (int a = 0; a < n; ++a)
                                for (int k = 0; k < 3; ++k) acc[k] += s[a * 3 + k];
                        }
                        for (int k = 0; k < 3; ++k) row[px * 3 + k] = float(acc[k] * inv);
                    }
                }
            });
        }
    }
    return out;
}

}  // namespace stochtex
