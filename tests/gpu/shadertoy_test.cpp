// The ShaderToy host (gpu/shadertoy.h): small programs written for the
// tests, one per uniform and feature, read back pixel by pixel; programs in
// the style of real ones render deterministically; bad programs are refused
// naming the file (and line).
#include "stochtex/gpu/shadertoy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/analysis/sound_spectrum.h"
#include "stochtex/report/frame_sequence.h"
#include "stochtex/report/wav.h"
#include "test_util.h"

namespace stochtex {
namespace {

namespace fs = std::filesystem;

class Shadertoy : public test::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        try {
            context_ = GlContext::headless();
        } catch (const GpuUnavailable& e) {
            GTEST_SKIP() << e.what();
        }
    }
    // Writes a file of the program under the scratch folder; returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        const fs::path p = dir_ / name;
        fs::create_directories(p.parent_path());
        std::ofstream(p) << text;
        return p.string();
    }
    static ShadertoySettings small(int w = 16, int h = 8) {
        ShadertoySettings s;
        s.width = w;
        s.height = h;
        return s;
    }
    std::unique_ptr<GlContext> context_;
};

std::string error(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

void expectPixel(const std::array<float, 4>& got, const std::array<float, 4>& want, float tolerance, const std::string& what) {
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(got[size_t(c)], want[size_t(c)], tolerance) << what << " [" << c << "]";
}

// iResolution, iTime, iTimeDelta, iFrame, iFrameRate at pixel centres
// (fragCoord = pixel + ½, y up), frame after frame.
TEST_F(Shadertoy, TimeAndResolutionUniformsFollowTheFrame) {
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        fragColor = vec4(fragCoord / iResolution.xy, iTime + 100.0 * iTimeDelta, float(iFrame) + iFrameRate * 1000.0);
    })");
    ShadertoySettings s = small();
    s.fps = 30;
    s.startTime = 2.0;
    ShadertoyHost host(loadShadertoy((dir_ / "p").string()), *context_, s);
    for (int frame = 0; frame < 3; ++frame) {
        host.renderFrame();
        expectPixel(host.pixel("image", 3, 5), {3.5f / 16, 5.5f / 8, float(2.0 + frame / 30.0 + 100.0 / 30), 30000.0f + frame},
                    1e-4f, "frame " + std::to_string(frame));
    }
    // image(): row 0 at the top, so fragCoord.y = h − ½ there.
    const Image top = host.image();
    EXPECT_NEAR(top.at(0, 0, 1), 7.5f / 8, 1e-6);
    EXPECT_NEAR(top.at(0, 7, 1), 0.5f / 8, 1e-6);
}

// A buffer reading its own previous frame counts frames (feedback); the
// image reads it as latest (this frame's), previous and current.
TEST_F(Shadertoy, BufferFeedbackCountsFramesAndFramesReadAsAsked) {
    write("p/a.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        fragColor = texelFetch(iChannel0, ivec2(fragCoord), 0) + vec4(1.0, 0.0, 0.0, 0.0);
    })");
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        ivec2 p = ivec2(fragCoord);
        fragColor = vec4(texelFetch(iChannel0, p, 0).x, texelFetch(iChannel1, p, 0).x, texelFetch(iChannel2, p, 0).x, 0.0);
    })");
    const std::string manifest = write("p/shadertoy.json", R"({"name": "counter", "passes": {
        "buffer_a": {"code": "a.glsl", "channels": [{"type": "buffer", "buffer": "a"}]},
        "image": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "a"},
                  {"type": "buffer", "buffer": "a", "frame": "previous"}, {"type": "buffer", "buffer": "a", "frame": "current"}]}}})");
    ShadertoyHost host(loadShadertoy(manifest), *context_, small());
    for (int frame = 0; frame < 5; ++frame) host.renderFrame();
    expectPixel(host.pixel("buffer_a", 7, 2), {5, 0, 0, 0}, 0, "buffer_a after 5 frames");
    expectPixel(host.pixel("image", 7, 2), {5, 4, 5, 0}, 0, "latest, previous, current");
    host.reset();
    host.renderFrame();
    expectPixel(host.pixel("buffer_a", 0, 0), {1, 0, 0, 0}, 0, "after reset");
}

// A resized program runs on: the frame count and the buffers' content are
// kept (the counter's value is uniform, so stretching keeps it exactly), and
// iResolution is the new size. A refused size changes nothing.
TEST_F(Shadertoy, ResizingKeepsTheFrameAndTheBuffers) {
    write("p/a.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        fragColor = texelFetch(iChannel0, ivec2(fragCoord), 0) + vec4(1.0, 0.0, 0.0, 0.0);
    })");
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        fragColor = vec4(texelFetch(iChannel0, ivec2(fragCoord), 0).x, iResolution.xy, float(iFrame));
    })");
    const std::string manifest = write("p/shadertoy.json", R"({"name": "counter", "passes": {
        "buffer_a": {"code": "a.glsl", "channels": [{"type": "buffer", "buffer": "a"}]},
        "image": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "a"}]}}})");
    ShadertoyHost host(loadShadertoy(manifest), *context_, small(16, 8));
    for (int frame = 0; frame < 5; ++frame) host.renderFrame();
    host.resize(24, 20);
    EXPECT_EQ(host.frame(), 5);
    EXPECT_EQ(host.settings().width, 24);
    EXPECT_EQ(host.image().width(), 24);
    host.renderFrame();
    for (const auto& [x, y] : {std::pair{0, 0}, std::pair{23, 19}, std::pair{11, 7}})
        expectPixel(host.pixel("image", x, y), {6, 24, 20, 5}, 0, "after the resize");
    EXPECT_NE(error([&] { host.resize(0, 20); }).find("width"), std::string::npos);
    EXPECT_EQ(host.settings().width, 24);
    host.renderFrame();
    expectPixel(host.pixel("image", 23, 19), {7, 24, 20, 6}, 0, "after a refused resize");
}

// Channel filters and wraps on a 4×1 image of known texels (vflip off):
// nearest and linear between texels, repeat and clamp outside [0, 1].
TEST_F(Shadertoy, ChannelFilterAndWrapSampleAsAsked) {
    Image img(4, 1, 1);
    const float texels[4] = {0.0f, 0.25f, 0.5f, 1.0f};
    for (int x = 0; x < 4; ++x) img.at(x, 0) = texels[x];
    fs::create_directories(dir_ / "p");
    writeImage((dir_ / "p/strip.exr").string(), img);
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        // u = 0.25: between texels 0 and 1 (centres 0.125, 0.375); u = 1.125: texel 0 again or clamped to 3.
        fragColor = vec4(texture(iChannel0, vec2(0.25, 0.5)).x, texture(iChannel1, vec2(0.25, 0.5)).x,
                         texture(iChannel1, vec2(1.125, 0.5)).x, texture(iChannel2, vec2(1.125, 0.5)).x);
    })");
    write("p/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [
        {"type": "image", "path": "strip.exr", "filter": "nearest", "wrap": "repeat", "vflip": false},
        {"type": "image", "path": "strip.exr", "filter": "linear", "wrap": "repeat", "vflip": false},
        {"type": "image", "path": "strip.exr", "filter": "linear", "wrap": "clamp", "vflip": false}]}}})");
    ShadertoyHost host(loadShadertoy((dir_ / "p").string()), *context_, small(4, 4));
    host.renderFrame();
    // Nearest at the boundary u = 0.25 takes texel 1; linear the mean of 0 and 1;
    // repeat at 1.125 is u = 0.125, texel 0's centre; clamp is texel 3.
    expectPixel(host.pixel("image", 1, 1), {0.25f, 0.125f, 0.0f, 1.0f}, 1e-3f, "filter and wrap");
}

