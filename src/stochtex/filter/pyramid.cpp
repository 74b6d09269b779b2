#include "stochtex/filter/pyramid.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "stochtex/core/parallel.h"

namespace stochtex {

static void checkExample(const Image& e) {
    if (e.channels() != 1 || e.width() != e.height() || !isPowerOfTwo(e.width()))
        throw std::invalid_argument("StatsPyramid: needs a square power-of-two 1-channel example");
}

namespace {

// The levels 1..kTileLevels above a level-0 tile of 2^kTileLevels texels are
// built from it while it is in cache (32² texels: 8 KiB at level 0), so
// level 0 is read from memory once rather than once per level above it.
constexpr int kTileLevels = 5;

// A texel from its four children c (mean, moment), by the pairwise update;
// for a covariance pyramid bc holds E'_l of the children and the texel's E'
// mean is returned (nullptr: E' = E, a variance).
float combineChildren(const float* const c[4], const float* bc, float* out) {
    const float mean = 0.25f * ((c[0][0] + c[1][0]) + (c[2][0] + c[3][0]));
    const float within = 0.25f * ((c[0][1] + c[1][1]) + (c[2][1] + c[3][1]));
    float d[4];
    for (int i = 0; i < 4; ++i) d[i] = c[i][0] - mean;
    float bMean = 0.0f, between;
    if (bc) {
        bMean = 0.25f * ((bc[0] + bc[1]) + (bc[2] + bc[3]));
        between = 0.25f * ((d[0] * (bc[0] - bMean) + d[1] * (bc[1] - bMean)) +
                           (d[2] * (bc[2] - bMean) + d[3] * (bc[3] - bMean)));
    } else {
        between = 0.25f * ((d[0] * d[0] + d[1] * d[1]) + (d[2] * d[2] + d[3] * d[3]));
    }
    out[0] = mean;
    out[1] = within + between;
    return bMean;
}

// Texel (x, y) of `level` from its children in `below`. A covariance
// pyramid also passes E' of the top-left child at bChild (its right
// neighbour next, the row below bStride further) and gets the texel's E'
// mean in *bOut; a variance pyramid passes nullptr.
void buildTexel(const BasicPeriodicGrid<2>& below, BasicPeriodicGrid<2>& level, int x, int y, const float* bChild,
                size_t bStride, float* bOut) {
    const float* c[4] = {below.texel(2 * x, 2 * y), below.texel(2 * x + 1, 2 * y), below.texel(2 * x, 2 * y + 1),
                         below.texel(2 * x + 1, 2 * y + 1)};
    if (!bChild) {
        combineChildren(c, nullptr, level.texel(x, y));
        return;
    }
    const float bc[4] = {bChild[0], bChild[1], bChild[bStride], bChild[bStride + 1]};
    *bOut = combineChildren(c, bc, level.texel(x, y));
}

// A level's mean moment, summed in double by rows and the rows in order
// (the same for any thread count).
float levelMeanMoment(const BasicPeriodicGrid<2>& g) {
    const int n = g.size();
    std::vector<double> rows(size_t(n), 0.0);
    parallelRows(n, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < n; ++x) rows[size_t(y)] += g.texel(x, y)[1];
    });
    double sum = 0;
    for (double r : rows) sum += r;
    return float(sum / (double(n) * double(n)));
}

}  // namespace

