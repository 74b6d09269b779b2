// `stochtex bake`'s export, loaded by a minimal GL program that uses only the
// exported files (manifest, EXR data, stochtex.glsl) and plain GL calls, must
// render what `render --gpu` renders.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <regex>
#include <set>
#include <sstream>

#include "stochtex/gpu/export.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/presets.h"
#include "test_util.h"

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

std::string readText(const fs::path& file) {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The PatternParameters block's bytes as an engine fills them: each member's
// value from the manifest, written at the offset the README's member table
// gives ("| offset | type | `member` | meaning | source |").
std::vector<std::uint8_t> parameterBlock(const std::string& readme, const nlohmann::json& m, std::size_t bytes) {
    const auto f = [](float v) { return std::bit_cast<std::uint32_t>(v); };
    const auto i = [](int v) { return std::bit_cast<std::uint32_t>(v); };
    std::map<std::string, std::vector<std::uint32_t>> values = {
        {"gridDensity", {f(m["grid_density"].get<float>())}},
        {"invExampleSize", {f(1.0f / m["example_size"].get<float>())}},
        {"aniso", {i(m["aniso"].get<int>())}},
        {"smoothTable", {i(m["filter"] == "smooth")}},
        {"tableLevels", {i(m.contains("table") ? m["table"]["levels"].get<int>() : 0)}},  // a lean program has none
        {"gridPeriodU", {i(m["grid_period"][0].get<int>())}},
        {"gridPeriodV", {i(m["grid_period"][1].get<int>())}},
        {"gridDensityU", {f(m["grid_density_u"].get<float>())}},
    };
    std::vector<std::uint8_t> block(bytes, 0);
    std::istringstream lines(readme);
    for (std::string line; std::getline(lines, line);) {
        // A member row: "| 8 | `int` | `aniso` | ..."; no other table's row starts with a number.
        std::size_t offset = 0;
        char member[64] = {};
        if (std::sscanf(line.c_str(), "| %zu | `%*[^`]` | `%63[^`]`", &offset, member) != 2) continue;
        const auto it = values.find(member);
        if (it == values.end()) {
            ADD_FAILURE() << "README member " << member << " has no value here";
            continue;
        }
        EXPECT_LE(offset + 4 * it->second.size(), bytes) << member;
        if (offset + 4 * it->second.size() > bytes) continue;
        std::memcpy(block.data() + offset, it->second.data(), 4 * it->second.size());
        values.erase(it);
    }
    EXPECT_TRUE(values.empty()) << values.size() << " members missing from the README, e.g. " << values.begin()->first;
    return block;
}

// What a fragment renders (uPixelScale: texels per pixel): the pattern at
// its pixel centre, the footprint from the fragment's derivatives.
constexpr const char* kSampleAtPixel = "stochtex_sample(gl_FragCoord.xy * uPixelScale * uPattern.invExampleSize)";

// An engine's view of the export: it knows GL and the README, nothing else.
// `fragment`: a whole fragment shader (its #version line first) that may
// declare uPixelScale and the PatternParameters block; the textures are
// bound by manifest.json's names.
Image renderFragment(const fs::path& dir, int width, int height, double scale, const std::string& fragment) {
    std::ifstream mf(dir / "manifest.json");
    const nlohmann::json m = nlohmann::json::parse(mf);
    const bool es = fragment.rfind("#version 300 es", 0) == 0;  // a program takes one kind of stage
    const GLuint vs =
        compile(GL_VERTEX_SHADER, std::string(es ? "#version 300 es\n" : "#version 330 core\n") +
                                      "void main() { vec2 p = vec2(float((gl_VertexID << 1) & 2), "
                                      "float(gl_VertexID & 2)); gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n");
    const GLuint fs_ = compile(GL_FRAGMENT_SHADER, fragment);
    const GLuint prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs_);
    glLinkProgram(prog);
    GLint linked = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &linked);
    if (!linked) {  // else the last program would stay in use and draw instead
        char linkLog[4096];
        glGetProgramInfoLog(prog, sizeof linkLog, nullptr, linkLog);
        ADD_FAILURE() << "link: " << linkLog;
        return Image(width, height, 3);
    }
    glUseProgram(prog);
    // Every sampler of manifest.json's "textures", each on a unit of its own,
    // uploaded in the GL format the manifest names: float files as floats,
    // 8-bit files as their codes.
    const auto upload = [&](GLenum target, GLint level, const std::string& format, const Image& img, int width,
                            int height, int depth) {
        const std::map<std::string, std::pair<GLint, int>> formats = {
            {"RG32F", {GL_RG32F, 2}},   {"RG16F", {GL_RG16F, 2}}, {"RGBA8", {GL_RGBA8, 4}}, {"RGB32F", {GL_RGB32F, 3}},
            {"RGB16F", {GL_RGB16F, 3}}, {"SRGB8", {GL_SRGB8, 3}}, {"RGB16", {GL_RGB16, 3}}};
        const auto it = formats.find(format);
        EXPECT_NE(it, formats.end()) << "unknown format " << format;
        if (it == formats.end()) return;
        const auto [internal, channels] = it->second;
        const GLenum layout = channels == 2 ? GL_RG : channels == 3 ? GL_RGB : GL_RGBA;
        EXPECT_GE(img.channels(), channels) << format;
        const bool bytes = format == "RGBA8" || format == "SRGB8", shorts = format == "RGB16";
        std::vector<float> values(img.pixelCount() * size_t(channels));
        std::vector<std::uint8_t> codes(bytes ? values.size() : 0);
        std::vector<std::uint16_t> codes16(shorts ? values.size() : 0);
        for (size_t i = 0; i < img.pixelCount(); ++i)
            for (size_t c = 0; c < size_t(channels); ++c) {
                const float v = img.data()[size_t(img.channels()) * i + c];
                values[size_t(channels) * i + c] = v;
                if (bytes) codes[size_t(channels) * i + c] = std::uint8_t(std::lround(v * 255.0f));
                if (shorts) codes16[size_t(channels) * i + c] = std::uint16_t(std::lround(v * 65535.0f));
            }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        const GLenum type = bytes ? GL_UNSIGNED_BYTE : shorts ? GL_UNSIGNED_SHORT : GL_FLOAT;
        const void* data = bytes    ? static_cast<const void*>(codes.data())
                           : shorts ? static_cast<const void*>(codes16.data())
                                    : static_cast<const void*>(values.data());
        if (target == GL_TEXTURE_2D_ARRAY)
            glTexImage3D(target, level, internal, width, height, depth, 0, layout, type, data);
        else
            glTexImage2D(target, level, internal, width, height, 0, layout, type, data);
    };
    auto pyramid = [&](const nlohmann::json& t) {
        GLuint id = 0;
        glGenTextures(1, &id);
        glBindTexture(GL_TEXTURE_2D, id);
        const nlohmann::json& files = t["files"];
        for (size_t l = 0; l < files.size(); ++l) {
            const Image img = readImage((dir / files[l].get<std::string>()).string());
            upload(GL_TEXTURE_2D, GLint(l), t["format"], img, img.width(), img.height(), 1);
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(files.size()) - 1);
        return id;
    };
    auto table = [&](const nlohmann::json& t) {
        const Image atlas = readImage((dir / t["file"].get<std::string>()).string());
        GLuint id = 0;
        glGenTextures(1, &id);
        glBindTexture(GL_TEXTURE_2D_ARRAY, id);
        upload(GL_TEXTURE_2D_ARRAY, 0, t["format"], atlas, t["width"].get<int>(), t["height"].get<int>(),
               t["layers"].get<int>());
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
        return id;
    };
    std::vector<GLuint> textures;
    for (const nlohmann::json& t : m["textures"])  // created on unit 0, then each bound to its own unit
        textures.push_back(t["kind"] == "table" ? table(t) : pyramid(t));
    for (size_t k = 0; k < textures.size(); ++k) {
        const nlohmann::json& t = m["textures"][k];
        glActiveTexture(GLenum(GL_TEXTURE0 + k));
        glBindTexture(t["kind"] == "table" ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, textures[k]);
        glUniform1i(glGetUniformLocation(prog, t["uniform"].get<std::string>().c_str()), GLint(k));
    }
    // The parameter block, at binding point 3 (not GpuGraph's 0, so only
    // this buffer can be read); a program without it (Godot's) has its
    // values as constants.
    const GLuint blockIndex = glGetUniformBlockIndex(prog, "PatternParameters");
    EXPECT_EQ(blockIndex == GL_INVALID_INDEX, fragment.find("PatternParameters") == std::string::npos);
    GLuint parameters = 0;
    if (blockIndex != GL_INVALID_INDEX) {
        GLint blockBytes = 0;
        glGetActiveUniformBlockiv(prog, blockIndex, GL_UNIFORM_BLOCK_DATA_SIZE, &blockBytes);
        const std::vector<std::uint8_t> block = parameterBlock(readText(dir / "README.md"), m, std::size_t(blockBytes));
        glGenBuffers(1, &parameters);
        glBindBuffer(GL_UNIFORM_BUFFER, parameters);
        glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(block.size()), block.data(), GL_STATIC_DRAW);
        glUniformBlockBinding(prog, blockIndex, 3);
        glBindBufferBase(GL_UNIFORM_BUFFER, 3, parameters);
    }
    auto loc = [&](const char* n) { return glGetUniformLocation(prog, n); };
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
    textures.push_back(target);
    glDeleteTextures(GLsizei(textures.size()), textures.data());
    glDeleteFramebuffers(1, &fbo);
    if (parameters) glDeleteBuffers(1, &parameters);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(prog);
    glDeleteShader(vs);
    glDeleteShader(fs_);
    return out;
}

