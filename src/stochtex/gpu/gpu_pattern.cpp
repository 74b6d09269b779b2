#include "stochtex/gpu/gpu_pattern.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <numbers>

#include "stochtex/core/error.h"
#include "stochtex/gpu/shader.h"

namespace stochtex {

namespace {

// Raised by setDerivatives and setPipeline, whichever of the pair comes second.
InputError rasterizerNeedsFragments() {
    return InputError::parameter("derivatives",
                                 "must be camera with the compute pipeline (compute shaders have no dFdx), got rasterizer");
}

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
        const Image rg = p.interleavedLevel(l, 2);
        glTexImage2D(GL_TEXTURE_2D, l, GL_RG32F, rg.width(), rg.height(), 0, GL_RG, GL_FLOAT, rg.data().data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, p.levels() - 1);
    return t;
}

// The prefiltered table's layers as one texture array (see atlas()).
GLuint tableTexture(const PrefilteredColormap& table, int rx, int ry) {
    const int n = int(table.sigmas().size());
    const Image atlas = table.atlas(rx, ry);
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D_ARRAY, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGB32F, rx, ry, n * n, 0, GL_RGB, GL_FLOAT, atlas.data().data());
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

}  // namespace

struct GpuPattern::Impl {
    GLuint program = 0, vao = 0, sceneProgram = 0, kernelProgram = 0;
    bool hasCompute = false;
    Pipeline pipeline = Pipeline::Fragment;
    GLuint examples[2] = {0, 0}, inverses[2] = {0, 0}, colormap = 0;
    float means[2] = {0, 0};
    uint32_t seeds[2] = {0, 0};
    bool gaussianized[2] = {false, false};
    int exampleSize = 0;
    double density = 0;
    Rgb sky{};
    // Filtered rendering.
    FilterOptions options;
    Derivatives derivatives = Derivatives::Camera;
    GLuint stats[2] = {0, 0}, covariance = 0, table = 0;
    bool shared = false;
    int maxLod = 0, tableLevels = 0;
    std::vector<float> average[3];  // Deliot–Heitz per-level moments: x, y, covariance
};

GpuPattern::GpuPattern(const Pattern& pattern, GlContext& context, const FilterOptions& options)
    : impl_(std::make_unique<Impl>()) {
    if (options.mode != FilterMode::None && options.mode != FilterMode::Paper && options.mode != FilterMode::Smooth)
        throw InputError::parameter("mode", "must be none, paper or smooth on the GPU");
    context.makeCurrent();
    Impl& m = *impl_;
    m.options = options;
    m.hasCompute = context.hasCompute();
    const bool filtered = options.mode != FilterMode::None;
    m.program = compileProgram({"fullscreen"}, filtered ? std::vector<std::string>{"common", "filtering", "view", "filtered"}
                                                       : std::vector<std::string>{"common", "unfiltered", "view", "pattern"});
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
        if (m.maxLod >= 16)
            throw InputError("the GPU filters examples of at most 32768² texels, got " + std::to_string(pattern.exampleSize()) +
                             "²");
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
    if (m.sceneProgram) glDeleteProgram(m.sceneProgram);
    if (m.kernelProgram) glDeleteProgram(m.kernelProgram);
}

Image GpuPattern::render(const View& view) {
    Camera camera;
    camera.view = view;
    return render(camera);
}

