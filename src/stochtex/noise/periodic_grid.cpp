#include "stochtex/noise/periodic_grid.h"

#include <stdexcept>

namespace stochtex {

PeriodicGrid::PeriodicGrid(Image values) : values_(std::move(values)) {
    if (values_.channels() != 1 || values_.width() != values_.height() || values_.width() < 1)
        throw std::invalid_argument("PeriodicGrid: needs a square 1-channel image");
    size_ = values_.width();
    sizeF_ = float(size_);
    const int n = size_, stride = n + 2;
    padded_.resize(size_t(stride) * size_t(stride));
    for (int y = -1; y <= n; ++y)
        for (int x = -1; x <= n; ++x)
            padded_[size_t(y + 1) * size_t(stride) + size_t(x + 1)] = values_.at((x + n) % n, (y + n) % n);
}

}  // namespace stochtex
