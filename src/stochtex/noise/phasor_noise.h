#pragma once
// Procedural phasor noise (Tricard et al. 2019, "Procedural Phasor Noise"),
// the unfiltered reference the paper's phasor patterns are compared with: a
// sparse convolution of complex Gabor kernels
//   G(u) = Σ_k w_k exp(−|u − u_k|² / (2 s²)) exp(2πi F d·(u − u_k)),
// impulses u_k scattered on a grid of cells one kernel radius wide, and the
// phasor field G/|G| whose argument φ feeds the profile, S = P(φ).
//
// Parameters speak the language of the spectral examples (noise/spectrum.h),
// so both fields can be compared at the same frequency and orientation:
// F in cycles per uv unit (per example period), the orientation θ in degrees
// with d = (cos θ, −sin θ) in (u, v), and the bandwidth b the standard
// deviation of the power spectrum's lobe around F d, as a bi-lobe
// component's: |Ĝ|² ∝ exp(−|f − F d|² / (2 b²)) gives s = 1 / (2√2 π b).
//
// Every impulse is hashed from its cell and the seed (kernel pcg3d), so a
// point's value depends on nothing else: any region, any thread count, the
// same numbers.
#include <array>
#include <cstdint>

namespace stochtex {

struct PhasorNoiseParams {
    double frequency = 24.0;    // F, cycles per uv unit, in (0, 10000]
    double bandwidth = 2.5;     // b, cycles per uv unit, in (0, 10000]
    double orientation = 30.0;  // θ, degrees, in [−360, 360]
    double density = 8.0;       // mean impulses per cell (cell side = kernel radius), in (0, 64]
    uint32_t seed = 1;
};

// InputError::parameter naming frequency, bandwidth, orientation or density.
void validatePhasorNoise(const PhasorNoiseParams& params);

// The kernel radius in standard deviations of its envelope: the envelope is
// exp(−4.5) ≈ 1.1% of its peak there, the truncation of the sum.
constexpr double kPhasorKernelRadius = 3.0;

class PhasorNoise {
public:
    explicit PhasorNoise(const PhasorNoiseParams& params);  // validates
    const PhasorNoiseParams& params() const { return params_; }
    // The envelope's standard deviation s and the cell side (uv units).
    double envelopeStddev() const { return sigma_; }
    double cellSize() const { return cell_; }

    // G(u, v) as (real, imaginary).
    std::array<double, 2> complexValue(double u, double v) const;
    // φ = arg G ∈ (−π, π].
    double phase(double u, double v) const;

private:
    PhasorNoiseParams params_;
    double sigma_ = 0, cell_ = 0, du_ = 1, dv_ = 0;
};

}  // namespace stochtex
