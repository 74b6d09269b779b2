// Texture graphs (pattern/texture_graph.h, graph_nodes.h): parsing and
// every refusal with its JSON pointer, equivalence with a preset, and the
// folding of linear nodes into examples.
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/texture_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/presets.h"
#include "test_util.h"

namespace stochtex {
namespace {

std::string errorOf(const std::string& text) {
    try {
        const PatternSpec s = test::parsePatternText(text);
        (void)GraphPattern::build(s);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

const std::string kNoise = R"({"type": "spectral_noise", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]})";

std::string graph(const std::string& nodes, const std::string& output = "c") {
    return R"({"size": 32, "nodes": {)" + nodes + R"(}, "output": ")" + output + R"("})";
}

TEST(TextureGraph, ParsesNodesInDependencyOrder) {
    const PatternSpec s = test::parsePatternText(graph(R"("a": )" + kNoise + R"(, "d": {"type": "derivative", "input": "a", "angle": 30},
        "c": {"type": "colormap", "x": "d", "y": "a", "colormap": {"type": "gaussian"}})"));
    ASSERT_TRUE(s.graph);
    ASSERT_EQ(s.graph->nodes.size(), 3u);
    std::set<std::string> seen;
    for (const GraphNode& n : s.graph->nodes) {
        for (const auto& [port, from] : n.inputs) EXPECT_TRUE(seen.count(from)) << n.id << " before its input " << from;
        seen.insert(n.id);
    }
    EXPECT_EQ(s.graph->node("d").numbers.at("angle"), 30.0);
    EXPECT_EQ(s.graph->node("d").numbers.at("stddev"), 1.0 / 6.0);  // the table's default
    EXPECT_EQ(s.graph->output, "c");
}

TEST(TextureGraph, RefusesBadGraphsNamingTheJsonPointer) {
    // An unknown type's message lists every type of the node table, in its order.
    std::string known;
    for (const NodeInfo& n : graphNodes()) known += (known.empty() ? "" : ", ") + n.name;
    ASSERT_NE(known.find("spectral_noise, exemplar"), std::string::npos);
    ASSERT_NE(known.find("compose, lean"), std::string::npos);
    const std::string cm = R"("c": {"type": "colormap", "x": "a", "y": "a", "colormap": {"type": "gaussian"}})";
    const struct {
        std::string text, expected;
    } cases[] = {
        {graph(R"("a": {"type": "wavelet"}, )" + cm),
         "g.json: /nodes/a/type: unknown node type \"wavelet\"; known: " + known},
        {graph(R"("a": )" + kNoise + R"(, "c": {"type": "colormap", "x": "a", "y": "b", "colormap": {"type": "gaussian"}})"),
         "g.json: /nodes/c/y: no node \"b\""},
        {graph(R"("a": )" + kNoise + R"(, "c": {"type": "colormap", "x": "a", "colormap": {"type": "gaussian"}})"),
         "g.json: /nodes/c: a colormap node needs its input \"y\" (a field)"},
        {graph(R"("a": )" + kNoise + R"(, "c": {"type": "colormap", "x": "a", "y": "a", "z": "a", "colormap": {"type": "gaussian"}})"),
         "g.json: /nodes/c/z: a colormap node has no port or parameter \"z\"; it has: x, y, colormap"},
        {graph(R"("a": )" + kNoise + R"(, "e": {"type": "colormap", "x": "a", "y": "a", "colormap": {"type": "gaussian"}},
               "c": {"type": "colormap", "x": "e", "y": "a", "colormap": {"type": "gaussian"}})"),
         "g.json: /nodes/c/x: expects a field, but \"e\" (colormap) gives a colour"},
        {graph(R"("p": {"type": "affine", "input": "q"}, "q": {"type": "affine", "input": "p"},
               "c": {"type": "colormap", "x": "p", "y": "q", "colormap": {"type": "gaussian"}})"),
         "closes a cycle: "},
        {graph(R"("a": )" + kNoise + R"(, "d": {"type": "derivative", "input": "a", "angle": 400}, )" + cm),
         "g.json: /nodes/d/angle: must be in [-360, 360], got 400"},
        {graph(R"("a": {"type": "spectral_noise", "size": 48, "components": [{"shape": "lowpass", "cutoff": 4}]}, )" + cm),
         "g.json: /nodes/a/size: must be a power of two"},
        {graph(R"("a": )" + kNoise + ", " + cm, "a"), "g.json: /output: the output must be a colour, but \"a\" (spectral_noise) gives a field"},
        {graph(R"("a": )" + kNoise + ", " + cm, "zz"), "g.json: /output: no node \"zz\""},
        {graph(R"("a b": )" + kNoise + ", " + cm), "g.json: /nodes/a b: node ids are 1–64 letters, digits, '_' or '-'"},
        {R"({"nodes": {}, "output": "c"})", "g.json: /nodes: needs at least one node"},
        {R"({"nodes": {"c": {"type": "colormap"}}, "output": "c", "noise_x": {}})", "g.json: /noise_x: unknown member (expected one of: name, description, seed, size, scale, offsets, grid_density, estimator, nodes, output)"},
    };
    for (const auto& c : cases) {
        const std::string e = errorOf(c.text);
        EXPECT_NE(e.find(c.expected), std::string::npos) << "got: " << e << "\nexpected: " << c.expected;
    }
}

TEST(TextureGraph, BuildTimeRefusalsNameTheNode) {
    const std::string e = errorOf(graph(R"("a": {"type": "spectral_noise", "size": 64, "components": [{"shape": "lowpass", "cutoff": 4}]},
        "b": {"type": "spectral_noise", "size": 32, "components": [{"shape": "lowpass", "cutoff": 4}]},
        "s": {"type": "sum", "a": "a", "b": "b"},
        "c": {"type": "colormap", "x": "s", "y": "a", "colormap": {"type": "gaussian"}})"));
    EXPECT_NE(e.find("node \"s\" (sum): its inputs' examples are 64 and 32 texels wide"), std::string::npos) << e;
}

// A graph with the preset's noises and colormap is the preset, bit for bit
// (its sources carry the seeds the preset derives for noise_x and noise_y).
TEST(TextureGraph, GraphOfAPresetRendersByteIdenticalToIt) {
    const PatternSpec preset = loadPreset("camouflage");
    const std::string text = R"({"seed": 6, "nodes": {
        "nx": {"type": "spectral_noise", "seed": )" + std::to_string(noiseSeed(preset, 0)) +
                             R"(, "components": [{"shape": "lowpass", "cutoff": 8}]},
        "ny": {"type": "spectral_noise", "seed": )" + std::to_string(noiseSeed(preset, 1)) +
                             R"(, "components": [{"shape": "lowpass", "cutoff": 8}]},
        "c": {"type": "colormap", "x": "nx", "y": "ny", "colormap": )" +
                             nlohmann::json::parse(presetText("camouflage"))["colormap"].dump() + R"(}}, "output": "c"})";
    const View view{96, 64, 1.7, 13.25, -40.5};
    const Image a = GraphPattern::build(preset).render(view), b = GraphPattern::build(test::parsePatternText(text)).render(view);
    ASSERT_EQ(a.data().size(), b.data().size());
    EXPECT_EQ(0, std::memcmp(a.data().data(), b.data().data(), a.data().size() * sizeof(float)));
}

// The derivative node is exact on the example: against a central difference
// of the periodic example (second-order accurate, so close for a smooth
// low-pass noise), after both are normalised.
TEST(TextureGraph, DerivativeFoldsIntoTheExampleAsItsDirectionalDerivative) {
    const PatternSpec s = test::parsePatternText(graph(R"("a": {"type": "spectral_noise", "size": 128, "seed": 5, "components": [{"shape": "lowpass", "cutoff": 6}]},
        "d": {"type": "derivative", "input": "a", "angle": 90, "mean": 0.4, "stddev": 0.1},
        "c": {"type": "colormap", "x": "d", "y": "a", "colormap": {"type": "gaussian"}})"));
    const NoiseExample base = buildGraphField(*s.graph, "a", s.seed, "g"), d = buildGraphField(*s.graph, "d", s.seed, "g");
    ASSERT_EQ(d.size(), 128);
    const int n = 128;
    double sum = 0, sumSq = 0, dot = 0, fdSq = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double v = d.values().at(x, y);
            // angle 90°: along +v, the rows.
            const double fd = 0.5 * (base.values().at(x, (y + 1) % n) - base.values().at(x, (y + n - 1) % n));
            sum += v, sumSq += v * v, dot += (v - 0.4) * fd, fdSq += fd * fd;
        }
    const double mean = sum / (n * n), sd = std::sqrt(sumSq / (n * n) - mean * mean);
    EXPECT_NEAR(mean, 0.4, 1e-5);
    EXPECT_NEAR(sd, 0.1, 1e-5);
    const double correlation = dot / std::sqrt(fdSq * (sd * sd * n * n));
    EXPECT_GT(correlation, 0.995);
}

TEST(TextureGraph, LinearNodesRefuseAGaussianizedExemplar) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "stochtex_graph_exemplar.png";
    Image img(32, 32, 1);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) img.at(x, y) = float((x * 7 + y * 3) % 32) / 31.0f;
    writeImage(file.string(), img, WriteOptions{.transfer = Transfer::Linear});
    const std::string e = errorOf(graph(R"("img": {"type": "exemplar", "path": ")" + file.string() +
                                        R"("}, "f": {"type": "affine", "input": "img", "scale": 2},
        "c": {"type": "colormap", "x": "f", "y": "img", "colormap": {"type": "gaussian"}})"));
    EXPECT_NE(e.find("node \"f\" (affine): its input \"img\" is a Gaussianized exemplar"), std::string::npos) << e;
    std::filesystem::remove(file);
}

TEST(TextureGraph, SourceSeedsComeFromTheIdNotThePosition) {
    EXPECT_EQ(graphNodeSeed(7, "height"), graphNodeSeed(7, "height"));
    EXPECT_NE(graphNodeSeed(7, "height"), graphNodeSeed(7, "heights"));
    EXPECT_NE(graphNodeSeed(7, "height"), graphNodeSeed(8, "height"));
}

// Every node of the table builds and renders in its sample graph, so a
// node added to the table is parsed, built and rendered here (and timed by
// the per-node benchmark) without a test of its own for that.
TEST(TextureGraph, EveryNodeBuildsAndRendersInItsSampleGraph) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "stochtex_sample_exemplar.png";
    Image img(64, 64, 1);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) img.at(x, y) = float(0.5 + 0.4 * std::sin(0.3 * x) * std::cos(0.2 * y));
    writeImage(file.string(), img, WriteOptions{.transfer = Transfer::Linear});
    for (const NodeInfo& node : graphNodes()) {
        const std::string text = sampleNodeGraph(node, file.string()).dump();
        try {
            // GraphPattern evaluates any graph (a folding one as the plain program).
            const GraphPattern p = GraphPattern::build(test::parsePatternText(text));
            const Image out = p.render(View{32, 32, 1.0});
            double lo = 1e9, hi = -1e9;
            for (float v : out.data()) lo = std::min(lo, double(v)), hi = std::max(hi, double(v));
            EXPECT_GT(hi - lo, 0.01) << node.name << ": a flat render";
        } catch (const std::exception& e) {
            ADD_FAILURE() << node.name << ": " << e.what() << "\n" << text;
        }
    }
    std::filesystem::remove(file);
}

// A chain where every node reads the previous one twice would take 2^n
// builds if shared inputs were rebuilt; each node is built once.
TEST(TextureGraph, SharedInputsAreBuiltOnceSoDeepDiamondsStayLinear) {
    std::string nodes = R"("s0": {"type": "spectral_noise", "size": 16, "components": [{"shape": "lowpass", "cutoff": 2}]})";
    for (int i = 1; i <= 200; ++i)
        nodes += ", \"s" + std::to_string(i) + "\": {\"type\": \"sum\", \"a\": \"s" + std::to_string(i - 1) +
                 "\", \"b\": \"s" + std::to_string(i - 1) + "\"}";
    nodes += R"(, "c": {"type": "colormap", "x": "s200", "y": "s0", "colormap": {"type": "gaussian"}})";
    const PatternSpec s = test::parsePatternText(graph(nodes));
    const NoiseExample e = buildGraphField(*s.graph, "s200", s.seed, "g");  // 0.5·a + 0.5·b of equal inputs: s0 itself
    const NoiseExample base = buildGraphField(*s.graph, "s0", s.seed, "g");
    for (size_t i = 0; i < e.values().data().size(); ++i)
        ASSERT_NEAR(e.values().data()[i], base.values().data()[i], 1e-5) << i;
}

}  // namespace
}  // namespace stochtex
