#pragma once
// C++ view of kernel/sigma_levels.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/sigma_levels.glsl"
}  // namespace stochtex::kernel
