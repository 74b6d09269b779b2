#pragma once
// The renderer behind `render` and `bake-image`: the CPU (FilteredPattern) or,
// with --gpu, the GLSL implementation on a headless OpenGL context.
#include <memory>
#include <string>

#include "common.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex::cli {

struct DeviceFlags {
    bool gpu = false;
    GpuPattern::Pipeline pipeline = GpuPattern::Pipeline::Fragment;
    GpuPattern::Derivatives derivatives = GpuPattern::Derivatives::Camera;
};
// --gpu, --pipeline and (withDerivatives) --derivatives.
void addDeviceFlags(CLI::App& cmd, DeviceFlags& flags, const std::string& gpuHelp, bool withDerivatives);
// --pipeline and --derivatives refused without --gpu (refuseWithoutEffect).
void refuseUnusedDeviceFlags(const CLI::App& cmd, const DeviceFlags& flags);
// InputError if --gpu is asked for a filter the GPU does not implement
// (exact, reference): callers check before building the pattern.
void checkDeviceFilter(const DeviceFlags& flags, const FilterOptions& options);

class PatternRenderer {
public:
    // Builds the pattern, or the graph (GraphPattern; GpuGraph with --gpu)
    // when it is not a pattern H∘N; checks checkDeviceFilter again.
    PatternRenderer(const PatternSpec& spec, const FilterOptions& options, const DeviceFlags& flags);
    ~PatternRenderer();
    // progress: the fraction of rows done (CPU renders; a GPU render is quick).
    Image render(const Camera& camera, const Progress& progress = {});
    // "CPU" or the OpenGL context's description.
    const std::string& device() const { return device_; }

private:
    std::unique_ptr<GlContext> context_;
    std::unique_ptr<GpuView> gpu_;  // GpuPattern or GpuGraph
    std::unique_ptr<Pattern> pattern_;
    std::unique_ptr<FilteredPattern> cpu_;
    std::unique_ptr<GraphPattern> graph_;
    std::unique_ptr<FilteredGraph> cpuGraph_;
    std::string device_ = "CPU";
};

}  // namespace stochtex::cli