// Published sources run unchanged: a UTF-8 byte-order mark and CR LF line
// ends (a macro continued across one), ShaderToy's names from before 2017
// (iGlobalTime, texture2D), HW_PERFORMANCE (1 as on a desktop, 0 when
// asked), and a grey channel image read as a browser uploads it, (v, v, v, 1).
TEST_F(Shadertoy, PublishedSourcesRunUnchanged) {
    Image grey(4, 1, 1);
    const float texels[4] = {0.0f, 0.25f, 0.5f, 1.0f};
    for (int x = 0; x < 4; ++x) grey.at(x, 0) = texels[x];
    fs::create_directories(dir_ / "p");
    writeImage((dir_ / "p/grey.exr").string(), grey);
    write("p/image.glsl", "\xEF\xBB\xBF// saved by a Windows editor\r\n#define HALF \\\r\n    0.5\r\n"
                          "vec4 fetch(vec2 uv) { return texture2D(iChannel0, uv); }  // a call after `return`\r\n"
                          "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\r\n"
                          "    vec4 g = fetch(vec2(0.375, 0.5));\r\n"
                          "    fragColor = vec4(HALF + iGlobalTime, g.g, g.b + g.a, float(HW_PERFORMANCE));\r\n}\r\n");
    write("p/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [
        {"type": "image", "path": "grey.exr", "filter": "nearest", "vflip": false}]}}})");
    ShadertoySettings s = small(4, 4);
    s.startTime = 2.0;
    {
        ShadertoyHost host(loadShadertoy((dir_ / "p").string()), *context_, s);
        host.renderFrame();
        // texel 1 (0.25) in green and blue as in red; alpha 1.
        expectPixel(host.pixel("image", 1, 1), {2.5f, 0.25f, 1.25f, 1.0f}, 1e-6f, "published source");
    }
    s.hwPerformance = 0;
    ShadertoyHost phone(loadShadertoy((dir_ / "p").string()), *context_, s);
    phone.renderFrame();
    EXPECT_EQ(phone.pixel("image", 0, 0)[3], 0.0f) << "HW_PERFORMANCE as a phone's";
    s.hwPerformance = 2;
    EXPECT_EQ(test::inputErrorOf([&] { validateShadertoySettings(s); }).parameter(), "hwPerformance");
    // A program's own shims of the old names win: no alias collides with them.
    write("q/image.glsl", R"(#define iGlobalTime (iTime * 2.0)
        vec4 texture2D(sampler2D s, vec2 uv) { return texture(s, uv) * 2.0; }
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            fragColor = vec4(iGlobalTime, texture2D(iChannel0, vec2(0.375, 0.5)).g, 0.0, 1.0);
        })");
    fs::copy_file(dir_ / "p/grey.exr", dir_ / "q/grey.exr");
    write("q/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [
        {"type": "image", "path": "grey.exr", "filter": "nearest", "vflip": false}]}}})");
    s.hwPerformance = 1;
    ShadertoyHost shims(loadShadertoy((dir_ / "q").string()), *context_, s);
    shims.renderFrame();
    expectPixel(shims.pixel("image", 1, 1), {4.0f, 0.5f, 0.0f, 1.0f}, 1e-6f, "the program's own shims");
}

// ShaderToy's RGBA noise has the structure published shaders rely on:
// green is red at (x − 37, y − 17) and alpha is blue there, so the
// one-fetch 3D value noise (iq's, in countless cloud and terrain shaders)
// is continuous across its z slices: just below and just above an integer
// z it gives the same value (within 1e-3 over 256 points; with independent
// channels it jumps by the difference of two independent uniforms).
TEST_F(Shadertoy, RgbaNoiseChannelsAreOffsetSoTheSliceTrickIsContinuous) {
    write("p/image.glsl", R"(float noise3(vec3 x) {
        vec3 p = floor(x), f = fract(x);
        f = f * f * (3.0 - 2.0 * f);
        vec2 uv = (p.xy + vec2(37.0, 17.0) * p.z) + f.xy;
        vec2 rg = textureLod(iChannel0, (uv + 0.5) / 256.0, 0.0).yx;
        return mix(rg.x, rg.y, f.z);
    }
    void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        vec2 xy = fragCoord * 1.37 + vec2(0.21, 0.63);
        ivec2 t = ivec2(fragCoord) * 7;
        vec4 here = texelFetch(iChannel0, t, 0), there = texelFetch(iChannel0, (t - ivec2(37, 17)) & 255, 0);
        fragColor = vec4(abs(noise3(vec3(xy, 2.9999)) - noise3(vec3(xy, 3.0001))), here.g - there.r, here.a - there.b,
                         abs(here.r - here.b));
    })");
    write("p/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [
        {"type": "noise", "kind": "rgba", "size": 256, "filter": "linear"}]}}})");
    ShadertoyHost host(loadShadertoy((dir_ / "p").string()), *context_, small(16, 16));
    host.renderFrame();
    double jump = 0, offsetG = 0, offsetA = 0, redVsBlue = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const std::array<float, 4> v = host.pixel("image", x, y);  // RGBA (image() reads RGB)
            jump = std::max(jump, double(v[0]));
            offsetG = std::max(offsetG, std::abs(double(v[1])));
            offsetA = std::max(offsetA, std::abs(double(v[2])));
            redVsBlue += v[3] / 256.0;
        }
    EXPECT_LT(jump, 1e-3) << "the 3D value noise jumps across z = 3";
    EXPECT_EQ(offsetG, 0.0) << "green is red at (x - 37, y - 17)";
    EXPECT_EQ(offsetA, 0.0) << "alpha is blue at (x - 37, y - 17)";
    EXPECT_GT(redVsBlue, 0.2) << "red and blue are independent (mean |r - b| of two uniforms is 1/3)";
}

// The keyboard texture: row 0 held, row 1 pressed this frame only, row 2 toggled.
TEST_F(Shadertoy, KeyboardTextureHoldsPressesAndToggles) {
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        fragColor = vec4(texelFetch(iChannel0, ivec2(65, 0), 0).x, texelFetch(iChannel0, ivec2(65, 1), 0).x,
                         texelFetch(iChannel0, ivec2(65, 2), 0).x, texelFetch(iChannel0, ivec2(66, 0), 0).x);
    })");
    write("p/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [{"type": "keyboard"}]}}})");
    ShadertoyHost host(loadShadertoy((dir_ / "p").string()), *context_, small());
    host.renderFrame();
    expectPixel(host.pixel("image", 0, 0), {0, 0, 0, 0}, 0, "no key");
    host.setKey(65, true);
    host.renderFrame();
    expectPixel(host.pixel("image", 0, 0), {1, 1, 1, 0}, 0, "A pressed");
    host.renderFrame();
    expectPixel(host.pixel("image", 0, 0), {1, 0, 1, 0}, 0, "A held");
    host.setKey(65, false);
    host.renderFrame();
    expectPixel(host.pixel("image", 0, 0), {0, 0, 1, 0}, 0, "A released, still toggled");
    host.setKey(65, true);
    host.renderFrame();
    expectPixel(host.pixel("image", 0, 0), {1, 1, 0, 0}, 0, "A pressed again, toggled back");
    EXPECT_NE(error([&] { host.setKey(300, true); }).find("key codes are 0–255"), std::string::npos);
}

