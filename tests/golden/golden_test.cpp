// Golden images: a fresh render of each case against the 64×64 PNG stored in
// tests/golden/, to catch any change of the pixels. The cases: the CPU's
// colour patterns (preset × filter × view), a texture graph (figure14,
// through the graph evaluator), the LEAN response of a normal map
// (lean-ridges), and the GPU path of the three on the headless OpenGL
// context (Mesa's llvmpipe in CI and here; a GPU's own driver rounds its
// own way, so these stored images are llvmpipe's).
//
// Both sides go through the same 8-bit PNG writer and reader (writeImage /
// readImage), so an unchanged renderer differs by exactly 0. Tolerance, in
// 8-bit steps of 1/255: max |Δ| ≤ 2 in every channel and mean |Δ| ≤ 0.2 over
// all channels — room for rounding differences between compilers and CPUs,
// far below any visible change. A failure names the worst pixel; the fresh
// renders are left in <build>/tests/golden-out/ to look at.
//
// After an intended change of the pixels, rewrite the stored images with
//     make golden-update    (= build/bin/stochtex_golden --update)
// look at them (git diff shows which changed) and commit them. Compare or
// update is this binary's own flag, so nothing a test run inherits (an
// environment variable) can turn a comparison into a rewrite.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "gl_test_context.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/cpu_renderer.h"
#include "stochtex/pattern/presets.h"

namespace stochtex {
namespace {

namespace fs = std::filesystem;

// A handful of presets with different ingredients: a three-sector palette
// (camouflage), thin strands (marble), a quadrature pair with shared offsets
// (phasor-stripes), an analytic colormap on a band-pass noise (ridged), and two
// anisotropic noises (woven).
const char* const kPresets[] = {"camouflage", "marble", "phasor-stripes", "ridged", "woven"};
const char* const kFilters[] = {"none", "paper", "smooth"};
const char* const kViews[] = {"zoom", "plane"};

constexpr int kSize = 64;
constexpr long kMaxStep = 2;       // max |Δ|, in 1/255
constexpr double kMeanStep = 0.2;  // mean |Δ|, in 1/255

bool gUpdate = false;  // --update: rewrite the stored images instead of comparing

struct GoldenCase {
    std::string preset;
    std::string filter;  // as parseFilter reads it
    std::string view;
    bool lean = false;  // the lean response (the preset's normal map) instead of the colours
    bool gpu = false;   // the GLSL implementation on the headless context

    std::string name() const { return preset + "-" + filter + (lean ? "-lean" : "") + "-" + view + (gpu ? "-gpu" : ""); }
};

// gtest prints a failing case's parameter with this (not as raw bytes).
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name(); }

std::vector<GoldenCase> goldenCases() {
    std::vector<GoldenCase> cases;
    for (const char* preset : kPresets)
        for (const char* filter : kFilters)
            for (const char* view : kViews) cases.push_back({preset, filter, view});
    for (const bool gpu : {false, true})
        for (const char* filter : {"none", "smooth"})
            for (const char* view : kViews) {
                cases.push_back({"figure14", filter, view, false, gpu});
                cases.push_back({"lean-ridges", filter, view, true, gpu});
                if (gpu) cases.push_back({"camouflage", filter, view, false, true});
            }
    return cases;
}

// One spec per preset for the whole process (the update runs every case).
const PatternSpec& spec(const std::string& preset) {
    static std::map<std::string, PatternSpec> specs;
    const auto it = specs.find(preset);
    return it != specs.end() ? it->second : specs.emplace(preset, loadPreset(preset)).first->second;
}
// Zoomed out 4 texels per pixel (the filters differ there), or the ground
// plane tilted 70° with 8 anisotropic probes (footprints of every shape).
Image render(const GoldenCase& c) {
    Camera camera;
    camera.view.width = camera.view.height = kSize;
    camera.view.scale = 4.0;
    FilterOptions options;
    options.use(parseFilter(c.filter));
    if (c.lean) options.response.kind = ResponseKind::Lean;
    if (c.view == "plane") {
        camera.kind = Camera::Kind::Plane;
        camera.tiltDeg = 70;
        options.aniso = 8;
    }
    if (c.gpu) return makeGpuView(spec(c.preset), test::glContext(), options)->render(camera);
    return makeCpuRenderer(spec(c.preset), options)->render(camera);
}

class GoldenImage : public testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenImage, MatchesTheStoredRender) {
    const GoldenCase& c = GetParam();
    const fs::path stored = fs::path(STOCHTEX_GOLDEN_DIR) / (c.name() + ".png");
    const Image fresh = render(c);
    if (gUpdate) {
        writeImage(stored.string(), fresh);
        std::printf("[ update ] wrote %s\n", stored.c_str());
        return;
    }
    ASSERT_TRUE(fs::exists(stored)) << stored << " is missing; run the update command (tests/golden/golden_test.cpp)";
    // The fresh render as the PNG writer quantises it.
    fs::create_directories(STOCHTEX_GOLDEN_OUT);
    const fs::path written = fs::path(STOCHTEX_GOLDEN_OUT) / (c.name() + ".png");
    writeImage(written.string(), fresh);
    const Image got = readImage(written.string()), want = readImage(stored.string());
    ASSERT_EQ(got.width(), want.width());
    ASSERT_EQ(got.height(), want.height());
    ASSERT_EQ(got.channels(), want.channels());

