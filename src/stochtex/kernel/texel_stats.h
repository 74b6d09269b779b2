#pragma once
// C++ view of kernel/texel_stats.glsl.
#include "stochtex/kernel/glsl.h"
#include "stochtex/kernel/moments.h"

namespace stochtex::kernel {
#include "stochtex/kernel/texel_stats.glsl"
}  // namespace stochtex::kernel
