#pragma once
// C++ view of kernel/colour.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/colour.glsl"
}  // namespace stochtex::kernel
