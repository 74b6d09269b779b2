#include "stochtex/textures/marble_texture.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"
#include "stochtex/kernel/marble.h"

namespace stochtex {

namespace {

constexpr double kMaxCoordinate = 1 << 20;  // pixels from the origin
constexpr double kMinLevel = -8, kMaxLevel = 40;

int kernelLayer(MarbleLayer layer) {
    switch (layer) {
        case MarbleLayer::Marble: return kernel::kMarbleLayerMarble;
        case MarbleLayer::ScaledNoise: return kernel::kMarbleLayerScaledNoise;
        case MarbleLayer::ScalingOnly: return kernel::kMarbleLayerScalingOnly;
        case MarbleLayer::BaseNoise: break;
    }
    return kernel::kMarbleLayerBaseNoise;
}

}  // namespace

std::span<const OptionMember<MarbleParams>> marbleParamsMembers() {
    using O = MarbleParams;
    static const OptionMember<O> members[] = {
        {"bandPeriod", "Pixels between two bands, 2π/|a|", 1, 1e6, &O::bandPeriod},
        {"bandAngle", "Direction of a, degrees from the x axis (0: vertical veins)", -360, 360, &O::bandAngle},
        {"distortion", "b: band phase, radians, per unit of noise", -1000, 1000, &O::distortion},
        {"level", "m: noise cells of 2^m pixels", -4, 20, &O::level},
        {"levelAmplitude", "n in l = m + n cos(q x) + r t (stretching)", -8, 8, &O::levelAmplitude},
        {"levelPeriod", "2π/q, pixels along x of one cycle of l", 1, 1e9, &O::levelPeriod},
        {"levelRate", "r, change of l per unit of time (sliding)", -100, 100, &O::levelRate},
    };
    return members;
}

void validateMarbleParams(const MarbleParams& p) { checkMembers(p, marbleParamsMembers()); }

kernel::Marble kernelMarble(const MarbleParams& p, int instance) {
    const double a = 2 * std::numbers::pi / p.bandPeriod, angle = p.bandAngle * std::numbers::pi / 180;
    const int scaling = p.scaling == MarbleScaling::Continuous ? kernel::kMarbleContinuous
                        : p.scaling == MarbleScaling::Blended  ? kernel::kMarbleBlended
                                                               : kernel::kMarbleBlendedCorrected;
    return {kernel::vec2(float(a * std::cos(angle)), float(a * std::sin(angle))),
            float(p.distortion),
            float(p.level),
            float(p.levelAmplitude),
            float(2 * std::numbers::pi / p.levelPeriod),
            float(p.levelRate),
            scaling,
            deriveSeed(p.seed, uint32_t(instance))};
}

double marbleLevelSlope(const MarbleParams& p, double x) {
    const double q = 2 * std::numbers::pi / p.levelPeriod;
    return -p.levelAmplitude * q * std::sin(q * x);
}

MarbleSource::MarbleSource(const MarbleParams& params) : params_(params) { validateMarbleParams(params_); }

void MarbleSource::checkWindow(const SourceRegion& region, double time) const {
    const MarbleParams& p = params_;
    if (!std::isfinite(time)) throw InputError::parameter("time", "must be finite, got " + formatValue(time));
    const double far = std::max({std::abs(region.x0), std::abs(region.y0), std::abs(region.x0 + region.width),
                                 std::abs(region.y0 + region.height)});
    if (!(far <= kMaxCoordinate))
        throw InputError("marble texture: the window reaches " + formatValue(far) + " pixels from the origin, beyond " +
                         formatValue(kMaxCoordinate));
    // l's extremes over the window: the cosine's range and the time term.
    const double low = p.level - std::abs(p.levelAmplitude) + p.levelRate * time;
    const double high = p.level + std::abs(p.levelAmplitude) + p.levelRate * time;
    if (low < kMinLevel || high > kMaxLevel)
        throw InputError("marble texture: at time " + formatValue(time) +
                         " the noise scale exponent l = m + n cos(q x) + "
                         "r t spans [" +
                         formatValue(low) + ", " + formatValue(high) + "], outside [" + formatValue(kMinLevel) + ", " +
                         formatValue(kMaxLevel) + "]");
}

Image MarbleSource::render(const SourceRegion& region, double time, int instance) const {
    checkWindow(region, time);
    const MarbleParams& p = params_;
    const kernel::Marble m = kernelMarble(p, instance);
    const int layer = kernelLayer(p.layer);
    Image out(region.width, region.height, 1, Image::Uninitialized{});
    parallelRows(region.height, [&](int y0, int y1) {
        for (int py = y0; py < y1; ++py) {
            const float y = float(region.y0 + py + 0.5);
            for (int px = 0; px < region.width; ++px)
                out.at(px, py) =
                    kernel::marbleValue(m, layer, kernel::vec2(float(region.x0 + px + 0.5), y), float(time));
        }
    });
    return out;
}

}  // namespace stochtex
