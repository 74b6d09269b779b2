// Phasor patterns (paper §6.4, Fig. 10): the quadrature partner of a bi-lobe
// noise and the profiles P of H = P ∘ atan2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "stochtex/core/error.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/image/image_io.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/presets.h"
#include "test_util.h"

namespace stochtex {
namespace {

constexpr double kPi = std::numbers::pi;

// phasor-stripes: one bi-lobe at 24 cycles per period, 30°, bandwidth 2.5.
constexpr double kStripesFrequency = 24.0, kStripesOrientation = 30.0;

// The field N of the preset at `count` uniform random points (seed 11).
struct FieldSamples {
    std::vector<double> u, v, x, y;
};
// N(uv) of a plain program: its two leaves (slots 0 and 1), in output space.
std::array<float, 2> field(const GraphPattern& p, double u, double v) {
    return {p.evaluate(u, v, 0, GraphPattern::kFromAbove)[0], p.evaluate(u, v, 1, GraphPattern::kFromAbove)[0]};
}

FieldSamples sampleField(const GraphPattern& p, int count) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uni(0.0, 4.0);  // four example periods
    FieldSamples s;
    for (int i = 0; i < count; ++i) {
        const double u = uni(rng), v = uni(rng);
        const auto n = field(p, u, v);
        s.u.push_back(u);
        s.v.push_back(v);
        s.x.push_back(n[0]);
        s.y.push_back(n[1]);
    }
    return s;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    double ma = 0, mb = 0;
    for (size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= double(a.size());
    mb /= double(b.size());
    double ab = 0, aa = 0, bb = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        ab += (a[i] - ma) * (b[i] - mb);
        aa += (a[i] - ma) * (a[i] - ma);
        bb += (b[i] - mb) * (b[i] - mb);
    }
    return ab / std::sqrt(aa * bb);
}

// N_y at a point carries no linear information about N_x at the same point:
// the Hilbert transform rotates every frequency's phase by 90°, and
// E[cos·sin] = 0. Both on the example and on the tiled-and-blended field
// (shared offsets keep the pair in quadrature). Over the whole example the
// DFT makes the two exactly orthogonal (measured 1e-7); over 2·10⁴ random
// points of the field the standard error of a zero correlation is
// 1/√n ≈ 0.007, so |corr| < 0.02 holds with margin (measured 0.006).
TEST(Phasor, QuadraturePartnerIsUncorrelatedAtTheSamePoint) {
    const PatternSpec spec = loadPreset("phasor-stripes");
    const GraphPattern p = GraphPattern::build(spec);
    const Image& ex = p.leaf(0).example().values();
    const Image& ey = p.leaf(1).example().values();
    std::vector<double> a(ex.data().begin(), ex.data().end()), b(ey.data().begin(), ey.data().end());
    EXPECT_LT(std::abs(correlation(a, b)), 0.02);
    const FieldSamples s = sampleField(p, 20000);
    EXPECT_LT(std::abs(correlation(s.x, s.y)), 0.02);
    // And the pair is not trivially independent: a quarter period along the
    // lobe, N_y follows N_x (cos(θ − π/2) = sin θ): correlation ≥ 0.8 (measured 0.98).
    const double t = kStripesOrientation * kPi / 180.0, q = 0.25 / kStripesFrequency;
    std::vector<double> shifted;
    for (size_t i = 0; i < s.u.size(); ++i) shifted.push_back(field(p, s.u[i] - q * std::cos(t), s.v[i] + q * std::sin(t))[0]);
    EXPECT_GT(correlation(shifted, s.y), 0.8);
}

// |F(N_y)| = |F(N_x)| at every frequency off the line f·d = 0 (the Hilbert
// transform changes phases only); the clamp to [0, 1] and the
// renormalisation of each example (3σ: they rarely clamp) leave the power
// spectra within 0.1% of the total power (summed absolute difference;
// measured 0.0035%), and the totals within 0.1%.
TEST(Phasor, QuadraturePartnerHasTheSameSpectrumMagnitude) {
    const GraphPattern p = GraphPattern::build(loadPreset("phasor-stripes"));
    const Image px = powerSpectrum(p.leaf(0).example().values()), py = powerSpectrum(p.leaf(1).example().values());
    double total = 0, totalY = 0, diff = 0;
    for (size_t i = 0; i < px.data().size(); ++i) {
        total += px.data()[i];
        totalY += py.data()[i];
        diff += std::abs(px.data()[i] - py.data()[i]);
    }
    EXPECT_LT(diff / total, 1e-3);
    EXPECT_NEAR(totalY / total, 1.0, 1e-3);
}

// The phase φ = atan2(N_y − ½, N_x − ½) advances along the lobe direction d
// at the lobe frequency f₀. With z = (N_x − ½) + i(N_y − ½) the field's
// complex value (one-sided: the partner cancels the lobe at −f₀ d), the mean
// phase increment over a step δ d is arg Σ z(u + δ d) z̄(u), the argument of
// the autocorrelation at lag δ d: Σ_f P(f) e^{2πi f·d δ}, which is e^{2πi f₀ δ}
// times a real factor for a lobe symmetric about f₀ d. One realisation's
// power |Ŵ(f)|² P(f) is not symmetric (white noise has a random power per
// frequency): its centroid scatters around f₀ by ~0.4 cycles (~40 frequencies
// in a lobe of bandwidth 2.5), 1.7% of 24. So the mean over 8 pattern seeds
// is checked, within 1.5% (measured 0.2%), and each seed within 6% (measured
// at most 2.4%); over
// δ = 1/(8 f₀) the phase advances by 2π f₀ δ = π/4. Across the lobe (δ ⟂ d)
// it does not advance (|arg| < 0.03 rad each).
TEST(Phasor, PhaseAdvancesAlongTheLobeAtTheLobeFrequency) {
    const double t = kStripesOrientation * kPi / 180.0;
    const double du = std::cos(t), dv = -std::sin(t);  // d in (u, v): v points down the rows
    const double step = 1.0 / (8.0 * kStripesFrequency);
    double sum = 0;
    const int seeds = 8;
    for (int seed = 1; seed <= seeds; ++seed) {
        PatternSpec spec = loadPreset("phasor-stripes");
        spec.seed = uint32_t(seed);
        const GraphPattern p = GraphPattern::build(spec);
        const FieldSamples s = sampleField(p, 5000);
        const auto meanAdvance = [&](double su, double sv) {
            double re = 0, im = 0;
            for (size_t i = 0; i < s.u.size(); ++i) {
                const auto b = field(p, s.u[i] + su, s.v[i] + sv);
                const double ax = s.x[i] - 0.5, ay = s.y[i] - 0.5, bx = b[0] - 0.5, by = b[1] - 0.5;
                re += bx * ax + by * ay;  // b · conj(a)
                im += by * ax - bx * ay;
            }
            return std::atan2(im, re);
        };
        const double along = meanAdvance(step * du, step * dv) / (kPi / 4.0);
        EXPECT_NEAR(along, 1.0, 0.06) << "seed " << seed;
        EXPECT_NEAR(meanAdvance(-step * dv, step * du), 0.0, 0.03) << "seed " << seed;
        sum += along;
    }
    EXPECT_NEAR(sum / seeds, 1.0, 0.015);
}

TEST(Phasor, AnalyticProfilesAndTheirMeans) {
    // Gray data: sine mean ½, sawtooth ½, square the duty (within the 1/4096 of the sampling).
    EXPECT_NEAR(PhasorColourProfile::analytic(PhasorProfile::Sine, 0.5, false).mean()[0], 0.5f, 1e-6f);
    EXPECT_NEAR(PhasorColourProfile::analytic(PhasorProfile::Sawtooth, 0.5, false).mean()[0], 0.5f, 1e-6f);
    EXPECT_NEAR(PhasorColourProfile::analytic(PhasorProfile::Square, 0.3, false).mean()[0], 0.3f, 1.0f / 4096);
    // Decoded: the mean of linear(½ + ½ sin φ), by an independent quadrature (10⁵ points).
    double m = 0;
    for (int k = 0; k < 100000; ++k)
        m += linearFromSrgb(float(0.5 + 0.5 * std::sin(2.0 * kPi * (k + 0.5) / 100000.0)));
    EXPECT_NEAR(PhasorColourProfile::analytic(PhasorProfile::Sine, 0.5, true).mean()[0], m / 100000.0, 1e-5);
    // A palette of two colours along the sawtooth: at t = ¼ (φ = −π/2), a quarter of the way.
    const auto ramp = PhasorColourProfile::analytic(PhasorProfile::Sawtooth, 0.5, false, {{0, 0, 0}, {1, 0.5f, 0}});
    const Rgb q = ramp(-kPi / 2);
    EXPECT_NEAR(q[0], 0.25f, 1e-6f);
    EXPECT_NEAR(q[1], 0.125f, 1e-6f);
    EXPECT_NEAR(ramp.mean()[0], 0.5f, 1e-6f);
}

class PhasorProfileImage : public test::ScratchFolder {
protected:
    PatternSpec spec(const std::string& colormap) const {
        const std::string text = R"({"noise_x": {"type": "spectrum", "size": 32, "components": [{"shape": "bilobe",
            "frequency": 4, "bandwidth": 1}]}, "noise_y": "quadrature", "colormap": )" + colormap + "}";
        return parsePatternSpec(JsonReader(JsonReader::parse(text, "test.json"), "test.json"), dir_);
    }
    std::string errorOf(const std::string& colormap) const {
        try {
            buildColormap(spec(colormap).colormap);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    }
};

