#pragma once
// C++ view of kernel/camera.glsl.
#include "stochtex/kernel/coords.h"
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/camera.glsl"
}  // namespace stochtex::kernel
