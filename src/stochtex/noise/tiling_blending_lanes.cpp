// Tiling and blending in lanes: compiled once per vector target by
// Highway's foreach_target (this file includes itself), dispatched at run
// time. Every step is the scalar kernel's formula, in its order of
// operations, with separate multiplies and adds (the build contracts none:
// -ffp-contract=off), so the lanes give the scalar kernel's values.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "stochtex/noise/tiling_blending_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

// Per target, after foreach_target.h (Log2).
#include <hwy/contrib/math/math-inl.h>

#include <algorithm>
#include <array>
#include <stdexcept>

#include "stochtex/noise/tiling_blending_lanes.h"

HWY_BEFORE_NAMESPACE();
namespace stochtex::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// GridRowLanes::compute in double lanes: the split of the skewed x into
// cell and fraction needs double precision far from the origin, as
// TriangleGridRow::stencil does it.
void GridRowImpl(GridRowLanes& row, double offset, double scale, double invW, double density, double xShift) {
    const hn::ScalableTag<double> dd;
    const hn::Rebind<int32_t, decltype(dd)> di32;
    const hn::Rebind<uint32_t, decltype(dd)> du32;
    const hn::Rebind<float, decltype(dd)> df;
    const size_t n = hn::Lanes(dd);
    const auto half = hn::Set(dd, 0.5), vOffset = hn::Set(dd, offset), vScale = hn::Set(dd, scale);
    const auto vInvW = hn::Set(dd, invW), vDensity = hn::Set(dd, density), vShift = hn::Set(dd, xShift);
    const auto one = hn::Set(df, 1.0f);
    const auto ramp = hn::Iota(dd, 0.0);
    for (size_t p = 0; p < row.cellX.size(); p += n) {
        const auto px = hn::Add(hn::Set(dd, double(p)), ramp);
        // kernel::zoomUv: (offset + p·scale)·invW at the pixel centre.
        const auto u = hn::Mul(hn::Add(vOffset, hn::Mul(hn::Add(px, half), vScale)), vInvW);
        const auto x = hn::Sub(hn::Mul(u, vDensity), vShift);
        const auto bx = hn::Floor(x);
        hn::StoreU(hn::DemoteTo(df, hn::Sub(x, bx)), df, row.fx.data() + p);
        // The cell ids: the first lane's as a 64-bit integer wrapped to 32
        // bits, the others' as their (exact, small) distance from it — a
        // vector's pixels span at most a few million cells at the largest
        // scale — so no lane converts a double to 64 bits.
        const double first = hn::GetLane(bx);
        const auto step = hn::BitCast(du32, hn::DemoteTo(di32, hn::Sub(bx, hn::Set(dd, first))));
        const auto cell = hn::Add(hn::Set(du32, uint32_t(uint64_t(int64_t(first)))), step);
        hn::StoreU(cell, du32, row.cellX.data() + p);
        // periodFraction: a value just below an integer may round to 1.
        const auto fu = hn::DemoteTo(df, hn::Sub(u, hn::Floor(u)));
        hn::StoreU(hn::IfThenZeroElse(hn::Ge(fu, one), fu), df, row.fu.data() + p);
    }
}

using DF = hn::ScalableTag<float>;
static_assert(hn::MaxLanes(DF()) <= size_t(kMaxFloatLanes), "a row's arrays are padded for 16 float lanes");
using DU = hn::RebindToUnsigned<DF>;
using DI = hn::RebindToSigned<DF>;
using VF = hn::Vec<DF>;
using VU = hn::Vec<DU>;
using VI = hn::Vec<DI>;

// kernel::pcg3d on three lanes' words; returns the first two.
HWY_INLINE void Pcg3d(DU du, VU x, VU y, VU z, VU& hx, VU& hy) {
    const auto mul = hn::Set(du, 1664525u), add = hn::Set(du, 1013904223u);
    x = hn::Add(hn::Mul(x, mul), add);
    y = hn::Add(hn::Mul(y, mul), add);
    z = hn::Add(hn::Mul(z, mul), add);
    x = hn::Add(x, hn::Mul(y, z));
    y = hn::Add(y, hn::Mul(z, x));
    z = hn::Add(z, hn::Mul(x, y));
    x = hn::Xor(x, hn::ShiftRight<16>(x));
    y = hn::Xor(y, hn::ShiftRight<16>(y));
    z = hn::Xor(z, hn::ShiftRight<16>(z));
    hx = hn::Add(x, hn::Mul(y, z));
    hy = hn::Add(y, hn::Mul(z, hx));
}

// hn::ConvertTo(DI(), v) (truncation) for lanes known to lie within
// int32's range — texel coordinates, table taps, σ levels, all bounded by
// the sizes they index — without the fix-up Highway adds on x86 for lanes
// beyond it (four instructions a conversion, a few a tile lookup). The
// callers' clamps keep them there: TableTap sends NaN and x ≤ 0 to 0 and
// caps x at 1, PeriodicTexel wraps into one period of a finite u
// (validateView bounds the view), SigmaLevelCoordinate masks NaN and σ ≤ 0
// and caps at the top level. Out of range, cvttps2dq gives INT_MIN where
// ConvertTo gave INT_MAX.
HWY_INLINE VI TruncateInRange(VF v) {
#if HWY_ARCH_X86 && HWY_TARGET == HWY_AVX2
    return VI{_mm256_cvttps_epi32(v.raw)};
#elif HWY_ARCH_X86 && (HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3)
    return VI{_mm_cvttps_epi32(v.raw)};
#elif HWY_ARCH_X86 && (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL)
    return VI{_mm512_cvttps_epi32(v.raw)};
#else
    return hn::ConvertTo(DI(), v);
#endif
}

