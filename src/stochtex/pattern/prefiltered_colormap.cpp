#include "stochtex/pattern/prefiltered_colormap.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/kernel/sigma_levels.h"
#include "stochtex/noise/normal.h"

namespace stochtex {

namespace {

// One output entry of a 1D Gaussian blur: the input entries it reads
// (already clamped to the table) and their normalised weights.
struct Tap {
    int index;
    double weight;
};

// Weights for blurring n entries by σ (domain units) and resampling to `out`
// entries at i/(out−1). The table is read as the piecewise-linear function
// bilinear lookups see, extended by its end values (clamp-to-edge), so each
// weight is the Gaussian integral of that entry's hat function: the result
// is the exact convolution [H ∗ G_σ], not a discrete approximation.
// σ = 0 degenerates to linear interpolation.
//
// With z_k = (k − c)/s, P_k = Φ(z_k), Q_k = φ(z_k), the integral of the
// rising half of hat j over [j−1, j] is (1 − j + c)(P_j − P_{j−1}) − s(Q_j − Q_{j−1}),
// and of the falling half over [j, j+1] is (1 + j − c)(P_{j+1} − P_j) + s(Q_{j+1} − Q_j);
// the end entries add the half-lines Φ(z_0) and 1 − Φ(z_{n−1}). Φ and φ are
// evaluated once per lattice node.
std::vector<std::vector<Tap>> blurTaps(int n, double sigma, int out) {
    std::vector<std::vector<Tap>> taps(static_cast<size_t>(out));
    const double scale = double(n - 1) / double(out - 1);
    const double s = sigma * double(n - 1);  // σ in entries
    std::vector<double> P, Q;
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
        P.assign(size_t(hi - lo + 3), 0.0);
        Q.assign(P.size(), 0.0);
        for (int k = lo - 1; k <= hi + 1; ++k) {  // nodes lo−1 … hi+1
            const double z = (k - c) / s;
            P[size_t(k - lo + 1)] = normalCdf(z);
            Q[size_t(k - lo + 1)] = 0.3989422804014327 * std::exp(-0.5 * z * z);
        }
        auto node = [&](int k, const std::vector<double>& v) { return v[size_t(k - lo + 1)]; };
        std::vector<double> w;
        double sum = 0;
        for (int j = lo; j <= hi; ++j) {
            const double rising =
                j == 0 ? node(0, P) : (1.0 - j + c) * (node(j, P) - node(j - 1, P)) - s * (node(j, Q) - node(j - 1, Q));
            const double falling =
                j == n - 1 ? 1.0 - node(j, P)
                           : (1.0 + j - c) * (node(j + 1, P) - node(j, P)) + s * (node(j + 1, Q) - node(j, Q));
            w.push_back(rising + falling);
            sum += w.back();
        }
        for (int j = lo; j <= hi; ++j) t.push_back({j, w[size_t(j - lo)] / sum});
    }
    return taps;
}

using TapTable = std::vector<std::vector<Tap>>;

// acc[i] += Σ_k weights[k]·rows[k][i] for i < n, the sum over k in float.
// A block of 48 columns stays in registers while every row is added to it
// (six independent sums hide the latency of the adds).
// On x86-64 an AVX2 clone is chosen at load time where the CPU has it; both
// clones do the same IEEE multiplies and adds per lane (no FMA), so tables
// are bit-identical on every machine.
#if defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void accumulateRows(const float* const* rows, const float* weights, size_t count, size_t n, double* acc) {
    typedef float Float8 __attribute__((vector_size(32)));
    typedef double Double8 __attribute__((vector_size(64)));
    constexpr size_t kSums = 6, kBlock = 8 * kSums;
    const size_t blocked = n - n % kBlock;
    for (size_t i = 0; i < blocked; i += kBlock) {
        Float8 p[kSums] = {};
        for (size_t k = 0; k < count; ++k) {
            const float w = weights[k];
            for (size_t q = 0; q < kSums; ++q) {
                Float8 r;
                std::memcpy(&r, rows[k] + i + 8 * q, sizeof r);
                p[q] += w * r;
            }
        }
        for (size_t q = 0; q < kSums; ++q) {
            Double8 a;
            std::memcpy(&a, acc + i + 8 * q, sizeof a);
            a += __builtin_convertvector(p[q], Double8);
            std::memcpy(acc + i + 8 * q, &a, sizeof a);
        }
    }
    for (size_t i = blocked; i < n; ++i) {
        float p = 0.0f;
        for (size_t k = 0; k < count; ++k) p += weights[k] * rows[k][i];
        acc[i] += double(p);
    }
}

