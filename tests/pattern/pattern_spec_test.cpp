#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/graph_nodes.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_members.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/presets.h"
#include "test_util.h"

using namespace stochtex;

namespace {

PatternSpec parse(const std::string& text) { return test::parsePatternText(text, "test.json"); }

std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const char* kValid = R"({
  "noise_x": {"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 8}]},
  "noise_y": {"type": "spectrum", "components": [{"shape": "ring", "frequency": 8, "bandwidth": 2}]},
  "colormap": {"type": "gaussian"}
})";

std::string withNoiseX(const std::string& noise) {
    return R"({"noise_x": )" + noise +
           R"(, "noise_y": {"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 8}]},
               "colormap": {"type": "gaussian"}})";
}

}  // namespace

TEST(PatternSpec, ValidSpecParsesWithDefaults) {
    const PatternSpec s = parse(kValid);
    EXPECT_EQ(s.width, 512);
    EXPECT_EQ(s.scale, 1.0);
    EXPECT_EQ(s.offsets, OffsetMode::Independent);
    EXPECT_EQ(s.noise[1].spectrum.components[0].shape, SpectrumShape::Ring);
}

TEST(PatternSpec, ErrorsNameSourceAndJsonPointer) {
    EXPECT_NE(errorOf("{\"noise_x\": ").find("test.json: malformed JSON"), std::string::npos);
    EXPECT_NE(errorOf("{\"noise_x\": ").find("line 1"), std::string::npos);
    EXPECT_NE(
        errorOf(
            withNoiseX(R"({"type": "spectrum", "components": [{"shape": "ring", "frequency": -3, "bandwidth": 2}]})"))
            .find("test.json: /noise_x/components/0/frequency: must be in"),
        std::string::npos);
    EXPECT_NE(errorOf(withNoiseX(R"({"type": "spectrum", "components": [{"shape": "ringg", "frequency": 3}]})"))
                  .find("/noise_x/components/0/shape: unknown value \"ringg\""),
              std::string::npos);
    EXPECT_NE(
        errorOf(withNoiseX(R"({"type": "spectrum", "componets": []})")).find("/noise_x/componets: unknown member"),
        std::string::npos);
    EXPECT_NE(errorOf(withNoiseX(R"({"type": "spectrum", "components": []})"))
                  .find("/noise_x/components: needs at least one"),
              std::string::npos);
    EXPECT_NE(
        errorOf(withNoiseX(R"({"type": "spectrum", "size": "big", "components": [{"shape": "lowpass", "cutoff": 8}]})"))
            .find("/noise_x/size: expected an integer"),
        std::string::npos);
    EXPECT_NE(errorOf(R"({"noise_x": {}})").find("/noise_x: missing required member \"type\""), std::string::npos);
    EXPECT_NE(errorOf("[1, 2]").find("test.json: /: expected an object"), std::string::npos);
}

TEST(PatternSpec, SizesAreCapped) {
    std::string big = kValid;
    big.insert(1, "\"size\": 20000, ");
    EXPECT_NE(errorOf(big).find("/size: must be in [1, 16384]"), std::string::npos);
    std::string tooMany = kValid;
    tooMany.insert(1, "\"size\": [16384, 16384], ");
    // The pixel cap is the renderer's (validateView), re-raised at /size.
    EXPECT_EQ(errorOf(tooMany), "test.json: /size: size must be at most 67108864 pixels, got 16384x16384");
    std::string negative = kValid;
    negative.insert(1, "\"scale\": -2, ");
    EXPECT_NE(errorOf(negative).find("/scale: must be in"), std::string::npos);
}

TEST(JsonReader, LibraryParameterErrorsLandAtTheirMember) {
    const nlohmann::json j = nlohmann::json::parse(R"({"scale": 0, "inner": {"x": 1}})");
    const JsonReader r(j, "test.json");
    auto messageOf = [](const JsonReader& at, const InputError& thrown) {
        return std::string(test::inputErrorOf([&] { at.check([&] { throw thrown; }); }).what());
    };
    EXPECT_EQ(messageOf(r, InputError::parameter("scale", "must be > 0, got 0")),
              "test.json: /scale: scale must be > 0, got 0");
    // A parameter with no member of its name: the object's pointer.
    EXPECT_EQ(messageOf(r.at("inner"), InputError::parameter("y", "must be set")), "test.json: /inner: y must be set");
    // Not a parameter error: as it was.
    EXPECT_EQ(messageOf(r, InputError("a.png: no such file")), "a.png: no such file");
    EXPECT_NO_THROW(r.check([] {}));
}

