#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>

#include "stochtex/core/hash.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/noise/tiling_blending.h"
#include "test_util.h"

using namespace stochtex;

namespace {

Image lowpassExample(double cutoff, uint32_t seed, int size = 256) {
    return test::example(SpectrumShape::LowPass, cutoff, 0, 0, seed, size);
}

Image bilobeExample(double f, double theta, uint32_t seed) {
    return test::example(SpectrumShape::BiLobe, f, 2, theta, seed, 256);
}

// Mean and std of the tiled noise over a large area: 1024² samples at two
// texels apart cover 8×8 example periods (~750 tiles).
ChannelStats tiledStats(const TilingBlendingNoise& noise, int w) {
    double s = 0, s2 = 0;
    const int n = 1024;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double v = noise.evaluate((x + 0.5) * 2.0 / w + 3.7, (y + 0.5) * 2.0 / w - 11.2);
            s += v;
            s2 += v * v;
        }
    ChannelStats st;
    st.mean = s / (double(n) * n);
    st.stddev = std::sqrt(s2 / (double(n) * n) - st.mean * st.mean);
    return st;
}

}  // namespace

TEST(Hash, Pcg3dMatchesReferenceValues) {
    // Reference values computed independently (Python, uint32 arithmetic);
    // the GLSL port must reproduce these bit for bit.
    const UInt3 a = pcg3d({1, 2, 3});
    EXPECT_EQ(a.x, 0xfa9f79a6u);
    EXPECT_EQ(a.y, 0x48f2f44cu);
    EXPECT_EQ(a.z, 0x596f5ab1u);
    const UInt3 b = pcg3d({0xffffffffu, 7, 42});
    EXPECT_EQ(b.x, 0xe387d2d4u);
    EXPECT_EQ(b.y, 0x47aa5f4au);
    EXPECT_EQ(b.z, 0xd51ae662u);
}

TEST(TriangleGrid, WeightsAreVariancePreservingAndVerticesAdjacent) {
    for (int i = 0; i < 2000; ++i) {
        const UInt3 h = pcg3d({uint32_t(i), 17, 5});
        const double u = (unitFloat(h.x) - 0.5) * 40.0, v = (unitFloat(h.y) - 0.5) * 40.0;
        const BlendStencil s = triangleGrid(u, v);
        const float sum2 = s.w[0] * s.w[0] + s.w[1] * s.w[1] + s.w[2] * s.w[2];
        ASSERT_NEAR(sum2, 1.0f, 1e-5f);
        for (int k = 0; k < 3; ++k) ASSERT_GE(s.w[size_t(k)], 0.0f);
        // The three vertices form one lattice triangle.
        for (int a = 0; a < 3; ++a)
            for (int b = a + 1; b < 3; ++b) {
                const kernel::uvec2 va = kernel::stencilVertex(s, a), vb = kernel::stencilVertex(s, b);
                const int dx = int32_t(va.x - vb.x), dy = int32_t(va.y - vb.y);
                ASSERT_LE(std::abs(dx) + std::abs(dy), 2);
                ASSERT_TRUE(std::abs(dx) <= 1 && std::abs(dy) <= 1);
            }
    }
    // At a lattice vertex, that vertex's tile alone is seen.
    const BlendStencil at = triangleGrid(0.0, 0.0);
    EXPECT_NEAR(at.w[0], 1.0f, 1e-6f);
}

// The convention of docs/MATH.md, pinned by values worked out by hand. With
// ρ = 2√3, ρ·0.57735027 = 2 and ρ·1.15470054 = 4, so the skewed point is
// (x, y) = (ρu − 2v, 4v); cell = (⌊x⌋, ⌊y⌋) (ids modulo 2³²), fz = 1 − {x} − {y};
// lower triangle (fz > 0): vertices (0,0), (0,1), (1,0), weights ({fz}, {y}, {x});
// upper: (1,1), (1,0), (0,1), weights (−fz, 1 − {y}, 1 − {x}); then w /= ‖w‖.
TEST(TriangleGrid, MatchesTheDocumentedConventionAtHandComputedPoints) {
    struct Case {
        double u, v;
        uint32_t cellX, cellY;
        bool upper;
        std::array<float, 3> w;  // normalised
    };
    const Case cases[] = {
        // x = 0.34641016 − 0.1 = 0.24641016, y = 0.2, fz = 0.55358984;
        // w = (0.55358984, 0.2, 0.24641016) / 0.63810632.
        {0.1, 0.05, 0, 0, false, {0.86755110f, 0.31342739f, 0.38615847f}},
        // x = 0.86602540 − 0.4 = 0.46602540, y = 0.8, fz = −0.26602540;
        // w = (0.26602540, 0.2, 0.53397460) / 0.62920457.
        {0.25, 0.2, 0, 0, true, {0.42279637f, 0.31786165f, 0.84865023f}},
        // x = −1.03923048 + 0.2 = −0.83923048, y = −0.4: cell (−1, −1) wraps to
        // 2³² − 1; {x} = 0.16076952, {y} = 0.6, fz = 0.23923048;
        // w = (0.23923048, 0.6, 0.16076952) / 0.66564109.
        {-0.3, -0.1, 0xffffffffu, 0xffffffffu, false, {0.35939861f, 0.90138666f, 0.24152583f}},
        // x = 3.46410162 − 0.6 = 2.86410162, y = 1.2: cell (2, 1), fz = −0.06410162;
        // w = (0.06410162, 0.8, 0.13589838) / 0.81398857.
        {1.0, 0.3, 2, 1, true, {0.07875002f, 0.98281479f, 0.16695368f}},
    };
    for (const Case& c : cases) {
        // The CPU's double-precision split (one point and scanline) and the
        // kernel's float version (what the shaders run) must all hold it.
        const kernel::vec2 uv(float(c.u), float(c.v));
        const BlendStencil stencils[] = {triangleGrid(c.u, c.v), TriangleGridRow(c.v).stencil(c.u),
                                         kernel::triangleGrid(uv, kernel::planeGrid(kernel::kDefaultGridDensity))};
        for (const BlendStencil& s : stencils) {
            SCOPED_TRACE(testing::Message() << "uv = (" << c.u << ", " << c.v << "), path " << (&s - stencils));
            EXPECT_EQ(s.cell.x, c.cellX);
            EXPECT_EQ(s.cell.y, c.cellY);
            EXPECT_EQ(s.upper, c.upper);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(s.w[i], c.w[size_t(i)], 1e-6f) << "weight " << i;
            // Vertex i of the stencil is the vertex weight i belongs to.
            const uint32_t dx[2][3] = {{0, 0, 1}, {1, 1, 0}}, dy[2][3] = {{0, 1, 0}, {1, 0, 1}};
            for (int i = 0; i < 3; ++i) {
                const kernel::uvec2 vertex = kernel::stencilVertex(s, i);
                EXPECT_EQ(vertex.x, c.cellX + dx[c.upper][i]) << "vertex " << i;
                EXPECT_EQ(vertex.y, c.cellY + dy[c.upper][i]) << "vertex " << i;
            }
        }
    }
}

