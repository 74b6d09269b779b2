// The SIMD lanes of tiling and blending against the scalar kernel
// (TriangleGridRow + TilingBlendingNoise::blend, the reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>

#include "lane_targets.h"
#include "stochtex/core/floor.h"
#include "stochtex/kernel/estimate.h"
#include "stochtex/kernel/graph_ops.h"
#include "stochtex/kernel/sigma_levels.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/noise/tiling_blending_lanes.h"
#include "test_util.h"

using namespace stochtex;

namespace {

// The largest |lanes − scalar| over the rows of a zoom view (W texels per
// period, pixel p at (offset + (p + ½)·scale)/W).
double maxLaneError(const TilingBlendingNoise& noise, double offsetU, double offsetV, double scale, int width,
                    int rows) {
    const double invW = 1.0 / noise.example().size();
    GridRowLanes grid;
    std::vector<float> lanes(size_t(paddedLaneCount(width)));
    double worst = 0;
    for (int py = 0; py < rows; ++py) {
        const double v = (offsetV + (py + 0.5) * scale) * invW;
        grid.compute(offsetU, scale, invW, v, width);
        blendRowLanes(noise, grid, lanes.data());
        const TriangleGridRow row(v);
        for (int px = 0; px < width; ++px) {
            const double u = (offsetU + (px + 0.5) * scale) * invW;
            const float ref =
                noise.example().toOutput(noise.blend(row.stencil(u), periodFraction(u), periodFraction(v)));
            const double d = std::abs(double(lanes[size_t(px)]) - double(ref));
            worst = std::isnan(d) ? INFINITY : std::max(worst, d);  // a NaN on either side fails
        }
    }
    return worst;
}

}  // namespace

// Views near and far from the origin (where the grid's split needs double
// precision), zoomed in and out (texels read from a window one or two
// vectors wide, or gathered), a width that is no whole number of vectors,
// and a Gaussianized exemplar (T⁻¹ as a gathered table lookup). Tolerance:
// float rounding of values in [0, 1], as a target fusing a multiply and an
// add moves them (a few ulps of 1).
TEST(TilingBlendingLanes, AgreeWithTheScalarKernel) {
    const Image e = test::example(SpectrumShape::LowPass, 0.1, 0, 0, 7, 64);
    const auto plain = std::make_shared<NoiseExample>(e);
    const HistogramTransform t = HistogramTransform::fit(e);
    const auto gaussianized = std::make_shared<NoiseExample>(t.forward(e), t);
    test::forEachLaneTarget([&](const char*) {
        for (const auto& example : {plain, gaussianized}) {
            const TilingBlendingNoise noise(example, 1234u);
            SCOPED_TRACE(example->gaussianized() ? "gaussianized" : "plain");
            EXPECT_LE(maxLaneError(noise, 0.0, 0.0, 1.0, 131, 40), 1e-5);
            EXPECT_LE(maxLaneError(noise, -517.25, 93.5, 0.37, 77, 40), 1e-5);
            // Neighbouring pixels 1.6 texels apart: the two-vector window.
            EXPECT_LE(maxLaneError(noise, 11.0, -7.0, 1.6, 150, 40), 1e-5);
            EXPECT_LE(maxLaneError(noise, 3.0e7, -2.0e7, 6.3, 200, 40), 1e-5);
            EXPECT_LE(maxLaneError(noise, -1.0e9, 1.0e9, 1.0e4, 67, 8), 1e-5);  // at the view's limits
            EXPECT_LE(maxLaneError(noise, 5.0e8, -3.0e8, 1.0e6, 67, 8), 1e-5);
        }
    });
}

// Forcing a target reaches the dispatch; and by default the lanes run
// vectorised where the machine can (not Highway's emulated fallback).
TEST(TilingBlendingLanes, RunOnEveryTargetAndAVectorOneByDefault) {
    test::forEachLaneTarget([](const char* name) { EXPECT_STREQ(laneTargetName(), name); });
    const std::string target = laneTargetName();
    EXPECT_NE(target, "SCALAR");
    EXPECT_NE(target, "EMU128");
}

