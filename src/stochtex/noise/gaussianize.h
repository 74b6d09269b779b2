#pragma once
// Histogram transform T of an exemplar to a Gaussian N(mean, σ²) and its
// inverse T⁻¹ as a lookup table (Heitz & Neyret 2018; Deliot & Heitz 2019).
//
// Tiling and blending preserves mean and variance but, as it averages tiles,
// pushes any histogram toward a Gaussian. Blending T(E) instead of E and
// applying T⁻¹ afterwards restores E's histogram, so non-Gaussian exemplars
// keep their look.
#include <algorithm>
#include <vector>

#include "stochtex/image/image.h"

namespace stochtex {

class HistogramTransform {
public:
    // Fits T to the values of a 1-channel exemplar.
    static HistogramTransform fit(const Image& exemplar, double mean = 0.5, double stddev = 1.0 / 6.0,
                                  int lutSize = 1024);

    // T(E): each texel gets the Gaussian quantile of its rank, so the result
    // has an exactly Gaussian histogram (ties broken by position), clamped to [0,1].
    Image forward(const Image& exemplar) const;

    // T⁻¹(g), linear interpolation in a LUT over g ∈ [0,1] (clamped outside).
    float inverse(float g) const {
        // Clamped so that NaN reads 0 (std::max(NaN, 0) is NaN, and int(NaN) an index anywhere).
        const float t = (g > 0.0f ? std::min(g, 1.0f) : 0.0f) * float(lut_.size() - 1);
        const int i = std::min(int(t), int(lut_.size()) - 2);
        const float f = t - float(i);
        return lut_[size_t(i)] + f * (lut_[size_t(i) + 1] - lut_[size_t(i)]);
    }

    const std::vector<float>& inverseLut() const { return lut_; }
    double mean() const { return mean_; }
    double stddev() const { return stddev_; }

private:
    double mean_ = 0.5, stddev_ = 1.0 / 6.0;
    std::vector<float> sorted_;  // exemplar values, ascending
    std::vector<float> lut_;
};

}  // namespace stochtex
