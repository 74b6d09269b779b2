#pragma once
// Numbers for a correlation map around its reference point (thesis §2.7.2,
// Figures 2.19–2.21), so that "this vein is stretched" and "the noise has
// anti-correlated lobes" are measurements:
//   * the correlated region: the pixels with Corr ≥ `threshold` connected
//     (4-neighbours) to the reference point — its area, and its shape as the
//     ratio of the principal axes of its pixel coordinates (1 for a disc,
//     large for a stretched vein) with the major axis' direction;
//   * the anti-correlation: the most negative value of the map averaged over
//     `smoothing`×`smoothing` pixels. A plain minimum would report the
//     estimator's noise (a map from N instances has a standard error of
//     about 1/√N per pixel, and the minimum of 10⁴ such pixels lies ~4
//     standard errors below 0); the lobes of a gradient noise are a lattice
//     cell wide and survive the average.
#include "stochtex/image/image.h"

namespace stochtex {

struct CorrelationShape {
    int area = 0;               // pixels in the correlated region
    double elongation = 1;      // √(λ₁/λ₂) of the region's coordinate covariance
    double orientationDeg = 0;  // major axis, degrees counter-clockwise from +x (image y points down)
    double antiCorrelation = 0; // min of the smoothed map (≤ 0 unless the whole map is positive)
};

// map: 1 channel (NaN where a pixel had no variance: never in the region, ignored by the average).
CorrelationShape correlationShape(const Image& map, int referenceX, int referenceY, double threshold = 0.5,
                                  int smoothing = 5);

}  // namespace stochtex
