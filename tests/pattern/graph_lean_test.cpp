// The lean node (graph_nodes.h, pattern/graph_pattern.h): a height field's
// slopes, tiled on the height's own tiles, shaded through the kernel's LEAN
// lobe; its filtering against the supersampled reference, with and without
// the slopes' covariance; its refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/kernel/graph_ops.h"
#include "stochtex/noise/slopes.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "test_util.h"

namespace stochtex {
namespace {

// Ridges across 30° (a bi-lobe height spectrum, as the lean-ridges preset),
// so the two slopes are strongly correlated; the albedo is a colormap of
// the height itself, so it must see the height's tiles.
std::string ridges(const std::string& leanParams = "") {
    return R"({"name": "ridges", "seed": 12, "nodes": {
        "height": {"type": "spectral_noise", "size": 128, "components": [{"shape": "bilobe", "frequency": 16, "bandwidth": 4, "orientation": 30}]},
        "albedo": {"type": "colormap", "x": "height", "y": "height", "colormap": {"type": "gaussian"}},
        "shaded": {"type": "lean", "height": "height", "albedo": "albedo", "amplitude": 0.25, "roughness": 0.08,
                   "light_azimuth": -90, "light_elevation": 36.87)" +
           leanParams + R"(}}, "output": "shaded"})";
}

using test::meanRgbDistance;

// The lean op (pattern/ops/lean_op.glsl) on moments: slopes (a, b) with
// their variances, the albedo c, the covariance from the context.
kernel::vec3 leanOp(kernel::vec2 mean, kernel::vec2 var, float cov, kernel::vec3 albedo, kernel::vec3 light,
                    kernel::vec3 eye, float roughness, float specular) {
    using namespace kernel;
    OpContext ctx;
    ctx.eye = eye;
    ctx.slopeCov = cov;
    const LeanParams p{roughness, specular, light.x, light.y, light.z, 1.0f, 0.0f, 0.0f, 0.0f};  // no fixed view
    return opFiltered(p, vec3(mean.x, var.x, 0.0f), vec3(mean.y, var.y, 0.0f), albedo, ctx);
}

TEST(GraphOps, LeanOpIsTheKernelsLobeLit) {
    using namespace kernel;
    const vec3 light = normalize(vec3(0.3f, -0.5f, 0.8f)), eye(0.0f, 0.0f, 1.0f), albedo(0.2f, 0.4f, 0.6f);
    const vec3 got = leanOp(vec2(0.1f, -0.2f), vec2(0.01f, 0.02f), 0.005f, albedo, light, eye, 0.1f, 0.3f);
    const vec3 want =
        leanShade(leanLobe(vec2(0.1f, -0.2f), vec2(0.01f, 0.02f), 0.005f, 0.1f), light, eye, albedo, 0.3f);
    EXPECT_EQ(got.x, want.x);
    EXPECT_EQ(got.y, want.y);
    EXPECT_EQ(got.z, want.z);
    // A flat facet lit from straight above, seen from above: the albedo plus
    // the lobe's peak D(z) = 1/(π m²) over 4, times the specular weight.
    const vec3 flat = leanOp(vec2(0.0f), vec2(0.0f), 0.0f, albedo, eye, eye, 0.5f, 1.0f);
    // A host's own light (a scene's, w = 1) replaces the op's.
    OpContext scene;
    scene.light = vec4(eye, 1.0f);
    const LeanParams p{0.5f, 1.0f, light.x, light.y, light.z, 1.0f, 0.0f, 0.0f, 0.0f};
    const vec3 lit = opPoint(p, vec3(0.0f), vec3(0.0f), albedo, scene);
    EXPECT_EQ(lit.x, flat.x);
    EXPECT_EQ(lit.z, flat.z);
    const float peak = 1.0f / (3.14159265f * 0.25f) / 4.0f;
    EXPECT_NEAR(flat.x, 0.2f + peak, 1e-5);
    EXPECT_NEAR(flat.z, 0.6f + peak, 1e-5);
}

// Unfiltered, the node is the kernel's shading of the height's spectral
// slopes (scaled to the RMS amplitude) on the height's tiles, with the
// albedo's colour at the same point.
TEST(GraphPattern, LeanNodeShadesTheHeightsSlopesOnItsTiles) {
    const PatternSpec spec = test::parsePatternText(ridges());
    const GraphPattern g = GraphPattern::build(spec);
    ASSERT_EQ(g.leafCount(), 3);
    EXPECT_EQ(g.leafIds()[1], "shaded.slope_u");
    EXPECT_EQ(g.leafIds()[2], "shaded.slope_v");
    ASSERT_EQ(g.leafPairs().size(), 2u);  // the height alone, then the slope pair
    EXPECT_TRUE(g.leafPairs()[1].shared());
    EXPECT_TRUE(g.pairCovariance(1));
    EXPECT_FALSE(g.pairCovariance(0));
    // The slopes see the height's tiles.
    EXPECT_EQ(g.leaf(1).offsetSeed(), g.leaf(0).offsetSeed());
    EXPECT_EQ(g.leaf(2).offsetSeed(), g.leaf(0).offsetSeed());

    const NoiseExample height = buildGraphField(*spec.graph, "height", spec.seed, "ridges");
    const TiledField slopes = slopeField(height.values(), 0.25, g.leaf(0).offsetSeed(), g.grid());
    const double pi = 3.14159265358979;
    const kernel::vec3 light(0.0f, float(-std::cos(36.87 * pi / 180)), float(std::sin(36.87 * pi / 180)));
    double worst = 0;
    for (int i = 0; i < 200; ++i) {
        const double u = 0.37 * i + 0.11, v = 0.23 * i - 1.7;
        const BlendStencil s = triangleGrid(u, v, g.grid());
        const float fu = periodFraction(u), fv = periodFraction(v);
        const float h = g.leaf(0).blend(s, fu, fv);
        const kernel::vec2 slope(slopes.channel(0).blend(s, fu, fv), slopes.channel(1).blend(s, fu, fv));
        const Rgb a = g.evaluate(u, v, 0, GraphPattern::kFromAbove);  // the height leaf
        EXPECT_EQ(a[0], h);
        const Rgb albedo = g.evaluate(u, v, 3, GraphPattern::kFromAbove);  // the colormap's slot
        const kernel::vec3 want = leanOp(slope, kernel::vec2(0.0f), 0.0f, kernel::vec3(albedo[0], albedo[1], albedo[2]),
                                         light, kernel::vec3(0.0f, 0.0f, 1.0f), 0.08f, 0.05f);
        const Rgb got = g.evaluate(u, v);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(got[size_t(c)]) - want[c]));
    }
    // The light goes through float rounding of cos/sin in double, then float.
    EXPECT_LT(worst, 2e-6);
}

