#pragma once
// C++ view of kernel/grid.glsl.
#include "stochtex/kernel/glsl.h"
#include "stochtex/kernel/hash.h"

namespace stochtex::kernel {
#include "stochtex/kernel/grid.glsl"
}  // namespace stochtex::kernel
