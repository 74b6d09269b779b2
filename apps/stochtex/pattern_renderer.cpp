#include "pattern_renderer.h"

namespace stochtex::cli {

void addDeviceFlags(CLI::App& cmd, DeviceFlags& flags, const std::string& gpuHelp, bool withDerivatives) {
    cmd.add_flag("--gpu", flags.gpu, gpuHelp);
    addPipelineFlag(cmd, flags.pipeline);
    if (withDerivatives)
        addEnumFlag(cmd, "--derivatives", flags.derivatives, kGpuDerivativesNames, "derivatives",
                    "--gpu footprints: camera (the view's exact Jacobian, as the CPU) | rasterizer (dFdx/dFdy)");
}

void refuseUnusedDeviceFlags(const CLI::App& cmd, const DeviceFlags& flags) {
    for (const char* flag : {"--pipeline", "--derivatives"})
        refuseWithoutEffect(cmd.get_option_no_throw(flag), flags.gpu, "without --gpu (it sets up the GPU render)");
}

void checkDeviceFilter(const DeviceFlags& flags, const FilterOptions& options) {
    if (flags.gpu && !isGpuFilter(options)) throw InputError("--gpu: the GPU renders --filter none, paper or smooth");
}

PatternRenderer::PatternRenderer(const PatternSpec& spec, const FilterOptions& options, const DeviceFlags& flags) {
    checkDeviceFilter(flags, options);
    const bool graph = needsGraphEvaluator(spec);
    if (graph)
        graph_ = std::make_unique<GraphPattern>(GraphPattern::build(spec));
    else
        pattern_ = std::make_unique<Pattern>(Pattern::build(spec));
    if (!flags.gpu) {
        if (graph)
            cpuGraph_ = std::make_unique<FilteredGraph>(*graph_, options);
        else
            cpu_ = std::make_unique<FilteredPattern>(*pattern_, options);
        return;
    }
    context_ = GlContext::headless();
    device_ = context_->describe();
    if (graph)
        gpu_ = std::make_unique<GpuGraph>(*graph_, *context_, options);
    else
        gpu_ = std::make_unique<GpuPattern>(*pattern_, *context_, options);
    gpu_->setDerivatives(flags.derivatives);
    gpu_->setPipeline(flags.pipeline);
}

PatternRenderer::~PatternRenderer() = default;

Image PatternRenderer::render(const Camera& camera, const Progress& progress) {
    if (gpu_) return gpu_->render(camera);
    return cpuGraph_ ? cpuGraph_->render(camera, progress) : cpu_->render(camera, progress);
}

}  // namespace stochtex::cli
