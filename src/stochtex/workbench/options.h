#pragma once
// What the workbench window starts with (workbench.h's runWorkbench, the
// model's first state): the camera, filter, view, mode and analysis, a
// program's settings, the panel, the frames to run, the screenshot and the
// script.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "stochtex/gpu/mesh_file.h"
#include "stochtex/gpu/shadertoy.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/workbench/live_analysis.h"
#include "stochtex/workbench/script.h"

namespace stochtex {

struct WorkbenchOptions {
    Camera camera;         // the starting camera; its view's size is the picture area's
    FilterOptions filter;  // the starting filter: none, paper or smooth (with its aniso and response)
    WorkbenchView view = WorkbenchView::Zoom;
    // The user's mesh for the mesh view (view --mesh FILE; none: the view is
    // not offered) and how the pattern lies on it.
    std::shared_ptr<const LoadedMesh> mesh;
    SurfaceMapping mapping = SurfaceMapping::Uv;
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
// The entries of its numbers (frames): its check, the CLI's flags.
std::span<const OptionMember<WorkbenchOptions>> workbenchOptionsMembers();

// Width of the editing panel, pixels: the window is this much wider than
// the picture area while the panel shows.
constexpr int kWorkbenchPanelWidth = 380;

}  // namespace stochtex