TEST(PatternSpec, PaintedColormapValidation) {
    const std::string base = R"({"noise_x": {"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 8}]},
        "noise_y": {"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 8}]},
        "colormap": {"type": "painted", "shapes": [)";
    EXPECT_NE(errorOf(base + R"({"shape": "disc", "center": [0.5, 0.5], "radius": 0.1, "colour": "#12345"}]}})")
                  .find("/colormap/shapes/0/colour: invalid colour"),
              std::string::npos);
    EXPECT_NE(errorOf(base + R"({"shape": "polygon", "points": [[0, 0], [1, 1]], "colour": "#123456"}]}})")
                  .find("/colormap/shapes/0/points: a polygon needs at least 3 points"),
              std::string::npos);
    // One spelling: the American member name is an unknown member.
    EXPECT_NE(errorOf(base + R"({"shape": "disc", "center": [0.5, 0.5], "radius": 0.1, "color": "#123456"}]}})")
                  .find("/colormap/shapes/0/color: unknown member"),
              std::string::npos);
    const PatternSpec ok =
        parse(base + R"({"shape": "band", "point": [0.5, 0.5], "angle": 10, "width": 0.1, "colour": [1, 0.5, 0]}]}})");
    ASSERT_EQ(ok.colormap.painted.shapes.size(), 1u);
    EXPECT_FLOAT_EQ(ok.colormap.painted.shapes[0].colour[1], 0.5f);
}

// "offsets" and a phasor's "profile" are read through the enums' name tables
// (the ones the CLI and the bake manifest use).
TEST(PatternSpec, EnumValuedKeysUseTheNameTables) {
    const std::string noise = R"({"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 8}]})";
    const std::string base = R"({"noise_x": )" + noise + R"(, "noise_y": )" + noise;
    const std::string gaussian = R"(, "colormap": {"type": "gaussian"}})";
    EXPECT_EQ(parse(base + R"(, "offsets": "shared")" + gaussian).offsets, OffsetMode::Shared);
    EXPECT_EQ(parse(base + R"(, "offsets": "independent")" + gaussian).offsets, OffsetMode::Independent);
    EXPECT_EQ(errorOf(base + R"(, "offsets": "same")" + gaussian),
              "test.json: /offsets: unknown value \"same\" (expected one of: independent, shared)");
    const std::string phasor = R"(, "colormap": {"type": "phasor", "profile": ")";
    EXPECT_EQ(parse(base + phasor + R"(square"}})").colormap.profile, PhasorProfile::Square);
    EXPECT_EQ(parse(base + phasor + R"(sawtooth"}})").colormap.profile, PhasorProfile::Sawtooth);
    EXPECT_EQ(
        errorOf(base + phasor + R"(triangle"}})"),
        "test.json: /colormap/profile: unknown value \"triangle\" (expected one of: sine, sawtooth, square, image)");
    // The footprint estimator a file asks for (commands' --estimator overrides it).
    EXPECT_FALSE(parse(base + gaussian).estimator.has_value());
    EXPECT_EQ(parse(base + R"(, "estimator": "sub-probes-4x4")" + gaussian).estimator, VarianceEstimator::SubProbes4x4);
    EXPECT_EQ(errorOf(base + R"(, "estimator": "dh")" + gaussian),
              "test.json: /estimator: unknown value \"dh\" (did you mean deliot-heitz?) (expected one of: paper, "
              "deliot-heitz, sub-probes, sub-probes-4x4, sub-probes-8x8-fine-means)");
}

TEST(PatternSpec, QuadratureShorthandSharesSeedAndOffsets) {
    const PatternSpec s = loadPreset("phasor-stripes");
    EXPECT_TRUE(s.quadraturePair);
    EXPECT_EQ(s.offsets, OffsetMode::Shared);
    EXPECT_TRUE(s.noise[1].spectrum.quadrature);
    EXPECT_EQ(noiseSeed(s, 0), noiseSeed(s, 1));
    const PatternSpec camo = loadPreset("camouflage");
    EXPECT_NE(noiseSeed(camo, 0), noiseSeed(camo, 1));
}

