#pragma once
// C++ view of kernel/lean.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/lean.glsl"
}  // namespace stochtex::kernel