// The export's stochtex.glsl in a GL 3.30 program whose fragments are `sample`.
Image renderFromExport(const fs::path& dir, int width, int height, double scale,
                       const std::string& sample = kSampleAtPixel) {
    return renderFragment(dir, width, height, scale,
                          "#version 330 core\n" + readText(dir / "stochtex.glsl") +
                              "uniform float uPixelScale;\nout vec4 colour;\nvoid main() { colour = " + sample +
                              "; }\n");
}

// The largest |export − render --gpu| over a 96 × 80 view at `scale`.
double exportDifference(GpuView& gpu, GlContext& ctx, const fs::path& dir, double scale) {
    View v;
    v.width = 96;
    v.height = 80;
    v.scale = scale;
    const Image reference = gpu.render(v);
    ctx.makeCurrent();
    const Image exported = renderFromExport(dir, v.width, v.height, scale);
    double maxDiff = 0;
    for (size_t i = 0; i < reference.data().size(); ++i)
        maxDiff = std::max(maxDiff, double(std::abs(reference.data()[i] - exported.data()[i])));
    return maxDiff;
}

// A plain pattern file's export (its program "two leaves → colormap"),
// loaded by a separate program as an engine would, renders what render
// --gpu renders: independent offsets with the smooth table in half floats
// (the default; table entries round by ≤ 2⁻¹², bilinear weights keep that
// bound), a quadrature pair (shared offsets) with the paper table in float
// (the same numbers as render --gpu). The README's file table names every
// file written, with its format.
TEST(Export, SeparateProgramRendersWhatRenderGpuRenders) {
    auto ctx = GlContext::headless();
    for (const char* name : {"camouflage", "phasor-stripes"}) {
        const PatternSpec spec = loadPreset(name);
        FilterOptions o;
        const bool half = std::string(name) == "camouflage";
        o.use(parseFilter(half ? "smooth" : "paper"));
        ExportOptions e;
        e.halfTable = half;
        const fs::path dir = test::scratchPath(std::string("stochtex_export_") + name);
        fs::remove_all(dir);
        exportPatternSpec(spec, o, dir.string(), e);
        for (const char* f : {"manifest.json", "stochtex.glsl", "README.md", "table_0.exr", "stats_0_0.exr"})
            EXPECT_TRUE(fs::exists(dir / f)) << f;
        const std::string readme = readText(dir / "README.md");
        const std::string fileTable = readme.substr(readme.find("## Files"));
        size_t written = 0;
        for (const auto& entry : fs::directory_iterator(dir)) {
            const std::string f = entry.path().filename().string();
            EXPECT_NE(fileTable.find("`" + f + "`"), std::string::npos) << f << " is not in the README's file table";
            ++written;
        }
        // 9 levels per leaf's pyramid (256²), no covariance pyramid (no lean op reads one), the
        // table, manifest, README and the five shader files (GLSL, HLSL, Unity, Godot's include and shader).
        EXPECT_EQ(written, 18u + 3u + 5u);
        // smooth: 10² layers of 256 rows, half floats; paper: 6² layers, floats.
        const std::string table = half ? "256 × 25600, 3 channels (R, G, B) of 16-bit half float"
                                       : "256 × 9216, 3 channels (R, G, B) of 32-bit float";
        EXPECT_NE(fileTable.find("| `table_0.exr` | OpenEXR, " + table), std::string::npos) << fileTable;
        EXPECT_NE(readme.find("`stats_0_8.exr` | OpenEXR, 256 × 256, 3 channels (R, G, B) of 32-bit float"),
                  std::string::npos);
        const std::unique_ptr<GpuView> gpu = makeGpuView(spec, *ctx, o);
        for (double scale : {1.0, 6.0}) {
            const double maxDiff = exportDifference(*gpu, *ctx, dir, scale);
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

// A texture graph's export (figure14, non-linear nodes before its output):
// its leaves' pyramids, its tables and its generated program, loaded by the
// same engine-side code, render what GpuGraph renders.
TEST(Export, GraphRendersWhatRenderGpuRenders) {
    auto ctx = GlContext::headless();
    const GraphPattern g = GraphPattern::build(loadPreset("figure14"));
    for (const bool half : {true, false}) {
        FilterOptions o;
        o.use(parseFilter(half ? "smooth" : "paper"));
        ExportOptions e;
        e.halfTable = half;
        const fs::path dir = test::scratchPath(std::string("stochtex_export_graph_") + (half ? "half" : "float"));
        fs::remove_all(dir);
        exportGraph(g, o, dir.string(), e);
        // 3 leaves of 9 levels (256²), 2 tables, manifest, README, the five shader files.
        size_t written = 0;
        const std::string readme = readText(dir / "README.md");
        for (const auto& entry : fs::directory_iterator(dir)) {
            EXPECT_NE(readme.find("`" + entry.path().filename().string() + "`"), std::string::npos)
                << entry.path().filename() << " is not in the README";
            ++written;
        }
        EXPECT_EQ(written, 3u * 9u + 2u + 2u + 5u);
        EXPECT_NE(readme.find("`uGraphPrefiltered1`"), std::string::npos);
        // The unfiltered path's samplers are named as ones that may stay unbound.
        EXPECT_NE(readme.find("also declares `uGraphExample0`"), std::string::npos) << readme;
        GpuGraph gpu(g, *ctx, o);
        for (double scale : {1.0, 6.0}) {
            const double maxDiff = exportDifference(gpu, *ctx, dir, scale);
            std::printf("[ info ] figure14 (%s table) at scale %g: max |export - render --gpu| %.2e\n",
                        half ? "half" : "float", scale, maxDiff);
            // Half floats only in the colour table (the field's (g, g²) table
            // stays float: a rounded g would cross the painted edges): entries
            // round by ≤ 2⁻¹² (measured 2.2e-4).
            EXPECT_LT(maxDiff, half ? 5e-4 : 1e-5) << "scale " << scale;
        }
        fs::remove_all(dir);
    }
}

// `bake` of a plain pattern file writes its program's export (as
// makeGpuView renders it): one pair of leaves, one table, the generated
// program; loaded by the engine-side code it renders what render --gpu does
// (the table in half floats, the default).
TEST(Export, PlainPatternFileExportsItsProgram) {
    auto ctx = GlContext::headless();
    const PatternSpec spec = loadPreset("camouflage");
    FilterOptions o;
    o.use(parseFilter("smooth"));
    const fs::path dir = test::scratchPath("stochtex_export_plain_program");
    fs::remove_all(dir);
    exportPatternSpec(spec, o, dir.string(), ExportOptions{});
    EXPECT_NE(readText(dir / "stochtex.glsl").find("vec3 filteredColour(vec2 uv, vec2 jx, vec2 jy)"),
              std::string::npos);
    EXPECT_NE(readText(dir / "README.md").find("`uGraphPrefiltered0`"), std::string::npos);
    const std::unique_ptr<GpuView> gpu = makeGpuView(spec, *ctx, o);
    for (double scale : {1.0, 6.0}) {
        const double maxDiff = exportDifference(*gpu, *ctx, dir, scale);
        std::printf("[ info ] camouflage at scale %g: max |export - render --gpu| %.2e\n", scale, maxDiff);
        EXPECT_LT(maxDiff, 5e-4) << "scale " << scale;  // half-float table entries (measured 1.1e-4)
    }
    fs::remove_all(dir);
}

// A graph with a lean node: its slope pair's covariance pyramid is exported
// and listed with its sampler, and the export renders what GpuGraph renders.
TEST(Export, LeanGraphExportsTheSlopesCovariance) {
    auto ctx = GlContext::headless();
    const std::string text = R"({"name": "lean-graph", "seed": 3, "nodes": {
        "h": {"type": "spectral_noise", "size": 64, "components": [{"shape": "bilobe", "frequency": 8, "bandwidth": 3, "orientation": 30}]},
        "a": {"type": "colormap", "x": "h", "y": "h", "colormap": {"type": "gaussian"}},
        "c": {"type": "lean", "height": "h", "albedo": "a", "specular": 0.3}}, "output": "c"})";
    const GraphPattern g = GraphPattern::build(parsePatternSpec(JsonReader(JsonReader::parse(text, "lg"), "lg"), "."));
    FilterOptions o;
    o.use(parseFilter("paper"));
    const fs::path dir = test::scratchPath("stochtex_export_lean_graph");
    fs::remove_all(dir);
    exportGraph(g, o, dir.string(), ExportOptions{});
    // 3 leaves and one covariance pyramid of 7 levels (64²), 1 table, manifest, README, the five shader files.
    size_t written = 0;
    for (const auto& entry : fs::directory_iterator(dir)) written += entry.is_regular_file();
    EXPECT_EQ(written, 4u * 7u + 1u + 2u + 5u);
    EXPECT_TRUE(fs::exists(dir / "covariance_1_0.exr"));
    EXPECT_NE(readText(dir / "README.md").find("`uGraphCov1`"), std::string::npos);
    GpuGraph gpu(g, *ctx, o);
    for (double scale : {1.0, 6.0}) {
        const double maxDiff = exportDifference(gpu, *ctx, dir, scale);
        std::printf("[ info ] lean graph at scale %g: max |export - render --gpu| %.2e\n", scale, maxDiff);
        // Two compilations of one program: the lobe's exponent (q ~ 10² for
        // a narrow lobe at one texel per pixel) turns their float rounding
        // into up to ~1e-4 (measured 2.1e-4 at scale 1, 1.0e-4 at 6).
        EXPECT_LT(maxDiff, 1e-3) << "scale " << scale;
    }
    fs::remove_all(dir);
}

