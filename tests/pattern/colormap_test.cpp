#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>

#include "lane_targets.h"
#include "stochtex/image/image.h"
#include "stochtex/noise/tiling_blending_lanes.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "stochtex/pattern/presets.h"

using namespace stochtex;

// The GPU's prefiltered table is every layer resampled to the table's
// resolution: each entry exactly the layer's bilinear sample there (the
// separable resampling does the same float operations), for layers stored
// at the full resolution and coarser, in both modes, and at another size.
TEST(PrefilteredColormap, TheAtlasIsEachLayerSampledBilinearlyBitForBit) {
    Image table(97, 61, 3);
    for (int y = 0; y < table.height(); ++y)
        for (int x = 0; x < table.width(); ++x)
            for (int c = 0; c < 3; ++c)
                table.at(x, y, c) = float(0.5 + 0.5 * std::sin(0.37 * x + 0.91 * y + 2.1 * c) * std::cos(0.05 * x * y));
    const ColormapTable h(table);
    for (PrefilterMode mode : {PrefilterMode::Paper, PrefilterMode::Smooth}) {
        const PrefilteredColormap p(h, mode);
        const int n = int(p.sigmas().size());
        for (const auto& [rx, ry] : {std::pair{97, 61}, std::pair{40, 24}}) {
            const Image atlas = p.atlas(rx, ry);
            ASSERT_EQ(atlas.width(), rx);
            ASSERT_EQ(atlas.height(), ry * n * n);
            int coarser = 0, mismatches = 0;
            for (int l = 0; l < n * n; ++l) {
                const ColormapTable& t = p.layer(l / n, l % n);
                const bool full = t.resolutionX() == rx && t.resolutionY() == ry;
                coarser += !full;
                for (int j = 0; j < ry; ++j)
                    for (int i = 0; i < rx; ++i) {
                        const Rgb want =
                            full ? t.entry(i, j) : t.sample(float(i) / float(rx - 1), float(j) / float(ry - 1));
                        for (int c = 0; c < 3; ++c) mismatches += atlas.at(i, l * ry + j, c) != want[size_t(c)];
                    }
            }
            EXPECT_EQ(mismatches, 0) << "mode " << int(mode) << " at " << rx << "x" << ry;
            EXPECT_GT(coarser, 0);  // the resampling is exercised
        }
    }
}

TEST(Colormap, GaussianIsIdentityInXEverywhere) {
    const ColormapTable t = makeAnalyticColormap(AnalyticColormap::Gaussian, 256);
    for (float x : {0.0f, 0.013f, 0.25f, 0.5f, 0.777f, 1.0f})
        for (float y : {0.0f, 0.4f, 1.0f}) {
            const Rgb c = t.sample(x, y);
            EXPECT_NEAR(c[0], x, 1e-6f);
            EXPECT_EQ(c[0], c[1]);
            EXPECT_EQ(c[1], c[2]);
        }
    // Clamp to edge outside [0,1].
    EXPECT_NEAR(t.sample(-0.3f, 2.0f)[0], 0.0f, 1e-7f);
    EXPECT_NEAR(t.sample(1.7f, -1.0f)[0], 1.0f, 1e-7f);
}

TEST(Colormap, RidgedIsAbsoluteValue) {
    const ColormapTable t = makeAnalyticColormap(AnalyticColormap::Ridged, 256);
    for (float x : {0.0f, 0.1f, 0.3f, 0.7f, 0.95f, 1.0f}) EXPECT_NEAR(t.sample(x, 0.3f)[0], std::abs(2 * x - 1), 1e-5f);
    // Near the kink the table is within one cell of the exact value.
    EXPECT_NEAR(t.sample(0.5f, 0.5f)[0], 0.0f, 2.0f / 255.0f);
}

