#include "stochtex/pattern/prefiltered_colormap.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <boost/math/distributions/beta.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/kernel/sigma_levels.h"
#include "stochtex/noise/normal.h"
#include "stochtex/noise/tiling_blending_lanes.h"
#include "stochtex/pattern/texel_pairs.h"

namespace stochtex {

namespace {

// One output entry of a 1D Gaussian blur: the input entries it reads
// (already clamped to the table) and their normalised weights.
struct Tap {
    int index;
    double weight;
};

// Taps of the linear interpolation of n entries at entry coordinate c ∈ [0, n − 1]: a blur of 0.
std::vector<Tap> interpolationTaps(int n, double c) {
    const int j = std::min(int(c), n - 2);
    const double f = c - j;
    return {{j, 1.0 - f}, {j + 1, f}};
}

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
            t = interpolationTaps(n, c);
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

// Weights for averaging n entries under a Beta distribution, per output
// entry i of `out` at mean m = i/(out−1), with shape ν = 4τ² (kernel
// betaLevelCoordinate): α = m(1/ν − 1), β = (1 − m)(1/ν − 1). The Beta lives on
// [0, 1], the table's domain, so there is no edge to clamp. As for
// blurTaps, each weight is the exact integral of the entry's hat function
// under the density, from the regularised incomplete beta function
// F(x) = I_x(α, β) and the partial first moment G(x) = ∫₀ˣ t f(t) dt =
// m·I_x(α + 1, β) at the lattice nodes x_k = k/(n − 1) (spacing h):
//   rising half of hat j:  ((G_j − G_{j−1}) − x_{j−1}(F_j − F_{j−1}))/h,
//   falling half:          (x_{j+1}(F_{j+1} − F_j) − (G_{j+1} − G_j))/h.
// Boost.Math's ibeta (Debian libboost-math-dev) computes F to double
// precision for the small α or β of a skewed Beta near a table's end,
// where a quadrature of the singular density would not. Nodes where F is
// within 1e-12 of 0 or 1 are found by bisection and skipped. A wide Beta
// (deviation ≥ 16 node spacings) reads every node, which would make a
// large table's build quadratic in ibeta calls (seconds at 1024 entries):
// there F steps from node to node by 4-point Gauss–Legendre quadrature of
// the density, which is smooth away from the ends (relative error below
// 1e-12 over a spacing ≤ 1/16 of its deviation), and ibeta is kept at the
// 8 nodes next to each end, where the density may be singular, and every
// 64th node, which bounds the accumulated rounding.
std::vector<std::vector<Tap>> betaTaps(int n, double tau, int out) {
    std::vector<std::vector<Tap>> taps(static_cast<size_t>(out));
    const double nu = 4.0 * tau * tau, h = 1.0 / double(n - 1);
    const auto x = [&](int k) { return double(k) * h; };
    // Entries are independent: each thread fills its own (the same taps for any thread count).
    parallelRows(out, [&](int i0, int i1) {
        std::vector<double> F, G;
        for (int i = i0; i < i1; ++i) {
            const double m = double(i) / double(out - 1);
            auto& t = taps[size_t(i)];
            if (nu <= 0.0 || i == 0 || i == out - 1) {  // a point: at m, or at an end of the table
                t = interpolationTaps(n, double(i) * double(n - 1) / double(out - 1));  // as blurTaps's
                continue;
            }
            if (nu >= 1.0) {  // the limit of a Beta of this mean: spikes at 0 and 1
                t = {{0, 1.0 - m}, {n - 1, m}};
                continue;
            }
            const double shape = 1.0 / nu - 1.0, a = m * shape, b = (1.0 - m) * shape;
            const auto cdf = [&](int k) { return boost::math::ibeta(a, b, x(k)); };
            // Boost's lgamma: std::lgamma writes the global signgam, a race between the rows' threads.
            const double logBeta = boost::math::lgamma(a) + boost::math::lgamma(b) - boost::math::lgamma(a + b);
            const auto density = [&](double v) {
                return std::exp((a - 1.0) * std::log(v) + (b - 1.0) * std::log1p(-v) - logBeta);
            };
            const bool wide = std::sqrt(nu * m * (1.0 - m)) >= 16.0 * h;
            const auto stepped = [&](int k) {  // F(x_k) − F(x_{k−1}) by quadrature
                constexpr double node[2] = {0.3399810435848563, 0.8611363115940526};
                constexpr double weight[2] = {0.6521451548625461, 0.3478548451374538};
                const double mid = x(k) - 0.5 * h;
                double sum = 0;
                for (int q = 0; q < 2; ++q)
                    sum += weight[q] * (density(mid - 0.5 * h * node[q]) + density(mid + 0.5 * h * node[q]));
                return 0.5 * h * sum;
            };
            // The first node with F > 1e-12 and the first with F > 1 − 1e-12 (F
            // is non-decreasing): the mass outside [lo, hi] is below that.
            const auto firstAbove = [&](double level) {
                int lo = 0, hi = n - 1;
                while (lo < hi) {
                    const int mid = (lo + hi) / 2;
                    if (cdf(mid) > level)
                        hi = mid;
                    else
                        lo = mid + 1;
                }
                return lo;
            };
            const int lo = std::max(firstAbove(1e-12) - 1, 0), hi = std::max(firstAbove(1.0 - 1e-12), lo + 1);
            F.resize(size_t(hi - lo + 1));
            G.resize(F.size());
            for (int k = lo; k <= hi; ++k) {
                const double xk = x(k);
                const bool exact = !wide || k == lo || k <= 8 || k >= n - 9 || k % 64 == 0;
                F[size_t(k - lo)] = exact ? cdf(k) : F[size_t(k - lo - 1)] + stepped(k);
                // I_x(α + 1, β) = I_x(α, β) − x^α (1 − x)^β / (α B(α, β)), the last
                // term x(1 − x) f(x)/α with f the density.
                const double tail = xk <= 0.0 || xk >= 1.0 ? 0.0 : xk * (1.0 - xk) * density(xk) / a;
                G[size_t(k - lo)] = m * (F[size_t(k - lo)] - tail);
            }
            double sum = 0;
            for (int j = lo; j <= hi; ++j) {
                const size_t q = size_t(j - lo);
                double w = 0;
                if (j > lo) w += ((G[q] - G[q - 1]) - x(j - 1) * (F[q] - F[q - 1])) / h;
                if (j < hi) w += (x(j + 1) * (F[q + 1] - F[q]) - (G[q + 1] - G[q])) / h;
                t.push_back({j, w});
                sum += w;
            }
            for (Tap& tap : t) tap.weight /= sum;
        }
    });
    return taps;
}

using TapTable = std::vector<std::vector<Tap>>;

// The loops below on 32-byte vectors of the GCC extension are compiled
// twice, for AVX2 and for the baseline (texel_pairs.h).
using texel_pairs::useAvx2Compilation;

// acc[i] += Σ_k weights[k]·rows[k][i] for i < n, the sum over k in float.
// A block of 48 columns stays in registers while every row is added to it
// (six independent sums hide the latency of the adds).
[[gnu::always_inline]] inline void accumulateRowsBody(const float* const* rows, const float* weights, size_t count,
                                                      size_t n, double* acc) {
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
STOCHTEX_AVX2_COMPILATION void accumulateRowsAvx2(const float* const* rows, const float* weights, size_t count,
                                                  size_t n, double* acc) {
    accumulateRowsBody(rows, weights, count, n, acc);
}
void accumulateRowsBaseline(const float* const* rows, const float* weights, size_t count, size_t n, double* acc) {
    accumulateRowsBody(rows, weights, count, n, acc);
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
    const auto accumulateRows = useAvx2Compilation() ? accumulateRowsAvx2 : accumulateRowsBaseline;
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

// Entries kept along an axis of n blurred by σ (in table coordinates, the
// axis spanning [0, 1]): halved while σ stays ≥ 4 of the kept entries'
// spacings, i.e. σ·(kept − 1) ≥ 4, and never fewer than 8.
int storedResolution(int n, double sigma) {
    int kept = n;
    for (int f = 2; f < n; f *= 2) {
        const int halved = std::max(int(std::ceil(double(n - 1) / double(f))) + 1, 8);
        if (halved >= kept || sigma * double(halved - 1) < 4.0) break;
        kept = halved;
    }
    return kept;
}

}  // namespace

std::vector<double> PrefilteredColormap::sigmaLevels(PrefilterMode mode) {
    std::vector<double> s;
    if (mode == PrefilterMode::Smooth) s.push_back(0.0);
    const int top = mode == PrefilterMode::Paper ? 5 : 8;
    for (int k = 0; k <= top; ++k) s.push_back(std::exp2(k) / 256.0);
    return s;
}

std::vector<double> PrefilteredColormap::betaLevels(PrefilterMode mode) {
    if (mode == PrefilterMode::Paper) return sigmaLevels(mode);
    std::vector<double> s{0.0};
    for (int k = 0; k <= 6; ++k) s.push_back(std::exp2(k) / 256.0);
    s.push_back(std::sqrt(2.0) / 4.0);
    s.push_back(0.5);
    return s;
}

void validatePrefilteredResolution(int width, int height) {
    if (width > kMaxPrefilteredResolution || height > kMaxPrefilteredResolution)
        throw InputError::parameter("resolution", "must be at most " + std::to_string(kMaxPrefilteredResolution) +
                                                      " per side to be prefiltered, got " + std::to_string(width) +
                                                      "x" + std::to_string(height));
}

PrefilteredColormap::PrefilteredColormap(const ColormapTable& h, PrefilterMode mode, BetaAxes beta)
    : mode_(mode), beta_(beta), sigmas_(sigmaLevels(mode)), betaLevels_(betaLevels(mode)) {
    validatePrefilteredResolution(h.resolutionX(), h.resolutionY());
    // The layers' size before any work: a Beta axis keeps every entry at each
    // level, so two of them at 1024² would take 1600 MiB.
    if (const size_t bytes = layerBytes(h.resolutionX(), h.resolutionY(), mode, beta); bytes > kMaxPrefilteredBytes)
        throw InputError::parameter(
            "resolution", "a " + std::to_string(h.resolutionX()) + "x" + std::to_string(h.resolutionY()) + " table" +
                              (beta[0] || beta[1] ? " read by bounded fields (Beta axes keep every entry)" : "") +
                              " would take " + std::to_string(bytes >> 20) + " MiB prefiltered, more than " +
                              std::to_string(kMaxPrefilteredBytes >> 20) + " MiB: lower the table's resolution");
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
    // A Beta axis keeps all its entries: its blur is narrow near the ends.
    const auto axisTaps = [](int n, double s, bool betaAxis) {
        return betaAxis ? betaTaps(n, s, n) : blurTaps(n, s, storedResolution(n, s));
    };
    for (size_t k = 0; k < levels; ++k) {
        tapsX.push_back(axisTaps(base.width(), axisLevels(0)[k], beta_[0]));
        // Square tables (the usual case) share the x taps.
        tapsY.push_back(base.height() == base.width() && beta_[0] == beta_[1]
                            ? tapsX.back()
                            : axisTaps(base.height(), axisLevels(1)[k], beta_[1]));
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
    for (const ColormapTable& l : layers_) layerTexels_.push_back(l.texels());
    for (size_t k = 0; k < levels; ++k) {
        widths_.push_back(layer(int(k), 0).resolutionX());
        heights_.push_back(layer(0, int(k)).resolutionY());
    }
    for (size_t kx = 0; kx < levels; ++kx)
        for (size_t ky = 0; ky < levels; ++ky)
            if (layer(int(kx), int(ky)).resolutionX() != widths_[kx] ||
                layer(int(kx), int(ky)).resolutionY() != heights_[ky])
                throw std::logic_error("PrefilteredColormap: a layer's size depends on the other axis's level");
}

// The level coordinates and the blend of the layers are the kernel's
// (kernel/sigma_levels.glsl), as in the shaders.
PrefilteredColormap::Lookup PrefilteredColormap::find(float mx, float my, float sx, float sy) const {
    const kernel::LayerBlend b =
        kernel::tableLayerBlend(kernel::vec2(mx, my), kernel::vec2(sx, sy), kernel::ivec2(beta_[0], beta_[1]),
                                mode_ == PrefilterMode::Paper, int(sigmas_.size()));
    Lookup l;
    l.single = b.f.x == 0.0f && b.f.y == 0.0f;
    l.f = b.f;
    l.layers = {&layer(b.k0.x, b.k0.y), &layer(b.k1.x, b.k0.y), &layer(b.k0.x, b.k1.y), &layer(b.k1.x, b.k1.y)};
    for (size_t i = 0; i < (l.single ? 1 : 4); ++i) l.taps[i] = l.layers[i]->taps(mx, my);
    return l;
}

Rgb PrefilteredColormap::blend(const Lookup& l) const {
    if (l.single) return l.layers[0]->blend(l.taps[0]);
    kernel::vec3 at[4];
    for (size_t i = 0; i < 4; ++i) {
        const Rgb e = l.layers[i]->blend(l.taps[i]);
        at[i] = kernel::vec3(e[0], e[1], e[2]);
    }
    const kernel::vec3 c = kernel::layerMix(at[0], at[1], at[2], at[3], l.f);
    return {c.x, c.y, c.z};
}

Rgb PrefilteredColormap::sample(float mx, float my, float sx, float sy) const { return blend(find(mx, my, sx, sy)); }

size_t PrefilteredColormap::sampleRow(const float* mx, const float* my, const float* sx, const float* sy, float* rgb,
                                      size_t count) const {
    constexpr size_t kChunk = LayerTapsLanes::kCapacity;  // pixels whose layers and taps the lanes find at once
    const bool lanes = !beta_[0] && !beta_[1];
    // A row without deviations: the same taps and blend as below, without
    // the per-pixel assembly and look-ahead that blends across layers need.
    const auto zero = [](float s) { return s == 0.0f; };
    if (lanes && std::all_of(sx, sx + count, zero) && std::all_of(sy, sy + count, zero))
        return sampleRowWithoutDeviations(mx, my, rgb, count);
    if (!lanes) {
        lookupRow(mx, my, sx, sy, rgb, count);
        return 0;
    }
    // The lanes' output, kept per thread: sampleRow runs once per row.
    thread_local LayerTapsLanes found;
    size_t inLanes = 0;
    for (size_t k = 0; k < count; k += kChunk) {
        const size_t n = std::min(kChunk, count - k);
        const size_t done = layerTapsLanes(mx + k, my + k, sx + k, sy + k, n, mode_ == PrefilterMode::Paper,
                                           int(sigmas_.size()), widths_.data(), heights_.data(), found);
        blendFound(found, done, rgb + k * 3);
        // The last partial vector, which the lanes leave.
        lookupRow(mx + k + done, my + k + done, sx + k + done, sy + k + done, rgb + (k + done) * 3, n - done);
        inLanes += done;
    }
    return inLanes;
}

namespace {

// Pixels between a lookup's prefetch and its blend.
constexpr size_t kAhead = ColormapTable::kPrefetchAhead;

// Pixel k's lookup found (its entries prefetched) at step k and blended at
// step k + kAhead, through a ring of kAhead slots: find(k, slot) for
// k < count, then blend(k, slot) with the same slot. Inlined with both
// steps, so that an AVX2 compilation keeps them in its registers.
template <class Find, class Blend>
[[gnu::always_inline]] inline void lookAhead(size_t count, Find&& find, Blend&& blend) {
    for (size_t k = 0; k < count + kAhead; ++k) {
        if (k >= kAhead) blend(k - kAhead, (k - kAhead) % kAhead);
        if (k < count) find(k, k % kAhead);
    }
}

using Texel = ColormapTable::Texel;
using texel_pairs::blendTexelPair, texel_pairs::pairOf, texel_pairs::TexelPair;
using texel_pairs::highOf, texel_pairs::lowOf;

// The lanes' lookups blended, pixel by pixel: each pixel's corners found
// and their entries prefetched kAhead pixels before its blend (a lookup
// reads up to four layers of up to a megabyte each, beyond a core's L2),
// then the layers blended two at a time, (x0,y0) beside (x1,y0) and (x0,y1)
// beside (x1,y1), and mixed as PrefilteredColormap::blend mixes them.
// layers: layer (kx, ky)'s entries at kx·levels + ky.
[[gnu::always_inline]] inline void blendLayerTapsBody(const LayerTapsLanes& found, size_t count,
                                                      const Texel* const* layers, float* rgb) {
    // The corners of a pixel's four layers, (x0,y0), (x1,y0), (x0,y1), (x1,y1).
    std::array<std::array<const Texel*, 4>, kAhead> ring;
    const auto find = [&](size_t k, size_t slot) __attribute__((always_inline)) {
        std::array<const Texel*, 4>& at = ring[slot];
        at[0] = layers[found.layer00[k]] + found.entry00[k];
        // Layer (x0, y0) is the largest of the four.
        const bool fetch = size_t(found.entries00[k]) * sizeof(Texel) > ColormapTable::kPrefetchedBytes;
        const size_t w0 = size_t(found.width0[k]);
        if (fetch) ColormapTable::prefetchTexels(at[0], w0);
        if (found.fx[k] == 0.0f && found.fy[k] == 0.0f) return;
        const size_t w1 = size_t(found.width1[k]);
        at[1] = layers[found.layer10[k]] + found.entry10[k];
        at[2] = layers[found.layer01[k]] + found.entry01[k];
        at[3] = layers[found.layer11[k]] + found.entry11[k];
        if (!fetch) return;
        ColormapTable::prefetchTexels(at[1], w1);
        ColormapTable::prefetchTexels(at[2], w0);
        ColormapTable::prefetchTexels(at[3], w1);
    };
    const auto blend = [&](size_t i, size_t slot) __attribute__((always_inline)) {
        const std::array<const Texel*, 4>& at = ring[slot];
        const size_t w0 = size_t(found.width0[i]);
        Texel c;
        if (found.fx[i] == 0.0f && found.fy[i] == 0.0f) {  // on a level: blend reads layer (x0, y0) only
            c = ColormapTable::blendTexels(at[0], w0, found.tx0[i], found.ty0[i]);
        } else {
            const size_t w1 = size_t(found.width1[i]);
            const TexelPair tx = pairOf(found.tx0[i], found.tx1[i]);
            const TexelPair y0 = blendTexelPair(at[0], w0, at[1], w1, tx, found.ty0[i]);
            const TexelPair y1 = blendTexelPair(at[2], w0, at[3], w1, tx, found.ty1[i]);
            c = ColormapTable::rowsFirst(lowOf(y0), highOf(y0), lowOf(y1), highOf(y1), found.fx[i], found.fy[i]);
        }
        texel_pairs::storeRgb(c, rgb + i * 3);
    };
    lookAhead(count, find, blend);
}
STOCHTEX_AVX2_COMPILATION void blendLayerTapsAvx2(const LayerTapsLanes& found, size_t count, const Texel* const* layers,
                                                  float* rgb) {
    blendLayerTapsBody(found, count, layers, rgb);
}
void blendLayerTapsBaseline(const LayerTapsLanes& found, size_t count, const Texel* const* layers, float* rgb) {
    blendLayerTapsBody(found, count, layers, rgb);
}

}  // namespace

void PrefilteredColormap::blendFound(const LayerTapsLanes& found, size_t count, float* rgb) const {
    (useAvx2Compilation() ? blendLayerTapsAvx2 : blendLayerTapsBaseline)(found, count, layerTexels_.data(), rgb);
}

// sample one pixel at a time, each pixel's entries prefetched kAhead
// pixels before its blend: Beta axes, and what the lanes leave.
void PrefilteredColormap::lookupRow(const float* mx, const float* my, const float* sx, const float* sy, float* rgb,
                                    size_t count) const {
    std::array<Lookup, kAhead> ring;
    lookAhead(
        count,
        [&](size_t k, size_t slot) {
            Lookup& l = ring[slot];
            l = find(mx[k], my[k], sx[k], sy[k]);
            for (size_t i = 0; i < (l.single ? 1 : 4); ++i) l.layers[i]->prefetch(l.taps[i]);
        },
        [&](size_t k, size_t slot) {
            const Rgb c = blend(ring[slot]);
            std::copy(c.begin(), c.end(), rgb + k * 3);
        });
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

size_t PrefilteredColormap::layerBytes(int width, int height, PrefilterMode mode, BetaAxes beta) {
    size_t entries[2] = {0, 0};
    for (size_t axis = 0; axis < 2; ++axis) {
        const int n = axis == 0 ? width : height;
        for (const double level : beta[axis] ? betaLevels(mode) : sigmaLevels(mode))
            entries[axis] += size_t(beta[axis] ? n : storedResolution(n, level));
    }
    return entries[0] * entries[1] * 4 * sizeof(float);  // ColormapTable keeps RGBA texels
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

Rgb betaAverageNumerically(const ColormapTable& h, double mx, double my, double sx, int steps) {
    const double nu = sx * sx / (mx * (1.0 - mx));
    if (!(nu > 0.0) || !(nu < 1.0))
        throw std::invalid_argument("betaAverageNumerically: needs 0 < var < m(1 − m), got m " + std::to_string(mx) +
                                    ", deviation " + std::to_string(sx));
    const boost::math::beta_distribution<double> d(mx * (1.0 / nu - 1.0), (1.0 - mx) * (1.0 / nu - 1.0));
    double acc[3] = {0, 0, 0};
    for (int i = 0; i < steps; ++i) {
        const Rgb c = h.sample(float(boost::math::quantile(d, (i + 0.5) / steps)), float(my));
        for (int k = 0; k < 3; ++k) acc[k] += c[size_t(k)] / steps;
    }
    return {float(acc[0]), float(acc[1]), float(acc[2])};
}

}  // namespace stochtex