// A lean program's include compiles and links in an engine's own program
// that lights it with its own light and eye (the globals its README names)
// before stochtex_sample.
TEST(Export, LeanProgramIncludeLinksLitByTheEnginesLight) {
    auto ctx = GlContext::headless();
    const GLuint vs =
        compile(GL_VERTEX_SHADER,
                "#version 330 core\nout vec2 uv;\nvoid main() { uv = vec2(0.5); gl_Position = vec4(0.0); }\n");
    const GraphPattern lean = GraphPattern::build(loadPreset("lean-ridges"), {ResponseKind::Lean});
    ASSERT_TRUE(lean.shadesLight());
    const GLuint fs_ = compile(GL_FRAGMENT_SHADER, "#version 330 core\n" + exportedGraphInclude(lean) +
                                                       "in vec2 uv;\nout vec4 colour;\n"
                                                       "void main() { gLightDirection = vec4(0.6, 0.0, 0.8, 1.0);\n"
                                                       "    gEyeDirection = vec3(0.0, 0.0, 1.0);\n"
                                                       "    colour = stochtex_sample(uv); }\n");
    const GLuint prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs_);
    glLinkProgram(prog);
    GLint linked = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &linked);
    char log[4096] = "";
    glGetProgramInfoLog(prog, sizeof log, nullptr, log);
    EXPECT_EQ(linked, GL_TRUE) << log;
    glDeleteProgram(prog);
    glDeleteShader(vs);
    glDeleteShader(fs_);
}

