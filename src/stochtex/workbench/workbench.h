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
#include "stochtex/workbench/document.h"
#include "stochtex/workbench/options.h"

namespace stochtex {

// Opens the window and runs until it closes, `frames` frames are drawn or
// the script quits; returns the number of frames drawn. GpuUnavailable
// without a display; InputError for a document or script step that fails
// (an edit the pattern refuses is shown in the panel instead).
int runWorkbench(WorkbenchDocument document, const WorkbenchOptions& options);

}  // namespace stochtex
