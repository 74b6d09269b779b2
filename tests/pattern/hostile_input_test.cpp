// Hostile input (issue "Defects found under hostile input", items 8–10, 12
// and 16): each is an InputError naming the input and the problem, never a
// crash, and refused before the work it would cost.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/kernel/sigma_levels.h"
#include "stochtex/noise/gaussianize.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/ops/ops.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "test_util.h"

using namespace stochtex;
namespace fs = std::filesystem;

namespace {

std::string parseError(const std::string& text) {
    return test::inputErrorOf([&] { (void)JsonReader::parse(text, "test.json"); }).what();
}

std::string patternError(const std::string& text) {
    return test::inputErrorOf([&] {
               const auto j = JsonReader::parse(text, "test.json");
               (void)parsePatternSpec(JsonReader(j, "test.json"), ".");
           })
        .what();
}

const char* kSpectrum = R"({"type": "spectrum", "size": 16, "components": [{"shape": "lowpass", "cutoff": 4}]})";

std::string pattern(const std::string& noiseX, const std::string& colormap) {
    return R"({"noise_x": )" + noiseX + R"(, "noise_y": )" + kSpectrum + R"(, "colormap": )" + colormap + "}";
}

// A folder of its own with a 16×16 float EXR holding `value` at pixel (3, 5).
struct ExrFixture {
    fs::path dir = test::scratchPath("hostile_exr");
    explicit ExrFixture(int channels, float value) {
        fs::create_directories(dir);
        Image img(16, 16, channels, 0.5f);
        img.at(3, 5, channels - 1) = value;
        writeImage((dir / "in.exr").string(), img);
    }
    ~ExrFixture() { fs::remove_all(dir); }
    std::string path() const { return (dir / "in.exr").string(); }
};

}  // namespace

// Item 9: 100 000 nested arrays overflowed the stack when the error message
// dumped the value; the depth is capped while parsing.
TEST(HostileJson, DeepNestingIsRefusedWhileParsing) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    const std::string e = parseError(deep);
    EXPECT_NE(e.find("test.json: /0/0/0/"), std::string::npos) << e;
    EXPECT_NE(e.find("nested deeper than 64 levels"), std::string::npos) << e;
    // 64 levels are still read.
    EXPECT_NO_THROW(JsonReader::parse(std::string(64, '[') + std::string(64, ']'), "test.json"));
}

// Item 9: no message shows a whole container.
TEST(HostileJson, MessagesDescribeContainersWithoutDumpingThem) {
    std::string big = "[1";
    for (int i = 0; i < 10000; ++i) big += ", 1";
    big += "]";
    const std::string e = patternError(pattern(kSpectrum, R"({"type": "painted", "shapes": {"a": )" + big + "}}"));
    EXPECT_EQ(e, "test.json: /colormap/shapes: expected an array, got an object of 1 members");
}

// Item 10: 1e400 was "internal error" (exit 1) without the file's name.
TEST(HostileJson, NumberOverflowingADoubleIsAnInputErrorAtItsPointer) {
    EXPECT_EQ(parseError(R"({"a": [1, {"b": 1e400}]})"),
              "test.json: /a/1/b: number 1e400 is out of the range of a double (line 1, column 21)");
    EXPECT_EQ(parseError("[1, -1e400]"),
              "test.json: /1: number -1e400 is out of the range of a double (line 1, column 10)");
    // Syntax errors keep their line and column.
    EXPECT_EQ(parseError("{\n  \"a\": }").rfind("test.json: malformed JSON: parse error at line 2, column 8", 0), 0u);
}

// Item 16: the DOM parser keeps the last of two equal keys, silently.
TEST(HostileJson, DuplicateMembersAreRefused) {
    EXPECT_EQ(parseError(R"({"noise_x": {"size": 16, "size": 32}})"),
              R"(test.json: /noise_x/size: member "size" given twice)");
    // The same key in two objects is fine.
    EXPECT_NO_THROW(JsonReader::parse(R"([{"a": 1}, {"a": 2}])", "test.json"));
}

