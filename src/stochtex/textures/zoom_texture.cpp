#include "stochtex/textures/zoom_texture.h"

#include <cmath>

#include "stochtex/core/error.h"
#include "stochtex/core/floor.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"

namespace stochtex {

std::span<const OptionMember<ZoomParams>> zoomParamsMembers() {
    using O = ZoomParams;
    static const OptionMember<O> members[] = {
        {"layers", "Number of layers n (eq. 2.1)", 1, 1024, &O::layers},
        {"maxScale", "Maximum scale H", 1e-3, 1e3, &O::maxScale},
        {"time", "Time t (first frame)", -1e9, 1e9, &O::time},
        {"envelopeSigma", "Width s of the Gaussian envelope A around a = 1", 1e-6, 1e6, &O::envelopeSigma},
    };
    return members;
}

void validateZoomParams(const ZoomParams& p) { checkMembers(p, zoomParamsMembers()); }

namespace {

// mod(a, m) in [0, m) for m > 0, as GLSL's mod.
double positiveMod(double a, double m) { return a - m * std::floor(a / m); }

double fract(double v) { return v - std::floor(v); }

}  // namespace

std::vector<ZoomLayer> zoomLayers(const ZoomParams& p, int baseWidth, int baseHeight) {
    validateZoomParams(p);
    const int n = p.layers;
    const double h = p.maxScale;
    std::vector<ZoomLayer> layers(static_cast<size_t>(n));
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        ZoomLayer& l = layers[size_t(i)];
        const double phase = double(i) * h / double(n);
        l.scale = p.scaling == ZoomScaling::Sliding ? positiveMod(phase - p.time, h)                  // eq. 2.2
                                                    : h * std::exp(-positiveMod(p.time - phase, h));  // eq. 2.5
        const double d = l.scale - 1.0;
        l.weight = std::exp(-d * d / (2.0 * p.envelopeSigma * p.envelopeSigma));
        sum += l.weight;
        l.offsetX = l.offsetY = 0.0;
        switch (p.offsets) {
            case ZoomOffsets::None: break;
            case ZoomOffsets::Simple: {
                // w (i/n)²: see the header for why not (w i/n)².
                const double s = double(i) / double(n);
                l.offsetX = double(baseWidth) * s * s;
                break;
            }
            case ZoomOffsets::Hashed: {
                const UInt3 r = pcg3d({uint32_t(i), p.offsetSeed, 0x2f0a7e13u});
                l.offsetX = double(unitFloat(r.x)) * baseWidth;
                l.offsetY = double(unitFloat(r.y)) * baseHeight;
                break;
            }
            case ZoomOffsets::SinHash:  // eq. 2.23, evaluated in double
                l.offsetX = fract(4567.89 * std::sin(765.43 * i * 1.0 + 1.0)) * baseWidth;
                l.offsetY = fract(4567.89 * std::sin(765.43 * i * -13.17 + 1.0)) * baseHeight;
                break;
        }
    }
    // The Gaussian envelope vanishes only asymptotically; when every layer
    // sits far from a = 1 (tiny s) the normalisation still holds.
    for (auto& l : layers) l.weight = sum > 0 ? l.weight / sum : 1.0 / n;
    return layers;
}

LatticeTexture LatticeTexture::whiteNoise(int width, int height, uint32_t seed) {
    if (width < 2 || height < 2 || width > 16384 || height > 16384)
        throw InputError("white-noise base texture: size must be in [2, 16384] per side");
    LatticeTexture t;
    t.width_ = width;
    t.height_ = height;
    t.mean_ = 0.5;
    t.variance_ = 1.0 / 12.0;
    t.values_.resize(size_t(width) * size_t(height));
    parallelRows(height, [&](int y0, int y1) {
        for (int j = y0; j < y1; ++j)
            for (int i = 0; i < width; ++i)
                t.values_[size_t(j) * size_t(width) + size_t(i)] = unitFloat(pcg3d({uint32_t(i), uint32_t(j), seed}).x);
    });
    t.pad();
    return t;
}

void LatticeTexture::checkImage(const Image& gray) {
    if (gray.channels() != 1) throw InputError("base texture: expected a 1-channel image");
    if (gray.width() < 2 || gray.height() < 2)
        throw InputError("base texture: needs at least 2×2 pixels, got " + std::to_string(gray.width()) + "×" +
                         std::to_string(gray.height()));
    // A float image (EXR) may hold anything: half float's range keeps the
    // layers' sums and their moments finite (1e20 squared overflows float and
    // rendered black).
    constexpr double kMaxBaseValue = 65504.0;
    checkPixelRange(gray, "base texture", -kMaxBaseValue, kMaxBaseValue, "its");
}