// iDate from the settings' date plus iTime, iMouse as given, iChannelResolution of each channel.
TEST_F(Shadertoy, DateMouseAndChannelResolution) {
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        fragColor = fragCoord.x < 1.0 ? iDate : fragCoord.x < 2.0 ? iMouse
                  : vec4(iChannelResolution[0].xy, iChannelResolution[1].xy);
    })");
    write("p/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [
        {"type": "noise", "size": 32}, {"type": "keyboard"}]}}})");
    ShadertoySettings s = small(4, 2);
    s.date = {2031, 7, 14, 9, 30, 5};
    s.startTime = 1.5;
    s.mouse = {10, 20, 3, 4};
    ShadertoyHost host(loadShadertoy((dir_ / "p").string()), *context_, s);
    host.renderFrame();
    expectPixel(host.pixel("image", 0, 0), {2031, 6, 14, 9 * 3600 + 30 * 60 + 5 + 1.5f}, 1e-2f, "iDate");
    expectPixel(host.pixel("image", 1, 0), {10, 20, 3, 4}, 0, "iMouse");
    expectPixel(host.pixel("image", 2, 0), {32, 32, 256, 3}, 0, "iChannelResolution");
    host.setMouse({1, 2, -1, -2});
    host.renderFrame();
    expectPixel(host.pixel("image", 1, 0), {1, 2, -1, -2}, 0, "iMouse moved");
}

// Noise textures: in [0, 1), deterministic by seed, gray in all channels;
// a Common file's functions reach every pass; the program's own uniforms
// and its instance uniform.
TEST_F(Shadertoy, NoiseCommonAndOwnUniforms) {
    write("p/common.glsl", "float twice(float x) { return 2.0 * x; }\n");
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        vec4 n = texelFetch(iChannel0, ivec2(fragCoord), 0), g = texelFetch(iChannel1, ivec2(fragCoord), 0);
        fragColor = fragCoord.y < 1.0 ? n : fragCoord.y < 2.0 ? vec4(g.x - g.y, g.x - g.w, twice(uGain), float(uInstance))
                  : vec4(uOffset, 0.0, 0.0);
    })");
    write("p/shadertoy.json", R"({"common": "common.glsl", "instance": "uInstance",
        "uniforms": {"uGain": {"type": "float", "value": 0.75}, "uInstance": {"type": "int"}, "uOffset": {"type": "vec2", "value": [3, -4]}},
        "passes": {"image": {"code": "image.glsl", "channels": [{"type": "noise", "size": 8, "seed": 3, "filter": "nearest"},
                                                                {"type": "noise", "kind": "gray", "size": 8}]}}})");
    const ShadertoySpec spec = loadShadertoy((dir_ / "p").string());
    ShadertoyHost host(spec, *context_, small(8, 3));
    host.reset(7);
    host.renderFrame();
    const Image a = host.image();
    double lo = 1, hi = 0;
    for (int x = 0; x < 8; ++x)
        for (int c = 0; c < 3; ++c) lo = std::min(lo, double(a.at(x, 2, c))), hi = std::max(hi, double(a.at(x, 2, c)));
    EXPECT_GE(lo, 0.0);
    EXPECT_LT(hi, 1.0);
    EXPECT_GT(hi - lo, 0.3);  // not a constant
    expectPixel(host.pixel("image", 4, 1), {0, 0, 1.5f, 7}, 0, "gray noise, common, uniforms");
    expectPixel(host.pixel("image", 4, 2), {3, -4, 0, 0}, 0, "vec2 uniform");
    ShadertoyHost again(spec, *context_, small(8, 3));
    again.reset(7);
    again.renderFrame();
    const Image b = again.image();
    EXPECT_EQ(a.data(), b.data());
}

// A program in the style of real ones: a Common file, two buffers that read
// each other (one this frame's, one the previous frame's), a noise and an
// image texture with mipmaps, the image pass reading both buffers; renders
// without error and the same twice, frame for frame.
TEST_F(Shadertoy, MultiBufferProgramRendersDeterministically) {
    Image img(16, 16, 3);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) img.at(x, y, c) = float((x * 3 + y * 5 + c * 7) % 16) / 15.0f;
    fs::create_directories(dir_ / "p");
    writeImage((dir_ / "p/tex.png").string(), img);
    write("p/common.glsl", "#define PI 3.14159265\nvec2 rot(vec2 p, float a) { return mat2(cos(a), sin(a), -sin(a), cos(a)) * p; }\n");
    write("p/a.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        vec2 uv = fragCoord / iResolution.xy;
        vec4 prev = texture(iChannel0, uv);
        vec4 n = texture(iChannel1, rot(uv, iTime) * 2.0);
        fragColor = mix(prev, n, 0.1);
    })");
    write("p/b.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        vec2 uv = fragCoord / iResolution.xy;
        fragColor = textureLod(iChannel0, uv + 0.01 * sin(iTime * PI), 2.0) * texture(iChannel1, uv);
    })");
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        vec2 uv = fragCoord / iResolution.xy;
        fragColor = vec4(0.5 * texture(iChannel0, uv).rgb + 0.5 * texture(iChannel1, uv).rgb, 1.0);
    })");
    write("p/shadertoy.json", R"({"name": "real-world", "common": "common.glsl", "passes": {
        "buffer_a": {"code": "a.glsl", "channels": [{"type": "buffer", "buffer": "a"}, {"type": "noise", "size": 64}]},
        "buffer_b": {"code": "b.glsl", "channels": [{"type": "buffer", "buffer": "a", "filter": "mipmap"}, {"type": "image", "path": "tex.png"}]},
        "image": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "a"}, {"type": "buffer", "buffer": "b"}]}}})");
    const ShadertoySpec spec = loadShadertoy((dir_ / "p").string());
    std::vector<Image> runs[2];
    for (auto& frames : runs) {
        ShadertoyHost host(spec, *context_, small(64, 48));
        renderShadertoyFrames(host, 6, [&](int, const Image& f) { frames.push_back(f); });
    }
    ASSERT_EQ(runs[0].size(), 6u);
    for (size_t k = 0; k < 6; ++k) EXPECT_EQ(runs[0][k].data(), runs[1][k].data()) << "frame " << k;
    double change = 0;
    for (size_t i = 0; i < runs[0][5].data().size(); ++i) change += std::abs(runs[0][5].data()[i] - runs[0][0].data()[i]);
    EXPECT_GT(change, 1.0);  // the buffers evolve
    // Read back only the last frame (an image output) or none: the same last frame, the sink called as asked.
    std::vector<int> taken;
    ShadertoyHost host(spec, *context_, small(64, 48));
    renderShadertoyFrames(host, 6, [&](int frame, const Image& f) {
        taken.push_back(frame);
        EXPECT_EQ(f.data(), runs[0][5].data());
    }, {}, FrameReadBack::Last);
    EXPECT_EQ(taken, std::vector<int>{5});
    host.reset();
    renderShadertoyFrames(host, 6, [&](int frame, const Image&) { taken.push_back(frame); }, {}, FrameReadBack::None);
    EXPECT_EQ(taken, std::vector<int>{5});
    EXPECT_EQ(host.image().data(), runs[0][5].data());
}

