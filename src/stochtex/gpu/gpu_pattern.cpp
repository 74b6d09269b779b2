#include "stochtex/gpu/gpu_pattern.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include "stochtex/core/error.h"
#include "stochtex/gpu/shader.h"

namespace stochtex {

namespace {

// A float texture read with texelFetch only (no filtering, no mipmaps).
GLuint floatTexture(int width, int height, int channels, const float* data) {
    static const GLenum internal[] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
    static const GLenum format[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal[channels - 1]), width, height, 0, format[channels - 1], GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

// A pyramid's levels as the mip chain of one RG32F texture (mean, moment).
GLuint pyramidTexture(const StatsPyramid& p) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int l = 0; l < p.levels(); ++l) {
        const Image& mean = p.meanImage(l);
        const Image& moment = p.momentImage(l);
        std::vector<float> rg(mean.pixelCount() * 2);
        for (size_t i = 0; i < mean.pixelCount(); ++i) {
            rg[2 * i] = mean.data()[i];
            rg[2 * i + 1] = moment.data()[i];
        }
        glTexImage2D(GL_TEXTURE_2D, l, GL_RG32F, mean.width(), mean.height(), 0, GL_RG, GL_FLOAT, rg.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, p.levels() - 1);
    return t;
}

// Every (σ_x, σ_y) layer of the prefiltered table resampled to the
// colormap's resolution (layers stored coarser are smooth: their bilinear
// resampling differs from the CPU lookup by far less than a colour step).
GLuint tableTexture(const PrefilteredColormap& table, int rx, int ry) {
    const int n = int(table.sigmas().size());
    std::vector<float> rgba(size_t(rx) * size_t(ry) * 4 * size_t(n) * size_t(n));
    for (int kx = 0; kx < n; ++kx)
        for (int ky = 0; ky < n; ++ky) {
            const ColormapTable& layer = table.layer(kx, ky);
            float* dst = rgba.data() + size_t(kx * n + ky) * size_t(rx) * size_t(ry) * 4;
            const bool full = layer.resolutionX() == rx && layer.resolutionY() == ry;
            for (int j = 0; j < ry; ++j)
                for (int i = 0; i < rx; ++i) {
                    const Rgb c = full ? layer.entry(i, j) : layer.sample(float(i) / float(rx - 1), float(j) / float(ry - 1));
                    float* o = dst + (size_t(j) * size_t(rx) + size_t(i)) * 4;
                    o[0] = c[0];
                    o[1] = c[1];
                    o[2] = c[2];
                    o[3] = 1.0f;
                }
        }
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D_ARRAY, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, rx, ry, n * n, 0, GL_RGBA, GL_FLOAT, rgba.data());
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

}  // namespace

struct GpuPattern::Impl {
    GLuint program = 0, vao = 0;
    GLuint examples[2] = {0, 0}, inverses[2] = {0, 0}, colormap = 0;
    float means[2] = {0, 0};
    uint32_t seeds[2] = {0, 0};
    bool gaussianized[2] = {false, false};
    int exampleSize = 0;
    double density = 0;
    Rgb sky{};
    // Filtered rendering.
    FilterOptions options;
    GLuint stats[2] = {0, 0}, covariance = 0, table = 0;
    bool shared = false;
    int maxLod = 0, tableLevels = 0;
    std::vector<float> average[3];  // Deliot–Heitz per-level moments: x, y, covariance
};

GpuPattern::GpuPattern(const Pattern& pattern, GlContext& context, const FilterOptions& options)
    : impl_(std::make_unique<Impl>()) {
    if (options.mode != FilterMode::None && options.mode != FilterMode::Paper && options.mode != FilterMode::Smooth)
        throw InputError("--gpu: the GPU renders --filter none, paper or smooth");
    context.makeCurrent();
    Impl& m = *impl_;
    m.options = options;
    const bool filtered = options.mode != FilterMode::None;
    m.program = compileProgram({"fullscreen"}, filtered ? std::vector<std::string>{"common", "filtering", "filtered"}
                                                       : std::vector<std::string>{"common", "unfiltered", "pattern"});
    const FilteredPattern f(pattern, options);  // pyramids, T⁻¹ folded into H, the table, the sky
    m.sky = f.skyColour();
    if (filtered) {
        const FootprintEstimator& est = f.estimator();
        for (int a = 0; a < 2; ++a) m.stats[a] = pyramidTexture(est.pyramid(a));
        m.shared = est.covariancePyramid() != nullptr;
        if (m.shared) m.covariance = pyramidTexture(*est.covariancePyramid());
        m.maxLod = est.maxLod();
        for (int l = 0; l <= m.maxLod; ++l) {
            m.average[0].push_back(est.pyramid(0).averageMoment(l));
            m.average[1].push_back(est.pyramid(1).averageMoment(l));
            m.average[2].push_back(m.shared ? est.covariancePyramid()->averageMoment(l) : 0.0f);
        }
        if (m.maxLod >= 16) throw InputError("--gpu: examples larger than 32768² are not supported");
        const ColormapTable& h = f.blendingSpaceColormap();
        m.table = tableTexture(f.table(), h.resolutionX(), h.resolutionY());
        m.tableLevels = int(f.table().sigmas().size());
    }
    glGenVertexArrays(1, &m.vao);
    m.exampleSize = pattern.exampleSize();
    m.density = pattern.gridDensity();
    for (int a = 0; a < 2; ++a) {
        const NoiseExample& ex = pattern.example(a);
        const Image& v = ex.grid().values();
        m.examples[a] = floatTexture(v.width(), v.height(), 1, v.data().data());
        m.means[a] = ex.mean();
        m.seeds[a] = pattern.noises()[size_t(a)].offsetSeed();
        m.gaussianized[a] = ex.gaussianized();
        const std::vector<float> identity = {0.0f, 1.0f};
        const std::vector<float>& lut = ex.gaussianized() ? ex.transform()->inverseLut() : identity;
        m.inverses[a] = floatTexture(int(lut.size()), 1, 1, lut.data());
    }
    const Image table = pattern.colormap().table();
    m.colormap = floatTexture(table.width(), table.height(), 3, table.data().data());
}

GpuPattern::~GpuPattern() {
    Impl& m = *impl_;
    GLuint textures[] = {m.examples[0], m.examples[1], m.inverses[0], m.inverses[1], m.colormap,
                         m.stats[0],    m.stats[1],    m.covariance,  m.table};
    glDeleteTextures(9, textures);  // zeros are ignored
    glDeleteVertexArrays(1, &m.vao);
    glDeleteProgram(m.program);
}

Image GpuPattern::render(const View& view) {
    Camera camera;
    camera.view = view;
    return render(camera);
}

Image GpuPattern::render(const Camera& camera) {
    validateCamera(camera);
    const View& view = camera.view;
    Impl& m = *impl_;
    GLuint target = 0, fbo = 0;
    glGenTextures(1, &target);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, view.width, view.height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    glViewport(0, 0, view.width, view.height);
    glUseProgram(m.program);
    auto bind = [&](int unit, GLenum target, GLuint texture, const char* name) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(target, texture);
        glUniform1i(glGetUniformLocation(m.program, name), unit);
    };
    if (m.options.mode == FilterMode::None) {
        const char* samplers[] = {"uExampleX", "uExampleY", "uInverseX", "uInverseY", "uColormap"};
        const GLuint textures[] = {m.examples[0], m.examples[1], m.inverses[0], m.inverses[1], m.colormap};
        for (int k = 0; k < 5; ++k) bind(k, GL_TEXTURE_2D, textures[k], samplers[k]);
        glUniform1i(glGetUniformLocation(m.program, "uGaussianizedX"), m.gaussianized[0]);
        glUniform1i(glGetUniformLocation(m.program, "uGaussianizedY"), m.gaussianized[1]);
    } else {
        bind(0, GL_TEXTURE_2D, m.stats[0], "uStatsX");
        bind(1, GL_TEXTURE_2D, m.stats[1], "uStatsY");
        bind(2, GL_TEXTURE_2D, m.shared ? m.covariance : m.stats[0], "uCovariance");
        bind(3, GL_TEXTURE_2D_ARRAY, m.table, "uTable");
        glUniform1i(glGetUniformLocation(m.program, "uShared"), m.shared);
        glUniform1i(glGetUniformLocation(m.program, "uDeliotHeitz"), m.options.estimator == VarianceEstimator::DeliotHeitz);
        glUniform1fv(glGetUniformLocation(m.program, "uAverageX"), GLsizei(m.average[0].size()), m.average[0].data());
        glUniform1fv(glGetUniformLocation(m.program, "uAverageY"), GLsizei(m.average[1].size()), m.average[1].data());
        glUniform1fv(glGetUniformLocation(m.program, "uAverageCov"), GLsizei(m.average[2].size()), m.average[2].data());
        glUniform1i(glGetUniformLocation(m.program, "uMaxLod"), m.maxLod);
        glUniform1i(glGetUniformLocation(m.program, "uAniso"), m.options.aniso);
        glUniform1i(glGetUniformLocation(m.program, "uSmooth"), m.options.mode == FilterMode::Smooth);
        glUniform1i(glGetUniformLocation(m.program, "uTableLevels"), m.tableLevels);
    }
    glUniform1f(glGetUniformLocation(m.program, "uMeanX"), m.means[0]);
    glUniform1f(glGetUniformLocation(m.program, "uMeanY"), m.means[1]);
    glUniform1ui(glGetUniformLocation(m.program, "uSeedX"), m.seeds[0]);
    glUniform1ui(glGetUniformLocation(m.program, "uSeedY"), m.seeds[1]);
    const double pi = 3.14159265358979323846;
    glUniform1i(glGetUniformLocation(m.program, "uPlane"), camera.kind == Camera::Kind::Plane);
    glUniform1f(glGetUniformLocation(m.program, "uTanHalfFov"), float(std::tan(0.5 * camera.fovDeg * pi / 180.0)));
    glUniform1f(glGetUniformLocation(m.program, "uSinTilt"), float(std::sin(camera.tiltDeg * pi / 180.0)));
    glUniform1f(glGetUniformLocation(m.program, "uCosTilt"), float(std::cos(camera.tiltDeg * pi / 180.0)));
    glUniform2f(glGetUniformLocation(m.program, "uViewSize"), float(view.width), float(view.height));
    glUniform3f(glGetUniformLocation(m.program, "uSky"), m.sky[0], m.sky[1], m.sky[2]);
    glUniform2f(glGetUniformLocation(m.program, "uOffset"), float(view.offsetU), float(view.offsetV));
    glUniform1f(glGetUniformLocation(m.program, "uScale"), float(view.scale));
    glUniform1f(glGetUniformLocation(m.program, "uInvW"), float(1.0 / m.exampleSize));
    glUniform1f(glGetUniformLocation(m.program, "uDensity"), float(m.density));
    glBindVertexArray(m.vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> rgba(size_t(view.width) * size_t(view.height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, view.width, view.height, GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &target);
    // Framebuffer row y is image row y: the shader maps fragment y to v the
    // way the CPU maps image rows.
    Image out(view.width, view.height, 3, Image::Uninitialized{});
    for (size_t i = 0; i < out.pixelCount(); ++i)
        for (size_t c = 0; c < 3; ++c) out.data()[3 * i + c] = rgba[4 * i + c];
    return out;
}

}  // namespace stochtex