TEST(Colormap, PhasorProfiles) {
    EXPECT_NEAR(phasorProfile(PhasorProfile::Sine, std::numbers::pi / 2, 0.5), 1.0f, 1e-6f);
    EXPECT_NEAR(phasorProfile(PhasorProfile::Sine, 0.0, 0.5), 0.5f, 1e-6f);
    EXPECT_NEAR(phasorProfile(PhasorProfile::Sawtooth, 0.0, 0.5), 0.5f, 1e-6f);
    EXPECT_EQ(phasorProfile(PhasorProfile::Square, -3.0, 0.3), 1.0f);  // t ≈ 0.023 < duty
    EXPECT_EQ(phasorProfile(PhasorProfile::Square, 0.0, 0.3), 0.0f);   // t = 0.5 ≥ duty
    const ColormapTable t = makePhasorColormap(PhasorProfile::Sine, 0.5, 256);
    // Point straight above the centre: phase π/2 → 1; straight below → 0.
    EXPECT_NEAR(t.sample(0.5f, 0.9f)[0], 1.0f, 1e-3f);
    EXPECT_NEAR(t.sample(0.5f, 0.1f)[0], 0.0f, 1e-3f);
}

// A shape that covers the whole domain [0, 1]² gives its colour on every
// entry, the border and corner entries included: a border entry averages
// the part of its cell inside the domain, not the half outside it (which
// read 50 % background on the edges and 75 % at the corners).
TEST(Colormap, AShapeCoveringTheDomainGivesItsColourOnEveryEntry) {
    PaintedColormap p;
    p.background = {0, 0, 0};
    PaintedShape all;
    all.kind = PaintedShape::Kind::Rectangle;
    all.a = {0.0, 0.0};
    all.b = {1.0, 1.0};
    all.colour = {0.2f, 0.6f, 1.0f};
    p.shapes.push_back(all);
    for (const int supersampling : {1, 4}) {
        const Image t = p.rasterize(17, supersampling).table();
        for (int j = 0; j < t.height(); ++j)
            for (int i = 0; i < t.width(); ++i)
                for (int k = 0; k < 3; ++k)
                    ASSERT_NEAR(t.at(i, j, k), all.colour[size_t(k)], 1e-6f)
                        << i << ", " << j << " supersampling " << supersampling;
    }
    // A half plane x ≤ 0.5: the left border column is the shape's colour,
    // the right one the background's, whatever the supersampling.
    PaintedColormap half;
    half.background = {0, 0, 0};
    PaintedShape left;
    left.kind = PaintedShape::Kind::HalfPlane;
    left.a = {0.5, 0.5};
    left.setAngle(90);
    left.colour = {1, 1, 1};
    half.shapes.push_back(left);
    const Image h = half.rasterize(9, 4).table();
    for (int j = 0; j < 9; ++j) {
        EXPECT_EQ(h.at(0, j, 0), 1.0f) << j;
        EXPECT_EQ(h.at(8, j, 0), 0.0f) << j;
        EXPECT_NEAR(h.at(4, j, 0), 0.5f, 1e-6f) << j;  // the boundary halves the middle column's cell
    }
}

