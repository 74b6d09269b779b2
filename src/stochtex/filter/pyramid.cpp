#include "stochtex/filter/pyramid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stochtex {

namespace {

// Box-halves a double grid (2×2 averages).
std::vector<double> halve(const std::vector<double>& src, int n) {
    const int h = n / 2;
    std::vector<double> dst(size_t(h) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < h; ++x) {
            const size_t a = size_t(2 * y) * size_t(n) + size_t(2 * x);
            dst[size_t(y) * size_t(h) + size_t(x)] = 0.25 * (src[a] + src[a + 1] + src[a + size_t(n)] + src[a + size_t(n) + 1]);
        }
    return dst;
}

Image toImage(const std::vector<double>& v, int n) {
    Image img(n, n, 1, Image::Uninitialized{});
    for (size_t i = 0; i < v.size(); ++i) img.data()[i] = float(v[i]);
    return img;
}

std::vector<double> toDouble(const Image& img) { return std::vector<double>(img.data().begin(), img.data().end()); }

}  // namespace

static void checkExample(const Image& e) {
    if (e.channels() != 1 || e.width() != e.height() || !isPowerOfTwo(e.width()))
        throw std::invalid_argument("StatsPyramid: needs a square power-of-two 1-channel example");
}

void StatsPyramid::addLevel(Image mean, Image moment) {
    double sum = 0;
    for (float v : moment.data()) sum += v;
    averageMoment_.push_back(float(sum / double(moment.data().size())));
    means_.push_back(std::move(mean));
    moments_.push_back(std::move(moment));
    grids_.emplace_back(std::array<const Image*, 2>{&means_.back(), &moments_.back()});
}

// Builds all levels from level-0 first moments a, b and their product ab:
// mean a_l and moment ab_l − a_l b_l (V_l or C_l).
void StatsPyramid::buildLevels(std::vector<double> a, std::vector<double> b, std::vector<double> ab, int n) {
    while (true) {
        std::vector<double> m(a.size());
        for (size_t i = 0; i < m.size(); ++i) m[i] = ab[i] - a[i] * b[i];
        addLevel(toImage(a, n), toImage(m, n));
        if (n == 1) break;
        a = halve(a, n);
        b = halve(b, n);
        ab = halve(ab, n);
        n /= 2;
    }
}

StatsPyramid::StatsPyramid(const Image& example) {
    checkExample(example);
    std::vector<double> e = toDouble(example), e2(e.size());
    for (size_t i = 0; i < e.size(); ++i) e2[i] = e[i] * e[i];
    buildLevels(e, e, std::move(e2), example.width());
}

StatsPyramid StatsPyramid::covariance(const Image& e, const Image& eprime) {
    checkExample(e);
    checkExample(eprime);
    if (e.width() != eprime.width()) throw std::invalid_argument("StatsPyramid::covariance: size mismatch");
    std::vector<double> a = toDouble(e), b = toDouble(eprime), ab(a.size());
    for (size_t i = 0; i < a.size(); ++i) ab[i] = a[i] * b[i];
    StatsPyramid p;
    p.buildLevels(std::move(a), std::move(b), std::move(ab), e.width());
    return p;
}

StatsPyramid StatsPyramid::quantized8() const {
    auto q = [](Image img, float scale) {
        for (float& v : img.data()) v = std::round(std::clamp(v * scale, 0.0f, 1.0f) * 255.0f) / 255.0f / scale;
        return img;
    };
    StatsPyramid p;
    for (size_t l = 0; l < grids_.size(); ++l) p.addLevel(q(means_[l], 1.0f), q(moments_[l], 16.0f));
    p.averageMoment_ = averageMoment_;  // the Deliot–Heitz constants stay as computed
    return p;
}

Image StatsPyramid::interleavedLevel(int l, int channels) const {
    const Image& mean = means_[size_t(l)];
    const Image& moment = moments_[size_t(l)];
    Image out(mean.width(), mean.height(), channels, 0.0f);
    for (size_t i = 0; i < mean.pixelCount(); ++i) {
        out.data()[size_t(channels) * i] = mean.data()[i];
        out.data()[size_t(channels) * i + 1] = moment.data()[i];
    }
    return out;
}

size_t StatsPyramid::bytes() const {
    size_t total = 0;
    for (const auto& g : grids_) total += g.bytes();
    return total;
}

}  // namespace stochtex