// Item 16: unsigned integers beyond long long were shown as −1.
TEST(HostileJson, LargeIntegersAreShownAsWritten) {
    EXPECT_EQ(patternError(R"({"seed": 18446744073709551615})"),
              "test.json: /seed: must be in [0, 4294967295], got 18446744073709551615");
    EXPECT_EQ(patternError(pattern(R"({"type": "spectrum", "size": 9223372036854775808, "components": []})", "{}")),
              "test.json: /noise_x/size: must be in [8, 4096], got 9223372036854775808");
    // Every seed takes the whole uint32 range.
    const std::string top =
        pattern(R"({"type": "spectrum", "seed": 4294967295, "components": [{"shape": "lowpass", "cutoff": 4}]})",
                R"({"type": "gaussian"})");
    const auto j = JsonReader::parse(R"({"seed": 4294967295, )" + top.substr(1), "test.json");
    const PatternSpec s = parsePatternSpec(JsonReader(j, "test.json"), ".");
    EXPECT_EQ(s.seed, 4294967295u);
    EXPECT_EQ(s.noise[0].spectrum.seed, 4294967295u);
}

// Item 12: a 100 MB file cost 1.8 GB; the text is refused by its size.
TEST(HostileJson, TextOverTheSizeLimitIsRefusedBeforeParsing) {
    const std::string big = "[" + std::string(kMaxJsonBytes, ' ') + "]";
    EXPECT_EQ(parseError(big), "test.json: " + std::to_string(kMaxJsonBytes + 2) + " bytes of JSON; the limit is " +
                                   std::to_string(kMaxJsonBytes) + " bytes");
    const fs::path file = test::scratchPath("hostile_big.json");
    std::ofstream(file) << big;
    const std::string e = test::inputErrorOf([&] { readJsonFile(file.string()); }).what();
    fs::remove(file);
    EXPECT_EQ(e, file.string() + ": " + std::to_string(kMaxJsonBytes + 2) + " bytes of JSON; the limit is " +
                     std::to_string(kMaxJsonBytes) + " bytes");
}

// Item 16: a folder given as the pattern said "no such file".
TEST(HostileJson, AFolderIsNotAPatternFile) {
    const std::string dir = fs::temp_directory_path().string();
    EXPECT_EQ(std::string(test::inputErrorOf([&] { loadPatternFile(dir); }).what()),
              dir + ": is a folder, not a JSON file");
}

// Item 12: the work budget, each product named by its parameter and re-raised
// at its JSON member.
TEST(WorkBudget, SpectrumComponentsTimesSizeSquaredIsCapped) {
    std::string comps;
    for (int i = 0; i < 17; ++i) comps += std::string(i ? ", " : "") + R"({"shape": "lowpass", "cutoff": 4})";
    const std::string noise = R"({"type": "spectrum", "size": 4096, "components": [)" + comps + "]}";
    EXPECT_EQ(patternError(pattern(noise, R"({"type": "gaussian"})")),
              "test.json: /noise_x/components: components × size² must be at most 268435456, got 17 × 4096² = "
              "285212672");
    SpectrumSpec s = test::spectrumSpec(SpectrumShape::LowPass, 4, 1, 0, 1, 4096);
    s.components.resize(16, s.components[0]);
    EXPECT_NO_THROW(validateSpectrumWork(s));  // 16 × 4096² is the limit itself
    s.components.push_back(s.components[0]);
    EXPECT_EQ(test::inputErrorOf([&] { synthesizeExample(s); }).parameter(), "components");
}

TEST(WorkBudget, PaintedShapesTimesResolutionSquaredIsCapped) {
    std::string shapes;
    for (int i = 0; i < 1000; ++i)
        shapes += std::string(i ? ", " : "") +
                  R"({"shape": "disc", "center": [0.5, 0.5], "radius": 0.1, "colour": "#ff0000"})";
    const std::string e =
        patternError(pattern(kSpectrum, R"({"type": "painted", "resolution": 4096, "shapes": [)" + shapes + "]}"));
    EXPECT_EQ(e.rfind("test.json: /colormap/shapes: shapes cost 1000 shape tests", 0), 0u) << e;
    EXPECT_NE(e.find("the limit is 4294967296"), std::string::npos) << e;
    // A polygon costs a test per vertex: 1000 vertices at 1024 are 1.7e10 tests.
    PaintedColormap painted;
    PaintedShape polygon;
    polygon.kind = PaintedShape::Kind::Polygon;
    for (int i = 0; i < 1000; ++i) polygon.points.push_back({0.5 + 0.4 * std::cos(i), 0.5 + 0.4 * std::sin(i)});
    painted.shapes = {polygon};
    EXPECT_EQ(painted.edges(), 1000);
    EXPECT_EQ(test::inputErrorOf([&] { painted.rasterize(1024); }).parameter(), "shapes");
    EXPECT_NO_THROW(painted.validateWork(512));  // 512² × 16 × 1000 = 4.19e9 ≤ 2³²
}

