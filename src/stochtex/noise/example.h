#pragma once
// A noise example E ready for tiling and blending: a periodic W×W grid of
// values (period 1 in uv), its mean μ_E, and, for a Gaussianized exemplar,
// the inverse histogram transform T⁻¹ that maps blended values back.
#include <cmath>
#include <memory>
#include <optional>

#include "stochtex/image/image.h"
#include "stochtex/noise/gaussianize.h"

namespace stochtex {

class NoiseExample {
public:
    NoiseExample() = default;
    // values: 1-channel square image. inverse: T⁻¹ when values = T(exemplar).
    explicit NoiseExample(Image values, std::optional<HistogramTransform> inverse = std::nullopt);

    int size() const { return size_; }
    float mean() const { return mean_; }
    const Image& values() const { return values_; }
    bool gaussianized() const { return inverse_.has_value(); }
    const std::optional<HistogramTransform>& transform() const { return inverse_; }

    // Bilinear sample at (u, v), u and v in [0,1) (one period), wrapping at
    // the edges. Texel centres sit at ((i + ½)/W, (j + ½)/W).
    float sampleBilinear(float u, float v) const {
        const float fx = u * float(size_) - 0.5f;
        const float fy = v * float(size_) - 0.5f;
        const float x0f = std::floor(fx), y0f = std::floor(fy);
        const float tx = fx - x0f, ty = fy - y0f;
        int x0 = int(x0f), y0 = int(y0f);
        // u, v ∈ [0,1) so x0, y0 ∈ [−1, W−1]: one compare wraps each side.
        int x1 = x0 + 1, y1 = y0 + 1;
        if (x0 < 0) x0 += size_;
        if (y0 < 0) y0 += size_;
        if (x1 >= size_) x1 -= size_;
        if (y1 >= size_) y1 -= size_;
        const float* data = values_.data().data();
        const float* r0 = data + size_t(y0) * size_t(size_);
        const float* r1 = data + size_t(y1) * size_t(size_);
        const float a = r0[x0] + tx * (r0[x1] - r0[x0]);
        const float b = r1[x0] + tx * (r1[x1] - r1[x0]);
        return a + ty * (b - a);
    }

    // Maps a blended value to the output space (T⁻¹ or identity).
    float toOutput(float n) const { return inverse_ ? inverse_->inverse(n) : n; }

private:
    Image values_;
    int size_ = 0;
    float mean_ = 0.5f;
    std::optional<HistogramTransform> inverse_;
};

}  // namespace stochtex
