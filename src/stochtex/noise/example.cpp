#include "stochtex/noise/example.h"

#include <stdexcept>

namespace stochtex {

NoiseExample::NoiseExample(Image values, std::optional<HistogramTransform> inverse)
    : values_(std::move(values)), inverse_(std::move(inverse)) {
    if (values_.channels() != 1 || values_.width() != values_.height() || values_.width() < 2)
        throw std::invalid_argument("NoiseExample: needs a square 1-channel image of size >= 2");
    size_ = values_.width();
    sizeF_ = float(size_);
    mean_ = float(channelStats(values_).mean);
    const int n = size_, stride = n + 2;
    padded_.resize(size_t(stride) * size_t(stride));
    for (int y = -1; y <= n; ++y)
        for (int x = -1; x <= n; ++x)
            padded_[size_t(y + 1) * size_t(stride) + size_t(x + 1)] = values_.at((x + n) % n, (y + n) % n);
}

}  // namespace stochtex