void GpuPattern::bind(unsigned program) const {
    const Impl& m = *impl_;
    glUseProgram(program);
    auto bindTexture = [&](int unit, GLenum target, GLuint texture, const char* name) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(target, texture);
        glUniform1i(glGetUniformLocation(program, name), unit);
    };
    auto uniform = [&](const char* name) { return glGetUniformLocation(program, name); };
    const char* samplers[] = {"uExampleX", "uExampleY", "uInverseX", "uInverseY", "uColormap"};
    const GLuint textures[] = {m.examples[0], m.examples[1], m.inverses[0], m.inverses[1], m.colormap};
    for (int k = 0; k < 5; ++k) bindTexture(k, GL_TEXTURE_2D, textures[k], samplers[k]);
    glUniform1i(uniform("uGaussianizedX"), m.gaussianized[0]);
    glUniform1i(uniform("uGaussianizedY"), m.gaussianized[1]);
    if (m.options.mode != FilterMode::None) {
        bindTexture(5, GL_TEXTURE_2D, m.stats[0], "uStatsX");
        bindTexture(6, GL_TEXTURE_2D, m.stats[1], "uStatsY");
        bindTexture(7, GL_TEXTURE_2D, m.shared ? m.covariance : m.stats[0], "uCovariance");
        bindTexture(8, GL_TEXTURE_2D_ARRAY, m.table, "uTable");
        glUniform1i(uniform("uShared"), m.shared);
        glUniform1i(uniform("uDeliotHeitz"), m.options.estimator == VarianceEstimator::DeliotHeitz);
        glUniform1fv(uniform("uAverageX"), GLsizei(m.average[0].size()), m.average[0].data());
        glUniform1fv(uniform("uAverageY"), GLsizei(m.average[1].size()), m.average[1].data());
        glUniform1fv(uniform("uAverageCov"), GLsizei(m.average[2].size()), m.average[2].data());
        glUniform1i(uniform("uMaxLod"), m.maxLod);
        glUniform1i(uniform("uAniso"), m.options.aniso);
        glUniform1i(uniform("uSmooth"), m.options.mode == FilterMode::Smooth);
        glUniform1i(uniform("uTableLevels"), m.tableLevels);
    }
    glUniform1f(uniform("uMeanX"), m.means[0]);
    glUniform1f(uniform("uMeanY"), m.means[1]);
    glUniform1ui(uniform("uSeedX"), m.seeds[0]);
    glUniform1ui(uniform("uSeedY"), m.seeds[1]);
    glUniform1f(uniform("uInvW"), float(1.0 / m.exampleSize));
    glUniform1f(uniform("uDensity"), float(m.density));
    glUniform3f(uniform("uSky"), m.sky[0], m.sky[1], m.sky[2]);
}

void GpuPattern::setDerivatives(Derivatives d) {
    if (d == Derivatives::Rasterizer && impl_->pipeline == Pipeline::Compute)
        throw rasterizerNeedsFragments();
    impl_->derivatives = d;
}

void GpuPattern::setPipeline(Pipeline p) {
    Impl& m = *impl_;
    if (p == Pipeline::Compute) {
        if (!m.hasCompute) throw GpuUnavailable("the compute pipeline needs OpenGL 4.3 (compute shaders)");
        if (m.derivatives == Derivatives::Rasterizer)
            throw rasterizerNeedsFragments();
        if (!m.kernelProgram) {
            const bool filtered = m.options.mode != FilterMode::None;
            m.kernelProgram = compileComputeProgram(
                filtered ? std::vector<std::string>{"common", "filtering", "view", "kernel_filtered", "view_kernel"}
                         : std::vector<std::string>{"common", "unfiltered", "view", "kernel_unfiltered", "view_kernel"});
        }
    }
    m.pipeline = p;
}

Image GpuPattern::draw(int width, int height, bool depth, const std::function<void()>& drawCalls) const {
    Image out(width, height, 3, Image::Uninitialized{});
    offscreen(width, height, depth, [&] {
        drawCalls();
        std::vector<float> rgba(size_t(width) * size_t(height) * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
        for (size_t i = 0; i < out.pixelCount(); ++i)
            for (size_t c = 0; c < 3; ++c) out.data()[3 * i + c] = rgba[4 * i + c];
    });
    return out;
}

void GpuPattern::offscreen(int width, int height, bool depth, const std::function<void()>& work) const {
    GLuint target = 0, fbo = 0, depthBuffer = 0;
    glGenTextures(1, &target);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    // Complete without mipmaps: an incomplete texture bound as a compute
    // image takes no stores (NVIDIA enforces this; llvmpipe does not).
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    if (depth) {
        glGenRenderbuffers(1, &depthBuffer);
        glBindRenderbuffer(GL_RENDERBUFFER, depthBuffer);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthBuffer);
    }
    glViewport(0, 0, width, height);
    work();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &target);
    if (depthBuffer) glDeleteRenderbuffers(1, &depthBuffer);
}

Image GpuPattern::render(const Camera& camera) {
    validateCamera(camera);
    const View& view = camera.view;
    // Framebuffer row y is image row y: the shader maps fragment y to v the
    // way the CPU maps image rows.
    return draw(view.width, view.height, false, [&] { drawOrDispatch(camera); });
}

void GpuPattern::setViewUniforms(unsigned program, const Camera& camera) const {
    const View& view = camera.view;
    const Impl& m = *impl_;
    bind(program);
    auto uniform = [&](const char* name) { return glGetUniformLocation(program, name); };
    const double pi = std::numbers::pi;
    glUniform1i(uniform("uPlane"), camera.kind == Camera::Kind::Plane);
    glUniform1f(uniform("uTanHalfFov"), float(std::tan(0.5 * camera.fovDeg * pi / 180.0)));
    glUniform1f(uniform("uSinTilt"), float(std::sin(camera.tiltDeg * pi / 180.0)));
    glUniform1f(uniform("uCosTilt"), float(std::cos(camera.tiltDeg * pi / 180.0)));
    glUniform2f(uniform("uViewSize"), float(view.width), float(view.height));
    glUniform2f(uniform("uOffset"), float(view.offsetU), float(view.offsetV));
    glUniform1f(uniform("uScale"), float(view.scale));
    glUniform1i(uniform("uRasterizerDerivatives"), m.derivatives == Derivatives::Rasterizer);
}

