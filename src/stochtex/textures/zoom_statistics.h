#pragma once
// Analytic statistics of the stationary zoom texture over the space of
// base-lattice realisations (Tavernier 2017, section 2.3, Table 2.3).
//
// With f(k) independent of mean μ_f and variance σ_f² (periodic: f(k) and
// f(k + (W, H)m) are the same value),
//     E[I(x)]            = μ_f
//     Cov(I(x1), I(x2))  = σ_f² α(x1, x2)
//     α(x1, x2) = Σ_i Σ_j A_i A_j Σ_k K(a_i x1 + o_i − k) K(a_j x2 + o_j − k)   (eq. 2.11)
// where the inner sum runs over lattice points k identified modulo the
// period. K = Λ (tent, linear interpolation) or the unit box (nearest); both
// are separable, so the inner sum is a product of two 1D sums, each over at
// most two lattice points. Correlation = α12 / √(α11 α22).
#include <vector>

#include "stochtex/image/image.h"
#include "stochtex/textures/zoom_texture.h"

namespace stochtex {

class ZoomStatistics {
public:
    ZoomStatistics(const ZoomParams& p, int baseWidth, int baseHeight);

    const std::vector<ZoomLayer>& layers() const { return layers_; }
    double alpha(double x1, double y1, double x2, double y2) const;
    double varianceFactor(double x, double y) const { return alpha(x, y, x, y); }  // Var = σ_f² α(x, x)
    double correlation(double x1, double y1, double x2, double y2) const;

    // α(x, x) over a region (1 channel): the per-pixel variance factor the
    // contrast corrections need. Multi-threaded.
    Image varianceFactorImage(const ZoomRegion& region) const;
    // Corr[I(⟨x;0⟩), I(⟨y;0⟩)] for x, y = 0 … size−1 pixels from the centre
    // (the radial plot of Figures 2.9, 2.10); row = y, column = x.
    Image radialCorrelation(int size) const;
    // Corr[I(⟨x;0⟩), I(⟨x;y⟩)] for x, y = 0 … size−1 (the non-radial plot of
    // Figure 2.8); row = y, column = x.
    Image nonRadialCorrelation(int size) const;

private:
    // Σ_k K(s − k) K(t − k) along one axis of period `period`.
    double overlap1d(double s, double t, double period) const;

    std::vector<ZoomLayer> layers_;
    LatticeInterpolation mode_;
    double width_, height_;
};

}  // namespace stochtex
