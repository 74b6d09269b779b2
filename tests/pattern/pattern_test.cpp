#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/presets.h"

using namespace stochtex;
namespace fs = std::filesystem;

namespace {

std::string pngBytes(const Image& img, const std::string& name) {
    const fs::path p = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".png");
    writeImage(p.string(), img);
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    fs::remove(p);
    return ss.str();
}

View smallView() {
    View v;
    v.width = 96;
    v.height = 80;
    v.scale = 1.5;
    return v;
}

}  // namespace

TEST(PlainProgram, ColormapOfXOnlyIgnoresNy) {
    PatternSpec spec = loadPreset("gaussian");  // H(x, y) = x
    spec.colormap.transfer = Transfer::Linear;  // as data: the pixel is N_x itself
    const Image a = GraphPattern::build(spec).render(smallView());
    // Change noise_y completely: another spectrum and another example seed.
    spec.noise[1].spectrum.components[0].shape = SpectrumShape::Ring;
    spec.noise[1].spectrum.components[0].frequency = 30;
    spec.noise[1].spectrum.components[0].bandwidth = 4;
    spec.noise[1].explicitSeed = true;
    spec.noise[1].spectrum.seed = 4242;
    const GraphPattern p = GraphPattern::build(spec);
    const Image b = p.render(smallView());
    EXPECT_EQ(a.data(), b.data());
    // And the pixel is N_x itself.
    const Image nx = p.renderNode(smallView(), p.leafIds()[0]);
    for (int y = 0; y < nx.height(); y += 7)
        for (int x = 0; x < nx.width(); x += 5) EXPECT_NEAR(b.at(x, y, 0), nx.at(x, y, 0), 1e-6f);
}

TEST(PlainProgram, PixelIsColormapOfField) {
    const GraphPattern p = GraphPattern::build(loadPreset("camouflage"));
    const View v = smallView();
    const Image img = p.render(v);
    for (int y = 0; y < v.height; y += 9)
        for (int x = 0; x < v.width; x += 11) {
            const double u = (v.offsetU + (x + 0.5) * v.scale) / p.exampleSize();
            const double w = (v.offsetV + (y + 0.5) * v.scale) / p.exampleSize();
            // N(uv): each leaf tiled and blended on the one triangle grid, in output space.
            const BlendStencil stencil = triangleGrid(u, w, p.grid());
            float n[2];
            for (int k = 0; k < 2; ++k)
                n[k] = p.leaf(k).example().toOutput(p.leaf(k).blend(stencil, periodFraction(u), periodFraction(w)));
            ASSERT_NE(p.plainColormap(), nullptr);
            const Rgb c = p.plainColormap()->sample(n[0], n[1]);
            for (int k = 0; k < 3; ++k) EXPECT_EQ(img.at(x, y, k), c[size_t(k)]);
        }
}

TEST(PlainProgram, SameSeedIsByteIdenticalForAnyThreadCount) {
    const PatternSpec spec = loadPreset("marble");
    View v;
    v.width = v.height = 256;
    std::string one, all;
    {
        ThreadLimit limit(1);
        one = pngBytes(GraphPattern::build(spec).render(v), "one");
    }
    {
        ThreadLimit limit(0);
        all = pngBytes(GraphPattern::build(spec).render(v), "all");
    }
    {
        ThreadLimit limit(3);
        EXPECT_EQ(pngBytes(GraphPattern::build(spec).render(v), "three"), one);
    }
    EXPECT_EQ(one, all);
    PatternSpec other = spec;
    other.seed += 1;
    EXPECT_NE(pngBytes(GraphPattern::build(other).render(v), "other"), one);
}

TEST(PlainProgram, RegionRendersTheSamePixelsAsTheWhole) {
    const GraphPattern p = GraphPattern::build(loadPreset("woven"));
    View whole;
    whole.width = whole.height = 128;
    whole.scale = 2.0;
    const Image a = p.render(whole);
    View part = whole;
    part.width = 32;
    part.height = 40;
    part.offsetU = 50 * whole.scale;
    part.offsetV = 70 * whole.scale;
    const Image b = p.render(part);
    for (int y = 0; y < part.height; ++y)
        for (int x = 0; x < part.width; ++x)
            for (int c = 0; c < 3; ++c) ASSERT_EQ(b.at(x, y, c), a.at(x + 50, y + 70, c));
}
