// `stochtex bake`'s export, loaded by a minimal GL program that uses only the
// exported files (manifest, EXR data, stochtex.glsl) and plain GL calls, must
// render what `render --gpu` renders.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdio>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "stochtex/gpu/export.h"
#include "stochtex/gpu/gl_context.h"
#include "test_util.h"
#include "stochtex/gpu/gpu_pattern.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/presets.h"

namespace stochtex {
namespace {

namespace fs = std::filesystem;

GLuint compile(GLenum stage, const std::string& src) {
    const GLuint s = glCreateShader(stage);
    const char* p = src.c_str();
    glShaderSource(s, 1, &p, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        ADD_FAILURE() << log;
    }
    return s;
}

// An engine's view of the export: it knows GL and the README, nothing else.
Image renderFromExport(const fs::path& dir, int width, int height, double scale) {
    std::ifstream mf(dir / "manifest.json");
    const nlohmann::json m = nlohmann::json::parse(mf);
    std::ifstream inc(dir / "stochtex.glsl");
    const std::string include((std::istreambuf_iterator<char>(inc)), std::istreambuf_iterator<char>());
    const GLuint vs = compile(GL_VERTEX_SHADER, "#version 330 core\nvoid main() { vec2 p = vec2(float((gl_VertexID << 1) & 2), "
                                                "float(gl_VertexID & 2)); gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n");
    const GLuint fs_ = compile(GL_FRAGMENT_SHADER, "#version 330 core\n" + include +
                                                      "uniform float uPixelScale;\nout vec4 colour;\n"
                                                      "void main() { colour = stochtex_sample(gl_FragCoord.xy * uPixelScale * uInvW); }\n");
    const GLuint prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs_);
    glLinkProgram(prog);
    glUseProgram(prog);
    auto pyramid = [&](const nlohmann::json& files) {
        GLuint t = 0;
        glGenTextures(1, &t);
        glBindTexture(GL_TEXTURE_2D, t);
        for (size_t l = 0; l < files.size(); ++l) {
            const Image img = readImage((dir / files[l].get<std::string>()).string());
            std::vector<float> rg(img.pixelCount() * 2);
            for (size_t i = 0; i < img.pixelCount(); ++i) {
                rg[2 * i] = img.data()[3 * i];
                rg[2 * i + 1] = img.data()[3 * i + 1];
            }
            glTexImage2D(GL_TEXTURE_2D, GLint(l), GL_RG32F, img.width(), img.height(), 0, GL_RG, GL_FLOAT, rg.data());
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(files.size()) - 1);
        return t;
    };
    const GLuint sx = pyramid(m["stats"]["x"]), sy = pyramid(m["stats"]["y"]);
    const bool shared = m["covariance"];
    const GLuint cov = shared ? pyramid(m["stats"]["covariance"]) : sx;
    const Image atlas = readImage((dir / m["table"]["file"].get<std::string>()).string());
    const int tw = m["table"]["width"], th = m["table"]["height"], tl = m["table"]["levels"];
    GLuint table = 0;
    glGenTextures(1, &table);
    glBindTexture(GL_TEXTURE_2D_ARRAY, table);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGB32F, tw, th, tl * tl, 0, GL_RGB, GL_FLOAT, atlas.data().data());
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    auto unit = [&](int u, GLenum target, GLuint t, const char* name) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(target, t);
        glUniform1i(glGetUniformLocation(prog, name), u);
    };
    unit(0, GL_TEXTURE_2D, sx, "uStatsX");
    unit(1, GL_TEXTURE_2D, sy, "uStatsY");
    unit(2, GL_TEXTURE_2D, cov, "uCovariance");
    unit(3, GL_TEXTURE_2D_ARRAY, table, "uTable");
    auto loc = [&](const char* n) { return glGetUniformLocation(prog, n); };
    glUniform1f(loc("uMeanX"), m["means"][0].get<float>());
    glUniform1f(loc("uMeanY"), m["means"][1].get<float>());
    glUniform1ui(loc("uSeedX"), m["seeds"][0].get<unsigned>());
    glUniform1ui(loc("uSeedY"), m["seeds"][1].get<unsigned>());
    glUniform1f(loc("uDensity"), m["grid_density"].get<float>());
    glUniform1f(loc("uInvW"), 1.0f / m["example_size"].get<float>());
    glUniform1i(loc("uHasCovariance"), shared);
    glUniform1i(loc("uDeliotHeitz"), 0);
    for (const char* k : {"x", "y", "cov"}) {
        const std::vector<float> v = m["average_moments"][k].get<std::vector<float>>();
        const std::string name = std::string("uAverage") + (k[0] == 'x' ? "X" : k[0] == 'y' ? "Y" : "Cov");
        glUniform1fv(loc(name.c_str()), GLsizei(v.size()), v.data());
    }
    glUniform1i(loc("uMaxLod"), m["levels"].get<int>() - 1);
    glUniform1i(loc("uAniso"), m["aniso"].get<int>());
    glUniform1i(loc("uSmooth"), m["filter"] == "smooth");
    glUniform1i(loc("uTableLevels"), tl);
    glUniform1f(loc("uPixelScale"), float(scale));
    GLuint target = 0, fbo = 0, vao = 0;
    glGenTextures(1, &target);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    glViewport(0, 0, width, height);
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> rgba(size_t(width) * size_t(height) * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    Image out(width, height, 3, Image::Uninitialized{});
    for (size_t i = 0; i < out.pixelCount(); ++i)
        for (size_t c = 0; c < 3; ++c) out.data()[3 * i + c] = rgba[4 * i + c];
    GLuint textures[] = {sx, sy, table, target};
    glDeleteTextures(4, textures);
    if (shared) glDeleteTextures(1, &cov);
    glDeleteFramebuffers(1, &fbo);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(prog);
    glDeleteShader(vs);
    glDeleteShader(fs_);
    return out;
}

