#pragma once
#include <cstdint>

namespace stochtex {

// floor() for |t| < 2⁶³ without a libm call (baseline x86-64 has no
// rounding instruction, and this runs several times per pixel).
inline int64_t floorToInt(double t) {
    const int64_t i = int64_t(t);
    return i - (t < double(i) ? 1 : 0);
}

}  // namespace stochtex