TEST(Colormap, PaintedShapesPutTheRightColourAtKnownPoints) {
    PaintedColormap p;
    p.background = {0.1f, 0.1f, 0.1f};
    auto add = [&](PaintedShape s, Rgb c) {
        s.colour = c;
        p.shapes.push_back(s);
    };
    PaintedShape half;
    half.kind = PaintedShape::Kind::HalfPlane;
    half.a = {0.5, 0.5};
    half.setAngle(90);  // boundary pointing up: its left side is x < 0.5
    add(half, {1, 0, 0});
    PaintedShape band;
    band.kind = PaintedShape::Kind::Band;
    band.a = {0.5, 0.2};
    band.setAngle(0);
    band.width = 0.1;
    add(band, {0, 1, 0});
    PaintedShape ring;
    ring.kind = PaintedShape::Kind::Ring;
    ring.a = {0.75, 0.75};
    ring.innerRadius = 0.1;
    ring.radius = 0.2;
    add(ring, {0, 0, 1});
    PaintedShape disc;
    disc.kind = PaintedShape::Kind::Disc;
    disc.a = {0.25, 0.8};
    disc.radius = 0.05;
    add(disc, {1, 1, 0});
    PaintedShape rect;
    rect.kind = PaintedShape::Kind::Rectangle;
    rect.a = {0.9, 0.0};
    rect.b = {1.0, 0.1};
    add(rect, {1, 0, 1});
    PaintedShape tri;
    tri.kind = PaintedShape::Kind::Polygon;
    tri.points = {{0.6, 0.4}, {0.8, 0.4}, {0.7, 0.5}};
    add(tri, {0, 1, 1});

    const std::vector<std::pair<std::array<double, 2>, Rgb>> probes = {
        {{0.2, 0.5}, {1, 0, 0}},             // half-plane
        {{0.8, 0.5}, {0.1f, 0.1f, 0.1f}},    // background
        {{0.3, 0.22}, {0, 1, 0}},            // band over the half-plane
        {{0.8, 0.17}, {0, 1, 0}},            // band on the background side
        {{0.75, 0.9}, {0, 0, 1}},            // ring
        {{0.75, 0.75}, {0.1f, 0.1f, 0.1f}},  // ring hole
        {{0.25, 0.8}, {1, 1, 0}},            // disc
        {{0.95, 0.05}, {1, 0, 1}},           // rectangle over band? (y=0.05 is outside band)
        {{0.7, 0.43}, {0, 1, 1}},            // polygon
        {{0.62, 0.48}, {0.1f, 0.1f, 0.1f}},  // beside the polygon
    };
    const ColormapTable table = p.rasterize(256, 4);
    for (const auto& [pt, want] : probes) {
        const Rgb exact = p.evaluate(pt[0], pt[1]);
        const Rgb tabled = table.sample(float(pt[0]), float(pt[1]));
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(exact[size_t(c)], want[size_t(c)]) << pt[0] << "," << pt[1];
            EXPECT_NEAR(tabled[size_t(c)], want[size_t(c)], 1e-5f) << pt[0] << "," << pt[1];
        }
    }
}

TEST(Colormap, ImagesAreYUp) {
    // An image whose top row is white: y = 1 must be white, y = 0 black.
    Image img(4, 4, 3, 0.0f);
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c) img.at(x, 0, c) = 1.0f;
    const ColormapTable t = ColormapTable::fromImage(img);
    EXPECT_EQ(t.sample(0.5f, 1.0f)[0], 1.0f);
    EXPECT_EQ(t.sample(0.5f, 0.0f)[0], 0.0f);
    EXPECT_EQ(t.toImage().data(), img.data());
}

TEST(Colormap, PresetLayoutsHaveThreeTouchingRegions) {
    // camouflage: three sectors meet at the centre (Fig. 3d / 8b).
    const PatternSpec spec = loadPreset("camouflage");
    const PaintedColormap& p = spec.colormap.painted;
    const Rgb left = p.evaluate(0.3, 0.6), right = p.evaluate(0.7, 0.6), bottom = p.evaluate(0.5, 0.3);
    EXPECT_NE(left, right);
    EXPECT_NE(right, bottom);
    EXPECT_NE(left, bottom);
}

