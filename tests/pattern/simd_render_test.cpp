// The SIMD evaluator (CpuKernel::Simd) against the scalar kernel it is
// tested against (CpuKernel::Scalar), image to image: every preset and
// every graph file of data/graphs, zoomed in, at scale 1 and zoomed out,
// near and far from the origin; a plain program's filtered zooms; and the
// lanes' output for any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include "lane_targets.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/presets.h"
#include "test_util.h"

namespace stochtex {
namespace {

double maxAbsDifference(const Image& a, const Image& b) {
    EXPECT_EQ(a.data().size(), b.data().size());
    double worst = 0;
    for (size_t i = 0; i < std::min(a.data().size(), b.data().size()); ++i) {
        const double d = std::abs(double(a.data()[i]) - double(b.data()[i]));
        worst = std::isnan(d) ? INFINITY : std::max(worst, d);  // a NaN on either side fails
    }
    return worst;
}

std::vector<View> views() {
    std::vector<View> out;
    for (const auto& [scale, offsetU, offsetV] :
         {std::array<double, 3>{0.31, 5.5, -2.25}, {1.0, 0.0, 0.0}, {4.7, -1.0e6, 3.3e5}}) {
        View v;
        v.width = 67;  // no whole number of vectors
        v.height = 29;
        v.scale = scale;
        v.offsetU = offsetU;
        v.offsetV = offsetV;
        out.push_back(v);
    }
    return out;
}

// Linear colour agrees within float rounding: max |Δ| ≤ 1e-5 (the lanes
// compute each formula in the scalar kernel's order of operations).
void expectLanesAgree(const GraphPattern& program, const std::string& name) {
    for (const View& view : views()) {
        SCOPED_TRACE(name + " at scale " + std::to_string(view.scale));
        const Image scalar = program.render(view, {}, CpuKernel::Scalar);
        test::forEachLaneTarget(
            [&](const char*) { EXPECT_LE(maxAbsDifference(program.render(view, {}, CpuKernel::Simd), scalar), 1e-5); });
    }
}

TEST(SimdRender, EveryPresetAgreesWithTheScalarKernel) {
    for (const std::string& name : presetNames()) {
        const PatternSpec spec = loadPreset(name);
        expectLanesAgree(GraphPattern::build(spec), name);
        if (spec.normalMap) expectLanesAgree(GraphPattern::build(spec, {ResponseKind::Lean}), name + " (lean)");
    }
}

TEST(SimdRender, EveryGraphFileAgreesWithTheScalarKernel) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(STOCHTEX_DATA_DIR) + "/graphs")) {
        if (entry.path().extension() != ".json") continue;
        expectLanesAgree(GraphPattern::build(loadPatternFile(entry.path().string())), entry.path().filename());
        ++files;
    }
    EXPECT_GE(files, 3);
}

// A plain program's filtered zoom: the texel statistics of each level in
// lanes. Scales at a whole level (one texel footprint), between levels
// (trilinear) and magnified; the paper's and Deliot–Heitz's variances, both
// prefiltered tables.
void expectFilteredZoomsAgree(const GraphPattern& program, std::initializer_list<double> scales) {
    ASSERT_NE(program.plainColormap(), nullptr);
    for (const char* filter : {"paper", "smooth"})
        for (const VarianceEstimator estimator : {VarianceEstimator::Paper, VarianceEstimator::DeliotHeitz}) {
            FilterOptions options;
            options.use(parseFilter(filter));
            options.estimator = estimator;
            FilterOptions scalarOptions = options;
            scalarOptions.cpuKernel = CpuKernel::Scalar;
            const FilteredGraph lanes(program, options), scalar(program, scalarOptions);
            for (const double scale : scales) {
                SCOPED_TRACE(std::string(filter) + " " + enumName(kVarianceEstimatorNames, estimator) + " at scale " +
                             std::to_string(scale));
                Camera camera;
                camera.view.width = 53;
                camera.view.height = 17;
                camera.view.scale = scale;
                camera.view.offsetU = -3.0e5;
                camera.view.offsetV = 77.25;
                const Image reference = scalar.render(camera);
                test::forEachLaneTarget(
                    [&](const char*) { EXPECT_LE(maxAbsDifference(lanes.render(camera), reference), 1e-5); });
            }
        }
}

TEST(SimdRender, FilteredZoomsAgreeWithTheScalarKernel) {
    expectFilteredZoomsAgree(GraphPattern::build(loadPreset("camouflage")), {0.37, 1.0, 2.0, 4.7, 16.0, 300.0, 1.0e4});
}

// A Gaussianized exemplar's filtered zoom stays in the Gaussianized space
// (the table applies T⁻¹): at one texel per pixel the lanes read the
// example's own texels, which must not go through T⁻¹ as an unfiltered
// blend does, nor differ from the pyramid's level 0 that the scalar kernel
// reads.
TEST(SimdRender, FilteredZoomsOfAGaussianizedExemplarAgreeWithTheScalarKernel) {
    const test::ScratchDir dir("stochtex_simd_render_test");
    const GraphPattern program = GraphPattern::build(test::gaussianizedBimodalPattern(dir.path()));
    ASSERT_TRUE(program.leaf(0).example().gaussianized());
    expectFilteredZoomsAgree(program, {1.0, 2.0});
}

TEST(SimdRender, IdenticalForAnyThreadCount) {
    const GraphPattern program = GraphPattern::build(loadPreset(presetNames().front()));
    View view;
    view.width = 203;
    view.height = 61;
    view.scale = 1.7;
    Image one, many;
    {
        ThreadLimit limit(1);
        one = program.render(view);
    }
    {
        ThreadLimit limit(3);
        many = program.render(view);
    }
    ASSERT_EQ(one.data().size(), many.data().size());
    EXPECT_EQ(std::memcmp(one.data().data(), many.data().data(), one.data().size() * sizeof(float)), 0);
    // The filtered zoom in lanes likewise.
    const FilteredGraph filtered(program, FilterOptions{});
    Camera camera;
    camera.view = view;
    {
        ThreadLimit limit(1);
        one = filtered.render(camera);
    }
    {
        ThreadLimit limit(3);
        many = filtered.render(camera);
    }
    EXPECT_EQ(std::memcmp(one.data().data(), many.data().data(), one.data().size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace stochtex
