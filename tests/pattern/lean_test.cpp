// LEAN-mapped procedural normal maps (paper §6.5): the slope pair of a height
// example, the covariance estimator on it, the Beckmann lobe and a file's
// lean program's zero-footprint and large-footprint limits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "stochtex/core/hash.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/kernel/lean.h"
#include "stochtex/noise/slopes.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "test_util.h"

namespace stochtex {
namespace {

using test::example;

// A low-pass height example that the synthesis does not clamp (σ = 0.08
// about ½: 6σ inside [0, 1]), so that it is the periodic band-limited
// signal whose derivative the spectrum gives.
Image smoothHeight(int size, double cutoff, uint32_t seed) {
    SpectrumSpec s = test::spectrumSpec(SpectrumShape::LowPass, cutoff, 0, 0, seed, size);
    s.stddev = 0.08;
    return synthesizeExample(s);
}

// A pure wave's spectral slopes are its analytic derivative (to float
// rounding); a band-limited example's are its central differences up to
// their own error: for a wave of ω radians per texel the central difference
// is sin ω/ω times the derivative, |1 − sin ω/ω| ≤ ω²/6. A Gaussian
// low-pass of cut-off fc holds its power below 3·fc, so the RMS difference
// is bounded by (2π·3fc/W)²/6 of the RMS slope (1.4% for fc = 4, W = 256;
// measured 0.64%).
TEST(SpectralSlopes, AreTheDerivativeAndMatchCentralDifferences) {
    const int n = 64;
    Image wave(n, n, 1);
    const double ku = 2 * std::numbers::pi * 3 / n, kv = 2 * std::numbers::pi * 5 / n;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) wave.at(x, y) = float(0.5 + 0.1 * std::sin(ku * x + kv * y));
    const auto ws = spectralSlopes(wave);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double c = 0.1 * std::cos(ku * x + kv * y);
            ASSERT_NEAR(ws[0].at(x, y), c * ku, 2e-6) << x << ", " << y;
            ASSERT_NEAR(ws[1].at(x, y), c * kv, 2e-6) << x << ", " << y;
        }

    const int w = 256;
    const double fc = 4;
    const Image h = smoothHeight(w, fc, 17);
    const auto s = spectralSlopes(h);
    double diff2 = 0, slope2 = 0, mean = 0;
    for (int y = 0; y < w; ++y)
        for (int x = 0; x < w; ++x) {
            const double cx = 0.5 * (h.at((x + 1) % w, y) - h.at((x + w - 1) % w, y));
            const double cy = 0.5 * (h.at(x, (y + 1) % w) - h.at(x, (y + w - 1) % w));
            diff2 += (cx - s[0].at(x, y)) * (cx - s[0].at(x, y)) + (cy - s[1].at(x, y)) * (cy - s[1].at(x, y));
            slope2 += double(s[0].at(x, y)) * s[0].at(x, y) + double(s[1].at(x, y)) * s[1].at(x, y);
            mean += s[0].at(x, y) + s[1].at(x, y);
        }
    const double omega = 2 * std::numbers::pi * 3 * fc / w;
    EXPECT_LT(std::sqrt(diff2 / slope2), omega * omega / 6);
    EXPECT_GT(slope2, 0.0);
    EXPECT_NEAR(mean / (2.0 * w * w), 0.0, 1e-7);  // periodic: slopes average to 0
}

// The height of the covariance tests: an oriented bi-lobe (ridges across
// 30°), whose slopes are strongly correlated: a single wave direction
// (cos 30°, −sin 30°) would make them perfectly anti-correlated, the
// lobes' angular spread (bandwidth 3 at frequency 10) lessens that.
TiledField ridgeSlopes(int size) {
    const Image h = example(SpectrumShape::BiLobe, 10, 3, 30, 23, size);
    return slopeField(h, 0.3, 41, GridLayout{});
}