// The include's explicit-derivative entry point: given the footprint a
// fragment's derivatives give (uv = pixel · s, so ddx = (s, 0), ddy =
// (0, s)) it renders what stochtex_sample renders; given a footprint 8
// times as wide it renders another (blurrier) image, so the footprint is
// the arguments', not the fragment's.
TEST(Export, SampleGradTakesTheFootprintFromItsArguments) {
    auto ctx = GlContext::headless();
    FilterOptions o;
    o.use(parseFilter("smooth"));
    const fs::path dir = test::scratchPath("stochtex_export_grad");
    fs::remove_all(dir);
    exportPatternSpec(loadPreset("camouflage"), o, dir.string(), {});
    const std::string s = "(uPixelScale * uPattern.invExampleSize)";
    const auto grad = [&](const std::string& k) {
        return "stochtex_sample_grad(gl_FragCoord.xy * " + s + ", vec2(" + k + " * " + s + ", 0.0), vec2(0.0, " + k +
               " * " + s + "))";
    };
    const Image fragment = renderFromExport(dir, 64, 48, 3.0);
    const Image given = renderFromExport(dir, 64, 48, 3.0, grad("1.0"));
    const Image wider = renderFromExport(dir, 64, 48, 3.0, grad("8.0"));
    // Triplanar on the plane z = 0 facing +z: only the xy projection, the pattern at uv = (x, y).
    const Image planar = renderFromExport(
        dir, 64, 48, 3.0, "stochtex_sample_triplanar(vec3(gl_FragCoord.xy * " + s + ", 0.0), vec3(0.0, 0.0, 2.0))");
    double same = 0, changed = 0, triplanar = 0;
    for (size_t i = 0; i < fragment.data().size(); ++i) {
        same = std::max(same, double(std::abs(fragment.data()[i] - given.data()[i])));
        changed += std::abs(fragment.data()[i] - wider.data()[i]) / double(fragment.data().size());
        triplanar = std::max(triplanar, double(std::abs(fragment.data()[i] - planar.data()[i])));
    }
    std::printf(
        "[ info ] stochtex_sample_grad: max |Δ| %.2e with the fragment's derivatives, mean |Δ| %.3f at 8×; "
        "triplanar on a plane: max |Δ| %.2e\n",
        same, changed, triplanar);
    EXPECT_LT(same, 1e-5);
    EXPECT_GT(changed, 0.02);
    EXPECT_LT(triplanar, 1e-5);
    fs::remove_all(dir);
}

// The include is also Vulkan GLSL: compiled as `#version 450` for SPIR-V
// by the reference compiler (which defines VULKAN) and checked by
// spirv-val, for a plain pattern, a quadrature pair, a lean program and a
// graph; every sampler has its own binding after the block's 0, as
// manifest.json lists them.
TEST(Export, IncludeIsVulkanGlslWithABindingPerResource) {
    const fs::path dir = test::scratchPath("stochtex_export_vulkan");
    const auto run = [&](const std::string& command) {
        const int rc = std::system((command + " > " + (dir / "log.txt").string() + " 2>&1").c_str());
        return std::make_pair(rc, readText(dir / "log.txt"));
    };
    for (const char* name : {"camouflage", "phasor-stripes", "lean-ridges", "figure14"}) {
        fs::remove_all(dir);
        FilterOptions o;
        o.use(parseFilter("paper"));
        if (std::string(name) == "lean-ridges") o.response.kind = ResponseKind::Lean;
        // Two in the 8-bit format: its packed pyramids, codes and covariance coding compile too.
        ExportOptions e;
        if (std::string(name) == "lean-ridges" || std::string(name) == "figure14") e.format = ExportFormat::Rgba8;
        exportPatternSpec(loadPreset(name), o, dir.string(), e);
        std::ifstream mf(dir / "manifest.json");
        const nlohmann::json m = nlohmann::json::parse(mf);
        EXPECT_EQ(m["block_binding"], 0);
        std::set<int> bindings{0};
        const std::string include = readText(dir / "stochtex.glsl");
        for (const nlohmann::json& t : m["textures"]) {
            const int b = t["binding"].get<int>();
            EXPECT_TRUE(bindings.insert(b).second) << name << ": binding " << b << " twice";
            EXPECT_NE(include.find("STOCHTEX_BINDING(" + std::to_string(b) + ") uniform sampler"), std::string::npos);
        }
        std::ofstream(dir / "probe.frag") << "#version 450\n"
                                          << include
                                          << "layout(location = 0) in vec2 vUv;\n"
                                             "layout(location = 0) out vec4 colour;\n"
                                             "void main() { colour = stochtex_sample(vUv) + "
                                             "stochtex_sample_grad(vUv, vec2(0.01, 0.0), vec2(0.0, 0.01)) + "
                                             "stochtex_sample_triplanar(vec3(vUv, 1.0), vec3(0.0, 1.0, 0.0)); }\n";
        const auto [compiled, log] =
            run("glslangValidator -V " + (dir / "probe.frag").string() + " -o " + (dir / "probe.spv").string());
        EXPECT_EQ(compiled, 0) << name << ":\n" << log;
        const auto [valid, validLog] = run("spirv-val --target-env vulkan1.0 " + (dir / "probe.spv").string());
        EXPECT_EQ(valid, 0) << name << ":\n" << validLog;
    }
    fs::remove_all(dir);
}