// kernel::unitFloat: the top 24 bits, exactly representable.
HWY_INLINE VF UnitFloat(DF df, VU bits) {
    const DI di;
    return hn::Mul(hn::ConvertTo(df, hn::BitCast(di, hn::ShiftRight<8>(bits))), hn::Set(df, 1.0f / 16777216.0f));
}

// kernel::periodicTexel: t = point + offset, wrapped once into [½, w + ½).
HWY_INLINE VF PeriodicTexel(VF point, VF offset, VF w, VF wHalf) {
    const auto t = hn::Add(point, offset);
    return hn::IfThenElse(hn::Ge(t, wHalf), hn::Sub(t, w), t);
}

// a + t·(b − a), the kernel's blends (blendEntries, blendColumnsFirst).
HWY_INLINE VF Lerp(VF a, VF b, VF t) { return hn::Add(a, hn::Mul(t, hn::Sub(b, a))); }

// The floats at index and index + 1 of every lane (a bilinear row's left
// and right texels): one 64-bit element per lane pair of floats, so half
// the gathered elements of two float gathers (a gather costs per element).
HWY_INLINE void GatherPairs(DF df, const float* base, VI index, VF& left, VF& right) {
#if HWY_TARGET == HWY_SCALAR  // one lane: no pairs
    left = hn::GatherIndex(df, base, index);
    right = hn::GatherIndex(df, base + 1, index);
#else
    const hn::Repartition<double, DF> dd;
    const hn::Repartition<int64_t, DF> di64;
    const hn::Half<DI> dih;
    const auto bytes = hn::ShiftLeft<2>(index);
    const double* pairs = reinterpret_cast<const double*>(base);  // read through gathers only
    const auto lo = hn::BitCast(df, hn::GatherOffset(dd, pairs, hn::PromoteTo(di64, hn::LowerHalf(dih, bytes))));
    const auto hi = hn::BitCast(df, hn::GatherOffset(dd, pairs, hn::PromoteTo(di64, hn::UpperHalf(dih, bytes))));
    left = hn::ConcatEven(df, hi, lo);
    right = hn::ConcatOdd(df, hi, lo);
#endif
}

// A bilinear tap's two rows at every lane's column: the floats at
// base + index, + 1, + second and + second + 1 (second = 2: one row of
// interleaved pairs, a texel's mean and variance, then its right
// neighbour's; second = the row stride: a one-channel texel and its right
// neighbour in the row and in the row above), transposed: quad[k] holds
// every lane's float k. Where a vector is one or two 128-bit blocks, a
// lane's four floats are one 128-bit load (two 64-bit ones) and the blocks
// a 4×4 transpose, cheaper here than the 64-bit gathers of GatherPairs;
// elsewhere those gathers. kPairs: second is 2. (A template, so that the
// branch for other vector sizes is not compiled.)
template <bool kPairs, class D, class VI4, class V>
HWY_INLINE void GatherQuads(D df, const float* base, int second, VI4 index, V (&quad)[4]) {
#if HWY_TARGET == HWY_SCALAR
    constexpr size_t kLanes = 1;  // no blocks
#else
    constexpr size_t kLanes = hn::MaxLanes(D());
#endif
    if constexpr (kLanes == 4 || kLanes == 8) {
#if HWY_TARGET != HWY_SCALAR
        const hn::Full128<float> d4;
        const hn::Full64<float> d2;
        const hn::Repartition<double, D> dd;
        alignas(32) int32_t at[kLanes];
        hn::Store(index, hn::RebindToSigned<D>(), at);
        const auto lane = [&](size_t j) {
            const float* p = base + at[j];
            if constexpr (kPairs)
                return hn::LoadU(d4, p);
            else
                return hn::Combine(d4, hn::LoadU(d2, p + second), hn::LoadU(d2, p));
        };
        // c[k]: lane k's four floats in block 0, lane 4 + k's in block 1.
        V c[4];
        for (size_t k = 0; k < 4; ++k) {
            if constexpr (kLanes == 4)
                c[k] = lane(k);
            else
                c[k] = hn::Combine(df, lane(4 + k), lane(k));
        }
        const auto t0 = hn::BitCast(dd, hn::InterleaveLower(df, c[0], c[1]));
        const auto t1 = hn::BitCast(dd, hn::InterleaveLower(df, c[2], c[3]));
        const auto t2 = hn::BitCast(dd, hn::InterleaveUpper(df, c[0], c[1]));
        const auto t3 = hn::BitCast(dd, hn::InterleaveUpper(df, c[2], c[3]));
        quad[0] = hn::BitCast(df, hn::InterleaveLower(dd, t0, t1));
        quad[1] = hn::BitCast(df, hn::InterleaveUpper(dd, t0, t1));
        quad[2] = hn::BitCast(df, hn::InterleaveLower(dd, t2, t3));
        quad[3] = hn::BitCast(df, hn::InterleaveUpper(dd, t2, t3));
#endif
    } else {
        GatherPairs(df, base, index, quad[0], quad[1]);
        GatherPairs(df, base + second, index, quad[2], quad[3]);
    }
}