TEST(SlopeField, IsASharedPairScaledToTheRmsSlope) {
    const TiledField f = ridgeSlopes(128);
    EXPECT_TRUE(f.shared());
    ASSERT_EQ(f.channelCount(), 2);
    double v[2] = {0, 0}, c = 0;
    const auto& x = f.channel(0).example().values().data();
    const auto& y = f.channel(1).example().values().data();
    for (size_t i = 0; i < x.size(); ++i) {
        v[0] += double(x[i]) * x[i];
        v[1] += double(y[i]) * y[i];
        c += double(x[i]) * y[i];
    }
    EXPECT_NEAR(std::sqrt((v[0] + v[1]) / (2.0 * double(x.size()))), 0.3, 1e-5);
    // Ridges across 30°: the slopes lie along (cos 30°, −sin 30°), so they
    // are anti-correlated (−1 for a single wave direction).
    EXPECT_LT(c / std::sqrt(v[0] * v[1]), -0.7);
    EXPECT_EQ(test::inputErrorOf([&] {
                  slopeField(example(SpectrumShape::LowPass, 4, 0, 0, 1, 32), -1, 1, GridLayout::plane(1));
              }).parameter(),
              "amplitude");
}

// The covariance estimator (eq. 16–19) against brute-force statistics on
// random footprints of 1 to 64 texels, isotropic and 4–8:1 anisotropic.
// Its error bound follows from the variance's: every step of eq. 8–19 is
// linear in the pyramids (C_l of (x, y) = (V_l(x + y) − V_l(x − y))/4, and
// N̂N̂' = ((N̂ + N̂')² − (N̂ − N̂')²)/4), so by polarisation
//   ĉov(x, y) = (σ̂²(x + y) − σ̂²(x − y))/4
// on the same footprint, and |ĉov − cov| ≤ (|σ̂²(x+y) − σ²(x+y)| +
// |σ̂²(x−y) − σ²(x−y)|)/4: the covariance is exactly as accurate as the
// variance estimator (bounded in filter_test, docs/TESTING.md) on the sum
// and difference fields. Checked per footprint (the identity within 2e-5:
// float pyramids and sums), plus the mean error, about twice the measured
// one (2026-12-01: 0.00024, 0.0029, 0.020, 0.017 for 1, 4, 16, 64 texels,
// against a mean |cov| of 0.0043 and 0.041 at 4 and 16 texels; a relative
// error of 0.5 at 16 texels, the variance estimator's on this
// 16-texel-period field, as in the paper's Table 1). Without the C_l
// pyramid (ĉov_l := 0) the error is larger from 4 texels on (measured
// 0.0032, 0.030, 0.060).
TEST(SlopeField, CovarianceEstimateMatchesBruteForceStatistics) {
    const TiledField f = ridgeSlopes(256);
    const FootprintEstimator est(f, true), noCov(f, false);
    // The sum and difference fields, with the same tiles.
    const int w = est.exampleSize();
    Image sum(w, w, 1), diff(w, w, 1);
    for (int y = 0; y < w; ++y)
        for (int x = 0; x < w; ++x) {
            const float a = f.channel(0).example().values().at(x, y), b = f.channel(1).example().values().at(x, y);
            sum.at(x, y) = a + b;
            diff.at(x, y) = a - b;
        }
    const uint32_t seed = f.channel(0).offsetSeed();
    const TiledField polar({TilingBlendingNoise(std::make_shared<const NoiseExample>(sum), seed),
                            TilingBlendingNoise(std::make_shared<const NoiseExample>(diff), seed)},
                           f.grid(), OffsetSharing::Shared);
    const FootprintEstimator polarEst(polar, false);
    struct Size {
        int texels;
        double bound;  // mean |ĉov − cov| over the footprints
    };
    for (const Size size : {Size{1, 0.0005}, Size{4, 0.006}, Size{16, 0.04}, Size{64, 0.035}}) {
        double err = 0, errNoCov = 0;
        const int count = 40;
        for (int i = 0; i < count; ++i) {
            const UInt3 hsh = pcg3d({uint32_t(i), uint32_t(size.texels), 5u});
            const double u = unitFloat(hsh.x) * 10, v = unitFloat(hsh.y) * 10;
            const bool aniso = i % 2 == 1;
            const double angle = unitFloat(hsh.z) * 3.14159, ratio = aniso ? 4.0 + 4.0 * unitFloat(hsh.x ^ hsh.y) : 1.0;
            Jacobian j;
            j.dudx = size.texels * std::cos(angle) / w;
            j.dvdx = size.texels * std::sin(angle) / w;
            j.dudy = -size.texels / ratio * std::sin(angle) / w;
            j.dvdy = size.texels / ratio * std::cos(angle) / w;
            const Footprint fp = makeFootprint(u, v, j, w, est.maxLod(), aniso ? 16 : 1);
            const FootprintStats exact = bruteForceStats(f, u, v, j, 256), e = est.estimate(fp);
            const FootprintStats pe = polarEst.estimate(fp), px = bruteForceStats(polar, u, v, j, 256);
            EXPECT_NEAR(e.cov, (pe.varX - pe.varY) / 4, 2e-5) << size.texels << " texels, footprint " << i;
            const double bound = (std::abs(pe.varX - px.varX) + std::abs(pe.varY - px.varY)) / 4;
            EXPECT_LE(std::abs(e.cov - exact.cov), bound + 4e-5) << size.texels << " texels, footprint " << i;
            err += std::abs(e.cov - exact.cov);
            errNoCov += std::abs(noCov.estimate(fp).cov - exact.cov);
        }
        err /= count;
        errNoCov /= count;
        EXPECT_LT(err, size.bound) << size.texels << " texels";
        if (size.texels > 1) {
            EXPECT_LT(err, errNoCov) << size.texels << " texels";
        }
    }
}

