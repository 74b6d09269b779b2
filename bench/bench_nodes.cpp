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
