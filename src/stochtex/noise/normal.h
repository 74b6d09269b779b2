#pragma once
// The standard normal distribution: CDF, quantile, and hashed Gaussian
// samples. Used by the spectral synthesis (white noise) and by the histogram
// transform that Gaussianizes exemplars.
#include <cstdint>

namespace stochtex {

// Φ(x) = P(Z ≤ x) for Z ~ N(0,1).
double normalCdf(double x);
// Φ⁻¹(p) for p in (0,1): Acklam's rational approximation refined by one
// Halley step, accurate to ~1e-15 relative.
double normalQuantile(double p);
// A N(0,1) sample that depends only on (x, y, seed): Box–Muller over pcg3d bits.
double hashedGaussian(uint32_t x, uint32_t y, uint32_t seed);

}  // namespace stochtex