// The lobe is a probability density of slopes: it integrates to 1 over
// the slope plane (midpoint rule on ±10 standard deviations, 600² cells:
// error < 1e-4), and its normal distribution D(h) = P(s_h)/h_z⁴
// integrates to 1 against h_z over the hemisphere (the slopes beyond the
// grid's 89.9° carry < 1e-3 of the mass for these roughnesses).
TEST(LeanLobe, IntegratesToOneOverSlopesAndOverTheHemisphere) {
    using namespace kernel;
    struct Case {
        vec2 mean, var;
        float cov, roughness;
    };
    for (const Case c :
         {Case{vec2(0.0f), vec2(0.0f), 0.0f, 0.2f}, Case{vec2(0.1f, -0.2f), vec2(0.02f, 0.05f), -0.025f, 0.1f},
          Case{vec2(-0.3f, 0.05f), vec2(0.01f, 0.003f), 0.004f, 0.3f}}) {
        const LeanLobe l = leanLobe(c.mean, c.var, c.cov, c.roughness);
        const double sx = std::sqrt(l.sigma.x), sy = std::sqrt(l.sigma.y);
        const int n = 600;
        double sum = 0;
        for (int b = 0; b < n; ++b)
            for (int a = 0; a < n; ++a) {
                const float x = float(l.mean.x + sx * (20.0 * (a + 0.5) / n - 10));
                const float y = float(l.mean.y + sy * (20.0 * (b + 0.5) / n - 10));
                sum += leanSlopeDensity(l, vec2(x, y));
            }
        EXPECT_NEAR(sum * (20 * sx / n) * (20 * sy / n), 1.0, 1e-4);
        // ∫ D(h) cos θ dω = ∫∫ D cos θ sin θ dθ dφ.
        const int nt = 2000, np = 400;
        double hemi = 0;
        for (int p = 0; p < np; ++p)
            for (int t = 0; t < nt; ++t) {
                const double theta = (t + 0.5) / nt * (0.5 * std::numbers::pi),
                             phi = (p + 0.5) / np * 2 * std::numbers::pi;
                const vec3 h(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                             float(std::cos(theta)));
                hemi += leanNdf(l, h) * std::cos(theta) * std::sin(theta);
            }
        EXPECT_NEAR(hemi * (0.5 * std::numbers::pi / nt) * (2 * std::numbers::pi / np), 1.0, 1e-3);
        // D takes the half vector at any length (leanShade passes l + v
        // unnormalised): the same density within float rounding.
        for (const vec3 h : {vec3(0.1f, -0.2f, 0.97f), vec3(-0.5f, 0.3f, 0.8f), vec3(0.02f, 0.6f, 0.35f)}) {
            const float unit = leanNdf(l, h / std::sqrt(h.x * h.x + h.y * h.y + h.z * h.z));
            for (const float k : {0.3f, 1.7f, 2.0f})
                EXPECT_NEAR(leanNdf(l, k * h), unit, 1e-5f * std::max(1.0f, unit)) << k;
        }
    }
}

