#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/presets.h"
#include "test_util.h"

using namespace stochtex;

namespace {

Camera zoom(int size, double scale) {
    Camera c;
    c.view.width = c.view.height = size;
    c.view.scale = scale;
    c.view.offsetU = 17;
    c.view.offsetV = -5;
    return c;
}

FilterOptions options(const std::string& filter, int aniso = 1) {
    FilterOptions o;
    o.use(parseFilter(filter));
    o.aniso = aniso;
    return o;
}

// A table of w × h uniform random entries in [0, 1) (a linear congruential sequence from seed).
ColormapTable randomTable(int w, int h, uint32_t seed) {
    Image t(w, h, 3);
    for (float& v : t.data()) {
        seed = seed * 1664525u + 1013904223u;
        v = float(seed >> 8) / 16777216.0f;
    }
    return ColormapTable(t);
}

}  // namespace

TEST(PrefilteredColormap, EntriesEqualDirectNumericalConvolution) {
    const ColormapTable h = buildColormap(loadPreset("marble").colormap);
    for (PrefilterMode mode : {PrefilterMode::Paper, PrefilterMode::Smooth}) {
        const PrefilteredColormap p(h, mode);
        const auto& s = p.sigmas();
        for (size_t kx = 0; kx < s.size(); ++kx)
            for (size_t ky = 0; ky < s.size(); ky += 2) {
                if (s[kx] > 0.25 || s[ky] > 0.25) continue;  // keep the Riemann reference fine enough
                const ColormapTable& layer = p.layer(int(kx), int(ky));
                for (int k = 0; k < 3; ++k) {
                    const int i = (k * 37 + 5) % layer.resolutionX(), j = (k * 91 + 3) % layer.resolutionY();
                    const double mx = double(i) / (layer.resolutionX() - 1), my = double(j) / (layer.resolutionY() - 1);
                    const Rgb want = convolveColormapNumerically(h, mx, my, s[kx], s[ky], 1500);
                    const Rgb got = layer.entry(i, j);
                    for (int c = 0; c < 3; ++c)
                        ASSERT_NEAR(got[size_t(c)], want[size_t(c)], 2e-4) << "σ " << s[kx] << "," << s[ky];
                }
            }
    }
}

TEST(PrefilteredColormap, BetweenKeptEntriesTheBilinearReadIsWithinItsBound) {
    // A layer keeps fewer entries along an axis while σ spans at least 4 of
    // their spacings h. Read bilinearly, the exact blur f = H ∗ G_σ is then
    // off by at most h²/8 · |f''| along that axis, and |f''| ≤ J · max|G_σ'|
    // = J · 0.242/σ² for an edge of height J in H: 0.0019 J per axis at
    // h = σ/4, 0.0076 J at σ/2. Here at the middle of kept cells (where a
    // linear read is worst), against the numerical convolution, for tables
    // with sharp edges between flat regions (J ≤ 1 in linear colour).
    for (const char* preset : {"camouflage", "marble"}) {
        const ColormapTable h = buildColormap(loadPreset(preset).colormap);
        for (PrefilterMode mode : {PrefilterMode::Paper, PrefilterMode::Smooth}) {
            const PrefilteredColormap p(h, mode);
            const auto& s = p.sigmas();
            double worst = 0.0;
            int reduced = 0;
            for (size_t kx = 0; kx < s.size(); ++kx)
                for (size_t ky = 0; ky < s.size(); ++ky) {
                    if (s[kx] > 0.25 || s[ky] > 0.25) continue;  // keep the Riemann reference fine enough
                    const ColormapTable& layer = p.layer(int(kx), int(ky));
                    const int rx = layer.resolutionX(), ry = layer.resolutionY();
                    if (rx == h.resolutionX() && ry == h.resolutionY()) continue;
                    ++reduced;
                    for (int k = 0; k < 4; ++k) {
                        const double i = (k * 37 + 5) % (rx - 1) + (rx < h.resolutionX() ? 0.5 : 0.0);
                        const double j = (k * 91 + 3) % (ry - 1) + (ry < h.resolutionY() ? 0.5 : 0.0);
                        const double mx = i / (rx - 1), my = j / (ry - 1);
                        const Rgb want = convolveColormapNumerically(h, mx, my, s[kx], s[ky], 600);
                        const Rgb got = layer.sample(float(mx), float(my));
                        for (int c = 0; c < 3; ++c)
                            worst = std::max(worst, std::abs(double(got[size_t(c)]) - double(want[size_t(c)])));
                    }
                }
            std::printf("[ info ] %s %s: %d reduced layers, largest |bilinear - exact| %.2e\n", preset,
                        mode == PrefilterMode::Paper ? "paper" : "smooth", reduced, worst);
            EXPECT_GT(reduced, 0);
            EXPECT_LE(worst, 2 * 0.0019) << preset;
        }
    }
}

