#pragma once
// C++ view of kernel/graph_ops.glsl.
#include "stochtex/kernel/glsl.h"

namespace stochtex::kernel {
#include "stochtex/kernel/graph_ops.glsl"
}  // namespace stochtex::kernel
