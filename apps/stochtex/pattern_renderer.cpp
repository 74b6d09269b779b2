#include "pattern_renderer.h"

#include "stochtex/pattern/cpu_renderer.h"

namespace stochtex::cli {

void addDeviceFlags(CLI::App& cmd, DeviceFlags& flags, const std::string& gpuHelp, bool withDerivatives) {
    flags.gpuOption = cmd.add_flag("--gpu", flags.gpu, gpuHelp);
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
    if (flags.gpu && !gpuHasSource(options.source))
        refuseOption(flags.gpuOption, "the GPU renders --filter none, paper or smooth");
}

std::unique_ptr<ViewRenderer> makeRenderer(const PatternSpec& spec, const FilterOptions& options,
                                           const DeviceFlags& flags, PartCache* parts) {
    checkDeviceFilter(flags, options);
    if (!flags.gpu) return makeCpuRenderer(spec, options, parts);
    return makeGpuRenderer(spec, options, flags.pipeline, flags.derivatives);
}

}  // namespace stochtex::cli