TEST(WorkBudget, PrefilteredResolutionIsCapped) {
    const InputError e = test::inputErrorOf(
        [] { PrefilteredColormap(makeAnalyticColormap(AnalyticColormap::Ridged, 1025), PrefilterMode::Smooth); });
    EXPECT_EQ(e.parameter(), "resolution");
    EXPECT_STREQ(e.what(), "resolution must be at most 1024 per side to be prefiltered, got 1025x1025");
    EXPECT_NO_THROW(validatePrefilteredResolution(1024, 1024));
}

// Item 8: a 1e20 in a float exemplar made E² inf, the variance inf − inf, σ
// NaN and int(NaN) a layer far out of the table: every filtered path crashed.
TEST(HostileImages, ExemplarValuesOutsideTheNoiseDomainAreRefused) {
    // (NaN and inf are refused by readImage already.)
    for (float bad : {1e20f, -0.5f, 1.5f}) {
        const ExrFixture exr(1, bad);
        NoiseSpec spec;
        spec.source = NoiseSpec::Source::Image;
        spec.image = exr.path();
        const std::string e = test::inputErrorOf([&] { buildNoiseExample(spec, "test.json"); }).what();
        EXPECT_EQ(
            e, exr.path() + ": pixel (3, 5) channel 0 is " + formatValue(bad) + "; exemplar values must be in [0, 1]");
    }
}

TEST(HostileImages, ColormapValuesBeyondHalfFloatAreRefused) {
    const ExrFixture exr(3, 1e20f);
    ColormapSpec spec;
    spec.source = ColormapSpec::Source::Image;
    spec.image = exr.path();
    EXPECT_EQ(std::string(test::inputErrorOf([&] { buildColormap(spec); }).what()),
              exr.path() + ": pixel (3, 5) channel 2 is 1e+20; colormap values must be in [-65504, 65504]");
    const ExrFixture hdr(3, 100.0f);  // HDR colours are kept
    spec.image = hdr.path();
    EXPECT_NO_THROW(buildColormap(spec));
}

// Item 8, second half: a NaN that still reaches a lookup reads an edge of
// the table (level 0, the first entry), never an index computed from NaN.
TEST(HostileImages, LookupsClampNaNBeforeAnyIntegerConversion) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (bool paper : {true, false}) {
        EXPECT_EQ(kernel::sigmaLevelCoordinate(nan, paper, 10), 0.0f);
        EXPECT_EQ(kernel::sigmaLevelCoordinate(-nan, paper, 10), 0.0f);
        EXPECT_EQ(kernel::sigmaLevelCoordinate(std::numeric_limits<float>::infinity(), paper, 10), 9.0f);
        const kernel::LayerBlend b = kernel::layerBlend(kernel::vec2(nan, nan), paper, 10);
        EXPECT_EQ(b.k0.x, 0);
        EXPECT_EQ(b.k0.y, 0);
    }
    const ColormapTable h = makeAnalyticColormap(AnalyticColormap::Gaussian, 16);  // H = x
    EXPECT_EQ(h.sample(nan, 0.5f)[0], 0.0f);
    const PrefilteredColormap table(h, PrefilterMode::Smooth);
    const Rgb c = table.sample(0.75f, 0.5f, nan, nan);
    EXPECT_EQ(c, table.layer(0, 0).sample(0.75f, 0.5f));  // σ NaN reads the unblurred layer
    HistogramTransform t = HistogramTransform::fit(test::example(SpectrumShape::LowPass, 4, 1, 0, 1, 16));
    EXPECT_EQ(t.inverse(nan), t.inverse(0.0f));
}

