#include "stochtex/gpu/gpu_graph.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <sstream>

#include "stochtex/core/error.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/render_target.h"
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

// Texture units: a fragment shader has at least 16.
constexpr int kMaxUnits = 16;

}  // namespace

std::string graphProgramSource(const GraphPattern& graph, bool filtered, GraphMoments moments) {
    std::ostringstream o;
    o << "// Generated for one texture graph (gpu/gpu_graph.cpp): its leaves, then its operations.\n";
    for (int k = 0; k < graph.leafCount(); ++k) {
        o << "uniform sampler2D uGraphLeaf" << k << ";  // leaf \"" << graph.leafIds()[size_t(k)] << "\": "
          << (filtered ? "(E, V) pyramid" : "example") << "\n";
        if (!filtered && graph.leaf(k).example().gaussianized()) o << "uniform sampler2D uGraphInverse" << k << ";\n";
    }
    for (size_t t = 0; t < graph.tables().size(); ++t)
        o << "uniform sampler2DArray uGraphTable" << t << ";  // " << (filtered ? "prefiltered layers" : "one layer")
          << "\n";
    o << "\nvec3 graphColour(vec2 uv, vec2 jx, vec2 jy) {\n";
    if (filtered) {
        for (size_t p = 0; p < graph.leafPairs().size(); ++p) {
            const TiledField& pair = graph.leafPairs()[p];
            // The leaves this pair holds (a leaf without a partner fills both channels).
            int leaves[2] = {-1, -1};
            for (int k = 0; k < graph.leafCount(); ++k)
                if (graph.leafLocation(k)[0] == int(p)) leaves[graph.leafLocation(k)[1]] = k;
            if (leaves[1] < 0) leaves[1] = leaves[0];
            int maxLod = 0;
            while ((1 << maxLod) < pair.exampleSize()) ++maxLod;
            o << "    FootprintMoments p" << p << " = pairStatistics(uGraphLeaf" << leaves[0] << ", uGraphLeaf" << leaves[1]
              << ", uGraphLeaf" << leaves[0] << ", NoisePair(vec2(" << glslFloat(pair.channel(0).example().mean())
              << ", " << glslFloat(pair.channel(1).example().mean()) << "), uvec2(" << pair.channel(0).offsetSeed()
              << "u, " << pair.channel(1).offsetSeed() << "u), 0, 0, " << maxLod << ", "
              << glslFloat(float(pair.exampleSize())) << "), uv, jx, jy);\n";
            for (int c = 0; c < 2; ++c)
                if (c == 0 || leaves[1] != leaves[0])
                    o << "    vec3 " << slot(leaves[c]) << " = vec3(p" << p << ".mean." << "xy"[c] << ", max(p" << p
                      << ".var." << "xy"[c] << ", 0.0), 0.0);\n";
        }
    } else {
        o << "    Stencil s = triangleGrid(uv, uPattern.gridDensity);\n    vec2 fu = fract(uv);\n";
        for (int k = 0; k < graph.leafCount(); ++k) {
            const TilingBlendingNoise& n = graph.leaf(k);
            o << "    vec3 " << slot(k) << " = vec3(tilingBlending(uGraphLeaf" << k << ", "
              << glslFloat(n.example().mean()) << ", " << n.offsetSeed() << "u, s, fu), 0.0, 0.0);\n";
            if (n.example().gaussianized())
                o << "    " << slot(k) << ".x = inverseTransform(uGraphInverse" << k << ", " << slot(k) << ".x);\n";
        }
    }
    int out = graph.leafCount();
    for (const GraphPattern::Operation& op : graph.operations()) {
        const std::string a = slot(op.inputs[0]), b = op.inputs[1] >= 0 ? slot(op.inputs[1]) : "",
                          t = op.inputs[2] >= 0 ? slot(op.inputs[2]) : "";
        const std::string table = "uGraphTable" + std::to_string(op.table);
        const std::string p0 = glslFloat(op.parameters[0]), p1 = glslFloat(op.parameters[1]);
        o << "    vec3 " << slot(out) << " = ";  // operation " << op.id
        switch (op.kind) {
            case NodeKind::Colormap:
                if (filtered)
                    o << "prefilteredLookup(" << table << ", vec2(" << a << ".x, " << b << ".x), sqrt(max(vec2(" << a
                      << ".y, " << b << ".y), 0.0)))";
                else
                    o << "tableLookup(" << table << ", 0, vec2(" << a << ".x, " << b << ".x))";
                break;
            case NodeKind::ColormapField:
                if (filtered)
                    o << "vec3(matchedMoments(prefilteredLookup(" << table << ", vec2(" << a << ".x, " << b
                      << ".x), sqrt(max(vec2(" << a << ".y, " << b << ".y), 0.0)))), 0.0)";
                else
                    o << "tableLookup(" << table << ", 0, vec2(" << a << ".x, " << b << ".x))";
                break;
            case NodeKind::Curve:
                if (filtered)
                    o << "vec3(matchedMoments(prefilteredLookup(" << table << ", vec2(" << a << ".x, 0.5), vec2(sqrt(max("
                      << a << ".y, 0.0)), 0.0))), 0.0)";
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
            default: throw std::logic_error("graphProgramSource: a source as an operation");
        }
        o << ";  // " << op.id << "\n";
        // MeanOnly: a table's output field passes on its mean alone (FilteredGraph::fromMoments).
        const bool fieldTable = op.kind == NodeKind::ColormapField || op.kind == NodeKind::Curve;
        if (filtered && fieldTable && moments == GraphMoments::MeanOnly) o << "    " << slot(out) << ".y = 0.0;\n";
        ++out;
    }
    o << "    return " << slot(out - 1) << ";\n}\n";
    return o.str();
}

