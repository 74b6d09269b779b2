#pragma once
// C++ view of kernel/estimate.glsl: footprintEstimate is a template over
// the host's texel source, whose probeTexels and levelAverages are found by
// argument-dependent lookup where it is instantiated.
#include "stochtex/kernel/coords.h"
#include "stochtex/kernel/footprint.h"
#include "stochtex/kernel/glsl.h"
#include "stochtex/kernel/moments.h"
#include "stochtex/kernel/texel_stats.h"

namespace stochtex::kernel {
#include "stochtex/kernel/estimate.glsl"
}  // namespace stochtex::kernel
