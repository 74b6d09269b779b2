#pragma once
// C++ view of kernel/hash.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/hash.glsl"
}  // namespace stochtex::kernel
