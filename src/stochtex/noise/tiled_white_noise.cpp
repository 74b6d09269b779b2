#include "stochtex/noise/tiled_white_noise.h"

#include <cmath>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"

namespace stochtex {

double tileCorrelation(double alpha) {
    const double a2 = alpha * alpha, b2 = (1.0 - alpha) * (1.0 - alpha);
    return a2 / (a2 + b2);
}

double blendAlphaForCorrelation(double correlation) {
    if (!(correlation >= 0.0 && correlation <= 1.0))
        throw InputError::parameter("correlation", "must be in [0, 1], got " + formatValue(correlation));
    // c = α² / (α² + (1 − α)²)  ⇔  α / (1 − α) = √(c / (1 − c)).
    const double s = std::sqrt(correlation), t = std::sqrt(1.0 - correlation);
    return s / (s + t);
}

double tiledWhiteNoiseBound(double alpha) { return 1.0 / std::sqrt(alpha * alpha + (1.0 - alpha) * (1.0 - alpha)); }

void validateTiledWhiteNoise(const TiledWhiteNoiseOptions& o) {
    if (o.size < 1 || o.size > 4096)
        throw InputError::parameter("size", "must be in [1, 4096], got " + std::to_string(o.size));
    if (o.tile < 1 || o.tile > o.size)
        throw InputError::parameter(
            "tile", "must be in [1, size = " + std::to_string(o.size) + "], got " + std::to_string(o.tile));
    if (!(o.alpha >= 0.0 && o.alpha <= 1.0))
        throw InputError::parameter("alpha", "must be in [0, 1], got " + formatValue(o.alpha));
}

namespace {

// Uniform on [−1, 1): 24 random bits, exact in float.
float uniformSigned(uint32_t x, uint32_t y, uint32_t key) { return 2.0f * unitFloat(pcg3d({x, y, key}).x) - 1.0f; }

}  // namespace

Image tiledWhiteNoise(const TiledWhiteNoiseOptions& o) {
    validateTiledWhiteNoise(o);
    const uint32_t tileKey = deriveSeed(o.seed, 0), freshKey = deriveSeed(o.seed, 1);
    // Eq. 2.24: weights divided by √(α² + (1 − α)²) keep the variance.
    const double norm = std::sqrt(o.alpha * o.alpha + (1.0 - o.alpha) * (1.0 - o.alpha));
    const float a = float(o.alpha / norm), b = float((1.0 - o.alpha) / norm);
    Image z(o.size, o.size, 1, Image::Uninitialized{});
    parallelRows(o.size, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* row = z.row(y);
            const uint32_t ty = uint32_t(y % o.tile);
            for (int x = 0; x < o.size; ++x) {
                const float tiled = uniformSigned(uint32_t(x % o.tile), ty, tileKey);
                const float fresh = uniformSigned(uint32_t(x), uint32_t(y), freshKey);
                row[x] = a * tiled + b * fresh;
            }
        }
    });
    return z;
}

}  // namespace stochtex