// A timeline of events plays with ShaderToy's click semantics: a buffer
// counts the frames whose iMouse.w is positive ("just clicked"), those with
// z positive (held) and those with space pressed; after a reset the
// timeline plays again.
TEST_F(Shadertoy, TimelineEventsFollowShadertoysClickSemantics) {
    write("t/a.glsl", R"(void mainImage(out vec4 c, in vec2 p) {
        vec4 prev = texelFetch(iChannel0, ivec2(0), 0);
        c = prev + vec4(iMouse.w > 0.0 ? 1.0 : 0.0, iMouse.z > 0.0 ? 1.0 : 0.0, texelFetch(iChannel1, ivec2(32, 1), 0).x, 0.0);
    })");
    write("t/image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = iMouse; }\n");
    write("t/shadertoy.json", R"({"passes": {"buffer_a": {"code": "a.glsl", "channels": [{"type": "buffer", "buffer": "a"}, {"type": "keyboard"}]},
        "image": {"code": "image.glsl"}}})");
    ShadertoySettings settings = small();
    using K = ShadertoyInput::Kind;
    settings.inputs = {{2, K::MouseDown, 0, 10, 5}, {3, K::KeyDown, 32}, {4, K::MouseMove, 0, 12, 6}, {5, K::KeyUp, 32},
                       {6, K::MouseUp}, {7, K::KeyDown, 32}, {8, K::MouseDown, 0, 3, 4}};
    ShadertoyHost host(loadShadertoy((dir_ / "t").string()), *context_, settings);
    for (int run = 0; run < 2; ++run) {
        for (int k = 0; k < 10; ++k) {
            host.renderFrame();
            if (k == 5) expectPixel(host.pixel("image", 1, 1), {12, 6, 10, -5}, 0, "iMouse held after a drag");
            if (k == 6) expectPixel(host.pixel("image", 1, 1), {12, 6, -10, -5}, 0, "iMouse after the release");
        }
        // Clicked on frames 2 and 8; held on 2–5 and 8–9; space pressed on frames 3 and 7.
        expectPixel(host.pixel("buffer_a", 0, 0), {2, 6, 2, 0}, 0, "counts, run " + std::to_string(run));
        expectPixel(host.pixel("image", 1, 1), {3, 4, 3, -4}, 0, "iMouse on frame 9");
        host.reset();
    }
    settings.inputs = {{5, K::KeyDown, 32}, {3, K::KeyUp, 32}};
    EXPECT_NE(error([&] { ShadertoyHost h(loadShadertoy((dir_ / "t").string()), *context_, settings); })
                  .find("events must come in order of frame"), std::string::npos);
}

// ShaderToy's own export: Common, two buffers and the image, inputs by
// output id (the export's own, and ShaderToy's old numeric one), a built-in
// noise texture and the keyboard; it runs as the program it describes, and
// --convert's folder runs the same.
TEST_F(Shadertoy, ExportedShaderRunsAndConvertsToAManifest) {
    const std::string exported = write("export/shader.json", R"({"Shader": {"ver": "0.1", "info": {"id": "abcd12", "name": "Two buffers"},
      "renderpass": [
        {"type": "common", "name": "Common", "code": "float twice(float x) { return 2.0 * x; }\r\n", "inputs": [], "outputs": []},
        {"type": "image", "name": "Image", "code": "void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0); }",
         "inputs": [{"id": 258, "src": "/media/previz/buffer01.png", "ctype": "buffer", "channel": 0,
                     "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"}},
                    {"id": 33, "src": "/presets/tex00.jpg", "ctype": "keyboard", "channel": "2"}],
         "outputs": [{"id": 37, "channel": 0}]},
        {"type": "buffer", "name": "Buffer A",
         "code": "void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0) + vec4(1.0, texelFetch(iChannel1, ivec2(3, 5), 0).g, 0.0, 0.0); }",
         "inputs": [{"id": "4dXGR8", "filepath": "/media/previz/buffer00.png", "type": "buffer", "channel": 0,
                     "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true"}},
                    {"id": "XdX3Rn", "filepath": "/media/a/f735bee5b64ef98879dc618b016ecf7939a5756040c2cde21ccb15e69a6e1cfb.png",
                     "type": "texture", "channel": 1, "sampler": {"filter": "nearest", "wrap": "repeat", "vflip": "false"}}],
         "outputs": [{"id": "4dXGR8", "channel": 0}]},
        {"type": "buffer", "name": "Buffer B",
         "code": "void mainImage(out vec4 c, in vec2 p) { c = vec4(twice(texelFetch(iChannel0, ivec2(p), 0).x), 0.0, 0.0, 1.0); }",
         "inputs": [{"id": "257", "src": "/media/previz/buffer00.png", "ctype": "buffer", "channel": 0}],
         "outputs": [{"id": "XsXGR8", "channel": 0}]}]}})");
    const ShadertoySpec spec = loadShadertoy(exported);
    EXPECT_EQ(spec.name, "Two buffers");
    ASSERT_EQ(spec.passes.size(), 3u);
    EXPECT_EQ(spec.passes[0].name, "buffer_a");
    const ShadertoyChannel& noise = spec.passes[0].channels[1];
    EXPECT_EQ(noise.kind, ShadertoyChannel::Kind::Noise);
    EXPECT_TRUE(noise.rgbaNoise);
    EXPECT_EQ(noise.noiseSize, 256);  // RGBA Noise Medium
    EXPECT_EQ(noise.filter, ChannelFilter::Nearest);
    EXPECT_EQ(spec.passes[1].channels[0].buffer, 0);  // "257": Buffer A
    EXPECT_EQ(spec.passes[2].channels[0].buffer, 1);  // 258, a number: Buffer B
    EXPECT_EQ(spec.passes[2].channels[2].kind, ShadertoyChannel::Kind::Keyboard);
    const auto run = [&](const ShadertoySpec& program) {
        ShadertoyHost host(program, *context_, small());
        for (int k = 0; k < 3; ++k) host.renderFrame();
        return std::pair{host.pixel("buffer_a", 1, 1), host.pixel("image", 1, 1)};
    };
    const auto [a, image] = run(spec);
    EXPECT_EQ(a[0], 3.0f);
    EXPECT_GT(a[1], 0.0f);  // three reads of the noise's green at (3, 5)
    expectPixel(image, {6, 0, 0, 1}, 0, "image: Buffer B, twice Buffer A's count");

    const std::string manifest = convertShadertoy(spec, (dir_ / "converted").string());
    EXPECT_TRUE(fs::is_regular_file(dir_ / "converted/buffer_b.glsl"));
    EXPECT_TRUE(fs::is_regular_file(dir_ / "converted/common.glsl"));
    const auto [a2, image2] = run(loadShadertoy((dir_ / "converted").string()));
    EXPECT_EQ(a2, a);
    EXPECT_EQ(image2, image);
    // Converting again onto the same files is refused, and nothing is written.
    EXPECT_NE(error([&] { convertShadertoy(spec, (dir_ / "converted").string()); }).find("exists"), std::string::npos);

    // A compile error names the export and the pass.
    write("export/bad.json", R"({"renderpass": [{"type": "image", "name": "Image", "code": "void mainImage(out vec4 c, in vec2 p) {\n c = nope;\n}"}]})");
    std::string e = error([&] { ShadertoyHost h(loadShadertoy((dir_ / "export/bad.json").string()), *context_, small()); });
    EXPECT_NE(e.find("bad.json (Image):2"), std::string::npos) << e;
    const auto exportError = [&](const std::string& passes) {
        write("export/e.json", R"({"Shader": {"renderpass": [)" + passes + "]}}");
        return error([&] { (void)loadShadertoy((dir_ / "export/e.json").string()); });
    };
    const std::string imagePass = R"({"type": "image", "name": "Image", "code": "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }")";
    e = exportError(imagePass + R"(, "inputs": [{"id": 5, "src": "", "ctype": "webcam", "channel": 0}]})");
    EXPECT_NE(e.find("/Shader/renderpass/0/inputs/0/ctype: a webcam input is a ShaderToy input this host does not support"),
              std::string::npos) << e;
    e = exportError(imagePass + "}, " + R"({"type": "vr", "name": "VR", "code": ""})");
    EXPECT_NE(e.find("/Shader/renderpass/1/type: a vr pass (VR) is a ShaderToy pass this host does not run"),
              std::string::npos) << e;
    e = exportError(imagePass + R"(, "inputs": [{"id": 8, "src": "/media/a/52d2a8f514c4fd2d9866587f4d7b2a5bfa1a11a0e772077d7682deb8b3b517e5.jpg", "ctype": "texture", "channel": 1}]})");
    EXPECT_NE(e.find("put its file (52d2a8f514c4fd2d9866587f4d7b2a5bfa1a11a0e772077d7682deb8b3b517e5.jpg) in"),
              std::string::npos) << e;
    e = exportError(imagePass + R"(, "inputs": [{"id": "XsXGR8", "ctype": "buffer", "channel": 0}]})");
    EXPECT_NE(e.find("reads buffer_b, which the export lacks"), std::string::npos) << e;
    e = exportError(R"({"type": "buffer", "name": "Buffer A", "code": ""})");
    EXPECT_NE(e.find("/Shader/renderpass: needs an Image pass"), std::string::npos) << e;
}

