#include "stochtex/gpu/gpu_graph.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "stochtex/core/error.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/gpu/uploads.h"
#include "stochtex/kernel/pattern_params.h"

namespace stochtex {

namespace {

// A float as a GLSL literal that reads back as the same float.
std::string glslFloat(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", double(v));
    std::string s = buffer;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string slot(int k) { return "v" + std::to_string(k); }

// A pair's uv (and Jacobian columns) through its transform of uv, written
// out with the transform's numbers: "uv" itself when it is the identity.
std::string pairUv(const UvTransform& t, const std::string& v, bool withOffset) {
    if (t.identity()) return v;
    const auto f = [](double x) { return glslFloat(float(x)); };
    std::string s = "vec2(" + f(t.m[0]) + " * " + v + ".x + " + f(t.m[1]) + " * " + v + ".y";
    if (withOffset) s += " + " + f(t.t[0]);
    s += ", " + f(t.m[2]) + " * " + v + ".x + " + f(t.m[3]) + " * " + v + ".y";
    if (withOffset) s += " + " + f(t.t[1]);
    return s + ")";
}

// Texture units: a fragment shader has at least 16.
constexpr int kMaxUnits = 16;

}  // namespace

namespace {

// The operations after the leaves, on values (point) or on moments
// (filtered), in the CPU evaluator's order (pattern/graph_pattern.cpp).
void writeOperations(std::ostringstream& o, const GraphPattern& graph, bool filtered, GraphMoments moments) {
    int out = graph.leafCount();
    for (const GraphPattern::Operation& op : graph.operations()) {
        const std::string a = slot(op.inputs[0]), b = op.inputs[1] >= 0 ? slot(op.inputs[1]) : "",
                          t = op.inputs[2] >= 0 ? slot(op.inputs[2]) : "";
        const std::string table = (filtered ? "uGraphPrefiltered" : "uGraphTable") + std::to_string(op.table);
        const std::string sigmas = "vec2(momentSigma(" + a + ".xy), momentSigma(" + b + ".xy))";
        const std::string p0 = glslFloat(op.parameters[0]), p1 = glslFloat(op.parameters[1]);
        o << "    vec3 " << slot(out) << " = ";
        switch (op.kind) {
            case NodeKind::Colormap:
                if (filtered)
                    o << "prefilteredLookup(" << table << ", vec2(" << a << ".x, " << b << ".x), " << sigmas << ")";
                else
                    o << "tableLookup(" << table << ", 0, vec2(" << a << ".x, " << b << ".x))";
                break;
            case NodeKind::ColormapField:
                if (filtered)
                    o << "vec3(matchedMoments(prefilteredLookup(" << table << ", vec2(" << a << ".x, " << b << ".x), "
                      << sigmas << ")), 0.0)";
                else
                    o << "tableLookup(" << table << ", 0, vec2(" << a << ".x, " << b << ".x))";
                break;
            case NodeKind::Curve:
                if (filtered)
                    o << "vec3(matchedMoments(prefilteredLookup(" << table << ", vec2(" << a << ".x, 0.5), vec2(momentSigma("
                      << a << ".xy), 0.0))), 0.0)";
                else
                    o << "tableLookup(" << table << ", 0, vec2(" << a << ".x, 0.5))";
                break;
            case NodeKind::Affine:
                if (filtered)
                    o << "vec3(affineMoments(" << a << ".xy, " << p0 << ", " << p1 << "), 0.0)";
                else
                    o << "vec3(affineValue(" << a << ".x, " << p0 << ", " << p1 << "), 0.0, 0.0)";
                break;
            case NodeKind::Sum:
                if (filtered)
                    o << "vec3(sumMoments(" << a << ".xy, " << b << ".xy, " << p0 << ", " << p1 << "), 0.0)";
                else
                    o << "vec3(sumValue(" << a << ".x, " << b << ".x, " << p0 << ", " << p1 << "), 0.0, 0.0)";
                break;
            case NodeKind::Mix: o << "mixColour(" << a << ", " << b << ", " << t << ".x)"; break;
            case NodeKind::Compose: o << "composeColour(" << a << ".x, " << b << ".x, " << t << ".x)"; break;
            case NodeKind::Lean: {
                // The scene's light when it has one (gLightDirection.w = 1), else the node's; the camera's eye.
                const auto& q = op.parameters;
                const std::string light = "(gLightDirection.w != 0.0 ? gLightDirection.xyz : vec3(" + glslFloat(q[2]) +
                                          ", " + glslFloat(q[3]) + ", " + glslFloat(q[4]) + "))";
                const int pair = graph.leafLocation(op.inputs[0])[0];
                const std::string cov = filtered && q[5] != 0 ? "p" + std::to_string(pair) + ".cov" : "0.0";
                o << "leanNodeShade(vec2(" << a << ".x, " << b << ".x), " << (filtered ? "vec2(" + a + ".y, " + b + ".y)" : "vec2(0.0)")
                  << ", " << cov << ", " << t << ", " << light << ", gEyeDirection, " << glslFloat(q[0]) << ", "
                  << glslFloat(q[1]) << ")";
                break;
            }
            default: throw std::logic_error("graphProgramSource: a source as an operation");
        }
        o << ";  // " << op.id << "\n";
        // MeanOnly: a table's output field passes on its mean alone (FilteredGraph::fromMoments).
        const bool fieldTable = op.kind == NodeKind::ColormapField || op.kind == NodeKind::Curve;
        if (filtered && fieldTable && moments == GraphMoments::MeanOnly) o << "    " << slot(out) << ".y = 0.0;\n";
        ++out;
    }
    o << "    return " << slot(out - 1) << ";\n}\n";
}

}  // namespace

std::string graphProgramSource(const GraphPattern& graph, GraphMoments moments) {
    std::ostringstream o;
    o << "// Generated for one texture graph (gpu/gpu_graph.cpp): the pattern's two colour\n"
         "// functions, its leaves then its operations.\n";
    for (int k = 0; k < graph.leafCount(); ++k) {
        o << "uniform sampler2D uGraphExample" << k << ", uGraphStats" << k << ";  // leaf \""
          << graph.leafIds()[size_t(k)] << "\": example, (E, V) pyramid\n";
        if (graph.leaf(k).example().gaussianized()) o << "uniform sampler2D uGraphInverse" << k << ";  // T⁻¹ LUT\n";
    }
    for (size_t t = 0; t < graph.tables().size(); ++t)
        o << "uniform sampler2DArray uGraphTable" << t << ", uGraphPrefiltered" << t << ";\n";
    for (size_t p = 0; p < graph.leafPairs().size(); ++p)
        if (graph.pairCovariance(int(p))) o << "uniform sampler2D uGraphCov" << p << ";  // pair " << p << "'s C_l pyramid\n";

    o << "\nvec3 unfilteredColour(vec2 uv) {\n";
    // One stencil per pair's uv (pairs under one transform share it).
    for (size_t p = 0; p < graph.leafPairs().size(); ++p)
        o << "    vec2 uv" << p << " = " << pairUv(graph.pairTransform(int(p)), "uv", true) << ";\n    Stencil s" << p
          << " = triangleGrid(uv" << p << ", uPattern.gridDensity);\n    vec2 fu" << p << " = fract(uv" << p << ");\n";
    for (int k = 0; k < graph.leafCount(); ++k) {
        const TilingBlendingNoise& n = graph.leaf(k);
        const int p = graph.leafLocation(k)[0];
        o << "    vec3 " << slot(k) << " = vec3(tilingBlending(uGraphExample" << k << ", " << glslFloat(n.example().mean())
          << ", " << n.offsetSeed() << "u, s" << p << ", fu" << p << "), 0.0, 0.0);\n";
        if (n.example().gaussianized())
            o << "    " << slot(k) << ".x = inverseTransform(uGraphInverse" << k << ", " << slot(k) << ".x);\n";
    }
    writeOperations(o, graph, false, moments);

    o << "\nvec3 filteredColour(vec2 uv, vec2 jx, vec2 jy) {\n";
    for (size_t p = 0; p < graph.leafPairs().size(); ++p) {
        const TiledField& pair = graph.leafPairs()[p];
        // The leaves this pair holds (a leaf without a partner fills both channels).
        int leaves[2] = {-1, -1};
        for (int k = 0; k < graph.leafCount(); ++k)
            if (graph.leafLocation(k)[0] == int(p)) leaves[graph.leafLocation(k)[1]] = k;
        if (leaves[1] < 0) leaves[1] = leaves[0];
        int maxLod = 0;
        while ((1 << maxLod) < pair.exampleSize()) ++maxLod;
        const bool covariance = graph.pairCovariance(int(p));
        o << "    FootprintMoments p" << p << " = pairStatistics(uGraphStats" << leaves[0] << ", uGraphStats" << leaves[1]
          << ", " << (covariance ? "uGraphCov" + std::to_string(p) : "uGraphStats" + std::to_string(leaves[0]))
          << ", NoisePair(vec2(" << glslFloat(pair.channel(0).example().mean()) << ", "
          << glslFloat(pair.channel(1).example().mean()) << "), uvec2(" << pair.channel(0).offsetSeed() << "u, "
          << pair.channel(1).offsetSeed() << "u), " << (covariance ? 1 : 0) << ", 0, " << maxLod << ", " << glslFloat(float(pair.exampleSize()))
          << "), " << pairUv(graph.pairTransform(int(p)), "uv", true) << ", "
          << pairUv(graph.pairTransform(int(p)), "jx", false) << ", " << pairUv(graph.pairTransform(int(p)), "jy", false)
          << ");\n";
        for (int c = 0; c < 2; ++c)
            if (c == 0 || leaves[1] != leaves[0])
                o << "    vec3 " << slot(leaves[c]) << " = vec3(p" << p << ".mean." << "xy"[c] << ", max(p" << p
                  << ".var." << "xy"[c] << ", 0.0), 0.0);\n";
    }
    writeOperations(o, graph, true, moments);
    return o.str();
}

void checkGraphTextureUnits(const GraphPattern& graph, bool filtered) {
    // The point set (examples, T⁻¹ LUTs, tables) always, the filtered set (pyramids, prefiltered tables) when filtering.
    int units = (int(graph.tables().size()) + graph.leafCount()) * (filtered ? 2 : 1);
    for (int k = 0; k < graph.leafCount(); ++k) units += graph.leaf(k).example().gaussianized();
    for (size_t p = 0; p < graph.leafPairs().size(); ++p) units += filtered && graph.pairCovariance(int(p));
    if (units > kMaxUnits)
        throw InputError("the graph's GPU program reads " + std::to_string(units) + " textures " +
                         (filtered ? "filtered" : "unfiltered") + ", more than the " + std::to_string(kMaxUnits) +
                         " units a fragment shader has; use fewer leaves or tables");
}

namespace {

// The graph's programs, once the options are ones its GPU program has.
GpuView::Recipes graphRecipes(const GraphPattern& graph, const FilterOptions& options, GraphMoments moments) {
    if (options.source != StatisticsSource::Point && options.source != StatisticsSource::Estimators)
        throw InputError::parameter("source", "must be point or estimators on the GPU, got " +
                                                  enumName(kStatisticsSourceNames, options.source));
    const bool filtered = options.source == StatisticsSource::Estimators;
    if (filtered && options.estimator != VarianceEstimator::Paper)
        throw InputError::parameter("estimator", "must be paper for a texture graph on the GPU");
    checkGraphTextureUnits(graph, filtered);
    return {filtered ? "graph-filtered" : "graph", filtered ? "graph-filtered-compute" : "graph-compute", "graph-scene",
            ResponseKind::PrefilteredColormap, {{kGraphProgramStem, graphProgramSource(graph, moments)}}};
}

}  // namespace

struct GpuGraph::Impl {
    bool filtered = false;
    std::vector<std::pair<std::string, gl::Texture>> planes, arrays;  // sampler name → texture
    gl::Buffer parameters;
    Rgb sky{};
};

GpuGraph::GpuGraph(const GraphPattern& graph, GlContext& context, const FilterOptions& options, GraphMoments moments)
    : GpuView(context, graphRecipes(graph, options, moments)), impl_(std::make_unique<Impl>()) {
    const bool filtered = options.source == StatisticsSource::Estimators;
    const FilteredGraph f(graph, options, moments);  // the prefiltered tables, the pyramids, the sky
    Impl& m = *impl_;
    m.filtered = filtered;
    m.sky = f.skyColour();
    kernel::PatternParams p{};
    p.gridDensity = float(graph.gridDensity());
    p.invExampleSize = float(1.0 / graph.exampleSize());
    p.aniso = options.aniso;
    p.smoothTable = options.response.prefilter == PrefilterMode::Smooth;
    p.tableLevels = int(PrefilteredColormap::sigmaLevels(options.response.prefilter).size());
    for (int k = 0; k < graph.leafCount(); ++k) {
        const std::string leaf = std::to_string(k);
        const NoiseExample& e = graph.leaf(k).example();
        const Image& v = e.grid().values();
        m.planes.emplace_back("uGraphExample" + leaf, floatTexture(v.width(), v.height(), 1, v.data().data()));
        if (e.gaussianized()) {
            const std::vector<float>& lut = e.transform()->inverseLut();
            m.planes.emplace_back("uGraphInverse" + leaf, floatTexture(int(lut.size()), 1, 1, lut.data()));
        }
        if (!filtered) continue;
        const auto [pair, channel] = graph.leafLocation(k);
        m.planes.emplace_back("uGraphStats" + leaf, pyramidTexture(f.estimator(pair).pyramid(channel)));
    }
    for (size_t p = 0; p < graph.leafPairs().size(); ++p)
        if (filtered && graph.pairCovariance(int(p)))
            m.planes.emplace_back("uGraphCov" + std::to_string(p), pyramidTexture(*f.estimator(int(p)).covariancePyramid()));
    for (size_t t = 0; t < graph.tables().size(); ++t) {
        const std::string table = std::to_string(t);
        const Image point = graph.tables()[t].point.table();
        m.arrays.emplace_back("uGraphTable" + table, tableTexture(point.width(), point.height(), 1, point.data().data()));
        if (!filtered) continue;
        const ColormapTable& h = graph.tables()[t].blended;
        const int levels = int(f.table(int(t)).sigmas().size());
        m.arrays.emplace_back("uGraphPrefiltered" + table,
                              tableTexture(h.resolutionX(), h.resolutionY(), levels * levels,
                                           f.table(int(t)).atlas(h.resolutionX(), h.resolutionY()).data().data()));
    }
    if (filtered) p.maxLod = f.estimator(0).maxLod();
    m.parameters = gl::newBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, m.parameters.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof p, &p, GL_STATIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

GpuGraph::~GpuGraph() = default;

bool GpuGraph::filtered() const { return impl_->filtered; }

std::unique_ptr<GpuView> makeGpuView(const PatternSpec& spec, GlContext& context, const FilterOptions& options) {
    if (needsGraphEvaluator(spec))
        return std::make_unique<GpuGraph>(GraphPattern::build(spec), context, options);
    return std::make_unique<GpuPattern>(Pattern::build(spec), context, options);
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
    for (const auto& [name, texture] : m.planes) bind(GL_TEXTURE_2D, name, texture.id());
    for (const auto& [name, texture] : m.arrays) bind(GL_TEXTURE_2D_ARRAY, name, texture.id());
    // Samplers declared but not bound (the filtered set when unfiltered, the
    // response chunk's): on a unit of their own type, since GL refuses to
    // draw when samplers of two types share one.
    for (int k = 0; k < kMaxUnits; ++k) {
        const std::string leaf = std::to_string(k);
        for (const std::string& name : {"uGraphStats" + leaf, "uGraphInverse" + leaf, "uGraphCov" + leaf})
            if (std::none_of(m.planes.begin(), m.planes.end(), [&](const auto& p) { return p.first == name; }))
                glUniform1i(glGetUniformLocation(program, name.c_str()), 0);
        const std::string name = "uGraphPrefiltered" + leaf;
        if (std::none_of(m.arrays.begin(), m.arrays.end(), [&](const auto& a) { return a.first == name; }))
            glUniform1i(glGetUniformLocation(program, name.c_str()), int(m.planes.size()));
    }
    for (const char* name : {"uTable", "uColormap"})
        glUniform1i(glGetUniformLocation(program, name), int(m.planes.size()));
    const GLuint block = glGetUniformBlockIndex(program, kPatternBlockName);
    if (block != GL_INVALID_INDEX) glUniformBlockBinding(program, block, kPatternBlockBinding);
    glBindBufferBase(GL_UNIFORM_BUFFER, kPatternBlockBinding, m.parameters.id());
    glUniform3f(glGetUniformLocation(program, "uSky"), m.sky[0], m.sky[1], m.sky[2]);
}

}  // namespace stochtex