// Runs a command, its output into `log`; (exit status, output).
std::pair<int, std::string> runLogged(const std::string& command, const fs::path& log) {
    const int rc = std::system(("(" + command + ") > " + log.string() + " 2>&1").c_str());
    return {rc, readText(log)};
}

// A pixel shader calling the entry points of stochtex.hlsl (a lean
// program's light set as a host would); with `triplanar` all four, else
// the two planar ones (glslang's HLSL front end inlines every call: the
// triplanar ones, three samples each, cost it seconds).
std::string hlslProbe(bool triplanar) {
    return std::string(
               "#include \"stochtex.hlsl\"\n"
               "float4 main(float2 uv : TEXCOORD0, float3 n : NORMAL) : SV_Target {\n"
               "    gLightDirection = float4(0.0, 0.6, 0.8, 1.0);\n"
               "    float3 p = float3(uv, 0.5);\n"
               "    return stochtex_sample(uv) + stochtex_sample_grad(uv, float2(0.01, 0.0), float2(0.0, 0.01))") +
           (triplanar
                ? " +\n        stochtex_sample_triplanar(p, n) + stochtex_sample_triplanar_grad(p, n, ddx(p), ddy(p))"
                : "") +
           ";\n}\n";
}
// The Unity file's Custom Function entry points, each precision.
constexpr const char* kUnityProbe = R"(#include "stochtex_unity.hlsl"
float4 main(float2 uv : TEXCOORD0, float3 n : NORMAL) : SV_Target {
    float3 p = float3(uv, 0.5), dx = float3(0.01, 0.0, 0.0), dy = float3(0.0, 0.01, 0.0);
    float4 a, b, c, d;
    half4 e, f, g, h;
    StochtexSample_float(uv, a);
    StochtexSampleGrad_float(uv, dx.xy, dy.xy, b);
    StochtexSampleTriplanar_float(p, n, c);
    StochtexSampleTriplanarGrad_float(p, n, dx, dy, d);
    StochtexSample_half(uv, e);
    StochtexSampleGrad_half(uv, dx.xy, dy.xy, f);
    StochtexSampleTriplanar_half(p, n, g);
    StochtexSampleTriplanarGrad_half(p, n, dx, dy, h);
    return a + b + c + d + float4(e + f + g + h);
}
)";

// The Godot include as GLSL ES 3.00: its uniforms' hints removed, its
// uniforms with defaults (this export's parameters) made constants.
std::string godotAsEs(const std::string& godot) {
    std::string out =
        "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
        "precision highp sampler2DArray;\n";
    const std::regex hinted(R"(^uniform (\w+) (\w+) : [^;]*;$)"), initialised(R"(^uniform (\w+) (\w+) = ([^;]*);$)");
    std::istringstream lines(godot);
    std::smatch m;
    for (std::string line; std::getline(lines, line);) {
        if (std::regex_match(line, m, hinted))
            line = "uniform " + m[1].str() + " " + m[2].str() + ";";
        else if (std::regex_match(line, m, initialised))
            line = "const " + m[1].str() + " " + m[2].str() + " = " + m[3].str() + ";";
        out += line + "\n";
    }
    return out;
}

// What Godot's shading language lacks, found in `godot`: one message per
// offending line (uniform blocks, layout qualifiers, precision statements,
// preprocessor version lines, stage in/out variables, mutable globals,
// prototypes, names starting with an underscore).
std::vector<std::string> godotViolations(const std::string& godot) {
    std::vector<std::string> out;
    const std::regex mutableGlobal(R"(^(\w+) (\w+)( = .*)?;$)"), prototype(R"(^\w+ \w+\(.*\);$)"),
        underscore(R"((^|[^\w])_\w)");
    std::istringstream lines(godot);
    for (std::string line; std::getline(lines, line);) {
        const std::string code = line.substr(0, line.find("//"));
        if (std::regex_search(code, underscore)) out.push_back("name starting with _: " + line);
        if (code.empty() || code[0] == ' ' || code[0] == '}' || code[0] == '{') continue;  // not top level
        for (const char* lacking : {"#version", "precision", "layout", "in ", "out "})
            if (code.rfind(lacking, 0) == 0) out.push_back(std::string(lacking) + ": " + line);
        if (code.rfind("uniform ", 0) == 0 && code.back() != ';') out.push_back("uniform block: " + line);
        if (std::regex_match(code, mutableGlobal)) out.push_back("mutable global: " + line);
        if (std::regex_match(code, prototype)) out.push_back("prototype: " + line);
    }
    return out;
}

