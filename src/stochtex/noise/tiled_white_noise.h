#pragma once
// Partly correlated tiled white noise, the perception stimuli of the thesis
// (Tavernier 2017, §2.6.2, Figures 2.13–2.14): a w×w block of white noise X
// repeated every w pixels, blended with fresh white noise Y by α and
// contrast-corrected (eq. 2.24):
//     Z(x) = (α X(x mod w) + (1 − α) Y(x)) / √(α² + (1 − α)²),
// X and Y independent, uniform in [−1, 1) (variance 1/3). Z keeps X's mean 0
// and variance 1/3 for every α (eq. 2.25–2.26), and two pixels one tile apart
// (x ≡ y mod w, x ≠ y) correlate by α² / (α² + (1 − α)²) (eq. 2.28); pixels
// that are not, by 0.
#include <cstdint>

#include "stochtex/image/image.h"

namespace stochtex {

// Eq. 2.28: the tile-to-tile correlation of a blend by alpha in [0, 1].
double tileCorrelation(double alpha);
// Eq. 2.28 inverted on [0, 1]: α = √c / (√c + √(1 − c)), so α = 0 for c = 0
// (fresh noise only) and 1 for c = 1 (the tile alone). InputError naming
// `correlation` outside [0, 1] or not finite.
double blendAlphaForCorrelation(double correlation);

// The variance of X, Y and Z: uniform on [−1, 1).
constexpr double kTiledWhiteNoiseVariance = 1.0 / 3.0;
// |Z| never exceeds 1 / √(α² + (1 − α)²) ≤ √2 (at α = ½).
double tiledWhiteNoiseBound(double alpha);

struct TiledWhiteNoiseOptions {
    int size = 256;      // image side, pixels, [1, 4096]
    int tile = 32;       // w, pixels, [1, size]; the tiles start at (0, 0)
    double alpha = 1.0;  // blend weight of the tiled noise, [0, 1]
    uint32_t seed = 0;   // X and Y are drawn from streams 0 and 1 of it (pcg3d)
};
// InputError naming the parameter (size, tile, alpha).
void validateTiledWhiteNoise(const TiledWhiteNoiseOptions& options);
// Z of eq. 2.24 as a 1-channel size×size image (values in
// [−tiledWhiteNoiseBound(α), +tiledWhiteNoiseBound(α)]); every pixel is hashed
// from (position, seed) alone, so the image does not depend on the thread count.
Image tiledWhiteNoise(const TiledWhiteNoiseOptions& options);

}  // namespace stochtex