// The diffuse term's quadrature (kernel leanDiffuse, five sigma points)
// against a Monte Carlo mean of max(n(s)·l, 0) over s ~ N(b, Σ): 100
// footprints (lights 20–85° high in every azimuth, RMS slopes 0.1–0.45,
// correlations in (−1, 1), means of the slopes' own spread), 10⁵ samples
// each (standard error ≈ 6·10⁻⁴).
TEST(LeanLobe, DiffuseQuadratureMatchesMonteCarloOverTheFootprintsSlopes) {
    using namespace kernel;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uniform(0, 1);
    std::normal_distribution<double> normal(0, 1);
    double quadrature = 0, worst = 0, meanNormal = 0;
    const int cases = 100, samples = 100000;
    for (int c = 0; c < cases; ++c) {
        const double elevation = (20 + 65 * uniform(rng)) * std::numbers::pi / 180;
        const double azimuth = 2 * std::numbers::pi * uniform(rng);
        const vec3 l(float(std::cos(elevation) * std::cos(azimuth)), float(std::cos(elevation) * std::sin(azimuth)),
                     float(std::sin(elevation)));
        const double rms = 0.1 + 0.35 * uniform(rng);
        const double sx = rms * (0.3 + 0.7 * uniform(rng)), sy = rms * (0.3 + 0.7 * uniform(rng));
        const double rho = 2 * uniform(rng) - 1, bx = rms * normal(rng), by = rms * normal(rng);
        const LeanLobe lobe =
            leanLobe(vec2(float(bx), float(by)), vec2(float(sx * sx), float(sy * sy)), float(rho * sx * sy), 0.1f);
        double reference = 0;
        for (int k = 0; k < samples; ++k) {
            const double z1 = normal(rng), z2 = normal(rng);
            const double s1 = bx + sx * z1, s2 = by + sy * (rho * z1 + std::sqrt(1 - rho * rho) * z2);
            reference += std::max((l.z - s1 * l.x - s2 * l.y) / std::sqrt(1 + s1 * s1 + s2 * s2), 0.0);
        }
        reference /= samples;
        const double error = std::abs(leanDiffuse(lobe, l) - reference);
        quadrature += error / cases;
        worst = std::max(worst, error);
        meanNormal += std::abs(leanLambert(lobe.mean, l) - reference) / cases;
    }
    std::printf("[ info ] diffuse |quadrature − Monte Carlo|: mean %.5f, worst %.5f; mean normal alone %.5f\n",
                quadrature, worst, meanNormal);
    EXPECT_LT(quadrature, 0.0015);
    EXPECT_LT(worst, 0.02);
    EXPECT_GT(meanNormal, 0.01);  // the footprints are wide enough for the quadrature to matter
}

// A pattern with a normal map (docs/PATTERNS.md); `normalMap`'s members
// replace the normal map's own.
PatternSpec normalMapSpec(const nlohmann::json& normalMap) {
    nlohmann::json j = nlohmann::json::parse(R"({
        "name": "bumps", "seed": 5,
        "noise_x": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]},
        "noise_y": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]},
        "colormap": {"type": "gaussian"},
        "normal_map": {"height": {"type": "spectrum", "size": 128,
                                  "components": [{"shape": "bilobe", "frequency": 12, "bandwidth": 3, "orientation": 30}]},
                       "amplitude": 0.25, "light": [0.3, -0.6, 0.75], "view": [0, 0.4, 1]}})");
    j["normal_map"].update(normalMap);
    return parsePatternSpec(JsonReader(j, "bumps.json"), ".");
}
PatternSpec normalMapSpec(double roughness) { return normalMapSpec({{"roughness", roughness}}); }

// A file's normal map under the lean response is its program
// (GraphPattern::build(spec, response)), filtered as every program is.
struct LeanRenderer {
    explicit LeanRenderer(const PatternSpec& spec, bool covariance = true)
        : program(GraphPattern::build(spec, {ResponseKind::Lean, PrefilterMode::Smooth, covariance})) {}
    Image render(FilterOptions o, const Camera& cam) const {
        o.response.kind = ResponseKind::Lean;
        return FilteredGraph(program, o).render(cam);
    }
    GraphPattern program;
};

