#include "stochtex/filter/pyramid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stochtex/core/parallel.h"

namespace stochtex {

static void checkExample(const Image& e) {
    if (e.channels() != 1 || e.width() != e.height() || !isPowerOfTwo(e.width()))
        throw std::invalid_argument("StatsPyramid: needs a square power-of-two 1-channel example");
}

void StatsPyramid::build(const Image& a, const Image* b) {
    int n = a.width();
    BasicPeriodicGrid<2> level0(n);
    parallelRows(n, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < n; ++x) {
                float* t = level0.texel(x, y);
                t[0] = a.at(x, y);
                t[1] = 0.0f;  // the moments of one texel
            }
    });
    level0.wrapBorder();
    grids_.push_back(std::move(level0));
    // b's means of the current level, for a covariance pyramid (the grids
    // hold a's).
    std::vector<float> bMeans, bNext;
    if (b) bMeans.assign(b->data().begin(), b->data().end());
    while (n > 1) {
        const int h = n / 2;
        const BasicPeriodicGrid<2>& below = grids_.back();
        BasicPeriodicGrid<2> level(h);
        if (b) bNext.resize(size_t(h) * size_t(h));
        parallelRows(h, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y)
                for (int x = 0; x < h; ++x) {
                    const float* c[4] = {below.texel(2 * x, 2 * y), below.texel(2 * x + 1, 2 * y),
                                         below.texel(2 * x, 2 * y + 1), below.texel(2 * x + 1, 2 * y + 1)};
                    const float mean = 0.25f * ((c[0][0] + c[1][0]) + (c[2][0] + c[3][0]));
                    const float within = 0.25f * ((c[0][1] + c[1][1]) + (c[2][1] + c[3][1]));
                    float d[4];
                    for (int i = 0; i < 4; ++i) d[i] = c[i][0] - mean;
                    float between;
                    if (b) {
                        const size_t i0 = size_t(2 * y) * size_t(n) + size_t(2 * x), i2 = i0 + size_t(n);
                        const float bc[4] = {bMeans[i0], bMeans[i0 + 1], bMeans[i2], bMeans[i2 + 1]};
                        const float bMean = 0.25f * ((bc[0] + bc[1]) + (bc[2] + bc[3]));
                        bNext[size_t(y) * size_t(h) + size_t(x)] = bMean;
                        between = 0.25f * ((d[0] * (bc[0] - bMean) + d[1] * (bc[1] - bMean)) +
                                           (d[2] * (bc[2] - bMean) + d[3] * (bc[3] - bMean)));
                    } else {
                        between = 0.25f * ((d[0] * d[0] + d[1] * d[1]) + (d[2] * d[2] + d[3] * d[3]));
                    }
                    float* t = level.texel(x, y);
                    t[0] = mean;
                    t[1] = within + between;
                }
        });
        level.wrapBorder();
        grids_.push_back(std::move(level));
        if (b) bMeans.swap(bNext);
        n = h;
    }
    for (int l = 0; l < levels(); ++l) addAverageMoment(l);
}

// The level's mean moment, summed in double by rows and the rows in order
// (the same for any thread count).
void StatsPyramid::addAverageMoment(int l) {
    const BasicPeriodicGrid<2>& g = grids_[size_t(l)];
    const int n = g.size();
    std::vector<double> rows(size_t(n), 0.0);
    parallelRows(n, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < n; ++x) rows[size_t(y)] += g.texel(x, y)[1];
    });
    double sum = 0;
    for (double r : rows) sum += r;
    averageMoment_.push_back(float(sum / (double(n) * double(n))));
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
