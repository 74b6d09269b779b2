#pragma once
// Tiling and blending (Heitz & Neyret 2018, Deliot & Heitz 2019; paper eq. 7).
//
// The plane is covered by a triangle grid on uv·density (density 2√3 by
// default) skewed by (u − 0.57735027 v, 1.15470054 v) — the GLSL
// `mat2(1,0,-0.57735027,1.15470054) * uv` convention. Each grid vertex owns a
// hexagonal tile: a copy of the example E shifted by a random offset
// o = hash(vertex, seed) ∈ [0,1)². A point sees three tiles and mixes them
//     N(u) = μ_E + Σ_i w_i(u) (E(u + o_i) − μ_E),
// with the barycentric weights normalised so Σ w_i² = 1, which keeps the
// variance of a Gaussian E (the mean is kept by centring on μ_E).
#include <array>
#include <cstdint>
#include <memory>

#include "stochtex/noise/example.h"

namespace stochtex {

constexpr double kDefaultGridDensity = 3.4641016151377544;  // 2√3

// The three tiles seen at a point: grid vertex ids and normalised weights.
struct BlendStencil {
    std::array<int32_t, 3> vx{}, vy{};
    std::array<float, 3> w{};
};

// Triangle-grid stencil at uv (any real uv; the grid does not wrap).
BlendStencil triangleGrid(double u, double v, double density = kDefaultGridDensity);

// Random tile offset of a grid vertex, in [0,1)² (one example period).
struct TileOffset {
    float u, v;
};
TileOffset tileOffset(int32_t vx, int32_t vy, uint32_t seed);

// One scalar noise made by tiling and blending an example.
class TilingBlendingNoise {
public:
    TilingBlendingNoise() = default;
    TilingBlendingNoise(std::shared_ptr<const NoiseExample> example, uint32_t offsetSeed)
        : example_(std::move(example)), seed_(offsetSeed) {}

    const NoiseExample& example() const { return *example_; }
    uint32_t offsetSeed() const { return seed_; }

    // Blended value (in the example's blending space, before T⁻¹) at uv,
    // given the stencil of uv. fu, fv are uv reduced to one period [0,1).
    float blend(const BlendStencil& s, float fu, float fv) const {
        const float mean = example_->mean();
        float n = mean;
        for (int i = 0; i < 3; ++i) {
            const TileOffset o = tileOffset(s.vx[size_t(i)], s.vy[size_t(i)], seed_);
            float su = fu + o.u, sv = fv + o.v;
            if (su >= 1.0f) su -= 1.0f;
            if (sv >= 1.0f) sv -= 1.0f;
            n += s.w[size_t(i)] * (example_->sampleBilinear(su, sv) - mean);
        }
        return n;
    }

    // Output value at uv (T⁻¹ applied for a Gaussianized exemplar).
    float evaluate(double u, double v, double density = kDefaultGridDensity) const;

private:
    std::shared_ptr<const NoiseExample> example_;
    uint32_t seed_ = 0;
};

// uv reduced to one period, in float, without losing precision for large uv.
inline float periodFraction(double t) {
    float f = float(t - std::floor(t));
    return f >= 1.0f ? 0.0f : f;  // rounding of values just below an integer
}

}  // namespace stochtex