TEST(Presets, RequiredPresetsExistAndBuild) {
    const auto names = presetNames();
    for (const char* required :
         {"gaussian", "ridged", "phasor-stripes", "camouflage", "marble", "concentric", "oblique-blots", "woven"})
        EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
    for (const auto& n : names) {
        const PatternSpec s = loadPreset(n);
        EXPECT_EQ(s.name, n);
        EXPECT_EQ(GraphPattern::build(s).exampleSize(), 256) << n;
    }
}

// A painted preset shows every colour it paints: a shape painted over by
// later shapes (bordered-blots' red and green edging once were) is a layout
// that does not match its description. Each shape's colour must own at least
// 1% of the colormap's entries (within 2/255 per channel: the table averages
// 4×4 samples per entry, so only edges mix); a 0.04-wide edging along two
// borders of a sector covers ~4%.
TEST(Presets, PaintedPresetsShowEveryColourTheyPaint) {
    const int resolution = 256;
    int painted = 0;
    for (const auto& name : presetNames()) {
        const PatternSpec spec = loadPreset(name);
        if (spec.colormap.source != ColormapSpec::Source::Painted) continue;
        ++painted;
        const PaintedColormap& layout = spec.colormap.painted;
        const ColormapTable table = layout.rasterize(resolution);
        for (size_t k = 0; k < layout.shapes.size(); ++k) {
            const Rgb want = layout.shapes[k].colour;
            int near = 0;
            for (int j = 0; j < resolution; ++j)
                for (int i = 0; i < resolution; ++i) {
                    const Rgb got = table.entry(i, j);
                    float d = 0;
                    for (size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(got[c] - want[c]));
                    if (d <= 2.0f / 255.0f) ++near;
                }
            EXPECT_GE(near, resolution * resolution / 100)
                << name << ": shape " << k << "'s colour (" << want[0] * 255 << ", " << want[1] * 255 << ", "
                << want[2] * 255 << ") covers " << near << " of " << resolution * resolution << " entries";
        }
    }
    EXPECT_GE(painted, 8);  // weld, camouflage, marble, bordered-blots and Figure 7's four at least
}

TEST(Presets, UnknownPresetListsTheKnownOnes) {
    try {
        loadPreset("nope");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown preset \"nope\""), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("camouflage"), std::string::npos);
    }
}

// A non-power-of-two exemplar is resampled up to the next power of two as the
// periodic image it is, so every filtered path can build its pyramids: its
// mean survives (bicubic keeps a periodic image's mean up to clamping) and the
// resampled image wraps without a seam (the periodic border is continuous).
TEST(PatternSpec, NonPowerOfTwoExemplarsAreResampledPeriodically) {
    const std::filesystem::path dir = test::scratchPath("npot-exemplar");
    std::filesystem::create_directories(dir);
    Image img(24, 24, 1);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x)
            img.at(x, y) = float(0.5 + 0.3 * std::sin(2 * M_PI * x / 24.0) * std::cos(2 * M_PI * 2 * y / 24.0));
    writeImage((dir / "e24.png").string(), img, WriteOptions{.bitDepth = 16, .transfer = Transfer::Linear});
    NoiseSpec spec;
    spec.source = NoiseSpec::Source::Image;
    spec.image = dir / "e24.png";
    const Image e = buildExampleImage(spec, "test");
    ASSERT_EQ(e.width(), 32);
    ASSERT_EQ(e.height(), 32);
    double mean = 0, maxStep = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            mean += e.at(x, y) / 1024.0;
            // Neighbour steps, the wrap-around pair (31 → 0) included: a seam
            // would be a step far above the smooth image's (≤ 2π·0.3·2/32 ≈ 0.12).
            maxStep = std::max(maxStep, double(std::abs(e.at((x + 1) % 32, y) - e.at(x, y))));
            maxStep = std::max(maxStep, double(std::abs(e.at(x, (y + 1) % 32) - e.at(x, y))));
        }
    EXPECT_NEAR(mean, 0.5, 2e-3);
    EXPECT_LT(maxStep, 0.13);
    // Texel centres map to texel centres: the value at resampled texel 0 is the
    // source's at −½ + ½·24/32 = −0.125 texel. Within 4e-3 (bicubic's own error
    // on this wave, measured 3.1e-3); corner-aligned sampling (source texel 0,
    // value 0.5) would be 9.8e-3 off.
    EXPECT_NEAR(e.at(0, 0), 0.5 + 0.3 * std::sin(2 * M_PI * -0.125 / 24.0) * std::cos(2 * M_PI * 2 * -0.125 / 24.0),
                4e-3);
    std::filesystem::remove_all(dir);
}

