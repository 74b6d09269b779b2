#pragma once
#include <array>

#include "stochtex/kernel/camera.h"

namespace stochtex {

// The transform of uv a linear field node is seen through (transform
// nodes, composed): the field at uv is its example's tiled field at
// M·uv + t. Identity for every node not downstream of a transform.
struct UvTransform {
    std::array<double, 4> m{1, 0, 0, 1};  // row-major: (m0 m1; m2 m3)
    std::array<double, 2> t{0, 0};
    bool identity() const { return m == std::array<double, 4>{1, 0, 0, 1} && t == std::array<double, 2>{0, 0}; }
    bool operator==(const UvTransform&) const = default;
    // The kernel's transformUv / transformVector (kernel/camera.glsl), which
    // the GPU program calls with these numbers.
    std::array<double, 2> apply(double u, double v) const {
        const kernel::coord2 r = kernel::transformUv(kernel::coord2(u, v), kernel::coord2(m[0], m[1]),
                                                     kernel::coord2(m[2], m[3]), kernel::coord2(t[0], t[1]));
        return {r.x, r.y};
    }
    // The linear part on a vector (a Jacobian column).
    std::array<double, 2> linear(double u, double v) const {
        const kernel::coord2 r =
            kernel::transformVector(kernel::coord2(u, v), kernel::coord2(m[0], m[1]), kernel::coord2(m[2], m[3]));
        return {r.x, r.y};
    }
};

}  // namespace stochtex