// A volume channel is a sampler3D of the generated noise: texels as
// shadertoyNoiseVolume gives them, trilinear between them, repeating at the
// edge; iChannelResolution holds its depth.
TEST_F(Shadertoy, VolumeChannelSamplesTheNoiseVolume) {
    write("vol/image.glsl", R"(void mainImage(out vec4 c, in vec2 p) {
        int x = int(p.x);
        if (x == 0) c = texelFetch(iChannel0, ivec3(1, 2, 3), 0);
        else if (x == 1) c = texture(iChannel0, (vec3(1.0, 2.0, 3.0) + vec3(1.0, 0.5, 0.5)) / 32.0);
        else if (x == 2) c = texture(iChannel0, (vec3(31.0, 2.0, 3.0) + vec3(1.0, 0.5, 0.5)) / 32.0);
        else if (x == 3) c = vec4(iChannelResolution[0], 0.0);
        else c = texelFetch(iChannel1, ivec3(5, 6, 7), 0);
    })");
    write("vol/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [
        {"type": "volume", "kind": "rgba", "filter": "linear"}, {"type": "volume", "kind": "gray", "seed": 4}]}}})");
    ShadertoyHost host(loadShadertoy((dir_ / "vol").string()), *context_, small(8, 2));
    host.renderFrame();
    const std::vector<float> v = shadertoyNoiseVolume(32, true, 0);
    const auto texel = [&](int x, int y, int z) {
        std::array<float, 4> t{};
        for (int c = 0; c < 4; ++c) t[size_t(c)] = v[((size_t(z) * 32 + y) * 32 + x) * 4 + size_t(c)];
        return t;
    };
    const auto mid = [](std::array<float, 4> a, std::array<float, 4> b) {
        for (int c = 0; c < 4; ++c) a[size_t(c)] = 0.5f * (a[size_t(c)] + b[size_t(c)]);
        return a;
    };
    expectPixel(host.pixel("image", 0, 0), texel(1, 2, 3), 0, "texel (1, 2, 3)");
    expectPixel(host.pixel("image", 1, 0), mid(texel(1, 2, 3), texel(2, 2, 3)), 2e-3f, "between texels");
    expectPixel(host.pixel("image", 2, 0), mid(texel(31, 2, 3), texel(0, 2, 3)), 2e-3f, "across the repeat");
    expectPixel(host.pixel("image", 3, 0), {32, 32, 32, 0}, 0, "iChannelResolution");
    const float grey = shadertoyNoiseVolume(32, false, 4)[((7 * 32 + 6) * 32 + 5) * 4];
    expectPixel(host.pixel("image", 4, 0), {grey, grey, grey, grey}, 0, "a gray volume");
    // The texels are uniform and the channels independent (mean ½, no correlation between red and green).
    double mean = 0, cross = 0;
    for (size_t k = 0; k < v.size(); k += 4) mean += v[k], cross += (v[k] - 0.5) * (v[k + 1] - 0.5);
    const double n = double(v.size() / 4);
    EXPECT_NEAR(mean / n, 0.5, 0.005);                // σ of the mean: 0.29 / √32768 = 0.0016
    EXPECT_NEAR(cross / n / (1.0 / 12.0), 0.0, 0.03);  // σ of the correlation: 1 / √32768 = 0.0055
}

// A cubemap channel is a samplerCube: six faces read along ±x, ±y, ±z, or
// an equirectangular image whose centre column looks along −z and top row up.
TEST_F(Shadertoy, CubemapChannelFromFacesAndFromAPanorama) {
    fs::create_directories(dir_ / "cube");
    std::string faces;
    for (int f = 0; f < 6; ++f) {
        Image face(4, 4, 3);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) face.at(x, y, 0) = float(f) / 5.0f, face.at(x, y, 1) = 0.5f, face.at(x, y, 2) = 1.0f;
        writeImage((dir_ / ("cube/f" + std::to_string(f) + ".png")).string(), face, kNoTransfer);
        faces += std::string(f ? ", " : "") + "\"f" + std::to_string(f) + ".png\"";
    }
    // The panorama's red is its column (u), green its row (v), 64 × 32.
    Image pano(64, 32, 3);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) pano.at(x, y, 0) = (x + 0.5f) / 64.0f, pano.at(x, y, 1) = (y + 0.5f) / 32.0f;
    writeImage((dir_ / "cube/pano.exr").string(), pano);
    write("cube/image.glsl", R"(const vec3 dirs[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));
        void mainImage(out vec4 c, in vec2 p) {
            int k = int(p.x);
            c = p.y < 1.0 ? texture(iChannel0, dirs[k]) : vec4(texture(iChannel1, dirs[k]).rgb, iChannelResolution[1].x);
        })");
    write("cube/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [
        {"type": "cubemap", "faces": [)" + faces + R"(]}, {"type": "cubemap", "equirect": "pano.exr", "filter": "linear"}]}}})");
    ShadertoyHost host(loadShadertoy((dir_ / "cube").string()), *context_, small(6, 2));
    host.renderFrame();
    for (int f = 0; f < 6; ++f)
        expectPixel(host.pixel("image", f, 0), {float(f) / 5.0f, 0.5f, 1.0f, 1.0f}, 2.5e-3f, "face " + std::to_string(f));
    // u: −z at ½, −x at ¼, +x at ¾, +z at the seam (0 or 1); v: +y at the top (0), −y at the bottom (1), the rest ½.
    const float uWant[6] = {0.75f, 0.25f, -1, -1, -1, 0.5f}, vWant[6] = {0.5f, 0.5f, 0.0f, 1.0f, 0.5f, 0.5f};
    for (int f = 0; f < 6; ++f) {
        const std::array<float, 4> got = host.pixel("image", f, 1);
        if (uWant[f] >= 0) {
            EXPECT_NEAR(got[0], uWant[f], 0.03) << "u of face " << f;
        }
        EXPECT_NEAR(got[1], vWant[f], 0.04) << "v of face " << f;
        EXPECT_EQ(got[3], 16.0f);  // a quarter of the panorama's width
    }
}