// The noise command writes what render accepts: a spectral example must have a
// power-of-two size, refused at parse time with the reason.
TEST(PatternSpec, SpectralExampleSizesArePowersOfTwo) {
    const std::string e =
        errorOf(withNoiseX(R"({"type": "spectrum", "size": 300, "components": [{"shape": "lowpass", "cutoff": 8}]})"));
    EXPECT_NE(e.find("/noise_x/size: must be a power of two"), std::string::npos) << e;
}

// The pattern file's numbers are read through their table entries
// (pattern_members.h), the same ones the workbench's widgets are drawn from:
// each member accepts its typical value and refuses one just past either
// end of the entry's range, naming the member's pointer.
TEST(PatternMembers, TheParserEnforcesEachTableEntrysRange) {
    struct Case {
        const char* preset;
        const char* pointer;
        const ParamInfo& member;
    };
    const Case cases[] = {
        {"bands", "/scale", patternMembers().scale},
        {"bands", "/grid_density", patternMembers().gridDensity},
        {"bands", "/noise_x/size", patternMembers().noiseSize},
        {"bands", "/noise_x/mean", patternMembers().noiseMean},
        {"bands", "/noise_x/stddev", patternMembers().noiseStddev},
        {"bands", "/noise_x/components/0/cutoff", patternMembers().cutoff},
        {"bands", "/noise_x/components/0/weight", patternMembers().weight},
        {"iso-aniso", "/noise_y/components/0/frequency", patternMembers().frequency},
        {"iso-aniso", "/noise_y/components/0/bandwidth", patternMembers().bandwidth},
        {"iso-aniso", "/noise_y/components/0/orientation", patternMembers().orientation},
        {"camouflage", "/colormap/resolution", patternMembers().colormapResolution},
        {"camouflage", "/colormap/shapes/2/radius", patternMembers().radius},
        {"camouflage", "/colormap/shapes/0/angle", patternMembers().angle},
        {"concentric", "/colormap/shapes/1/inner", patternMembers().inner},
        {"concentric", "/colormap/shapes/1/outer", patternMembers().outer},
        {"oblique-blots", "/colormap/shapes/2/width", patternMembers().width},
        {"phasor-square", "/colormap/duty", patternMembers().duty},
        {"lean-ridges", "/normal_map/amplitude", patternMembers().amplitude},
        {"lean-ridges", "/normal_map/roughness", patternMembers().roughness},
        {"lean-ridges", "/normal_map/specular", patternMembers().specular},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.preset) + " " + c.pointer);
        const nlohmann::json base = nlohmann::json::parse(presetText(c.preset));
        const bool integer = c.member.type == ParamType::Integer;
        const auto parseWith = [&](double v) {
            nlohmann::json j = base;
            j[nlohmann::json::json_pointer(c.pointer)] = integer ? nlohmann::json(std::llround(v)) : nlohmann::json(v);
            return parsePatternSpec(JsonReader(j, "t.json"), ".");
        };
        EXPECT_NO_THROW(parseWith(c.member.typical()));
        const double step = integer ? 1.0 : std::max(1.0, std::abs(c.member.max)) * 1e-6;
        // The refusal states the table's range: the parser's range is the entry's.
        const std::string range = "must be in [" + formatValue(c.member.min) + ", " + formatValue(c.member.max) + "]";
        for (double outside : {c.member.min - step, c.member.max + step}) {
            const std::string message = test::inputErrorOf([&] { parseWith(outside); }).what();
            EXPECT_NE(message.find(std::string(c.pointer) + ": "), std::string::npos) << message;
            EXPECT_NE(message.find(range), std::string::npos) << message;
        }
    }
    // The graph's spectral noise takes the same entries as a pattern's noise.
    const NodeInfo* noise = findGraphNode("spectral_noise");
    ASSERT_NE(noise, nullptr);
    for (const ParamInfo* p :
         {&patternMembers().noiseSize, &patternMembers().noiseMean, &patternMembers().noiseStddev}) {
        const auto it = std::find_if(noise->params.begin(), noise->params.end(),
                                     [&](const ParamInfo& q) { return q.name == p->name; });
        ASSERT_NE(it, noise->params.end());
        EXPECT_EQ(it->min, p->min);
        EXPECT_EQ(it->max, p->max);
        EXPECT_EQ(it->fallback, p->fallback);
    }
}
