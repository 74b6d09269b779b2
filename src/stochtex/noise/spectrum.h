#pragma once
// Periodic Gaussian noise examples defined by their power spectrum.
//
// A W×W example is seeded white noise filtered in the Fourier domain by an
// amplitude |F(f)| = sqrt(Σ_k weight_k · P_k(f)), then shifted and scaled to a
// requested mean and standard deviation and clamped to [0,1]. Because the
// FFT is periodic, the example tiles seamlessly with period 1 in uv.
//
// Frequencies are in cycles per example period (f = 8 means eight waves
// across the example), independent of W. An orientation θ (degrees) is the
// direction of the wave vector as seen on screen, counter-clockwise from +u;
// with v pointing down the image rows, d = (cos θ, −sin θ) in (u, v).
#include <cstdint>
#include <vector>

#include "stochtex/image/image.h"

namespace stochtex {

enum class SpectrumShape {
    LowPass,  // P = exp(−|f|² / (2 fc²)); `frequency` is the cut-off fc
    Ring,     // P = exp(−(|f| − f0)² / (2 b²)); isotropic band around f0
    BiLobe,   // P = Σ± exp(−|f ∓ f0 d|² / (2 b²)); two lobes along θ
};

struct SpectrumComponent {
    SpectrumShape shape = SpectrumShape::LowPass;
    double frequency = 8.0;    // cut-off (low-pass) or centre frequency f0
    double bandwidth = 2.0;    // standard deviation b of the band (ring, bi-lobe)
    double orientation = 0.0;  // θ in degrees (bi-lobe only)
    double weight = 1.0;       // relative power of this component

    bool operator==(const SpectrumComponent&) const = default;
};

struct SpectrumSpec {
    int size = 256;  // W
    uint32_t seed = 0;
    double mean = 0.5;
    double stddev = 1.0 / 6.0;
    std::vector<SpectrumComponent> components;
    // Hilbert transform along the first bi-lobe's orientation (or +u): the
    // quadrature partner of the same seed, used for phasor fields.
    bool quadrature = false;

    bool operator==(const SpectrumSpec&) const = default;
};

constexpr int kMaxExampleSize = 4096;
// Work budget of a synthesis: every component's power is evaluated at every
// one of the W² frequencies, ~10 ns each (2²⁸ ≈ 3 s on one core).
constexpr long long kMaxSpectrumWork = 1LL << 28;

// Fails (parameter "components") if components × W² is over kMaxSpectrumWork.
void validateSpectrumWork(const SpectrumSpec& spec);

// Power P(f) of the spec at frequency (fu, fv) in cycles per period.
double spectrumPower(const SpectrumSpec& spec, double fu, double fv);

// Synthesizes the example (1 channel, W×W). Deterministic in spec.seed.
Image synthesizeExample(const SpectrumSpec& spec);

// |FFT|² of a 1-channel square image with its mean removed; entry (i, j)
// holds frequency (i, j) with indices above W/2 meaning negative frequencies.
Image powerSpectrum(const Image& example);

// Signed frequency of FFT index k for size n.
inline int fftFrequency(int k, int n) { return k <= n / 2 ? k : k - n; }

}  // namespace stochtex

namespace stochtex {
// A power spectrum for display: zero frequency moved to the centre,
// log(1 + P/P_max·10⁴)/log(1 + 10⁴) so weak bands stay visible.
Image displaySpectrum(const Image& power);
}  // namespace stochtex
