#include "stochtex/textures/zoom_statistics.h"

#include <cmath>

#include "stochtex/core/floor.h"
#include "stochtex/core/parallel.h"

namespace stochtex {

ZoomStatistics::ZoomStatistics(const ZoomParams& p, int baseWidth, int baseHeight)
    : layers_(zoomLayers(p, baseWidth, baseHeight)),
      mode_(p.interpolation),
      width_(baseWidth),
      height_(baseHeight) {}

double ZoomStatistics::overlap1d(double s, double t, double period) const {
    // Bring t to the periodic image nearest to s: only that image can share
    // a lattice point with s (kernels have support ≤ 2 and periods ≥ 2).
    t = s + (t - s) - period * std::round((t - s) / period);
    if (mode_ == LatticeInterpolation::Nearest)
        return floorToInt(s + 0.5) == floorToInt(t + 0.5) ? 1.0 : 0.0;
    // Tent: s reads lattice points k0 = ⌊s⌋ (weight 1 − fs) and k0 + 1 (fs).
    auto tent = [](double d) { return std::max(0.0, 1.0 - std::abs(d)); };
    const double k0 = double(floorToInt(s));
    const double fs = s - k0;
    return (1.0 - fs) * tent(t - k0) + fs * tent(t - (k0 + 1.0));
}

double ZoomStatistics::alpha(double x1, double y1, double x2, double y2) const {
    double a = 0;
    for (const ZoomLayer& li : layers_) {
        const double sx = li.scale * x1 + li.offsetX, sy = li.scale * y1 + li.offsetY;
        double row = 0;
        for (const ZoomLayer& lj : layers_) {
            const double ox = overlap1d(sx, lj.scale * x2 + lj.offsetX, width_);
            if (ox == 0.0) continue;
            row += lj.weight * ox * overlap1d(sy, lj.scale * y2 + lj.offsetY, height_);
        }
        a += li.weight * row;
    }
    return a;
}

double ZoomStatistics::correlation(double x1, double y1, double x2, double y2) const {
    const double d = std::sqrt(varianceFactor(x1, y1) * varianceFactor(x2, y2));
    return d > 0 ? alpha(x1, y1, x2, y2) / d : 0.0;
}

Image ZoomStatistics::varianceFactorImage(const ZoomRegion& region) const {
    Image out(region.width, region.height, 1, Image::Uninitialized{});
    parallelRows(region.height, [&](int y0, int y1) {
        for (int py = y0; py < y1; ++py)
            for (int px = 0; px < region.width; ++px) {
                const double x = region.x0 + px, y = region.y0 + py;
                out.at(px, py) = float(varianceFactor(x, y));
            }
    });
    return out;
}

Image ZoomStatistics::radialCorrelation(int size) const {
    std::vector<double> diag(static_cast<size_t>(size));
    for (int x = 0; x < size; ++x) diag[size_t(x)] = varianceFactor(x, 0);
    Image out(size, size, 1, Image::Uninitialized{});
    parallelRows(size, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < size; ++x) {
                const double d = std::sqrt(diag[size_t(x)] * diag[size_t(y)]);
                out.at(x, y) = d > 0 ? float(alpha(x, 0, y, 0) / d) : 0.0f;
            }
    });
    return out;
}

Image ZoomStatistics::nonRadialCorrelation(int size) const {
    Image out(size, size, 1, Image::Uninitialized{});
    parallelRows(size, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < size; ++x) out.at(x, y) = float(correlation(x, 0, x, y));
    });
    return out;
}

}  // namespace stochtex