// kernel::tableTap in lanes on tables of n ≥ 2 entries (n per lane): index
// i, weight t.
HWY_INLINE void TableTap(DF df, VI n, VF x, VI& i, VF& t) {
    const DI di;
    const auto fx = hn::Mul(hn::IfThenElseZero(hn::Gt(x, hn::Zero(df)), hn::Min(x, hn::Set(df, 1.0f))),
                            hn::ConvertTo(df, hn::Sub(n, hn::Set(di, 1))));
    i = hn::Min(TruncateInRange(fx), hn::Sub(n, hn::Set(di, 2)));
    t = hn::Sub(fx, hn::ConvertTo(df, i));
}
HWY_INLINE void TableTap(DF df, int n, VF x, VI& i, VF& t) { TableTap(df, hn::Set(DI(), n), x, i, t); }

// kernel::tableTap + blendEntries on a table of n ≥ 2 entries (T⁻¹'s LUT).
HWY_INLINE VF TableLookup(DF df, const float* table, int n, VF x) {
    VI i;
    VF t;
    TableTap(df, n, x, i, t);
    VF left, right;
    GatherPairs(df, table, i, left, right);
    return Lerp(left, right, t);
}

// The C channels of n consecutive texels as C vectors (C = 2: interleaved
// mean and variance, split).
template <int C>
HWY_INLINE void LoadChannels(DF df, const float* p, VF (&channels)[C]) {
    if constexpr (C == 1)
        channels[0] = hn::LoadU(df, p);
    else
        hn::LoadInterleaved2(df, p, channels[0], channels[1]);
}

// The bilinear taps of lanes that read one row pair at columns ix: each
// channel's left and right texel in the row below (b) and above (a). When
// the columns are ix0 + d with 0 ≤ d < 2n — the lanes' texels lie in a
// window two vectors wide, as they do where neighbouring pixels are at
// most about two texels apart (the unfiltered view at scale ≤ 2, the
// levels a filtered zoom reads, chosen for its footprint) — the window is
// loaded and its lanes permuted into place, cheaper than gathering them.
// Returns false, having read nothing, when the columns are not such a
// window (a wrap inside the vector, pixels further apart) or the window
// would read more than the `available` floats from `below` on.
template <int C>
HWY_INLINE bool WindowTaps(DF df, const float* below, size_t available, int stride, VI ix, VF (&bl)[C], VF (&br)[C],
                           VF (&al)[C], VF (&ar)[C]) {
    const DI di;
    const int n = int(hn::Lanes(df));
    const int ix0 = hn::GetLane(ix);
    const auto d = hn::Sub(ix, hn::Set(di, ix0));
    if (hn::AllTrue(di, hn::Eq(d, hn::Iota(di, 0)))) {
        // Consecutive columns (one texel a pixel, as a zoom at scale 1
        // reads): each tap is the window itself, no permute.
        if (size_t(C * ix0 + stride + C * (1 + n)) > available) return false;
        const float* left = below + C * ix0;
        LoadChannels<C>(df, left, bl);
        LoadChannels<C>(df, left + C, br);
        LoadChannels<C>(df, left + stride, al);
        LoadChannels<C>(df, left + stride + C, ar);
        return true;
    }
    if (!hn::AllFalse(di, hn::Lt(d, hn::Zero(di))) || !hn::AllTrue(di, hn::Lt(d, hn::Set(di, 2 * n)))) return false;
    const bool narrow = hn::AllTrue(di, hn::Lt(d, hn::Set(di, n)));
    if (size_t(C * ix0 + stride + C * (1 + (narrow ? n : 2 * n))) > available) return false;
    const float* left = below + C * ix0;
    const auto index = hn::IndicesFromVec(df, hn::And(d, hn::Set(di, n - 1)));
    const auto inHigh = hn::RebindMask(df, hn::Gt(d, hn::Set(di, n - 1)));
    // One tap of every channel: the window's lanes at d.
    const auto tap = [&](const float* p, VF(&out)[C]) {
        VF low[C];
        LoadChannels<C>(df, p, low);
        for (int c = 0; c < C; ++c) out[c] = hn::TableLookupLanes(low[c], index);
        if (narrow) return;
        VF high[C];
        LoadChannels<C>(df, p + C * n, high);
        for (int c = 0; c < C; ++c) out[c] = hn::IfThenElse(inHigh, hn::TableLookupLanes(high[c], index), out[c]);
    };
    tap(left, bl);
    tap(left + C, br);
    tap(left + stride, al);
    tap(left + stride + C, ar);
    return true;
}

// What a tile's lookups share along a row: its offset in texels along u,
// the padded index of the row below its lookups and the upper row's weight
// (v is fixed on a row, so its rows are too).
struct TileRow {
    float offsetTexels;
    int rowIndex;
    float wy;
};

// A grid a row reads and the constants of its lookups.
template <int C>
struct RowGrid {
    const float* texels;     // the padded grid: index int(ty)·stride + int(tx)·C
    const float* texelsEnd;  // one past its last float
    int stride;              // floats a row
    float size;              // texels a period
    float pointTexelV;       // the row's v in texels (no tile offset)

    explicit RowGrid(const BasicPeriodicGrid<C>& grid, float fv)
        : texels(grid.texel(-1, -1)),
          texelsEnd(texels + grid.bytes() / sizeof(float)),
          stride((grid.size() + 2) * C),
          size(grid.sizeF()),
          pointTexelV(kernel::texelOfPoint(fv, grid.sizeF())) {}
};