// The engine flavours (engine_shaders.h), compiled by real compilers here:
// stochtex.hlsl and the Unity file by glslang's HLSL front end, each entry
// point called, to SPIR-V spirv-val accepts; the Godot include holds none of
// what Godot's language lacks and compiles as GLSL ES 3.00. They run the
// same program: the HLSL compiled and translated back to GLSL 3.30 by
// SPIRV-Cross, and the Godot include as ES 3.00, render what stochtex.glsl
// renders (independent offsets in float, a lean program and a graph in the
// 8-bit format; 2 texels per pixel).
TEST(Export, EngineFlavoursCompileAndRenderWhatTheGlslRenders) {
    auto ctx = GlContext::headless();
    const fs::path dir = test::scratchPath("stochtex_export_engines");
    const fs::path log = test::scratchPath("stochtex_export_engines.log");
    struct Case {
        const char* preset;
        ResponseKind response;
        ExportFormat format;
    };
    const Case cases[] = {{"camouflage", ResponseKind::PrefilteredColormap, ExportFormat::Float},
                          {"lean-ridges", ResponseKind::Lean, ExportFormat::Rgba8},
                          {"figure14", ResponseKind::PrefilteredColormap, ExportFormat::Rgba8}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.preset);
        fs::remove_all(dir);
        FilterOptions o;
        o.use(parseFilter("paper"));
        o.response.kind = c.response;
        ExportOptions e;
        e.format = c.format;
        exportPatternSpec(loadPreset(c.preset), o, dir.string(), e);
        // The entry points are the same wrappers for every program: the
        // triplanar ones and the Unity file's are compiled for the first.
        const bool everyEntryPoint = &c == &cases[0];
        std::ofstream(dir / "probe.hlsl") << hlslProbe(everyEntryPoint);
        std::ofstream(dir / "probe_unity.hlsl") << kUnityProbe;
        for (const std::string probe : {"probe", "probe_unity"}) {
            if (probe == "probe_unity" && !everyEntryPoint) continue;
            const fs::path spv = dir / (probe + ".spv");
            const auto [compiled, compileLog] = runLogged(
                "glslangValidator -D -V -S frag -e main " + (dir / (probe + ".hlsl")).string() + " -o " + spv.string(),
                log);
            EXPECT_EQ(compiled, 0) << probe << ":\n" << compileLog;
            const auto [valid, validLog] = runLogged("spirv-val --target-env vulkan1.0 " + spv.string(), log);
            EXPECT_EQ(valid, 0) << probe << ":\n" << validLog;
        }
        const std::string godot = readText(dir / "stochtex.gdshaderinc");
        for (const std::string& v : godotViolations(godot)) ADD_FAILURE() << "Godot lacks " << v;
        // The spatial shader: the include's text, after its shader_type line.
        const std::string shader = readText(dir / "stochtex.gdshader");
        EXPECT_NE(shader.find("\nshader_type spatial;\n"), std::string::npos);
        EXPECT_NE(shader.find(godot), std::string::npos);
        EXPECT_NE(shader.find("void fragment() {\n    ALBEDO = stochtex_sample(UV * stochtex_tiling).rgb;"),
                  std::string::npos);
        std::ofstream(dir / "godot_probe.frag")
            << godotAsEs(godot)
            << "in vec2 uv;\nin vec3 n;\nout vec4 colour;\nvoid main() {\n    vec3 p = vec3(uv, 0.5);\n"
               "    colour = stochtex_sample(uv) + stochtex_sample_grad(uv, vec2(0.01, 0.0), vec2(0.0, 0.01)) +\n"
               "        stochtex_sample_triplanar(p, n) + stochtex_sample_triplanar_grad(p, n, dFdx(p), dFdy(p));\n}\n";
        const auto [esOk, esLog] = runLogged("glslangValidator " + (dir / "godot_probe.frag").string(), log);
        EXPECT_EQ(esOk, 0) << esLog;

        std::ifstream mf(dir / "manifest.json");
        const float invExampleSize = 1.0f / nlohmann::json::parse(mf)["example_size"].get<float>();
        char inv[32];
        std::snprintf(inv, sizeof inv, "%.9g", double(invExampleSize));
        for (const double scale : {2.0}) {
            const int w = 64, h = 48;
            const Image glsl = renderFromExport(dir, w, h, scale);
            // HLSL → SPIR-V → GLSL 3.30; the combined samplers take the textures' names.
            char constant[64];
            std::snprintf(constant, sizeof constant, "static const float kPixelScale = %.9g;\n", scale);
            std::ofstream(dir / "round_trip.hlsl")
                << "#include \"stochtex.hlsl\"\n"
                << constant
                << "float4 main(float4 pos : SV_Position) : SV_Target {\n"
                   "    return stochtex_sample(pos.xy * kPixelScale * uPattern.invExampleSize);\n}\n";
            const auto [hlslOk, hlslLog] = runLogged(
                "glslangValidator -D -V -S frag -e main " + (dir / "round_trip.hlsl").string() + " -o " +
                    (dir / "round_trip.spv").string() + " && spirv-cross " + (dir / "round_trip.spv").string() +
                    " --version 330 --no-es --output " + (dir / "round_trip.glsl").string(),
                log);
            ASSERT_EQ(hlslOk, 0) << hlslLog;
            const std::string roundTrip = std::regex_replace(
                readText(dir / "round_trip.glsl"),
                std::regex(R"(SPIRV_Cross_Combined(\w+?)(SPIRV_Cross_DummySampler|sampler_\1))"), "$1");
            const Image fromHlsl = renderFragment(dir, w, h, scale, roundTrip);
            const Image fromGodot =
                renderFragment(dir, w, h, scale,
                               godotAsEs(godot) +
                                   "uniform float uPixelScale;\nout vec4 colour;\nvoid main() { colour = "
                                   "stochtex_sample(gl_FragCoord.xy * uPixelScale * " +
                                   inv + "); }\n");
            double hlslDiff = 0, godotDiff = 0, mean = 0;
            for (size_t i = 0; i < glsl.data().size(); ++i) {
                hlslDiff = std::max(hlslDiff, double(std::abs(glsl.data()[i] - fromHlsl.data()[i])));
                godotDiff = std::max(godotDiff, double(std::abs(glsl.data()[i] - fromGodot.data()[i])));
                mean += glsl.data()[i] / double(glsl.data().size());
            }
            std::printf("%s at %g texels per pixel: max |HLSL - GLSL| %.3g, max |Godot - GLSL| %.3g (mean %.3f)\n",
                        c.preset, scale, hlslDiff, godotDiff, mean);
            EXPECT_GT(mean, 0.02);  // something was drawn
            EXPECT_LE(hlslDiff, 1e-4) << scale;
            EXPECT_LE(godotDiff, 1e-4) << scale;
        }
    }
    fs::remove_all(dir);
    fs::remove(log);
}

