#include "stochtex/gpu/gpu_graph.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <sstream>

#include "stochtex/core/error.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/gpu/uploads.h"
#include "stochtex/kernel/pattern_params.h"
#include "stochtex/pattern/part_cache.h"

namespace stochtex {

namespace {

std::string slot(int k) { return "v" + std::to_string(k); }

// A pair's uv (and Jacobian columns) through its transform of uv: the
// kernel's transformUv / transformVector (kernel/camera.glsl, which
// UvTransform calls on the CPU) with the transform's numbers; "uv" itself
// when it is the identity.
std::string pairUv(const UvTransform& t, const std::string& v, bool withOffset) {
    if (t.identity()) return v;
    const auto f = [](double x, double y) { return "vec2(" + glslFloat(float(x)) + ", " + glslFloat(float(y)) + ")"; };
    return (withOffset ? "transformUv(" : "transformVector(") + v + ", " + f(t.m[0], t.m[1]) + ", " +
           f(t.m[2], t.m[3]) + (withOffset ? ", " + f(t.t[0], t.t[1]) : std::string()) + ")";
}

// Texture units: a fragment shader has at least 16.
constexpr int kMaxUnits = 16;

}  // namespace

namespace {

// The host side of the ops' interface (pattern/ops/op_host.h) for this
// graph: OpContext, and the table lookups over the graph's samplers by the
// op's table index (a constant in each call, so the branches fold away).
void writeOpHost(std::ostringstream& o, const GraphPattern& graph, GraphMoments moments) {
    // Each op's kernel file (with ops/op_host.glsl, which declares OpContext
    // and these two lookups) is assembled before this chunk.
    std::vector<std::string> stems;
    for (const GraphPattern::Operation& op : graph.operations())
        for (const bool matched : {false, true})
            if (const char* stem = opKernelStem(GraphPattern::filteredCall(op, matched).params);
                std::find(stems.begin(), stems.end(), stem) == stems.end())
                stems.emplace_back(stem);
    for (const std::string& stem : stems) o << "#include \"stochtex/pattern/ops/" << stem << ".glsl\"\n";
    for (const bool filtered : {false, true}) {
        o << (filtered ? "vec3 opPrefiltered(OpContext ctx, vec2 xy, vec2 sigma) {\n"
                       : "vec3 opTable(OpContext ctx, vec2 xy) {\n");
        for (size_t t = 0; t < graph.tables().size(); ++t) {
            if (!graph.readsTable(int(t), filtered, moments == GraphMoments::Matched)) continue;
            const BetaAxes& beta = graph.tables()[t].beta;
            o << "    if (ctx.table == " << t << ") return "
              << (filtered ? "prefilteredLookup(uGraphPrefiltered" + std::to_string(t) + ", xy, sigma, ivec2(" +
                                 std::to_string(beta[0]) + ", " + std::to_string(beta[1]) + "))"
                           : "tableLookup(uGraphTable" + std::to_string(t) + ", 0, xy)")
              << ";\n";
        }
        o << "    return vec3(0.0);\n}\n";
    }
}

// Pair p's texel source (gpu/shaders/filtering.glsl) with its numbers.
std::string pairSource(const GraphPattern& graph, int p, int maxLod) {
    const TiledField& pair = graph.leafPairs()[size_t(p)];
    return "TexelSource(" + std::to_string(p) + ", vec2(" + glslFloat(pair.channel(0).example().mean()) + ", " +
           glslFloat(pair.channel(1).example().mean()) + "), uvec2(" + std::to_string(pair.channel(0).offsetSeed()) +
           "u, " + std::to_string(pair.channel(1).offsetSeed()) + "u), " + (graph.pairCovariance(p) ? "1" : "0") +
           ", " + std::to_string(maxLod) + ", " + glslFloat(float(pair.exampleSize())) + ")";
}

// The leaves pair p holds, as (channel x, channel y) (a leaf without a
// partner fills both channels).
std::array<int, 2> pairLeaves(const GraphPattern& graph, int p) {
    std::array<int, 2> leaves{-1, -1};
    for (int k = 0; k < graph.leafCount(); ++k)
        if (graph.leafLocation(k)[0] == p) leaves[size_t(graph.leafLocation(k)[1])] = k;
    if (leaves[1] < 0) leaves[1] = leaves[0];
    return leaves;
}

// statsCoding (gpu/shaders/filtering.glsl): each pair's per-level codes
// as constant arrays, or the float data's identity.
void writeStatsCoding(std::ostringstream& o, const GraphEstimator& estimator) {
    const auto vec = [](const auto& v) {
        std::string out = "vec" + std::to_string(v.size()) + "(";
        for (size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + glslFloat(v[i]);
        return out + ")";
    };
    o << "StatsCoding statsCoding(TexelSource s, int level) {\n";
    for (size_t p = 0; p < estimator.pyramidCoding.size(); ++p) {
        const auto& levels = estimator.pyramidCoding[p];
        const std::string n = std::to_string(levels.size());
        std::string offsets, scales, covariances;
        for (size_t l = 0; l < levels.size(); ++l) {
            const char* separator = l ? ", " : "";
            offsets.append(separator).append(vec(levels[l].offset));
            scales.append(separator).append(vec(levels[l].scale));
            covariances.append(separator).append(vec(levels[l].covariance));
        }
        o << "    if (s.pair == " << p << ") {\n"
          << "        const vec4 offset" << p << "[" << n << "] = vec4[" << n << "](" << offsets << ");\n"
          << "        const vec4 scale" << p << "[" << n << "] = vec4[" << n << "](" << scales << ");\n"
          << "        const vec2 covariance" << p << "[" << n << "] = vec2[" << n << "](" << covariances << ");\n"
          << "        return StatsCoding(offset" << p << "[level], scale" << p << "[level], covariance" << p
          << "[level], " << (estimator.packedPairs ? 1 : 0) << ");\n    }\n";
    }
    o << "    return StatsCoding(vec4(0.0), vec4(1.0), vec2(0.0, 1.0), 0);\n}\n";
}

// The texel source's two functions (kernel/estimate.glsl) over the graph's
// pyramids: a branch per pair (a constant in each call, so they fold
// away), then the kernel's loop; each pair's level averages as a constant
// array when there are any (the Deliot–Heitz estimator).
void writeTexelSource(std::ostringstream& o, const GraphPattern& graph, const GraphEstimator& estimator) {
    const LevelAverages& averages = estimator.levelAverages;
    o << "#include \"stochtex/kernel/estimate.glsl\"\n";
    o << "ProbeTexels probeTexels(TexelSource s, vec2 uv, ProbeLevels levels) {\n";
    const int pairs = int(graph.leafPairs().size());
    for (int p = 0; p < pairs; ++p) {
        const std::array<int, 2> leaves = pairLeaves(graph, p);
        const std::string packed = "uGraphPairStats" + std::to_string(p);
        const std::string x = estimator.packedPairs ? packed : "uGraphStats" + std::to_string(leaves[0]);
        const std::string y = estimator.packedPairs ? packed : "uGraphStats" + std::to_string(leaves[1]);
        const std::string cov = graph.pairCovariance(p) ? "uGraphCov" + std::to_string(p) : x;
        o << "    " << (p + 1 < pairs ? "if (s.pair == " + std::to_string(p) + ") " : std::string())
          << "return pairProbeTexels(" << x << ", " << y << ", " << cov << ", s, uv, levels);\n";
    }
    if (pairs == 0)
        o << "    TexelStats none = TexelStats(vec2(0.0), vec2(0.0), 0.0);\n    return ProbeTexels(none, none);\n";
    o << "}\nvec3 levelAverages(TexelSource s, int level) {\n";
    for (size_t p = 0; p < averages.size(); ++p) {
        o << "    if (s.pair == " << p << ") {\n        const vec3 a" << p << "[" << averages[p].size() << "] = vec3["
          << averages[p].size() << "](";
        for (size_t l = 0; l < averages[p].size(); ++l) {
            const kernel::vec3 a = averages[p][l];
            o << (l ? ", " : "") << "vec3(" << glslFloat(a.x) << ", " << glslFloat(a.y) << ", " << glslFloat(a.z)
              << ")";
        }
        o << ");\n        return a" << p << "[level];\n    }\n";
    }
    o << "    return vec3(0.0);\n}\n";
    writeStatsCoding(o, estimator);
}

// The operations after the leaves, on values (point) or on moments
// (filtered), in the CPU evaluator's order (pattern/graph_pattern.cpp): each
// op's call with its context — its table, the camera's eye, the scene's
// light (gLightDirection.w = 1 when it has one) and, filtered, the
// covariance of its Operation::covariancePair.
void writeOperations(std::ostringstream& o, const GraphPattern& graph, bool filtered, GraphMoments moments) {
    int out = graph.leafCount();
    const bool matched = moments == GraphMoments::Matched;
    for (const GraphPattern::Operation& op : graph.operations()) {
        if (filtered && !GraphPattern::runsFiltered(op, matched)) {  // read by none (functions of sources read past it)
            ++out;
            continue;
        }
        // Filtered, the op or its function of sources (GraphPattern::filteredCall, as the CPU runs it).
        const GraphPattern::OpCall call =
            filtered ? GraphPattern::filteredCall(op, matched) : GraphPattern::OpCall{op.params, op.inputs, op.table};
        const auto in = [&](int k) { return call.inputs[size_t(k)] >= 0 ? slot(call.inputs[size_t(k)]) : "vec3(0.0)"; };
        const std::string cov =
            filtered && op.covariancePair >= 0 ? "p" + std::to_string(op.covariancePair) + ".cov" : "0.0";
        const std::string ctx =
            "OpContext(" + std::to_string(call.table) + ", gEyeDirection, gLightDirection, " + cov + ")";
        o << "    vec3 " << slot(out) << " = " << opGlslCall(call.params, filtered, in(0), in(1), in(2), ctx)
          << ";  // " << op.id << (call.sourceFunction ? " (as a function of its sources)" : "") << "\n";
        // MeanOnly: a table's output field passes on its mean alone (FilteredGraph::fromMoments).
        const bool fieldTable = op.info->output != PortType::Colour && op.table >= 0;
        if (filtered && fieldTable && moments == GraphMoments::MeanOnly) o << "    " << slot(out) << ".y = 0.0;\n";
        ++out;
    }
    o << "    return " << slot(out - 1) << ";\n}\n";
}

}  // namespace

kernel::PatternParams patternParams(const GraphPattern& graph, const FilterOptions& options) {
    kernel::PatternParams p{};
    p.gridDensity = float(graph.grid().densityV);
    p.gridDensityU = float(graph.grid().densityU);
    p.gridPeriodU = graph.grid().period.x;
    p.gridPeriodV = graph.grid().period.y;
    p.invExampleSize = float(1.0 / graph.exampleSize());
    p.aniso = options.aniso;
    p.smoothTable = options.response.prefilter == PrefilterMode::Smooth;
    p.tableLevels = int(PrefilteredColormap::sigmaLevels(options.response.prefilter).size());
    return p;
}

GraphEstimator graphEstimator(const FilteredGraph& filtered, const FilterOptions& options) {
    GraphEstimator out;
    if (options.source != StatisticsSource::Estimators) return out;
    out.subProbes = subProbesOf(options.estimator);
    out.fineMeans = fineMeansOf(options.estimator);
    if (options.estimator == VarianceEstimator::DeliotHeitz)
        for (size_t p = 0; p < filtered.estimatorCount(); ++p) {
            const FootprintEstimator& e = filtered.estimator(int(p));
            std::vector<kernel::vec3>& levels = out.levelAverages.emplace_back();
            for (int l = 0; l <= e.maxLod(); ++l) levels.push_back(e.levelAverages(l));
        }
    return out;
}

std::string graphProgramSource(const GraphPattern& graph, GraphMoments moments, const GraphEstimator& estimator) {
    std::ostringstream o;
    o << "// Generated for one texture graph (gpu/gpu_graph.cpp): the pattern's two colour\n"
         "// functions, its leaves then its operations.\n"
         "#include \"stochtex/kernel/camera.glsl\"\n";  // transformUv
    // Each sampler with its own binding, in declaration order after the
    // parameter block's 0 (STOCHTEX_BINDING: Vulkan's layout in the export).
    int binding = 1;
    const auto sampler = [&](const char* type, const std::string& name, const std::string& comment) {
        o << "STOCHTEX_BINDING(" << binding++ << ") uniform " << type << " " << name << ";"
          << (comment.empty() ? "" : "  // " + comment) << "\n";
    };
    for (int k = 0; k < graph.leafCount(); ++k) {
        const std::string n = std::to_string(k);
        sampler("sampler2D", "uGraphExample" + n, "leaf \"" + graph.leafIds()[size_t(k)] + "\": example");
        if (!estimator.packedPairs) sampler("sampler2D", "uGraphStats" + n, "its (E, V) pyramid");
        if (graph.leaf(k).example().gaussianized()) sampler("sampler2D", "uGraphInverse" + n, "its T⁻¹ LUT");
    }
    if (estimator.packedPairs)
        for (size_t p = 0; p < graph.leafPairs().size(); ++p)
            sampler("sampler2D", "uGraphPairStats" + std::to_string(p),
                    "pair " + std::to_string(p) + "'s (E_x, E_y, V_x, V_y) pyramid, coded");
    // Each table where a program reads it: an op's own in the point program,
    // a function of sources only filtered (GraphPattern::readsTable).
    const bool matched = moments == GraphMoments::Matched;
    for (int t = 0; t < int(graph.tables().size()); ++t) {
        if (graph.readsTable(t, false, matched)) sampler("sampler2DArray", "uGraphTable" + std::to_string(t), "");
        if (graph.readsTable(t, true, matched)) sampler("sampler2DArray", "uGraphPrefiltered" + std::to_string(t), "");
    }
    for (size_t p = 0; p < graph.leafPairs().size(); ++p)
        if (graph.pairCovariance(int(p)))
            sampler("sampler2D", "uGraphCov" + std::to_string(p), "pair " + std::to_string(p) + "'s C_l pyramid");
    writeOpHost(o, graph, moments);
    writeTexelSource(o, graph, estimator);

    o << "\nvec3 unfilteredColour(vec2 uv) {\n";
    // One stencil per pair's uv (pairs under one transform share it).
    for (size_t p = 0; p < graph.leafPairs().size(); ++p)
        o << "    vec2 uv" << p << " = " << pairUv(graph.pairTransform(int(p)), "uv", true) << ";\n    Stencil s" << p
          << " = triangleGrid(uv" << p << ", patternGrid(uPattern));\n    vec2 fu" << p << " = fract(uv" << p << ");\n";
    for (int k = 0; k < graph.leafCount(); ++k) {
        const TilingBlendingNoise& n = graph.leaf(k);
        const int p = graph.leafLocation(k)[0];
        o << "    vec3 " << slot(k) << " = vec3(tilingBlending(uGraphExample" << k << ", "
          << glslFloat(n.example().mean()) << ", " << n.offsetSeed() << "u, s" << p << ", fu" << p << "), 0.0, 0.0);\n";
        if (n.example().gaussianized())
            o << "    " << slot(k) << ".x = inverseTransform(uGraphInverse" << k << ", " << slot(k) << ".x);\n";
    }
    writeOperations(o, graph, false, moments);

    o << "\nvec3 filteredColour(vec2 uv, vec2 jx, vec2 jy) {\n";
    for (size_t p = 0; p < graph.leafPairs().size(); ++p) {
        const TiledField& pair = graph.leafPairs()[p];
        const std::array<int, 2> leaves = pairLeaves(graph, int(p));
        int maxLod = 0;
        while ((1 << maxLod) < pair.exampleSize()) ++maxLod;
        const bool covariance = graph.pairCovariance(int(p));
        o << "    FootprintMoments p" << p << " = jacobianEstimate(" << pairSource(graph, int(p), maxLod) << ", "
          << pairUv(graph.pairTransform(int(p)), "uv", true) << ", " << pairUv(graph.pairTransform(int(p)), "jx", false)
          << ", " << pairUv(graph.pairTransform(int(p)), "jy", false) << ", " << glslFloat(float(pair.exampleSize()))
          << ", uPattern.aniso, " << maxLod << ", " << (estimator.levelAverages.empty() ? "false" : "true") << ", "
          << (covariance ? "true" : "false") << ", " << estimator.subProbes << ", "
          << (estimator.fineMeans ? "true" : "false") << ");\n";
        for (int c = 0; c < 2; ++c)
            if (c == 0 || leaves[1] != leaves[0])
                o << "    vec3 " << slot(leaves[c]) << " = vec3(p" << p << ".mean."
                  << "xy"[c] << ", max(p" << p << ".var."
                  << "xy"[c] << ", 0.0), 0.0);\n";
    }
    writeOperations(o, graph, true, moments);
    return o.str();
}

int graphTextureUnits(const GraphPattern& graph, bool filtered, bool packedPairs, GraphMoments moments) {
    int units = graph.leafCount();
    for (int k = 0; k < graph.leafCount(); ++k) units += graph.leaf(k).example().gaussianized();
    for (int t = 0; t < int(graph.tables().size()); ++t)
        units += graph.readsTable(t, false, false) +
                 (filtered && graph.readsTable(t, true, moments == GraphMoments::Matched));
    if (!filtered) return units;
    units += packedPairs ? int(graph.leafPairs().size()) : graph.leafCount();
    for (size_t p = 0; p < graph.leafPairs().size(); ++p) units += graph.pairCovariance(int(p));
    return units;
}

void checkGraphTextureUnits(const GraphPattern& graph, bool filtered, GraphMoments moments) {
    const int units = graphTextureUnits(graph, filtered, false, moments);
    if (units > kMaxUnits)
        throw InputError("the graph's GPU program reads " + std::to_string(units) + " textures " +
                         (filtered ? "filtered" : "unfiltered") + ", more than the " + std::to_string(kMaxUnits) +
                         " units a fragment shader has; use fewer leaves or tables");
}

namespace {

// The graph's programs, once the options are ones its GPU program has.
// The filtered graph the GPU reads, once the options are ones its GPU
// program has (checked first: they cost no pyramid).
std::shared_ptr<const FilteredGraph> gpuFilteredGraph(const GraphPattern& graph, const FilterOptions& options,
                                                      GraphMoments moments, PartCache* parts) {
    if (!gpuHasSource(options.source))
        throw InputError::parameter("source", "must be point or estimators on the GPU, got " +
                                                  enumName(kStatisticsSourceNames, options.source));
    checkGraphTextureUnits(graph, options.source == StatisticsSource::Estimators, moments);
    return std::make_shared<const FilteredGraph>(graph, options, moments, parts);
}

GpuView::Recipes graphRecipes(const GraphPattern& graph, const FilterOptions& options, GraphMoments moments,
                              const FilteredGraph& filtered) {
    const bool estimators = options.source == StatisticsSource::Estimators;
    return {estimators ? "graph-filtered" : "graph",
            estimators ? "graph-filtered-compute" : "graph-compute",
            "graph-scene",
            {{kGraphProgramStem, graphProgramSource(graph, moments, graphEstimator(filtered, options))}},
            graph.shadesLight()};
}

}  // namespace

struct GpuGraph::Impl {
    bool filtered = false;
    int tables = 0;  // the graph's, each with its uGraphPrefiltered sampler where a program reads it
    // Sampler name → texture; shared with a PartCache where the view was built with one.
    std::vector<std::pair<std::string, std::shared_ptr<const gl::Texture>>> planes, arrays;
    gl::Buffer parameters;
    Rgb sky{};
};

GpuGraph::GpuGraph(const GraphPattern& graph, GlContext& context, const FilterOptions& options, GraphMoments moments,
                   PartCache* parts)
    : GpuGraph(graph, context, options, moments, gpuFilteredGraph(graph, options, moments, parts), parts) {}

GpuGraph::GpuGraph(const GraphPattern& graph, GlContext& context, const FilterOptions& options, GraphMoments moments,
                   std::shared_ptr<const FilteredGraph> filteredGraph, PartCache* parts)
    : GpuView(context, graphRecipes(graph, options, moments, *filteredGraph), graph.exampleSize()),
      impl_(std::make_unique<Impl>()) {
    const bool filtered = options.source == StatisticsSource::Estimators;
    const FilteredGraph& f = *filteredGraph;  // the prefiltered tables, the pyramids, the sky
    Impl& m = *impl_;
    m.filtered = filtered;
    m.tables = int(graph.tables().size());
    m.sky = f.skyColour();
    const kernel::PatternParams p = patternParams(graph, options);
    // The texture of a part of the program: with `parts`, the one uploaded
    // when the part was built (an edit uploads only what it changed).
    const auto texture = [&](const std::shared_ptr<const void>& part, const std::string& what,
                             const std::function<gl::Texture()>& upload) -> std::shared_ptr<const gl::Texture> {
        const auto make = [&] { return std::make_shared<gl::Texture>(upload()); };
        if (!parts) return make();
        return std::static_pointer_cast<const gl::Texture>(parts->attachment(part, what, make));
    };
    for (int k = 0; k < graph.leafCount(); ++k) {
        const std::string leaf = std::to_string(k);
        const std::shared_ptr<const NoiseExample>& e = graph.leaf(k).sharedExample();
        m.planes.emplace_back("uGraphExample" + leaf, texture(e, "values", [&] {
                                  const Image& v = e->grid().values();
                                  return floatTexture(v.width(), v.height(), 1, v.data().data());
                              }));
        if (e->gaussianized())
            m.planes.emplace_back("uGraphInverse" + leaf, texture(e, "inverse", [&] {
                                      const std::vector<float>& lut = e->transform()->inverseLut();
                                      return floatTexture(int(lut.size()), 1, 1, lut.data());
                                  }));
        if (!filtered) continue;
        // Not a structured binding: the lambda below captures them (clang 14, the fuzz build, cannot).
        const int pair = graph.leafLocation(k)[0], channel = graph.leafLocation(k)[1];
        m.planes.emplace_back("uGraphStats" + leaf,
                              texture(f.sharedEstimator(pair), "pyramid " + std::to_string(channel),
                                      [&] { return pyramidTexture(f.estimator(pair).pyramid(channel)); }));
    }
    for (size_t p = 0; p < graph.leafPairs().size(); ++p)
        if (filtered && graph.pairCovariance(int(p)))
            m.planes.emplace_back("uGraphCov" + std::to_string(p),
                                  texture(f.sharedEstimator(int(p)), "covariance",
                                          [&] { return pyramidTexture(*f.estimator(int(p)).covariancePyramid()); }));
    for (size_t t = 0; t < graph.tables().size(); ++t) {
        const std::string table = std::to_string(t);
        if (graph.readsTable(int(t), false, false)) {
            const Image point = graph.tables()[t].point.table();
            m.arrays.emplace_back("uGraphTable" + table, std::make_shared<const gl::Texture>(tableTexture(
                                                             point.width(), point.height(), 1, point.data().data())));
        }
        if (!filtered || !graph.readsTable(int(t), true, moments == GraphMoments::Matched)) continue;
        // The prefiltered table's layers at the table's resolution (atlas), made for the upload alone.
        const ColormapTable& h = graph.tables()[t].blended;
        const int rx = h.resolutionX(), ry = h.resolutionY();
        const int layers = int(f.table(int(t)).sigmas().size() * f.table(int(t)).sigmas().size());
        m.arrays.emplace_back(
            "uGraphPrefiltered" + table,
            texture(f.sharedTable(int(t)), "atlas " + std::to_string(rx) + "x" + std::to_string(ry), [&] {
                const Image atlas = f.table(int(t)).atlas(rx, ry);
                return tableTexture(rx, ry, layers, atlas.data().data());
            }));
    }
    m.parameters = gl::newBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, m.parameters.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof p, &p, GL_STATIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

GpuGraph::~GpuGraph() = default;

bool GpuGraph::filtered() const { return impl_->filtered; }

std::unique_ptr<GpuView> makeGpuView(const PatternSpec& spec, GlContext& context, const FilterOptions& options,
                                     PartCache* parts) {
    return std::make_unique<GpuGraph>(GraphPattern::build(spec, options.response, parts), context, options,
                                      GraphMoments::Matched, parts);
}

namespace {

// A GpuView with the context it draws in (destroyed after it).
class HeadlessGpuRenderer final : public ViewRenderer {
public:
    HeadlessGpuRenderer(const PatternSpec& spec, const FilterOptions& options, GpuView::Pipeline pipeline,
                        GpuView::Derivatives derivatives)
        : context_(GlContext::headless()), view_(makeGpuView(spec, *context_, options)) {
        view_->setDerivatives(derivatives);
        view_->setPipeline(pipeline);
    }
    Image render(const Camera& camera, const Progress& progress) const override {
        context_->makeCurrent();
        return view_->render(camera, progress);
    }
    int exampleSize() const override { return view_->exampleSize(); }
    std::string device() const override { return view_->device(); }

private:
    std::unique_ptr<GlContext> context_;
    std::unique_ptr<GpuView> view_;
};

}  // namespace

std::unique_ptr<ViewRenderer> makeGpuRenderer(const PatternSpec& spec, const FilterOptions& options,
                                              GpuView::Pipeline pipeline, GpuView::Derivatives derivatives) {
    return std::make_unique<HeadlessGpuRenderer>(spec, options, pipeline, derivatives);
}

void GpuGraph::bind(unsigned program) const {
    const Impl& m = *impl_;
    glUseProgram(program);
    int unit = 0;
    const auto bind = [&](GLenum target, const std::string& name, GLuint texture) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(target, texture);
        glUniform1i(glGetUniformLocation(program, name.c_str()), unit++);
    };
    for (const auto& [name, texture] : m.planes) bind(GL_TEXTURE_2D, name, texture->id());
    for (const auto& [name, texture] : m.arrays) bind(GL_TEXTURE_2D_ARRAY, name, texture->id());
    // Samplers declared but not bound (the filtered set when unfiltered):
    // on a unit of their own type, since GL refuses to
    // draw when samplers of two types share one.
    for (int k = 0; k < kMaxUnits; ++k) {
        const std::string leaf = std::to_string(k);
        for (const std::string& name : {"uGraphStats" + leaf, "uGraphInverse" + leaf, "uGraphCov" + leaf})
            if (std::none_of(m.planes.begin(), m.planes.end(), [&](const auto& p) { return p.first == name; }))
                glUniform1i(glGetUniformLocation(program, name.c_str()), 0);
    }
    // Every table's (a function of sources comes after the ops' tables, past 16 in a long graph).
    for (int t = 0; t < m.tables; ++t) {
        const std::string name = "uGraphPrefiltered" + std::to_string(t);
        if (std::none_of(m.arrays.begin(), m.arrays.end(), [&](const auto& a) { return a.first == name; }))
            glUniform1i(glGetUniformLocation(program, name.c_str()), int(m.planes.size()));
    }
    const GLuint block = glGetUniformBlockIndex(program, kPatternBlockName);
    if (block != GL_INVALID_INDEX) glUniformBlockBinding(program, block, kPatternBlockBinding);
    glBindBufferBase(GL_UNIFORM_BUFFER, kPatternBlockBinding, m.parameters.id());
    glUniform3f(glGetUniformLocation(program, "uSky"), m.sky[0], m.sky[1], m.sky[2]);
}

}  // namespace stochtex