// Blurs along y (one tap list per output row): input rows are scaled and
// added, which vectorises. Taps are summed in float in groups of 16 and the
// groups in double, which keeps wide blurs (hundreds of taps) accurate to
// ~1e-7. The columns are processed in strips of 192 floats so that a strip of
// every input row (≤ 256 × 768 bytes) stays in L2 while the output rows that
// read it are made: wide blurs read every input row for every output row.
Image blurColumns(const Image& in, const TapTable& taps) {
    constexpr size_t kStrip = 192;
    Image res(in.width(), int(taps.size()), 3, Image::Uninitialized{});
    const size_t n = size_t(in.width()) * 3;
    parallelRows(res.height(), [&](int y0, int y1) {
        std::array<double, kStrip> acc;
        std::array<const float*, 16> rows;
        std::array<float, 16> weights;
        for (size_t c0 = 0; c0 < n; c0 += kStrip) {
            const size_t width = std::min(kStrip, n - c0);
            for (int y = y0; y < y1; ++y) {
                std::fill(acc.begin(), acc.begin() + ptrdiff_t(width), 0.0);
                const auto& list = taps[size_t(y)];
                for (size_t g = 0; g < list.size(); g += 16) {
                    const size_t count = std::min<size_t>(16, list.size() - g);
                    for (size_t k = 0; k < count; ++k) {
                        rows[k] = in.row(list[g + k].index) + c0;
                        weights[k] = float(list[g + k].weight);
                    }
                    accumulateRows(rows.data(), weights.data(), count, width, acc.data());
                }
                float* q = res.row(y) + c0;
                for (size_t i = 0; i < width; ++i) q[i] = float(acc[i]);
            }
        }
    });
    return res;
}

// Swaps x and y of an RGB grid.
Image transposed(const Image& in) {
    Image out(in.height(), in.width(), 3, Image::Uninitialized{});
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x)
            for (int c = 0; c < 3; ++c) out.at(y, x, c) = in.at(x, y, c);
    return out;
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

void validatePrefilteredResolution(int width, int height) {
    if (width > kMaxPrefilteredResolution || height > kMaxPrefilteredResolution)
        throw InputError::parameter("resolution", "must be at most " + std::to_string(kMaxPrefilteredResolution) +
                                                      " per side to be prefiltered, got " + std::to_string(width) +
                                                      "x" + std::to_string(height));
}

PrefilteredColormap::PrefilteredColormap(const ColormapTable& h, PrefilterMode mode)
    : mode_(mode), sigmas_(sigmaLevels(mode)) {
    validatePrefilteredResolution(h.resolutionX(), h.resolutionY());
    const Image base = h.table();
    // The x blur runs as a y blur of the transposed table (streams rows).
    const Image baseT = transposed(base);
    const size_t levels = sigmas_.size();
    // Tap tables depend only on (axis, σ level): build each once.
    std::vector<TapTable> tapsX, tapsY;
    auto taps = [](const TapTable& t) {
        size_t n = 0;
        for (const auto& row : t) n += row.size();
        return n;
    };
    for (double s : sigmas_) {
        tapsX.push_back(blurTaps(base.width(), s, storedResolution(base.width(), s)));
        // Square tables (the usual case) share the x taps.
        tapsY.push_back(base.height() == base.width() ? tapsX.back()
                                                      : blurTaps(base.height(), s, storedResolution(base.height(), s)));
    }
    // The blurs along x and y commute, so each layer takes the order whose
    // second pass is cheaper: the wide blur runs first, on one shared
    // intermediate per σ level, and the narrow one per layer. The second
    // pass reads taps(second axis) × entries kept along the first axis.
    std::vector<Image> blurredX(levels), blurredYT(levels);  // xT: stored transposed
    for (size_t k = 0; k < levels; ++k) {
        blurredX[k] = transposed(blurColumns(baseT, tapsX[k]));
        blurredYT[k] = transposed(blurColumns(base, tapsY[k]));
    }
    layers_.reserve(levels * levels);
    for (size_t kx = 0; kx < levels; ++kx)
        for (size_t ky = 0; ky < levels; ++ky) {
            const size_t xThenY = tapsX[kx].size() * taps(tapsY[ky]);
            const size_t yThenX = tapsY[ky].size() * taps(tapsX[kx]);
            layers_.emplace_back(xThenY <= yThenX ? blurColumns(blurredX[kx], tapsY[ky])
                                                  : transposed(blurColumns(blurredYT[ky], tapsX[kx])));
        }
}

