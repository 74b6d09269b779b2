#include "stochtex/pattern/prefiltered_colormap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stochtex/core/parallel.h"
#include "stochtex/noise/normal.h"

namespace stochtex {

namespace {

// One output entry of a 1D Gaussian blur: the input entries it reads
// (already clamped to the table) and their normalised weights.
struct Tap {
    int index;
    double weight;
};

// ∫_L^U (α + βx) N(x; c, s²) dx.
double linearMoment(double lo, double hi, double alpha, double beta, double c, double s) {
    const double zl = (lo - c) / s, zh = (hi - c) / s;
    const double p = normalCdf(zh) - normalCdf(zl);
    const double q = std::exp(-0.5 * zh * zh) - std::exp(-0.5 * zl * zl);  // × 1/√(2π) below
    return alpha * p + beta * (c * p - s * q * 0.3989422804014327);
}

// Weights for blurring n entries by σ (domain units) and resampling to `out`
// entries at i/(out−1). The table is read as the piecewise-linear function
// bilinear lookups see, extended by its end values (clamp-to-edge), so each
// weight is the Gaussian integral of that entry's hat function: the result
// is the exact convolution [H ∗ G_σ], not a discrete approximation.
// σ = 0 degenerates to linear interpolation.
std::vector<std::vector<Tap>> blurTaps(int n, double sigma, int out) {
    std::vector<std::vector<Tap>> taps(static_cast<size_t>(out));
    const double scale = double(n - 1) / double(out - 1);
    const double s = sigma * double(n - 1);  // σ in entries
    const double inf = 1e300;
    for (int i = 0; i < out; ++i) {
        const double c = i * scale;
        auto& t = taps[size_t(i)];
        if (s <= 0.0) {
            const int j = std::min(int(c), n - 2);
            const double f = c - j;
            t.push_back({j, 1.0 - f});
            t.push_back({j + 1, f});
            continue;
        }
        // ±5σ: the Gaussian mass left out (< 6e-7) is below float precision.
        const int lo = std::max(0, int(std::floor(c - 5.0 * s)) - 1);
        const int hi = std::min(n - 1, int(std::ceil(c + 5.0 * s)) + 1);
        std::vector<double> w;
        double sum = 0;
        for (int j = lo; j <= hi; ++j) {
            const double left = j == 0 ? linearMoment(-inf, 0.0, 1.0, 0.0, c, s)
                                       : linearMoment(j - 1.0, double(j), 1.0 - j, 1.0, c, s);
            const double right = j == n - 1 ? linearMoment(double(j), inf, 1.0, 0.0, c, s)
                                            : linearMoment(double(j), j + 1.0, 1.0 + j, -1.0, c, s);
            w.push_back(left + right);
            sum += w.back();
        }
        for (int j = lo; j <= hi; ++j) t.push_back({j, w[size_t(j - lo)] / sum});
    }
    return taps;
}

using TapTable = std::vector<std::vector<Tap>>;

// Blurs an RGB grid along x with precomputed taps (one list per output column).
Image blurRows(const Image& in, const TapTable& taps) {
    Image res(int(taps.size()), in.height(), 3, Image::Uninitialized{});
    parallelRows(res.height(), [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float* row = in.row(y);
            float* q = res.row(y);
            for (size_t x = 0; x < taps.size(); ++x) {
                // Double accumulation: wide blurs sum hundreds of taps.
                double acc[3] = {0, 0, 0};
                for (const Tap& t : taps[x]) {
                    const float* p = row + size_t(t.index) * 3;
                    acc[0] += t.weight * p[0];
                    acc[1] += t.weight * p[1];
                    acc[2] += t.weight * p[2];
                }
                q[3 * x] = float(acc[0]);
                q[3 * x + 1] = float(acc[1]);
                q[3 * x + 2] = float(acc[2]);
            }
        }
    });
    return res;
}

// Blurs along y (one tap list per output row): whole input rows are scaled
// and added, which streams through memory and vectorises.
Image blurColumns(const Image& in, const TapTable& taps) {
    Image res(in.width(), int(taps.size()), 3, Image::Uninitialized{});
    const size_t n = size_t(in.width()) * 3;
    parallelRows(res.height(), [&](int y0, int y1) {
        std::vector<double> acc(n);
        for (int y = y0; y < y1; ++y) {
            std::fill(acc.begin(), acc.end(), 0.0);
            for (const Tap& t : taps[size_t(y)]) {
                const float* row = in.row(t.index);
                for (size_t i = 0; i < n; ++i) acc[i] += t.weight * row[i];
            }
            float* q = res.row(y);
            for (size_t i = 0; i < n; ++i) q[i] = float(acc[i]);
        }
    });
    return res;
}

// Entries kept along an axis blurred by σ: all of them until the blur spans
// 8 entries, then halved per doubling of σ so that σ stays ≥ 4 entries.
int storedResolution(int n, double sigma) {
    const double s = sigma * double(n - 1);
    if (s < 8.0) return n;
    const double f = std::exp2(std::floor(std::log2(s / 4.0)));
    return std::clamp(int(std::ceil(double(n - 1) / f)) + 1, 8, n);
}

}  // namespace

