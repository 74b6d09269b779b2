// Per-function parity of the kernel (src/stochtex/kernel/*.glsl): each
// function runs on the GPU (a compute shader on whatever OpenGL the machine
// has; Mesa llvmpipe in CI) over ≥ 10⁴ random inputs and is compared with
// the same source compiled as C++. Integer results must match exactly;
// float results within the number of ulps stated in each test (0 where the
// operations are exactly rounded on both sides; log2 and sqrt-based lengths
// are the GPU's own approximations).
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "gl_test_context.h"
#include "stochtex/gpu/gl_objects.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/kernel/camera.h"
#include "stochtex/kernel/colour.h"
#include "stochtex/kernel/cube_map.h"
#include "stochtex/kernel/footprint.h"
#include "stochtex/kernel/graph_ops.h"
#include "stochtex/kernel/grid.h"
#include "stochtex/kernel/hash.h"
#include "stochtex/kernel/lean.h"
#include "stochtex/kernel/lookup.h"
#include "stochtex/kernel/marble.h"
#include "stochtex/kernel/moments.h"
#include "stochtex/kernel/sigma_levels.h"
#include "stochtex/noise/tiling_blending.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/ops/ops.h"

namespace stochtex {
namespace {

using namespace kernel;

constexpr int kItems = 1 << 14;  // random inputs per function

// Runs `body` (GLSL) once per item in a compute shader after the kernel
// files `chunks`. Each item reads `inWords` uvec4 words (word(k), wordf(k))
// and writes `outWords` (emit(k, uvec4), emitf(k, vec4)).
std::vector<uvec4> runOnGpu(const std::vector<std::string>& chunks, const std::string& body, int inWords, int outWords,
                            const std::vector<uvec4>& input,
                            std::vector<std::pair<std::string, std::string>> generated = {}) {
    const int items = int(input.size()) / inWords;
    const std::string harness =
        "layout(local_size_x = 64) in;\n"
        "layout(std430, binding = 0) readonly buffer Inputs { uvec4 inputWords[]; };\n"
        "layout(std430, binding = 1) writeonly buffer Outputs { uvec4 outputWords[]; };\n"
        "uniform uint uCount;\n"
        "uint gItem;\n"
        "uvec4 word(int k) { return inputWords[gItem * " +
        std::to_string(inWords) +
        "u + uint(k)]; }\n"
        "vec4 wordf(int k) { return uintBitsToFloat(word(k)); }\n"
        "void emit(int k, uvec4 v) { outputWords[gItem * " +
        std::to_string(outWords) +
        "u + uint(k)] = v; }\n"
        "void emitf(int k, vec4 v) { emit(k, floatBitsToUint(v)); }\n"
        "void main() {\n"
        "    gItem = gl_GlobalInvocationID.x;\n"
        "    if (gItem >= uCount) return;\n" +
        body + "\n}\n";
    std::vector<std::string> files = chunks;
    files.push_back("parity_harness");
    generated.emplace_back("parity_harness", harness);
    const gl::Program program(compileComputeProgram(files, generated));
    const gl::Buffer inputs = gl::newBuffer(), outputs = gl::newBuffer();
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, inputs.id());
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(input.size() * sizeof(uvec4)), input.data(), GL_STATIC_DRAW);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, inputs.id());
    std::vector<uvec4> output(size_t(items) * size_t(outWords), uvec4(0u));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, outputs.id());
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(output.size() * sizeof(uvec4)), nullptr, GL_DYNAMIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, outputs.id());
    glUseProgram(program.id());
    glUniform1ui(glGetUniformLocation(program.id(), "uCount"), GLuint(items));
    glDispatchCompute(GLuint((items + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(output.size() * sizeof(uvec4)), output.data());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return output;
}

uvec4 bits(vec4 v) {
    return uvec4(floatBitsToUint(v.x), floatBitsToUint(v.y), floatBitsToUint(v.z), floatBitsToUint(v.w));
}
vec4 floats(uvec4 w) {
    return vec4(uintBitsToFloat(w.x), uintBitsToFloat(w.y), uintBitsToFloat(w.z), uintBitsToFloat(w.w));
}

// Deterministic random inputs (the kernel's own hash, seeded per test).
struct Random {
    uint seed;
    uint counter = 0;
    uvec3 next() { return pcg3d(uvec3(counter++, seed, 0x9e3779b9u)); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * unitFloat(next().x); }
};

// Compares item by item: `cpu` gives the expected words of item i, `check`
// compares one item's words (GPU, CPU) and returns a failure message or "".
void compareItems(const std::vector<uvec4>& gpu, int outWords, const std::function<std::vector<uvec4>(int)>& cpu,
                  const std::function<std::string(const uvec4*, const uvec4*)>& check) {
    int failures = 0;
    for (int i = 0; i < int(gpu.size()) / outWords; ++i) {
        const std::vector<uvec4> expected = cpu(i);
        const std::string message = check(&gpu[size_t(i) * size_t(outWords)], expected.data());
        if (!message.empty() && ++failures <= 5) ADD_FAILURE() << "item " << i << ": " << message;
    }
    EXPECT_EQ(failures, 0);
}

std::string exactWords(const uvec4* g, const uvec4* c, int n) {
    for (int k = 0; k < n; ++k)
        if (g[k] != c[k])
            return "word " + std::to_string(k) + " differs: GPU (" + std::to_string(g[k].x) + ", " +
                   std::to_string(g[k].y) + ", " + std::to_string(g[k].z) + ", " + std::to_string(g[k].w) + "), C++ (" +
                   std::to_string(c[k].x) + ", " + std::to_string(c[k].y) + ", " + std::to_string(c[k].z) + ", " +
                   std::to_string(c[k].w) + ")";
    return "";
}

// For log2-based values: |Δ| within `units` ulps of max(1, |value|). The
// GPU's log2 has an absolute error of a few 2⁻²³ on [1, 2), which is many
// ulps of a result near 0 (e.g. log2Split of 0.86 = −1 + log2 1.72).
std::string closeLog(float g, float c, int units, const char* what) {
    const double tolerance = units * std::ldexp(std::max(1.0, double(std::abs(c))), -23);
    if (std::abs(double(g) - double(c)) <= tolerance) return "";
    return std::string(what) + ": GPU " + std::to_string(g) + ", C++ " + std::to_string(c) +
           " (|Δ| = " + std::to_string(std::abs(double(g) - double(c))) + " > " + std::to_string(tolerance) + ")";
}

class KernelParity : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::glContext().hasCompute()) GTEST_SKIP() << "no OpenGL 4.3 compute: " << test::glContext().describe();
    }
};

