#pragma once
// C++ view of kernel/footprint.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/footprint.glsl"
}  // namespace stochtex::kernel