// A row of lookups (taps in SIMD lanes, on every target) is sample's,
// bit for bit: contiguous values and the first channel of vec3 rows, with a
// tail that is no whole vector, values outside [0, 1] and NaN; nothing
// past the row is written.
TEST(Colormap, ARowOfLookupsIsSamplesBitForBit) {
    Image table(53, 29, 3);
    for (int y = 0; y < table.height(); ++y)
        for (int x = 0; x < table.width(); ++x)
            for (int c = 0; c < 3; ++c) table.at(x, y, c) = float(0.5 + 0.5 * std::sin(0.7 * x - 1.3 * y + c));
    const ColormapTable h(table);
    test::forEachLaneTarget([&](const char*) {
        // 301: the lanes leave a tail; 304 (19 vectors of 16): they end the row.
        for (const auto& [stride, count] : {std::pair<size_t, size_t>{1, 301}, {3, 301}, {1, 304}, {3, 304}}) {
            std::vector<float> x(count * stride, 7.0f), y(count * stride, -7.0f);
            for (size_t k = 0; k < count; ++k) {
                x[k * stride] = float(k) / 281.0f - 0.05f;
                y[k * stride] = 1.02f - float(k * 37 % 293) / 290.0f;
            }
            x[2 * stride] = std::nanf("");
            y[4 * stride] = -0.3f;
            y[9 * stride] = std::nanf("");
            // Four floats past the row, which no store may touch (the
            // pairs' blends store a pixel's four floats, its last three).
            std::vector<float> rgb(count * 3 + 4, -1.0f);
            h.sampleRow(x.data(), y.data(), stride, rgb.data(), count);
            for (size_t k = 0; k < count; ++k) {
                const Rgb c = h.sample(x[k * stride], y[k * stride]);
                for (int i = 0; i < 3; ++i) ASSERT_EQ(rgb[k * 3 + size_t(i)], c[size_t(i)]) << k << " " << stride;
            }
            for (size_t k = count * 3; k < rgb.size(); ++k) ASSERT_EQ(rgb[k], -1.0f) << k << " " << count;
        }
    });
}

// A 41×23 table of cosines, a different wave per channel: rows of lookups
// against single lookups.
static ColormapTable wavyTable() {
    Image table(41, 23, 3);
    for (int y = 0; y < table.height(); ++y)
        for (int x = 0; x < table.width(); ++x)
            for (int c = 0; c < 3; ++c) table.at(x, y, c) = float(0.5 + 0.5 * std::cos(0.9 * x + 0.4 * y * c));
    return ColormapTable(table);
}

// The layers' blur and the row lookups' blend run an AVX2 compilation where
// the lanes' target has 8 float lanes or more and a baseline one elsewhere
// (pattern/texel_pairs.h): the same IEEE operations per lane, so a table
// built on any lane target is the same, bit for bit.
TEST(PrefilteredColormap, EveryLaneTargetBuildsTheSameTable) {
    const ColormapTable h = wavyTable();
    for (const PrefilterMode mode : {PrefilterMode::Paper, PrefilterMode::Smooth}) {
        const PrefilteredColormap reference(h, mode);
        const size_t n = reference.sigmas().size();
        test::forEachLaneTarget([&](const char*) {
            const PrefilteredColormap p(h, mode);
            for (size_t kx = 0; kx < n; ++kx)
                for (size_t ky = 0; ky < n; ++ky) {
                    const ColormapTable& a = reference.layer(int(kx), int(ky));
                    const ColormapTable& b = p.layer(int(kx), int(ky));
                    ASSERT_EQ(a.resolutionX(), b.resolutionX());
                    ASSERT_EQ(a.resolutionY(), b.resolutionY());
                    const size_t bytes =
                        size_t(a.resolutionX()) * size_t(a.resolutionY()) * sizeof(ColormapTable::Texel);
                    ASSERT_EQ(std::memcmp(a.texels(), b.texels(), bytes), 0)
                        << "layer " << kx << "," << ky << ", mode " << int(mode);
                }
        });
    }
}