// The lanes' table taps are kernel::tableTap's, bit for bit, at values in
// and outside [0, 1], NaN (entry 0) and the ends; with stride 3 they read
// the first channel of vec3 rows; only whole vectors are done.
TEST(TilingBlendingLanes, TableTapsAreTheKernels) {
    test::forEachLaneTarget([](const char*) {
        for (const size_t stride : {size_t(1), size_t(3)}) {
            std::vector<float> x, y;
            for (int k = 0; k < 203; ++k) {
                const float a = float(k) / 173.0f - 0.1f, b = 1.05f - float(k * k % 211) / 199.0f;
                for (size_t c = 0; c < stride; ++c) {
                    x.push_back(c == 0 ? a : 1e30f);
                    y.push_back(c == 0 ? b : -1e30f);
                }
            }
            x[3 * stride] = std::nanf("");
            y[5 * stride] = 1.0f;
            const size_t count = x.size() / stride;
            std::vector<int32_t> entry(count, -1);
            std::vector<float> tx(count), ty(count);
            const int width = 37, height = 2;
            const size_t done =
                tableTapsLanes(x.data(), y.data(), stride, width, height, count, entry.data(), tx.data(), ty.data());
            EXPECT_LE(count - done, size_t(kMaxFloatLanes) - 1);
            for (size_t k = 0; k < done; ++k) {
                const kernel::TableTap a = kernel::tableTap(x[k * stride], width);
                const kernel::TableTap b = kernel::tableTap(y[k * stride], height);
                ASSERT_EQ(entry[k], b.i * width + a.i) << k;
                ASSERT_EQ(tx[k], a.t) << k;
                ASSERT_EQ(ty[k], b.t) << k;
            }
            for (size_t k = done; k < count; ++k) EXPECT_EQ(entry[k], -1) << "a tap past the whole vectors";
        }
    });
}

