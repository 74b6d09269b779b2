#pragma once
// The interactive window of `stochtex view`: GLFW input drives a camera, a
// filter mode and the footprint derivatives; each frame is drawn by the GLSL
// implementation.
#include <string>

#include "stochtex/gpu/gpu_pattern.h"
#include "stochtex/pattern/pattern_spec.h"

namespace stochtex::cli {

struct ViewWindowOptions {
    Camera camera;  // the starting camera; the view's size is the window's
    FilterOptions filter;
    int frames = 0;          // quit after this many frames (0: when the window closes)
    std::string screenshot;  // save the last frame here when not empty
};

// Opens the window on the pattern of `spec` (a texture graph that is not a
// pattern H∘N through its generated program) and runs until it closes (or
// `frames` frames); returns the number of frames drawn.
int runViewWindow(const PatternSpec& spec, const ViewWindowOptions& options);

}  // namespace stochtex::cli