TEST(PrefilteredColormap, NonSquareTablesBlurEachAxisByItsOwnSigma) {
    // A 64×40 random table: x and y have different tap tables, and layers
    // blur x first or y first depending on which is cheaper — both orders
    // must give the exact separable convolution.
    const ColormapTable h = randomTable(64, 40, 12345);
    const PrefilteredColormap p(h, PrefilterMode::Smooth);
    const auto& s = p.sigmas();
    for (auto [kx, ky] : {std::pair{1, 5}, {5, 1}, {0, 4}, {4, 0}, {3, 3}}) {
        const ColormapTable& layer = p.layer(kx, ky);
        for (int k = 0; k < 3; ++k) {
            const int i = (k * 29 + 3) % layer.resolutionX(), j = (k * 17 + 5) % layer.resolutionY();
            const double mx = double(i) / (layer.resolutionX() - 1), my = double(j) / (layer.resolutionY() - 1);
            const Rgb want = convolveColormapNumerically(h, mx, my, s[size_t(kx)], s[size_t(ky)], 800);
            const Rgb got = layer.entry(i, j);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(got[size_t(c)], want[size_t(c)], 5e-4) << "levels " << kx << "," << ky;
        }
    }
}

TEST(FilterOptions, TheDefaultEstimatorIsTheFirstOfTheNames) {
    // The studies' main columns are the default estimator's and add one per
    // name after the first (Figures 4, 11, 14, Table 1).
    EXPECT_EQ(kVarianceEstimatorNames.front().second, FilterOptions{}.estimator);
    EXPECT_EQ(kVarianceEstimatorNames.front().first, "paper");
}