void GpuPattern::drawView(const Camera& camera) {
    const Impl& m = *impl_;
    setViewUniforms(m.program, camera);
    glBindVertexArray(m.vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GpuPattern::drawOrDispatch(const Camera& camera) {
    const Impl& m = *impl_;
    if (m.pipeline == Pipeline::Fragment) return drawView(camera);
    // The kernel writes the texture attached to the bound framebuffer.
    GLint target = 0;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                          &target);
    setViewUniforms(m.kernelProgram, camera);
    glBindImageTexture(0, GLuint(target), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint((camera.view.width + 7) / 8), GLuint((camera.view.height + 7) / 8), 1);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

double GpuPattern::secondsPerFrame(const Camera& camera, int frames) {
    validateCamera(camera);
    if (frames < 1) throw InputError::parameter("frames", "must be >= 1, got " + std::to_string(frames));
    double seconds = 0;
    offscreen(camera.view.width, camera.view.height, false, [&] {
        // Warm-up, at least 0.3 s: drivers finish compiling and uploading at
        // the first draw, and a GPU that idled (during a read-back, say)
        // needs a while at full load to raise its clocks again (an H100
        // measured right after idling ran at 345 of 1980 MHz).
        using clock = std::chrono::steady_clock;
        const auto warm = clock::now();
        do {
            drawOrDispatch(camera);
            glFinish();
        } while (std::chrono::duration<double>(clock::now() - warm).count() < 0.3);
        const auto start = clock::now();
        for (int f = 0; f < frames; ++f) drawOrDispatch(camera);
        glFinish();
        seconds = std::chrono::duration<double>(clock::now() - start).count();
    });
    return seconds / frames;
}

Image GpuPattern::renderScene(const Mesh& mesh, const SceneCamera& camera, int width, int height, float tiling) {
    if (width < 1 || height < 1 || width > 8192 || height > 8192)
        throw InputError::parameter("size", "must be in [1, 8192] per side, got " + std::to_string(width) + "x" +
                                                std::to_string(height));
    if (!(tiling > 0) || !std::isfinite(tiling) || tiling > 1e4)
        throw InputError::parameter("tiling", "must be a finite number in (0, 1e4], got " + formatValue(tiling));
    Impl& m = *impl_;
    if (!m.sceneProgram)
        m.sceneProgram = compileProgram({"mesh"}, {"common", "unfiltered", "filtering", "scene"});
    GLuint vao = 0, buffers[2] = {0, 0};
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(2, buffers);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(float)), mesh.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)), mesh.indices.data(),
                 GL_STATIC_DRAW);
    const GLsizei stride = Mesh::kStride * sizeof(float);
    const int sizes[3] = {3, 3, 2}, offsets[3] = {0, 3, 6};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(size_t(offsets[a]) * sizeof(float)));
    }
    Image img = draw(width, height, true, [&] {
        glClearColor(0.08f, 0.09f, 0.11f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        bind(m.sceneProgram);
        auto uniform = [&](const char* name) { return glGetUniformLocation(m.sceneProgram, name); };
        const Mat4 vp = camera.viewProjection(float(width) / float(height));
        glUniformMatrix4fv(uniform("uViewProjection"), 1, GL_FALSE, vp.data());
        glUniform1f(uniform("uTiling"), tiling);
        glUniform1i(uniform("uFiltered"), m.options.mode != FilterMode::None);
        const float l[3] = {0.45f, 0.8f, 0.4f};
        const float n = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
        glUniform3f(uniform("uLight"), l[0] / n, l[1] / n, l[2] / n);
        glUniform3f(uniform("uEye"), camera.eye[0], camera.eye[1], camera.eye[2]);
        glBindVertexArray(vao);
        glDrawElements(GL_TRIANGLES, GLsizei(mesh.indices.size()), GL_UNSIGNED_INT, nullptr);
        glDisable(GL_DEPTH_TEST);
    });
    glDeleteBuffers(2, buffers);
    glDeleteVertexArrays(1, &vao);
    // GL's row 0 is the bottom of the picture: flip for an image file.
    Image flipped(width, height, 3, Image::Uninitialized{});
    for (int y = 0; y < height; ++y) std::copy_n(img.row(height - 1 - y), size_t(width) * 3, flipped.row(y));
    return flipped;
}

}  // namespace stochtex
