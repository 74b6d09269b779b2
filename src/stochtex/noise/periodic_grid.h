#pragma once
// A periodic W×W grid of values (period 1 in uv) with branch-free bilinear
// lookups. Noise examples and every level of their MIP pyramids are
// PeriodicGrids, so all of them are read by the same code.
#include <cstddef>
#include <vector>

#include "stochtex/image/image.h"

namespace stochtex {

class PeriodicGrid {
public:
    PeriodicGrid() = default;
    explicit PeriodicGrid(Image values);  // 1-channel, square, W ≥ 1

    int size() const { return size_; }
    float sizeF() const { return sizeF_; }
    const Image& values() const { return values_; }

    // The two padded rows a bilinear lookup at v reads, and the weight
    // between them. Along a scanline v is fixed per tile, so this is
    // computed once per tile rather than once per pixel.
    struct RowPair {
        const float* row0;  // start of the padded row above (index 0 = texel −1)
        const float* row1;
        float ty;
    };
    RowPair rows(float v) const {
        // fy ∈ [−½, W−½]: truncating fy + 1 > 0 is a floor without a libm
        // call, and y0 ∈ [−1, W−1] indexes the padded copy directly.
        const float fy = v * sizeF_ - 0.5f;
        const int y0 = int(fy + 1.0f) - 1;
        const size_t stride = size_t(size_) + 2;
        const float* r0 = padded_.data() + size_t(y0 + 1) * stride;
        return {r0, r0 + stride, fy - float(y0)};
    }

    // Bilinear sample between the rows of a RowPair at t = u·W + ½ ∈ [½, W + ½]
    // (texel units, shifted so that int(t) is the padded index of the left texel).
    float sampleTexel(const RowPair& r, float t) const {
        const int i = int(t);
        const float tx = t - float(i);
        const float a = r.row0[i] + tx * (r.row0[i + 1] - r.row0[i]);
        const float b = r.row1[i] + tx * (r.row1[i + 1] - r.row1[i]);
        return a + r.ty * (b - a);
    }

    // Bilinear sample at (u, v) ∈ [0,1]² (one period), wrapping at the
    // edges. Texel centres sit at ((i + ½)/W, (j + ½)/W).
    float sampleBilinear(float u, float v) const { return sampleTexel(rows(v), u * sizeF_ + 0.5f); }

private:
    Image values_;
    // values_ with a one-texel periodic border on every side, (W+2)², so
    // bilinear lookups never branch to wrap.
    std::vector<float> padded_;
    int size_ = 0;
    float sizeF_ = 0.0f;
};

}  // namespace stochtex