// A W×1 image is one period of P: sample k at t = (k + ½)/W, linear between,
// wrapping; 8-bit codes decoded to linear light.
TEST_F(PhasorProfileImage, OneRowIsOnePeriodOfColours) {
    Image row(4, 1, 3);
    const float codes[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) row.at(k, 0, c) = codes[k][c];
    writeImage((dir_ / "rgbw.png").string(), row);
    const ColormapSpec cm = spec(R"({"type": "phasor", "profile": "image", "path": "rgbw.png"})").colormap;
    const PhasorColourProfile p = buildPhasorProfile(cm);
    // t = 1/8 is sample 0 exactly: red; t = 1/4 is halfway red → green (linear light).
    const Rgb red = p(-kPi + 2.0 * kPi / 8.0), mid = p(-kPi + 2.0 * kPi / 4.0);
    EXPECT_NEAR(red[0], 1.0f, 1e-6f);
    EXPECT_NEAR(red[1], 0.0f, 1e-6f);
    EXPECT_NEAR(mid[0], 0.5f, 1e-6f);
    EXPECT_NEAR(mid[1], 0.5f, 1e-6f);
    // t = 0 wraps: halfway between white (sample 3) and red (sample 0).
    const Rgb wrap = p(-kPi);
    EXPECT_NEAR(wrap[0], 1.0f, 1e-6f);
    EXPECT_NEAR(wrap[2], 0.5f, 1e-6f);
    // The table: straight right of the centre is φ = 0, t = ½: between green and blue.
    const ColormapTable t = buildColormap(cm);
    const Rgb right = t.sample(0.99f, 0.5f);
    EXPECT_NEAR(right[1], 0.5f, 2e-3f);
    EXPECT_NEAR(right[2], 0.5f, 2e-3f);
}