    // In whole 8-bit steps (the PNGs hold nothing finer).
    const auto step = [](float value) { return std::lround(value * 255.0f); };
    double sum = 0;
    long worst = -1;
    size_t worstIndex = 0;
    for (size_t i = 0; i < got.data().size(); ++i) {
        const long d = std::abs(step(got.data()[i]) - step(want.data()[i]));
        sum += d;
        if (d > worst) worst = d, worstIndex = i;
    }
    const double mean = sum / double(got.data().size());
    const size_t pixel = worstIndex / size_t(got.channels());
    const int x = int(pixel % size_t(got.width())), y = int(pixel / size_t(got.width()));
    const int channel = int(worstIndex % size_t(got.channels()));
    std::printf("[ info ] %s: mean |Δ| %.3f/255, max %ld/255\n", c.name().c_str(), mean, worst);
    const std::string where = "worst pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                              std::to_string(channel) + ": fresh " + std::to_string(step(got.data()[worstIndex])) +
                              "/255, stored " + std::to_string(step(want.data()[worstIndex])) +
                              "/255; fresh render in " + written.string();
    EXPECT_TRUE(worst <= kMaxStep && mean <= kMeanStep)
        << c.name() << ": max |Δ| " << worst << "/255 (limit " << kMaxStep << "), mean |Δ| " << mean << "/255 (limit "
        << kMeanStep << "); " << where;
}

INSTANTIATE_TEST_SUITE_P(Golden, GoldenImage, testing::ValuesIn(goldenCases()),
                         [](const testing::TestParamInfo<GoldenCase>& info) {
                             std::string name = info.param.name();
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// Every stored image belongs to a case, so renamed or dropped cases leave no
// stale file that nothing compares any more.
TEST(Golden, StoresExactlyTheImagesOfTheCases) {
    std::set<std::string> expected, stored;
    for (const GoldenCase& c : goldenCases()) expected.insert(c.name() + ".png");
    for (const auto& entry : fs::directory_iterator(STOCHTEX_GOLDEN_DIR))
        if (entry.path().extension() == ".png") stored.insert(entry.path().filename().string());
    if (gUpdate) return;  // the update writes the images; stale ones are for a person to delete
    for (const std::string& name : stored) EXPECT_TRUE(expected.count(name)) << "stale golden image " << name;
    for (const std::string& name : expected) EXPECT_TRUE(stored.count(name)) << "missing golden image " << name;
}

}  // namespace
}  // namespace stochtex

// gtest's own flags, then this binary's: --update rewrites the stored images.
int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--update") {
            stochtex::gUpdate = true;
        } else {
            std::fprintf(stderr, "stochtex_golden: unknown argument %s (only --update and gtest's flags)\n", argv[i]);
            return 2;
        }
    }
    return RUN_ALL_TESTS();
}
