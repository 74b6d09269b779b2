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
#include "stochtex/pattern/view.h"

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

// Pixel columns [x0, x0 + columns) of a zoom camera's view (its offset
// moved right by x0 columns), as bandCamera for rows.
Camera columnCamera(const Camera& whole, int x0, int columns);

// Rows [y0, y0 + rows) of a zoom view as wide as a baked one
// (kMaxBakedSide): bandCamera's band, rendered in tiles of at most
// kMaxOutputSide columns (each a render) joined side by side.
Image renderRows(const ViewRenderer& renderer, const Camera& whole, int y0, int rows, const Progress& progress = {});

// The rows of a band of a view `width` pixels wide: `band`, fewer where
// `band` rows would hold more than kMaxBandPixels, at least one.
int bandRows(int width, int band);

// The view rendered in bands of bandRows(width, band) rows (renderRows),
// top to bottom, each handed to sink as it is done: memory stays one band
// whatever the view's size.
void renderInBands(const ViewRenderer& renderer, const Camera& whole, int band,
                   const std::function<void(const Image& rows)>& sink, const Progress& progress = {});

}  // namespace stochtex