struct GpuGraph::Impl {
    gl::Program program;
    gl::VertexArray vao;
    std::vector<std::pair<std::string, gl::Texture>> planes, arrays;  // sampler name → texture
    gl::Buffer parameters;
    Rgb sky{};
};

GpuGraph::GpuGraph(const GraphPattern& graph, GlContext& context, const FilterOptions& options, GraphMoments moments)
    : impl_(std::make_unique<Impl>()) {
    if (options.source != StatisticsSource::Point && options.source != StatisticsSource::Estimators)
        throw InputError::parameter("source", "must be point or estimators on the GPU, got " +
                                                  enumName(kStatisticsSourceNames, options.source));
    const bool filtered = options.source == StatisticsSource::Estimators;
    if (filtered && options.estimator != VarianceEstimator::Paper)
        throw InputError::parameter("estimator", "must be paper for a texture graph on the GPU");
    int units = int(graph.tables().size()) + graph.leafCount();
    for (int k = 0; k < graph.leafCount() && !filtered; ++k) units += graph.leaf(k).example().gaussianized();
    if (units > kMaxUnits)
        throw InputError("the graph's GPU program reads " + std::to_string(units) + " textures, more than the " +
                         std::to_string(kMaxUnits) + " units a fragment shader has; use fewer leaves or tables");
    const FilteredGraph f(graph, options, moments);  // the prefiltered tables, the pyramids, the sky
    context.makeCurrent();
    Impl& m = *impl_;
    m.sky = f.skyColour();
    m.program = buildProgram(filtered ? "graph-filtered" : "graph", ResponseKind::PrefilteredColormap,
                             {{kGraphProgramStem, graphProgramSource(graph, filtered, moments)}});
    kernel::PatternParams p{};
    p.gridDensity = float(graph.gridDensity());
    p.invExampleSize = float(1.0 / graph.exampleSize());
    p.aniso = options.aniso;
    p.smoothTable = options.response.prefilter == PrefilterMode::Smooth;
    p.tableLevels = int(PrefilteredColormap::sigmaLevels(options.response.prefilter).size());
    for (int k = 0; k < graph.leafCount(); ++k) {
        const std::string name = "uGraphLeaf" + std::to_string(k);
        const auto [pair, channel] = graph.leafLocation(k);
        if (filtered) {
            m.planes.emplace_back(name, pyramidTexture(f.estimator(pair).pyramid(channel)));
            continue;
        }
        const NoiseExample& e = graph.leaf(k).example();
        const Image& v = e.grid().values();
        m.planes.emplace_back(name, floatTexture(v.width(), v.height(), 1, v.data().data()));
        if (e.gaussianized()) {
            const std::vector<float>& lut = e.transform()->inverseLut();
            m.planes.emplace_back("uGraphInverse" + std::to_string(k), floatTexture(int(lut.size()), 1, 1, lut.data()));
        }
    }
    for (size_t t = 0; t < graph.tables().size(); ++t) {
        const std::string name = "uGraphTable" + std::to_string(t);
        if (filtered) {
            const ColormapTable& h = graph.tables()[t].blended;
            const int levels = int(f.table(int(t)).sigmas().size());
            m.arrays.emplace_back(name, tableTexture(h.resolutionX(), h.resolutionY(), levels * levels,
                                                     f.table(int(t)).atlas(h.resolutionX(), h.resolutionY()).data().data()));
        } else {
            const Image table = graph.tables()[t].point.table();
            m.arrays.emplace_back(name, tableTexture(table.width(), table.height(), 1, table.data().data()));
        }
    }
    if (filtered) p.maxLod = f.estimator(0).maxLod();
    m.vao = gl::newVertexArray();
    m.parameters = gl::newBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, m.parameters.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof p, &p, GL_STATIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

GpuGraph::~GpuGraph() = default;

void GpuGraph::drawView(const Camera& camera) {
    const Impl& m = *impl_;
    const GLuint program = m.program.id();
    glUseProgram(program);
    int unit = 0;
    const auto bind = [&](GLenum target, const std::string& name, GLuint texture) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(target, texture);
        glUniform1i(glGetUniformLocation(program, name.c_str()), unit++);
    };
    for (const auto& [name, texture] : m.planes) bind(GL_TEXTURE_2D, name, texture.id());
    for (const auto& [name, texture] : m.arrays) bind(GL_TEXTURE_2D_ARRAY, name, texture.id());
    // The pattern's own samplers, declared by the shared chunks but not read
    // by the graph: on units of their own type, since GL refuses to draw
    // when samplers of two types share one.
    for (const char* name : {"uStatsX", "uStatsY", "uCovariance"})
        glUniform1i(glGetUniformLocation(program, name), 0);
    for (const char* name : {"uTable", "uColormap"})
        glUniform1i(glGetUniformLocation(program, name), int(m.planes.size()));
    const GLuint block = glGetUniformBlockIndex(program, kPatternBlockName);
    if (block != GL_INVALID_INDEX) glUniformBlockBinding(program, block, kPatternBlockBinding);
    glBindBufferBase(GL_UNIFORM_BUFFER, kPatternBlockBinding, m.parameters.id());
    glUniform3f(glGetUniformLocation(program, "uSky"), m.sky[0], m.sky[1], m.sky[2]);
    setCameraUniforms(program, camera, false);
    glBindVertexArray(m.vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

Image GpuGraph::render(const Camera& camera) {
    validateCamera(camera);
    // Framebuffer row y is image row y, as GpuPattern::render.
    const RenderTarget target(camera.view.width, camera.view.height, false);
    drawView(camera);
    Image out = target.readRgb(RenderTarget::Rows::AsDrawn);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

}  // namespace stochtex
