#pragma once
// What renders a camera's view of a pattern: one interface for the CPU
// evaluator (FilteredGraph; makeCpuRenderer owns one for a pattern file)
// and the GPU host (GpuView; gpu/gpu_graph.h has makeGpuRenderer), spoken
// to by the CLI's render and bake-image, CameraSource (the studies' frames)
// and the workbench.
#include <functional>
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

// Pixel rows [y0, y0 + rows) of a zoom camera's view as a view of their own
// (its offset moved down by y0 rows): the band bake-image renders, and the
// task of a distributed bake (stochtex/dask.py), so both write the same
// bytes. InputError for a plane camera (a perspective frame is rendered
// whole) or rows outside the view.
Camera bandCamera(const Camera& whole, int y0, int rows);

// The view rendered in bands of `band` rows (bandCamera), top to bottom,
// each handed to sink as it is done: memory stays one band whatever the
// view's size.
void renderInBands(const ViewRenderer& renderer, const Camera& whole, int band,
                   const std::function<void(const Image& rows)>& sink, const Progress& progress = {});

}  // namespace stochtex
