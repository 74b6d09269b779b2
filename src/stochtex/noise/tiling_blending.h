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
#include <tuple>
#include <utility>

#include "stochtex/core/floor.h"
#include "stochtex/kernel/grid.h"
#include "stochtex/noise/example.h"

namespace stochtex {

// The grid's density, skew, stencil, vertices and tile offsets are the
// kernel's (kernel/grid.glsl), shared with the shaders.
// 2√3 rounded to float, the value the shaders get.
inline const double kDefaultGridDensity = double(kernel::kDefaultGridDensity);

// The three tiles seen at a point (cell, triangle, weights); see kernel::Stencil.
using BlendStencil = kernel::Stencil;

inline bool sameTiles(const BlendStencil& a, const BlendStencil& b) {
    return a.cell.x == b.cell.x && a.cell.y == b.cell.y && a.upper == b.upper;
}

// The grid's shape (kernel::GridShape) with its densities in double, as
// the CPU splits uv into cells: the plane's equilateral grid, or a grid
// stretched along u (the v density is kept) that repeats over a whole
// number of example periods, for tileable bakes.
struct GridLayout {
    double densityU = kDefaultGridDensity, densityV = kDefaultGridDensity;
    kernel::ivec2 period{0, 0};  // (n, m) cells, kernel::GridShape's; (0, 0): no period

    static GridLayout plane(double density) { return {density, density, {0, 0}}; }
    // The grid nearest the plane's of `density` that repeats every
    // periodsU × periodsV example periods: m = round(density·periodsV/√3)
    // skewed rows and n = round(density·periodsU) cells, each at least 1,
    // the densities made to fit them exactly. periodsU, periodsV ≥ 1.
    static GridLayout periodic(double density, int periodsU, int periodsV);
    bool periodic() const { return period.x > 0; }
    kernel::GridShape kernelShape() const {
        kernel::GridShape g;
        g.density = kernel::vec2(float(densityU), float(densityV));
        g.period = period;
        return g;
    }
    bool operator==(const GridLayout&) const = default;
};

// The triangle grid along one row of constant v: the skewed y coordinate
// (kGridSkewY·v) and its floor do not change along u, so a scanline pays
// only for x = u − kGridSkewX·v. The split into cell and fraction is done in
// double (uv may be far from the origin); the stencil itself is the
// kernel's blendStencil, the same function the shaders call.
class TriangleGridRow {
public:
    TriangleGridRow(double v, const GridLayout& grid = GridLayout{}) : densityU_(grid.densityU), period_(grid.period) {
        const double sv = v * grid.densityV;
        xShift_ = double(kernel::kGridSkewX) * sv;
        const double y = double(kernel::kGridSkewY) * sv;
        const int64_t by = floorToInt(y);
        fy_ = float(y - double(by));
        iy_ = uint32_t(uint64_t(by));  // ids wrap to 32 bits for hashing, as in GLSL
    }

    BlendStencil stencil(double u) const {
        const double x = u * densityU_ - xShift_;
        const int64_t bx = floorToInt(x);
        BlendStencil s = kernel::blendStencil(kernel::uvec2(uint32_t(uint64_t(bx)), iy_), float(x - double(bx)), fy_);
        s.period = period_;
        return s;
    }

private:
    double densityU_, xShift_;
    kernel::ivec2 period_;
    float fy_;
    uint32_t iy_;
};

// Triangle-grid stencil at uv (any real uv).
inline BlendStencil triangleGrid(double u, double v, const GridLayout& grid = GridLayout{}) {
    return TriangleGridRow(v, grid).stencil(u);
}

// Random tile offset of a grid vertex, in [0,1)² (one example period).
using TileOffset = kernel::vec2;
inline TileOffset tileOffset(uint32_t vx, uint32_t vy, uint32_t seed) {
    return kernel::tileOffset(kernel::uvec2(vx, vy), seed);
}

// One scalar noise made by tiling and blending an example.
class TilingBlendingNoise {
public:
    TilingBlendingNoise() = default;
    TilingBlendingNoise(std::shared_ptr<const NoiseExample> example, uint32_t offsetSeed)
        : example_(std::move(example)), seed_(offsetSeed) {}

    const NoiseExample& example() const { return *example_; }
    // The example as held, shared: what a kept part built from it holds (PartCache).
    const std::shared_ptr<const NoiseExample>& sharedExample() const { return example_; }
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
        return {kernel::tileOffset(kernel::stencilVertex(s, 0), seed_),
                kernel::tileOffset(kernel::stencilVertex(s, 1), seed_),
                kernel::tileOffset(kernel::stencilVertex(s, 2), seed_)};
    }
    template <class Grid>
    TileRows tileRows(const Offsets& offs, float fv, const Grid& g) const {
        TileRows t;
        const float tv = kernel::texelOfPoint(fv, g.sizeF());
        for (size_t i = 0; i < 3; ++i) std::tie(t.offsetTexels[i], t.rows[i]) = tileRow(offs[i], tv, g);
        return t;
    }
    // One tile's part of tileRows: its u offset in texels of g and the rows
    // its lookup reads, for a point at texel row tv of g (no offset).
    template <class Grid>
    static std::pair<float, GridRows> tileRow(TileOffset o, float tv, const Grid& g) {
        const float size = g.sizeF();
        return {o.x * size, g.rowsAt(kernel::periodicTexel(tv, o.y * size, size))};
    }
    TileRows tileRows(const BlendStencil& s, float fv) const { return tileRows(offsets(s), fv, example_->grid()); }

    // The three tiles' values (every channel) of grid g at u (fu = u reduced
    // to one period).
    template <int C>
    std::array<std::array<float, C>, 3> tileValues(const TileRows& t, float fu, const BasicPeriodicGrid<C>& g) const {
        const float size = g.sizeF();
        const float tu = kernel::texelOfPoint(fu, size);
        std::array<std::array<float, C>, 3> out;
        for (size_t i = 0; i < 3; ++i)
            out[i] = g.sampleTexels(t.rows[i], kernel::periodicTexel(tu, t.offsetTexels[i], size));
        return out;
    }

    // Channel c of the three tiles' values.
    template <int C>
    static kernel::vec3 channel(const std::array<std::array<float, C>, 3>& e, int c = 0) {
        return {e[0][size_t(c)], e[1][size_t(c)], e[2][size_t(c)]};
    }
    // Eq. 7 (and eq. 8 on a MIP level): μ + Σ w_i (e_i − μ), e_i = channel c
    // of the tiles' values (kernel::blendMean, as in the shaders).
    template <int C>
    static float mix(const BlendStencil& s, const std::array<std::array<float, C>, 3>& e, float mean, int c = 0) {
        return kernel::blendMean(mean, s.w, channel<C>(e, c));
    }

    // N(u) in the example's blending space (before T⁻¹), with the tiles of
    // the stencil s; fu is u reduced to one period.
    float blend(const BlendStencil& s, const TileRows& t, float fu) const {
        return mix<1>(s, tileValues<1>(t, fu, example_->grid()), example_->mean());
    }
    float blend(const BlendStencil& s, float fu, float fv) const { return blend(s, tileRows(s, fv), fu); }

    // Output value at uv (T⁻¹ applied for a Gaussianized exemplar).
    float evaluate(double u, double v, const GridLayout& grid = GridLayout{}) const;

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