// A video channel shows the video's frame at the frame's time (OpenCV's
// decoder), looping after its last frame, with iChannelTime the frame's time
// in the video; the frames are grey k/7, 8 frames at 10 fps, and the
// program runs at 20 fps (two of its frames per video frame).
TEST_F(Shadertoy, VideoChannelPlaysByTimeAndLoops) {
    fs::create_directories(dir_ / "video");
    {
        FrameSequenceWriter writer((dir_ / "video/clip.mp4").string(), 32, 16, 10, "", Transfer::Linear);
        for (int k = 0; k < 8; ++k) writer.write(Image(32, 16, 3, float(k) / 7.0f));
        writer.finish();
    }
    write("video/image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(texture(iChannel0, vec2(0.5)).rgb, iChannelTime[0]); }\n");
    write("video/shadertoy.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [{"type": "video", "path": "clip.mp4"}]}}})");
    ShadertoySettings settings = small();
    settings.fps = 20;
    ShadertoyHost host(loadShadertoy((dir_ / "video").string()), *context_, settings);
    for (int n = 0; n < 18; ++n) {
        host.renderFrame();
        const int shown = (n / 2) % 8;  // t = n / 20 s: video frame ⌊t · 10⌋, looping after 8
        const float grey = float(shown) / 7.0f;
        expectPixel(host.pixel("image", 3, 3), {grey, grey, grey, float(shown) / 10.0f}, 0.02f, "frame " + std::to_string(n));
    }
    write("video/bad.json", R"({"passes": {"image": {"code": "image.glsl", "channels": [{"type": "video", "path": "image.glsl"}]}}})");
    EXPECT_NE(error([&] { ShadertoyHost h(loadShadertoy((dir_ / "video/bad.json").string()), *context_, small()); })
                  .find("image.glsl: not a video"), std::string::npos);
}

// A sound pass: sample s of the render is mainSound(s, s / iSampleRate) in
// ShaderToy's 512 × 512 blocks (exact sample numbers across the first
// block's end); the older mainSound(time) form plays a 440 Hz tone whose
// spectrum peaks at 440 Hz; the WAV holds the samples as 16-bit PCM.
TEST_F(Shadertoy, SoundPassRendersSamplesInOrderAndATone) {
    write("snd/image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }\n");
    write("snd/sound.glsl", "vec2 mainSound(int s, float t) { return vec2(float(s % 1000) / 1000.0, -float(s % 777) / 777.0); }\n");
    ShadertoyHost host(loadShadertoy((dir_ / "snd").string()), *context_, small());
    const double seconds = 270000.0 / 44100.0;  // past the first block of 262144 samples
    const std::vector<float> samples = host.renderSound(seconds);
    ASSERT_EQ(samples.size(), 270000u * 2);
    for (const int k : {0, 1, 511, 512, 262143, 262144, 262145, 269999}) {
        EXPECT_NEAR(samples[size_t(k) * 2], float(k % 1000) / 1000.0f, 1e-6f) << "left " << k;
        EXPECT_NEAR(samples[size_t(k) * 2 + 1], -float(k % 777) / 777.0f, 1e-6f) << "right " << k;
    }
    write("tone/image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }\n");
    write("tone/Sound.glsl", "vec2 mainSound(float time) { return vec2(0.5 * sin(6.2831853 * 440.0 * time)); }\n");
    ShadertoyHost tone(loadShadertoy((dir_ / "tone").string()), *context_, small());
    const std::vector<float> a = tone.renderSound(1.0);
    const SoundSpectrum spectrum = soundSpectrum(a, 2, 44100);
    EXPECT_NEAR(spectrum.peakFrequency, 440.0, 0.5);
    EXPECT_NEAR(spectrum.rms, 0.5 / std::sqrt(2.0), 1e-3);
    const std::string wav = (dir_ / "tone.wav").string();
    writeWav(wav, a, 2, 44100);
    std::ifstream in(wav, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_EQ(bytes.size(), 44u + a.size() * 2);
    EXPECT_EQ(bytes.substr(0, 4), "RIFF");
    EXPECT_EQ(bytes.substr(8, 8), "WAVEfmt ");
    const auto sample = [&](size_t i) { return int16_t(uint16_t(uint8_t(bytes[44 + 2 * i])) | uint16_t(uint8_t(bytes[45 + 2 * i])) << 8); };
    for (const size_t i : {size_t(0), size_t(101), size_t(25)}) EXPECT_NEAR(sample(i * 2), a[i * 2] * 32767.0f, 0.51f) << i;
    EXPECT_NE(error([&] { (void)host.renderSound(0); }).find("must be in (0, 180] s"), std::string::npos);
    write("nosound/image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }\n");
    ShadertoyHost none(loadShadertoy((dir_ / "nosound").string()), *context_, small());
    EXPECT_NE(error([&] { (void)none.renderSound(1); }).find("has no sound pass"), std::string::npos);
}

// Cube A renders a cube map face by face, each fragment given the ray
// direction that samples it back (so a texel's value written along rayDir
// is read along rayDir), with feedback from its previous frame like a
// buffer: after 3 frames each texel holds 3 · (rayDir, 1).
TEST_F(Shadertoy, CubePassRendersTheDirectionsItIsReadAlongWithFeedback) {
    write("cubea/cube.glsl", R"(void mainCubemap(out vec4 c, in vec2 fragCoord, in vec3 rayOri, in vec3 rayDir) {
        c = texture(iChannel0, rayDir) + vec4(rayDir, 1.0) + vec4(0.0 * rayOri, 0.0);
    })");
    write("cubea/image.glsl", R"(void mainImage(out vec4 c, in vec2 p) {
        vec3 d = int(p.x) == 0 ? vec3(1.0, 0.375, -0.375) : int(p.x) == 1 ? vec3(0.375, 0.375, 1.0) : vec3(-0.125, -1.0, 0.625);
        c = int(p.x) == 3 ? vec4(iChannelResolution[0], 0.0) : texture(iChannel0, d);
    })");
    write("cubea/shadertoy.json", R"({"passes": {
        "cube_a": {"code": "cube.glsl", "size": 8, "channels": [{"type": "cube_a", "filter": "nearest"}]},
        "image": {"code": "image.glsl", "channels": [{"type": "cube_a", "filter": "nearest"}]}}})");
    const ShadertoySpec spec = loadShadertoy((dir_ / "cubea").string());
    ASSERT_EQ(spec.passes.size(), 2u);
    EXPECT_EQ(spec.passes[0].name, "cube_a");
    ShadertoyHost host(spec, *context_, small(4, 1));
    for (int k = 0; k < 3; ++k) host.renderFrame();
    // Texel centres of faces +x, +z and −y of an 8² face: (a, b) = (±0.375, ±0.375) and (−0.125, 0.625).
    const float dirs[3][3] = {{1.0f, 0.375f, -0.375f}, {0.375f, 0.375f, 1.0f}, {-0.125f, -1.0f, 0.625f}};
    for (int k = 0; k < 3; ++k) {
        const float* d = dirs[k];
        const float n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        expectPixel(host.pixel("image", k, 0), {3 * d[0] / n, 3 * d[1] / n, 3 * d[2] / n, 3.0f}, 1e-4f,
                    "direction " + std::to_string(k));
    }
    expectPixel(host.pixel("image", 3, 0), {8, 8, 1, 0}, 0, "iChannelResolution");
    EXPECT_NE(error([&] { host.checkPixel("cube_a", 0, 0); }).find("a cube map, not a frame"), std::string::npos);
    host.reset();
    host.renderFrame();
    EXPECT_NEAR(host.pixel("image", 0, 0)[3], 1.0f, 1e-6f);  // cleared on reset
}