void StatsPyramid::build(const Image& a, const Image* b) {
    const int n = a.width();
    const int fine = std::min(kTileLevels, std::countr_zero(unsigned(n)));  // levels built per tile
    const int tile = 1 << fine, tiles = n / tile;
    for (int l = 0; l <= fine; ++l) grids_.emplace_back(n >> l);
    // E' means of level `fine` (a covariance pyramid: the grids hold E's).
    std::vector<float> bCoarse(b ? size_t(tiles) * size_t(tiles) : 0);
    parallelRows(tiles, [&](int ty0, int ty1) {
        // E' means of the tile's current level and the next (row stride: their side).
        std::vector<float> bLevel(b ? size_t(tile) * size_t(tile) : 0), bNext(bLevel.size());
        for (int ty = ty0; ty < ty1; ++ty)
            for (int tx = 0; tx < tiles; ++tx) {
                const int x0 = tx * tile, y0 = ty * tile;
                for (int y = 0; y < tile; ++y)
                    for (int x = 0; x < tile; ++x) {
                        float* t = grids_[0].texel(x0 + x, y0 + y);
                        t[0] = a.at(x0 + x, y0 + y);
                        t[1] = 0.0f;  // the moments of one texel
                        if (b) bLevel[size_t(y) * size_t(tile) + size_t(x)] = b->at(x0 + x, y0 + y);
                    }
                for (int l = 1; l <= fine; ++l) {
                    const int side = tile >> l;  // the tile's texels at level l start at (x0, y0) >> l
                    for (int y = 0; y < side; ++y)
                        for (int x = 0; x < side; ++x) {
                            const size_t child = size_t(2 * y) * size_t(2 * side) + size_t(2 * x);
                            buildTexel(grids_[size_t(l - 1)], grids_[size_t(l)], (x0 >> l) + x, (y0 >> l) + y,
                                       b ? bLevel.data() + child : nullptr, size_t(2 * side),
                                       b ? &bNext[size_t(y) * size_t(side) + size_t(x)] : nullptr);
                        }
                    if (b) bLevel.swap(bNext);
                }
                if (b) bCoarse[size_t(ty) * size_t(tiles) + size_t(tx)] = bLevel[0];
            }
    });
    for (BasicPeriodicGrid<2>& g : grids_) g.wrapBorder();
    // The levels above `fine`, a level at a time (they are at most 1/1024 of
    // the data); bMeans: E' means of the level below.
    std::vector<float> bMeans = std::move(bCoarse), bNext;
    for (int side = tiles / 2; side >= 1; side /= 2) {
        BasicPeriodicGrid<2> level(side);
        const BasicPeriodicGrid<2>& below = grids_.back();
        if (b) bNext.resize(size_t(side) * size_t(side));
        parallelRows(side, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y)
                for (int x = 0; x < side; ++x)
                    buildTexel(below, level, x, y,
                               b ? bMeans.data() + size_t(2 * y) * size_t(2 * side) + size_t(2 * x) : nullptr,
                               size_t(2 * side), b ? &bNext[size_t(y) * size_t(side) + size_t(x)] : nullptr);
        });
        level.wrapBorder();
        grids_.push_back(std::move(level));
        if (b) bMeans.swap(bNext);
    }
    averageMoment_.push_back(0.0f);  // level 0: one texel has no spread
    for (int l = 1; l < levels(); ++l) averageMoment_.push_back(levelMeanMoment(grids_[size_t(l)]));
}

StatsPyramid::StatsPyramid(const Image& example) {
    checkExample(example);
    build(example, nullptr);
}

StatsPyramid StatsPyramid::covariance(const Image& e, const Image& eprime) {
    checkExample(e);
    checkExample(eprime);
    if (e.width() != eprime.width()) throw std::invalid_argument("StatsPyramid::covariance: size mismatch");
    StatsPyramid p;
    p.build(e, &eprime);
    return p;
}

StatsPyramid StatsPyramid::quantized8() const {
    const auto q = [](float v, float scale) {
        return std::round(std::clamp(v * scale, 0.0f, 1.0f) * 255.0f) / 255.0f / scale;
    };
    StatsPyramid p = *this;  // the Deliot–Heitz constants stay as computed
    for (BasicPeriodicGrid<2>& g : p.grids_) {
        const int n = g.size();
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                float* t = g.texel(x, y);
                t[0] = q(t[0], 1.0f);
                t[1] = q(t[1], 16.0f);
            }
        g.wrapBorder();
    }
    return p;
}

Image StatsPyramid::interleavedLevel(int l, int channels) const {
    const BasicPeriodicGrid<2>& g = grids_[size_t(l)];
    Image out(g.size(), g.size(), channels, 0.0f);
    for (int y = 0; y < g.size(); ++y)
        for (int x = 0; x < g.size(); ++x) {
            out.at(x, y, 0) = g.texel(x, y)[0];
            out.at(x, y, 1) = g.texel(x, y)[1];
        }
    return out;
}

size_t StatsPyramid::bytes() const {
    size_t total = 0;
    for (const auto& g : grids_) total += g.bytes();
    return total;
}

}  // namespace stochtex
