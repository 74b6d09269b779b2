#include "stochtex/noise/spectrum.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "stochtex/core/budget.h"
#include "stochtex/core/error.h"
#include "stochtex/noise/normal.h"

namespace stochtex {

namespace {

struct Direction {
    double u, v;
};

Direction waveDirection(double degrees) {
    const double t = degrees * std::numbers::pi / 180.0;
    return {std::cos(t), -std::sin(t)};
}

double componentPower(const SpectrumComponent& c, double fu, double fv) {
    const double r = std::hypot(fu, fv);
    switch (c.shape) {
        case SpectrumShape::LowPass: return std::exp(-0.5 * (r * r) / (c.frequency * c.frequency));
        case SpectrumShape::Ring: {
            const double t = (r - c.frequency) / c.bandwidth;
            return std::exp(-0.5 * t * t);
        }
        case SpectrumShape::BiLobe: {
            const Direction d = waveDirection(c.orientation);
            const double cu = c.frequency * d.u, cv = c.frequency * d.v;
            const double b2 = c.bandwidth * c.bandwidth;
            const double p = (fu - cu) * (fu - cu) + (fv - cv) * (fv - cv);
            const double m = (fu + cu) * (fu + cu) + (fv + cv) * (fv + cv);
            return std::exp(-0.5 * p / b2) + std::exp(-0.5 * m / b2);
        }
    }
    return 0.0;
}

// Shifts and scales to the requested mean/std, then clamps to [0,1]. The
// clamp shrinks the spread, so the gain and shift are re-fitted a few times
// until the clamped values themselves have the requested moments.
void normalizeAndClamp(std::vector<double>& values, double mean, double stddev, Image& out) {
    double m = 0, s = 0;
    for (double v : values) m += v;
    m /= double(values.size());
    for (double v : values) s += (v - m) * (v - m);
    s = std::sqrt(s / double(values.size()));
    if (s <= 0) s = 1;
    double gain = stddev / s, shift = mean;
    float* dst = out.data().data();
    for (int iter = 0; iter < 6; ++iter) {
        double cm = 0, c2 = 0;
        for (size_t i = 0; i < values.size(); ++i) {
            const double v = std::clamp(shift + gain * (values[i] - m), 0.0, 1.0);
            dst[i] = float(v);
            cm += v;
            c2 += v * v;
        }
        cm /= double(values.size());
        const double cs = std::sqrt(std::max(0.0, c2 / double(values.size()) - cm * cm));
        if (std::abs(cs - stddev) < 1e-5 && std::abs(cm - mean) < 1e-5) break;
        if (cs > 0) gain *= stddev / cs;
        shift += mean - cm;
    }
}

}  // namespace

double spectrumPower(const SpectrumSpec& spec, double fu, double fv) {
    double p = 0.0;
    for (const auto& c : spec.components) p += c.weight * componentPower(c, fu, fv);
    return p;
}

void validateSpectrumWork(const SpectrumSpec& spec) {
    const long long n = spec.size, work = (long long)spec.components.size() * n * n;
    if (work > budgeted(kMaxSpectrumWork))
        throw InputError::overBudget("components", "components × size² must be at most " +
                                                       std::to_string(budgeted(kMaxSpectrumWork)) + ", got " +
                                                       std::to_string(spec.components.size()) + " × " +
                                                       std::to_string(n) + "² = " + std::to_string(work));
}

Image synthesizeExample(const SpectrumSpec& spec) {
    const int n = spec.size;
    if (n < 2 || n > kMaxExampleSize) throw std::invalid_argument("synthesizeExample: bad size");
    validateSpectrumWork(spec);
    // White noise → spectrum.
    cv::Mat field(n, n, CV_64FC2);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            field.at<cv::Vec2d>(y, x) = {hashedGaussian(uint32_t(x), uint32_t(y), spec.seed), 0.0};
    cv::dft(field, field, cv::DFT_COMPLEX_OUTPUT);

    Direction hilbert{1.0, 0.0};
    for (const auto& c : spec.components)
        if (c.shape == SpectrumShape::BiLobe) {
            hilbert = waveDirection(c.orientation);
            break;
        }

    for (int y = 0; y < n; ++y) {
        const double fv = fftFrequency(y, n);
        for (int x = 0; x < n; ++x) {
            const double fu = fftFrequency(x, n);
            cv::Vec2d& z = field.at<cv::Vec2d>(y, x);
            const double a = (x == 0 && y == 0) ? 0.0 : std::sqrt(std::max(0.0, spectrumPower(spec, fu, fv)));
            double re = z[0] * a, im = z[1] * a;
            if (spec.quadrature) {
                // Multiply by −i·sign(f·d): the real part of the inverse FFT
                // becomes the Hilbert transform along d.
                const double s = fu * hilbert.u + fv * hilbert.v;
                const double sign = s > 1e-12 ? 1.0 : (s < -1e-12 ? -1.0 : 0.0);
                const double nre = sign * im, nim = -sign * re;
                re = nre;
                im = nim;
            }
            z = {re, im};
        }
    }
    cv::dft(field, field, cv::DFT_INVERSE | cv::DFT_SCALE | cv::DFT_COMPLEX_OUTPUT);

    std::vector<double> values(size_t(n) * size_t(n));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) values[size_t(y) * size_t(n) + size_t(x)] = field.at<cv::Vec2d>(y, x)[0];
    Image out(n, n, 1);
    normalizeAndClamp(values, spec.mean, spec.stddev, out);
    return out;
}

Image powerSpectrum(const Image& example) {
    if (example.channels() != 1 || example.width() != example.height())
        throw std::invalid_argument("powerSpectrum: needs a square 1-channel image");
    const int n = example.width();
    const ChannelStats stats = channelStats(example);
    cv::Mat field(n, n, CV_64FC2);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) field.at<cv::Vec2d>(y, x) = {example.at(x, y) - stats.mean, 0.0};
    cv::dft(field, field, cv::DFT_COMPLEX_OUTPUT);
    Image power(n, n, 1);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const cv::Vec2d z = field.at<cv::Vec2d>(y, x);
            power.at(x, y) = float(z[0] * z[0] + z[1] * z[1]);
        }
    return power;
}

}  // namespace stochtex

namespace stochtex {
Image displaySpectrum(const Image& power) {
    const int n = power.width();
    float maxP = 0.0f;
    for (float p : power.data()) maxP = std::max(maxP, p);
    Image out(n, n, 1);
    if (maxP <= 0.0f) return out;
    const double k = 1e4;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int sx = (x + n / 2) % n, sy = (y + n / 2) % n;
            out.at(sx, sy) = float(std::log1p(k * power.at(x, y) / maxP) / std::log1p(k));
        }
    return out;
}
}  // namespace stochtex
