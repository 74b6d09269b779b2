#pragma once
// The statistical accumulator (Tavernier 2017, section 3.3): frames of N
// instances of a random texture (different seeds, same parameters) are added
// one at a time, and sample statistics come out at the end:
//   * per-pixel mean and variance;
//   * correlation of every pixel with one reference point (Figure 2.8c/d);
//   * correlation of every pixel (x, y) with (x, referenceRow) — the
//     measured non-radial plot Corr[I(x,0), I(x,y)] when frame row
//     `referenceRow` is the axis through the zoom centre;
//   * correlation between every pair of pixels of row `probeRow` (the radial
//     plot Corr[I(x,0), I(y,0)] of Figures 2.9–2.10), a W×W matrix.
// Memory is O(W·H + W²) whatever N (sums are kept, frames are not). Sums are
// in double; rows are accumulated in parallel, each row by one thread, so
// results do not depend on the thread count. Correlations use eq. 3.1 (the
// 1/N sample estimator). Accumulators of disjoint sets of frames merge (their
// sums add), so a run can be split into parts anywhere and the parts' sums
// added in a fixed order (studies/instance_statistics.h).
#include <array>
#include <vector>

#include "stochtex/image/image.h"

namespace stochtex {

class CorrelationAccumulator {
public:
    // width × height frames; the reference point and rows must lie inside.
    CorrelationAccumulator(int width, int height, int referenceX, int referenceY, int referenceRow, int probeRow);

    void add(const Image& frame);  // 1 channel, width × height
    int count() const { return count_; }
    // Adds the sums of `other`, an accumulator of other frames with the same
    // size, point and rows (InputError otherwise).
    void merge(const CorrelationAccumulator& other);

    // The sums, for a copy that travels to another process: per pixel Σv, Σv²,
    // Σv·v(point), Σv·v(x, referenceRow) (width·height each), and per pair of
    // the probe row Σv(x)v(y) (width² values), in that order.
    static constexpr int kSums = 5;
    std::array<const std::vector<double>*, kSums> sums() const {
        return {&sum_, &sum2_, &sumPoint_, &sumRow_, &sumProbe_};
    }
    // Sets the count and the sums (as sums() lists them); InputError for a
    // negative count or a sum of the wrong size.
    void restore(int count, std::array<std::vector<double>, kSums> sums);
    int width() const { return width_; }
    int height() const { return height_; }
    int referenceX() const { return refX_; }
    int referenceY() const { return refY_; }
    int referenceRow() const { return refRow_; }
    int probeRow() const { return probeRow_; }

    Image mean() const;
    Image variance() const;
    Image correlationWithPoint() const;  // vs (referenceX, referenceY)
    Image correlationWithRow() const;    // pixel (x, y) vs (x, referenceRow)
    Image probeCorrelation() const;      // W × W: (x, y) = Corr[I(x, probeRow), I(y, probeRow)]

private:
    std::array<std::vector<double>*, kSums> sumsToAdd() { return {&sum_, &sum2_, &sumPoint_, &sumRow_, &sumProbe_}; }
    double meanAt(size_t i) const { return sum_[i] / count_; }
    double varAt(size_t i) const;
    float corr(double sumXY, size_t i, size_t j) const;

    int width_, height_, refX_, refY_, refRow_, probeRow_;
    int count_ = 0;
    std::vector<double> sum_, sum2_, sumPoint_, sumRow_, sumProbe_;
};

}  // namespace stochtex
