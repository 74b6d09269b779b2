// Throughput of pattern evaluation. One RGB output pixel = one texel;
// counters report Mtexel/s (benchmark's rate counter, in texels/s).
#include <benchmark/benchmark.h>

#include <algorithm>

#include "alternate_timing.h"
#include "gather_floor.h"
#include "resident_memory.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/presets.h"

using namespace stochtex;

namespace {

// The camouflage preset's program: two leaves → colormap.
const GraphPattern& camouflage() {
    static const GraphPattern p = GraphPattern::build(loadPreset("camouflage"));
    return p;
}

// The gather floor (gather_floor.h) of a pixel's reads, as issue 33 counts
// them (45 and 75 cycles a texel at 1.25 a float): the leaves' texels and
// each table lookup's four taps of RGB (12 floats, 6 pairs, a layer), as
// 64-bit pairs. Timed in turn with the SIMD and scalar renders, so that the
// machine's drift falls on it alike.
constexpr double kPairsPerLayerLookup = 6;
struct FloorPairs {
    double leaves = 0, lookups = 0;  // per image
    double seconds() const { return bench::gatherFloorSeconds((long long)(leaves + lookups)); }
};
// floor_ratio: the SIMD time over the floor, how far the lanes are from the
// limit; leaves_floor_ratio: over the leaves' floor alone (this counter's
// first definition, which left the lookups out).
void reportFloorRatio(benchmark::State& state, const bench::AlternateTimes& t, const FloorPairs& pairs) {
    state.counters["floor_ratio"] = t.first / t.third;
    state.counters["leaves_floor_ratio"] = t.first / (t.third * pairs.leaves / (pairs.leaves + pairs.lookups));
}

// The program's unfiltered 1024² zoom once per iteration; counter Mtexel/s.
void timeUnfilteredRenders(benchmark::State& state, const GraphPattern& p) {
    View view;
    view.width = view.height = 1024;
    for (auto _ : state) {
        Image img = p.render(view);
        benchmark::DoNotOptimize(img.data().data());
    }
    state.counters["Mtexel/s"] =
        benchmark::Counter(double(view.width) * view.height * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// Unfiltered S = H ∘ N for a two-noise pattern, 1024², all threads (arg 0)
// or a fixed thread count.
void BM_RenderUnfiltered(benchmark::State& state) {
    ThreadLimit limit(int(state.range(0)));
    timeUnfilteredRenders(state, camouflage());
}
BENCHMARK(BM_RenderUnfiltered)->Arg(0)->Arg(1)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

// The SIMD evaluator against its scalar reference (issue 33), timed
// alternately on one thread, 1024², scale 1: arg 0 the camouflage preset
// (a plain program: leaves in lanes, its colormap per pixel), 1 the one-noise graph of
// BM_RenderSingleNoise (leaves in lanes, the colormap op per pixel), 2 the
// figure14 graph (three leaves, a field colormap and a colormap op).
// Counters: simd_ and scalar_Mtexel/s, speedup = scalar time / SIMD time
// and floor_ratio = SIMD time / the same-run gather floor of its pairs.
const GraphPattern& singleNoise();
const GraphPattern& figure14() {
    static const GraphPattern p = GraphPattern::build(loadPreset("figure14"));
    return p;
}
void BM_SimdVsScalarUnfiltered(benchmark::State& state) {
    ThreadLimit limit(1);
    View view;
    view.width = view.height = 1024;
    const GraphPattern& p = state.range(0) == 0 ? camouflage() : state.range(0) == 1 ? singleNoise() : figure14();
    // Per pixel and leaf: three tiles, two rows, one pair each; per op that
    // reads a table (a colormap, a field colormap), one lookup of one layer.
    const double pixels = double(view.width) * view.height;
    const auto lookups = std::count_if(p.operations().begin(), p.operations().end(),
                                       [](const GraphPattern::Operation& op) { return op.table >= 0; });
    const FloorPairs pairs{pixels * 6 * p.leafCount(), pixels * kPairsPerLayerLookup * double(lookups)};
    const auto t = bench::timeAlternately(
        state, [&] { benchmark::DoNotOptimize(p.render(view, {}, CpuKernel::Simd).data().data()); },
        [&] { benchmark::DoNotOptimize(p.render(view, {}, CpuKernel::Scalar).data().data()); },
        [&] { return pairs.seconds(); });
    bench::reportAlternateRates(state, pixels, bench::TexelRate::Mega, {"simd", t.first}, {"scalar", t.second},
                                "speedup");
    reportFloorRatio(state, t, pairs);
}
BENCHMARK(BM_SimdVsScalarUnfiltered)
    ->ArgName("program")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The same for a filtered zoom of the camouflage preset (smooth table,
// paper's variances), 1024², one thread: arg the scale ×10 (10: one texel
// footprint per pixel at level 0; 40: level 2 alone; 47: two levels,
// trilinear).
void BM_SimdVsScalarFiltered(benchmark::State& state) {
    ThreadLimit limit(1);
    Camera camera;
    camera.view.width = camera.view.height = 1024;
    camera.view.scale = double(state.range(0)) / 10.0;
    FilterOptions options;
    const FilteredGraph simd(camouflage(), options);
    options.cpuKernel = CpuKernel::Scalar;
    const FilteredGraph scalar(camouflage(), options);
    // Per pixel, level and leaf: three tiles, two rows, a pair left and
    // right. The lookup reads one layer at one texel a pixel (level 0's
    // texels: σ̂ = 0), else four: a smooth lookup between σ levels on both
    // axes (at 4 and 4.7 texels, ≥ 98 % of this view's pixels, counted).
    const double lod = std::log2(camera.view.scale);
    const int levels = lod == std::floor(lod) ? 1 : 2;
    const double pixels = double(camera.view.width) * camera.view.height;
    const FloorPairs pairs{pixels * 12 * 2 * levels,
                           pixels * kPairsPerLayerLookup * (camera.view.scale == 1.0 ? 1 : 4)};
    const auto t = bench::timeAlternately(
        state, [&] { benchmark::DoNotOptimize(simd.render(camera).data().data()); },
        [&] { benchmark::DoNotOptimize(scalar.render(camera).data().data()); }, [&] { return pairs.seconds(); });
    bench::reportAlternateRates(state, pixels, bench::TexelRate::Mega, {"simd", t.first}, {"scalar", t.second},
                                "speedup");
    reportFloorRatio(state, t, pairs);
}
BENCHMARK(BM_SimdVsScalarFiltered)
    ->ArgName("scale_x10")
    ->Arg(10)
    ->Arg(40)
    ->Arg(47)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One noise: the camouflage's noise_x as the one leaf of a colormap that
// reads it twice. Not the plain pattern's one-lookup path (that needs two
// leaves of one pair): the program's interpreter, so against
// BM_RenderUnfiltered it shows what the plain path saves as well as the
// cost of a second leaf.
void BM_RenderSingleNoise(benchmark::State& state) { timeUnfilteredRenders(state, singleNoise()); }
BENCHMARK(BM_RenderSingleNoise)->Unit(benchmark::kMillisecond)->UseRealTime();

const GraphPattern& singleNoise() {
    static const GraphPattern p = [] {
        const nlohmann::json preset = JsonReader::parse(std::string(presetText("camouflage")), "camouflage");
        nlohmann::json nodes;
        nodes["n"] = {{"type", "spectral_noise"}, {"components", preset["noise_x"]["components"]}};
        nodes["c"] = {{"type", "colormap"}, {"x", "n"}, {"y", "n"}, {"colormap", preset["colormap"]}};
        const nlohmann::json graph{{"seed", preset["seed"]}, {"nodes", nodes}, {"output", "c"}};
        const nlohmann::json parsed = JsonReader::parse(graph.dump(), "one-noise");
        return GraphPattern::build(parsePatternSpec(JsonReader(parsed, "one-noise"), "."));
    }();
    return p;
}

// Building a pattern's program: two 256² spectral examples (FFT) + painted colormap.
void BM_BuildPattern(benchmark::State& state) {
    const PatternSpec spec = loadPreset("camouflage");
    for (auto _ : state) {
        GraphPattern p = GraphPattern::build(spec);
        benchmark::DoNotOptimize(&p);
    }
}
BENCHMARK(BM_BuildPattern)->Unit(benchmark::kMillisecond);

// Filtered vs unfiltered on the same 512² zoom view, timed alternately in
// one run so machine drift cancels in the ratio. Args: scale (footprint
// side in texels), filter mode (1 paper, 2 smooth), anisotropy K.
void BM_FilteredVsUnfiltered(benchmark::State& state) {
    const GraphPattern& p = camouflage();
    FilterOptions o;
    o.use(parseFilter(state.range(1) == 1 ? "paper" : "smooth"));
    o.aniso = int(state.range(2));
    const FilteredGraph f(p, o);
    Camera cam;
    cam.view.width = cam.view.height = 512;
    cam.view.scale = double(state.range(0));
    const bench::AlternateTimes t = bench::timeAlternately(
        state, [&] { benchmark::DoNotOptimize(p.render(cam.view).data().data()); },
        [&] { benchmark::DoNotOptimize(f.render(cam).data().data()); });
    bench::reportAlternateRates(state, 512.0 * 512.0, bench::TexelRate::Mega, {"filtered", t.second},
                                {"unfiltered", t.first});
}
BENCHMARK(BM_FilteredVsUnfiltered)
    ->ArgNames({"scale", "mode", "K"})
    ->Args({1, 1, 1})
    ->Args({128, 1, 1})
    ->Args({1, 2, 1})
    ->Args({128, 2, 1})
    ->Args({16, 1, 8})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A perspective plane (tilt 75°): footprints from 1 to thousands of texels,
// strongly anisotropic near the horizon.
void BM_PlaneFiltered(benchmark::State& state) {
    const GraphPattern& p = camouflage();
    FilterOptions o;
    o.use(parseFilter("smooth"));
    o.aniso = int(state.range(0));
    const FilteredGraph f(p, o);
    Camera cam;
    cam.kind = Camera::Kind::Plane;
    cam.tiltDeg = 75;
    cam.view.width = cam.view.height = 512;
    for (auto _ : state) benchmark::DoNotOptimize(f.render(cam).data().data());
    state.counters["Mtexel/s"] =
        benchmark::Counter(512.0 * 512.0 * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PlaneFiltered)->ArgName("K")->Arg(1)->Arg(8)->Unit(benchmark::kMillisecond)->UseRealTime();

// LEAN mapping (paper §6.5): the lean-ridges normal map on the perspective
// plane (512², tilt 70°, as Figure 12), filtered (estimators with the
// covariance, K probes) and unfiltered (the base lobe at each pixel's
// slope), alternately in one run. Args: K, covariance (0: the variant
// without it, which skips the covariance pyramid).
void BM_LeanFilteredVsUnfiltered(benchmark::State& state) {
    FilterOptions o;
    o.response.kind = ResponseKind::Lean;
    o.response.covariance = state.range(1) != 0;
    o.aniso = int(state.range(0));
    FilterOptions u = o;
    u.source = StatisticsSource::Point;
    // The file's lean program (GraphPattern::build), as `render --response lean` runs it.
    const GraphPattern p = GraphPattern::build(loadPreset("lean-ridges"), o.response);
    const FilteredGraph filtered(p, o), unfiltered(p, u);
    Camera cam;
    cam.kind = Camera::Kind::Plane;
    cam.tiltDeg = 70;
    cam.view.width = cam.view.height = 512;
    cam.view.scale = 0.5;
    const bench::AlternateTimes t = bench::timeAlternately(
        state, [&] { benchmark::DoNotOptimize(unfiltered.render(cam).data().data()); },
        [&] { benchmark::DoNotOptimize(filtered.render(cam).data().data()); });
    bench::reportAlternateRates(state, 512.0 * 512.0, bench::TexelRate::Mega, {"filtered", t.second},
                                {"unfiltered", t.first});
}
BENCHMARK(BM_LeanFilteredVsUnfiltered)
    ->ArgNames({"K", "cov"})
    ->Args({1, 1})
    ->Args({8, 1})
    ->Args({8, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Precomputation: mean/variance pyramids of two N² examples (N = the
// argument), and with the covariance pyramid when the second is 1. "ns/texel"
// is the time per level-0 texel of one example: constant from 256² to 4096²
// when the build scales linearly.
void BM_BuildPyramids(benchmark::State& state) {
    const int n = int(state.range(0));
    std::array<TilingBlendingNoise, 2> noises;
    for (uint32_t a = 0; a < 2; ++a) {
        SpectrumSpec s;
        s.size = n;
        s.seed = a;
        s.components.push_back({SpectrumShape::LowPass, 8, 2, 0, 1});
        // Shared offsets need one tile-offset seed for both channels.
        noises[a] =
            TilingBlendingNoise(std::make_shared<const NoiseExample>(synthesizeExample(s)), state.range(1) ? 0 : a);
    }
    const TiledField field({noises[0], noises[1]}, GridLayout{},
                           state.range(1) ? OffsetSharing::Shared : OffsetSharing::Independent);
    size_t bytes = 0, peakGrowth = 0;
    for (auto _ : state) {
        const size_t before = bench::resetPeakResidentBytes();
        FootprintEstimator e(field, state.range(1) != 0);
        const size_t peak = bench::peakResidentBytes();
        peakGrowth = std::max(peakGrowth, peak > before ? peak - before : 0);
        bytes = e.bytes();
        benchmark::DoNotOptimize(&e);
    }
    state.counters["MB"] = double(bytes) * 1e-6;
    // The build's peak resident memory over its result (1 = nothing but the pyramids).
    state.counters["peak/data"] = double(peakGrowth) / double(bytes);
    state.counters["ns/texel"] = benchmark::Counter(
        double(n) * double(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BuildPyramids)
    ->ArgsProduct({{256, 1024, 4096}, {0}})
    ->Args({1024, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The floor of any build that produces N bytes of new data: allocate them
// (as the pyramids are allocated) and write each once, rows in parallel. On
// a VM the first touch of fresh memory (page faults, the kernel zeroing the
// pages) dominates at 4096², so BuildPyramids is quoted against this.
void BM_WriteFreshMemory(benchmark::State& state) {
    const int n = int(state.range(0));
    // The floats of the two pyramids of BM_BuildPyramids: 2 examples × 2
    // channels × the padded levels.
    size_t floats = 0;
    for (int s = n; s >= 1; s /= 2) floats += 2 * 2 * (size_t(s) + 2) * (size_t(s) + 2);
    for (auto _ : state) {
        Image::Buffer data(floats);
        const size_t rows = 1024, perRow = (floats + rows - 1) / rows;
        parallelRows(int(rows), [&](int y0, int y1) {
            const size_t begin = std::min(floats, size_t(y0) * perRow), end = std::min(floats, size_t(y1) * perRow);
            std::fill(data.begin() + std::ptrdiff_t(begin), data.begin() + std::ptrdiff_t(end), 1.0f);
        });
        benchmark::DoNotOptimize(data.data());
    }
    state.counters["MB"] = double(floats * sizeof(float)) * 1e-6;
    state.counters["ns/texel"] = benchmark::Counter(
        double(n) * double(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_WriteFreshMemory)->Arg(256)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime();

// Precomputation of the prefiltered table H̄ from a 256² colormap: mode 1
// paper, 2 smooth, 3 smooth with a Beta x axis (a graph table reading a
// bounded field; its cost against mode 2 is the Beta's).
void BM_BuildPrefilteredTable(benchmark::State& state) {
    const ColormapTable h = camouflage().tables().front().blended;
    const PrefilterMode mode = state.range(0) == 1 ? PrefilterMode::Paper : PrefilterMode::Smooth;
    size_t bytes = 0;
    for (auto _ : state) {
        PrefilteredColormap t(h, mode, {state.range(0) == 3, false});
        bytes = t.bytes();
        benchmark::DoNotOptimize(&t);
    }
    state.counters["MB"] = double(bytes) * 1e-6;
}
BENCHMARK(BM_BuildPrefilteredTable)->ArgName("mode")->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);

// Not a timing: the accuracy cost of the paper's 8-bit pyramid packing,
// over 2000 random isotropic footprints of 1–128 texels (counters: mean and
// max |Δμ̂_x|, |Δσ̂_x| between float and 8-bit pyramids).
void BM_Pack8Loss(benchmark::State& state) {
    const GraphPattern& p = camouflage();
    const FootprintEstimator full(p.leafPairs().front(), false), packed(p.leafPairs().front(), false, true);
    double dmu = 0, dsigma = 0, maxMu = 0, maxSigma = 0;
    const int count = 2000;
    for (auto _ : state) {
        dmu = dsigma = maxMu = maxSigma = 0;
        for (int i = 0; i < count; ++i) {
            const UInt3 h = pcg3d({uint32_t(i), 5, 6});
            Jacobian j;
            j.dudx = j.dvdy = std::exp2(7.0 * unitFloat(h.z)) / 256.0;
            const Footprint f = makeFootprint(unitFloat(h.x) * 4, unitFloat(h.y) * 4, j, 256, full.maxLod(), 1);
            const FootprintStats a = full.estimate(f), b = packed.estimate(f);
            const double m = std::abs(a.mean[0] - b.mean[0]), s = std::abs(a.sigmaX() - b.sigmaX());
            dmu += m;
            dsigma += s;
            maxMu = std::max(maxMu, m);
            maxSigma = std::max(maxSigma, s);
        }
    }
    state.counters["mean_dmu"] = dmu / count;
    state.counters["max_dmu"] = maxMu;
    state.counters["mean_dsigma"] = dsigma / count;
    state.counters["max_dsigma"] = maxSigma;
}
BENCHMARK(BM_Pack8Loss)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