// A folder saved with ShaderToy's tab names is a program too.
TEST_F(Shadertoy, FolderWithShadertoysTabNamesLoads) {
    write("tabs/Common.glsl", "#define ONE 1.0\n");
    write("tabs/Buffer A.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(ONE); }\n");
    write("tabs/Image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5 * ONE); }\n");
    const ShadertoySpec spec = loadShadertoy((dir_ / "tabs").string());
    ASSERT_EQ(spec.passes.size(), 2u);
    EXPECT_EQ(spec.passes[0].name, "buffer_a");
    EXPECT_EQ(spec.common.filename(), "Common.glsl");
    ShadertoyHost host(spec, *context_, small());
    host.renderFrame();
    expectPixel(host.pixel("image", 0, 0), {0.5f, 0.5f, 0.5f, 0.5f}, 0, "image");
}

// After a reset, every level of a mipmapped buffer reads 0 until the
// buffer runs again (no level of the previous run survives); keys held by
// the settings come back with every reset, so a texture source sees them.
TEST_F(Shadertoy, ResetClearsEveryMipLevelAndKeepsTheHeldKeys) {
    write("p/a.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(5.0); }\n");
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        vec2 uv = fragCoord / iResolution.xy;
        fragColor = vec4(textureLod(iChannel0, uv, 3.0).x, texture(iChannel0, uv).x, texelFetch(iChannel1, ivec2(65, 0), 0).x,
                         texelFetch(iChannel1, ivec2(65, 1), 0).x);
    })");
    write("p/shadertoy.json", R"({"passes": {"buffer_a": {"code": "a.glsl"},
        "image": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "a", "frame": "previous", "filter": "mipmap"},
                                                     {"type": "keyboard"}]}}})");
    ShadertoySettings s = small(32, 16);
    s.keys = {65};
    ShadertoyHost host(loadShadertoy((dir_ / "p").string()), *context_, s);
    host.renderFrame();
    expectPixel(host.pixel("image", 5, 5), {0, 0, 1, 1}, 0, "frame 0: nothing before; A held and pressed");
    host.renderFrame();
    expectPixel(host.pixel("image", 5, 5), {5, 5, 1, 0}, 0, "frame 1: the previous frame at every level");
    host.reset();
    host.renderFrame();
    expectPixel(host.pixel("image", 5, 5), {0, 0, 1, 1}, 0, "frame 0 after a reset");
}

// The shipped examples, in the style of real programs (feedback buffers,
// Common files, noise and keyboard channels, a raymarcher, a pattern
// through stochtex_sample): each compiles, renders frames that are not
// flat, and renders them again identically.
TEST_F(Shadertoy, ShippedExamplesRenderDeterministically) {
    int programs = 0;
    for (const auto& entry : fs::directory_iterator(STOCHTEX_SHADERTOY_EXAMPLES)) {
        if (!entry.is_directory()) continue;
        const ShadertoySpec spec = loadShadertoy(entry.path().string());
        ShadertoySettings s = small(48, 32);
        s.startTime = 4.0;
        std::vector<Image> runs[2];
        for (auto& frames : runs) {
            ShadertoyHost host(spec, *context_, s);
            renderShadertoyFrames(host, 40, [&](int frame, const Image& f) {
                if (frame % 13 == 0 || frame == 39) frames.push_back(f);
            });
        }
        for (size_t k = 0; k < runs[0].size(); ++k) EXPECT_EQ(runs[0][k].data(), runs[1][k].data()) << spec.name << " frame " << k;
        const Image& last = runs[0].back();
        double lo = 1e9, hi = -1e9;
        for (const float v : last.data()) lo = std::min(lo, double(v)), hi = std::max(hi, double(v));
        EXPECT_GT(hi - lo, 0.1) << spec.name << ": a flat frame";
        ++programs;
    }
    EXPECT_GE(programs, 4);
}

// A program's frames through the texture-source interface: a window of the
// frame at a time, the instance uniform per instance, refusals outside.
TEST_F(Shadertoy, FramesFeedTheStudiesAsATextureSource) {
    write("p/image.glsl", R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
        fragColor = vec4(float(iFrame), float(uInstance), fragCoord.x, 1.0);
    })");
    write("p/shadertoy.json", R"({"instance": "uInstance", "uniforms": {"uInstance": {"type": "int"}},
        "passes": {"image": {"code": "image.glsl"}}})");
    ShadertoySettings s = small(16, 8);
    s.fps = 10;
    ShadertoyHost host(loadShadertoy((dir_ / "p").string()), *context_, s);
    const ShadertoySource source(host);
    const Image a = source.render({4, 2, -5, -3}, 0.5, 2);  // frame pixels x 3–6, rows 1–2 (centre (8, 4))
    EXPECT_EQ(a.width(), 4);
    EXPECT_EQ(a.at(0, 0, 0), 5.0f);  // t = 0.5 s at 10 fps
    EXPECT_EQ(a.at(0, 0, 1), 2.0f);
    EXPECT_EQ(a.at(1, 0, 2), 4.5f);
    const Image b = source.render({4, 2, -5, -3}, 0.2, 0);  // earlier: replayed from frame 0
    EXPECT_EQ(b.at(0, 0, 0), 2.0f);
    EXPECT_EQ(b.at(0, 0, 1), 0.0f);
    EXPECT_NE(error([&] { source.checkWindow(SourceRegion::centred(20, 2), 0); }).find("exceeds the 16x8 frame"),
              std::string::npos);
    EXPECT_NE(error([&] { source.checkWindow(SourceRegion::centred(4, 2), -1); }).find("at or after the program's start"),
              std::string::npos);
    const Image whole = source.render(SourceRegion::centred(16, 8), 0.5, 2);
    EXPECT_EQ(whole.at(0, 0, 2), 0.5f);  // the whole frame from its first pixel
}

