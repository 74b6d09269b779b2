// The workbench's throughput, as the thesis's Table 3.2 (GLcv): frames per
// second of a ShaderToy program alone ("none"), with each frame read back
// to the CPU ("copy"), and with the read-back frame's power spectrum
// ("spectrum") or its dense optical flow from the previous frame (DIS,
// "flow") computed by the analyses the studies use. The four modes run in
// turn within each iteration, so machine drift falls on all alike.
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "alternate_timing.h"
#include "gl_bench.h"
#include "stochtex/analysis/optical_flow.h"
#include "stochtex/analysis/power_spectrum.h"
#include "stochtex/core/watchdog.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/shadertoy.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/workbench/document.h"
#include "stochtex/workbench/previews.h"

namespace stochtex {
namespace {

namespace fs = std::filesystem;

// A program in the style of real ones: a feedback buffer advecting dye
// through a swirling field (data/shadertoy/swirl's code) and an image pass
// colouring it.
ShadertoySpec workbenchProgram(const fs::path& dir) {
    fs::create_directories(dir);
    std::ofstream(dir / "buffer_a.glsl") << R"(
vec2 velocity(vec2 uv, float t) {
    vec2 d1 = uv - vec2(0.35 + 0.1 * sin(0.7 * t), 0.5), d2 = uv - vec2(0.65, 0.5 + 0.1 * cos(0.5 * t));
    return 0.004 * (vec2(-d1.y, d1.x) / (dot(d1, d1) + 0.02) + vec2(d2.y, -d2.x) / (dot(d2, d2) + 0.02));
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec4 dye = texture(iChannel0, uv - velocity(uv, iTime)) * 0.99;
    float source = 0.08 * smoothstep(0.08, 0.0, uv.x) * (0.5 + 0.5 * sin(40.0 * uv.y + 3.0 * iTime));
    fragColor = dye + vec4(source, 12.0 * source * source, 0.0, 0.0);
})";
    std::ofstream(dir / "image.glsl") << R"(
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 d = texture(iChannel0, fragCoord / iResolution.xy);
    fragColor = vec4(clamp(vec3(d.x, 0.6 * d.x + 0.4 * d.y, 0.2 + 0.3 * d.y), 0.0, 1.0), 1.0);
})";
    std::ofstream(dir / "shadertoy.json") << R"({"name": "workbench", "passes": {
        "buffer_a": {"code": "buffer_a.glsl", "channels": [{"type": "buffer", "buffer": "a"}]},
        "image": {"code": "image.glsl", "channels": [{"type": "buffer", "buffer": "a"}]}}})";
    return loadShadertoy(dir.string());
}

// The program on a host of the benchmark's size (its arguments width,
// height) past its empty first frames, in a folder removed at the end; no
// host where there is no OpenGL (the benchmark skipped).
struct WorkbenchRun {
    WorkbenchRun(benchmark::State& state, const std::string& folder)
        : dir(fs::temp_directory_path() / folder), context(bench::contextOrSkip(state)) {
        if (!context) return;
        ShadertoySettings s;
        s.width = int(state.range(0));
        s.height = int(state.range(1));
        host = std::make_unique<ShadertoyHost>(workbenchProgram(dir), *context, s);
        for (int k = 0; k < 30; ++k) host->renderFrame();
        state.SetLabel(context->describe());
    }
    ~WorkbenchRun() { fs::remove_all(dir); }
    fs::path dir;
    std::unique_ptr<GlContext> context;
    std::unique_ptr<ShadertoyHost> host;
};

void BM_WorkbenchThroughput(benchmark::State& state) {
    const WorkbenchRun run(state, "stochtex_bench_workbench");
    if (!run.host) return;
    ShadertoyHost& host = *run.host;
    Image previous = toGray(host.image());
    double none = 0, copy = 0, spectrum = 0, flow = 0;
    for (auto _ : state) {
        none += bench::seconds([&] {
            host.renderFrame();
            glFinish();
        });
        copy += bench::seconds([&] {
            host.renderFrame();
            benchmark::DoNotOptimize(host.image().data().data());
        });
        spectrum += bench::seconds([&] {
            host.renderFrame();
            benchmark::DoNotOptimize(centredPowerSpectrum(toGray(host.image()), SpectrumWindow::Hann).data().data());
        });
        flow += bench::seconds([&] {
            host.renderFrame();
            Image next = toGray(host.image());
            benchmark::DoNotOptimize(denseFlow(previous, next, FlowMethod::Dis).data().data());
            previous = std::move(next);
        });
    }
    const double n = double(state.iterations());
    state.counters["fps_none"] = n / none;
    state.counters["fps_copy"] = n / copy;
    state.counters["fps_spectrum"] = n / spectrum;
    state.counters["fps_flow"] = n / flow;
    state.counters["copy/none"] = copy / none;  // how many times slower than the program alone
    state.counters["spectrum/none"] = spectrum / none;
    state.counters["flow/none"] = flow / none;
}
BENCHMARK(BM_WorkbenchThroughput)
    ->ArgNames({"width", "height"})
    ->Args({640, 360})
    ->Args({1280, 720})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