namespace {

// A spectral noise seen through `count` transform nodes, each with the
// given members, colour-mapped with the noise itself.
std::string transformChain(int count, const std::string& members) {
    std::string nodes =
        R"("n0": {"type": "spectral_noise", "size": 16, "components": [{"shape": "ring", "frequency": 4, "bandwidth": 1}]})";
    std::string previous = "n0";
    for (int i = 1; i <= count; ++i) {
        std::string id = "t";  // not "t" + to_string(i), on which GCC 12 warns falsely (-Wrestrict)
        id += std::to_string(i);
        nodes += R"(, ")" + id + R"(": {"type": "transform", "input": ")" + previous + R"(", )" + members + "}";
        previous = id;
    }
    return R"({"name": "chain", "size": 16, "nodes": {)" + nodes + R"(, "c": {"type": "colormap", "x": ")" + previous +
           R"(", "y": "n0", "colormap": {"type": "gaussian"}}}, "output": "c"})";
}

PatternSpec parseSpec(const std::string& text) {
    const auto j = JsonReader::parse(text, "test.json");
    return parsePatternSpec(JsonReader(j, "test.json"), ".");
}

std::string buildError(const std::string& text) {
    return test::inputErrorOf([&] { (void)GraphPattern::build(parseSpec(text)); }).what();
}

}  // namespace

// Issue "Hostile input on the new surfaces", item 1: chained transform
// nodes, each in its documented range, composed a uv scale that overflows
// float (SIGSEGV in the CPU's lookups, "inf.0" in the generated GLSL). The
// composition is refused at the node where it leaves what one node may do.
TEST(HostileGraph, ComposedTransformsBeyondOneNodesRangeAreRefusedAtTheNode) {
    EXPECT_NO_THROW((void)GraphPattern::build(parseSpec(transformChain(1, R"("scale": 64)"))));
    EXPECT_NO_THROW(
        (void)GraphPattern::build(parseSpec(transformChain(6, R"("scale": 2, "angle": 33)"))));  // 64 in all
    for (int count : {2, 5, 40, 172})
        EXPECT_EQ(buildError(transformChain(count, R"("scale": 64)")),
                  "chain: node \"t2\" (transform): /nodes/t2/scale: composed with the transforms it reads, uv is "
                  "scaled by 4096; a chain of transform nodes may scale it by [1/64, 64] in all")
            << count;
    EXPECT_NE(buildError(transformChain(7, R"("scale": 2, "angle": 33)")).find("/nodes/t7/scale: "), std::string::npos);
    EXPECT_NE(buildError(transformChain(2, R"("scale": 0.015625)")).find("/nodes/t2/scale: "), std::string::npos);
    // Offsets add up through the scales before them: 2·5000 + 5000 along v.
    EXPECT_EQ(buildError(transformChain(2, R"("scale": 2, "offset_v": 5000)")),
              "chain: node \"t2\" (transform): /nodes/t2/offset_v: composed with the transforms it reads, uv is offset "
              "by 15000 example periods; a chain of transform nodes may offset it by at most 1e4 in all");
}

// What the bound lets through renders under every filter and both views at
// the camera's own extremes (scale 1e6 texels per pixel, offset 1e9 texels,
// a plane tilted 89°) with no undefined behaviour (the sanitizer build runs
// this) and a finite image.
TEST(HostileGraph, TheExtremeTransformAtTheExtremeCameraRendersFinite) {
    const GraphPattern program = GraphPattern::build(
        parseSpec(transformChain(1, R"("scale": 64, "angle": -360, "offset_u": 1e4, "offset_v": -1e4)")));
    Camera zoom;
    zoom.view = View{4, 3, 1e6, 1e9, -1e9};
    Camera plane = zoom;
    plane.kind = Camera::Kind::Plane;
    plane.tiltDeg = 89;
    for (const Camera& camera : {zoom, plane})
        for (const auto& [name, filter] : kFilterNames) {
            FilterOptions options;
            options.use(filter);
            options.referenceMaxSamples = 4;
            const Image image = FilteredGraph(program, options).render(camera);
            for (const float x : image.data()) ASSERT_TRUE(std::isfinite(x)) << name;
        }
}

// GLSL has no literal for a non-finite number: the writer refuses one.
TEST(HostileGraph, NoNonFiniteLiteralReachesGlsl) {
    EXPECT_EQ(glslFloat(64.0f), "64.0");
    EXPECT_THROW((void)glslFloat(std::numeric_limits<float>::infinity()), std::logic_error);
    EXPECT_THROW((void)glslFloat(std::numeric_limits<float>::quiet_NaN()), std::logic_error);
}

