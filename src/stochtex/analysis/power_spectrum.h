#pragma once
// Power spectra of images and frames (thesis §2.7, Figure 2.22): the centred
// periodogram of a gray image, averaged over instances when asked, its radial
// and angular profiles, and figures of its shape that tell a stretched
// texture from an isotropic one.
//
// Conventions. A W×H image I with its mean removed, multiplied by a window w
// (Hann for frames, which are not periodic: the window removes the cross of
// leakage that the frame's borders would add; none for periodic images such
// as noise examples), gives P(f) = |DFT(w·I)|² / Σw². So white noise of
// variance σ² has the flat spectrum P = σ² whatever the window, and
// Σ_f P(f) / (W·H) is the windowed variance. Frequencies are in cycles per
// pixel: sample (x, y) of the spectrum image is f = ((x − ⌊W/2⌋)/W,
// (y − ⌊H/2⌋)/H), zero frequency at (⌊W/2⌋, ⌊H/2⌋), f_y pointing down like
// image rows.
#include <vector>

#include "stochtex/core/enum_names.h"
#include "stochtex/image/image.h"

namespace stochtex {

enum class SpectrumWindow { Hann, None };
inline const EnumNames<SpectrumWindow> kSpectrumWindowNames{{"hann", SpectrumWindow::Hann},
                                                           {"none", SpectrumWindow::None}};

// The centred periodogram of a 1-channel image (colour: toGray first), as
// above. InputError for an image smaller than 4×4.
Image centredPowerSpectrum(const Image& gray, SpectrumWindow window);

// The mean of the periodograms of several images of one size (instances of
// a random texture, frames of a sequence): the estimate of the spectrum whose
// variance falls as 1/N. Streaming, O(W·H) memory.
class SpectrumAccumulator {
public:
    SpectrumAccumulator(int width, int height, SpectrumWindow window);
    // InputError if the image's size differs from the accumulator's.
    void add(const Image& image);
    int count() const { return count_; }
    Image mean() const;

private:
    int width_, height_;
    SpectrumWindow window_;
    std::vector<double> sum_;
    int count_ = 0;
};

// Mean power per bin of radius |f| ∈ [0, 0.5] cycles/pixel (bin b covers
// [b, b + 1)·0.5/bins), the zero frequency left out; frequencies beyond 0.5
// (the corners) are not counted. radius[b] is the bin's centre.
struct RadialProfile {
    std::vector<double> radius, power;
};
RadialProfile radialProfile(const Image& spectrum, int bins);

// Mean power per bin of orientation θ = atan2(f_y, f_x) folded into [0°, 180°)
// (a real image's spectrum is symmetric), over the annulus rMin ≤ |f| ≤ rMax.
// θ is measured with f_y up (counter-clockwise on screen).
struct AngularProfile {
    std::vector<double> angleDeg, power;
};
AngularProfile angularProfile(const Image& spectrum, int bins, double rMin = 0.0, double rMax = 0.5);

// The spectrum's shape over the annulus rMin ≤ |f| ≤ rMax (zero frequency out):
// * peak: the frequency of the largest P (its radius, and orientation in [0°, 180°));
// * the power-weighted second moment M = Σ P f fᵀ / Σ P, with eigenvalues
//   λ₁ ≥ λ₂: anisotropy = λ₁/λ₂ (1 for an isotropic spectrum, large for a
//   stretched texture, whose spectrum stretches across the stretch),
//   orientationDeg = the direction of M's major axis in [0°, 180°);
// * meanRadius = Σ P |f| / Σ P;
// * angularMaxMin = max/min of the angular profile in 18 bins of 10°.
struct SpectrumGeometry {
    double peakRadius = 0, peakOrientationDeg = 0;
    double anisotropy = 1, orientationDeg = 0;
    double meanRadius = 0;
    double angularMaxMin = 1;
};
SpectrumGeometry spectrumGeometry(const Image& spectrum, double rMin = 0.0, double rMax = 0.5);

// For display: log10(P / P_ref) mapped from [−decades, 0] to [0, 1], P_ref the
// largest P off the zero frequency (which is shown black: the mean is removed).
Image logSpectrumImage(const Image& spectrum, double decades = 4.0);

}  // namespace stochtex