// Eq. 7 on the example (C = 1: N, then T⁻¹ where the example has one) or
// eq. 8 and 12 on levels of its statistics pyramid (C = 2: N̂_l and σ̂²_l)
// at every pixel of the row, on L grids at once (L = 2: a zoom between two
// levels): the stencil, its weights and the tiles' hashes are the grids'
// own, the texels and the offsets in texels each grid's.
template <int C, int L>
void BlendGridRow(const TilingBlendingNoise& noise, const std::array<const BasicPeriodicGrid<C>*, L>& grids,
                  const GridRowLanes& row, const std::array<float*, L>& out, const std::array<float*, L>& variance,
                  bool outputSpace) {
    static_assert(C == 1 || C == 2);
    const DF df;
    const DU du;
    const DI di;
    const size_t n = hn::Lanes(df);
    const NoiseExample& example = noise.example();
    const std::array<RowGrid<C>, L> g = [&] {
        if constexpr (L == 1)
            return std::array<RowGrid<C>, 1>{RowGrid<C>(*grids[0], row.fv)};
        else
            return std::array<RowGrid<C>, 2>{RowGrid<C>(*grids[0], row.fv), RowGrid<C>(*grids[1], row.fv)};
    }();
    const auto mean = hn::Set(df, example.mean());
    const auto one = hn::Set(df, 1.0f), zero = hn::Zero(df);
    const auto fy = hn::Set(df, row.fy);
    const auto cellY = hn::Set(du, row.cellY);
    const auto seed = hn::Set(du, noise.offsetSeed());
    const auto oneU = hn::Set(du, 1u);
    const std::vector<float>* lut =
        C == 1 && outputSpace && example.transform() ? &example.transform()->inverseLut() : nullptr;
    // The tiles of the last vector whose lanes all saw one triangle.
    kernel::Stencil shared{};
    bool sharedValid = false;
    std::array<std::array<TileRow, 3>, L> sharedRows{};
    // The tiles of the row's lattice vertices, memoised: along a row each
    // new triangle shares two of its three vertices with the last, so a
    // vertex's offset is hashed and its rows located about once instead of
    // once per triangle that has it (kernel::tileOffset, then
    // TilingBlendingNoise::tileRow on each grid).
    // Direct-mapped by (x mod 4, dy): the triangles walk the vertices in
    // order of x.
    struct VertexTile {
        bool valid = false;
        uint32_t x = 0;
        std::array<TileRow, L> tile{};
    };
    std::array<VertexTile, 8> vertexTiles{};
    const auto vertexTile = [&](uint32_t x, uint32_t dy) -> const std::array<TileRow, L>& {
        VertexTile& v = vertexTiles[size_t((x & 3u) * 2u + dy)];
        if (!v.valid || v.x != x) {
            const TileOffset o = kernel::tileOffset(kernel::uvec2(x, row.cellY + dy), noise.offsetSeed());
            v.valid = true;
            v.x = x;
            for (size_t l = 0; l < size_t(L); ++l) {
                const auto [offsetTexels, rows] = TilingBlendingNoise::tileRow(o, g[l].pointTexelV, *grids[l]);
                v.tile[l] = {offsetTexels, int(rows.row0 - g[l].texels), rows.ty};
            }
        }
        return v.tile;
    };
    for (size_t p = 0; p < row.cellX.size(); p += n) {
        const auto fx = hn::LoadU(df, row.fx.data() + p);
        const auto cellX = hn::LoadU(du, row.cellX.data() + p);
        // kernel::blendStencil: the triangle and its normalised weights.
        const auto fz = hn::Sub(hn::Sub(one, fx), fy);
        const auto upper = hn::Not(hn::Gt(fz, zero));
        auto w0 = hn::IfThenElse(upper, hn::Neg(fz), fz);
        auto w1 = hn::IfThenElse(upper, hn::Sub(one, fy), fy);
        auto w2 = hn::IfThenElse(upper, hn::Sub(one, fx), fx);
        const auto norm = hn::Div(one, hn::Sqrt(hn::Add(hn::Add(hn::Mul(w0, w0), hn::Mul(w1, w1)), hn::Mul(w2, w2))));
        w0 = hn::Mul(w0, norm);
        w1 = hn::Mul(w1, norm);
        w2 = hn::Mul(w2, norm);
        // The lanes' u in each grid's texels.
        const auto fu = hn::LoadU(df, row.fu.data() + p);
        VF tu[L];
        for (size_t l = 0; l < size_t(L); ++l) tu[l] = hn::Add(hn::Mul(fu, hn::Set(df, g[l].size)), hn::Set(df, 0.5f));
        // The lookup of a tile at the lanes' u on grid l: the texels of its
        // two rows (BasicPeriodicGrid::sampleTexels' order), each channel.
        // A tile shared by every lane has one row pair, `sharedRow`, so its
        // texels may come from a window (WindowTaps) instead of gathers.
        VF e[L][3], var[L][3];
        const auto lookup = [&](size_t l, int i, VI rowIndex, VF wy, VF offsetTexels, const float* sharedRow) {
            const RowGrid<C>& grid = g[l];
            const auto tx = PeriodicTexel(tu[l], offsetTexels, hn::Set(df, grid.size), hn::Set(df, grid.size + 0.5f));
            const auto ix = TruncateInRange(tx);
            const auto wx = hn::Sub(tx, hn::ConvertTo(df, ix));
            VF bl[C], br[C], al[C], ar[C];  // below: left, right; above: left, right — each channel
            if (!sharedRow ||
                !WindowTaps<C>(df, sharedRow, size_t(grid.texelsEnd - sharedRow), grid.stride, ix, bl, br, al, ar)) {
                const auto index = hn::Add(rowIndex, C == 1 ? ix : hn::ShiftLeft<1>(ix));
                if constexpr (C == 1) {
                    VF quad[4];  // left and right, below then above
                    GatherQuads<false>(df, grid.texels, grid.stride, index, quad);
                    bl[0] = quad[0], br[0] = quad[1], al[0] = quad[2], ar[0] = quad[3];
                } else {
                    VF below[4], above[4];  // left's mean and variance, right's
                    GatherQuads<true>(df, grid.texels, 2, index, below);
                    GatherQuads<true>(df, grid.texels + grid.stride, 2, index, above);
                    bl[0] = below[0], bl[1] = below[1], br[0] = below[2], br[1] = below[3];
                    al[0] = above[0], al[1] = above[1], ar[0] = above[2], ar[1] = above[3];
                }
            }
            e[l][i] = Lerp(Lerp(bl[0], al[0], wy), Lerp(br[0], ar[0], wy), wx);
            if constexpr (C == 2) var[l][i] = Lerp(Lerp(bl[1], al[1], wy), Lerp(br[1], ar[1], wy), wx);
        };
        const uint32_t firstCell = hn::GetLane(cellX);
        const bool firstUpper = hn::AllTrue(df, upper);
        if (hn::AllTrue(du, hn::Eq(cellX, hn::Set(du, firstCell))) && (firstUpper || hn::AllFalse(df, upper))) {
            // Every lane sees the same three tiles (most vectors: a tile
            // spans tens of pixels): their vertices' offsets and rows, found
            // by the scalar kernel (vertexTile), are reused while they last.
            if (!sharedValid || shared.cell.x != firstCell || shared.upper != firstUpper) {
                shared.cell = kernel::uvec2(firstCell, row.cellY);
                shared.upper = firstUpper;
                for (int i = 0; i < 3; ++i) {
                    const kernel::uvec2 v = kernel::stencilVertex(shared, i);  // the plane's: no period
                    const std::array<TileRow, L>& tiles = vertexTile(v.x, v.y - row.cellY);
                    for (size_t l = 0; l < size_t(L); ++l) sharedRows[l][size_t(i)] = tiles[l];
                }
                sharedValid = true;
            }
            for (size_t l = 0; l < size_t(L); ++l)
                for (int i = 0; i < 3; ++i) {
                    const TileRow& t = sharedRows[l][size_t(i)];
                    lookup(l, i, hn::Set(di, t.rowIndex), hn::Set(df, t.wy), hn::Set(df, t.offsetTexels),
                           g[l].texels + t.rowIndex);
                }
        } else {
            // kernel::stencilVertex: upper (1,1), (1,0), (0,1); lower (0,0), (0,1), (1,0).
            const auto up = hn::RebindMask(du, upper);
            const auto dUpper = hn::IfThenElseZero(up, oneU), dLower = hn::IfThenZeroElse(up, oneU);
            const VU vx[3] = {hn::Add(cellX, dUpper), hn::Add(cellX, dUpper), hn::Add(cellX, dLower)};
            const VU vy[3] = {hn::Add(cellY, dUpper), hn::Add(cellY, dLower), hn::Add(cellY, dUpper)};
            for (int i = 0; i < 3; ++i) {
                // kernel::tileOffset, then the tile's rows on each grid
                // (TilingBlendingNoise::tileRows).
                VU hx, hy;
                Pcg3d(du, vx[i], vy[i], seed, hx, hy);
                const auto ox = UnitFloat(df, hx), oy = UnitFloat(df, hy);
                for (size_t l = 0; l < size_t(L); ++l) {
                    const auto vSize = hn::Set(df, g[l].size);
                    const auto ty = PeriodicTexel(hn::Set(df, g[l].pointTexelV), hn::Mul(oy, vSize), vSize,
                                                  hn::Set(df, g[l].size + 0.5f));
                    const auto iy = TruncateInRange(ty);
                    lookup(l, i, hn::Mul(iy, hn::Set(di, g[l].stride)), hn::Sub(ty, hn::ConvertTo(df, iy)),
                           hn::Mul(ox, vSize), nullptr);
                }
            }
        }
        for (size_t l = 0; l < size_t(L); ++l) {
            // kernel::blendMean: μ + Σ w_i (e_i − μ), in vertex order.
            auto value = hn::Add(mean, hn::Mul(w0, hn::Sub(e[l][0], mean)));
            value = hn::Add(value, hn::Mul(w1, hn::Sub(e[l][1], mean)));
            value = hn::Add(value, hn::Mul(w2, hn::Sub(e[l][2], mean)));
            if (lut) value = TableLookup(df, lut->data(), int(lut->size()), value);
            hn::StoreU(value, df, out[l] + p);
            if constexpr (C == 2) {  // kernel::blendVariance: Σ w_i² V_i
                const auto v =
                    hn::Add(hn::Add(hn::Mul(hn::Mul(w0, w0), var[l][0]), hn::Mul(hn::Mul(w1, w1), var[l][1])),
                            hn::Mul(hn::Mul(w2, w2), var[l][2]));
                hn::StoreU(v, df, variance[l] + p);
            }
        }
    }
}

