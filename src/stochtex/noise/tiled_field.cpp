#include "stochtex/noise/tiled_field.h"

#include <cmath>
#include <string>

#include "stochtex/core/error.h"

namespace stochtex {

TiledField::TiledField(std::vector<TilingBlendingNoise> channels, const GridLayout& grid, OffsetSharing sharing)
    : channels_(std::move(channels)), grid_(grid), sharing_(sharing) {
    if (channels_.empty()) throw InputError::parameter("channels", "must hold at least one noise, got none");
    for (const auto& c : channels_)
        if (c.example().size() != exampleSize())
            throw InputError::parameter("channels", "must have examples of one size, got " +
                                                        std::to_string(exampleSize()) + " and " +
                                                        std::to_string(c.example().size()) + " texels");
    for (const double density : {grid.densityU, grid.densityV})
        if (!(std::isfinite(density) && density > 0))
            throw InputError::parameter("gridDensity", "must be finite and positive, got " + formatValue(density));
    if (shared())
        for (const auto& c : channels_)
            if (c.offsetSeed() != channels_.front().offsetSeed())
                throw InputError::parameter("offsets", "shared needs one tile-offset seed for every channel, got " +
                                                           std::to_string(channels_.front().offsetSeed()) + " and " +
                                                           std::to_string(c.offsetSeed()));
}

}  // namespace stochtex
