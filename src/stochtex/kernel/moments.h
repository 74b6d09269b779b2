#pragma once
// C++ view of kernel/moments.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/moments.glsl"
}  // namespace stochtex::kernel
