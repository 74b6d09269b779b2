#pragma once
// The marble texture of the thesis (Tavernier 2017, §2.7.2 and §2.8,
// eq. 2.29): bands perturbed by a gradient noise whose scale 2^l varies in
// space (stretching) or in time (sliding), with the fix by blended integer
// scales. The per-pixel formula is the kernel's (kernel/marble.glsl), so a
// shader computes the same texture; this file holds its parameters in the
// units a user thinks in and renders windows of it for the studies.
#include <cstdint>
#include <span>

#include "stochtex/core/enum_names.h"
#include "stochtex/image/image.h"
#include "stochtex/kernel/marble.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

// How the noise follows the scale exponent l.
enum class MarbleScaling {
    Continuous,        // noise(x / 2^l): stretches where l varies in space, slides where it varies in time
    Blended,           // the fix: the two integer scales around l, each its own field, mixed by fract(l)
    BlendedCorrected,  // the same, divided by √((1 − w)² + w²) to restore the contrast the mix loses (eq. 2.24)
};
inline const EnumNames<MarbleScaling> kMarbleScalingNames{{"continuous", MarbleScaling::Continuous},
                                                          {"blended", MarbleScaling::Blended},
                                                          {"blended-corrected", MarbleScaling::BlendedCorrected}};

// Which step of eq. 2.29 is shown, each in [0, 1].
enum class MarbleLayer {
    Marble,       // I(x), the texture
    ScaledNoise,  // ½ + ½ noise(x / 2^l): the perturbation
    ScalingOnly,  // ½ + ½ white cell noise through the same scaling: the scaling step's own correlation
    BaseNoise,    // ½ + ½ noise(x / 2^m): the gradient noise before any scaling (Figure 2.21)
};
inline const EnumNames<MarbleLayer> kMarbleLayerNames{{"marble", MarbleLayer::Marble},
                                                      {"scaled-noise", MarbleLayer::ScaledNoise},
                                                      {"scaling-only", MarbleLayer::ScalingOnly},
                                                      {"base-noise", MarbleLayer::BaseNoise}};

// I(x) = ½ + ½ sin(a·x + b noise(x / 2^l)), l = m + n cos(q x_x) + r t, with
// x in pixels from the source's origin (the centre of a centred window).
struct MarbleParams {
    double bandPeriod = 64;     // 2π/|a|, pixels between two bands
    double bandAngle = 0;       // direction of a, degrees from the x axis (0: vertical veins)
    double distortion = 6;      // b, radians of band phase per unit of noise
    double level = 5;           // m: noise cells of 2^m pixels
    double levelAmplitude = 1;  // n
    double levelPeriod = 128;   // 2π/q, pixels (along x) of one cycle of l
    double levelRate = 0;       // r, change of l per unit of time (sliding)
    MarbleScaling scaling = MarbleScaling::Continuous;
    MarbleLayer layer = MarbleLayer::Marble;
    uint32_t seed = 1;  // instance i draws its noise with deriveSeed(seed, i)
};

// The entries of MarbleParams' numbers (validateMarbleParams; the CLI's flags).
std::span<const OptionMember<MarbleParams>> marbleParamsMembers();
// InputError naming the parameter, before any work.
void validateMarbleParams(const MarbleParams& p);

// The parameters as the kernel takes them (kernel/marble.glsl), for instance i.
kernel::Marble kernelMarble(const MarbleParams& p, int instance);
// ∂l/∂x of the kernel's noise-scale exponent l = m + n cos(q x) + r t
// (kernel::marbleLevel) at pixel x_x: the stretch of the scaling (the
// marble study's anisotropy). l itself is only the kernel's.
double marbleLevelSlope(const MarbleParams& p, double x);

// The marble texture as a source (1 channel, values in [0, 1] except where
// the corrected blend overshoots): instance i = the noises of seed
// deriveSeed(seed, i) on the same lattice. Pixel (px, py) of a region is the
// point (x0 + px + ½, y0 + py + ½). InputError when a region or time puts the
// scale or the coordinates out of the range validated here (|x| ≤ 2²⁰ pixels,
// l ∈ [−8, 40]).
class MarbleSource : public TextureSource {
public:
    explicit MarbleSource(const MarbleParams& params);
    const MarbleParams& params() const { return params_; }
    int channels() const override { return 1; }
    Image render(const SourceRegion& region, double time, int instance) const override;
    void checkWindow(const SourceRegion& region, double time) const override;

private:
    MarbleParams params_;
};

}  // namespace stochtex
