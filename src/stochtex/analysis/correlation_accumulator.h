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
// 1/N sample estimator).
#include <vector>

#include "stochtex/image/image.h"

namespace stochtex {

class CorrelationAccumulator {
public:
    // width × height frames; the reference point and rows must lie inside.
    CorrelationAccumulator(int width, int height, int referenceX, int referenceY, int referenceRow, int probeRow);

    void add(const Image& frame);  // 1 channel, width × height
    int count() const { return count_; }

    Image mean() const;
    Image variance() const;
    Image correlationWithPoint() const;   // vs (referenceX, referenceY)
    Image correlationWithRow() const;     // pixel (x, y) vs (x, referenceRow)
    Image probeCorrelation() const;       // W × W: (x, y) = Corr[I(x, probeRow), I(y, probeRow)]

private:
    double meanAt(size_t i) const { return sum_[i] / count_; }
    double varAt(size_t i) const;
    float corr(double sumXY, size_t i, size_t j) const;

    int width_, height_, refX_, refY_, refRow_, probeRow_;
    int count_ = 0;
    std::vector<double> sum_, sum2_, sumPoint_, sumRow_, sumProbe_;
};

}  // namespace stochtex
