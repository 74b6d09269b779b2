#include "stochtex/analysis/power_spectrum.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The separable window's weight along an axis of n samples.
std::vector<double> windowWeights(int n, SpectrumWindow window) {
    std::vector<double> w(size_t(n), 1.0);
    if (window == SpectrumWindow::Hann)
        // The periodic Hann window (no zero at both ends), whose DFT leaks into
        // the two neighbouring bins only.
        for (int i = 0; i < n; ++i) w[size_t(i)] = 0.5 - 0.5 * std::cos(2 * kPi * i / n);
    return w;
}

// Centred frequency of spectrum sample (x, y), cycles per pixel.
struct Frequency {
    double fx, fy;
};
Frequency frequencyOf(int x, int y, int w, int h) { return {double(x - w / 2) / w, double(y - h / 2) / h}; }

// θ in [0, π) with f_y up (image rows grow downwards).
double foldedAngle(const Frequency& f) {
    double a = std::atan2(-f.fy, f.fx);
    if (a < 0) a += kPi;
    if (a >= kPi) a -= kPi;
    return a;
}

void checkSpectrum(const Image& spectrum, const char* who) {
    if (spectrum.channels() != 1 || spectrum.width() < 4 || spectrum.height() < 4)
        throw std::invalid_argument(std::string(who) + ": needs a 1-channel spectrum of at least 4×4");
}

}  // namespace

Image centredPowerSpectrum(const Image& image, SpectrumWindow window) {
    const Image gray = toGray(image);
    const int w = gray.width(), h = gray.height();
    if (w < 4 || h < 4)
        throw InputError("power spectrum: the image must be at least 4×4 pixels, got " + std::to_string(w) + "×" +
                         std::to_string(h));
    double mean = 0;
    for (float v : gray.data()) mean += v;
    mean /= double(w) * h;
    const std::vector<double> wx = windowWeights(w, window), wy = windowWeights(h, window);
    double energy = 0;  // Σ w²
    cv::Mat field(h, w, CV_64FC2);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double weight = wx[size_t(x)] * wy[size_t(y)];
            energy += weight * weight;
            field.at<cv::Vec2d>(y, x) = {weight * (gray.at(x, y) - mean), 0.0};
        }
    cv::dft(field, field, cv::DFT_COMPLEX_OUTPUT);
    Image out(w, h, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const cv::Vec2d z = field.at<cv::Vec2d>(y, x);
            // DFT index k holds frequency k (k ≤ n/2) or k − n: shifted so that
            // zero frequency lands at ⌊n/2⌋.
            const int cx = (x + w / 2) % w, cy = (y + h / 2) % h;
            out.at(cx, cy) = float((z[0] * z[0] + z[1] * z[1]) / energy);
        }
    return out;
}

SpectrumAccumulator::SpectrumAccumulator(int width, int height, SpectrumWindow window)
    : width_(width), height_(height), window_(window), sum_(size_t(width) * size_t(height), 0.0) {
    if (width < 4 || height < 4) throw InputError::parameter("size", "must be at least 4×4 for a power spectrum");
}

void SpectrumAccumulator::add(const Image& image) {
    if (image.width() != width_ || image.height() != height_)
        throw InputError("power spectrum: every image must be " + std::to_string(width_) + "×" +
                         std::to_string(height_) + ", got " + std::to_string(image.width()) + "×" +
                         std::to_string(image.height()));
    const Image p = centredPowerSpectrum(image, window_);
    for (size_t i = 0; i < sum_.size(); ++i) sum_[i] += p.data()[i];
    ++count_;
}

Image SpectrumAccumulator::mean() const {
    if (count_ == 0) throw std::logic_error("SpectrumAccumulator::mean: no image added");
    Image out(width_, height_, 1);
    for (size_t i = 0; i < sum_.size(); ++i) out.data()[i] = float(sum_[i] / count_);
    return out;
}

namespace {

// The mean of P over the samples binOf puts in each of `bins` bins (binOf
// returns −1 to leave a sample out; the zero frequency is never counted):
// (bin, mean) for the bins that received samples.
template <class BinOf>
std::vector<std::pair<int, double>> binnedMeans(const Image& spectrum, int bins, BinOf binOf) {
    const int w = spectrum.width(), h = spectrum.height();
    std::vector<double> sum(size_t(bins), 0.0), count(size_t(bins), 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (x == w / 2 && y == h / 2) continue;
            const Frequency f = frequencyOf(x, y, w, h);
            const int b = binOf(f, std::hypot(f.fx, f.fy));
            if (b < 0) continue;
            sum[size_t(b)] += spectrum.at(x, y);
            count[size_t(b)] += 1;
        }
    std::vector<std::pair<int, double>> out;
    for (int b = 0; b < bins; ++b)
        if (count[size_t(b)] > 0) out.emplace_back(b, sum[size_t(b)] / count[size_t(b)]);
    return out;
}

}  // namespace