std::vector<double> PrefilteredColormap::sigmaLevels(PrefilterMode mode) {
    std::vector<double> s;
    if (mode == PrefilterMode::Smooth) s.push_back(0.0);
    const int top = mode == PrefilterMode::Paper ? 5 : 8;
    for (int k = 0; k <= top; ++k) s.push_back(std::exp2(k) / 256.0);
    return s;
}

PrefilteredColormap::PrefilteredColormap(const ColormapTable& h, PrefilterMode mode)
    : mode_(mode), sigmas_(sigmaLevels(mode)) {
    const Image base = h.table();
    // Tap tables depend only on (axis, σ level): build each once.
    std::vector<TapTable> tapsY;
    for (double sy : sigmas_) tapsY.push_back(blurTaps(base.height(), sy, storedResolution(base.height(), sy)));
    layers_.reserve(sigmas_.size() * sigmas_.size());
    for (double sx : sigmas_) {
        const Image bx = blurRows(base, blurTaps(base.width(), sx, storedResolution(base.width(), sx)));
        for (const TapTable& ty : tapsY) layers_.emplace_back(blurColumns(bx, ty));
    }
}

float PrefilteredColormap::levelCoordinate(float sigma) const {
    const float top = float(sigmas_.size() - 1);
    const float s256 = std::max(sigma, 0.0f) * 256.0f;
    if (mode_ == PrefilterMode::Paper) {
        // Nearest level in log2 σ; below 1/256 the finest level.
        if (s256 <= 1.0f) return 0.0f;
        return std::min(std::round(std::log2(s256)), top);
    }
    // Level 0 is σ = 0, level k ≥ 1 is 2^(k−1)/256.
    const float c = s256 <= 1.0f ? s256 : 1.0f + std::log2(s256);
    return std::min(c, top);
}

Rgb PrefilteredColormap::sample(float mx, float my, float sx, float sy) const {
    const float cx = levelCoordinate(sx), cy = levelCoordinate(sy);
    const int n = int(sigmas_.size());
    const int x0 = std::min(int(cx), n - 1), y0 = std::min(int(cy), n - 1);
    const float fx = cx - float(x0), fy = cy - float(y0);
    if (fx == 0.0f && fy == 0.0f) return layer(x0, y0).sample(mx, my);
    const int x1 = std::min(x0 + 1, n - 1), y1 = std::min(y0 + 1, n - 1);
    const Rgb a = layer(x0, y0).sample(mx, my), b = layer(x1, y0).sample(mx, my);
    const Rgb c = layer(x0, y1).sample(mx, my), d = layer(x1, y1).sample(mx, my);
    Rgb out;
    for (size_t k = 0; k < 3; ++k) {
        const float top = a[k] + fx * (b[k] - a[k]);
        const float bottom = c[k] + fx * (d[k] - c[k]);
        out[k] = top + fy * (bottom - top);
    }
    return out;
}

size_t PrefilteredColormap::bytes() const {
    size_t b = 0;
    for (const auto& l : layers_) b += l.bytes();
    return b;
}

Rgb convolveColormapNumerically(const ColormapTable& h, double mx, double my, double sx, double sy, int steps) {
    // Separable Gaussian weights on a uniform grid over ±6σ (a Dirac for σ = 0).
    auto nodes = [&](double m, double s) {
        std::vector<std::pair<double, double>> v;
        if (s <= 0) return std::vector<std::pair<double, double>>{{m, 1.0}};
        double sum = 0;
        for (int i = 0; i < steps; ++i) {
            const double t = -6.0 + 12.0 * (i + 0.5) / steps;
            v.push_back({std::clamp(m + s * t, 0.0, 1.0), std::exp(-0.5 * t * t)});
            sum += v.back().second;
        }
        for (auto& p : v) p.second /= sum;
        return v;
    };
    const auto nx = nodes(mx, sx), ny = nodes(my, sy);
    double acc[3] = {0, 0, 0};
    for (const auto& [y, wy] : ny)
        for (const auto& [x, wx] : nx) {
            const Rgb c = h.sample(float(x), float(y));
            for (int k = 0; k < 3; ++k) acc[k] += wx * wy * c[size_t(k)];
        }
    return {float(acc[0]), float(acc[1]), float(acc[2])};
}

}  // namespace stochtex
