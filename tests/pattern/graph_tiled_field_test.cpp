// The tiled_field source and its channel nodes (graph_nodes.h): K channels
// of one image tiled and blended on the same tiles, so that relations
// between the channels hold in the pattern; their transfer functions; the
// compose node; the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "test_util.h"

namespace stochtex {
namespace {

namespace fs = std::filesystem;

std::string parseError(const std::string& text) {
    try {
        (void)GraphPattern::build(test::parsePatternText(text));
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

class TiledFieldNode : public test::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        // A float image (linear): green = 1 − red, blue another pattern.
        Image img(64, 64, 3);
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const float r = float(0.5 + 0.35 * std::sin(0.3 * x + 0.2 * y) * std::cos(0.25 * y));
                img.at(x, y, 0) = r;
                img.at(x, y, 1) = 1.0f - r;
                img.at(x, y, 2) = float(0.5 + 0.3 * std::cos(0.4 * x));
            }
        exr_ = (dir_ / "rgb.exr").string();
        writeImage(exr_, img);
    }

    // The image's channels 0 and 1 as red and green; from one tiled field,
    // or (control) from two tiled_field nodes of the same file.
    std::string graph(bool oneField) const {
        return R"({"name": "g", "seed": 4, "nodes": {
            "t": {"type": "tiled_field", "path": ")" + exr_ + R"(", "gaussianize": false},
            "t2": {"type": "tiled_field", "path": ")" + exr_ + R"(", "gaussianize": false},
            "n": {"type": "spectral_noise", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]},
            "r": {"type": "channel", "field": "t", "index": 0},
            "g": {"type": "channel", "field": ")" + std::string(oneField ? "t" : "t2") + R"(", "index": 1},
            "c": {"type": "compose", "r": "r", "g": "n", "b": "g"}}, "output": "c"})";
    }

    std::string exr_;
};

// Red + green = 1 in the image, so in the pattern exactly when both see the
// same tiles and weights (tiling and blending is linear in the example,
// mean included), unfiltered and filtered; two tiled_field nodes of the same
// file are two tilings, and the relation breaks (the test can fail).
TEST_F(TiledFieldNode, ChannelsOfOneFieldShareTilesSoTheirRelationHolds) {
    const GraphPattern g = GraphPattern::build(test::parsePatternText(graph(true)));
    ASSERT_EQ(g.leafCount(), 3);  // r, n, g: the noise between two channels of one field
    EXPECT_EQ(g.leaf(0).offsetSeed(), g.leaf(2).offsetSeed());
    EXPECT_NE(g.leaf(1).offsetSeed(), g.leaf(0).offsetSeed());
    const auto maxDeviation = [](const Image& img) {
        double worst = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) worst = std::max(worst, std::abs(img.at(x, y, 0) + img.at(x, y, 2) - 1.0));
        return worst;
    };
    Camera cam;
    cam.view = {48, 40, 1.7, 11.0, -3.0};
    EXPECT_LT(maxDeviation(g.render(cam.view)), 1e-5);
    FilterOptions smooth;
    smooth.use(parseFilter("smooth"));
    cam.view.scale = 9.0;
    EXPECT_LT(maxDeviation(FilteredGraph(g, smooth).render(cam)), 1e-4);

    const GraphPattern two = GraphPattern::build(test::parsePatternText(graph(false)));
    EXPECT_NE(two.leaf(0).offsetSeed(), two.leaf(2).offsetSeed());
    cam.view.scale = 1.7;
    EXPECT_GT(maxDeviation(two.render(cam.view)), 0.1);
}

// An integer image's colour channels are sRGB codes decoded to linear light
// (transfer auto or srgb), alpha stays data, and "linear" takes codes as data.
TEST_F(TiledFieldNode, TransferDecodesColourChannelsButNotAlpha) {
    Image img(16, 16, 4);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 4; ++c) img.at(x, y, c) = float((x * 16 + y * 3 + c * 40) % 256) / 255.0f;
    const std::string png = (dir_ / "rgba.png").string();
    writeImage(png, img, kNoTransfer);
    for (const std::string transfer : {"auto", "srgb", "linear"})
        for (const int channel : {1, 3}) {
            const std::string text = R"({"name": "g", "nodes": {
                "t": {"type": "tiled_field", "path": ")" + png + R"(", "gaussianize": false, "transfer": ")" + transfer + R"("},
                "k": {"type": "channel", "field": "t", "index": )" + std::to_string(channel) + R"(},
                "c": {"type": "colormap", "x": "k", "y": "k", "colormap": {"type": "gaussian"}}}, "output": "c"})";
            const PatternSpec spec = test::parsePatternText(text);
            const NoiseExample e = buildGraphField(*spec.graph, "k", spec.seed, "g");
            const bool decoded = transfer != "linear" && channel < 3;
            double worst = 0;
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) {
                    const float code = img.at(x, y, channel);
                    worst = std::max(worst, double(std::abs(e.values().at(x, y) - (decoded ? linearFromSrgb(code) : code))));
                }
            EXPECT_LT(worst, 1e-6) << transfer << ", channel " << channel;
        }
}

TEST_F(TiledFieldNode, RefusesMissingChannelsAndTiledFieldsWhereAFieldGoes) {
    const std::string field = R"("t": {"type": "tiled_field", "path": ")" + exr_ + R"("}, )";
    std::string e = parseError(R"({"name": "g", "nodes": {)" + field + R"("k": {"type": "channel", "field": "t", "index": 3},
        "c": {"type": "colormap", "x": "k", "y": "k", "colormap": {"type": "gaussian"}}}, "output": "c"})");
    EXPECT_NE(e.find("node \"k\" (channel): " + exr_ + " has 3 channels; there is no channel 3"), std::string::npos) << e;
    e = parseError(R"({"name": "g", "nodes": {)" + field +
                   R"("c": {"type": "colormap", "x": "t", "y": "t", "colormap": {"type": "gaussian"}}}, "output": "c"})");
    EXPECT_NE(e.find("/nodes/c/x: expects a field, but \"t\" (tiled_field) gives a tiled field"), std::string::npos) << e;
    e = parseError(R"({"name": "g", "nodes": {)" + field + R"("k": {"type": "channel", "field": "t", "index": 4}}, "output": "k"})");
    EXPECT_NE(e.find("/nodes/k/index: must be in [0, 3], got 4"), std::string::npos) << e;
    e = parseError(R"({"name": "g", "nodes": {)" + field.substr(0, field.size() - 2) + R"(}, "output": "t"})");
    EXPECT_NE(e.find("/output: the output must be a colour, but \"t\" (tiled_field) gives a tiled field"), std::string::npos)
        << e;
    // A Gaussianized channel (the default) is read by transfer functions only.
    e = parseError(R"({"name": "g", "nodes": {)" + field + R"("k": {"type": "channel", "field": "t", "index": 0},
        "f": {"type": "affine", "input": "k", "scale": 2},
        "c": {"type": "colormap", "x": "f", "y": "f", "colormap": {"type": "gaussian"}}}, "output": "c"})");
    EXPECT_NE(e.find("node \"f\" (affine): its input \"k\" is a Gaussianized exemplar"), std::string::npos) << e;
}

}  // namespace
}  // namespace stochtex