// Filtered: at one texel per pixel the estimators give the point's slopes
// (a zero footprint variance, up to interpolation). On a plane seen at 70°
// with the light beyond the horizon (the paper's Figure 12), the lobe
// widened by the footprint's slope covariance follows the reference far
// better than the point shading, and without the covariance the lobe
// spreads along the horizon (the ridges' slopes are strongly correlated).
TEST(GraphPattern, LeanNodeFilteredFollowsTheReferenceAndNeedsTheCovariance) {
    const GraphPattern g = GraphPattern::build(test::parsePatternText(ridges()));
    const GraphPattern noCov = GraphPattern::build(test::parsePatternText(ridges(R"(, "covariance": false)")));
    EXPECT_FALSE(noCov.pairCovariance(1));
    FilterOptions unfiltered, smooth, exact, reference;
    unfiltered.use(parseFilter("none"));
    smooth.use(parseFilter("smooth"));
    exact.use(parseFilter("exact"));
    reference.use(parseFilter("reference"));
    exact.referenceMaxSamples = reference.referenceMaxSamples = 24;
    Camera zoom;
    zoom.view = {48, 48, 1.0, 13.0, 7.0};
    EXPECT_LT(meanRgbDistance(FilteredGraph(g, smooth).render(zoom), g.render(zoom.view)), 0.02);

    Camera plane;
    plane.kind = Camera::Kind::Plane;
    plane.view = {96, 60, 1.7};
    plane.tiltDeg = 70;
    plane.fovDeg = 50;
    const Image ref = FilteredGraph(g, reference).render(plane);
    const double none = meanRgbDistance(FilteredGraph(g, unfiltered).render(plane), ref);
    const double withCov = meanRgbDistance(FilteredGraph(g, smooth).render(plane), ref);
    const double withoutCov = meanRgbDistance(FilteredGraph(noCov, smooth).render(plane), ref);
    const double exactStats = meanRgbDistance(FilteredGraph(g, exact).render(plane), ref);
    std::printf("lean node, plane view: none %.4f, estimators %.4f, without covariance %.4f, exact statistics %.4f\n",
                none, withCov, withoutCov, exactStats);
    EXPECT_LT(withCov, 0.6 * none) << "none " << none << ", estimators " << withCov;
    EXPECT_LT(exactStats, 0.6 * none) << "none " << none << ", exact statistics " << exactStats;
    EXPECT_LT(withCov, 0.7 * withoutCov) << "with " << withCov << ", without " << withoutCov;
}