TEST(PrefilteredColormap, BetaAxisLayersAverageTheTableUnderTheBetaOfTheirLevel) {
    // A 64×40 random table with a Beta x axis: layer (kx, 0) at entry (i, j)
    // is E[T(X, y_j)] for X ~ Beta of mean m_i = i/63 and shape τ = level kx
    // (deviation 2τ√(m(1 − m))), against a quadrature over the Beta's
    // quantiles (a route that shares nothing with the tables' incomplete-beta
    // taps). The largest difference seen was 3.1e-5 (the quantile midpoint
    // rule at 6000 steps); the tolerance is ten times that.
    const ColormapTable h = randomTable(64, 40, 777);
    const PrefilteredColormap p(h, PrefilterMode::Smooth, {true, false});
    const auto& s = p.axisLevels(0);  // τ: 0, 1/256 … 1/4, √2/4, ½
    int checked = 0;
    for (size_t kx = 1; kx < s.size(); ++kx) {
        const ColormapTable& layer = p.layer(int(kx), 0);
        ASSERT_EQ(layer.resolutionX(), 64);  // a Beta axis keeps its entries
        for (int i : {1, 2, 9, 31, 50, 62}) {
            const int j = (i * 7 + int(kx)) % 40;
            const double m = i / 63.0, y = j / 39.0;
            const Rgb got = layer.entry(i, j);
            if (s[kx] >= 0.5) {  // the limit ν = 1: the end entries, weighted by the mean
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(got[size_t(c)], (1 - m) * h.entry(0, j)[size_t(c)] + m * h.entry(63, j)[size_t(c)],
                                1e-6);
                continue;
            }
            const Rgb want = betaAverageNumerically(h, m, y, 2.0 * s[kx] * std::sqrt(m * (1 - m)), 6000);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(got[size_t(c)], want[size_t(c)], 3e-4) << "τ " << s[kx] << " m " << m;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 6 * 8);  // τ = 1/256 … √2/4
    // A 512-entry curve-like table (two rows), where the wide levels step F
    // by quadrature between ibeta anchors: the same agreement.
    Image wide(512, 2, 3);
    for (int i = 0; i < 512; ++i)
        for (int c = 0; c < 3; ++c)
            wide.at(i, 0, c) = wide.at(i, 1, c) = float(0.5 + 0.4 * std::sin(0.05 * i * (c + 1)) * (i % 7 ? 1 : 0.5));
    const ColormapTable w(wide);
    const PrefilteredColormap pw(w, PrefilterMode::Smooth, {true, false});
    for (size_t kx : {5u, 6u, 7u})  // τ = 1/16, 1/8, 1/4: deviations of 32–128 entries at m = ½
        for (int i : {3, 40, 255, 470, 509}) {
            const double m = i / 511.0;
            const Rgb got = pw.layer(int(kx), 0).entry(i, 0);
            const Rgb want = betaAverageNumerically(w, m, 0.0, 2.0 * s[kx] * std::sqrt(m * (1 - m)), 6000);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(got[size_t(c)], want[size_t(c)], 3e-4) << "τ " << s[kx] << " m " << m;
        }
    // The ends are points at every level; the y axis stays Gaussian, the
    // same as without a Beta axis wherever x is not blurred.
    const PrefilteredColormap gaussian(h, PrefilterMode::Smooth);
    for (size_t k = 0; k < s.size(); ++k) {
        EXPECT_EQ(p.layer(int(k), 3).entry(0, 17), p.layer(0, 3).entry(0, 17));
        EXPECT_EQ(p.layer(int(k), 3).entry(63, 5), p.layer(0, 3).entry(63, 5));
        EXPECT_EQ(p.layer(0, int(k)).sample(0.3f, 0.6f),
                  gaussian.layer(0, int(k)).sample(0.3f, 0.6f));  // wide σ: fewer y entries
    }
}

TEST(PrefilteredColormap, BetaAxisLookupReadsTheShapeOfTheMeanAndDeviation) {
    // The lookup at mean m and deviation σ on a Beta axis reads the layer of
    // τ = σ/(2√(m(1 − m))): at τ on a level it is that layer's entry, and a
    // deviation past the bounded field's largest, √(m(1 − m)), reads the
    // top (two spikes).
    const ColormapTable h = buildColormap(loadPreset("weld").colormap);
    const PrefilteredColormap p(h, PrefilterMode::Smooth, {true, false});
    const int n = h.resolutionX();
    const float m = float(n / 4) / float(n - 1), y = 0.5f;
    for (size_t k : {2u, 5u, 7u, 8u}) {
        const float sigma = float(2.0 * p.axisLevels(0)[k] * std::sqrt(double(m) * (1.0 - m)));
        const Rgb got = p.sample(m, y, sigma, 0.0f), want = p.layer(int(k), 0).sample(m, y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[size_t(c)], want[size_t(c)], 2e-6) << "level " << k;
    }
    const Rgb top = p.sample(m, y, 0.9f, 0.0f), spikes = p.layer(int(p.sigmas().size()) - 1, 0).sample(m, y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(top[size_t(c)], spikes[size_t(c)], 1e-6);
}

TEST(PrefilteredColormap, ATableTooLargeToPrefilterIsRefusedByItsResolution) {
    // Two Beta axes keep every entry of all 10 × 10 layers: 10240² RGBA
    // entries at 1024², 1600 MiB; one keeps 10240 × 3079 (481 MiB), within
    // the bound, and Gaussian axes 3079² (145 MiB): along a Gaussian axis
    // the levels 0 and 1/256 keep 1024 entries, then 2^k/256 keeps 2^(10−k) + 1
    // (σ four of their spacings), at least 8.
    constexpr size_t MiB = size_t(1) << 20;
    EXPECT_EQ(PrefilteredColormap::layerBytes(1024, 1024, PrefilterMode::Smooth, {true, true}), 1600 * MiB);
    EXPECT_EQ(PrefilteredColormap::layerBytes(1024, 1024, PrefilterMode::Smooth, {true, false}),
              size_t(10240) * 3079 * 16);
    EXPECT_LE(PrefilteredColormap::layerBytes(1024, 1024, PrefilterMode::Smooth, {true, false}), kMaxPrefilteredBytes);
    EXPECT_EQ(PrefilteredColormap::layerBytes(1024, 1024, PrefilterMode::Smooth, {false, false}),
              size_t(3079) * 3079 * 16);
    // It is what the built layers take (a small table, both kinds of axis).
    const ColormapTable small = makeAnalyticColormap(AnalyticColormap::Gaussian, 64);
    EXPECT_EQ(PrefilteredColormap(small, PrefilterMode::Smooth, {true, false}).bytes(),
              PrefilteredColormap::layerBytes(64, 64, PrefilterMode::Smooth, {true, false}));
    const ColormapTable h = makeAnalyticColormap(AnalyticColormap::Gaussian, 1024);
    const InputError e = test::inputErrorOf([&] { PrefilteredColormap(h, PrefilterMode::Smooth, {true, true}); });
    EXPECT_EQ(e.parameter(), "resolution");
    EXPECT_NE(std::string(e.what()).find("1024x1024 table read by bounded fields"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("would take 1600 MiB"), std::string::npos) << e.what();
    // The library's own table builder names the parameter too.
    const InputError r = test::inputErrorOf([] { makeAnalyticColormap(AnalyticColormap::Gaussian, 1); });
    EXPECT_EQ(r.parameter(), "resolution");
    EXPECT_STREQ(r.what(), "resolution must be in [2, 4096], got 1");
}

TEST(PrefilteredColormap, SmoothModeInterpolatesBetweenLevelsAndPaperSnaps) {
    const ColormapTable h = buildColormap(loadPreset("weld").colormap);
    const PrefilteredColormap smooth(h, PrefilterMode::Smooth), paper(h, PrefilterMode::Paper);
    // Smooth: continuous in σ (no jump across a level boundary).
    const float a = smooth.sample(0.45f, 0.52f, 0.0156f * 0.999f, 0.02f)[0];
    const float b = smooth.sample(0.45f, 0.52f, 0.0156f * 1.001f, 0.02f)[0];
    EXPECT_NEAR(a, b, 1e-3f);
    // Paper: nearest level in log2: σ = 0.0125 and 0.015 both read 2^2/256.
    EXPECT_EQ(paper.sample(0.45f, 0.52f, 0.0125f, 0.02f), paper.sample(0.45f, 0.52f, 0.015f, 0.02f));
    EXPECT_EQ(paper.sigmas().size(), 6u);
    EXPECT_EQ(smooth.sigmas().front(), 0.0);
    // Paper level = round(log2(256σ)) clamped to 0..5: check either side of
    // every boundary 2^(k+½)/256, and far outside the range.
    auto level = [&](float sigma) {
        const Rgb got = paper.sample(0.3f, 0.7f, sigma, 0.0f);
        for (int k = 0; k < 6; ++k)
            if (got == paper.layer(k, 0).sample(0.3f, 0.7f)) return k;
        return -1;
    };
    EXPECT_EQ(level(0.0f), 0);
    EXPECT_EQ(level(1e-30f), 0);
    for (int k = 0; k < 5; ++k) {
        const float edge = std::exp2(float(k) + 0.5f) / 256.0f;
        EXPECT_EQ(level(edge * 0.99f), k) << "just below the edge above level " << k;
        EXPECT_EQ(level(edge * 1.01f), k + 1) << "just above the edge above level " << k;
    }
    EXPECT_EQ(level(10.0f), 5);
    EXPECT_EQ(level(std::numeric_limits<float>::infinity()), 5);
}

TEST(FilteredProgram, LinearColormapReturnsTheEstimatedMean) {
    PatternSpec spec = loadPreset("gaussian");
    spec.colormap.transfer = Transfer::Linear;  // H(x, y) = x as data, not decoded
    const GraphPattern p = GraphPattern::build(spec);
    for (const char* mode : {"smooth", "paper"}) {
        const FilteredGraph f(p, options(mode, 4));
        int checked = 0;
        for (int i = 0; i < 1000; ++i) {
            const double u = 0.013 * i, v = 0.0071 * i;
            Jacobian j;
            j.dudx = (1 + i % 8) / 256.0;
            j.dvdy = (1 + (i * 7) % 4) / 256.0;
            const Footprint fp = makeFootprint(u, v, j, 256, f.estimator(0).maxLod(), 4);
            const FootprintStats s = f.estimator(0).estimate(fp);
            const float sigma = std::max(s.sigmaX(), 1.0f / 256);  // paper mode blurs by ≥ 1/256
            // The lookup may read the σ level above σ̂ (at most 2σ̂): stay 4 of
            // those σ away from the borders, where the clamp-to-edge bias of
            // the blur is below 1e-5.
            if (s.mean[0] < 8 * sigma || s.mean[0] > 1 - 8 * sigma) continue;
            ++checked;
            // Away from the borders the blur of a linear H is H itself; only
            // the clamp and float rounding remain.
            EXPECT_NEAR(f.shade(true, u, v, j)[0], s.mean[0], 1e-5);
        }
        EXPECT_GT(checked, 300);
    }
}

TEST(FilteredProgram, ConstantColormapStaysConstant) {
    PatternSpec spec = loadPreset("weld");
    spec.colormap.painted.shapes.clear();
    spec.colormap.painted.background = {0.2f, 0.6f, 0.9f};
    spec.colormap.transfer = Transfer::Linear;  // the colour as given
    const GraphPattern p = GraphPattern::build(spec);
    Camera cam = zoom(48, 7.0);
    cam.kind = Camera::Kind::Plane;
    cam.tiltDeg = 70;
    for (const char* mode : {"paper", "smooth"}) {
        const Image img = FilteredGraph(p, options(mode, 8)).render(cam);
        for (size_t i = 0; i < img.data().size(); i += 3) {
            ASSERT_NEAR(img.data()[i], 0.2f, 1e-6f);
            ASSERT_NEAR(img.data()[i + 2], 0.9f, 1e-6f);
        }
    }
}

TEST(FilteredProgram, OneTexelFootprintReproducesTheUnfilteredPattern) {
    const GraphPattern p = GraphPattern::build(loadPreset("camouflage"));
    const Camera cam = zoom(64, 1.0);
    const Image unfiltered = p.render(cam.view);
    const Image smooth = FilteredGraph(p, options("smooth")).render(cam);
    EXPECT_EQ(smooth.data(), unfiltered.data());  // σ̂ = 0 reads the σ = 0 level: bit-identical
    // Paper mode: the finest level blurs by σ = 1/256, i.e. one colormap entry.
    const Image paper = FilteredGraph(p, options("paper")).render(cam);
    double diff = 0;
    for (size_t i = 0; i < paper.data().size(); ++i) diff += std::abs(paper.data()[i] - unfiltered.data()[i]);
    diff /= double(paper.data().size());
    EXPECT_GT(diff, 0.0);
    EXPECT_LT(diff, 0.01);
}

TEST(FilteredProgram, FilteredIsCloserToTheReferenceThanUnfilteredWhenZoomedOut) {
    const GraphPattern p = GraphPattern::build(loadPreset("marble"));
    FilterOptions ref = options("reference");
    ref.referenceMaxSamples = 32;
    const Camera cam = zoom(24, 16.0);
    const Image r = FilteredGraph(p, ref).render(cam);
    auto error = [&](const char* m) {
        const Image img = FilteredGraph(p, options(m)).render(cam);
        double e = 0;
        for (size_t i = 0; i < img.data().size(); ++i) e += std::abs(img.data()[i] - r.data()[i]);
        return e / double(img.data().size());
    };
    const double none = error("none"), smooth = error("smooth"), exact = error("exact");
    EXPECT_LT(smooth, 0.5 * none);
    EXPECT_LT(exact, smooth * 1.5);  // exact statistics are at least about as good
    EXPECT_LT(smooth, 0.05);
}

// A zoom's reference is rendered as the point image at n times the
// resolution, box-filtered; it must be the n×n average that shade computes
// per pixel (the same sample points: equal to float rounding). 70 pixels
// wide at n = 16 makes two tiles in x, the second partial; the plain
// program (camouflage) takes the one-lookup path, the graph the interpreter.
TEST(FilteredProgram, ZoomReferenceIsThePerPixelAverage) {
    for (const char* preset : {"camouflage", "figure14"}) {
        const GraphPattern p = GraphPattern::build(loadPreset(preset));
        FilterOptions ref = options("reference");
        ref.referenceMaxSamples = 16;
        Camera cam = zoom(70, 12.0);
        cam.view.height = 9;
        const FilteredGraph filtered(p, ref);
        const Image image = filtered.render(cam);
        double worst = 0, spread = 0;
        for (int y = 0; y < cam.view.height; ++y)
            for (int x = 0; x < cam.view.width; ++x) {
                double u = 0, v = 0;
                Jacobian j;
                ASSERT_TRUE(cam.footprint(x, y, p.exampleSize(), u, v, j));
                const Rgb want = filtered.shade(true, u, v, j);
                for (int k = 0; k < 3; ++k) {
                    const float got = image.row(y)[x * 3 + k];
                    worst = std::max(worst, double(std::abs(got - want[size_t(k)])));
                    spread = std::max(spread, double(std::abs(got - image.row(0)[k])));
                }
            }
        EXPECT_LT(worst, 2e-5) << preset;
        EXPECT_GT(spread, 0.02) << preset << ": the image must vary for the comparison to mean anything";
    }
}

// min = max fixes the brute-force samples per axis whatever the footprint;
// the default minimum keeps the footprint rule (⌈2·side⌉, at least 8).
TEST(FilterOptions, BruteForceSamplesFollowTheRuleOrAFixedCount) {
    Jacobian j;
    j.dudx = j.dvdy = 3.0 / 512;  // a 3-texel footprint
    EXPECT_EQ(bruteForceSamples(j, 512, 64), 8);
    EXPECT_EQ(bruteForceSamples(j, 512, 64, 1), 6);
    EXPECT_EQ(bruteForceSamples(j, 512, 32, 32), 32);
    EXPECT_EQ(bruteForceSamples(j, 512, 4), 8);  // a cap below the minimum is raised to it, as before
    j.dudx = j.dvdy = 1e30;                      // no overflow for an absurd footprint
    EXPECT_EQ(bruteForceSamples(j, 512, 64), 64);
}

// The plane view's sky is the pattern's average colour in every filter mode
// (it used to be H at the mean unfiltered, and each table's lookup at the
// whole example's σ otherwise: 141, 135 and 130/255 in camouflage's red).
// Expected value from elsewhere: the mean of 65536 unfiltered samples spread
// over ~160 example periods (0.62 of a period apart, beyond the noises'
// correlation length), within 3/255 (its sampling error is ~0.5/255; the
// rest is the blended noise's departure from a Gaussian).
TEST(FilteredProgram, SkyIsThePatternsAverageColourInEveryMode) {
    for (const char* name : {"camouflage", "marble", "weld"}) {
        const GraphPattern p = GraphPattern::build(loadPreset(name));
        View spread;
        spread.width = spread.height = 256;
        spread.scale = 0.618 * p.exampleSize();
        const Image samples = p.render(spread);
        Rgb average{0, 0, 0};
        for (size_t i = 0; i < samples.pixelCount(); ++i)
            for (size_t c = 0; c < 3; ++c) average[c] += samples.data()[3 * i + c] / float(samples.pixelCount());
        Camera plane;
        plane.kind = Camera::Kind::Plane;
        plane.tiltDeg = 80;
        plane.view.width = plane.view.height = 16;
        const Rgb sky = FilteredGraph(p, options("none")).skyColour();
        PartCache parts;  // each table built once for the five modes
        for (const std::string mode : {"none", "paper", "smooth", "exact", "reference"}) {
            const std::string what = std::string(name) + ", " + mode;
            const FilteredGraph f(p, options(mode), GraphMoments::Matched, &parts);
            for (size_t c = 0; c < 3; ++c) {
                EXPECT_EQ(f.skyColour()[c], sky[c]) << what << " channel " << c;
                EXPECT_NEAR(f.skyColour()[c], average[c], 3.0 / 255.0) << what << " channel " << c;
            }
            if (mode == "exact" || mode == "reference") continue;  // slow; same shade() path
            const Image img = f.render(plane);                     // the top rows look above the horizon at tilt 80°
            for (int c = 0; c < 3; ++c) EXPECT_EQ(img.at(0, 0, c), sky[size_t(c)]) << what << " pixel (0, 0)";
        }
    }
}

TEST(FilteredProgram, BadInputIsRejected) {
    const GraphPattern p = GraphPattern::build(loadPreset("gaussian"));
    EXPECT_THROW(FilteredGraph(p, options("smooth", 0)), InputError);
    EXPECT_THROW(FilteredGraph(p, options("smooth", 17)), InputError);
    Jacobian nan;
    nan.dudx = std::nan("");
    EXPECT_THROW(makeFootprint(0, 0, nan, 256, 8, 1), InputError);
    const FilteredGraph f(p, options("smooth"));
    Camera c = zoom(8, 0.0);
    EXPECT_THROW(f.render(c), InputError);
    c = zoom(8, 1.0);
    c.kind = Camera::Kind::Plane;
    c.tiltDeg = 95;
    EXPECT_THROW(f.render(c), InputError);
}

// The library names its own parameters and the value it got; the CLI adds
// the flag (tests/cli).
TEST(FilteredProgram, ErrorsNameTheParameterAndTheValue) {
    const GraphPattern p = GraphPattern::build(loadPreset("gaussian"));
    const InputError aniso = test::inputErrorOf([&] { FilteredGraph(p, options("smooth", 0)); });
    EXPECT_EQ(aniso.parameter(), "aniso");
    EXPECT_STREQ(aniso.what(), "aniso must be in [1, 16], got 0");
    FilterOptions o = options("reference");
    o.referenceMaxSamples = 5000;
    const InputError samples = test::inputErrorOf([&] { FilteredGraph(p, o); });
    EXPECT_EQ(samples.parameter(), "referenceMaxSamples");
    EXPECT_STREQ(samples.what(), "referenceMaxSamples must be in [1, 4096], got 5000");
    const InputError filter = test::inputErrorOf([] { parseFilter("blurry"); });
    EXPECT_EQ(filter.parameter(), "filter");
    EXPECT_STREQ(filter.what(), "filter must be none, paper, smooth, exact or reference, got \"blurry\"");
    const InputError k = test::inputErrorOf([] { makeFootprint(0, 0, Jacobian{1, 0, 0, 1}, 256, 8, 17); });
    EXPECT_EQ(k.parameter(), "maxAniso");
    EXPECT_STREQ(k.what(), "maxAniso (K) must be in [1, 16], got 17");
}

TEST(FilteredProgram, IdenticalForAnyThreadCountAndEstimatorInstance) {
    const GraphPattern p = GraphPattern::build(loadPreset("woven"));
    Camera cam = zoom(64, 3.0);
    cam.kind = Camera::Kind::Plane;
    cam.tiltDeg = 65;
    Image one, all;
    {
        ThreadLimit limit(1);
        one = FilteredGraph(p, options("smooth", 4)).render(cam);
    }
    // A second estimator (possibly at the same address) must not reuse the
    // first one's cached tiles.
    all = FilteredGraph(p, options("smooth", 4)).render(cam);
    EXPECT_EQ(one.data(), all.data());
    const GraphPattern other = GraphPattern::build(loadPreset("marble"));
    const Image m1 = FilteredGraph(other, options("smooth", 4)).render(cam);
    EXPECT_NE(m1.data(), all.data());
}

namespace stochtex {
namespace {

// The colormap op reads no covariance, so a shared-offset pair
// (phasor-stripes: a quadrature pair) builds no covariance pyramid.
TEST(FilteredProgram, CovarianceIsBuiltOnlyWhenAnOpReadsIt) {
    const GraphPattern p = GraphPattern::build(loadPreset("phasor-stripes"));
    ASSERT_TRUE(p.leafPairs().front().shared());
    EXPECT_FALSE(p.pairCovariance(0));
    const FilteredGraph f(p, FilterOptions{});  // estimators + the smooth table
    EXPECT_EQ(f.estimator(0).covariancePyramid(), nullptr);
    // The pyramid would change ĉov, which the program does not read.
    const FootprintEstimator withCov(p.leafPairs().front(), true);
    ASSERT_NE(withCov.covariancePyramid(), nullptr);
    Jacobian j;
    j.dudx = j.dvdy = 6.0 / p.exampleSize();
    const Footprint fp = makeFootprint(0.3, 0.7, j, p.exampleSize(), withCov.maxLod(), 1);
    const FootprintStats a = f.estimator(0).estimate(fp), b = withCov.estimate(fp);
    // Without the pyramid only the between-texel part of ĉov remains.
    EXPECT_GT(std::abs(b.cov - a.cov), 1e-6f);
    EXPECT_EQ(a.mean, b.mean);
    EXPECT_EQ(a.varX, b.varX);
    EXPECT_EQ(a.varY, b.varY);
}

// The pairs written out here from the papers' definitions (pattern/
// filter_options.h): the CLI's names must keep meaning what they did.
TEST(FilterOptions, NamedFiltersAreASourceAndAResponse) {
    const auto pair = [](const char* name) {
        const NamedFilter f = parseFilter(name);
        return std::make_tuple(f.source, f.response.kind, f.response.prefilter);
    };
    constexpr auto kTable = ResponseKind::PrefilteredColormap;
    using S = StatisticsSource;
    using M = PrefilterMode;
    EXPECT_EQ(std::get<0>(pair("none")), S::Point);
    EXPECT_EQ(pair("paper"), std::make_tuple(S::Estimators, kTable, M::Paper));
    EXPECT_EQ(pair("smooth"), std::make_tuple(S::Estimators, kTable, M::Smooth));
    EXPECT_EQ(pair("exact"), std::make_tuple(S::Exact, kTable, M::Smooth));
    EXPECT_EQ(pair("reference"), std::make_tuple(S::Reference, kTable, M::Smooth));
    // The default options are the smooth filter; every named pair reads back
    // as its name, an unnamed one as source/response.
    EXPECT_EQ(filterName(FilterOptions{}), "smooth");
    for (const char* name : {"none", "paper", "smooth", "exact", "reference"})
        EXPECT_EQ(filterName(FilterOptions{}.use(parseFilter(name))), name);
    FilterOptions exactPaper = FilterOptions{}.use(parseFilter("exact"));
    exactPaper.response.prefilter = PrefilterMode::Paper;
    EXPECT_EQ(filterName(exactPaper), "exact/prefiltered-colormap");
    FilterOptions lean = FilterOptions{}.use(parseFilter("paper"));
    lean.response.kind = ResponseKind::Lean;
    EXPECT_EQ(filterName(lean), "paper/lean");
    lean.use(parseFilter("none"));
    lean.response.kind = ResponseKind::Lean;
    lean.response.covariance = false;
    EXPECT_EQ(filterName(lean), "none/lean without covariance");
}

// The options' prefilter mode reaches the program's colormap op: its
// colours are those of a table built directly in that mode from the
// blending-space colormap (exactly: the same blurs), and the two modes
// differ.
TEST(FilteredProgram, ColormapOpReadsTheTableOfTheOptionsMode) {
    const GraphPattern p = GraphPattern::build(loadPreset("weld"));
    const float mx = 0.45f, my = 0.52f, sx = 0.0125f, sy = 0.02f;
    Rgb colours[2];
    for (PrefilterMode mode : {PrefilterMode::Paper, PrefilterMode::Smooth}) {
        FilterOptions o;
        o.response.prefilter = mode;
        const FilteredGraph f(p, o);
        colours[int(mode)] = f.fromMoments({{mx, sx * sx}, {my, sy * sy}});
        const PrefilteredColormap direct(p.tables().front().blended, mode);
        EXPECT_EQ(colours[int(mode)], direct.sample(mx, my, std::sqrt(sx * sx), std::sqrt(sy * sy)));
    }
    EXPECT_NE(colours[0], colours[1]);
}

}  // namespace
}  // namespace stochtex
