// Throughput of pattern evaluation. One RGB output pixel = one texel;
// counters report Mtexel/s (benchmark's rate counter, in texels/s).
#include <benchmark/benchmark.h>

#include "stochtex/core/parallel.h"
#include "stochtex/pattern/pattern.h"
#include "stochtex/pattern/presets.h"

using namespace stochtex;

namespace {

const Pattern& camouflage() {
    static const Pattern p = Pattern::build(loadPreset("camouflage"));
    return p;
}

// Unfiltered S = H ∘ N for a two-noise pattern, 1024², all threads (arg 0)
// or a fixed thread count.
void BM_RenderUnfiltered(benchmark::State& state) {
    ThreadLimit limit(int(state.range(0)));
    View view;
    view.width = view.height = 1024;
    const Pattern& p = camouflage();
    for (auto _ : state) {
        Image img = p.render(view);
        benchmark::DoNotOptimize(img.data().data());
    }
    state.counters["Mtexel/s"] = benchmark::Counter(double(view.width) * view.height * 1e-6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_RenderUnfiltered)->Arg(0)->Arg(1)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

// One noise only, to separate tiling-and-blending from colormap cost.
void BM_RenderSingleNoise(benchmark::State& state) {
    View view;
    view.width = view.height = 1024;
    const Pattern& p = camouflage();
    for (auto _ : state) {
        Image img = p.renderNoise(0, view);
        benchmark::DoNotOptimize(img.data().data());
    }
    state.counters["Mtexel/s"] = benchmark::Counter(double(view.width) * view.height * 1e-6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_RenderSingleNoise)->Unit(benchmark::kMillisecond)->UseRealTime();

// Building a pattern: two 256² spectral examples (FFT) + painted colormap.
void BM_BuildPattern(benchmark::State& state) {
    const PatternSpec spec = loadPreset("camouflage");
    for (auto _ : state) {
        Pattern p = Pattern::build(spec);
        benchmark::DoNotOptimize(&p);
    }
}
BENCHMARK(BM_BuildPattern)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
