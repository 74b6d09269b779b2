#pragma once
// The workbench window (issue "The workbench"; thesis ch. 3, GLcv): a
// pattern, texture graph or ShaderToy program drawn by the GLSL
// implementation in a GLFW window, with Dear ImGui panels to edit it (the
// noises' spectra, the colormap's shapes and colours, a graph's node
// parameters from the node table), filter and view switches, the view
// modes of thesis Figure 3.2 (texture, analysis, side by side, split,
// overlay) over a live spectrum, flow or correlation, live reload of the
// files on disk, screenshots, MP4 recording and saving the edited pattern.
//
// The picture area shows exactly what `render` (or `shadertoy`) writes for
// the same view: linear light encoded to sRGB codes, row 0 at the top.
#include <string>
#include <vector>

#include "stochtex/gpu/shadertoy.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/workbench/document.h"
#include "stochtex/workbench/live_analysis.h"
#include "stochtex/workbench/script.h"

namespace stochtex {

struct WorkbenchOptions {
    Camera camera;         // the starting camera; its view's size is the picture area's
    FilterOptions filter;  // the starting filter: none, paper or smooth (with its aniso and response)
    WorkbenchView view = WorkbenchView::Zoom;
    WorkbenchMode mode = WorkbenchMode::Texture;
    LiveAnalysisKind analysis = LiveAnalysisKind::Spectrum;
    ShadertoySettings shadertoy;  // a program's settings (its size follows the picture area); its fps is
                                  // also a recording's rate, a pattern's frames placed on the wall clock
    bool panel = true;            // the editing panel at the left (Tab toggles it)
    int frames = 0;               // quit after this many frames (0: when the window closes)
    std::string screenshot;       // the picture area of the last frame, to this file, when not empty
    std::vector<WorkbenchStep> script;
};

// InputError naming the parameter: sizes, aniso, camera, a filter the GPU
// does not draw.
void validateWorkbenchOptions(const WorkbenchOptions& options);

// Width of the editing panel, pixels: the window is this much wider than
// the picture area while the panel shows.
constexpr int kWorkbenchPanelWidth = 380;

// Opens the window and runs until it closes, `frames` frames are drawn or
// the script quits; returns the number of frames drawn. GpuUnavailable
// without a display; InputError for a document or script step that fails
// (an edit the pattern refuses is shown in the panel instead).
int runWorkbench(WorkbenchDocument document, const WorkbenchOptions& options);

}  // namespace stochtex