RadialProfile radialProfile(const Image& spectrum, int bins) {
    checkSpectrum(spectrum, "radialProfile");
    if (bins < 1) throw std::invalid_argument("radialProfile: bins must be ≥ 1");
    RadialProfile p;
    // Bins narrower than a sample near 0 may stay empty: left out.
    for (const auto& [b, mean] : binnedMeans(spectrum, bins, [bins](const Frequency&, double r) {
             const int b = int(r / 0.5 * bins);
             return b < bins ? b : -1;
         })) {
        p.radius.push_back((b + 0.5) * 0.5 / bins);
        p.power.push_back(mean);
    }
    return p;
}

AngularProfile angularProfile(const Image& spectrum, int bins, double rMin, double rMax) {
    checkSpectrum(spectrum, "angularProfile");
    if (bins < 1) throw std::invalid_argument("angularProfile: bins must be ≥ 1");
    AngularProfile p;
    for (const auto& [b, mean] : binnedMeans(spectrum, bins, [=](const Frequency& f, double r) {
             if (r < rMin || r > rMax) return -1;
             return std::min(bins - 1, int(foldedAngle(f) / kPi * bins));
         })) {
        p.angleDeg.push_back((b + 0.5) * 180.0 / bins);
        p.power.push_back(mean);
    }
    return p;
}

SpectrumGeometry spectrumGeometry(const Image& spectrum, double rMin, double rMax) {
    checkSpectrum(spectrum, "spectrumGeometry");
    const int w = spectrum.width(), h = spectrum.height();
    double total = 0, mxx = 0, mxy = 0, myy = 0, radius = 0, peak = -1;
    SpectrumGeometry s;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (x == w / 2 && y == h / 2) continue;
            const Frequency f = frequencyOf(x, y, w, h);
            const double r = std::hypot(f.fx, f.fy);
            if (r < rMin || r > rMax) continue;
            const double p = spectrum.at(x, y);
            // With f_y up, so that orientations read counter-clockwise on screen.
            const double u = f.fx, v = -f.fy;
            total += p;
            mxx += p * u * u;
            mxy += p * u * v;
            myy += p * v * v;
            radius += p * r;
            if (p > peak) {
                peak = p;
                s.peakRadius = r;
                s.peakOrientationDeg = foldedAngle(f) * 180 / kPi;
            }
        }
    if (!(total > 0)) return s;  // a constant image: no shape
    mxx /= total, mxy /= total, myy /= total;
    const double mid = 0.5 * (mxx + myy), half = std::sqrt(0.25 * (mxx - myy) * (mxx - myy) + mxy * mxy);
    const double l1 = mid + half, l2 = mid - half;
    s.anisotropy = l2 > 0 ? l1 / l2 : std::numeric_limits<double>::infinity();
    double major = 0.5 * std::atan2(2 * mxy, mxx - myy);  // the major eigenvector's angle
    if (major < 0) major += kPi;
    s.orientationDeg = major * 180 / kPi;
    s.meanRadius = radius / total;
    const AngularProfile a = angularProfile(spectrum, 18, rMin, rMax);
    if (!a.power.empty()) {
        const auto [lo, hi] = std::minmax_element(a.power.begin(), a.power.end());
        s.angularMaxMin = *lo > 0 ? *hi / *lo : std::numeric_limits<double>::infinity();
    }
    return s;
}

Image logSpectrumImage(const Image& spectrum, double decades) {
    checkSpectrum(spectrum, "logSpectrumImage");
    const int w = spectrum.width(), h = spectrum.height();
    float ref = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (x != w / 2 || y != h / 2) ref = std::max(ref, spectrum.at(x, y));
    Image out(w, h, 1);
    if (!(ref > 0)) return out;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double p = spectrum.at(x, y);
            const double v = p > 0 ? 1.0 + std::log10(p / ref) / decades : 0.0;
            out.at(x, y) = float(std::clamp(v, 0.0, 1.0));
        }
    out.at(w / 2, h / 2) = 0.0f;
    return out;
}

}  // namespace stochtex