// The lanes' prefiltered-table lookups are kernel::tableLayerBlend's and
// kernel::tableTap's, on every target: the paper mode's levels and every
// tap bit for bit; the smooth mode's level coordinate (k0 + f) within 1e-5
// of the kernel's (the mantissa's log2 is Highway's: a few ulps of
// coordinates up to 9), its weights in [0, 1), and exactly the kernel's on
// a level. Deviations of 0, tiny, linear (σ·256 < 1), at and between
// levels, past the top, NaN and infinite; means outside [0, 1] and NaN;
// layer sizes that differ per level.
TEST(TilingBlendingLanes, LayerTapsAreTheKernels) {
    const int levels = 10;
    std::vector<int32_t> widths, heights;
    for (int k = 0; k < levels; ++k) {
        widths.push_back(256 >> std::min(k, 6));
        heights.push_back(2 + 3 * k);
    }
    std::vector<float> mx, my, sx, sy;
    // One call's worth less three: the last vector is partial, which the lanes leave.
    for (int k = 0; k < int(LayerTapsLanes::kCapacity) - 3; ++k) {
        mx.push_back(float(k) / 210.0f - 0.1f);
        my.push_back(0.5f + 0.6f * std::sin(0.37f * float(k)));
        sx.push_back(std::ldexp(float(1 + k % 17) / 17.0f, k % 23 - 12));  // σ·256 from 0.004 to 2^18
        sy.push_back(k % 9 == 0 ? 0.0f : std::ldexp(1.0f, k % 16 - 11));   // 0 and the levels themselves
    }
    mx[3] = std::nanf("");
    sx[4] = std::nanf("");
    sy[5] = INFINITY;
    sx[6] = 1e-30f;
    sy[7] = -0.25f;
    const size_t count = mx.size();
    test::forEachLaneTarget([&](const char*) {
        for (const bool paper : {true, false}) {
            SCOPED_TRACE(paper ? "paper" : "smooth");
            const auto owned = std::make_unique<LayerTapsLanes>();  // 14 KiB: not on the stack
            LayerTapsLanes& out = *owned;
            const size_t done = layerTapsLanes(mx.data(), my.data(), sx.data(), sy.data(), count, paper, levels,
                                               widths.data(), heights.data(), out);
            EXPECT_GE(done, count - size_t(kMaxFloatLanes) + 1);
            for (size_t k = 0; k < done; ++k) {
                const kernel::LayerBlend b = kernel::tableLayerBlend(
                    kernel::vec2(mx[k], my[k]), kernel::vec2(sx[k], sy[k]), kernel::ivec2(0, 0), paper, levels);
                if (paper) {
                    ASSERT_EQ(out.kx0[k], b.k0.x) << k;
                    ASSERT_EQ(out.ky0[k], b.k0.y) << k;
                    ASSERT_EQ(out.kx1[k], b.k1.x) << k;
                    ASSERT_EQ(out.ky1[k], b.k1.y) << k;
                    ASSERT_EQ(out.fx[k], b.f.x) << k;
                    ASSERT_EQ(out.fy[k], b.f.y) << k;
                } else {
                    ASSERT_NEAR(float(out.kx0[k]) + out.fx[k], float(b.k0.x) + b.f.x, 1e-5) << k;
                    ASSERT_NEAR(float(out.ky0[k]) + out.fy[k], float(b.k0.y) + b.f.y, 1e-5) << k;
                    ASSERT_LE(std::abs(out.kx0[k] - b.k0.x), 1) << k;
                    ASSERT_LE(std::abs(out.ky0[k] - b.k0.y), 1) << k;
                    for (const float f : {out.fx[k], out.fy[k]}) {
                        ASSERT_GE(f, 0.0f) << k;
                        ASSERT_LT(f, 1.0f) << k;
                    }
                    ASSERT_EQ(out.kx1[k], std::min(out.kx0[k] + 1, levels - 1)) << k;
                    ASSERT_EQ(out.ky1[k], std::min(out.ky0[k] + 1, levels - 1)) << k;
                    // On a level (σ = 0, 2^j/256, past the top) exactly the
                    // kernel's: a lookup there reads one layer.
                    if (b.f.x == 0.0f) {
                        ASSERT_TRUE(out.kx0[k] == b.k0.x && out.fx[k] == 0.0f) << k;
                    }
                    if (b.f.y == 0.0f) {
                        ASSERT_TRUE(out.ky0[k] == b.k0.y && out.fy[k] == 0.0f) << k;
                    }
                }
                // The taps in the sizes of the lanes' own layers.
                const auto tap = [&](float x, int32_t n, int32_t i, float t) {
                    const kernel::TableTap a = kernel::tableTap(x, n);
                    ASSERT_EQ(i, a.i) << k;
                    ASSERT_EQ(t, a.t) << k;
                };
                tap(mx[k], widths[size_t(out.kx0[k])], out.ix0[k], out.tx0[k]);
                tap(mx[k], widths[size_t(out.kx1[k])], out.ix1[k], out.tx1[k]);
                tap(my[k], heights[size_t(out.ky0[k])], out.iy0[k], out.ty0[k]);
                tap(my[k], heights[size_t(out.ky1[k])], out.iy1[k], out.ty1[k]);
                // The corners as the blend reads them.
                const int32_t w0 = widths[size_t(out.kx0[k])], w1 = widths[size_t(out.kx1[k])];
                ASSERT_EQ(out.width0[k], w0) << k;
                ASSERT_EQ(out.width1[k], w1) << k;
                ASSERT_EQ(out.entries00[k], w0 * heights[size_t(out.ky0[k])]) << k;
                ASSERT_EQ(out.layer00[k], out.kx0[k] * levels + out.ky0[k]) << k;
                ASSERT_EQ(out.layer10[k], out.kx1[k] * levels + out.ky0[k]) << k;
                ASSERT_EQ(out.layer01[k], out.kx0[k] * levels + out.ky1[k]) << k;
                ASSERT_EQ(out.layer11[k], out.kx1[k] * levels + out.ky1[k]) << k;
                ASSERT_EQ(out.entry00[k], out.iy0[k] * w0 + out.ix0[k]) << k;
                ASSERT_EQ(out.entry10[k], out.iy0[k] * w1 + out.ix1[k]) << k;
                ASSERT_EQ(out.entry01[k], out.iy1[k] * w0 + out.ix0[k]) << k;
                ASSERT_EQ(out.entry11[k], out.iy1[k] * w1 + out.ix1[k]) << k;
            }
        }
    });
}