// With a zero footprint (every magnified pixel reads one level-0 texel,
// whose variances and covariance are 0) the filtered shading is the
// unfiltered shading with the base roughness, exactly; zoomed out, it is
// not.
TEST(LeanProgram, ZeroFootprintIsTheUnfilteredShading) {
    const LeanRenderer lean(normalMapSpec(0.15));
    FilterOptions filtered, point;
    point.source = StatisticsSource::Point;
    Camera cam;
    cam.view = View{48, 40, 0.5, 3.0, 7.0};
    const Image near = lean.render(filtered, cam), nearPoint = lean.render(point, cam);
    EXPECT_EQ(near.data(), nearPoint.data());
    double spread = 0;  // the image is not flat: the test compares shading, not a constant
    for (size_t i = 3; i < near.data().size(); ++i)
        spread = std::max(spread, double(std::abs(near.data()[i] - near.data()[0])));
    EXPECT_GT(spread, 0.05);
    cam.view.scale = 8;
    EXPECT_NE(lean.render(filtered, cam).data(), lean.render(point, cam).data());
}

// Diffuse shading averaged over a large footprint: the reference is the
// mean of the unfiltered shading n(s)·l over the footprint's slopes, which
// is not the shading through the mean slope (n·l is concave near the top).
// With exact footprint statistics (no estimator error) and no specular
// lobe, the filtered diffuse term integrated over the slopes' distribution
// (kernel leanDiffuse) meets the supersampled reference within 0.006;
// through the mean normal alone it stayed 0.04–0.05 too bright at every
// footprint.
TEST(LeanProgram, DiffuseConvergesToTheReferenceAtLargeFootprints) {
    const LeanRenderer lean(
        normalMapSpec(nlohmann::json::parse(R"({"amplitude": 0.3, "albedo": [1, 1, 1], "specular": 0})")));
    FilterOptions exact, reference;
    exact.source = StatisticsSource::Exact;
    reference.source = StatisticsSource::Reference;
    exact.referenceMaxSamples = reference.referenceMaxSamples = 64;
    for (const double scale : {8.0, 32.0}) {
        Camera cam;
        cam.view = View{16, 16, scale, 0.0, 0.0};
        const Image a = lean.render(exact, cam), b = lean.render(reference, cam);
        double bias = 0;
        for (size_t i = 0; i < a.data().size(); ++i) bias += double(a.data()[i]) - double(b.data()[i]);
        bias /= double(a.data().size());
        // Measured (linear light, albedo 1): lit through the mean normal
        // +0.0395 at 8 and +0.0479 at 32 texels a pixel; a second-order
        // Taylor term −0.0072 and −0.0126; 3×3 Gauss–Hermite (leanDiffuse)
        // +0.0044 and +0.0027.
        std::printf("[ info ] scale %g: mean (filtered − reference) %.5f\n", scale, bias);
        EXPECT_LT(std::abs(bias), 0.006) << "scale " << scale;
    }
}

// The lean response needs a normal map and a valid shading; the slopes'
// covariance pyramid is built only when the lean node reads it.
TEST(LeanProgram, NeedsANormalMapAndAValidRoughness) {
    const std::string message = test::inputErrorOf([] { normalMapSpec(-0.1); }).what();
    EXPECT_NE(message.find("/normal_map/roughness: roughness must be in [0.001, 10], got -0.1"), std::string::npos)
        << message;
    PatternSpec colourOnly = normalMapSpec(0.1);
    colourOnly.normalMap.reset();
    EXPECT_EQ(test::inputErrorOf([&] { LeanRenderer{colourOnly}; }).parameter(), "response");
    FilterOptions lean;
    lean.response.kind = ResponseKind::Lean;
    const LeanRenderer withCovariance(normalMapSpec(0.1)), without(normalMapSpec(0.1), false);
    EXPECT_NE(FilteredGraph(withCovariance.program, lean).estimator(0).covariancePyramid(), nullptr);
    EXPECT_EQ(FilteredGraph(without.program, lean).estimator(0).covariancePyramid(), nullptr);
    // The lean op reads its slopes' pair's covariance (the CPU evaluator and the GLSL emitter both take it from here).
    EXPECT_EQ(withCovariance.program.operations().back().covariancePair, withCovariance.program.leafLocation(0)[0]);
    EXPECT_EQ(without.program.operations().back().covariancePair, -1);
    EXPECT_EQ(withCovariance.program.operations().front().covariancePair, -1);  // the albedo reads nothing
}

}  // namespace
}  // namespace stochtex
