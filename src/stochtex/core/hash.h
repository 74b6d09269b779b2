#pragma once
// The project's integer hash for CPU code that works on plain integers. The
// hash itself is the kernel's pcg3d (kernel/hash.glsl), the same function
// the shaders call, so both sides draw the same numbers bit for bit.
#include <cstdint>

#include "stochtex/kernel/hash.h"

namespace stochtex {

struct UInt3 {
    uint32_t x, y, z;
};

inline UInt3 pcg3d(UInt3 v) {
    const kernel::uvec3 h = kernel::pcg3d(kernel::uvec3(v.x, v.y, v.z));
    return {h.x, h.y, h.z};
}

using kernel::deriveSeed;
using kernel::unitFloat;

}  // namespace stochtex
