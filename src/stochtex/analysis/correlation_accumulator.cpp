#include "stochtex/analysis/correlation_accumulator.h"

#include <cmath>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"

namespace stochtex {

CorrelationAccumulator::CorrelationAccumulator(int width, int height, int referenceX, int referenceY,
                                               int referenceRow, int probeRow)
    : width_(width), height_(height), refX_(referenceX), refY_(referenceY), refRow_(referenceRow), probeRow_(probeRow) {
    if (width < 1 || height < 1 || width > 8192 || height > 8192)
        throw InputError("accumulator: frame size must be in [1, 8192] per side");
    if (referenceX < 0 || referenceX >= width || referenceY < 0 || referenceY >= height)
        throw InputError("accumulator: the reference point lies outside the frame");
    if (referenceRow < 0 || referenceRow >= height || probeRow < 0 || probeRow >= height)
        throw InputError("accumulator: the reference and probe rows must lie inside the frame");
    const size_t n = size_t(width) * size_t(height);
    sum_.assign(n, 0.0);
    sum2_.assign(n, 0.0);
    sumPoint_.assign(n, 0.0);
    sumRow_.assign(n, 0.0);
    sumProbe_.assign(size_t(width) * size_t(width), 0.0);
}

void CorrelationAccumulator::add(const Image& frame) {
    if (frame.width() != width_ || frame.height() != height_ || frame.channels() != 1)
        throw InputError("accumulator: every frame must be " + std::to_string(width_) + "x" +
                         std::to_string(height_) + " with 1 channel");
    const double ref = frame.at(refX_, refY_);
    const float* axis = frame.row(refRow_);
    const float* probes = frame.row(probeRow_);
    // Rows of the frame, then rows of the probe matrix: each output row is
    // written by exactly one task.
    parallelRows(height_ + width_, [&](int r0, int r1) {
        for (int r = r0; r < r1; ++r) {
            if (r < height_) {
                const float* p = frame.row(r);
                const size_t base = size_t(r) * size_t(width_);
                for (int x = 0; x < width_; ++x) {
                    const double v = p[x];
                    sum_[base + size_t(x)] += v;
                    sum2_[base + size_t(x)] += v * v;
                    sumPoint_[base + size_t(x)] += v * ref;
                    sumRow_[base + size_t(x)] += v * double(axis[x]);
                }
            } else {
                const int y = r - height_;
                const double py = probes[y];
                double* m = sumProbe_.data() + size_t(y) * size_t(width_);
                for (int x = 0; x < width_; ++x) m[x] += double(probes[x]) * py;
            }
        }
    });
    ++count_;
}

void CorrelationAccumulator::merge(const CorrelationAccumulator& other) {
    if (other.width_ != width_ || other.height_ != height_ || other.refX_ != refX_ || other.refY_ != refY_ ||
        other.refRow_ != refRow_ || other.probeRow_ != probeRow_)
        throw InputError("accumulator: merges only an accumulator of the same frame size, point and rows");
    const auto mine = sumsToAdd();
    const auto theirs = other.sums();
    for (int k = 0; k < kSums; ++k) {
        std::vector<double>& to = *mine[size_t(k)];
        const std::vector<double>& from = *theirs[size_t(k)];
        for (size_t i = 0; i < to.size(); ++i) to[i] += from[i];
    }
    count_ += other.count_;
}

void CorrelationAccumulator::restore(int count, std::array<std::vector<double>, kSums> sums) {
    if (count < 0) throw InputError("accumulator: a count of frames cannot be negative");
    const auto mine = this->sums();
    for (int k = 0; k < kSums; ++k)
        if (sums[size_t(k)].size() != mine[size_t(k)]->size())
            throw InputError("accumulator: sum " + std::to_string(k) + " holds " +
                             std::to_string(sums[size_t(k)].size()) + " values, not " +
                             std::to_string(mine[size_t(k)]->size()));
    count_ = count;
    const auto to = sumsToAdd();
    for (int k = 0; k < kSums; ++k) *to[size_t(k)] = std::move(sums[size_t(k)]);
}

double CorrelationAccumulator::varAt(size_t i) const {
    const double m = meanAt(i);
    return std::max(0.0, sum2_[i] / count_ - m * m);
}

float CorrelationAccumulator::corr(double sumXY, size_t i, size_t j) const {
    const double cov = sumXY / count_ - meanAt(i) * meanAt(j);
    const double d = std::sqrt(varAt(i) * varAt(j));
    return d > 0 ? float(cov / d) : 0.0f;
}

Image CorrelationAccumulator::mean() const {
    Image out(width_, height_, 1, Image::Uninitialized{});
    for (size_t i = 0; i < sum_.size(); ++i) out.data()[i] = count_ ? float(meanAt(i)) : 0.0f;
    return out;
}

Image CorrelationAccumulator::variance() const {
    Image out(width_, height_, 1, Image::Uninitialized{});
    for (size_t i = 0; i < sum_.size(); ++i) out.data()[i] = count_ ? float(varAt(i)) : 0.0f;
    return out;
}

Image CorrelationAccumulator::correlationWithPoint() const {
    Image out(width_, height_, 1, 0.0f);
    if (!count_) return out;
    const size_t ref = size_t(refY_) * size_t(width_) + size_t(refX_);
    for (size_t i = 0; i < sum_.size(); ++i) out.data()[i] = corr(sumPoint_[i], i, ref);
    return out;
}

Image CorrelationAccumulator::correlationWithRow() const {
    Image out(width_, height_, 1, 0.0f);
    if (!count_) return out;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const size_t i = size_t(y) * size_t(width_) + size_t(x);
            out.at(x, y) = corr(sumRow_[i], i, size_t(refRow_) * size_t(width_) + size_t(x));
        }
    return out;
}

Image CorrelationAccumulator::probeCorrelation() const {
    Image out(width_, width_, 1, 0.0f);
    if (!count_) return out;
    const size_t row = size_t(probeRow_) * size_t(width_);
    for (int y = 0; y < width_; ++y)
        for (int x = 0; x < width_; ++x)
            out.at(x, y) = corr(sumProbe_[size_t(y) * size_t(width_) + size_t(x)], row + size_t(x), row + size_t(y));
    return out;
}

}  // namespace stochtex