TEST_F(KernelParity, Pcg3dUnitFloatAndDeriveSeedAreBitExact) {
    Random r{1};
    std::vector<uvec4> in(kItems);
    for (auto& w : in) w = uvec4(r.next(), r.next().x);
    const auto gpu = runOnGpu({"hash"}, R"(
        uvec4 a = word(0);
        uvec3 h = pcg3d(a.xyz);
        emit(0, uvec4(h, deriveSeed(a.x, a.w)));
        emitf(1, vec4(unitFloat(a.x), unitFloat(a.w), 0.0, 0.0));)",
                              1, 2, in);
    compareItems(
        gpu, 2,
        [&](int i) {
            const uvec4 a = in[size_t(i)];
            return std::vector<uvec4>{uvec4(pcg3d(uvec3(a.x, a.y, a.z)), deriveSeed(a.x, a.w)),
                                      bits(vec4(unitFloat(a.x), unitFloat(a.w), 0.0f, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) { return exactWords(g, c, 2); });
}

TEST_F(KernelParity, TriangleGridStencilVerticesAndOffsetsAreBitExact) {
    // |uv| ≤ 64 periods, the default density and a random one.
    Random r{2};
    std::vector<uvec4> in(kItems);
    for (auto& w : in) w = bits(vec4(r.uniform(-64.0f, 64.0f), r.uniform(-64.0f, 64.0f), r.uniform(1.0f, 9.0f), 0.0f));
    for (int i = 0; i < kItems; i += 2) in[size_t(i)].z = floatBitsToUint(kernel::kDefaultGridDensity);
    const auto gpu = runOnGpu({"grid"}, R"(
        vec4 a = wordf(0);
        Stencil s = triangleGrid(a.xy, planeGrid(a.z));
        emit(0, uvec4(s.cell, uint(s.upper), 0u));
        emitf(1, vec4(s.w, 0.0));
        emit(2, uvec4(stencilVertex(s, 0), stencilVertex(s, 1)));
        emitf(3, vec4(tileOffset(stencilVertex(s, 2), 77u), tileOffset(s.cell, word(0).x)));)",
                              1, 4, in);
    compareItems(
        gpu, 4,
        [&](int i) {
            const vec4 a = floats(in[size_t(i)]);
            const Stencil s = triangleGrid(vec2(a.x, a.y), planeGrid(a.z));
            return std::vector<uvec4>{
                uvec4(s.cell.x, s.cell.y, uint(s.upper), 0u), bits(vec4(s.w, 0.0f)),
                uvec4(stencilVertex(s, 0), stencilVertex(s, 1)),
                bits(vec4(tileOffset(stencilVertex(s, 2), 77u), tileOffset(s.cell, in[size_t(i)].x)))};
        },
        [](const uvec4* g, const uvec4* c) { return exactWords(g, c, 4); });
}

TEST_F(KernelParity, BlendMeanAndVarianceAreBitExact) {
    Random r{3};
    std::vector<uvec4> in(size_t(kItems) * 3);
    for (size_t i = 0; i < in.size(); i += 3) {
        const Stencil s = blendStencil(uvec2(0u), r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f));
        in[i] = bits(vec4(s.w, r.uniform(0.0f, 1.0f)));
        in[i + 1] = bits(vec4(r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), 0.0f));
        in[i + 2] = bits(vec4(r.uniform(0.0f, 0.1f), r.uniform(0.0f, 0.1f), r.uniform(0.0f, 0.1f), 0.0f));
    }
    const auto gpu = runOnGpu({"grid"}, R"(
        vec4 w = wordf(0), e = wordf(1), v = wordf(2);
        emitf(0, vec4(blendMean(w.w, w.xyz, e.xyz), blendVariance(w.xyz, v.xyz), 0.0, 0.0));)",
                              3, 1, in);
    compareItems(
        gpu, 1,
        [&](int i) {
            const vec4 w = floats(in[size_t(i) * 3]), e = floats(in[size_t(i) * 3 + 1]),
                       v = floats(in[size_t(i) * 3 + 2]);
            const vec3 w3(w.x, w.y, w.z);
            return std::vector<uvec4>{bits(
                vec4(blendMean(w.w, w3, vec3(e.x, e.y, e.z)), blendVariance(w3, vec3(v.x, v.y, v.z)), 0.0f, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) { return exactWords(g, c, 1); });
}

// Random Jacobians: 2⁻¹² to 2⁴ uv per pixel (a thousandth of a texel to
// thousands of texels on a 256² example), any direction, anisotropy 1 to 64.
std::vector<uvec4> randomJacobians(uint seed) {
    Random r{seed};
    std::vector<uvec4> in(size_t(kItems) * 2);
    for (size_t i = 0; i < in.size(); i += 2) {
        const float major = std::exp2(r.uniform(-12.0f, 4.0f)), ratio = std::exp2(r.uniform(0.0f, 6.0f));
        const float angle = r.uniform(0.0f, 6.2831853f);
        const vec2 a(std::cos(angle), std::sin(angle)), b(-a.y, a.x);
        const bool swap = (i / 2) % 2 == 1;
        const vec2 jx = (swap ? b * (major / ratio) : a * major), jy = (swap ? a * major : b * (major / ratio));
        in[i] = bits(vec4(jx.x, jx.y, jy.x, jy.y));
        in[i + 1] = uvec4(1u + (r.next().x % 16u), 8u, 0u, 0u);  // K, maxLod
    }
    return in;
}

TEST_F(KernelParity, ProbeLayoutCountsAndAxesAreExactLodsWithinFourUlpsOfOne) {
    // The lod's integer part comes from the exponent bits, its fraction from
    // the GPU's log2 of the mantissa (llvmpipe: up to 3·2⁻²³ here).
    const std::vector<uvec4> in = randomJacobians(4);
    const auto gpu = runOnGpu({"footprint"}, R"(
        vec4 j = wordf(0);
        uvec4 p = word(1);
        ProbeLayout l = probeLayout(j.xy, j.zw, 256.0, int(p.x), int(p.y));
        emit(0, uvec4(uint(l.count), 0u, 0u, 0u));
        emitf(1, vec4(l.lod, l.axis, 0.0));)",
                              2, 2, in);
    compareItems(
        gpu, 2,
        [&](int i) {
            const vec4 j = floats(in[size_t(i) * 2]);
            const uvec4 p = in[size_t(i) * 2 + 1];
            const ProbeLayout l = probeLayout(vec2(j.x, j.y), vec2(j.z, j.w), 256.0f, int(p.x), int(p.y));
            return std::vector<uvec4>{uvec4(uint(l.count), 0u, 0u, 0u), bits(vec4(l.lod, l.axis, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) {
            std::string m = exactWords(g, c, 1);
            if (m.empty() && (g[1].y != c[1].y || g[1].z != c[1].z)) m = "axis differs";
            if (m.empty()) m = closeLog(floats(g[1]).x, floats(c[1]).x, 4, "lod");
            return m;
        });
}

TEST_F(KernelParity, Log2SplitHasAnExactIntegerPart) {
    Random r{5};
    std::vector<uvec4> in(kItems);
    for (auto& w : in)
        w = bits(vec4(std::exp2(r.uniform(-40.0f, 40.0f)), std::exp2(float(int(r.uniform(-20.0f, 20.0f)))), 0, 0));
    const auto gpu = runOnGpu({"footprint"},
                              "vec4 a = wordf(0); emitf(0, vec4(log2Split(a.x), log2Split(a.y), 0.0, 0.0));", 1, 1, in);
    compareItems(
        gpu, 1,
        [&](int i) {
            const vec4 a = floats(in[size_t(i)]);
            return std::vector<uvec4>{bits(vec4(log2Split(a.x), log2Split(a.y), 0.0f, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) {
            const vec4 gf = floats(g[0]), cf = floats(c[0]);
            if (std::floor(gf.x) != std::floor(cf.x)) return std::string("integer part differs");
            if (gf.y != cf.y) return std::string("a power of two is not exact");  // log2 of a mantissa of 1 is 0
            return closeLog(gf.x, cf.x, 4, "log2Split");
        });
}

TEST_F(KernelParity, ProbePositionsAndLevelsAreBitExact) {
    Random r{6};
    std::vector<uvec4> in(kItems);
    for (auto& w : in) {
        const uint count = 1u + r.next().x % 16u;
        w = uvec4(count, r.next().x % count, floatBitsToUint(r.uniform(0.0f, 9.0f)), 1u + r.next().x % 12u);
    }
    for (size_t i = 0; i < in.size(); i += 7) in[i].z = floatBitsToUint(float(i % 9));  // whole levels
    const auto gpu = runOnGpu({"footprint"}, R"(
        uvec4 a = word(0);
        ProbeLevels l = probeLevels(uintBitsToFloat(a.z), int(a.w), int(a.x));
        emit(0, uvec4(uint(l.l0), uint(l.l1), uint(isSingleTexel(int(a.x), l.frac)), 0u));
        emitf(1, vec4(l.frac, l.w0, l.w1, probePosition(int(a.y), int(a.x))));)",
                              1, 2, in);
    compareItems(
        gpu, 2,
        [&](int i) {
            const uvec4 a = in[size_t(i)];
            const ProbeLevels l = probeLevels(uintBitsToFloat(a.z), int(a.w), int(a.x));
            return std::vector<uvec4>{uvec4(uint(l.l0), uint(l.l1), uint(isSingleTexel(int(a.x), l.frac)), 0u),
                                      bits(vec4(l.frac, l.w0, l.w1, probePosition(int(a.y), int(a.x))))};
        },
        [](const uvec4* g, const uvec4* c) { return exactWords(g, c, 2); });
}

TEST_F(KernelParity, FootprintSumsAreBitExact) {
    // 1 to 32 weighted texel footprints per item (16 probes × 2 levels).
    Random r{7};
    constexpr int kTexels = 32;
    std::vector<uvec4> in(size_t(kItems) * (1 + 2 * kTexels));
    for (size_t i = 0; i < in.size(); i += 1 + 2 * kTexels) {
        const uint n = 1u + r.next().x % kTexels;
        in[i] = uvec4(n, 0u, 0u, 0u);
        for (uint k = 0; k < kTexels; ++k) {
            in[i + 1 + 2 * k] = bits(
                vec4(r.uniform(0.3f, 0.7f), r.uniform(0.3f, 0.7f), r.uniform(0.0f, 0.02f), r.uniform(0.0f, 0.02f)));
            in[i + 2 + 2 * k] = bits(vec4(r.uniform(-0.01f, 0.01f), 1.0f / float(n), 0.0f, 0.0f));
        }
    }
    const auto run = [](uint n, const std::function<vec4(int)>& w) {
        Moments m = momentsAbout(vec2(w(0).x, w(0).y));
        for (int k = 0; k < int(n); ++k) {
            const vec4 s = w(2 * k), c = w(2 * k + 1);
            m = momentsAdd(m, c.y, vec2(s.x, s.y), vec2(s.z, s.w), c.x);
        }
        return momentsResult(m);
    };
    const auto gpu = runOnGpu({"moments"}, R"(
        int n = int(word(0).x);
        Moments m = momentsAbout(wordf(1).xy);
        for (int k = 0; k < n; ++k) {
            vec4 s = wordf(1 + 2 * k), c = wordf(2 + 2 * k);
            m = momentsAdd(m, c.y, s.xy, s.zw, c.x);
        }
        FootprintMoments r = momentsResult(m);
        emitf(0, vec4(r.mean, r.var));
        emitf(1, vec4(r.cov, 0.0, 0.0, 0.0));)",
                              1 + 2 * kTexels, 2, in);
    compareItems(
        gpu, 2,
        [&](int i) {
            const size_t base = size_t(i) * (1 + 2 * kTexels);
            const FootprintMoments m = run(in[base].x, [&](int k) { return floats(in[base + 1 + size_t(k)]); });
            return std::vector<uvec4>{bits(vec4(m.mean, m.var)), bits(vec4(m.cov, 0.0f, 0.0f, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) { return exactWords(g, c, 2); });
}

TEST_F(KernelParity, SigmaLevelsPaperExactSmoothWithinFourUlpsOfOneAndLayerMixExact) {
    Random r{8};
    std::vector<uvec4> in(size_t(kItems) * 2);
    for (size_t i = 0; i < in.size(); i += 2) {
        in[i] = bits(vec4(std::exp2(r.uniform(-14.0f, 0.0f)), std::exp2(r.uniform(-14.0f, 0.0f)), r.uniform(0.0f, 1.0f),
                          r.uniform(0.0f, 1.0f)));
        in[i + 1] = uvec4(6u + r.next().x % 4u, 0u, 0u, 0u);
    }
    const auto gpu = runOnGpu({"sigma_levels"}, R"(
        vec4 a = wordf(0);
        int levels = int(word(1).x);
        LayerBlend p = layerBlend(a.xy, true, levels), s = layerBlend(a.xy, false, levels);
        emit(0, uvec4(p.k0, p.k1));
        emit(1, uvec4(s.k0, s.k1));
        emitf(2, vec4(p.f, s.f));
        vec3 c = layerMix(vec3(a.z), vec3(a.w), vec3(a.x), vec3(a.y), a.zw);
        emitf(3, vec4(c, sigmaLevelCoordinate(a.x, false, levels)));)",
                              2, 4, in);
    compareItems(
        gpu, 4,
        [&](int i) {
            const vec4 a = floats(in[size_t(i) * 2]);
            const int levels = int(in[size_t(i) * 2 + 1].x);
            const LayerBlend p = layerBlend(vec2(a.x, a.y), true, levels),
                             s = layerBlend(vec2(a.x, a.y), false, levels);
            const vec3 c = layerMix(vec3(a.z), vec3(a.w), vec3(a.x), vec3(a.y), vec2(a.z, a.w));
            return std::vector<uvec4>{uvec4(uvec2(p.k0), uvec2(p.k1)), uvec4(uvec2(s.k0), uvec2(s.k1)),
                                      bits(vec4(p.f, s.f)), bits(vec4(c, sigmaLevelCoordinate(a.x, false, levels)))};
        },
        [](const uvec4* g, const uvec4* c) {
            std::string m = exactWords(g, c, 1);  // paper: exact layers and weights
            if (m.empty() && (g[2].x != c[2].x || g[2].y != c[2].y)) m = "paper weights differ";
            if (m.empty() && (g[3].x != c[3].x || g[3].y != c[3].y || g[3].z != c[3].z)) m = "layerMix differs";
            if (m.empty()) {  // smooth: log2 of σ·256 (coordinates ≥ 1); the layer may differ only at a whole
                              // coordinate
                const vec4 gf = floats(g[2]), cf = floats(c[2]);
                m = closeLog(floats(g[3]).w, floats(c[3]).w, 4, "smooth coordinate");
                if (m.empty() && g[1] != c[1] && std::abs((float(g[1].x) + gf.z) - (float(c[1].x) + cf.z)) > 1e-6f)
                    m = "smooth layers differ away from a whole coordinate";
            }
            return m;
        });
}

TEST_F(KernelParity, BetaLevelCoordinatesWithinFourUlpsOfOneAndTheirLayersAway) {
    // Means across [−0.1, 1.1] (past the ends: the top level), deviations
    // 2⁻¹⁴…2 (some 0), paper and smooth, each axis Beta or not. One sqrt, two
    // divisions (GLSL rounds each within 3 ulps): coordinates within 4 ulps
    // of max(1, c); the layers may differ only at a whole coordinate.
    Random r{19};
    std::vector<uvec4> in(static_cast<size_t>(kItems) * 2);
    for (size_t i = 0; i < in.size(); i += 2) {
        in[i] = bits(vec4(r.uniform(-0.1f, 1.1f), r.uniform(-0.1f, 1.1f), std::exp2(r.uniform(-14.0f, 1.0f)),
                          i % 14 == 0 ? 0.0f : std::exp2(r.uniform(-14.0f, 1.0f))));
        in[i + 1] = uvec4(6u + r.next().x % 5u, r.next().x % 2u, r.next().x % 2u, r.next().x % 2u);
    }
    const auto gpu = runOnGpu({"sigma_levels"}, R"(
        vec4 a = wordf(0);
        uvec4 w = word(1);
        int levels = int(w.x);
        bool paper = w.y != 0u;
        LayerBlend b = tableLayerBlend(a.xy, a.zw, ivec2(w.zw), paper, levels);
        emit(0, uvec4(b.k0, b.k1));
        emitf(1, vec4(b.f, betaLevelCoordinate(a.x, a.z, paper, levels), betaLevelCoordinate(a.y, a.w, paper, levels)));)",
                              2, 2, in);
    compareItems(
        gpu, 2,
        [&](int i) {
            const vec4 a = floats(in[size_t(i) * 2]);
            const uvec4 w = in[size_t(i) * 2 + 1];
            const int levels = int(w.x);
            const bool paper = w.y != 0u;
            const LayerBlend b = tableLayerBlend(vec2(a.x, a.y), vec2(a.z, a.w), ivec2(w.z, w.w), paper, levels);
            return std::vector<uvec4>{uvec4(uvec2(b.k0), uvec2(b.k1)),
                                      bits(vec4(b.f, betaLevelCoordinate(a.x, a.z, paper, levels),
                                                betaLevelCoordinate(a.y, a.w, paper, levels)))};
        },
        [](const uvec4* g, const uvec4* c) {
            const vec4 gf = floats(g[1]), cf = floats(c[1]);
            std::string m = closeLog(gf.z, cf.z, 4, "x coordinate");
            if (m.empty()) m = closeLog(gf.w, cf.w, 4, "y coordinate");
            for (int k = 0; k < 2 && m.empty(); ++k)
                if (std::abs((float(g[0][k]) + gf[k]) - (float(c[0][k]) + cf[k])) > 1e-5f)
                    m = "layer blend of axis " + std::to_string(k) + " differs";
            return m;
        });
}

TEST_F(KernelParity, PlaneRayIsBitExact) {
    // Pixels of 1 to 2048-pixel views, tilts 0–89°, fields of view 1–150°.
    Random r{10};
    std::vector<uvec4> in(size_t(kItems) * 2);
    for (size_t i = 0; i < in.size(); i += 2) {
        const vec2 size(float(1u + r.next().x % 2048u), float(1u + r.next().x % 2048u));
        const float tilt = r.uniform(0.0f, 89.0f) * 0.017453293f, fov = r.uniform(1.0f, 150.0f) * 0.017453293f;
        in[i] = bits(vec4(std::floor(r.uniform(0.0f, size.x)) + 0.5f, std::floor(r.uniform(0.0f, size.y)) + 0.5f,
                          size.x, size.y));
        in[i + 1] = bits(vec4(std::exp2(r.uniform(-4.0f, 6.0f)), std::tan(0.5f * fov), std::sin(tilt), std::cos(tilt)));
    }
    const auto gpu = runOnGpu({"camera"}, R"(
        vec4 a = wordf(0), b = wordf(1);
        PlaneRay r = planeRay(a.xy, a.zw, b.x, b.y, b.z, b.w);
        emit(0, uvec4(uint(r.sky), 0u, 0u, 0u));
        emitf(1, vec4(r.texels, r.jx));
        emitf(2, vec4(r.jy, 0.0, 0.0));)",
                              2, 3, in);
    int sky = 0;
    compareItems(
        gpu, 3,
        [&](int i) {
            const vec4 a = floats(in[size_t(i) * 2]), b = floats(in[size_t(i) * 2 + 1]);
            const PlaneRay r = planeRay(vec2(a.x, a.y), vec2(a.z, a.w), b.x, b.y, b.z, b.w);
            sky += r.sky;
            return std::vector<uvec4>{uvec4(uint(r.sky), 0u, 0u, 0u), bits(vec4(r.texels, r.jx)),
                                      bits(vec4(r.jy, 0.0f, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) { return exactWords(g, c, 3); });
    EXPECT_GT(sky, kItems / 50);  // the horizon is in the sample
    EXPECT_LT(sky, kItems / 2);
}

// A cube face's texel directions (Cube A's rays, the panorama resampling):
// every face, texel centres of faces 1–2048 texels wide, bit-exact.
TEST_F(KernelParity, CubeFaceDirectionsAreBitExact) {
    Random r{12};
    std::vector<uvec4> in(kItems);
    for (uvec4& v : in) {
        const uint size = 1u + r.next().x % 2048u;
        const float s = (float(r.next().x % size) + 0.5f) / float(size),
                    t = (float(r.next().x % size) + 0.5f) / float(size);
        v = uvec4(r.next().x % 6u, floatBitsToUint(s), floatBitsToUint(t), 0u);
    }
    const auto gpu = runOnGpu({"cube_map"}, R"(
        uvec4 w = word(0);
        emitf(0, vec4(cubeFaceDirection(int(w.x), uintBitsToFloat(w.y), uintBitsToFloat(w.z)), 0.0));)",
                              1, 1, in);
    std::array<int, 6> faces{};
    compareItems(
        gpu, 1,
        [&](int i) {
            const uvec4 w = in[size_t(i)];
            ++faces[w.x];
            return std::vector<uvec4>{
                bits(vec4(cubeFaceDirection(int(w.x), uintBitsToFloat(w.y), uintBitsToFloat(w.z)), 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) { return exactWords(g, c, 1); });
    for (const int n : faces) EXPECT_GT(n, kItems / 8);  // every face is in the sample
}

// The view mappings (kernel/camera.glsl) run at each host's coordinate
// precision (kernel/coords.h): float on the GPU, double on the CPU. From the
// same float inputs the GPU's results are the CPU's within 3 ulps (float) of
// the sum of the magnitudes of their terms: the float rounding of each
// operation and nothing else (offsets up to 10⁴ texels, pixels up to 2048,
// scales 2⁻⁴–2⁶, W 64–1024, transforms with entries in [−2, 2]).
TEST_F(KernelParity, ViewMappingsMatchTheCpuWithinFloatRounding) {
    Random r{11};
    std::vector<uvec4> in(size_t(kItems) * 3);
    for (size_t i = 0; i < in.size(); i += 3) {
        in[i] = bits(vec4(std::floor(r.uniform(0.0f, 2048.0f)) + 0.5f, std::floor(r.uniform(0.0f, 2048.0f)) + 0.5f,
                          r.uniform(-1e4f, 1e4f), r.uniform(-1e4f, 1e4f)));
        in[i + 1] = bits(vec4(std::exp2(r.uniform(-4.0f, 6.0f)), std::ldexp(1.0f, -int(6 + r.next().x % 5u)),
                              float(1u + r.next().x % 2048u), float(1u + r.next().x % 2048u)));
        in[i + 2] =
            bits(vec4(r.uniform(-2.0f, 2.0f), r.uniform(-2.0f, 2.0f), r.uniform(-2.0f, 2.0f), r.uniform(-2.0f, 2.0f)));
    }
    const auto gpu = runOnGpu({"camera"}, R"(
        vec4 a = wordf(0), b = wordf(1), m = wordf(2);
        vec2 uv = zoomUv(a.xy, a.zw, b.x, b.y);
        emitf(0, vec4(uv, planeCentreTexel(b.zw, a.zw, b.x)));
        emitf(1, vec4(transformUv(uv, m.xy, m.zw, a.xy * b.y), transformVector(a.zw * b.y, m.xy, m.zw)));)",
                              3, 2, in);
    std::array<double, 8> bound{};  // the item's sums of |terms|, one per result
    compareItems(
        gpu, 2,
        [&](int i) {
            const vec4 a = floats(in[size_t(i) * 3]), b = floats(in[size_t(i) * 3 + 1]),
                       m = floats(in[size_t(i) * 3 + 2]);
            const coord2 p(a.x, a.y), offset(a.z, a.w), size(b.z, b.w), row0(m.x, m.y), row1(m.z, m.w);
            const double scale = b.x, invW = b.y;
            // The transforms take the GPU's uv (float) so that only their own rounding is compared.
            const vec4 g0 = floats(gpu[size_t(i) * 2]);
            const coord2 gpuUv(g0.x, g0.y), t = p * invW, v = offset * invW;
            const coord2 uv = zoomUv(p, offset, scale, invW), centre = planeCentreTexel(size, offset, scale);
            const coord2 moved = transformUv(gpuUv, row0, row1, t), vector = transformVector(v, row0, row1);
            for (int k = 0; k < 2; ++k) {
                bound[size_t(k)] = (std::abs(offset[k]) + std::abs(p[k] * scale)) * invW;
                bound[size_t(2 + k)] = std::abs(offset[k]) + std::abs(0.5 * size[k] * scale);
                const coord2 row = k == 0 ? row0 : row1;
                bound[size_t(4 + k)] = std::abs(row.x * gpuUv.x) + std::abs(row.y * gpuUv.y) + std::abs(t[k]);
                bound[size_t(6 + k)] = std::abs(row.x * v.x) + std::abs(row.y * v.y);
            }
            return std::vector<uvec4>{bits(vec4(float(uv.x), float(uv.y), float(centre.x), float(centre.y))),
                                      bits(vec4(float(moved.x), float(moved.y), float(vector.x), float(vector.y)))};
        },
        [&](const uvec4* g, const uvec4* c) -> std::string {
            for (int w = 0; w < 2; ++w)
                for (int k = 0; k < 4; ++k) {
                    const float gv = floats(g[w])[k], cv = floats(c[w])[k];
                    const double tolerance = 3.0 * std::ldexp(bound[size_t(4 * w + k)], -23);
                    if (!(std::abs(double(gv) - double(cv)) <= tolerance))
                        return "word " + std::to_string(w) + "[" + std::to_string(k) + "]: GPU " + std::to_string(gv) +
                               ", C++ " + std::to_string(cv) + " (|Δ| > " + std::to_string(tolerance) + ")";
                }
            return "";
        });
}

TEST_F(KernelParity, LookupAddressingAndBlendsAreBitExact) {
    // Periodic grids of 1…1024 texels at points of one period moved by a tile
    // offset; tables of 2…1024 entries at x ∈ [−0.2, 1.2] (both clamps).
    Random r{10};
    constexpr int kIn = 8;
    std::vector<uvec4> in(size_t(kItems) * kIn);
    for (size_t i = 0; i < in.size(); i += kIn) {
        in[i] = bits(vec4(r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f)));
        in[i + 1] = uvec4(1u << (r.next().x % 11u), 2u + r.next().x % 1023u, 2u + r.next().x % 1023u, 0u);
        in[i + 2] =
            bits(vec4(r.uniform(-0.2f, 1.2f), r.uniform(-0.2f, 1.2f), r.uniform(-1.0f, 1.0f), r.uniform(-1.0f, 1.0f)));
        for (size_t k = 3; k < 7; ++k)
            in[i + k] = bits(
                vec4(r.uniform(-1.0f, 1.0f), r.uniform(-1.0f, 1.0f), r.uniform(-1.0f, 1.0f), r.uniform(0.0f, 8.0f)));
        in[i + 7] = bits(vec4(r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), 0.0f));
    }
    const auto gpu = runOnGpu({"lookup"}, R"(
        vec4 a = wordf(0); uvec4 n = word(1); vec4 c = wordf(2); vec4 f = wordf(7);
        float w = float(n.x);
        vec2 t = vec2(periodicTexel(texelOfPoint(a.x, w), a.z * w, w), periodicTexel(texelOfPoint(a.y, w), a.w * w, w));
        PeriodicTaps k = periodicTaps(t, int(n.x));
        emitf(0, vec4(t, k.f));
        emit(1, uvec4(k.left, k.right));
        TableTap tx = tableTap(c.x, int(n.y)), ty = tableTap(c.y, int(n.z));
        emit(2, uvec4(uint(tx.i), uint(ty.i), floatBitsToUint(tx.t), floatBitsToUint(ty.t)));
        emitf(3, blendColumnsFirst(wordf(3), wordf(4), wordf(5), wordf(6), f.xy));
        emitf(4, blendRowsFirst(wordf(3), wordf(4), wordf(5), wordf(6), f.xy));
        emitf(5, vec4(blendEntries(c.z, c.w, f.z), 0.0, 0.0, 0.0));)",
                              kIn, 6, in);
    compareItems(
        gpu, 6,
        [&](int i) {
            const uvec4* item = &in[size_t(i) * kIn];
            const vec4 a = floats(item[0]), c = floats(item[2]), f = floats(item[7]);
            const uvec4 n = item[1];
            const float w = float(n.x);
            const vec2 t(periodicTexel(texelOfPoint(a.x, w), a.z * w, w),
                         periodicTexel(texelOfPoint(a.y, w), a.w * w, w));
            const PeriodicTaps k = periodicTaps(t, int(n.x));
            const TableTap tx = tableTap(c.x, int(n.y)), ty = tableTap(c.y, int(n.z));
            const vec4 e[4] = {floats(item[3]), floats(item[4]), floats(item[5]), floats(item[6])};
            return std::vector<uvec4>{bits(vec4(t, k.f)),
                                      uvec4(uvec2(k.left), uvec2(k.right)),
                                      uvec4(uint(tx.i), uint(ty.i), floatBitsToUint(tx.t), floatBitsToUint(ty.t)),
                                      bits(blendColumnsFirst(e[0], e[1], e[2], e[3], vec2(f.x, f.y))),
                                      bits(blendRowsFirst(e[0], e[1], e[2], e[3], vec2(f.x, f.y))),
                                      bits(vec4(blendEntries(c.z, c.w, f.z), 0.0f, 0.0f, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) { return exactWords(g, c, 6); });
}

// The sRGB pair (the window's encode): pow is the GPU's own approximation, so
// values agree within 1e-6 absolute (results in [0, 1]; an 8-bit code is
// 3.9e-3, a 16-bit code 1.5e-5); inputs cover both pieces and both clamps.
TEST_F(KernelParity, SrgbTransferPairWithin1e6) {
    Random r{11};
    std::vector<uvec4> in(kItems);
    for (auto& w : in)
        w = bits(vec4(r.uniform(-0.1f, 1.1f), r.uniform(0.0f, 0.0031308f), r.uniform(0.0f, 1.0f),
                      r.uniform(0.0f, 0.04045f)));
    const auto gpu = runOnGpu({"colour"}, R"(
        vec4 a = wordf(0);
        vec3 e = srgbFromLinear3(vec3(a.x, a.y, a.z));
        emitf(0, vec4(e.x, e.y, e.z, linearFromSrgb(a.z)));
        emitf(1, vec4(linearFromSrgb(a.x), linearFromSrgb(a.w), 0.0, 0.0));)",
                              1, 2, in);
    compareItems(
        gpu, 2,
        [&](int i) {
            const vec4 a = floats(in[size_t(i)]);
            const vec3 e = srgbFromLinear3(vec3(a.x, a.y, a.z));
            return std::vector<uvec4>{bits(vec4(e.x, e.y, e.z, kernel::linearFromSrgb(a.z))),
                                      bits(vec4(kernel::linearFromSrgb(a.x), kernel::linearFromSrgb(a.w), 0.0f, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) -> std::string {
            const vec4 g0 = floats(g[0]), c0 = floats(c[0]), g1 = floats(g[1]), c1 = floats(c[1]);
            for (int k = 0; k < 4; ++k) {
                if (std::abs(g0[k] - c0[k]) > 1e-6f)
                    return "word 0[" + std::to_string(k) + "]: GPU " + std::to_string(g0[k]) + ", C++ " +
                           std::to_string(c0[k]);
                if (std::abs(g1[k] - c1[k]) > 1e-6f)
                    return "word 1[" + std::to_string(k) + "]: GPU " + std::to_string(g1[k]) + ", C++ " +
                           std::to_string(c1[k]);
            }
            return "";
        });
}

// A random unit direction above the plane (z ≥ ~0.1 before normalising).
vec3 randomUpperDirection(Random& r) {
    const vec3 d(r.uniform(-1.0f, 1.0f), r.uniform(-1.0f, 1.0f), r.uniform(0.1f, 1.0f));
    return d / length(d);
}

// The LEAN lobe and shading (kernel/lean.glsl): exp2 and sqrt are the GPU's
// own approximations (a few ulps each), so values agree within 1e-5 of
// max(1, |value|) (the densities reach ~10³ for narrow lobes; a display code
// is 3.9e-3). Inputs: lobes with any roughness in [0.02, 0.5], covariances
// beyond the clamp at ±σ_x σ_y, slopes about the mean, directions above the
// plane.
TEST_F(KernelParity, LeanLobeAndShadingWithin1e5) {
    Random r{12};
    const auto direction = [&r] { return randomUpperDirection(r); };
    std::vector<uvec4> in;
    for (int i = 0; i < kItems; ++i) {
        const vec2 var(r.uniform(0.0f, 0.1f), r.uniform(0.0f, 0.1f));
        const float cov = r.uniform(-1.2f, 1.2f) * std::sqrt(var.x * var.y);
        const vec2 mean(r.uniform(-0.5f, 0.5f), r.uniform(-0.5f, 0.5f));
        in.push_back(bits(vec4(mean.x, mean.y, var.x, var.y)));
        in.push_back(
            bits(vec4(cov, r.uniform(0.02f, 0.5f), mean.x + r.uniform(-0.5f, 0.5f), mean.y + r.uniform(-0.5f, 0.5f))));
        const vec3 l = direction(), v = direction();
        in.push_back(bits(vec4(l.x, l.y, l.z, r.uniform(0.0f, 1.0f))));
        in.push_back(bits(vec4(v.x, v.y, v.z, r.uniform(0.0f, 1.0f))));
    }
    const auto gpu = runOnGpu({"lean"}, R"(
        vec4 a = wordf(0), b = wordf(1), c = wordf(2), d = wordf(3);
        LeanLobe lobe = leanLobe(a.xy, a.zw, b.x, b.y);
        vec3 rgb = leanShade(lobe, c.xyz, d.xyz, vec3(d.w), c.w);
        emitf(0, vec4(leanSlopeDensity(lobe, b.zw), rgb));)",
                              4, 1, in);
    compareItems(
        gpu, 1,
        [&](int i) {
            const vec4 a = floats(in[size_t(4 * i)]), b = floats(in[size_t(4 * i + 1)]),
                       c = floats(in[size_t(4 * i + 2)]), d = floats(in[size_t(4 * i + 3)]);
            const LeanLobe lobe = leanLobe(vec2(a.x, a.y), vec2(a.z, a.w), b.x, b.y);
            const vec3 rgb = leanShade(lobe, vec3(c.x, c.y, c.z), vec3(d.x, d.y, d.z), vec3(d.w), c.w);
            return std::vector<uvec4>{bits(vec4(leanSlopeDensity(lobe, vec2(b.z, b.w)), rgb.x, rgb.y, rgb.z))};
        },
        [](const uvec4* g, const uvec4* c) -> std::string {
            const vec4 gv = floats(g[0]), cv = floats(c[0]);
            for (int k = 0; k < 4; ++k)
                if (!(std::abs(gv[k] - cv[k]) <= 1e-5f * std::max(1.0f, std::abs(cv[k]))))
                    return "[" + std::to_string(k) + "]: GPU " + std::to_string(gv[k]) + ", C++ " +
                           std::to_string(cv[k]);
            return "";
        });
}

// The marble texture and its noises (kernel/marble.glsl): cos, sin and exp2
// are the GPU's own approximations, so values agree within 1e-5 (the noises
// at a given point), 1e-4 (the scaled layers: a rounding δl of l, a few
// 10⁻⁷, moves the noise coordinate p = x / 2^l by |p| ln 2 δl ≤ 3·10⁻⁵
// here, the noise by ≤ 3 times that) and 1e-3 for the marble, whose band
// phase multiplies the noise's error by b ≤ 10 (a display code is 3.9e-3). Cell noise is piecewise constant: points
// within 10⁻⁴ + 10⁻⁵|p| of a cell edge at either scale read are left out, since there one rounding of exp2 picks the
// neighbouring cell on one side only.
TEST_F(KernelParity, MarbleLayersWithin1e3AndNoisesWithin1e5) {
    Random r{13};
    std::vector<uvec4> in;
    const auto nearEdge = [](double v) { return std::abs(v - std::round(v)) < 1e-4 + 1e-5 * std::abs(v); };
    while (int(in.size()) < 2 * kItems) {
        const vec2 x(r.uniform(-300.0f, 300.0f), r.uniform(-300.0f, 300.0f));
        const float level = r.uniform(2.0f, 9.0f), amplitude = r.uniform(0.0f, 1.5f), t = r.uniform(0.0f, 2.0f);
        const float rate = r.uniform(-1.0f, 1.0f), frequency = r.uniform(0.0f, 0.05f);
        const int scaling = int(r.next().x % 3u);
        const uint seed = r.next().x;
        const Marble m{vec2(r.uniform(-0.2f, 0.2f), r.uniform(-0.2f, 0.2f)),
                       r.uniform(0.0f, 10.0f),
                       level,
                       amplitude,
                       frequency,
                       rate,
                       scaling,
                       seed};
        const double l = double(marbleLevel(m, x, t)), k = std::floor(l);
        bool edge = false;
        const auto cellEdge = [&](double level, uint cellSeed) {
            const vec2 phase = cellPhase(cellSeed);
            return nearEdge(x.x * std::exp2(-level) + phase.x) || nearEdge(x.y * std::exp2(-level) + phase.y);
        };
        if (scaling == kMarbleContinuous)
            edge = cellEdge(l, seed);
        else
            edge = cellEdge(k, deriveSeed(seed, uint(int(k)))) || cellEdge(k + 1, deriveSeed(seed, uint(int(k) + 1)));
        edge = edge || cellEdge(std::log2(32.0), seed);  // the direct cellNoise(x / 32) below
        if (edge) continue;
        in.push_back(bits(vec4(x.x, x.y, t, m.bandFrequency.x)));
        in.push_back(uvec4(floatBitsToUint(m.bandFrequency.y), floatBitsToUint(m.distortion), floatBitsToUint(level),
                           floatBitsToUint(amplitude)));
        in.push_back(uvec4(floatBitsToUint(frequency), floatBitsToUint(rate), uint(scaling), seed));
    }
    const auto gpu = runOnGpu({"marble"}, R"(
        vec4 a = wordf(0), b = wordf(1);
        uvec4 c = word(2);
        Marble m = Marble(vec2(a.w, b.x), b.y, b.z, b.w, uintBitsToFloat(c.x), uintBitsToFloat(c.y), int(c.z), c.w);
        vec2 x = a.xy;
        emitf(0, vec4(marbleValue(m, kMarbleLayerMarble, x, a.z), marbleValue(m, kMarbleLayerScaledNoise, x, a.z),
                      marbleValue(m, kMarbleLayerScalingOnly, x, a.z), marbleValue(m, kMarbleLayerBaseNoise, x, a.z)));
        emitf(1, vec4(gradientNoise(x * 0.03125, c.w), cellNoise(x * 0.03125, c.w), marbleLevel(m, x, a.z), 0.0));)",
                              3, 2, in);
    compareItems(
        gpu, 2,
        [&](int i) {
            const vec4 a = floats(in[size_t(3 * i)]), b = floats(in[size_t(3 * i + 1)]);
            const uvec4 c = in[size_t(3 * i + 2)];
            const Marble m{vec2(a.w, b.x), b.y, b.z, b.w, uintBitsToFloat(c.x), uintBitsToFloat(c.y), int(c.z), c.w};
            const vec2 x(a.x, a.y);
            return std::vector<uvec4>{
                bits(vec4(marbleValue(m, kMarbleLayerMarble, x, a.z), marbleValue(m, kMarbleLayerScaledNoise, x, a.z),
                          marbleValue(m, kMarbleLayerScalingOnly, x, a.z),
                          marbleValue(m, kMarbleLayerBaseNoise, x, a.z))),
                bits(vec4(gradientNoise(x * 0.03125f, c.w), cellNoise(x * 0.03125f, c.w), marbleLevel(m, x, a.z),
                          0.0f))};
        },
        [](const uvec4* g, const uvec4* c) -> std::string {
            const vec4 layers = floats(g[0]) - floats(c[0]), noises = floats(g[1]) - floats(c[1]);
            for (int k = 0; k < 4; ++k) {
                if (!(std::abs(layers[k]) <= (k == 0 ? 1e-3f : 1e-4f)))
                    return "layer " + std::to_string(k) + ": GPU " + std::to_string(floats(g[0])[k]) + ", C++ " +
                           std::to_string(floats(c[0])[k]);
                if (!(std::abs(noises[k]) <= 1e-5f))
                    return "noise " + std::to_string(k) + ": GPU " + std::to_string(floats(g[1])[k]) + ", C++ " +
                           std::to_string(floats(c[1])[k]);
            }
            return "";
        });
}

// What the texture-graph ops share (kernel/graph_ops.glsl) on random
// inputs: within 4 ulps of max(1, |value|), the room a fused multiply-add
// leaves (E[g²] − E[g]² cancels, so ulps of the result itself would be too
// strict).
TEST_F(KernelParity, GraphOperationsWithin4UlpsOfOne) {
    Random r{17};
    std::vector<uvec4> in;
    for (int i = 0; i < kItems; ++i) {
        const float mean = r.uniform(-1.0f, 2.0f);
        in.push_back(
            bits(vec4(r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), r.uniform(-1.0f, 2.0f))));
        in.push_back(
            bits(vec4(mean, mean * mean + r.uniform(-0.01f, 0.2f), r.uniform(-1.0f, 2.0f), r.uniform(-0.05f, 0.3f))));
    }
    const auto gpu = runOnGpu({"graph_ops"}, R"(
        vec4 c = wordf(0), m = wordf(1);
        emitf(0, vec4(graphChannel(c.xyz, kGraphChannelRed), graphChannel(c.xyz, kGraphChannelGreen),
                      graphChannel(c.xyz, kGraphChannelBlue), graphChannel(c.xyz, kGraphChannelLuminance)));
        emitf(1, vec4(momentEntry(c.w).xy, matchedMoments(vec3(m.x, m.y, 0.0))));
        emitf(2, vec4(momentSigma(m.zw), 0.0, 0.0, 0.0));)",
                              2, 3, in);
    compareItems(
        gpu, 3,
        [&](int i) {
            const vec4 c = floats(in[size_t(2 * i)]), m = floats(in[size_t(2 * i + 1)]);
            const vec3 rgb(c.x, c.y, c.z);
            const vec3 entry = momentEntry(c.w);
            const vec2 matched = matchedMoments(vec3(m.x, m.y, 0.0f));
            return std::vector<uvec4>{
                bits(vec4(graphChannel(rgb, kGraphChannelRed), graphChannel(rgb, kGraphChannelGreen),
                          graphChannel(rgb, kGraphChannelBlue), graphChannel(rgb, kGraphChannelLuminance))),
                bits(vec4(entry.x, entry.y, matched.x, matched.y)),
                bits(vec4(momentSigma(vec2(m.z, m.w)), 0.0f, 0.0f, 0.0f))};
        },
        [](const uvec4* g, const uvec4* c) -> std::string {
            for (int w = 0; w < 3; ++w)
                for (int k = 0; k < 4; ++k) {
                    const std::string m = closeLog(floats(g[w])[k], floats(c[w])[k], 4, "graph op");
                    if (!m.empty()) return "word " + std::to_string(w) + "[" + std::to_string(k) + "] " + m;
                }
            return "";
        });
}

// A host of the ops for the parity test (pattern/ops/op_host.h): tables
// that are known functions of where they are read, so that what an op
// computes around its lookups is compared, on both sides.
constexpr const char* kTestOpHost = R"(
#include "stochtex/pattern/ops/op_host.glsl"
vec3 opTable(OpContext ctx, vec2 xy) { return vec3(xy.x, xy.y, xy.x * xy.y + float(ctx.table)); }
vec3 opPrefiltered(OpContext ctx, vec2 xy, vec2 sigma) { return vec3(xy.x + sigma.x, xy.x * xy.x + sigma.y, xy.y); }
)";
struct TestOpTables final : OpTableLookup {
    vec3 point(int table, vec2 xy) const override { return vec3(xy.x, xy.y, xy.x * xy.y + float(table)); }
    vec3 prefiltered(int, vec2 xy, vec2 sigma) const override {
        return vec3(xy.x + sigma.x, xy.x * xy.x + sigma.y, xy.y);
    }
};

// Every op of the list (pattern/ops/ops.h), both entry points, on random
// inputs, parameters and contexts: the GLSL the GPU program includes and
// the C++ the CPU evaluator calls agree within 4 ulps of max(1, |value|),
// and the lean op, which goes through the LEAN lobe's exp2 and sqrt, within
// 1e-5 of max(1, |value|) as the lobe itself (LeanLobeAndShadingWithin1e5).
template <size_t I>
void checkOpParity() {
    using Op = std::tuple_element_t<I, OpList::Tuple>;
    using P = typename Op::Params;
    constexpr int floatsOfParams = int(sizeof(P) / sizeof(float));
    constexpr int paramWords = (floatsOfParams + 3) / 4;
    const bool lean = std::string(Op::kKernel) == "lean_op";
    SCOPED_TRACE(Op::kKernel);
    Random r{31 + uint32_t(I)};
    const auto direction = [&r] { return randomUpperDirection(r); };
    std::vector<uvec4> in;
    for (int i = 0; i < kItems; ++i) {
        // a, b, c: (value or mean, variance, z); the context: eye, light (w 0 or 1), covariance.
        const float va = r.uniform(0.0f, 0.1f), vb = r.uniform(0.0f, 0.1f);
        in.push_back(bits(vec4(r.uniform(-0.5f, 1.5f), va, r.uniform(0.0f, 1.0f), r.uniform(-0.5f, 1.5f))));
        in.push_back(bits(vec4(vb, r.uniform(0.0f, 1.0f), r.uniform(-0.5f, 1.5f), r.uniform(0.0f, 1.0f))));
        in.push_back(bits(
            vec4(r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f), r.uniform(-1.2f, 1.2f) * std::sqrt(va * vb), 0.0f)));
        const vec3 eye = direction(), light = direction();
        in.push_back(bits(vec4(eye, r.uniform(0.0f, 1.0f) < 0.5f ? 0.0f : 1.0f)));
        in.push_back(bits(vec4(light, 0.0f)));
        // The parameters: a lobe's roughness and weight, a unit light, a covariance flag, or factors.
        std::vector<float> p(size_t(paramWords) * 4, 0.0f);
        for (int k = 0; k < floatsOfParams; ++k) p[size_t(k)] = r.uniform(0.05f, 1.0f);
        if (lean) {
            const vec3 l = direction();
            p[2] = l.x, p[3] = l.y, p[4] = l.z;
            p[5] = r.uniform(0.0f, 1.0f) < 0.5f ? 0.0f : 1.0f;
        }
        for (int w = 0; w < paramWords; ++w)
            in.push_back(
                bits(vec4(p[size_t(4 * w)], p[size_t(4 * w + 1)], p[size_t(4 * w + 2)], p[size_t(4 * w + 3)])));
    }
    const int inWords = 5 + paramWords;
    std::string params = paramsStructName(Op::kKernel) + "(";
    for (int k = 0; k < floatsOfParams; ++k)
        params += (k ? ", " : "") + std::string("wordf(") + std::to_string(5 + k / 4) + ")." + "xyzw"[k % 4];
    params += ")";
    const std::string body = R"(
        vec4 w0 = wordf(0), w1 = wordf(1), w2 = wordf(2), e = wordf(3), l = wordf(4);
        vec3 a = vec3(w0.x, w0.y, 0.0), b = vec3(w0.w, w1.x, 0.0), c = vec3(w1.y, w1.z, w1.w);
        OpContext ctx = OpContext(2, e.xyz, vec4(l.xyz, e.w), w2.z);
        emitf(0, vec4(opPoint()" +
                             params + R"(, a, b, c, ctx), 0.0));
        emitf(1, vec4(opFiltered()" +
                             params + R"(, a, b, c, ctx), 0.0));)";
    const auto gpu = runOnGpu({"op_test_host", Op::kKernel}, body, inWords, 2, in, {{"op_test_host", kTestOpHost}});
    const TestOpTables tables;
    compareItems(
        gpu, 2,
        [&](int i) {
            const auto word = [&](int k) { return floats(in[size_t(inWords * i + k)]); };
            const vec4 w0 = word(0), w1 = word(1), w2 = word(2), e = word(3), l = word(4);
            const vec3 a(w0.x, w0.y, 0.0f), b(w0.w, w1.x, 0.0f), c(w1.y, w1.z, w1.w);
            OpContext ctx;
            ctx.table = 2;
            ctx.eye = vec3(e.x, e.y, e.z);
            ctx.light = vec4(l.x, l.y, l.z, e.w);
            ctx.slopeCov = w2.z;
            ctx.tables = &tables;
            float f[paramWords * 4];
            for (int k = 0; k < paramWords; ++k)
                for (int j = 0; j < 4; ++j) f[4 * k + j] = word(5 + k)[j];
            P p;
            std::memcpy(&p, f, sizeof p);
            return std::vector<uvec4>{bits(vec4(opPoint(p, a, b, c, ctx), 0.0f)),
                                      bits(vec4(opFiltered(p, a, b, c, ctx), 0.0f))};
        },
        [lean](const uvec4* g, const uvec4* c) -> std::string {
            for (int w = 0; w < 2; ++w)
                for (int k = 0; k < 3; ++k) {
                    const float gv = floats(g[w])[k], cv = floats(c[w])[k];
                    const std::string what = w == 0 ? "opPoint" : "opFiltered";
                    if (lean) {
                        if (!(std::abs(gv - cv) <= 1e-5f * std::max(1.0f, std::abs(cv))))
                            return what + " [" + std::to_string(k) + "]: GPU " + std::to_string(gv) + ", C++ " +
                                   std::to_string(cv);
                    } else if (const std::string m = closeLog(gv, cv, 4, what.c_str()); !m.empty()) {
                        return m + " [" + std::to_string(k) + "]";
                    }
                }
            return "";
        });
}

TEST_F(KernelParity, EveryOpMatchesTheCpu) {
    []<size_t... I>(std::index_sequence<I...>) { (checkOpParity<I>(), ...); }
    (std::make_index_sequence<std::tuple_size_v<OpList::Tuple>>{});
}

// The CPU's periodic grids keep a padded copy and vector loads; held here,
// bit for bit, to the kernel's taps and blend over the unpadded values (what
// the shaders fetch), through the tiling-and-blending scanline path.
TEST(KernelCpuPath, PeriodicGridsFollowTheKernelLookup) {
    Random r{11};
    for (const int w : {1, 2, 16, 64}) {
        Image values(w, w, 1), second(w, w, 1);
        for (int y = 0; y < w; ++y)
            for (int x = 0; x < w; ++x) {
                values.at(x, y) = r.uniform(0.0f, 1.0f);
                second.at(x, y) = r.uniform(0.0f, 1.0f);
            }
        // Examples have W ≥ 2; pyramid tops are 1×1, read through the pair
        // grid with the scanline path of a 2×2 example's noise.
        const auto example = std::make_shared<NoiseExample>(w >= 2 ? values : Image(2, 2, 1, 0.5f));
        const TilingBlendingNoise noise(example, 1234u);
        const BasicPeriodicGrid<2> pair({&values, &second});
        const auto kernelLookup = [&](const Image& img, vec2 p, vec2 o) {
            const float fw = float(w);
            const vec2 t(periodicTexel(texelOfPoint(p.x, fw), o.x * fw, fw),
                         periodicTexel(texelOfPoint(p.y, fw), o.y * fw, fw));
            const PeriodicTaps k = periodicTaps(t, w);
            const auto texel = [&](int x, int y) { return vec4(img.at(x, y), 0.0f, 0.0f, 0.0f); };
            return blendColumnsFirst(texel(k.left.x, k.left.y), texel(k.right.x, k.left.y), texel(k.left.x, k.right.y),
                                     texel(k.right.x, k.right.y), k.f)
                .x;
        };
        int mismatches = 0;
        for (int i = 0; i < kItems / 4; ++i) {
            const vec2 p(r.uniform(0.0f, 1.0f), r.uniform(0.0f, 1.0f));
            const BlendStencil s = triangleGrid(r.uniform(-8.0f, 8.0f), r.uniform(-8.0f, 8.0f));
            const auto offsets = noise.offsets(s);
            const auto pairs = noise.tileValues<2>(noise.tileRows(offsets, p.y, pair), p.x, pair);
            for (size_t t = 0; t < 3; ++t) {
                const vec2 o(offsets[t].x, offsets[t].y);
                mismatches += pairs[t][0] != kernelLookup(values, p, o);
                mismatches += pairs[t][1] != kernelLookup(second, p, o);
            }
            mismatches += pair.sample(p.x, p.y)[1] != kernelLookup(second, p, vec2(0.0f));
            if (w < 2) continue;
            const auto tiles = noise.tileValues<1>(noise.tileRows(offsets, p.y, example->grid()), p.x, example->grid());
            for (size_t t = 0; t < 3; ++t)
                mismatches += tiles[t][0] != kernelLookup(values, p, vec2(offsets[t].x, offsets[t].y));
            mismatches += example->grid().sampleBilinear(p.x, p.y) != kernelLookup(values, p, vec2(0.0f));
        }
        EXPECT_EQ(mismatches, 0) << "W = " << w;
    }
}

// The CPU colormap table reads RGBA vectors; held to the kernel's taps and
// blend over its entries, bit for bit, clamps included.
TEST(KernelCpuPath, ColormapTableFollowsTheKernelLookup) {
    Random r{12};
    Image entries(5, 7, 3);
    for (float& v : entries.data()) v = r.uniform(0.0f, 1.0f);
    const ColormapTable table(entries);
    int mismatches = 0;
    for (int i = 0; i < kItems; ++i) {
        const float x = r.uniform(-0.2f, 1.2f), y = r.uniform(-0.2f, 1.2f);
        const TableTap tx = tableTap(x, 5), ty = tableTap(y, 7);
        const auto e = [&](int di, int dj) {
            const Rgb c = table.entry(tx.i + di, ty.i + dj);
            return vec4(c[0], c[1], c[2], 0.0f);
        };
        const vec4 expected = blendRowsFirst(e(0, 0), e(1, 0), e(0, 1), e(1, 1), vec2(tx.t, ty.t));
        const Rgb got = table.sample(x, y);
        mismatches += got[0] != expected.x || got[1] != expected.y || got[2] != expected.z;
    }
    EXPECT_EQ(mismatches, 0);
}

// The CPU scanline path splits the skewed coordinate in double and then
// calls the kernel's blendStencil; held here to the kernel's float
// triangleGrid (what the shaders run) on the same inputs.
TEST(KernelCpuPath, ScanlineStencilMatchesTheKernelTriangleGrid) {
    Random r{9};
    int sameCell = 0, n = 0;
    double maxWeightError = 0;
    for (int i = 0; i < kItems; ++i) {
        const float u = r.uniform(-64.0f, 64.0f), v = r.uniform(-64.0f, 64.0f);
        const Stencil row = TriangleGridRow(v).stencil(u);
        const Stencil k = triangleGrid(vec2(u, v), kernel::planeGrid(kernel::kDefaultGridDensity));
        ++n;
        if (row.cell == k.cell && row.upper == k.upper) {
            ++sameCell;
            for (int c = 0; c < 3; ++c) maxWeightError = std::max(maxWeightError, double(std::abs(row.w[c] - k.w[c])));
        }
    }
    // Float uv on a 128-period-wide range: the skew loses up to ~1e-5 cells,
    // so only points that close to an edge may change triangle.
    EXPECT_GE(double(sameCell) / n, 0.999);
    EXPECT_LT(maxWeightError, 2e-4);
}

}  // namespace
}  // namespace stochtex
