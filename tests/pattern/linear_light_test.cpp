// Colour is linear light (docs/MATH.md, "Colour space"): colours enter
// sRGB-encoded and are decoded once into the table H, every average (H̄, the
// reference S̄, lookups) is of linear values, and a PNG holds sRGB codes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "stochtex/image/colour_space.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/pattern_spec.h"
#include "test_util.h"

namespace stochtex {
namespace {

PatternSpec specFromText(const std::string& text, const std::filesystem::path& dir = ".") {
    return parsePatternSpec(JsonReader(JsonReader::parse(text, "test"), "test"), dir);
}

std::string patternText(const std::string& colormap) {
    return R"({"name": "half", "seed": 5, "size": 4,
        "noise_x": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 12}]},
        "noise_y": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 12}]},
        "colormap": )" + colormap + "}";
}

// Black left of x = ½, white right of it: N_x (mean ½, a Gaussian) falls on
// either side half the time.
const std::string kBlackWhite = R"({"type": "painted", "background": "#000000",
    "shapes": [{"shape": "halfplane", "colour": "#ffffff", "point": [0.5, 0], "angle": -90}]})";

class LinearLight : public test::ScratchFolder {};

// Seen through a footprint of 4 example periods a pixel, the pattern is half
// black, half white: linear ½, which the PNG writes as code 188 (an average
// of sRGB codes, as before, wrote 128).
TEST_F(LinearLight, HalfBlackHalfWhiteIsLinearHalfAndCode188InThePng) {
    const GraphPattern p = GraphPattern::build(specFromText(patternText(kBlackWhite)));
    Camera cam;
    cam.view.width = cam.view.height = 4;
    cam.view.scale = 4 * 64;  // texels per pixel
    for (const char* filter : {"smooth", "paper", "exact", "reference"}) {
        FilterOptions o;
        o.use(parseFilter(filter));
        const Image img = FilteredGraph(p, o).render(cam);
        const std::string file = (dir_ / (std::string(filter) + ".png")).string();
        writeImage(file, img);
        const Image png = readImage(file);
        // The estimators' μ̂, σ̂ over 4 periods are the example's (mean ½ within
        // 1e-5), so H̄ is ½ up to the table's sampling of the edge: ±1 code
        // (8-bit rounding of 0.7354 · 255 = 187.5). The exact statistics and the
        // reference see the tiled noise itself, whose share of white in one
        // pixel differs from ½ by the realisation (up to 0.025 here): their
        // codes are the encode of their own values, and the mean is ½.
        const bool fromEstimators = std::string(filter) == "smooth" || std::string(filter) == "paper";
        double sum = 0;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const float v = img.at(x, y, 0), code = 255.0f * png.at(x, y, 1);
                sum += v;
                EXPECT_NEAR(v, 0.5, fromEstimators ? 0.004 : 0.03) << filter << " (" << x << ", " << y << ")";
                EXPECT_NEAR(code, fromEstimators ? 188.0f : 255.0f * srgbFromLinear(v), fromEstimators ? 1.0f : 0.5f)
                    << filter << " (" << x << ", " << y << ")";
            }
        EXPECT_NEAR(sum / 16, 0.5, 0.015) << filter;
    }
}

TEST_F(LinearLight, ColoursAreDecodedOnceWhereTheyEnterTheTable) {
    // Hex #808080 is code 128: linear 0.2158 in the table, as given with "transfer": "linear".
    const std::string grey = R"({"type": "painted", "resolution": 8, "background": "#808080"%s})";
    const auto table = [&](const std::string& transfer) {
        std::string t = grey;
        t.replace(t.find("%s"), 2, transfer);
        return buildColormap(specFromText(patternText(t)).colormap);
    };
    EXPECT_NEAR(table("").entry(3, 4)[0], 0.2158605, 1e-6);
    EXPECT_NEAR(table(R"(, "transfer": "srgb")").entry(3, 4)[1], 0.2158605, 1e-6);
    EXPECT_FLOAT_EQ(table(R"(, "transfer": "linear")").entry(3, 4)[2], 128.0f / 255.0f);
    // The analytic H = x is sRGB-encoded too: entry x = ½ is linear 0.2140.
    const ColormapTable g = buildColormap(specFromText(patternText(R"({"type": "gaussian", "resolution": 3})")).colormap);
    EXPECT_NEAR(g.entry(1, 0)[0], 0.2140411, 1e-6);
    EXPECT_THROW(specFromText(patternText(R"({"type": "gaussian", "transfer": "gamma"})")), InputError);
}

TEST_F(LinearLight, ColormapImagesPngDecodedExrLinearAndTheColormapRoundTrips) {
    // A table written as PNG (sRGB codes) or EXR (linear) reads back as the same linear table.
    Image mid(4, 4, 3, 0.5f);
    writeImage((dir_ / "mid.png").string(), mid);
    writeImage((dir_ / "mid.exr").string(), mid);
    for (const char* file : {"mid.png", "mid.exr"}) {
        const ColormapTable t = buildColormap(
            specFromText(patternText(R"({"type": "image", "path": ")" + std::string(file) + "\"}"), dir_).colormap);
        // 3e-3: the PNG's 8-bit code 188 is linear 0.5029.
        EXPECT_NEAR(t.entry(1, 2)[0], 0.5, 3e-3) << file;
    }
    // Declared as data, the PNG's code 188 is taken as it is.
    const ColormapTable data = buildColormap(
        specFromText(patternText(R"({"type": "image", "path": "mid.png", "transfer": "linear"})"), dir_).colormap);
    EXPECT_FLOAT_EQ(data.entry(0, 0)[0], 188.0f / 255.0f);
}

}  // namespace
}  // namespace stochtex
