#include "stochtex/noise/tiling_blending.h"

#include <cmath>

#include "stochtex/core/hash.h"

namespace stochtex {

float TilingBlendingNoise::evaluate(double u, double v, double density) const {
    const BlendStencil s = triangleGrid(u, v, density);
    return example_->toOutput(blend(s, periodFraction(u), periodFraction(v)));
}

}  // namespace stochtex
