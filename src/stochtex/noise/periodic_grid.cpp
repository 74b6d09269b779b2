#include "stochtex/noise/periodic_grid.h"

#include <stdexcept>

namespace stochtex {

static const Image& checked(const Image& values) {
    if (values.channels() != 1 || values.width() != values.height() || values.width() < 1)
        throw std::invalid_argument("PeriodicGrid: needs a square 1-channel image");
    return values;
}

PeriodicGrid::PeriodicGrid(Image values)
    : BasicPeriodicGrid<1>({&checked(values)}), values_(std::move(values)) {}

}  // namespace stochtex
