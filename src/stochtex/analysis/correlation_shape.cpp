#include "stochtex/analysis/correlation_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace stochtex {

CorrelationShape correlationShape(const Image& map, int rx, int ry, double threshold, int smoothing) {
    const int w = map.width(), h = map.height();
    if (map.channels() != 1 || rx < 0 || ry < 0 || rx >= w || ry >= h || smoothing < 1)
        throw std::invalid_argument("correlationShape: a 1-channel map with the reference inside it");
    CorrelationShape s;
    // The region: flood fill from the reference point.
    std::vector<char> seen(size_t(w) * size_t(h), 0);
    std::vector<std::pair<int, int>> stack;
    const auto inRegion = [&](int x, int y) { return map.at(x, y) >= threshold; };  // false for NaN
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    if (inRegion(rx, ry)) {
        stack.push_back({rx, ry});
        seen[size_t(ry) * size_t(w) + size_t(rx)] = 1;
    }
    while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        ++s.area;
        sx += x, sy += y, sxx += double(x) * x, syy += double(y) * y, sxy += double(x) * y;
        const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
        for (int k = 0; k < 4; ++k) {
            if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
            char& v = seen[size_t(ny[k]) * size_t(w) + size_t(nx[k])];
            if (v || !inRegion(nx[k], ny[k])) continue;
            v = 1;
            stack.push_back({nx[k], ny[k]});
        }
    }
    if (s.area > 0) {
        // Each pixel is a unit square: its own variance 1/12 per axis keeps a
        // one-pixel region round.
        const double n = s.area, mx = sx / n, my = sy / n;
        const double cxx = sxx / n - mx * mx + 1.0 / 12, cyy = syy / n - my * my + 1.0 / 12, cxy = sxy / n - mx * my;
        const double mid = 0.5 * (cxx + cyy), r = std::sqrt(0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy);
        s.elongation = std::sqrt((mid + r) / std::max(mid - r, 1e-12));
        // Angle of the major axis in image axes, then flipped: image y points down.
        s.orientationDeg = -0.5 * std::atan2(2 * cxy, cxx - cyy) * 180 / std::numbers::pi;
        if (s.orientationDeg < 0) s.orientationDeg += 180;
    }
    // The smoothed minimum, with a box of `smoothing` pixels clipped at the borders.
    const int half = smoothing / 2;
    double lowest = 0;
    bool any = false;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0;
            int count = 0;
            for (int v = std::max(0, y - half); v <= std::min(h - 1, y + half); ++v)
                for (int u = std::max(0, x - half); u <= std::min(w - 1, x + half); ++u)
                    if (const float c = map.at(u, v); std::isfinite(c)) sum += c, ++count;
            if (count == 0) continue;
            const double mean = sum / count;
            if (!any || mean < lowest) lowest = mean;
            any = true;
        }
    s.antiCorrelation = lowest;
    return s;
}

}  // namespace stochtex