void BlendRowImpl(const TilingBlendingNoise& noise, const GridRowLanes& row, float* out, bool outputSpace) {
    BlendGridRow<1, 1>(noise, {&noise.example().grid()}, row, {out}, {nullptr}, outputSpace);
}

void BlendLevelRowImpl(const TilingBlendingNoise& noise, const BasicPeriodicGrid<2>& level, const GridRowLanes& row,
                       float* mean, float* variance) {
    BlendGridRow<2, 1>(noise, {&level}, row, {mean}, {variance}, false);
}

void BlendLevelPairRowImpl(const TilingBlendingNoise& noise, const BasicPeriodicGrid<2>& lower,
                           const BasicPeriodicGrid<2>& upper, const GridRowLanes& row, float* meanLower,
                           float* varianceLower, float* meanUpper, float* varianceUpper) {
    BlendGridRow<2, 2>(noise, {&lower, &upper}, row, {meanLower, meanUpper}, {varianceLower, varianceUpper}, false);
}

// The 2D taps of values x[k·stride], y[k·stride] (stride 1 or 3) in a
// width × height table, for k < count (whole vectors; the caller does the
// rest): the entry (i, j) as j·width + i, and the two weights.
size_t TableTaps2Impl(const float* x, const float* y, size_t stride, int width, int height, size_t count,
                      int32_t* entry, float* tx, float* ty) {
    const DF df;
    const DI di;
    const size_t n = hn::Lanes(df);
    size_t k = 0;
    for (; k + n <= count; k += n) {
        VF vx, vy;
        if (stride == 1) {
            vx = hn::LoadU(df, x + k);
            vy = hn::LoadU(df, y + k);
        } else {
            VF unused1, unused2;
            hn::LoadInterleaved3(df, x + k * 3, vx, unused1, unused2);
            hn::LoadInterleaved3(df, y + k * 3, vy, unused1, unused2);
        }
        VI i, j;
        VF ti, tj;
        TableTap(df, width, vx, i, ti);
        TableTap(df, height, vy, j, tj);
        hn::StoreU(hn::Add(hn::Mul(j, hn::Set(di, width)), i), di, entry + k);
        hn::StoreU(ti, df, tx + k);
        hn::StoreU(tj, df, ty + k);
    }
    return k;
}