// A unit sphere or the cube [-1, 1]³ ray-cast in a fragment shader (an
// orthographic camera looking down at a corner), textured by the export's
// triplanar entry point at half an example period per unit (the pattern's
// features several pixels wide, so neighbours correlate); uMode 1: the hard
// switch to the dominant projection (what blending avoids), 2: the blend
// weights. A miss is -1.
constexpr const char* kTriplanarShapes = R"(
uniform int uShape;  // 0: sphere, 1: cube
uniform int uMode;   // 0: stochtex_sample_triplanar, 1: dominant projection only, 2: weights
out vec4 colour;
bool castRay(vec2 pixel, out vec3 p, out vec3 n) {
    vec2 s = (pixel / kViewSize * 2.0 - 1.0) * vec2(kViewSize.x / kViewSize.y, 1.0) * 1.25;
    vec3 d = normalize(vec3(-0.9, -0.7, -1.1));
    vec3 right = normalize(cross(d, vec3(0.0, 1.0, 0.0))), up = cross(right, d);
    vec3 o = -4.0 * d + s.x * right + s.y * up;
    if (uShape == 0) {
        float b = dot(o, d), disc = b * b - (dot(o, o) - 1.0);
        if (disc < 0.0) return false;
        p = o + (-b - sqrt(disc)) * d;
        n = p;
        return true;
    }
    vec3 t0 = (-1.0 - o) / d, t1 = (1.0 - o) / d, tn = min(t0, t1), tf = max(t0, t1);
    float enter = max(max(tn.x, tn.y), tn.z);
    if (enter > min(min(tf.x, tf.y), tf.z)) return false;
    p = o + enter * d;
    n = enter == tn.x ? vec3(-sign(d.x), 0.0, 0.0) : enter == tn.y ? vec3(0.0, -sign(d.y), 0.0) : vec3(0.0, 0.0, -sign(d.z));
    return true;
}
void main() {
    vec3 p, n;
    bool hit = castRay(gl_FragCoord.xy, p, n);
    vec3 q = p * 0.5, dx = dFdx(q), dy = dFdy(q);
    if (!hit) {
        colour = vec4(-1.0);
    } else if (uMode == 2) {
        colour = vec4(triplanarWeights(n), 1.0);
    } else if (uMode == 1) {
        vec3 a = abs(n);
        colour = a.x >= a.y && a.x >= a.z ? stochtex_sample_grad(q.zy, dx.zy, dy.zy)
               : a.y >= a.z               ? stochtex_sample_grad(q.xz, dx.xz, dy.xz)
                                          : stochtex_sample_grad(q.xy, dx.xy, dy.xy);
    } else {
        colour = stochtex_sample_triplanar_grad(q, n, dx, dy);
    }
}
)";

// The triplanar variant draws a sphere and a cube without seams. On the
// sphere the projections blend: the mean colour difference of neighbouring
// pixels whose dominant projection differs (the pairs across a blend's
// middle) stays within that of neighbours inside one projection, where the
// hard switch to the dominant projection (measured too, so the measure is
// seen to catch a seam) jumps by the difference of unrelated pixels. On the
// cube each face is one projection and the change of projection is the
// crease itself: the pairs across an edge differ no more than unrelated
// pixels do, and the pixels along the edges have the faces' mean and spread
// (no line of pixels filtered with a wrong footprint).
TEST(Export, TriplanarDrawsASphereAndACubeWithoutSeams) {
    auto ctx = GlContext::headless();
    const fs::path dir = test::scratchPath("stochtex_export_triplanar");
    fs::remove_all(dir);
    FilterOptions o;
    o.use(parseFilter("paper"));
    exportPatternSpec(loadPreset("camouflage"), o, dir.string());
    const int w = 192, h = 160;
    const std::string source = "#version 330 core\nconst vec2 kViewSize = vec2(" + std::to_string(w) + ".0, " +
                               std::to_string(h) + ".0);\n" + readText(dir / "stochtex.glsl") + kTriplanarShapes;
    for (const int shape : {0, 1}) {
        const auto draw = [&](int mode) {
            std::string s = source;
            s.replace(s.find("uniform int uShape;"), 19, "const int uShape = " + std::to_string(shape) + ";");
            s.replace(s.find("uniform int uMode;"), 18, "const int uMode = " + std::to_string(mode) + ";");
            return renderFragment(dir, w, h, 1.0, s);
        };
        const Image blended = draw(0), hard = draw(1), weights = draw(2);
        // Pixels 2 or more from a miss (the 2 × 2 derivative quads stay on the surface).
        const auto inside = [&](int x, int y) {
            for (int j = y - 2; j <= y + 2; ++j)
                for (int i = x - 2; i <= x + 2; ++i)
                    if (i < 0 || j < 0 || i >= w || j >= h || weights.at(i, j, 0) < 0.0f) return false;
            return true;
        };
        const auto dominant = [&](int x, int y) {
            const float a = weights.at(x, y, 0), b = weights.at(x, y, 1), c = weights.at(x, y, 2);
            return a >= b && a >= c ? 0 : b >= c ? 1 : 2;
        };
        const auto largest = [&](int x, int y) {
            return std::max({weights.at(x, y, 0), weights.at(x, y, 1), weights.at(x, y, 2)});
        };
        const auto diff = [](const Image& img, int x0, int y0, int x1, int y1) {
            double d = 0;
            for (int c = 0; c < 3; ++c) d += std::abs(img.at(x0, y0, c) - img.at(x1, y1, c)) / 3.0;
            return d;
        };
        struct Mean {
            double sum = 0;
            int n = 0;
            void add(double v) { sum += v, ++n; }
            double value() const { return sum / std::max(n, 1); }
        };
        for (const Image* img : {&blended, &hard}) {
            Mean seam, interior, unrelated, seamGreen, interiorGreen, seamGreen2, interiorGreen2;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    if (!inside(x, y)) continue;
                    const bool pure = largest(x, y) > 0.97f;
                    for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                        if (!inside(x + dx, y + dy)) continue;
                        const double d = diff(*img, x, y, x + dx, y + dy);
                        if (dominant(x, y) != dominant(x + dx, y + dy)) {
                            seam.add(d);
                            const double g = img->at(x, y, 1);
                            seamGreen.add(g), seamGreen2.add(g * g);
                        } else if (pure && largest(x + dx, y + dy) > 0.97f) {
                            interior.add(d);
                            const double g = img->at(x, y, 1);
                            interiorGreen.add(g), interiorGreen2.add(g * g);
                        }
                    }
                    // An unrelated pixel: a few pattern features away.
                    const int ux = x + 23, uy = y + 17;
                    if (inside(ux, uy)) unrelated.add(diff(*img, x, y, ux, uy));
                }
            const double seamStd = std::sqrt(seamGreen2.value() - seamGreen.value() * seamGreen.value()),
                         interiorStd =
                             std::sqrt(interiorGreen2.value() - interiorGreen.value() * interiorGreen.value());
            const char* what = img == &blended ? "blended" : "hard switch";
            std::printf(
                "[ info ] %s, %s: mean |Δ| across the seams %.4f (%d pairs), inside %.4f (%d), unrelated "
                "%.4f; green along the seams %.3f ± %.3f, inside %.3f ± %.3f\n",
                shape == 0 ? "sphere" : "cube", what, seam.value(), seam.n, interior.value(), interior.n,
                unrelated.value(), seamGreen.value(), seamStd, interiorGreen.value(), interiorStd);
            ASSERT_GT(seam.n, 100);
            ASSERT_GT(interior.n, 1000);
            ASSERT_GT(unrelated.n, 1000);
            EXPECT_GT(unrelated.value(), 2.0 * interior.value());  // the measure has room to see a jump
            if (shape == 0 && img == &blended) {
                EXPECT_LT(seam.value(), 1.25 * interior.value());
            }
            if (shape == 0 && img == &hard) {
                EXPECT_GT(seam.value(), 1.5 * interior.value());
            }
            if (shape == 1) {
                EXPECT_LT(seam.value(), 1.15 * unrelated.value());
                EXPECT_LT(std::abs(seamGreen.value() - interiorGreen.value()), 0.25 * interiorStd);
                EXPECT_GT(seamStd, 0.75 * interiorStd);
                EXPECT_LT(seamStd, 1.33 * interiorStd);
            }
        }
    }
    fs::remove_all(dir);
}