// A palette's colours are sRGB codes decoded once, then interpolated in
// linear light: #bcbcbc (code 188) decodes to 0.5029 (sRGB curve by hand:
// ((188/255 + 0.055)/1.055)^2.4), and halfway from black (the sawtooth at
// t = ½, φ = 0) is half that, not the decode of code 94 (0.1119).
TEST_F(PhasorProfileImage, PaletteColoursAreDecodedAndBlendedInLinearLight) {
    const ColormapSpec cm = spec(R"({"type": "phasor", "profile": "sawtooth", "palette": ["#000000", "#bcbcbc"]})").colormap;
    const PhasorColourProfile p = buildPhasorProfile(cm);
    const double top = std::pow((188.0 / 255.0 + 0.055) / 1.055, 2.4);
    EXPECT_NEAR(p(kPi - 1e-9)[0], top, 1e-5);
    EXPECT_NEAR(p(0.0)[1], 0.5 * top, 1e-5);
    // The table too: straight right of the centre is φ = 0.
    EXPECT_NEAR(buildColormap(cm).sample(0.99f, 0.5f)[2], 0.5 * top, 2e-3);
    // As data ("transfer": "linear"), the codes are the values.
    const ColormapSpec data = spec(R"({"type": "phasor", "profile": "sawtooth", "transfer": "linear",
        "palette": ["#000000", "#bcbcbc"]})").colormap;
    EXPECT_NEAR(buildPhasorProfile(data)(0.0)[0], 0.5 * 188.0 / 255.0, 1e-6);
}

