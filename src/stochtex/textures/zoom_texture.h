#pragma once
// The stationary zoom texture (Tavernier 2017, eq. 2.1): n layers of one
// base texture, each scaled by its own factor a_i, blended with a Gaussian
// envelope normalised over the layers,
//     I(x) = Σ_i A(a_i) g(a_i x + o_i),   A(a_i) = e^{−(a_i−1)²/2s²} / Σ_j e^{−(a_j−1)²/2s²},
// where x is the pixel position relative to the zoom centre (pixel units)
// and g = f ∗ K is a periodic lattice texture f (one value per integer
// point, period W×H) reconstructed by the kernel K: the tent Λ (linear
// interpolation, eq. 2.8) or the unit box (nearest).
//
// Scales: sliding a_i = mod(iH/n − t, H) (eq. 2.2), or the exponential fix
// a_i = H e^{−mod(t − iH/n, H)} (eq. 2.5) that gives every layer the same
// screen-space speed. Offsets o_i: none; "simple" w (i/n)² along x (the
// artist's quadratic hack of section 2.5.2; the thesis writes (w i/n)², which
// is a whole number of periods — no shift at all on a periodic lattice —
// whenever w/n is an integer, so we apply the same law as a fraction of the
// period); "hashed": rand(i) × (w, h) with rand the
// project's integer hash pcg3d (our convention: bit-identical on CPU and
// GPU); "sin-hash": rand(i) = fract(4567.89 sin(765.43 i (1, −13.17) + (1, 1)))
// exactly as eq. 2.23 writes it.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "stochtex/core/enum_names.h"
#include "stochtex/image/image.h"
#include "stochtex/pattern/param_info.h"

namespace stochtex {

enum class ZoomScaling { Sliding, Exponential };
inline const EnumNames<ZoomScaling> kZoomScalingNames{
    {"sliding", ZoomScaling::Sliding}, {"exponential", ZoomScaling::Exponential}, {"fixed", ZoomScaling::Exponential}};
enum class ZoomOffsets { None, Simple, Hashed, SinHash };
inline const EnumNames<ZoomOffsets> kZoomOffsetsNames{{"none", ZoomOffsets::None},
                                                      {"simple", ZoomOffsets::Simple},
                                                      {"hashed", ZoomOffsets::Hashed},
                                                      {"sin-hash", ZoomOffsets::SinHash}};
enum class LatticeInterpolation { Nearest, Linear };
inline const EnumNames<LatticeInterpolation> kLatticeInterpolationNames{{"nearest", LatticeInterpolation::Nearest},
                                                                        {"linear", LatticeInterpolation::Linear}};

struct ZoomParams {
    int layers = 8;              // n
    double maxScale = 2.0;       // H
    double time = 0.0;           // t
    double envelopeSigma = 0.3;  // s: width of the envelope A around a = 1
    ZoomScaling scaling = ZoomScaling::Exponential;
    ZoomOffsets offsets = ZoomOffsets::None;
    LatticeInterpolation interpolation = LatticeInterpolation::Linear;
    uint32_t offsetSeed = 1;  // hashed offsets only
};

// The entries of ZoomParams' numbers: n, H, t, s (validateZoomParams; the CLI's flags).
std::span<const OptionMember<ZoomParams>> zoomParamsMembers();
// InputError naming the offending parameter (n, H, s or t outside its entry's range).
void validateZoomParams(const ZoomParams& p);

// One layer of eq. 2.1 at time t.
struct ZoomLayer {
    double scale;    // a_i
    double weight;   // A(a_i), Σ weights = 1
    double offsetX;  // o_i, lattice units
    double offsetY;
};
// The n layers for a base lattice of period baseWidth × baseHeight.
std::vector<ZoomLayer> zoomLayers(const ZoomParams& p, int baseWidth, int baseHeight);

// A periodic lattice of values f(k), k ∈ Z², period W×H, with its
// statistics μ_f and σ_f² (over the process that generated it).
class LatticeTexture {
public:
    LatticeTexture() = default;
    // Independent uniform values in [0, 1): μ_f = 1/2, σ_f² = 1/12.
    static LatticeTexture whiteNoise(int width, int height, uint32_t seed);
    // Any 1-channel image (values as given); μ_f and σ_f² are its own
    // mean and variance. InputError (checkImage) for one it cannot use.
    static LatticeTexture fromImage(const Image& gray);
    // InputError unless gray is 1-channel and at least 2×2; the message
    // names no input, so whoever read the image prefixes its name.
    static void checkImage(const Image& gray);

    int width() const { return width_; }
    int height() const { return height_; }
    double mean() const { return mean_; }
    double variance() const { return variance_; }
    float at(int64_t i, int64_t j) const;  // periodic

    // g(y) = Σ_k f(k) K(y − k).
    float sample(double x, double y, LatticeInterpolation mode) const;
    // The lattice with a one-texel periodic border (row stride W + 2), for
    // the renderer's branch-free bilinear reads.
    const std::vector<float>& padded() const { return padded_; }

private:
    void pad();
    int width_ = 0, height_ = 0;
    double mean_ = 0, variance_ = 0;
    std::vector<float> values_, padded_;
};

// The region of the plane a rendering covers: pixel (px, py) of the image
// is the point x = (x0 + px, y0 + py) relative to the zoom centre.
struct ZoomRegion {
    int width = 512, height = 512;
    double x0 = -256, y0 = -256;
    static ZoomRegion centred(int width, int height) { return {width, height, -0.5 * width, -0.5 * height}; }
};

// I(x) at one point.
double evaluateZoom(const LatticeTexture& f, const std::vector<ZoomLayer>& layers, LatticeInterpolation mode, double x,
                    double y);
// The texture over a region, 1 channel, multi-threaded (rows in parallel;
// the result does not depend on the thread count).
Image renderZoom(const LatticeTexture& f, const ZoomParams& p, const ZoomRegion& region);

// Parsers over the name tables above; InputError naming the parameter otherwise.
ZoomScaling parseZoomScaling(const std::string& s);
ZoomOffsets parseZoomOffsets(const std::string& s);
LatticeInterpolation parseLatticeInterpolation(const std::string& s);

}  // namespace stochtex
