#include "stochtex/noise/tiling_blending.h"

#include <algorithm>
#include <cmath>

#include "stochtex/core/hash.h"

namespace stochtex {

GridLayout GridLayout::periodic(double density, int periodsU, int periodsV) {
    // Along v the skewed lattice repeats every √3·m / densityV (m skewed
    // rows: (−m, 2m) cells); along u every n / densityU.
    const int m = std::max(1, int(std::lround(density * periodsV / std::sqrt(3.0))));
    const int n = std::max(1, int(std::lround(density * periodsU)));
    return {double(n) / periodsU, std::sqrt(3.0) * m / periodsV, {n, m}};
}

float TilingBlendingNoise::evaluate(double u, double v, const GridLayout& grid) const {
    const BlendStencil s = triangleGrid(u, v, grid);
    return example_->toOutput(blend(s, periodFraction(u), periodFraction(v)));
}

}  // namespace stochtex
