#include "stochtex/noise/tiling_blending.h"

#include <cmath>

#include "stochtex/core/hash.h"

namespace stochtex {

BlendStencil triangleGrid(double u, double v, double density) {
    const double su = u * density, sv = v * density;
    // Skew: (u − 0.57735027 v, 1.15470054 v), i.e. the inverse of the
    // equilateral lattice basis (1,0), (½, √3/2).
    const double x = su - 0.57735026918962573 * sv;
    const double y = 1.1547005383792515 * sv;
    const double bx = std::floor(x), by = std::floor(y);
    const float fx = float(x - bx), fy = float(y - by);
    const int32_t ix = int32_t(bx), iy = int32_t(by);
    BlendStencil s;
    const float fz = 1.0f - fx - fy;
    if (fz > 0.0f) {
        s.w = {fz, fy, fx};
        s.vx = {ix, ix, ix + 1};
        s.vy = {iy, iy + 1, iy};
    } else {
        s.w = {-fz, 1.0f - fy, 1.0f - fx};
        s.vx = {ix + 1, ix + 1, ix};
        s.vy = {iy + 1, iy, iy + 1};
    }
    // Variance-preserving normalisation: Σ w² = 1.
    const float norm = 1.0f / std::sqrt(s.w[0] * s.w[0] + s.w[1] * s.w[1] + s.w[2] * s.w[2]);
    for (float& w : s.w) w *= norm;
    return s;
}

TileOffset tileOffset(int32_t vx, int32_t vy, uint32_t seed) {
    const UInt3 h = pcg3d({uint32_t(vx), uint32_t(vy), seed});
    return {unitFloat(h.x), unitFloat(h.y)};
}

float TilingBlendingNoise::evaluate(double u, double v, double density) const {
    const BlendStencil s = triangleGrid(u, v, density);
    return example_->toOutput(blend(s, periodFraction(u), periodFraction(v)));
}

}  // namespace stochtex