LatticeTexture LatticeTexture::fromImage(const Image& gray) {
    checkImage(gray);
    LatticeTexture t;
    t.width_ = gray.width();
    t.height_ = gray.height();
    t.values_.assign(gray.data().begin(), gray.data().end());
    double s = 0, s2 = 0;
    for (float v : t.values_) {
        s += v;
        s2 += double(v) * v;
    }
    const double n = double(t.values_.size());
    t.mean_ = s / n;
    t.variance_ = std::max(0.0, s2 / n - t.mean_ * t.mean_);
    t.pad();
    return t;
}

void LatticeTexture::pad() {
    const int w = width_, h = height_;
    padded_.resize(size_t(w + 2) * size_t(h + 2));
    for (int j = -1; j <= h; ++j)
        for (int i = -1; i <= w; ++i) padded_[size_t(j + 1) * size_t(w + 2) + size_t(i + 1)] = at(i, j);
}

float LatticeTexture::at(int64_t i, int64_t j) const {
    const int64_t w = width_, h = height_;
    i %= w;
    j %= h;
    if (i < 0) i += w;
    if (j < 0) j += h;
    return values_[size_t(j) * size_t(w) + size_t(i)];
}

float LatticeTexture::sample(double x, double y, LatticeInterpolation mode) const {
    if (mode == LatticeInterpolation::Nearest) return at(floorToInt(x + 0.5), floorToInt(y + 0.5));
    const int64_t i = floorToInt(x), j = floorToInt(y);
    const float tx = float(x - double(i)), ty = float(y - double(j));
    const float a = at(i, j), b = at(i + 1, j), c = at(i, j + 1), d = at(i + 1, j + 1);
    const float top = a + tx * (b - a), bottom = c + tx * (d - c);
    return top + ty * (bottom - top);
}

double evaluateZoom(const LatticeTexture& f, const std::vector<ZoomLayer>& layers, LatticeInterpolation mode, double x,
                    double y) {
    double sum = 0;
    for (const ZoomLayer& l : layers)
        sum += l.weight * f.sample(l.scale * x + l.offsetX, l.scale * y + l.offsetY, mode);
    return sum;
}

Image renderZoom(const LatticeTexture& f, const ZoomParams& p, const ZoomRegion& region) {
    if (region.width < 1 || region.height < 1 || region.width > 16384 || region.height > 16384)
        throw InputError("zoom texture: output size must be in [1, 16384] per side");
    const std::vector<ZoomLayer> layers = zoomLayers(p, f.width(), f.height());
    Image out(region.width, region.height, 1, Image::Uninitialized{});
    const int w = f.width(), h = f.height();
    const size_t stride = size_t(w) + 2;
    const float* padded = f.padded().data();
    const bool nearest = p.interpolation == LatticeInterpolation::Nearest;
    parallelRows(region.height, [&](int y0, int y1) {
        std::vector<double> acc(size_t(region.width));
        for (int py = y0; py < y1; ++py) {
            std::fill(acc.begin(), acc.end(), 0.0);
            const double y = region.y0 + py;
            for (const ZoomLayer& l : layers) {
                // The lattice row(s) this layer reads along the whole scanline.
                const double yy = l.scale * y + l.offsetY + (nearest ? 0.5 : 0.0);
                const int64_t j = floorToInt(yy);
                const float ty = float(yy - double(j));
                const int64_t jr = ((j % h) + h) % h;
                const float* r0 = padded + size_t(jr + 1) * stride + 1;  // column 0 of lattice row jr
                const float* r1 = r0 + stride;
                const double wgt = l.weight;
                // i grows with px (a_i ≥ 0): track the multiple of w to
                // subtract instead of dividing per pixel.
                const int64_t first = floorToInt(l.scale * region.x0 + l.offsetX + (nearest ? 0.5 : 0.0));
                int64_t shift = first - (((first % w) + w) % w);
                for (int px = 0; px < region.width; ++px) {
                    const double xx = l.scale * (region.x0 + px) + l.offsetX + (nearest ? 0.5 : 0.0);
                    const int64_t i = floorToInt(xx);
                    const float tx = float(xx - double(i));
                    int64_t ir = i - shift;
                    while (ir >= w) {
                        shift += w;
                        ir -= w;
                    }
                    float v;
                    if (nearest) {
                        v = r0[ir];
                    } else {
                        const float top = r0[ir] + tx * (r0[ir + 1] - r0[ir]);
                        const float bottom = r1[ir] + tx * (r1[ir + 1] - r1[ir]);
                        v = top + ty * (bottom - top);
                    }
                    acc[size_t(px)] += wgt * v;
                }
            }
            float* o = out.row(py);
            for (int px = 0; px < region.width; ++px) o[px] = float(acc[size_t(px)]);
        }
    });
    return out;
}

ZoomScaling parseZoomScaling(const std::string& s) { return parseEnum(kZoomScalingNames, s, "scaling"); }
ZoomOffsets parseZoomOffsets(const std::string& s) { return parseEnum(kZoomOffsetsNames, s, "offsets"); }
LatticeInterpolation parseLatticeInterpolation(const std::string& s) {
    return parseEnum(kLatticeInterpolationNames, s, "interpolation");
}

}  // namespace stochtex