std::string buildError(const std::string& text) {
    try {
        (void)GraphPattern::build(test::parsePatternText(text));
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(GraphPattern, LeanNodeRefusesHeightsWithoutAnExampleOrWithTurnedAxes) {
    const std::string noise =
        R"({"type": "spectral_noise", "size": 32, "components": [{"shape": "lowpass", "cutoff": 4}]})";
    const std::string head = R"({"name": "g", "nodes": {"h": )" + noise +
                             R"(, "a": {"type": "colormap", "x": "h", "y": "h", "colormap": {"type": "gaussian"}}, )";
    std::string e = buildError(head + R"("k": {"type": "curve", "input": "h", "points": [[0, 0], [1, 1]]},
        "c": {"type": "lean", "height": "k", "albedo": "a"}}, "output": "c"})");
    EXPECT_NE(e.find("node \"c\" (lean): its input \"k\" is not linear in the sources, so it has no example to take "
                     "the slopes of"),
              std::string::npos)
        << e;
    e = buildError(head + R"("t": {"type": "transform", "input": "h", "angle": 30},
        "c": {"type": "lean", "height": "t", "albedo": "a"}}, "output": "c"})");
    EXPECT_NE(e.find("node \"c\" (lean): its input \"t\" is seen through a transform of uv"), std::string::npos) << e;
    e = buildError(head + R"("f": {"type": "affine", "input": "h", "scale": 0},
        "c": {"type": "lean", "height": "f", "albedo": "a"}}, "output": "c"})");
    EXPECT_NE(e.find("node \"c\" (lean): amplitude cannot scale a flat height example"), std::string::npos) << e;
    // Each lean node adds two slope values per pixel: 100 of them (a mix
    // chain keeps each one needed) outnumber the program's 256 slots.
    std::string chain = head + R"("l0": {"type": "lean", "height": "h", "albedo": "a"})";
    for (int i = 1; i < 100; ++i)
        chain += ", \"l" + std::to_string(i) + "\": {\"type\": \"lean\", \"height\": \"h\", \"albedo\": \"l" +
                 std::to_string(i - 1) + "\"}";
    e = buildError(chain + R"(}, "output": "l99"})");
    EXPECT_NE(e.find("the graph's program needs 302 values per pixel (each lean node adds two slopes), more than 256"),
              std::string::npos)
        << e;
    // The albedo is a colour, the height a field.
    e = buildError(head + R"("c": {"type": "lean", "height": "a", "albedo": "a"}}, "output": "c"})");
    EXPECT_NE(e.find("/nodes/c/height: expects a field, but \"a\" (colormap) gives a colour"), std::string::npos) << e;
}

}  // namespace
}  // namespace stochtex
