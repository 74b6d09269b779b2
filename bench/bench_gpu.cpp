// The GLSL implementation's throughput on the machine's OpenGL (llvmpipe on
// CPU-only machines, the vendor driver on a GPU), beside the CPU renderer.
#include <benchmark/benchmark.h>

#include <chrono>

#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/gpu_pattern.h"
#include "stochtex/pattern/presets.h"

namespace stochtex {
namespace {

// A headless context, or the benchmark skipped with the reason.
std::unique_ptr<GlContext> contextOrSkip(benchmark::State& state) {
    try {
        return GlContext::headless();
    } catch (const GpuUnavailable& e) {
        state.SkipWithError(e.what());
        return nullptr;
    }
}

template <class F>
double seconds(F&& f) {
    const auto a = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

// Unfiltered camouflage, 1024², GPU and CPU alternately in one run; each GPU
// frame includes the draw, the wait and the read-back of the float image.
void BM_GpuVsCpuUnfiltered(benchmark::State& state) {
    const Pattern p = Pattern::build(loadPreset("camouflage"));
    const std::unique_ptr<GlContext> ctx = contextOrSkip(state);
    if (!ctx) return;
    GpuPattern gpu(p, *ctx);
    View v;
    v.width = v.height = int(state.range(0));
    double tg = 0, tc = 0;
    for (auto _ : state) {
        tg += seconds([&] { benchmark::DoNotOptimize(gpu.render(v).data().data()); });
        tc += seconds([&] { benchmark::DoNotOptimize(p.render(v).data().data()); });
    }
    const double texels = double(v.width) * v.height * double(state.iterations());
    state.counters["gpu_Mtexel/s"] = texels / tg * 1e-6;
    state.counters["cpu_Mtexel/s"] = texels / tc * 1e-6;
    state.counters["gpu/cpu"] = tc / tg;
    state.SetLabel(ctx->describe());
}
BENCHMARK(BM_GpuVsCpuUnfiltered)->ArgName("size")->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);

// The shader filtered (isotropic paper mode, footprint `scale` texels) vs
// unfiltered, both on the GPU, alternately in one run, 1024².
void BM_GpuFilteredVsUnfiltered(benchmark::State& state) {
    const Pattern p = Pattern::build(loadPreset("camouflage"));
    const std::unique_ptr<GlContext> ctx = contextOrSkip(state);
    if (!ctx) return;
    FilterOptions o;
    o.mode = FilterMode::Paper;
    GpuPattern filtered(p, *ctx, o), unfiltered(p, *ctx);
    View v;
    v.width = v.height = 1024;
    v.scale = double(state.range(0));
    double tf = 0, tu = 0;
    for (auto _ : state) {
        tf += seconds([&] { benchmark::DoNotOptimize(filtered.render(v).data().data()); });
        tu += seconds([&] { benchmark::DoNotOptimize(unfiltered.render(v).data().data()); });
    }
    const double texels = double(v.width) * v.height * double(state.iterations());
    state.counters["filtered_Mtexel/s"] = texels / tf * 1e-6;
    state.counters["unfiltered_Mtexel/s"] = texels / tu * 1e-6;
    state.counters["ratio"] = tu / tf;
    state.SetLabel(ctx->describe());
}
BENCHMARK(BM_GpuFilteredVsUnfiltered)->ArgName("scale")->Arg(1)->Arg(128)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stochtex
