#include "stochtex/noise/phasor_noise.h"

#include <cmath>
#include <numbers>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"

namespace stochtex {

namespace {

constexpr double kMaxFrequency = 1e4, kMaxDensity = 64.0;

void checkRange(const char* name, double value, double lo, double hi, bool openLow) {
    if (!std::isfinite(value) || value > hi || (openLow ? value <= lo : value < lo))
        throw InputError::parameter(name, std::string("must be in ") + (openLow ? "(" : "[") + formatValue(lo) +
                                              ", " + formatValue(hi) + "], got " + formatValue(value));
}

}  // namespace

void validatePhasorNoise(const PhasorNoiseParams& p) {
    checkRange("frequency", p.frequency, 0.0, kMaxFrequency, true);
    checkRange("bandwidth", p.bandwidth, 0.0, kMaxFrequency, true);
    checkRange("orientation", p.orientation, -360.0, 360.0, false);
    checkRange("density", p.density, 0.0, kMaxDensity, true);
}

PhasorNoise::PhasorNoise(const PhasorNoiseParams& params) : params_(params) {
    validatePhasorNoise(params);
    sigma_ = 1.0 / (2.0 * std::numbers::sqrt2 * std::numbers::pi * params.bandwidth);
    cell_ = kPhasorKernelRadius * sigma_;
    const double t = params.orientation * std::numbers::pi / 180.0;
    du_ = std::cos(t);
    dv_ = -std::sin(t);
}

std::array<double, 2> PhasorNoise::complexValue(double u, double v) const {
    const double cu = std::floor(u / cell_), cv = std::floor(v / cell_);
    const double radius2 = cell_ * cell_, inv2s2 = 1.0 / (2.0 * sigma_ * sigma_);
    const double omega = 2.0 * std::numbers::pi * params_.frequency;
    const int whole = int(params_.density);
    const double fraction = params_.density - whole;
    double re = 0, im = 0;
    // The kernels reaching (u, v) have their impulse within one cell side:
    // in this cell or its eight neighbours.
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            const double ci = cu + i, cj = cv + j;
            // Cell coordinates as 32-bit patterns (wrapping far from the origin is harmless).
            UInt3 h = pcg3d({uint32_t(int64_t(ci)), uint32_t(int64_t(cj)), params_.seed});
            // The count: the density's whole part, plus one with probability its fraction.
            const int count = whole + (unitFloat(h.z) < fraction ? 1 : 0);
            for (int k = 0; k < count; ++k) {
                h = pcg3d({h.x, h.y, h.z ^ uint32_t(k + 1)});
                const double pu = (ci + unitFloat(h.x)) * cell_, pv = (cj + unitFloat(h.y)) * cell_;
                const double x = u - pu, y = v - pv, r2 = x * x + y * y;
                if (r2 >= radius2) continue;
                const double w = 2.0 * unitFloat(h.z) - 1.0;  // weight, uniform in [−1, 1]
                const double a = w * std::exp(-r2 * inv2s2), arg = omega * (x * du_ + y * dv_);
                re += a * std::cos(arg);
                im += a * std::sin(arg);
            }
        }
    return {re, im};
}

double PhasorNoise::phase(double u, double v) const {
    const auto g = complexValue(u, v);
    return std::atan2(g[1], g[0]);
}

}  // namespace stochtex