// Item 2: linear nodes multiply their scales; 20 affines at scale 100
// overflowed float in the folded example and rendered black with exit 0.
// The fold is refused at the node where the field leaves half float's range.
TEST(HostileGraph, ALinearChainThatOverflowsIsRefusedAtItsNode) {
    std::string nodes =
        R"("n0": {"type": "spectral_noise", "size": 16, "components": [{"shape": "ring", "frequency": 4, "bandwidth": 1}]})";
    std::string previous = "n0";
    for (int i = 1; i <= 20; ++i) {
        std::string id = "a";  // not "a" + to_string(i), on which GCC 12 warns falsely (-Wrestrict)
        id += std::to_string(i);
        nodes += R"(, ")" + id + R"(": {"type": "affine", "input": ")" + previous + R"(", "scale": 100})";
        previous = id;
    }
    const std::string text = R"({"name": "chain", "size": 16, "nodes": {)" + nodes +
                             R"(, "c": {"type": "colormap", "x": ")" + previous +
                             R"(", "y": "n0", "colormap": {"type": "gaussian"}}}, "output": "c"})";
    const std::string e = buildError(text);
    EXPECT_EQ(e.find("chain: node \"a3\" (affine): pixel ("), 0u) << e;  // 100³ · a value near 0.5
    EXPECT_NE(e.find("; its field's values must be in [-65504, 65504]"), std::string::npos) << e;
}

// The same through the per-pixel ops, which no fold sees: an affine to
// values near 200 squared eight times overflowed float and rendered white
// with exit 0. Refused at the op whose values can leave half float's range;
// a chain that stays in range (squares of values below 1: half a noise of
// mean 0.5, whose blends stay within 0.5 ± 1.2) is built.
TEST(HostileGraph, AnOpChainThatOverflowsIsRefusedAtItsNode) {
    const auto squares = [](int count, const std::string& affine) {
        std::string nodes =
            R"("n0": {"type": "spectral_noise", "size": 16, "components": [{"shape": "ring", "frequency": 4, "bandwidth": 1}]}, )"
            R"("a": {"type": "affine", "input": "n0", )" +
            affine + "}";
        std::string previous = "a";
        for (int i = 1; i <= count; ++i) {
            std::string id = "s";
            id += std::to_string(i);
            nodes += R"(, ")" + id + R"(": {"type": "square", "input": ")" + previous + R"("})";
            previous = id;
        }
        return R"({"name": "squares", "size": 16, "nodes": {)" + nodes + R"(, "c": {"type": "colormap", "x": ")" +
               previous + R"(", "y": "n0", "colormap": {"type": "gaussian"}}}, "output": "c"})";
    };
    EXPECT_NO_THROW((void)GraphPattern::build(parseSpec(squares(12, R"("scale": 0.5)"))));
    // Values near 100: squared about 1e4, then 1e8, past 65504.
    const std::string e = buildError(squares(3, R"("scale": 1, "offset": 100)"));
    EXPECT_EQ(e.find("squares: node \"s2\" (square): its values may reach "), 0u) << e;
    EXPECT_NE(e.find("; a node's values must be in [-65504, 65504]"), std::string::npos) << e;
}

// A table op's values peak where its entries do, not at its inputs' ends: a
// curve up to 100 and down again is 0 at both ends of a noise's range, so
// its ends alone would let two squares (1e4, then 1e8) through.
TEST(HostileGraph, ATableOpsRangeIsItsEntries) {
    const std::string text =
        R"({"name": "peak", "size": 16, "nodes": {)"
        R"("n": {"type": "spectral_noise", "size": 16, "components": [{"shape": "ring", "frequency": 4, "bandwidth": 1}]}, )"
        R"("k": {"type": "curve", "input": "n", "points": [[0, 0], [0.5, 100], [1, 0]]}, )"
        R"("q1": {"type": "square", "input": "k"}, "q2": {"type": "square", "input": "q1"}, )"
        R"("c": {"type": "colormap", "x": "q2", "y": "n", "colormap": {"type": "gaussian"}}}, "output": "c"})";
    const std::string e = buildError(text);
    EXPECT_EQ(e.find("peak: node \"q2\" (square): its values may reach 9.8"), 0u)
        << e;  // 99.2⁴: the table's highest entry
}
