#include "stochtex/noise/gaussianize.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "stochtex/noise/normal.h"

namespace stochtex {

HistogramTransform HistogramTransform::fit(const Image& exemplar, double mean, double stddev, int lutSize) {
    if (exemplar.channels() != 1 || exemplar.empty())
        throw std::invalid_argument("HistogramTransform: needs a non-empty 1-channel image");
    if (lutSize < 2) throw std::invalid_argument("HistogramTransform: LUT too small");
    HistogramTransform t;
    t.mean_ = mean;
    t.stddev_ = stddev;
    t.sorted_.assign(exemplar.data().begin(), exemplar.data().end());
    std::sort(t.sorted_.begin(), t.sorted_.end());
    const double n = double(t.sorted_.size());
    // T⁻¹(g) = empirical quantile of E at probability Φ((g − mean)/σ).
    t.lut_.resize(size_t(lutSize));
    for (int k = 0; k < lutSize; ++k) {
        const double g = double(k) / double(lutSize - 1);
        const double p = normalCdf((g - mean) / stddev);
        const double pos = std::clamp(p * n - 0.5, 0.0, n - 1.0);
        const size_t i = std::min(size_t(pos), t.sorted_.size() - 1);
        const size_t j = std::min(i + 1, t.sorted_.size() - 1);
        const double f = pos - double(i);
        t.lut_[size_t(k)] = float((1.0 - f) * t.sorted_[i] + f * t.sorted_[j]);
    }
    return t;
}

Image HistogramTransform::forward(const Image& exemplar) const {
    if (exemplar.channels() != 1) throw std::invalid_argument("HistogramTransform::forward: 1 channel");
    const auto& v = exemplar.data();
    std::vector<size_t> order(v.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
    Image out(exemplar.width(), exemplar.height(), 1);
    const double n = double(v.size());
    for (size_t r = 0; r < order.size(); ++r) {
        const double g = mean_ + stddev_ * normalQuantile((double(r) + 0.5) / n);
        out.data()[order[r]] = float(std::clamp(g, 0.0, 1.0));
    }
    return out;
}

}  // namespace stochtex