// A probe's moments over two levels in lanes are the kernel's, bit for bit
// (NaN for NaN), on every target: means and variances of both levels with
// negative variances, a NaN and an infinity, where l1 weighs and where it
// does not (w1 = 0: l1's rows are not read, so theirs are NaN here).
TEST(TilingBlendingLanes, ProbeMomentsAreTheKernels) {
    const size_t count = 203;  // the last vector partial, which the lanes leave
    std::vector<float> meanLo, varLo, meanHi, varHi;
    for (size_t k = 0; k < count; ++k) {
        meanLo.push_back(0.5f + 0.45f * std::sin(0.31f * float(k)));
        meanHi.push_back(0.5f + 0.4f * std::cos(0.17f * float(k)));
        varLo.push_back(k % 11 == 0 ? -1e-4f : 0.02f * float(k % 7));
        varHi.push_back(k % 13 == 0 ? -1e-3f : 0.015f * float(k % 5));
    }
    meanLo[3] = std::nanf("");
    varHi[5] = std::nanf("");
    meanHi[8] = INFINITY;
    varLo[9] = 1e-30f;
    // The same bits (−0 is not 0), or both NaN.
    const auto same = [](float a, float b) {
        return (std::isnan(a) && std::isnan(b)) || std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);
    };
    test::forEachLaneTarget([&](const char*) {
        for (const auto& [w0, w1] : {std::pair{0.7f, 0.3f}, {0.35f, 0.65f}, {1.0f, 0.0f}}) {
            SCOPED_TRACE(w1);
            const std::vector<float> hiMean = w1 > 0 ? meanHi : std::vector<float>(count, std::nanf(""));
            const std::vector<float> hiVar = w1 > 0 ? varHi : std::vector<float>(count, std::nanf(""));
            std::vector<float> mean(count, -7.0f), sigma(count, -7.0f);
            const size_t done = probeMomentsLanes(meanLo.data(), varLo.data(), hiMean.data(), hiVar.data(), w0, w1,
                                                  count, mean.data(), sigma.data());
            EXPECT_GE(done, count - size_t(kMaxFloatLanes) + 1);
            kernel::ProbeLevels levels{};
            levels.w0 = w0;
            levels.w1 = w1;
            for (size_t k = 0; k < count; ++k) {
                if (k >= done) {
                    ASSERT_EQ(mean[k], -7.0f) << k;  // left to the caller
                    ASSERT_EQ(sigma[k], -7.0f) << k;
                    continue;
                }
                kernel::ProbeTexels t{};
                t.lo.mean = kernel::vec2(meanLo[k], 0.0f);
                t.lo.var = kernel::vec2(varLo[k], 0.0f);
                t.hi.mean = kernel::vec2(hiMean[k], 0.0f);
                t.hi.var = kernel::vec2(hiVar[k], 0.0f);
                const kernel::FootprintMoments r =
                    kernel::momentsResult(kernel::momentsAddProbe(kernel::momentsAbout(t.lo.mean), t, levels));
                ASSERT_PRED2(same, mean[k], r.mean.x) << k;
                ASSERT_PRED2(same, sigma[k], kernel::momentSigma(kernel::vec2(r.mean.x, std::max(r.var.x, 0.0f)))) << k;
            }
        }
    });
}
