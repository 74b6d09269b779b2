// Our filtered render beside ASTex MicroPatterns on the same job, in one
// process (issue 33: "≥ 10× ASTex MicroPatterns on the same job and
// machine"): the camouflage preset's two examples and colormap given to
// both, a pixels² zoom at `scale` texels per pixel, timed alternately.
// Times are the process's CPU seconds, so ASTex's thread pool (a thread per
// core) and our one thread are charged alike; cycles per texel use the
// core's clock measured in the same run by a chain of dependent adds.
// Built only with -DSTOCHTEX_ASTEX_DIR=<an ASTex checkout> (bench/CMakeLists.txt).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "alternate_timing.h"
#include "astex/astex_micropatterns.h"
#include "stochtex/core/parallel.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/presets.h"

using namespace stochtex;

namespace {

double processSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Process CPU seconds of one call of f.
template <class F>
double cpuSeconds(F&& f) {
    const double t0 = processSeconds();
    f();
    return processSeconds() - t0;
}

// The core's clock (Hz): a chain of dependent integer adds retires one add
// per cycle on every x86-64 core of the last two decades; the loop's own
// counter and branch run beside it on other ports. 0 elsewhere.
double measuredClockHz() {
#if defined(__x86_64__)
    constexpr long long kIterations = 25'000'000;  // 8 adds each: 2e8 cycles, ~0.1 s
    uint64_t x = 0;
    const double seconds = cpuSeconds([&] {
        for (long long i = 0; i < kIterations; ++i)
            asm volatile(
                "add $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\t"
                "add $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0"
                : "+r"(x));
    });
    benchmark::DoNotOptimize(x);
    return 8.0 * double(kIterations) / seconds;
#else
    return 0.0;
#endif
}

struct Moments {
    double mean = 0, deviation = 0;
};
// Per channel of interleaved RGB.
std::array<Moments, 3> channelMoments(const float* rgb, size_t count) {
    std::array<double, 3> sum{}, squares{};
    for (size_t i = 0; i < count; ++i) {
        sum[i % 3] += rgb[i];
        squares[i % 3] += double(rgb[i]) * rgb[i];
    }
    const double n = double(count / 3);
    std::array<Moments, 3> m;
    for (size_t c = 0; c < 3; ++c) {
        m[c].mean = sum[c] / n;
        m[c].deviation = std::sqrt(std::max(0.0, squares[c] / n - m[c].mean * m[c].mean));
    }
    return m;
}

const GraphPattern& camouflage() {
    static const GraphPattern p = GraphPattern::build(loadPreset("camouflage"));
    return p;
}

// The job's inputs as ASTex reads them: each example in its output space
// (what the colormap reads, in [0, 1]) and the colormap's table.
bench::AstexMicroPatterns& astex() {
    static bench::AstexMicroPatterns a = [] {
        const GraphPattern& p = camouflage();
        const auto values = [&](int k) {
            const NoiseExample& e = p.leaf(k).example();
            std::vector<float> v(size_t(e.size()) * size_t(e.size()));
            for (int y = 0; y < e.size(); ++y)
                for (int x = 0; x < e.size(); ++x)
                    v[size_t(y) * size_t(e.size()) + size_t(x)] = e.toOutput(e.values().at(x, y, 0));
            return v;
        };
        const Image table = p.plainColormap()->table();
        if (table.width() != table.height()) throw std::runtime_error("ASTex needs a square colormap");
        const std::vector<float> rgb(table.data().begin(), table.data().end());
        return bench::AstexMicroPatterns(values(0), values(1), p.exampleSize(), rgb, table.width());
    }();
    return a;
}

// Args: scale ×10, filter (1 paper, 2 smooth). 1024², our one thread.
void BM_FilteredVsAstex(benchmark::State& state) {
    constexpr int kPixels = 1024;
    ThreadLimit limit(1);
    FilterOptions options;
    options.use(parseFilter(state.range(1) == 1 ? "paper" : "smooth"));
    const FilteredGraph ours(camouflage(), options);
    Camera camera;
    camera.view.width = camera.view.height = kPixels;
    camera.view.scale = double(state.range(0)) / 10.0;
    bench::AstexMicroPatterns& theirs = astex();
    Image image;
    const bench::AlternateTimes t = bench::timeAlternately(
        state, [&] { return cpuSeconds([&] { image = ours.render(camera); }); },
        [&] { return cpuSeconds([&] { theirs.render(kPixels, camera.view.scale); }); });
    const double texels = double(kPixels) * kPixels;
    bench::reportAlternateRates(state, texels, bench::TexelRate::Mega, {"stochtex", t.first}, {"astex", t.second},
                                "speedup");
    const double hz = measuredClockHz();
    const double perImage = 1.0 / double(state.iterations());
    state.counters["clock_GHz"] = hz * 1e-9;
    state.counters["stochtex_cycles/texel"] = t.first * perImage * hz / texels;
    state.counters["astex_cycles/texel"] = t.second * perImage * hz / texels;
    // That the two rendered the same pattern (their tiles lie apart: the
    // grids and hashes differ): each image's mean and standard deviation of
    // linear RGB, compared channel by channel.
    const std::vector<float> other = theirs.image();
    const std::array<Moments, 3> a = channelMoments(image.data().data(), image.data().size()),
                                 b = channelMoments(other.data(), other.size());
    double meanDiff = 0, stdRatio = 0;
    for (size_t c = 0; c < 3; ++c) {
        meanDiff += std::abs(a[c].mean - b[c].mean) / 3.0;
        stdRatio += a[c].deviation / b[c].deviation / 3.0;
    }
    state.counters["mean_rgb_diff"] = meanDiff;
    state.counters["std_ratio"] = stdRatio;
}
BENCHMARK(BM_FilteredVsAstex)
    ->ArgNames({"scale_x10", "filter"})
    ->Args({10, 1})
    ->Args({10, 2})
    ->Args({40, 1})
    ->Args({47, 1})
    ->Args({47, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
