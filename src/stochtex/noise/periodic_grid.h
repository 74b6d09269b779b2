#pragma once
// Periodic W×W grids of C interleaved channels (period 1 in uv) with
// branch-free bilinear lookups. Noise examples (C = 1) and the levels of
// their statistics pyramids (C = 2: mean and variance side by side, as the
// paper packs them into one texture) are all read by this one piece of code.
#include <array>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

#include "stochtex/image/image.h"
#include "stochtex/kernel/lookup.h"

namespace stochtex {

// The two padded rows a bilinear lookup at v reads, and the weight between
// them. Along a scanline v is fixed per tile, so this is computed once per
// tile rather than once per pixel.
struct GridRows {
    const float* row0;  // start of the padded row above (texel −1)
    const float* row1;
    float ty;
};

// GCC/Clang vector extensions: SSE on x86-64, NEON on ARM, scalar elsewhere.
typedef float Float2 __attribute__((vector_size(8)));
typedef float Float4 __attribute__((vector_size(16)));

template <int C>
class BasicPeriodicGrid {
public:
    BasicPeriodicGrid() = default;
    // channels: C square 1-channel images of the same size W ≥ 1.
    explicit BasicPeriodicGrid(const std::array<const Image*, C>& channels) : BasicPeriodicGrid(channels[0]->width()) {
        for (int y = 0; y < size_; ++y)
            for (int x = 0; x < size_; ++x) {
                float* t = texel(x, y);
                for (int c = 0; c < C; ++c) t[c] = channels[size_t(c)]->at(x, y);
            }
        wrapBorder();
    }

    // A W×W grid to be written in place: fill every texel(x, y), then
    // wrapBorder() (a pyramid level computed from the one below).
    explicit BasicPeriodicGrid(int size)
        : padded_((size_t(size) + 2) * (size_t(size) + 2) * C), size_(size), sizeF_(float(size)) {}
    // The C channels of texel (x, y), 0 ≤ x, y < W.
    float* texel(int x, int y) { return padded_.data() + paddedIndex(x, y); }
    const float* texel(int x, int y) const { return padded_.data() + paddedIndex(x, y); }
    // Copies the periodic border from the texels (after writing them in place).
    void wrapBorder() {
        const int n = size_;
        if (n == 0) return;
        for (int y = 0; y < n; ++y) {
            std::memcpy(texel(-1, y), texel(n - 1, y), C * sizeof(float));
            std::memcpy(texel(n, y), texel(0, y), C * sizeof(float));
        }
        const size_t row = (size_t(n) + 2) * C;  // whole padded rows, corners included
        std::memcpy(texel(-1, -1), texel(-1, n - 1), row * sizeof(float));
        std::memcpy(texel(-1, n), texel(-1, 0), row * sizeof(float));
    }

    int size() const { return size_; }
    float sizeF() const { return sizeF_; }
    size_t bytes() const { return padded_.size() * sizeof(float); }

    // The row pair of a lookup at the texel coordinate t of
    // kernel::periodicTexel (in [½, W + ½]): int(t) is the padded index of
    // the lower row, t − int(t) the upper row's weight (kernel/lookup.glsl).
    GridRows rowsAt(float t) const {
        const int y = int(t);
        const size_t stride = (size_t(size_) + 2) * C;
        const float* r0 = padded_.data() + size_t(y) * stride;
        return {r0, r0 + stride, t - float(y)};
    }

    // Bilinear sample of every channel between the rows r at the texel
    // coordinate t ∈ [½, W + ½] of kernel::periodicTexel (int(t) is the
    // padded index of the left texel).
    //
    // The left and right texels of a row are adjacent in memory (2·C
    // floats), so each row is one vector load: interpolate the two rows
    // vertically as whole vectors, then the left and right halves
    // horizontally. Every grid (examples, pyramid levels) shares this exact
    // order of operations, so a level-0 mean lookup equals the example's;
    // it is kernel::blendColumnsFirst's order, which the shaders use.
    std::array<float, C> sampleTexels(const GridRows& r, float t) const {
        static_assert(C == 1 || C == 2, "texel pairs are loaded as one 8- or 16-byte vector");
        using Pair = std::conditional_t<C == 1, Float2, Float4>;
        const int i = int(t);
        const float tx = t - float(i);
        Pair a, b;
        std::memcpy(&a, r.row0 + size_t(i) * C, sizeof(Pair));
        std::memcpy(&b, r.row1 + size_t(i) * C, sizeof(Pair));
        const Pair col = a + r.ty * (b - a);  // [left channels…, right channels…]
        std::array<float, C> out;
        if constexpr (C == 1) {
            out[0] = col[0] + tx * (col[1] - col[0]);
        } else {
            const Float2 left = __builtin_shufflevector(col, col, 0, 1);
            const Float2 right = __builtin_shufflevector(col, col, 2, 3);
            const Float2 r = left + tx * (right - left);
            std::memcpy(out.data(), &r, sizeof r);
        }
        return out;
    }

    // Bilinear sample at (u, v) ∈ [0,1]² (one period), wrapping at the
    // edges. Texel centres sit at ((i + ½)/W, (j + ½)/W).
    std::array<float, C> sample(float u, float v) const {
        return sampleTexels(rowsAt(kernel::texelOfPoint(v, sizeF_)), kernel::texelOfPoint(u, sizeF_));
    }

private:
    size_t paddedIndex(int x, int y) const { return (size_t(y + 1) * (size_t(size_) + 2) + size_t(x + 1)) * C; }
    // The channels interleaved, with a one-texel periodic border on every
    // side, (W+2)²·C, so bilinear lookups never branch to wrap.
    Image::Buffer padded_;  // bulk storage: left unset until written
    int size_ = 0;
    float sizeF_ = 0.0f;
};

// The one-channel grid, which also keeps its values as an image.
class PeriodicGrid : public BasicPeriodicGrid<1> {
public:
    using RowPair = GridRows;
    PeriodicGrid() = default;
    explicit PeriodicGrid(Image values);  // 1-channel, square, W ≥ 1

    const Image& values() const { return values_; }
    float sampleTexel(const GridRows& r, float t) const { return sampleTexels(r, t)[0]; }
    float sampleBilinear(float u, float v) const { return sample(u, v)[0]; }

private:
    Image values_;
};

}  // namespace stochtex
