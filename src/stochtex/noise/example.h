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

}  // namespace stochtex
