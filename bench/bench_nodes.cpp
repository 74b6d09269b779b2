// One benchmark per node of texture graphs, registered from the node table
// (pattern/graph_nodes.h) without code per node: each node's sample graph
// (sampleNodeGraph) is built (examples synthesised, linear nodes folded,
// tables made) and rendered at 256² by the graph evaluator (GraphPattern),
// so a new node is timed as soon as it is in the table.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "stochtex/image/image_io.h"
#include "stochtex/pattern/graph_nodes.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/presets.h"
#include "alternate_timing.h"

using namespace stochtex;

namespace {

// The exemplar the sample graphs read: a smooth periodic 128² image.
std::string sampleExemplar() {
    static const std::string path = [] {
        const std::string p = (std::filesystem::temp_directory_path() / "stochtex_bench_exemplar.png").string();
        Image img(128, 128, 1);
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x)
                img.at(x, y) = float(0.5 + 0.2 * std::sin(6.2831853 * x / 32) + 0.2 * std::cos(6.2831853 * y / 16));
        writeImage(p, img, WriteOptions{.transfer = Transfer::Linear});
        return p;
    }();
    return path;
}

void buildAndRender(benchmark::State& state, const NodeInfo* node) {
    nlohmann::json graph = sampleNodeGraph(*node, sampleExemplar());
    graph["size"] = 256;
    const nlohmann::json parsed = JsonReader::parse(graph.dump(), node->name);
    const PatternSpec spec = parsePatternSpec(JsonReader(parsed, node->name), ".");
    const View view{256, 256, 1.0};
    for (auto _ : state) {
        const GraphPattern p = GraphPattern::build(spec);
        Image img = p.render(view);
        benchmark::DoNotOptimize(img.data().data());
    }
}

const bool kRegistered = [] {
    for (const NodeInfo& node : graphNodes())
        benchmark::RegisterBenchmark(("BM_GraphNode/" + node.name).c_str(), buildAndRender, &node)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    return true;
}();

}  // namespace

// A graph that folds into a plain pattern ("linear part → colormap": the
// camouflage preset written as nodes, with its noises' seeds) against the
// plain file itself, alternately in one run, 512²: both compile to the plain
// program, so the graph runs at the plain pattern's speed. Args:
// filter (0 none, 1 paper, 2 smooth, 3 smooth on a plane tilted 75°),
// scale (texels per pixel), K.
namespace {
const PatternSpec& camouflageGraph() {
    static const PatternSpec spec = [] {
        nlohmann::json g = JsonReader::parse(std::string(presetText("camouflage")), "camouflage");
        nlohmann::json nodes;
        const PatternSpec preset = loadPreset("camouflage");
        nodes["nx"] = {{"type", "spectral_noise"}, {"components", g["noise_x"]["components"]}, {"seed", noiseSeed(preset, 0)}};
        nodes["ny"] = {{"type", "spectral_noise"}, {"components", g["noise_y"]["components"]}, {"seed", noiseSeed(preset, 1)}};
        nodes["out"] = {{"type", "colormap"}, {"x", "nx"}, {"y", "ny"}, {"colormap", g["colormap"]}};
        nlohmann::json graph{{"name", "camouflage-graph"}, {"seed", g["seed"]}, {"nodes", nodes}, {"output", "out"}};
        const nlohmann::json parsed = JsonReader::parse(graph.dump(), "camouflage-graph");
        return parsePatternSpec(JsonReader(parsed, "camouflage-graph"), ".");
    }();
    return spec;
}

void BM_FoldingGraphVsPattern(benchmark::State& state) {
    const PatternSpec& spec = camouflageGraph();
    static const GraphPattern pattern = GraphPattern::build(loadPreset("camouflage"));
    static const GraphPattern graph = GraphPattern::build(spec);
    Camera cam;
    cam.view.width = cam.view.height = 512;
    cam.view.scale = double(state.range(1));
    bench::AlternateTimes t;
    if (state.range(0) == 0) {
        t = bench::timeAlternately(
            state, [&] { benchmark::DoNotOptimize(pattern.render(cam.view).data().data()); },
            [&] { benchmark::DoNotOptimize(graph.render(cam.view).data().data()); });
    } else {
        FilterOptions o;
        o.use(parseFilter(state.range(0) == 1 ? "paper" : "smooth"));
        if (state.range(0) == 3) {  // a perspective plane at 75°: footprints of every size and shape, and sky
            cam.kind = Camera::Kind::Plane;
            cam.tiltDeg = 75;
        }
        o.aniso = int(state.range(2));
        const FilteredGraph fp(pattern, o);
        const FilteredGraph fg(graph, o);
        t = bench::timeAlternately(
            state, [&] { benchmark::DoNotOptimize(fp.render(cam).data().data()); },
            [&] { benchmark::DoNotOptimize(fg.render(cam).data().data()); });
    }
    bench::reportAlternateRates(state, 512.0 * 512.0, bench::TexelRate::Mega, {"pattern", t.first},
                                {"graph", t.second});
}
BENCHMARK(BM_FoldingGraphVsPattern)
    ->ArgNames({"filter", "scale", "K"})
    ->Args({0, 1, 1})
    ->Args({1, 16, 1})
    ->Args({2, 16, 1})
    ->Args({2, 16, 8})
    ->Args({3, 1, 8})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
}  // namespace
