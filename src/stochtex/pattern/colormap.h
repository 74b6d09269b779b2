#pragma once
// 2D transfer functions H: [0,1]² → RGB, the colour maps of S = H ∘ N.
//
// Every H is evaluated through a ColormapTable: an Rx×Ry grid of RGB samples
// at x = i/(Rx−1), y = j/(Ry−1), read bilinearly with clamp-to-edge (the
// paper encodes H as a lookup table too, and the prefiltered table H̄ of the
// filtering stage is built from this one). Sources of tables:
//   * an image (any size; column 0 is x = 0, the bottom row is y = 0, so the
//     file looks like a plot of H with y up),
//   * analytic presets: Gaussian H = x, ridged H = |2x − 1|, and the phasor
//     profile H = P(atan2(y − ½, x − ½)) with P = sine, sawtooth or square,
//   * a painted layout: an ordered list of shapes, later ones on top.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "stochtex/core/enum_names.h"
#include "stochtex/image/image.h"
#include "stochtex/kernel/lookup.h"

namespace stochtex {

class NoiseExample;  // noise/example.h

using Rgb = std::array<float, 3>;

class ColormapTable {
public:
    ColormapTable() = default;
    // table: Rx×Ry×3 with row j holding y = j/(Ry−1) (row 0 is y = 0).
    explicit ColormapTable(const Image& table);

    int resolutionX() const { return width_; }
    int resolutionY() const { return height_; }
    // The entries as an Rx×Ry RGB image, row 0 = y = 0.
    Image table() const;
    // Entry (i, j) (no interpolation).
    Rgb entry(int i, int j) const {
        const Texel t = rgba_[size_t(j) * size_t(width_) + size_t(i)];
        return {t[0], t[1], t[2]};
    }

    // Bilinear, clamp-to-edge: the taps of kernel::tableTap and the order
    // of kernel::blendRowsFirst, as in the shaders.
    Rgb sample(float x, float y) const { return blend(taps(x, y)); }
    // sample in two steps, so a caller can fetch ahead: the lower corner
    // entry (i, j) as j·Rx + i and the weights, then the blend.
    struct Taps {
        size_t entry;
        float tx, ty;
    };
    Taps taps(float x, float y) const {
        const kernel::TableTap tx = kernel::tableTap(x, width_), ty = kernel::tableTap(y, height_);
        return {size_t(ty.i) * size_t(width_) + size_t(tx.i), tx.t, ty.t};
    }
    Rgb blend(const Taps& t) const {
        const Texel c = blendTexels(rgba_.data() + t.entry, size_t(width_), t.tx, t.ty);
        return {c[0], c[1], c[2]};
    }
    // Asks the cache for the entries blend(t) will read.
    void prefetch(const Taps& t) const { prefetchTexels(rgba_.data() + t.entry, size_t(width_)); }

    // Entries as RGBA texels (alpha unused) so a lookup is four 16-byte
    // loads and vector arithmetic (a GCC/Clang vector extension).
    typedef float Texel __attribute__((vector_size(16)));
    // Entry j·Rx + i (the corner of Taps::entry), for a caller that blends
    // the taps of several tables at once (PrefilteredColormap::sampleRow).
    const Texel* texels() const { return rgba_.data(); }
    // kernel::blendRowsFirst's arithmetic (kernel::layerMix's too) on a
    // vector type V of the GCC extension, with weights tx, ty (floats or
    // vectors): IEEE multiplies and adds (no FMA), so each lane, at any
    // vector width, is the kernel's value.
    // Always inlined: GCC's warning that a 32-byte V would pass differently
    // without AVX concerns calls, and there are none.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
    template <class V, class X, class Y>
    [[gnu::always_inline]] static V rowsFirst(V e00, V e10, V e01, V e11, X tx, Y ty) {
        const V bottom = e00 + tx * (e10 - e00);
        const V top = e01 + tx * (e11 - e01);
        return bottom + ty * (top - bottom);
    }
#pragma GCC diagnostic pop
    // blend at the lower corner a of a table width texels wide.
    [[gnu::always_inline]] static Texel blendTexels(const Texel* a, size_t width, float tx, float ty) {
        return rowsFirst(a[0], a[1], a[width], a[width + 1], tx, ty);
    }
    // A row of lookups in a table of more than kPrefetchedBytes (beyond a
    // core's L2, where a smaller one stays in cache and its prefetches would
    // only take issue slots) asks for each pixel's entries kPrefetchAhead
    // pixels before its blend.
    static constexpr size_t kPrefetchedBytes = size_t(128) << 10;
    static constexpr size_t kPrefetchAhead = 8;
    [[gnu::always_inline]] static void prefetchTexels(const Texel* a, size_t width) {
        __builtin_prefetch(a);
        __builtin_prefetch(a + 1);
        __builtin_prefetch(a + width);
        __builtin_prefetch(a + width + 1);
    }
    // sample(x[k·stride], y[k·stride]) into rgb[3k..3k+2] for k < count
    // (stride 1, or 3: the first channel of vec3 rows): the taps of whole
    // vectors of values computed in SIMD lanes (tableTapsLanes), the same
    // values as sample's. Returns how many the lanes tapped (the rest: one
    // at a time).
    size_t sampleRow(const float* x, const float* y, size_t stride, float* rgb, size_t count) const;

    size_t bytes() const { return rgba_.size() * sizeof(Texel); }
    // The same resolution and entries (RGB; the unused alpha is not compared).
    bool operator==(const ColormapTable& other) const;