// ⌊log2 x⌋ of positive finite floats x, from the exponent field.
HWY_INLINE VI FloorLog2(VF x) {
    const DI di;
    const DU du;
    return hn::Sub(hn::BitCast(di, hn::ShiftRight<23>(hn::BitCast(du, x))), hn::Set(di, 127));
}

// kernel::sigmaLevelCoordinate.
HWY_INLINE VF SigmaLevelCoordinate(DF df, VF sigma, bool paper, float top) {
    const DU du;
    const auto s256 = hn::Mul(sigma, hn::Set(df, 256.0f));
    const auto positive = hn::Gt(s256, hn::Zero(df));  // false for NaN, as the kernel's !(s256 > 0)
    if (paper) {
        // round(log2 x) = ⌊log2(√2·x)⌋.
        const auto y = hn::Mul(s256, hn::Set(df, 1.41421356f));
        const auto c = hn::Min(hn::ConvertTo(df, FloorLog2(y)), hn::Set(df, top));
        return hn::IfThenElseZero(hn::And(positive, hn::Ge(y, hn::Set(df, 2.0f))), c);
    }
    // 1 + log2(s256) as 1 + e + log2(m), s256 = m·2^e with m ∈ [1, 2) split
    // off the float's bits: exact at the levels (m = 1), as std::log2 is,
    // and within a few ulps of 1 elsewhere (Highway's log2, on [1, 2) only).
    // Lanes at or below 1 (NaN and σ ≤ 0 too) take the linear part or 0;
    // +inf reads the top (e = 128).
    const auto one = hn::Set(df, 1.0f);
    const auto bits = hn::BitCast(du, s256);
    const auto e = FloorLog2(s256);
    const auto m = hn::BitCast(df, hn::Or(hn::And(bits, hn::Set(du, 0x007fffffu)), hn::Set(du, 0x3f800000u)));
    const auto logarithmic = hn::Add(hn::Add(one, hn::ConvertTo(df, e)), hn::Log2(df, m));
    const auto c = hn::IfThenElse(hn::Le(s256, one), s256, logarithmic);
    return hn::IfThenElseZero(positive, hn::Min(c, hn::Set(df, top)));
}

// sizes[level] in each lane, for levels < the table's count: lane permutes
// of the sizes a vector at a time (a table's few levels fit one or a few
// vectors), where a gather costs about ten cycles a vector.
class LevelSizeLookup {
public:
    static constexpr size_t kMaxSizes = 64;
    LevelSizeLookup(const int32_t* sizes, int count)
        : chunks_((size_t(count) + hn::Lanes(DI()) - 1) / hn::Lanes(DI())) {
        if (count < 1 || size_t(count) > kMaxSizes) throw std::invalid_argument("LevelSizeLookup: 1 to 64 levels");
        std::copy(sizes, sizes + count, sizes_.begin());
    }
    VI operator()(VI level) const {
        const DI di;
        const size_t n = hn::Lanes(di);
        const auto lane = hn::IndicesFromVec(di, hn::And(level, hn::Set(di, int32_t(n - 1))));
        VI size = hn::TableLookupLanes(hn::Load(di, sizes_.data()), lane);
        for (size_t c = 1; c < chunks_; ++c)
            size = hn::IfThenElse(hn::Gt(level, hn::Set(di, int32_t(c * n) - 1)),
                                  hn::TableLookupLanes(hn::Load(di, sizes_.data() + c * n), lane), size);
        return size;
    }

private:
    size_t chunks_;
    alignas(64) std::array<int32_t, kMaxSizes> sizes_{};
};

