#include "stochtex/noise/example.h"

#include <stdexcept>

namespace stochtex {

NoiseExample::NoiseExample(Image values, std::optional<HistogramTransform> inverse)
    : values_(std::move(values)), inverse_(std::move(inverse)) {
    if (values_.channels() != 1 || values_.width() != values_.height() || values_.width() < 2)
        throw std::invalid_argument("NoiseExample: needs a square 1-channel image of size >= 2");
    size_ = values_.width();
    mean_ = float(channelStats(values_).mean);
}

}  // namespace stochtex