    // The table as an image with y up (row 0 = y = 1), for writing to disk.
    Image toImage() const;
    // Inverse of toImage: an image file's pixels as a table.
    static ColormapTable fromImage(const Image& image);

private:
    int width_ = 0, height_ = 0;
    std::vector<Texel, BulkAllocator<Texel>> rgba_;  // filled by the constructor
};

// Analytic presets. Phasor profiles: the analytic shapes, or Image, a
// profile sampled over one period (a W×1 image; PhasorColourProfile::sampled).
enum class PhasorProfile { Sine, Sawtooth, Square, Image };
inline const EnumNames<PhasorProfile> kPhasorProfileNames{{"sine", PhasorProfile::Sine},
                                                          {"sawtooth", PhasorProfile::Sawtooth},
                                                          {"square", PhasorProfile::Square},
                                                          {"image", PhasorProfile::Image}};
enum class AnalyticColormap { Gaussian, Ridged };

ColormapTable makeAnalyticColormap(AnalyticColormap kind, int resolution = 256);
// P(φ) ∈ [0, 1] for φ ∈ (−π, π] of an analytic shape (not Image: invalid_argument);
// duty: fraction of the period that is bright (square profile only).
float phasorProfile(PhasorProfile profile, double phase, double duty);

// The phasor noise's periodic profile as colours: phase φ ∈ (−π, π] → the
// table's colour (linear light, or data), so H(x, y) = P(atan2(y − ½, x − ½)).
// Phase φ is at t = (φ + π)/(2π) of the period, as for the sawtooth.
class PhasorColourProfile {
public:
    // An analytic shape. Without a palette, P is a gray level: an sRGB code,
    // decoded to linear light when `decodeGray` (the colour pipeline decodes
    // colours where they enter), else taken as data. With a palette (linear
    // colours, ≥ 2), P ∈ [0, 1] runs through it, interpolated in linear light.
    static PhasorColourProfile analytic(PhasorProfile shape, double duty, bool decodeGray,
                                        std::vector<Rgb> palette = {});
    // Samples over one period (≥ 2; sample k at t = (k + ½)/n, linear in
    // between, wrapping): already linear colours, or, with a palette, gray
    // levels (channel 0) indexing it.
    static PhasorColourProfile sampled(std::vector<Rgb> samples, std::vector<Rgb> palette = {});

    Rgb operator()(double phase) const;
    // The average colour over one period (4096 midpoint samples: within
    // 1/4096 of the exact mean for a square profile's jumps): what the
    // pattern fades to when the footprint covers many periods.
    Rgb mean() const;

private:
    PhasorProfile shape_ = PhasorProfile::Sine;
    double duty_ = 0.5;
    bool decodeGray_ = false;
    std::vector<Rgb> samples_, palette_;
};

// H = P ∘ atan2 tabulated (resolution² entries).
ColormapTable makePhasorColormap(const PhasorColourProfile& profile, int resolution = 256);
// An analytic gray profile as data (no transfer).
ColormapTable makePhasorColormap(PhasorProfile profile, double duty = 0.5, int resolution = 256);

// A painted layout. Shapes are tested in order; the last one containing a
// point gives its colour. Angles are in degrees, counter-clockwise, y up.
struct PaintedShape {
    enum class Kind { Rectangle, Disc, Ring, HalfPlane, Band, Polygon };
    Kind kind = Kind::Rectangle;
    Rgb colour{0, 0, 0};
    std::array<double, 2> a{0, 0};  // rectangle min; disc/ring centre; half-plane/band point
    std::array<double, 2> b{0, 0};  // rectangle max
    double radius = 0;              // disc radius; ring outer radius
    double innerRadius = 0;         // ring inner radius
    // Half-plane/band boundary direction, degrees (painted side: its left),
    // kept as its sine and cosine: set it with setAngle.
    double sinAngle = 0, cosAngle = 1;
    void setAngle(double degrees);
    double width = 0;                           // band width
    std::vector<std::array<double, 2>> points;  // polygon vertices (even-odd rule)

    bool contains(double x, double y) const;
    bool operator==(const PaintedShape&) const = default;
};

struct PaintedColormap {
    Rgb background{0, 0, 0};
    std::vector<PaintedShape> shapes;
    bool operator==(const PaintedColormap&) const = default;

    // Exact colour at (x, y).
    Rgb evaluate(double x, double y) const;
    // Table with `supersampling`² samples averaged per entry so edges are anti-aliased.
    ColormapTable rasterize(int resolution = 256, int supersampling = 4) const;

    // Shape tests one sample costs: 1 per shape, 1 per vertex of a polygon.
    long long edges() const;
    // Fails (parameter "shapes") if resolution² × supersampling² × edges()
    // is over kMaxPaintedWork.
    void validateWork(int resolution, int supersampling = 4) const;
};

constexpr int kMaxColormapResolution = 4096;
// Work budget of a painted rasterisation in shape tests, ~2 ns each
// (2³² ≈ 9 s on one core): 16 shapes at resolution 4096, 4096 at 256.
constexpr long long kMaxPaintedWork = 1LL << 32;

// H'(x, y) = H(T_x⁻¹(x), T_y⁻¹(y)) on H's own grid, for each of x and y
// that is a Gaussianized exemplar (null: that axis as it is): a colormap
// moved into the blending space, where the statistics are Gaussian.
ColormapTable foldInverseTransforms(const ColormapTable& h, const NoiseExample* x, const NoiseExample* y);

}  // namespace stochtex
