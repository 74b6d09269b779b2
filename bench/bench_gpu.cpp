// The GLSL implementation's throughput on the machine's OpenGL (llvmpipe on
// CPU-only machines, the vendor driver on a GPU), beside the CPU renderer.
#include <benchmark/benchmark.h>

#include <algorithm>

#include "alternate_timing.h"
#include "gl_bench.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/pattern/presets.h"

namespace stochtex {
namespace {

using bench::contextOrSkip;

// Frames per `secondsPerFrame` measurement so that one measurement takes
// about 0.2 s (1 on llvmpipe, hundreds on a GPU).
int framesPerMeasurement(GpuView& g, const Camera& c) {
    return std::clamp(int(0.2 / g.secondsPerFrame(c, 1)), 1, 2000);
}

// The file's program, unfiltered, as makeGpuView and makeCpuRenderer run it.
FilterOptions unfilteredOptions() {
    FilterOptions o;
    o.source = StatisticsSource::Point;
    return o;
}

// Unfiltered camouflage, 1024², GPU and CPU alternately in one run; each GPU
// frame includes the draw, the wait and the read-back of the float image.
void BM_GpuVsCpuUnfiltered(benchmark::State& state) {
    const GraphPattern p = GraphPattern::build(loadPreset("camouflage"));
    const std::unique_ptr<GlContext> ctx = contextOrSkip(state);
    if (!ctx) return;
    GpuGraph gpu(p, *ctx, unfilteredOptions());
    View v;
    v.width = v.height = int(state.range(0));
    const bench::AlternateTimes t = bench::timeAlternately(
        state, [&] { benchmark::DoNotOptimize(gpu.render(v).data().data()); },
        [&] { benchmark::DoNotOptimize(p.render(v).data().data()); });
    bench::reportAlternateRates(state, double(v.width) * v.height, bench::TexelRate::Mega, {"gpu", t.first},
                                {"cpu", t.second}, "gpu/cpu");
    state.SetLabel(ctx->describe());
}
BENCHMARK(BM_GpuVsCpuUnfiltered)->ArgName("size")->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);

// The shader filtered (isotropic paper mode, footprint `scale` texels) vs
// unfiltered, both on the GPU, alternately in one run, 1024².
void BM_GpuFilteredVsUnfiltered(benchmark::State& state) {
    const GraphPattern p = GraphPattern::build(loadPreset("camouflage"));
    const std::unique_ptr<GlContext> ctx = contextOrSkip(state);
    if (!ctx) return;
    FilterOptions o;
    o.use(parseFilter("paper"));
    GpuGraph filtered(p, *ctx, o), unfiltered(p, *ctx, unfilteredOptions());
    View v;
    v.width = v.height = 1024;
    v.scale = double(state.range(0));
    const bench::AlternateTimes t = bench::timeAlternately(
        state, [&] { benchmark::DoNotOptimize(filtered.render(v).data().data()); },
        [&] { benchmark::DoNotOptimize(unfiltered.render(v).data().data()); });
    bench::reportAlternateRates(state, double(v.width) * v.height, bench::TexelRate::Mega, {"filtered", t.first},
                                {"unfiltered", t.second});
    state.SetLabel(ctx->describe());
}
BENCHMARK(BM_GpuFilteredVsUnfiltered)->ArgName("scale")->Arg(1)->Arg(128)->Unit(benchmark::kMillisecond);

// The shader's own throughput (GPU timer queries, RGBA8 target, no
// read-back): the paper's Figure 6 measure. Plane view (tilt 55°, every
// pixel on the ground, footprints from 1 texel to strongly anisotropic);
// mode 1 = paper, 2 = smooth, 3 = paper ×8 anisotropic, each beside the
// unfiltered shader in the same run; pipeline 0 = fragment shader, 1 =
// compute kernel (OpenGL 4.3); `framesPerMeasurement` frames a measurement.
void BM_GpuShaderThroughput(benchmark::State& state) {
    const GraphPattern p = GraphPattern::build(loadPreset("camouflage"));
    const std::unique_ptr<GlContext> ctx = contextOrSkip(state);
    if (!ctx) return;
    FilterOptions o;
    o.use(parseFilter(state.range(0) == 2 ? "smooth" : "paper"));
    o.aniso = state.range(0) == 3 ? 8 : 1;
    GpuGraph filtered(p, *ctx, o), unfiltered(p, *ctx, unfilteredOptions());
    if (state.range(2) == 1) {
        if (!ctx->hasCompute()) return state.SkipWithError("no OpenGL 4.3 compute shaders");
        filtered.setPipeline(GpuView::Pipeline::Compute);
        unfiltered.setPipeline(GpuView::Pipeline::Compute);
    }
    Camera c;
    c.kind = Camera::Kind::Plane;
    c.tiltDeg = 55;
    c.view.width = c.view.height = int(state.range(1));
    const int ff = framesPerMeasurement(filtered, c), fu = framesPerMeasurement(unfiltered, c);
    const bench::AlternateTimes t = bench::timeAlternately(
        state, [&] { return filtered.secondsPerFrame(c, ff); }, [&] { return unfiltered.secondsPerFrame(c, fu); });
    bench::reportAlternateRates(state, double(c.view.width) * c.view.height, bench::TexelRate::Giga,
                                {"filtered", t.first}, {"unfiltered", t.second});
    state.SetLabel(ctx->describe());
}
BENCHMARK(BM_GpuShaderThroughput)
    ->ArgNames({"mode", "size", "pipeline"})
    ->ArgsProduct({{1, 2, 3}, {1024, 2048, 4096}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// LEAN mapping on the GPU, the same measure: the lean-ridges normal map on
// the plane (tilt 70°, as Figure 12), filtered (K = 8, with the slopes'
// covariance) beside its unfiltered shading (the base lobe at each pixel's
// slope), fragment pipeline.
void BM_GpuLeanThroughput(benchmark::State& state) {
    const std::unique_ptr<GlContext> ctx = contextOrSkip(state);
    if (!ctx) return;
    FilterOptions o;
    o.response.kind = ResponseKind::Lean;
    o.aniso = 8;
    FilterOptions u = o;
    u.source = StatisticsSource::Point;
    // The file's lean program, as `render --gpu --response lean` runs it.
    const GraphPattern p = GraphPattern::build(loadPreset("lean-ridges"), o.response);
    GpuGraph filtered(p, *ctx, o), unfiltered(p, *ctx, u);
    Camera c;
    c.kind = Camera::Kind::Plane;
    c.tiltDeg = 70;
    c.view.scale = 0.5;
    c.view.width = c.view.height = int(state.range(0));
    const int ff = framesPerMeasurement(filtered, c), fu = framesPerMeasurement(unfiltered, c);
    const bench::AlternateTimes t = bench::timeAlternately(
        state, [&] { return filtered.secondsPerFrame(c, ff); }, [&] { return unfiltered.secondsPerFrame(c, fu); });
    bench::reportAlternateRates(state, double(c.view.width) * c.view.height, bench::TexelRate::Giga,
                                {"filtered", t.first}, {"unfiltered", t.second});
    state.SetLabel(ctx->describe());
}
BENCHMARK(BM_GpuLeanThroughput)->ArgName("size")->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stochtex