size_t LayerTapsImpl(const float* mx, const float* my, const float* sx, const float* sy, size_t count, bool paper,
                     int levels, const int32_t* widths, const int32_t* heights, LayerTapsLanes& out) {
    const DF df;
    const DI di;
    const size_t n = hn::Lanes(df);
    const float top = float(levels - 1);
    const LevelSizeLookup widthOf(widths, levels), heightOf(heights, levels);
    const auto last = hn::Set(di, levels - 1), oneI = hn::Set(di, 1);
    size_t k = 0;
    for (; k + n <= count; k += n) {
        // kernel::levelBlend of the two axes' coordinates.
        const auto cx = SigmaLevelCoordinate(df, hn::LoadU(df, sx + k), paper, top);
        const auto cy = SigmaLevelCoordinate(df, hn::LoadU(df, sy + k), paper, top);
        const auto kx0 = hn::Min(TruncateInRange(cx), last), ky0 = hn::Min(TruncateInRange(cy), last);
        const auto kx1 = hn::Min(hn::Add(kx0, oneI), last), ky1 = hn::Min(hn::Add(ky0, oneI), last);
        hn::StoreU(hn::Sub(cx, hn::ConvertTo(df, kx0)), df, out.fx.data() + k);
        hn::StoreU(hn::Sub(cy, hn::ConvertTo(df, ky0)), df, out.fy.data() + k);
        hn::StoreU(kx0, di, out.kx0.data() + k);
        hn::StoreU(ky0, di, out.ky0.data() + k);
        hn::StoreU(kx1, di, out.kx1.data() + k);
        hn::StoreU(ky1, di, out.ky1.data() + k);
        // The taps in the layers' sizes along each axis: a layer's entry
        // count along it is sizes[level].
        const auto tap = [&](VI size, VF value, int32_t* entry, float* weight) {
            VI i;
            VF t;
            TableTap(df, size, value, i, t);
            hn::StoreU(i, di, entry + k);
            hn::StoreU(t, df, weight + k);
            return i;
        };
        const auto x = hn::LoadU(df, mx + k), y = hn::LoadU(df, my + k);
        const auto w0 = widthOf(kx0), w1 = widthOf(kx1), h0 = heightOf(ky0);
        const auto ix0 = tap(w0, x, out.ix0.data(), out.tx0.data());
        const auto ix1 = tap(w1, x, out.ix1.data(), out.tx1.data());
        const auto iy0 = tap(h0, y, out.iy0.data(), out.ty0.data());
        const auto iy1 = tap(heightOf(ky1), y, out.iy1.data(), out.ty1.data());
        const auto n0 = hn::Mul(kx0, hn::Set(di, levels)), n1 = hn::Mul(kx1, hn::Set(di, levels));
        hn::StoreU(hn::Add(n0, ky0), di, out.layer00.data() + k);
        hn::StoreU(hn::Add(n1, ky0), di, out.layer10.data() + k);
        hn::StoreU(hn::Add(n0, ky1), di, out.layer01.data() + k);
        hn::StoreU(hn::Add(n1, ky1), di, out.layer11.data() + k);
        hn::StoreU(hn::Add(hn::Mul(iy0, w0), ix0), di, out.entry00.data() + k);
        hn::StoreU(hn::Add(hn::Mul(iy0, w1), ix1), di, out.entry10.data() + k);
        hn::StoreU(hn::Add(hn::Mul(iy1, w0), ix0), di, out.entry01.data() + k);
        hn::StoreU(hn::Add(hn::Mul(iy1, w1), ix1), di, out.entry11.data() + k);
        hn::StoreU(w0, di, out.width0.data() + k);
        hn::StoreU(w1, di, out.width1.data() + k);
        hn::StoreU(hn::Mul(w0, h0), di, out.entries00.data() + k);
    }
    return k;
}

// glm's and std's max(x, y): (x < y) ? y : x (a NaN x stays).
HWY_INLINE VF MaxAsKernel(VF x, VF y) { return hn::IfThenElse(hn::Lt(x, y), y, x); }

