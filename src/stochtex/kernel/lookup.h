#pragma once
// C++ view of kernel/lookup.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/lookup.glsl"
}  // namespace stochtex::kernel