TEST_F(PhasorProfileImage, AnythingButOneRowIsRefusedNamingTheFile) {
    writeImage((dir_ / "square.png").string(), Image(4, 4, 1));
    const std::string e = errorOf(R"({"type": "phasor", "profile": "image", "path": "square.png"})");
    EXPECT_NE(e.find("square.png: a phasor profile image must be one row over one period"), std::string::npos) << e;
    EXPECT_NE(e.find("got 4x4"), std::string::npos) << e;
    writeImage((dir_ / "colours.png").string(), Image(4, 1, 3));
    EXPECT_NE(errorOf(R"({"type": "phasor", "profile": "image", "path": "colours.png", "palette": ["#000000", "#ffffff"]})")
                  .find("colours.png: a profile image that indexes a palette must be grayscale"),
              std::string::npos);
    // The JSON itself: a path needs the image profile, the image profile a path, a palette 2+ colours.
    EXPECT_NE(errorOf(R"({"type": "phasor", "profile": "sine", "path": "x.png"})").find("/colormap/path"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "phasor", "profile": "image"})").find("/colormap"), std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "phasor", "palette": ["#000000"]})").find("/colormap/palette: a palette needs 2"),
              std::string::npos);
}

// Figure 10's four variants are presets: the sine and sawtooth share their
// noises, the square one sums two bi-lobes, the colour one is not gray.
TEST(Phasor, Figure10PresetsExist) {
    const PatternSpec sine = loadPreset("phasor-stripes"), saw = loadPreset("phasor-sawtooth"),
                      square = loadPreset("phasor-square"), colour = loadPreset("phasor-colour");
    EXPECT_EQ(saw.colormap.profile, PhasorProfile::Sawtooth);
    EXPECT_EQ(noiseSeed(saw, 0), noiseSeed(sine, 0));
    EXPECT_EQ(square.noise[0].spectrum.components.size(), 2u);
    EXPECT_EQ(square.colormap.profile, PhasorProfile::Square);
    EXPECT_GE(colour.colormap.palette.size(), 3u);
    const Rgb m = buildPhasorProfile(colour.colormap).mean();
    EXPECT_GT(std::abs(m[0] - m[2]), 0.05f);  // a colour, not a gray
    for (const PatternSpec* s : {&sine, &saw, &square, &colour}) {
        EXPECT_TRUE(s->quadraturePair) << s->name;
        EXPECT_EQ(s->offsets, OffsetMode::Shared) << s->name;
    }
}

}  // namespace
}  // namespace stochtex
