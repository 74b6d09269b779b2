#include "stochtex/noise/example.h"

#include <stdexcept>

namespace stochtex {

NoiseExample::NoiseExample(Image values, std::optional<HistogramTransform> inverse) : inverse_(std::move(inverse)) {
    if (values.channels() != 1 || values.width() != values.height() || values.width() < 2)
        throw std::invalid_argument("NoiseExample: needs a square 1-channel image of size >= 2");
    mean_ = float(channelStats(values).mean);
    grid_ = PeriodicGrid(std::move(values));
}

}  // namespace stochtex