// The level coordinates and the blend of the layers are the kernel's
// (kernel/sigma_levels.glsl), as in the shaders.
float PrefilteredColormap::levelCoordinate(float sigma) const {
    return kernel::sigmaLevelCoordinate(sigma, mode_ == PrefilterMode::Paper, int(sigmas_.size()));
}

Rgb PrefilteredColormap::sample(float mx, float my, float sx, float sy) const {
    const kernel::LayerBlend b =
        kernel::layerBlend(kernel::vec2(sx, sy), mode_ == PrefilterMode::Paper, int(sigmas_.size()));
    if (b.f.x == 0.0f && b.f.y == 0.0f) return layer(b.k0.x, b.k0.y).sample(mx, my);
    const auto at = [&](int kx, int ky) {
        const Rgb c = layer(kx, ky).sample(mx, my);
        return kernel::vec3(c[0], c[1], c[2]);
    };
    const kernel::vec3 c =
        kernel::layerMix(at(b.k0.x, b.k0.y), at(b.k1.x, b.k0.y), at(b.k0.x, b.k1.y), at(b.k1.x, b.k1.y), b.f);
    return {c.x, c.y, c.z};
}

Image PrefilteredColormap::atlas(int rx, int ry) const {
    const int n = int(sigmas_.size());
    Image out(rx, ry * n * n, 3, Image::Uninitialized{});
    // The layers shared among the worker threads (tens of MB per table: a
    // workbench edit of the colormap waits). A coarser layer is resampled
    // as ColormapTable::sample does, separably: each stored row along x
    // once, then each output row as the blend of two of those — the same
    // float operations in the same order per entry (bit-identical, tested),
    // without the taps and four fetches of every entry.
    parallelRows(n * n, [&](int l0, int l1) {
        std::vector<float> across;  // the layer's stored rows at rx entries
        for (int l = l0; l < l1; ++l) {
            const ColormapTable& t = layer(l / n, l % n);
            const int w = t.resolutionX(), h = t.resolutionY();
            if (w == rx && h == ry) {
                for (int j = 0; j < ry; ++j) {
                    float* row = out.row(l * ry + j);
                    for (int i = 0; i < rx; ++i) {
                        const Rgb c = t.entry(i, j);
                        std::copy(c.begin(), c.end(), row + 3 * i);
                    }
                }
                continue;
            }
            across.resize(size_t(h) * size_t(rx) * 3);
            for (int i = 0; i < rx; ++i) {
                const kernel::TableTap tx = kernel::tableTap(float(i) / float(rx - 1), w);
                for (int r = 0; r < h; ++r) {
                    const Rgb a = t.entry(tx.i, r), b = t.entry(tx.i + 1, r);
                    float* q = &across[(size_t(r) * size_t(rx) + size_t(i)) * 3];
                    for (int c = 0; c < 3; ++c) q[c] = a[size_t(c)] + tx.t * (b[size_t(c)] - a[size_t(c)]);
                }
            }
            for (int j = 0; j < ry; ++j) {
                const kernel::TableTap ty = kernel::tableTap(float(j) / float(ry - 1), h);
                const float* bottom = &across[size_t(ty.i) * size_t(rx) * 3];
                const float* top = bottom + size_t(rx) * 3;
                float* row = out.row(l * ry + j);
                for (size_t k = 0; k < size_t(rx) * 3; ++k) row[k] = bottom[k] + ty.t * (top[k] - bottom[k]);
            }
        }
    });
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