size_t ProbeMomentsImpl(const float* meanLo, const float* varLo, const float* meanHi, const float* varHi, float w0,
                        float w1, size_t count, float* mean, float* sigma) {
    const DF df;
    const size_t n = hn::Lanes(df);
    const auto zero = hn::Zero(df), weightLo = hn::Set(df, w0), weightHi = hn::Set(df, w1);
    const bool hi = w1 > 0.0f;  // kernel::momentsAddProbe: level l1 where it weighs
    size_t k = 0;
    for (; k + n <= count; k += n) {
        // kernel::momentsAbout(lo's mean), then kernel::momentsAdd of each level.
        const auto shift = hn::LoadU(df, meanLo + k);
        auto d = hn::Sub(shift, shift);
        auto m = hn::Add(zero, hn::Mul(weightLo, d));
        auto m2 = hn::Add(zero, hn::Mul(weightLo, hn::Add(hn::Mul(d, d), hn::LoadU(df, varLo + k))));
        if (hi) {
            d = hn::Sub(hn::LoadU(df, meanHi + k), shift);
            m = hn::Add(m, hn::Mul(weightHi, d));
            m2 = hn::Add(m2, hn::Mul(weightHi, hn::Add(hn::Mul(d, d), hn::LoadU(df, varHi + k))));
        }
        // kernel::momentsResult, then momentSigma of the variance clamped at 0.
        const auto var = MaxAsKernel(hn::Sub(m2, hn::Mul(m, m)), zero);
        hn::StoreU(hn::Add(shift, m), df, mean + k);
        hn::StoreU(hn::Sqrt(MaxAsKernel(MaxAsKernel(var, zero), zero)), df, sigma + k);
    }
    return k;
}

const char* TargetNameImpl() { return hwy::TargetName(HWY_TARGET); }
size_t FloatLanesImpl() { return hn::MaxLanes(DF()); }

}  // namespace stochtex::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace stochtex {

HWY_EXPORT(GridRowImpl);
HWY_EXPORT(BlendRowImpl);
HWY_EXPORT(BlendLevelRowImpl);
HWY_EXPORT(BlendLevelPairRowImpl);
HWY_EXPORT(TableTaps2Impl);
HWY_EXPORT(LayerTapsImpl);
HWY_EXPORT(ProbeMomentsImpl);
HWY_EXPORT(TargetNameImpl);
HWY_EXPORT(FloatLanesImpl);

void GridRowLanes::compute(double offset, double scale, double invW, double v, int pixels, const GridLayout& grid) {
    if (grid.periodic()) throw std::logic_error("GridRowLanes: a periodic grid needs the scalar kernel");
    count = pixels;
    const size_t padded = size_t(paddedLaneCount(pixels));
    cellX.resize(padded);
    fx.resize(padded);
    fu.resize(padded);
    // The row's y, as TriangleGridRow splits it.
    const double sv = v * grid.densityV;
    const double y = double(kernel::kGridSkewY) * sv;
    const int64_t by = floorToInt(y);
    fy = float(y - double(by));
    cellY = uint32_t(uint64_t(by));
    fv = periodFraction(v);
    HWY_DYNAMIC_DISPATCH(GridRowImpl)(*this, offset, scale, invW, grid.densityU, double(kernel::kGridSkewX) * sv);
}

void blendRowLanes(const TilingBlendingNoise& noise, const GridRowLanes& row, float* out) {
    HWY_DYNAMIC_DISPATCH(BlendRowImpl)(noise, row, out, true);
}

void blendExampleRowLanes(const TilingBlendingNoise& noise, const GridRowLanes& row, float* out) {
    HWY_DYNAMIC_DISPATCH(BlendRowImpl)(noise, row, out, false);
}

void blendRowLanes(const TilingBlendingNoise& noise, const BasicPeriodicGrid<2>& level, const GridRowLanes& row,
                   float* mean, float* variance) {
    HWY_DYNAMIC_DISPATCH(BlendLevelRowImpl)(noise, level, row, mean, variance);
}

void blendRowLanes(const TilingBlendingNoise& noise, const BasicPeriodicGrid<2>& lower,
                   const BasicPeriodicGrid<2>& upper, const GridRowLanes& row, float* meanLower, float* varianceLower,
                   float* meanUpper, float* varianceUpper) {
    HWY_DYNAMIC_DISPATCH(BlendLevelPairRowImpl)
    (noise, lower, upper, row, meanLower, varianceLower, meanUpper, varianceUpper);
}

size_t tableTapsLanes(const float* x, const float* y, size_t stride, int width, int height, size_t count,
                      int32_t* entry, float* tx, float* ty) {
    if (stride != 1 && stride != 3) throw std::invalid_argument("tableTapsLanes: stride must be 1 or 3");
    return HWY_DYNAMIC_DISPATCH(TableTaps2Impl)(x, y, stride, width, height, count, entry, tx, ty);
}

size_t layerTapsLanes(const float* mx, const float* my, const float* sx, const float* sy, size_t count, bool paper,
                      int levels, const int32_t* widths, const int32_t* heights, LayerTapsLanes& out) {
    if (count > LayerTapsLanes::kCapacity)
        throw std::invalid_argument("layerTapsLanes: count exceeds the output's capacity");
    if (levels < 1) throw std::invalid_argument("layerTapsLanes: a table needs at least one level");
    return HWY_DYNAMIC_DISPATCH(LayerTapsImpl)(mx, my, sx, sy, count, paper, levels, widths, heights, out);
}

size_t probeMomentsLanes(const float* meanLo, const float* varLo, const float* meanHi, const float* varHi, float w0,
                         float w1, size_t count, float* mean, float* sigma) {
    return HWY_DYNAMIC_DISPATCH(ProbeMomentsImpl)(meanLo, varLo, meanHi, varHi, w0, w1, count, mean, sigma);
}

const char* laneTargetName() { return HWY_DYNAMIC_DISPATCH(TargetNameImpl)(); }
size_t laneTargetFloatLanes() { return HWY_DYNAMIC_DISPATCH(FloatLanesImpl)(); }

}  // namespace stochtex
#endif  // HWY_ONCE
