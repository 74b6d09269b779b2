#pragma once
// Contrast correction of a blended texture whose per-pixel variance σ_r² is
// known (Tavernier 2017, section 2.4): restore the base variance σ_f² while
// keeping the mean μ_f.
//
//   linear     h(I) = μ_f + (I − μ_f) σ_f/σ_r. Eq. 2.14 applied to the
//              centred value so the mean is kept (as section 2.4 requires);
//              values leave [0, 1] and are clamped.
//   polynomial h(x) = b x + c x² + d x³ (a = 0), the unique solution of the
//              linear system eq. 2.18 (h(1) = 1, h'(μ_f) = σ_f/σ_r,
//              E[h(I)] ≈ μ_f to second order), solved by Cramer's rule. Valid
//              where h' ≥ 0 on [0, 1] (eq. 2.17); elsewhere it still applies
//              but may fold, and out-of-range values are clamped.
//   sigmoid    the normalised sigmoid h(x) = kx/(1 + k − |x|) on [−1, 1]
//              (eq. 2.20) moved to [0, 1] as (1 + h(2x − 1))/2, with
//              k = s/(1 − s), s = σ_f/σ_r (eq. 2.22), so the slope at ½ is s.
//              Maps [0, 1] onto itself monotonically: it never clamps. It is
//              centred at ½ (for μ_f ≠ ½ the mean shifts).
#include <string>

#include "stochtex/image/image.h"

namespace stochtex {

enum class ContrastMethod { Linear, Polynomial, Sigmoid };
ContrastMethod parseContrastMethod(const std::string& s);
const char* contrastMethodName(ContrastMethod m);

// The cubic of eq. 2.18–2.19 for one pixel.
struct CubicCorrection {
    double b = 1, c = 0, d = 0;
    double operator()(double x) const { return x * (b + x * (c + x * d)); }
    double derivative(double x) const { return b + x * (2 * c + 3 * d * x); }
    // min over [0, 1] of h' ≥ 0 (eq. 2.17's monotonicity condition).
    bool monotone() const;
    // Throws if the system is singular (σ_r² = μ_f(1 − μ_f)… degenerate).
    static CubicCorrection solve(double meanF, double varianceF, double varianceR);
};

// One corrected value (unclamped) for a pixel of value v and variance σ_r².
double correctContrast(ContrastMethod m, double v, double meanF, double varianceF, double varianceR);

struct ContrastResult {
    Image image;                    // corrected and clamped to [0, 1]
    double clampedPercent = 0;      // pixels whose corrected value left [0, 1]
    Image invalid;                  // polynomial: 1 where h' < 0 somewhere on [0, 1]
    double invalidPercent = 0;
};

// texture and varianceR: 1-channel images of the same size (σ_r² per pixel).
ContrastResult correctContrast(ContrastMethod m, const Image& texture, const Image& varianceR, double meanF,
                               double varianceF);

}  // namespace stochtex