// What the watchdog around each pass's draw (core/watchdog.h: a watch armed
// and disarmed; it was a thread started and joined, 0.35 ms a frame at
// 64 × 36) costs a frame: the workbench program's frame (two passes, waited
// for) beside two watchdogs around nothing, in turn. At small sizes the
// frame is cheapest, so the share is the largest it gets.
void BM_ShadertoyWatchdogShare(benchmark::State& state) {
    const WorkbenchRun run(state, "stochtex_bench_watchdog");
    if (!run.host) return;
    ShadertoyHost& host = *run.host;
    const bench::AlternateTimes t = bench::timeAlternately(
        state,
        [&] {
            host.renderFrame();
            glFinish();
        },
        [&] {
            for (int pass = 0; pass < 2; ++pass) const Watchdog watchdog("nothing", 30, 1LL << 31);
        });
    const double n = double(state.iterations());
    state.counters["frame_us"] = 1e6 * t.first / n;
    state.counters["watchdogs_us"] = 1e6 * t.second / n;  // the two a frame of this program starts
    state.counters["watchdogs/frame"] = t.second / t.first;
}
BENCHMARK(BM_ShadertoyWatchdogShare)
    ->ArgNames({"width", "height"})
    ->Args({64, 36})
    ->Args({640, 360})
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(1.0);

// Issue 31 item 2: an edit's latency to its first frame, as the window runs
// it (docs/WORKBENCH.md): the edit (checked by its one parse), the panels'
// previews, the GPU program of the new pattern and one 256² filtered frame
// read back. Edit 0: a colormap colour (camouflage); 1: a noise's cut-off
// (camouflage); 2: a graph node's parameter (figure14's derivative angle).
// Every call changes the value, and each path's call a value its own last
// call did not see. The kept path builds with the workbench's caches
// (PreviewCache, PartCache: a generation per edit); beside it, alternately,
// the same edit as the workbench did it before them: every preview and every
// part of the program rebuilt and the pattern parsed a second time.
void BM_WorkbenchEditLatency(benchmark::State& state) {
    const std::unique_ptr<GlContext> context = bench::contextOrSkip(state);
    if (!context) return;
    const int edit = int(state.range(0));
    WorkbenchDocument doc = WorkbenchDocument::preset(edit == 2 ? "figure14" : "camouflage");
    const char* pointer = edit == 0   ? "/colormap/shapes/0/colour"
                          : edit == 1 ? "/noise_y/components/0/cutoff"
                                      : "/nodes/du/angle";
    // Three values in turn: the two paths alternate, so with two the kept
    // caches would see the same spec at every call of their path; with
    // three, each kept call's value was last seen three of its revisions
    // ago, beyond the two whose parts PartCache keeps.
    const nlohmann::json original = doc.json().at(nlohmann::json::json_pointer(pointer));
    const nlohmann::json values[3] = {edit == 0 ? nlohmann::json("#d02020") : nlohmann::json(5),
                                      edit == 0 ? nlohmann::json("#20d020") : nlohmann::json(7), original};
    FilterOptions options;
    options.use(parseFilter("paper"));
    View view;
    view.width = view.height = 256;
    PreviewCache kept;
    PartCache parts;
    kept.update(doc.patternSpec(), &parts);
    makeGpuView(doc.patternSpec(), *context, options, &parts);
    int toggle = 0;
    double phases[4] = {0, 0, 0, 0};  // edit, previews, program, frame (the kept path)
    const auto editToFrame = [&](bool before) {
        const auto t0 = std::chrono::steady_clock::now();
        doc.set(pointer, values[toggle++ % 3]);
        const auto t1 = std::chrono::steady_clock::now();
        PreviewCache fresh;
        if (before) parsePatternSpec(JsonReader(doc.json(), doc.source()), doc.baseDir());
        if (!before) parts.beginGeneration();  // as the workbench does per revision
        benchmark::DoNotOptimize(
            (before ? fresh : kept).update(doc.patternSpec(), before ? nullptr : &parts).colormap.data().data());
        const auto t2 = std::chrono::steady_clock::now();
        const std::unique_ptr<GpuView> program =
            makeGpuView(doc.patternSpec(), *context, options, before ? nullptr : &parts);
        const auto t3 = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(program->render(view).data().data());
        const auto t4 = std::chrono::steady_clock::now();
        if (!before) {
            const std::chrono::steady_clock::time_point t[] = {t0, t1, t2, t3, t4};
            for (int k = 0; k < 4; ++k) phases[k] += std::chrono::duration<double>(t[k + 1] - t[k]).count();
        }
    };
    const bench::AlternateTimes t = bench::timeAlternately(
        state, [&] { editToFrame(false); }, [&] { editToFrame(true); });
    const double n = double(state.iterations());
    state.counters["ms"] = 1e3 * t.first / n;
    state.counters["before_ms"] = 1e3 * t.second / n;
    const char* names[4] = {"edit_ms", "previews_ms", "program_ms", "frame_ms"};
    for (int k = 0; k < 4; ++k) state.counters[names[k]] = 1e3 * phases[k] / n;
    state.SetLabel(context->describe());
}
BENCHMARK(BM_WorkbenchEditLatency)->ArgName("edit")->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stochtex
