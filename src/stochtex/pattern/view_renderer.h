#pragma once
// What renders a camera's view of a pattern: one interface for the CPU
// evaluator (FilteredGraph; makeCpuRenderer owns one for a pattern file)
// and the GPU host (GpuView; gpu/gpu_graph.h has makeGpuRenderer), spoken
// to by the CLI's render and bake-image, CameraSource (the studies' frames)
// and the workbench.
#include <string>

#include "stochtex/core/progress.h"
#include "stochtex/image/image.h"
#include "stochtex/pattern/camera.h"

namespace stochtex {

class ViewRenderer {
public:
    virtual ~ViewRenderer() = default;
    // The view through `camera`: linear RGB, row 0 on top. progress: the
    // fraction of rows done, where the renderer works by rows (the CPU).
    virtual Image render(const Camera& camera, const Progress& progress = {}) const = 0;
    // W of the examples: a camera's texels are in units of it.
    virtual int exampleSize() const = 0;
    // Where it runs: "CPU", or the OpenGL context's description.
    virtual std::string device() const { return "CPU"; }
};

}  // namespace stochtex