// Each storage format renders within the accuracy kExportFormatAccuracy
// states (the export README's format table): against the float export with
// a float table, loaded by the same engine-side code, over presets of each
// kind (independent and shared offsets, a gaussianized marble, a lean
// response, a graph of two tables) at 1, 4 and 16 texels per pixel. The
// 8-bit format must also cost something measurable (its codes do differ)
// and store its data in under a third of the float export's (its table
// in half floats, the default) bytes.
TEST(ExportFormats, RenderWithinTheirStatedAccuracy) {
    auto ctx = GlContext::headless();
    struct Case {
        const char* preset;
        const char* filter;
        ResponseKind response;
    };
    const Case cases[] = {{"camouflage", "smooth", ResponseKind::PrefilteredColormap},
                          {"phasor-stripes", "paper", ResponseKind::PrefilteredColormap},
                          {"marble", "paper", ResponseKind::PrefilteredColormap},
                          {"lean-ridges", "paper", ResponseKind::Lean},
                          {"figure14", "smooth", ResponseKind::PrefilteredColormap}};
    const auto bytesIn = [](const fs::path& dir) {
        std::uintmax_t bytes = 0;
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".exr" || entry.path().extension() == ".png") bytes += entry.file_size();
        return bytes;
    };
    std::map<ExportFormat, double> worstMean;
    for (const Case& c : cases) {
        std::map<ExportFormat, std::uintmax_t> bytes;
        FilterOptions o;
        o.use(parseFilter(c.filter));
        o.response.kind = c.response;
        const PatternSpec spec = loadPreset(c.preset);
        const auto exportAs = [&](ExportFormat format, bool halfTable) {
            const fs::path dir = test::scratchPath(std::string("stochtex_format_") + c.preset + "_" +
                                                   enumName(kExportFormatNames, format) + (halfTable ? "h" : ""));
            fs::remove_all(dir);
            ExportOptions e;
            e.format = format;
            e.halfTable = halfTable;
            exportPatternSpec(spec, o, dir.string(), e);
            return dir;
        };
        const fs::path reference = exportAs(ExportFormat::Float, false);
        const std::array<double, 3> scales{1.0, 4.0, 16.0};
        std::vector<Image> expectedAt;
        for (const double scale : scales) expectedAt.push_back(renderFromExport(reference, 96, 80, scale));
        fs::remove_all(reference);
        for (const ExportFormatAccuracy& a : kExportFormatAccuracy) {
            const fs::path dir = exportAs(a.format, true);
            for (size_t k = 0; k < scales.size(); ++k) {
                const double scale = scales[k];
                const Image& expected = expectedAt[k];
                const Image got = renderFromExport(dir, 96, 80, scale);
                std::vector<double> diffs(got.data().size());
                for (size_t i = 0; i < diffs.size(); ++i)
                    diffs[i] = std::abs(double(got.data()[i]) - double(expected.data()[i]));
                const double mean = std::accumulate(diffs.begin(), diffs.end(), 0.0) / double(diffs.size());
                std::sort(diffs.begin(), diffs.end());
                const double maxDiff = diffs.back(), p99 = diffs[diffs.size() * 99 / 100];
                worstMean[a.format] = std::max(worstMean[a.format], mean);
                std::printf("[ info ] %s %s at scale %g: |%s - float| max %.2e, 99%% %.2e, mean %.2e\n", c.preset,
                            c.filter, scale, enumName(kExportFormatNames, a.format).c_str(), maxDiff, p99, mean);
                EXPECT_LE(p99, a.p99Error) << c.preset << " " << enumName(kExportFormatNames, a.format) << " " << scale;
                EXPECT_LE(maxDiff, a.maxError)
                    << c.preset << " " << enumName(kExportFormatNames, a.format) << " " << scale;
                EXPECT_LE(mean, a.meanError)
                    << c.preset << " " << enumName(kExportFormatNames, a.format) << " " << scale;
            }
            bytes[a.format] = bytesIn(dir);
            fs::remove_all(dir);
        }
        std::printf("[ info ] %s: data %ju bytes (8bit) vs %ju (float)\n", c.preset, bytes[ExportFormat::Rgba8],
                    bytes[ExportFormat::Float]);
        EXPECT_LT(3 * bytes[ExportFormat::Rgba8], bytes[ExportFormat::Float]) << c.preset;
    }
    EXPECT_GT(worstMean[ExportFormat::Rgba8], 1e-4) << "the 8-bit codes should cost something measurable";
}

}  // namespace
}  // namespace stochtex
