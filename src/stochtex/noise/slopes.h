#pragma once
// The slope pair of a periodic height example, for LEAN-mapped normal maps
// (paper §6.5, Olano & Baker 2010): ∂h/∂x and ∂h/∂y by spectral derivative
// (the derivative of the example's Fourier series, exact on the periodic
// example), tiled and blended as one Shared pair so that the covariance
// estimator (eq. 16–19) applies to them.
#include <array>
#include <cstdint>

#include "stochtex/image/image.h"
#include "stochtex/noise/tiled_field.h"

namespace stochtex {

// ∂h/∂x and ∂h/∂y of the periodic W×W example h in height units per texel
// (x along the columns = u, y along the rows = v). The Nyquist row and
// column carry no derivative (a real signal's Nyquist term has none), so
// the slopes have zero mean and are band-limited like h.
std::array<Image, 2> spectralSlopes(const Image& height);

// The slope pair scaled so that its RMS slope per axis, √((σ_x² + σ_y²)/2),
// equals rmsSlope (a height field of any size and frequency gets the same
// roughness), as a Shared two-channel field with one tile-offset seed.
// InputError naming `amplitude` if rmsSlope is not finite and positive or
// the height example is flat.
TiledField slopeField(const Image& height, double rmsSlope, uint32_t offsetSeed, const GridLayout& grid);

}  // namespace stochtex