// A program with a pattern: stochtex_sample(uv) is the filtered pattern
// (the export's include, the footprint from the fragment's derivatives), as
// the CPU filters it over the same zoom view; a graph pattern too.
TEST_F(Shadertoy, PatternIncludeSamplesTheFilteredProgram) {
    for (const std::string preset : {"camouflage", "figure14"}) {
        const PatternSpec spec = loadPreset(preset);
        const GraphPattern program = GraphPattern::build(spec);
        const int w = program.exampleSize();
        const double scale = 3.0;
        write("pat/image.glsl", "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                "    vec2 uv = vec2(fragCoord.x, iResolution.y - fragCoord.y) * " + std::to_string(scale) +
                                " / " + std::to_string(w) + ".0;\n    fragColor = stochtex_sample(uv);\n}\n");
        write("pat/shadertoy.json", R"({"pattern": {"preset": ")" + preset + R"(", "filter": "smooth"},
            "passes": {"image": {"code": "image.glsl", "channels": [{"type": "noise"}]}}})");
        ShadertoyHost host(loadShadertoy((dir_ / "pat").string()), *context_, small(48, 32));
        host.renderFrame();
        const Image gpu = host.image();
        Camera cam;
        cam.view = {48, 32, scale};
        FilterOptions o;
        o.use(parseFilter("smooth"));
        const Image cpu = FilteredGraph(program, o).render(cam);
        double mean = 0;
        for (size_t i = 0; i < cpu.data().size(); ++i) mean += std::abs(double(gpu.data()[i]) - cpu.data()[i]);
        mean /= double(cpu.data().size());
        std::printf("[ info ] %s through stochtex_sample: mean |ShaderToy - CPU| %.2e\n", preset.c_str(), mean);
        EXPECT_LT(mean, 2e-4) << preset;
    }
    write("pat/shadertoy.json", R"({"pattern": {"preset": "nope"}, "passes": {"image": {"code": "image.glsl"}}})");
    EXPECT_NE(error([&] { (void)loadShadertoy((dir_ / "pat").string()); }).find("/pattern/preset: "), std::string::npos);
}

TEST_F(Shadertoy, BadProgramsAreRefusedNamingTheFileAndLine) {
    const std::string image = write("bad/image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n    c.x = undefinedThing;\n}\n");
    std::string e = error([&] { ShadertoyHost host(loadShadertoy((dir_ / "bad").string()), *context_, small()); });
    EXPECT_NE(e.find(image + ":3"), std::string::npos) << e;
    EXPECT_NE(e.find("\n    3 | c.x = undefinedThing;"), std::string::npos) << e;  // the line itself
    // A call matching no overload: the first error alone, not the compiler's list of candidates.
    const std::string overload = write("overload/image.glsl",
                                       "void mainImage(out vec4 c, in vec2 p) {\n    c = texture(iChannel0, p, 1.0, 2.0);\n}\n");
    e = error([&] { ShadertoyHost host(loadShadertoy((dir_ / "overload").string()), *context_, small()); });
    EXPECT_NE(e.find(overload + ":2"), std::string::npos) << e;
    EXPECT_EQ(e.find("sampler1D"), std::string::npos) << e;  // no candidate overloads
    EXPECT_LT(std::count(e.begin(), e.end(), '\n'), 3) << e;
    EXPECT_LT(e.size(), 400u) << e;
    // ShaderToy features the host lacks are named: a channel read as a cube or volume, a sound pass.
    write("cube/image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    c = texture(iChannel0, vec3(p, 1.0));\n}\n");
    e = error([&] { ShadertoyHost host(loadShadertoy((dir_ / "cube").string()), *context_, small()); });
    EXPECT_NE(e.find("a volume or cubemap channel on ShaderToy: give a volume as"), std::string::npos) << e;
    write("sound/image.glsl", "vec2 mainSound(int s, float t) { return vec2(sin(6.2831 * 440.0 * t)); }\n");
    e = error([&] { ShadertoyHost host(loadShadertoy((dir_ / "sound").string()), *context_, small()); });
    EXPECT_NE(e.find("a sound pass's code (mainSound), which belongs in sound.glsl or the manifest's \"sound\" pass, not a picture pass"),
              std::string::npos) << e;
    write("nomain/image.glsl", "float f(float x) { return x; }\n");
    e = error([&] { ShadertoyHost host(loadShadertoy((dir_ / "nomain").string()), *context_, small()); });
    EXPECT_NE(e.find("defines no mainImage"), std::string::npos) << e;
    e = error([&] { (void)loadShadertoy((dir_ / "none").string()); });
    EXPECT_NE(e.find("no such ShaderToy folder or manifest"), std::string::npos) << e;
    write("empty/common.glsl", "\n");
    e = error([&] { (void)loadShadertoy((dir_ / "empty").string()); });
    EXPECT_NE(e.find("a ShaderToy folder needs image.glsl"), std::string::npos) << e;
    write("m/image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }\n");
    const auto manifestError = [&](const std::string& text) {
        write("m/shadertoy.json", text);
        return error([&] { ShadertoyHost host(loadShadertoy((dir_ / "m").string()), *context_, small()); });
    };
    e = manifestError(R"({"passes": {"image": {"code": "image.glsl", "channels": [{"type": "image", "path": "missing.png"}]}}})");
    EXPECT_NE(e.find("missing.png"), std::string::npos) << e;
    e = manifestError(R"({"passes": {"buffer_a": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "b", "frame": "current"}]},
        "buffer_b": {"code": "image.glsl"}, "image": {"code": "image.glsl"}}})");
    EXPECT_NE(e.find("/passes/buffer_a/channels/0/frame: a pass cycle"), std::string::npos) << e;
    e = manifestError(R"({"uniforms": {"uX": {"type": "mat3"}}, "passes": {"image": {"code": "image.glsl"}}})");
    EXPECT_NE(e.find("/uniforms/uX/type: unknown value \"mat3\""), std::string::npos) << e;
    e = manifestError(R"({"passes": {"image": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "c"}]}}})");
    EXPECT_NE(e.find("/passes/image/channels/0/buffer: the program has no pass \"buffer_c\""), std::string::npos) << e;
    e = manifestError(R"({"passes": {"image": {"code": "image.glsl", "channels": [{"type": "mic"}]}}})");
    EXPECT_NE(e.find("/passes/image/channels/0/type: a mic channel is a ShaderToy input this host does not support"),
              std::string::npos) << e;
    e = manifestError(R"({"uniforms": {"iTime": {"type": "float"}}, "passes": {"image": {"code": "image.glsl"}}})");
    EXPECT_NE(e.find("/uniforms/iTime: not a usable uniform name"), std::string::npos) << e;
    e = manifestError(R"({"passes": {"buffer_a": {"code": "image.glsl"}}})");
    EXPECT_NE(e.find("/passes: needs an \"image\" pass"), std::string::npos) << e;
}

}  // namespace
}  // namespace stochtex

// Issue "Hostile input on the new surfaces", item 6: a `#line` near 2³¹
// made the driver print line numbers past an int, and std::stoi ended the
// run as "internal error: stoi". A line an int does not hold is 0 (unknown).
TEST(ShaderLog, LineNumbersPastAnIntAreUnknownNotAnError) {
    EXPECT_EQ(stochtex::logLineNumber("12"), 12);
    EXPECT_EQ(stochtex::logLineNumber("2147483647"), 2147483647);
    EXPECT_EQ(stochtex::logLineNumber("2147483648"), 0);
    EXPECT_EQ(stochtex::logLineNumber("99999999999999999999999"), 0);
    EXPECT_EQ(stochtex::logLineNumber("0"), 0);
    EXPECT_EQ(stochtex::logLineNumber(""), 0);
}
