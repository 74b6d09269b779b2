#include "stochtex/gpu/gpu_pattern.h"

#include <epoxy/gl.h>

#include <algorithm>

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

}  // namespace

struct GpuPattern::Impl {
    GLuint program = 0, vao = 0;
    GLuint examples[2] = {0, 0}, inverses[2] = {0, 0}, colormap = 0;
    float means[2] = {0, 0};
    uint32_t seeds[2] = {0, 0};
    bool gaussianized[2] = {false, false};
    int exampleSize = 0;
    double density = 0;
};

GpuPattern::GpuPattern(const Pattern& pattern, GlContext& context) : impl_(std::make_unique<Impl>()) {
    context.makeCurrent();
    Impl& m = *impl_;
    m.program = compileProgram({"fullscreen"}, {"common", "pattern"});
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
    GLuint textures[] = {m.examples[0], m.examples[1], m.inverses[0], m.inverses[1], m.colormap};
    glDeleteTextures(5, textures);
    glDeleteVertexArrays(1, &m.vao);
    glDeleteProgram(m.program);
}

Image GpuPattern::render(const View& view) {
    validateView(view, "render --gpu");
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
    const char* samplers[] = {"uExampleX", "uExampleY", "uInverseX", "uInverseY", "uColormap"};
    const GLuint textures[] = {m.examples[0], m.examples[1], m.inverses[0], m.inverses[1], m.colormap};
    for (int k = 0; k < 5; ++k) {
        glActiveTexture(GLenum(GL_TEXTURE0 + k));
        glBindTexture(GL_TEXTURE_2D, textures[k]);
        glUniform1i(glGetUniformLocation(m.program, samplers[k]), k);
    }
    glUniform1f(glGetUniformLocation(m.program, "uMeanX"), m.means[0]);
    glUniform1f(glGetUniformLocation(m.program, "uMeanY"), m.means[1]);
    glUniform1ui(glGetUniformLocation(m.program, "uSeedX"), m.seeds[0]);
    glUniform1ui(glGetUniformLocation(m.program, "uSeedY"), m.seeds[1]);
    glUniform1i(glGetUniformLocation(m.program, "uGaussianizedX"), m.gaussianized[0]);
    glUniform1i(glGetUniformLocation(m.program, "uGaussianizedY"), m.gaussianized[1]);
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
