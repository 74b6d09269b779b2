#pragma once
// The interactive window of `stochtex view`: GLFW input drives a camera, a
// filter mode and the footprint derivatives; each frame is drawn by the GLSL
// implementation.
#include <string>

#include "stochtex/gpu/gpu_pattern.h"

namespace stochtex::cli {

struct ViewWindowOptions {
    Camera camera;  // the starting camera; the view's size is the window's
    FilterOptions filter;
    int frames = 0;          // quit after this many frames (0: when the window closes)
    std::string screenshot;  // save the last frame here when not empty
};

// Opens the window and runs until it closes (or `frames` frames); returns
// the number of frames drawn.
int runViewWindow(const Pattern& pattern, const std::string& name, const ViewWindowOptions& options);

}  // namespace stochtex::cli
