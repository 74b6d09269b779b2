#pragma once
// C++ view of kernel/marble.glsl.
#include "stochtex/kernel/glsl.h"
#include "stochtex/kernel/hash.h"

namespace stochtex::kernel {
#include "stochtex/kernel/marble.glsl"
}  // namespace stochtex::kernel
