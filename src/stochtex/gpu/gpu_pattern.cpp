#include "stochtex/gpu/gpu_pattern.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "stochtex/core/error.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/uploads.h"
#include "stochtex/kernel/pattern_params.h"

namespace stochtex {

namespace {

// The pattern's programs, once the statistics source is one the GPU has.
GpuView::Recipes patternRecipes(const FilterOptions& options) {
    if (options.source != StatisticsSource::Point && options.source != StatisticsSource::Estimators)
        throw InputError::parameter("source", "must be point or estimators on the GPU, got " +
                                                  enumName(kStatisticsSourceNames, options.source));
    const bool filtered = options.source == StatisticsSource::Estimators;
    return {filtered ? "filtered" : "unfiltered", filtered ? "filtered-compute" : "unfiltered-compute", "scene",
            {}};
}

}  // namespace

struct GpuPattern::Impl {
    gl::Texture examples[2], inverses[2], colormap;
    gl::Buffer parameters;  // kernel::PatternParams, the shaders' PatternParameters block
    Rgb sky{};
    // Filtered rendering.
    FilterOptions options;
    gl::Texture stats[2], covariance, table;
    bool shared = false;
};

GpuPattern::GpuPattern(const Pattern& pattern, GlContext& context, const FilterOptions& options)
    : GpuView(context, patternRecipes(options), pattern.exampleSize()), impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.options = options;
    const bool filtered = options.source == StatisticsSource::Estimators;
    // Pyramids, T⁻¹ folded into H, the table, the sky; refuses the lean
    // response (a file's normal map is its program's: makeGpuView).
    const FilteredPattern f(pattern, options);
    m.sky = f.skyColour();
    const TiledField& field = f.field();
    kernel::PatternParams p{};
    if (filtered) {
        const FootprintEstimator& est = f.estimator();
        if (est.maxLod() >= kernel::kMaxPyramidLevels)
            throw InputError("the GPU filters examples of at most 32768² texels, got " +
                             std::to_string(field.exampleSize()) + "²");
        for (int a = 0; a < 2; ++a) m.stats[a] = pyramidTexture(est.pyramid(a));
        // uHasCovariance: the pyramid exists only for a shared-offset pair
        // whose response reads the covariance (FilteredPattern).
        m.shared = f.response().needsCovariance() && est.covariancePyramid() != nullptr;
        if (m.shared) m.covariance = pyramidTexture(*est.covariancePyramid());
        const ColormapTable& h = f.blendingSpaceColormap();
        const int levels = int(f.table().sigmas().size());
        m.table = tableTexture(h.resolutionX(), h.resolutionY(), levels * levels,
                               f.table().atlas(h.resolutionX(), h.resolutionY()).data().data());
        p.hasCovariance = m.shared;
        p.deliotHeitz = options.estimator == VarianceEstimator::DeliotHeitz;
        p.maxLod = est.maxLod();
        p.aniso = options.aniso;
        p.smoothTable = options.response.prefilter == PrefilterMode::Smooth;
        p.tableLevels = levels;
        for (int l = 0; l <= est.maxLod(); ++l)
            p.averageMoments[l] = {est.pyramid(0).averageMoment(l), est.pyramid(1).averageMoment(l),
                                   m.shared ? est.covariancePyramid()->averageMoment(l) : 0.0f, 0.0f};
    }
    p.meanX = field.channel(0).example().mean();
    p.meanY = field.channel(1).example().mean();
    p.gridDensity = float(field.gridDensity());
    p.invExampleSize = float(1.0 / field.exampleSize());
    p.seedX = field.channel(0).offsetSeed();
    p.seedY = field.channel(1).offsetSeed();
    p.gaussianizedX = field.channel(0).example().gaussianized();
    p.gaussianizedY = field.channel(1).example().gaussianized();
    for (int a = 0; a < 2; ++a) {
        const NoiseExample& ex = field.channel(a).example();
        const Image& v = ex.grid().values();
        m.examples[a] = floatTexture(v.width(), v.height(), 1, v.data().data());
        const std::vector<float> identity = {0.0f, 1.0f};
        const std::vector<float>& lut = ex.gaussianized() ? ex.transform()->inverseLut() : identity;
        m.inverses[a] = floatTexture(int(lut.size()), 1, 1, lut.data());
    }
    const Image table = pattern.colormap().table();
    m.colormap = tableTexture(table.width(), table.height(), 1, table.data().data());
    m.parameters = gl::newBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, m.parameters.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof p, &p, GL_STATIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

GpuPattern::~GpuPattern() = default;

bool GpuPattern::filtered() const { return impl_->options.source == StatisticsSource::Estimators; }

void GpuPattern::bind(unsigned program) const {
    const Impl& m = *impl_;
    glUseProgram(program);
    auto bindTexture = [&](int unit, GLenum target, GLuint texture, const char* name) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(target, texture);
        glUniform1i(glGetUniformLocation(program, name), unit);
    };
    const char* samplers[] = {"uExampleX", "uExampleY", "uInverseX", "uInverseY"};
    const gl::Texture* textures[] = {&m.examples[0], &m.examples[1], &m.inverses[0], &m.inverses[1]};
    for (int k = 0; k < 4; ++k) bindTexture(k, GL_TEXTURE_2D, textures[k]->id(), samplers[k]);
    bindTexture(4, GL_TEXTURE_2D_ARRAY, m.colormap.id(), "uColormap");
    // Every sampler gets its own unit even when unfiltered: a program that
    // declares both (the scene's) would otherwise leave uTable, an array
    // sampler, on unit 0 with the 2D uExampleX, and GL refuses to draw
    // (GL_INVALID_OPERATION) when samplers of two types share a unit.
    const bool estimated = filtered();
    bindTexture(5, GL_TEXTURE_2D, estimated ? m.stats[0].id() : 0, "uStatsX");
    bindTexture(6, GL_TEXTURE_2D, estimated ? m.stats[1].id() : 0, "uStatsY");
    bindTexture(7, GL_TEXTURE_2D, !estimated ? 0 : m.shared ? m.covariance.id() : m.stats[0].id(), "uCovariance");
    bindTexture(8, GL_TEXTURE_2D_ARRAY, estimated ? m.table.id() : 0, "uTable");
    // GLSL 3.30 / ES 3.00 cannot fix a block's binding point in the source.
    const GLuint block = glGetUniformBlockIndex(program, kPatternBlockName);
    if (block != GL_INVALID_INDEX) glUniformBlockBinding(program, block, kPatternBlockBinding);
    glBindBufferBase(GL_UNIFORM_BUFFER, kPatternBlockBinding, m.parameters.id());
    glUniform3f(glGetUniformLocation(program, "uSky"), m.sky[0], m.sky[1], m.sky[2]);
}

}  // namespace stochtex