// A row of prefiltered lookups (found ahead, prefetched, in SIMD lanes on
// Gaussian axes) is sample's, on every lane target: bit for bit in the paper
// mode and with Beta axes, within 1e-5 in the smooth mode on Gaussian axes
// (the lanes' log2, a few ulps from std::log2, moves a level weight);
// deviations from 0 (one layer) through the largest level and beyond,
// means outside [0, 1], NaN, rows shorter than a vector, than the
// look-ahead, and longer than the lanes' chunk of 256.
TEST(PrefilteredColormap, ARowOfLookupsIsSamples) {
    const ColormapTable h = wavyTable();
    for (const PrefilterMode mode : {PrefilterMode::Paper, PrefilterMode::Smooth})
        for (const BetaAxes beta : {BetaAxes{false, false}, BetaAxes{true, false}, BetaAxes{true, true}}) {
            const PrefilteredColormap p(h, mode, beta);
            const bool exact = mode == PrefilterMode::Paper || beta[0] || beta[1];
            for (const size_t count : {size_t(3), size_t(250), size_t(600)}) {
                std::vector<float> mx(count), my(count), sx(count), sy(count);
                for (size_t k = 0; k < count; ++k) {
                    mx[k] = float(k) / float(count) * 1.2f - 0.1f;
                    my[k] = 0.5f + 0.45f * std::sin(0.3f * float(k));
                    // σ of 0, in the smooth mode's linear part (σ·256 < 1), at and between levels.
                    sx[k] = k % 7 == 0 ? 0.0f : k % 7 == 1 ? float(k % 5) / 1280.0f : 0.4f * float(k % 13) / 12.0f;
                    sy[k] = k % 5 == 0 ? 0.0f : 0.6f * float(k % 11) / 10.0f;
                }
                if (count > 2) {  // NaN means and deviations read as the kernel reads them
                    mx[1] = std::nanf("");
                    sy[2] = std::nanf("");
                }
                test::forEachLaneTarget([&](const char*) {
                    std::vector<float> rgb(count * 3, -1.0f);
                    const size_t inLanes = p.sampleRow(mx.data(), my.data(), sx.data(), sy.data(), rgb.data(), count);
                    // Gaussian axes in lanes (all but a row's last partial vector), Beta axes one at a time.
                    if (beta[0] || beta[1])
                        EXPECT_EQ(inLanes, 0u);
                    else
                        EXPECT_GE(inLanes + size_t(kMaxFloatLanes) - 1, count);
                    for (size_t k = 0; k < count; ++k) {
                        const Rgb c = p.sample(mx[k], my[k], sx[k], sy[k]);
                        for (size_t i = 0; i < 3; ++i) {
                            if (exact)
                                ASSERT_EQ(rgb[k * 3 + i], c[i]) << "pixel " << k << " of " << count << ", mode "
                                                                << int(mode) << ", beta " << beta[0] << beta[1];
                            else
                                ASSERT_NEAR(rgb[k * 3 + i], c[i], 1e-5) << "pixel " << k << " of " << count;
                        }
                    }
                });
            }
        }
}

// A row whose deviations are all 0 (a zoom at one texel per pixel) takes
// the first layer's row lookup: still sample's, bit for bit, in both modes,
// -0 and NaN means included; one nonzero σ sends the row the general way
// (σ on a level there, where the lanes' smooth level weights are exact).
TEST(PrefilteredColormap, ARowWithoutDeviationsIsSamples) {
    const ColormapTable h = wavyTable();
    for (const PrefilterMode mode : {PrefilterMode::Paper, PrefilterMode::Smooth}) {
        const PrefilteredColormap p(h, mode);
        for (const size_t count : {size_t(3), size_t(600)})
            for (const bool oneDeviation : {false, true}) {
                std::vector<float> mx(count), my(count), sx(count, 0.0f), sy(count, 0.0f);
                for (size_t k = 0; k < count; ++k) {
                    mx[k] = float(k) / float(count) * 1.2f - 0.1f;
                    my[k] = 0.5f + 0.45f * std::sin(0.3f * float(k));
                }
                sx[0] = -0.0f;
                mx[1] = std::nanf("");
                if (oneDeviation) sy[count - 1] = 4.0f / 256.0f;  // on a level: the lanes' log2 is exact there
                test::forEachLaneTarget([&](const char*) {
                    std::vector<float> rgb(count * 3, -1.0f);
                    const size_t inLanes = p.sampleRow(mx.data(), my.data(), sx.data(), sy.data(), rgb.data(), count);
                    EXPECT_GE(inLanes + size_t(kMaxFloatLanes) - 1, count);
                    for (size_t k = 0; k < count; ++k) {
                        const Rgb c = p.sample(mx[k], my[k], sx[k], sy[k]);
                        for (size_t i = 0; i < 3; ++i)
                            ASSERT_EQ(std::bit_cast<uint32_t>(rgb[k * 3 + i]), std::bit_cast<uint32_t>(c[i]))
                                << "pixel " << k << " of " << count << ", mode " << int(mode);
                    }
                });
            }
    }
}
