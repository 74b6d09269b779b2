#pragma once
// The renderer behind `render` and `bake-image`: the CPU evaluator or, with
// --gpu, the GLSL implementation on a headless OpenGL context, as one
// ViewRenderer (pattern/view_renderer.h).
#include <memory>
#include <string>

#include "common.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/pattern/view_renderer.h"

namespace stochtex::cli {

struct DeviceFlags {
    bool gpu = false;
    GpuView::Pipeline pipeline = GpuView::Pipeline::Fragment;
    GpuView::Derivatives derivatives = GpuView::Derivatives::Camera;
    const CLI::Option* gpuOption = nullptr;  // the flag that sets gpu, which its errors name
};
// --gpu, --pipeline and (withDerivatives) --derivatives.
void addDeviceFlags(CLI::App& cmd, DeviceFlags& flags, const std::string& gpuHelp, bool withDerivatives);
// --pipeline and --derivatives refused without --gpu (refuseWithoutEffect).
void refuseUnusedDeviceFlags(const CLI::App& cmd, const DeviceFlags& flags);
// InputError if --gpu is asked for a filter the GPU does not implement
// (exact, reference): callers check before building the pattern.
void checkDeviceFilter(const DeviceFlags& flags, const FilterOptions& options);

// The renderer of a pattern file for these flags: the CPU evaluator, or
// with --gpu the GPU's on a headless context (checkDeviceFilter first).
// `parts` (PartCache) serves the CPU evaluator only: each GPU renderer has a
// context of its own, and a cache's device attachments belong to one.
std::unique_ptr<ViewRenderer> makeRenderer(const PatternSpec& spec, const FilterOptions& options,
                                           const DeviceFlags& flags, PartCache* parts = nullptr);

}  // namespace stochtex::cli
