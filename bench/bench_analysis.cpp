// Benchmarks of the artifact-analysis tools (thesis chapter 2–3).
#include <benchmark/benchmark.h>

#include "stochtex/analysis/correlation_accumulator.h"
#include "stochtex/textures/zoom_statistics.h"
#include "stochtex/core/hash.h"
#include "stochtex/textures/zoom_texture.h"

namespace stochtex {
namespace {

// The statistical accumulator over N = 512 instances of a 512² stationary
// zoom texture (n = 8 layers, linear interpolation): each instance draws a
// new 512² white-noise lattice, renders the texture and adds it (per-pixel
// moments, correlation with a point and with the centre row, and the 512×512
// pairwise matrix of the centre row). Issue target: under ~10 s on 2 cores.
void BM_ZoomAccumulator512(benchmark::State& state) {
    const int instances = int(state.range(0)), size = 512;
    ZoomParams p;
    p.layers = 8;
    for (auto _ : state) {
        CorrelationAccumulator acc(size, size, size / 2, size / 2, size / 2, size / 2);
        for (int k = 0; k < instances; ++k)
            acc.add(renderZoom(LatticeTexture::whiteNoise(size, size, deriveSeed(1, uint32_t(k))), p,
                               ZoomRegion::centred(size, size)));
        benchmark::DoNotOptimize(acc.probeCorrelation().data().data());
    }
    state.counters["instances/s"] = benchmark::Counter(double(instances), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_ZoomAccumulator512)->ArgName("N")->Arg(512)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

// The analytic radial correlation plot (eq. 2.11 for every pair), 256², n = 16.
void BM_AnalyticCorrelation256(benchmark::State& state) {
    ZoomParams p;
    p.layers = 16;
    const ZoomStatistics stats(p, 512, 512);
    for (auto _ : state) benchmark::DoNotOptimize(stats.radialCorrelation(256).data().data());
}
BENCHMARK(BM_AnalyticCorrelation256)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace stochtex