TEST(TilingBlending, MatchesEquationSevenAtAPoint) {
    auto ex = std::make_shared<const NoiseExample>(lowpassExample(8, 3, 64));
    const TilingBlendingNoise noise(ex, 77);
    const double u = 2.31, v = -0.77;
    const BlendStencil s = triangleGrid(u, v);
    double expected = ex->mean();
    for (int i = 0; i < 3; ++i) {
        const kernel::uvec2 vertex = kernel::stencilVertex(s, i);
        const TileOffset o = tileOffset(vertex.x, vertex.y, 77);
        const double su = u + o.x - std::floor(u + o.x), sv = v + o.y - std::floor(v + o.y);
        expected += s.w[size_t(i)] * (ex->sampleBilinear(float(su), float(sv)) - ex->mean());
    }
    EXPECT_NEAR(noise.evaluate(u, v), expected, 1e-5);
}

TEST(TilingBlending, IsContinuousAcrossTileBoundaries) {
    auto ex = std::make_shared<const NoiseExample>(lowpassExample(8, 4));
    const TilingBlendingNoise noise(ex, 9);
    // Walk ~8 example periods in steps of ~0.01 texel. The noise's own slope
    // moves it by < 0.002 per step; a seam would jump by a fraction of σ ≈ 0.17.
    const double step = 0.001 / 256.0;
    double prev = noise.evaluate(0.1, 0.3), maxJump = 0;
    for (int i = 1; i < 200000; ++i) {
        const double t = i * step;
        const double cur = noise.evaluate(0.1 + t * 10.0, 0.3 + t * 3.0);  // ~10.4 texels per period step
        maxJump = std::max(maxJump, std::abs(cur - prev));
        prev = cur;
    }
    EXPECT_LT(maxJump, 0.005);
}

TEST(TilingBlending, KeepsMeanAndStdOfGaussianExamples) {
    for (const Image& e : {lowpassExample(8, 11), bilobeExample(20, 30, 12), lowpassExample(16, 13)}) {
        auto ex = std::make_shared<const NoiseExample>(e);
        const ChannelStats want = channelStats(e);
        const ChannelStats got = tiledStats(TilingBlendingNoise(ex, 1234), e.width());
        EXPECT_NEAR(got.mean, want.mean, 0.03 * want.mean);
        EXPECT_NEAR(got.stddev, want.stddev, 0.03 * want.stddev);
    }
}

TEST(TilingBlending, GaussianizedExemplarKeepsItsHistogram) {
    // A thresholded noise: two plateaus, far from Gaussian.
    const Image base = lowpassExample(6, 21);
    Image e(base.width(), base.height(), 1);
    for (size_t i = 0; i < e.data().size(); ++i) {
        const float b = base.data()[i];
        e.data()[i] = b > 0.55f ? 0.75f + 0.5f * (b - 0.55f) : 0.2f + 0.3f * b;
    }
    const ChannelStats want = channelStats(e);
    HistogramTransform t = HistogramTransform::fit(e);
    auto ex = std::make_shared<const NoiseExample>(t.forward(e), t);
    const TilingBlendingNoise noise(ex, 99);
    const ChannelStats got = tiledStats(noise, e.width());
    EXPECT_NEAR(got.mean, want.mean, 0.03 * want.mean);
    EXPECT_NEAR(got.stddev, want.stddev, 0.03 * want.stddev);
    // The two plateaus survive: almost nothing falls in the gap between them.
    int gap = 0, total = 0;
    for (int i = 0; i < 100000; ++i) {
        const float v = noise.evaluate(i * 0.0137, i * 0.0071);
        gap += (v > 0.45f && v < 0.74f) ? 1 : 0;
        ++total;
    }
    EXPECT_LT(double(gap) / total, 0.03);
}

TEST(TilingBlending, DifferentOffsetSeedsGiveDifferentNoise) {
    auto ex = std::make_shared<const NoiseExample>(lowpassExample(8, 5, 64));
    const TilingBlendingNoise a(ex, 1), b(ex, 2);
    int differ = 0;
    for (int i = 0; i < 100; ++i) differ += a.evaluate(i * 0.37, i * 0.11) != b.evaluate(i * 0.37, i * 0.11);
    EXPECT_GT(differ, 90);
}
