#pragma once
// C++ view of kernel/cube_map.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/cube_map.glsl"
}  // namespace stochtex::kernel
