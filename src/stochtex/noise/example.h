#pragma once
// A noise example E ready for tiling and blending: a periodic W×W grid of
// values (period 1 in uv), its mean μ_E, and, for a Gaussianized exemplar,
// the inverse histogram transform T⁻¹ that maps blended values back.
#include <optional>

#include "stochtex/image/image.h"
#include "stochtex/noise/gaussianize.h"
#include "stochtex/noise/periodic_grid.h"

namespace stochtex {

class NoiseExample {
public:
    NoiseExample() = default;
    // values: 1-channel square image. inverse: T⁻¹ when values = T(exemplar).
    explicit NoiseExample(Image values, std::optional<HistogramTransform> inverse = std::nullopt);

    int size() const { return grid_.size(); }
    float sizeF() const { return grid_.sizeF(); }
    float mean() const { return mean_; }
    const Image& values() const { return grid_.values(); }
    const PeriodicGrid& grid() const { return grid_; }
    bool gaussianized() const { return inverse_.has_value(); }
    const std::optional<HistogramTransform>& transform() const { return inverse_; }

    float sampleBilinear(float u, float v) const { return grid_.sampleBilinear(u, v); }

    // Maps a blended value to the output space (T⁻¹ or identity).
    float toOutput(float n) const { return inverse_ ? inverse_->inverse(n) : n; }

private:
    PeriodicGrid grid_;
    float mean_ = 0.5f;
    std::optional<HistogramTransform> inverse_;
};

// The smallest power of two ≥ n (n ≥ 1).
int nextPowerOfTwo(int n);

// A square 1-channel example resampled to size × size as the periodic image
// it is (period 1 in uv both ways): bicubic (OpenCV's, a = −0.75) with
// wrap-around, so the seams stay continuous; texel centres map to texel
// centres, (i + ½)·W/size − ½. Cubic overshoot is clamped to [lo, hi].
Image resamplePeriodic(const Image& example, int size, float lo, float hi);

}  // namespace stochtex