TEST(Export, SeparateProgramRendersWhatRenderGpuRenders) {
    auto ctx = GlContext::headless();
    // Independent offsets with the smooth table in half floats (the default;
    // table entries round by ≤ 2⁻¹², bilinear weights keep that bound),
    // shared offsets (covariance pyramid) with the paper table in float
    // (the same numbers as render --gpu).
    for (const char* name : {"camouflage", "phasor-stripes"}) {
        const Pattern p = Pattern::build(loadPreset(name));
        FilterOptions o;
        const bool half = std::string(name) == "camouflage";
        o.mode = half ? FilterMode::Smooth : FilterMode::Paper;
        ExportOptions e;
        e.halfTable = half;
        const fs::path dir = test::scratchPath(std::string("stochtex_export_") + name);
        fs::remove_all(dir);
        exportPattern(p, o, dir.string(), e);
        for (const char* f : {"manifest.json", "stochtex.glsl", "README.md", "table.exr", "stats_x_0.exr"})
            EXPECT_TRUE(fs::exists(dir / f)) << f;
        GpuPattern gpu(p, *ctx, o);
        for (double scale : {1.0, 6.0}) {
            View v;
            v.width = 96;
            v.height = 80;
            v.scale = scale;
            const Image reference = gpu.render(v);
            ctx->makeCurrent();
            const Image exported = renderFromExport(dir, v.width, v.height, scale);
            double maxDiff = 0;
            for (size_t i = 0; i < reference.data().size(); ++i)
                maxDiff = std::max(maxDiff, double(std::abs(reference.data()[i] - exported.data()[i])));
            std::printf("[ info ] %s (%s table) at scale %g: max |export - render --gpu| %.2e\n", name,
                        half ? "half" : "float", scale, maxDiff);
            EXPECT_LT(maxDiff, half ? 2.5e-4 : 1e-5) << name << " at scale " << scale;
            if (half) {
                EXPECT_GT(maxDiff, 1e-6) << "the half table should differ from the float one";
            }
        }
        fs::remove_all(dir);
    }
}

}  // namespace
}  // namespace stochtex
