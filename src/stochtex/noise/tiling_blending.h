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
#include <cmath>
#include <cstdint>
#include <memory>

#include "stochtex/core/floor.h"
#include "stochtex/core/hash.h"
#include "stochtex/noise/example.h"

namespace stochtex {

constexpr double kDefaultGridDensity = 3.4641016151377544;  // 2√3

// The three tiles seen at a point: the lattice cell, which of its two
// triangles holds the point, and the normalised weights of its vertices.
// Vertex ids wrap modulo 2³² (as GLSL uints do) before hashing.
struct BlendStencil {
    uint32_t cellX = 0, cellY = 0;
    bool upper = false;  // triangle (1,1),(1,0),(0,1) of the cell, else (0,0),(0,1),(1,0)
    std::array<float, 3> w{};

    uint32_t vx(size_t i) const { return cellX + uint32_t(upper ? i < 2 : i == 2); }
    uint32_t vy(size_t i) const { return cellY + uint32_t(upper ? i != 1 : i == 1); }
    bool sameTiles(const BlendStencil& o) const { return cellX == o.cellX && cellY == o.cellY && upper == o.upper; }
};

// The triangle grid along one row of constant v: the skewed y coordinate
// (1.15470054 v) and its floor do not change along u, so a scanline pays
// only for x = u − 0.57735027 v.
class TriangleGridRow {
public:
    TriangleGridRow(double v, double density = kDefaultGridDensity) : density_(density) {
        const double sv = v * density;
        xShift_ = 0.57735026918962573 * sv;
        const double y = 1.1547005383792515 * sv;
        const int64_t by = floorToInt(y);
        fy_ = float(y - double(by));
        iy_ = uint32_t(uint64_t(by));  // ids wrap to 32 bits for hashing, as in GLSL
    }

    BlendStencil stencil(double u) const {
        const double x = u * density_ - xShift_;
        const int64_t bx = floorToInt(x);
        const float fx = float(x - double(bx));
        BlendStencil s;
        s.cellX = uint32_t(uint64_t(bx));
        s.cellY = iy_;
        const float fz = 1.0f - fx - fy_;
        s.upper = !(fz > 0.0f);
        if (!s.upper)
            s.w = {fz, fy_, fx};
        else
            s.w = {-fz, 1.0f - fy_, 1.0f - fx};
        // Variance-preserving normalisation: Σ w² = 1.
        const float norm = 1.0f / std::sqrt(s.w[0] * s.w[0] + s.w[1] * s.w[1] + s.w[2] * s.w[2]);
        for (float& w : s.w) w *= norm;
        return s;
    }

private:
    double density_, xShift_;
    float fy_;
    uint32_t iy_;
};

// Triangle-grid stencil at uv (any real uv; the grid does not wrap).
inline BlendStencil triangleGrid(double u, double v, double density = kDefaultGridDensity) {
    return TriangleGridRow(v, density).stencil(u);
}

// Random tile offset of a grid vertex, in [0,1)² (one example period).
struct TileOffset {
    float u, v;
};
inline TileOffset tileOffset(uint32_t vx, uint32_t vy, uint32_t seed) {
    const UInt3 h = pcg3d({vx, vy, seed});
    return {unitFloat(h.x), unitFloat(h.y)};
}

// One scalar noise made by tiling and blending an example.
class TilingBlendingNoise {
public:
    TilingBlendingNoise() = default;
    TilingBlendingNoise(std::shared_ptr<const NoiseExample> example, uint32_t offsetSeed)
        : example_(std::move(example)), seed_(offsetSeed) {}

    const NoiseExample& example() const { return *example_; }
    uint32_t offsetSeed() const { return seed_; }

    // What a pixel needs from its three tiles that stays fixed along a
    // scanline while the tiles do not change: the tiles' u offsets (in
    // texels of grid g) and the rows of g their lookups read (v + o_v is
    // constant). g is the example itself or any level of its pyramids.
    struct TileRows {
        std::array<float, 3> offsetTexels;
        std::array<GridRows, 3> rows;
    };
    using Offsets = std::array<TileOffset, 3>;
    Offsets offsets(const BlendStencil& s) const {
        return {tileOffset(s.vx(0), s.vy(0), seed_), tileOffset(s.vx(1), s.vy(1), seed_),
                tileOffset(s.vx(2), s.vy(2), seed_)};
    }
    template <class Grid>
    TileRows tileRows(const Offsets& offs, float fv, const Grid& g) const {
        TileRows t;
        for (size_t i = 0; i < 3; ++i) {
            const TileOffset o = offs[i];
            float sv = fv + o.v;
            if (sv >= 1.0f) sv -= 1.0f;
            t.offsetTexels[i] = o.u * g.sizeF();
            t.rows[i] = g.rows(sv);
        }
        return t;
    }
    TileRows tileRows(const BlendStencil& s, float fv) const { return tileRows(offsets(s), fv, example_->grid()); }

    // The three tiles' values (every channel) of grid g at u (fu = u reduced
    // to one period).
    template <int C>
    std::array<std::array<float, C>, 3> tileValues(const TileRows& t, float fu, const BasicPeriodicGrid<C>& g) const {
        const float size = g.sizeF();
        const float tu = fu * size + 0.5f;  // texel units, as sampleTexels wants
        std::array<std::array<float, C>, 3> out;
        for (size_t i = 0; i < 3; ++i) {
            float su = tu + t.offsetTexels[i];
            su -= su >= size + 0.5f ? size : 0.0f;  // wrap into one period (branch-free)
            out[i] = g.sampleTexels(t.rows[i], su);
        }
        return out;
    }

    // Eq. 7 (and eq. 8 on a MIP level): μ + Σ w_i (e_i − μ), e_i = channel c
    // of the tiles' values.
    template <int C>
    static float mix(const BlendStencil& s, const std::array<std::array<float, C>, 3>& e, float mean, int c = 0) {
        float n = mean;
        for (size_t i = 0; i < 3; ++i) n += s.w[i] * (e[i][size_t(c)] - mean);
        return n;
    }

    // N(u) in the example's blending space (before T⁻¹), with the tiles of
    // the stencil s; fu is u reduced to one period.
    float blend(const BlendStencil& s, const TileRows& t, float fu) const {
        return mix<1>(s, tileValues<1>(t, fu, example_->grid()), example_->mean());
    }
    float blend(const BlendStencil& s, float fu, float fv) const { return blend(s, tileRows(s, fv), fu); }

    // Output value at uv (T⁻¹ applied for a Gaussianized exemplar).
    float evaluate(double u, double v, double density = kDefaultGridDensity) const;

private:
    std::shared_ptr<const NoiseExample> example_;
    uint32_t seed_ = 0;
};

// uv reduced to one period, in float, without losing precision for large uv.
inline float periodFraction(double t) {
    float f = float(t - double(floorToInt(t)));
    return f >= 1.0f ? 0.0f : f;  // rounding of values just below an integer
}

}  // namespace stochtex
