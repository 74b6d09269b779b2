#include "stochtex/pattern/colormap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/noise/example.h"

namespace stochtex {

ColormapTable::ColormapTable(const Image& table) : width_(table.width()), height_(table.height()) {
    if (table.channels() != 3 || table.width() < 2 || table.height() < 2)
        throw std::invalid_argument("ColormapTable: needs an RGB table of at least 2×2");
    rgba_.resize(table.pixelCount());
    const float* src = table.data().data();
    for (size_t i = 0; i < rgba_.size(); ++i) rgba_[i] = Texel{src[3 * i], src[3 * i + 1], src[3 * i + 2], 0.0f};
}

// Flips rows: tables keep y = 0 in row 0, images on disk show y up.
static Image flipRows(const Image& image) {
    Image out(image.width(), image.height(), image.channels());
    const size_t rowSize = size_t(image.width()) * size_t(image.channels());
    for (int j = 0; j < image.height(); ++j)
        std::copy(image.row(j), image.row(j) + rowSize, out.row(image.height() - 1 - j));
    return out;
}

bool ColormapTable::operator==(const ColormapTable& other) const {
    if (width_ != other.width_ || height_ != other.height_) return false;
    for (size_t k = 0; k < rgba_.size(); ++k)
        for (int c = 0; c < 3; ++c)
            if (rgba_[k][c] != other.rgba_[k][c]) return false;
    return true;
}

Image ColormapTable::table() const {
    Image out(width_, height_, 3, Image::Uninitialized{});
    for (size_t i = 0; i < rgba_.size(); ++i)
        for (size_t c = 0; c < 3; ++c) out.data()[3 * i + c] = rgba_[i][c];
    return out;
}

Image ColormapTable::toImage() const { return flipRows(table()); }

ColormapTable ColormapTable::fromImage(const Image& image) { return ColormapTable(flipRows(toRgb(image))); }

namespace {

template <class F>
ColormapTable tabulate(int resolution, F&& h) {
    if (resolution < 2 || resolution > kMaxColormapResolution)
        throw InputError::parameter("resolution", "must be in [2, " + std::to_string(kMaxColormapResolution) +
                                                      "], got " + std::to_string(resolution));
    Image table(resolution, resolution, 3);
    const double step = 1.0 / double(resolution - 1);
    parallelRows(resolution, [&](int y0, int y1) {
        for (int j = y0; j < y1; ++j)
            for (int i = 0; i < resolution; ++i) {
                const Rgb c = h(double(i) * step, double(j) * step);
                for (int k = 0; k < 3; ++k) table.at(i, j, k) = c[size_t(k)];
            }
    });
    return ColormapTable(table);
}

Rgb gray(double v) { return {float(v), float(v), float(v)}; }

}  // namespace

ColormapTable makeAnalyticColormap(AnalyticColormap kind, int resolution) {
    switch (kind) {
        case AnalyticColormap::Gaussian: return tabulate(resolution, [](double x, double) { return gray(x); });
        case AnalyticColormap::Ridged:
            return tabulate(resolution, [](double x, double) { return gray(std::abs(2.0 * x - 1.0)); });
    }
    throw std::invalid_argument("unknown analytic colormap");
}

float phasorProfile(PhasorProfile profile, double phase, double duty) {
    const double t = (phase + std::numbers::pi) / (2.0 * std::numbers::pi);  // [0,1]
    switch (profile) {
        case PhasorProfile::Sine: return float(0.5 + 0.5 * std::sin(phase));
        case PhasorProfile::Sawtooth: return float(t - std::floor(t));
        case PhasorProfile::Square: return (t - std::floor(t)) < duty ? 1.0f : 0.0f;
        case PhasorProfile::Image: break;
    }
    throw std::invalid_argument("phasorProfile: a sampled profile has no analytic shape");
}

namespace {

Rgb mix(const Rgb& a, const Rgb& b, float t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

// Linear interpolation between samples k at positions (k + ½)/n (periodic) or
// k/(n − 1) (clamped, for palettes).
Rgb interpolate(const std::vector<Rgb>& samples, double t, bool periodic) {
    const size_t n = samples.size();
    const double x = periodic ? (t - std::floor(t)) * double(n) - 0.5 : std::clamp(t, 0.0, 1.0) * double(n - 1);
    const double f = std::floor(x);
    const double w = x - f;
    const long long i = (long long)f;
    const auto at = [&](long long k) {
        return samples[periodic ? size_t((k % (long long)n + (long long)n) % (long long)n)
                                : size_t(std::clamp(k, 0LL, (long long)n - 1))];
    };
    return mix(at(i), at(i + 1), float(w));
}

}  // namespace

PhasorColourProfile PhasorColourProfile::analytic(PhasorProfile shape, double duty, bool decodeGray,
                                                  std::vector<Rgb> palette) {
    if (shape == PhasorProfile::Image) throw std::invalid_argument("PhasorColourProfile::analytic: needs a shape");
    if (palette.size() == 1) throw std::invalid_argument("PhasorColourProfile: a palette needs at least 2 colours");
    PhasorColourProfile p;
    p.shape_ = shape;
    p.duty_ = duty;
    p.decodeGray_ = decodeGray;
    p.palette_ = std::move(palette);
    return p;
}

PhasorColourProfile PhasorColourProfile::sampled(std::vector<Rgb> samples, std::vector<Rgb> palette) {
    if (samples.size() < 2) throw std::invalid_argument("PhasorColourProfile::sampled: needs at least 2 samples");
    if (palette.size() == 1) throw std::invalid_argument("PhasorColourProfile: a palette needs at least 2 colours");
    PhasorColourProfile p;
    p.shape_ = PhasorProfile::Image;
    p.samples_ = std::move(samples);
    p.palette_ = std::move(palette);
    return p;
}

Rgb PhasorColourProfile::operator()(double phase) const {
    Rgb c;
    if (shape_ == PhasorProfile::Image) {
        c = interpolate(samples_, (phase + std::numbers::pi) / (2.0 * std::numbers::pi), true);
    } else {
        const float p = phasorProfile(shape_, phase, duty_);
        // A palette is indexed by the value itself; a gray level is a colour.
        c = gray(palette_.empty() && decodeGray_ ? linearFromSrgb(p) : p);
    }
    return palette_.empty() ? c : interpolate(palette_, double(c[0]), false);
}

Rgb PhasorColourProfile::mean() const {
    constexpr int n = 4096;
    double sum[3] = {0, 0, 0};
    for (int k = 0; k < n; ++k) {
        const Rgb c = (*this)(-std::numbers::pi + 2.0 * std::numbers::pi * (k + 0.5) / n);
        for (size_t i = 0; i < 3; ++i) sum[i] += c[i];
    }
    return {float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
}

ColormapTable makePhasorColormap(const PhasorColourProfile& profile, int resolution) {
    return tabulate(resolution, [&](double x, double y) { return profile(std::atan2(y - 0.5, x - 0.5)); });
}

ColormapTable makePhasorColormap(PhasorProfile profile, double duty, int resolution) {
    return makePhasorColormap(PhasorColourProfile::analytic(profile, duty, false), resolution);
}

void PaintedShape::setAngle(double degrees) {
    const double t = degrees * std::numbers::pi / 180.0;
    sinAngle = std::sin(t);
    cosAngle = std::cos(t);
}

bool PaintedShape::contains(double x, double y) const {
    switch (kind) {
        case Kind::Rectangle: return x >= a[0] && x <= b[0] && y >= a[1] && y <= b[1];
        case Kind::Disc: {
            const double dx = x - a[0], dy = y - a[1];
            return dx * dx + dy * dy <= radius * radius;
        }
        case Kind::Ring: {
            const double dx = x - a[0], dy = y - a[1], r2 = dx * dx + dy * dy;
            return r2 >= innerRadius * innerRadius && r2 <= radius * radius;
        }
        case Kind::HalfPlane:
        case Kind::Band: {
            // Signed distance to the boundary line, positive on its left.
            const double d = -(x - a[0]) * sinAngle + (y - a[1]) * cosAngle;
            return kind == Kind::HalfPlane ? d >= 0.0 : std::abs(d) <= 0.5 * width;
        }
        case Kind::Polygon: {
            bool inside = false;
            const size_t n = points.size();
            for (size_t i = 0, j = n - 1; i < n; j = i++) {
                const auto& p = points[i];
                const auto& q = points[j];
                if ((p[1] > y) != (q[1] > y) && x < (q[0] - p[0]) * (y - p[1]) / (q[1] - p[1]) + p[0]) inside = !inside;
            }
            return inside;
        }
    }
    return false;
}

Rgb PaintedColormap::evaluate(double x, double y) const {
    Rgb c = background;
    for (const auto& s : shapes)
        if (s.contains(x, y)) c = s.colour;
    return c;
}

long long PaintedColormap::edges() const {
    long long n = 0;
    for (const PaintedShape& s : shapes) n += s.kind == PaintedShape::Kind::Polygon ? (long long)s.points.size() : 1;
    return n;
}

void PaintedColormap::validateWork(int resolution, int supersampling) const {
    const long long samples = (long long)resolution * resolution * supersampling * supersampling;
    if (edges() > 0 && samples * edges() > kMaxPaintedWork)
        throw InputError::parameter(
            "shapes", "cost " + std::to_string(edges()) + " shape tests (1 per shape, 1 per polygon vertex) × " +
                          std::to_string(samples) + " samples (resolution " + std::to_string(resolution) + "² × " +
                          std::to_string(supersampling * supersampling) +
                          ") = " + formatValue(double(samples * edges())) + "; the limit is " +
                          std::to_string(kMaxPaintedWork) + " (fewer shapes or vertices, or a lower resolution)");
}

ColormapTable PaintedColormap::rasterize(int resolution, int supersampling) const {
    if (supersampling < 1) throw std::invalid_argument("supersampling must be >= 1");
    validateWork(resolution, supersampling);
    const double cell = 1.0 / double(resolution - 1);
    // The part of the cell centred on a table sample that lies in the
    // domain [0, 1]: a border entry's cell is half outside it (a corner's
    // three quarters), where nothing is painted, so averaging the whole cell
    // would mix in the background that no N inside the domain ever sees.
    const auto span = [cell](double x) {
        const double lo = std::max(0.0, x - 0.5 * cell), hi = std::min(1.0, x + 0.5 * cell);
        return std::array<double, 2>{lo, hi - lo};
    };
    return tabulate(resolution, [&](double x, double y) {
        // Average over the cell centred on the table sample, within the domain.
        const std::array<double, 2> sx = span(x), sy = span(y);
        Rgb sum{0, 0, 0};
        for (int sj = 0; sj < supersampling; ++sj)
            for (int si = 0; si < supersampling; ++si) {
                const Rgb c =
                    evaluate(sx[0] + (si + 0.5) / supersampling * sx[1], sy[0] + (sj + 0.5) / supersampling * sy[1]);
                for (int k = 0; k < 3; ++k) sum[size_t(k)] += c[size_t(k)];
            }
        const float inv = 1.0f / float(supersampling * supersampling);
        return Rgb{sum[0] * inv, sum[1] * inv, sum[2] * inv};
    });
}

ColormapTable foldInverseTransforms(const ColormapTable& h, const NoiseExample* x, const NoiseExample* y) {
    const bool foldX = x && x->gaussianized(), foldY = y && y->gaussianized();
    if (!foldX && !foldY) return h;
    Image t(h.resolutionX(), h.resolutionY(), 3, Image::Uninitialized{});
    for (int j = 0; j < t.height(); ++j)
        for (int i = 0; i < t.width(); ++i) {
            const float a = float(i) / float(t.width() - 1), b = float(j) / float(t.height() - 1);
            const Rgb c = h.sample(foldX ? x->toOutput(a) : a, foldY ? y->toOutput(b) : b);
            for (int k = 0; k < 3; ++k) t.at(i, j, k) = c[size_t(k)];
        }
    return ColormapTable(t);
}

}  // namespace stochtex
