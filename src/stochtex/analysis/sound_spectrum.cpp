#include "stochtex/analysis/sound_spectrum.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

#include "stochtex/core/error.h"

namespace stochtex {

SoundSpectrum soundSpectrum(const std::vector<float>& interleaved, int channels, double rate) {
    if (channels != 1 && channels != 2) throw InputError::parameter("channels", "a sound has 1 or 2 channels");
    if (!(std::isfinite(rate) && rate > 0 && rate <= 1e6))
        throw InputError::parameter("sampleRate", "must be in (0, 1e6] Hz, got " + formatValue(rate));
    const size_t n = interleaved.size() / size_t(channels);
    if (n < 64) throw InputError::parameter("sound", "needs at least 64 samples, got " + std::to_string(n));
    std::vector<double> mono(n);
    double sumSquares = 0;
    for (size_t i = 0; i < n; ++i) {
        double v = 0;
        for (int c = 0; c < channels; ++c) v += interleaved[i * size_t(channels) + size_t(c)];
        mono[i] = v / channels;
        sumSquares += mono[i] * mono[i];
    }
    // Segments of up to 8192 samples (5 Hz bins at 44.1 kHz), half overlapping.
    size_t segment = 64;
    while (segment * 2 <= std::min<size_t>(n, 8192)) segment *= 2;
    std::vector<double> window(segment);
    double windowPower = 0;
    constexpr double kPi = 3.14159265358979323846;
    for (size_t k = 0; k < segment; ++k) {
        window[k] = 0.5 - 0.5 * std::cos(2 * kPi * double(k) / double(segment));
        windowPower += window[k] * window[k];
    }
    const size_t bins = segment / 2 + 1;
    SoundSpectrum out;
    out.power.assign(bins, 0.0);
    int segments = 0;
    cv::Mat in(1, int(segment), CV_64F), spectrum;
    for (size_t start = 0; start + segment <= n; start += segment / 2, ++segments) {
        for (size_t k = 0; k < segment; ++k) in.at<double>(0, int(k)) = mono[start + k] * window[k];
        cv::dft(in, spectrum, cv::DFT_COMPLEX_OUTPUT);
        for (size_t b = 0; b < bins; ++b) {
            const cv::Vec2d z = spectrum.at<cv::Vec2d>(0, int(b));
            out.power[b] += (z[0] * z[0] + z[1] * z[1]) / windowPower;
        }
    }
    out.frequency.resize(bins);
    for (size_t b = 0; b < bins; ++b) {
        out.power[b] /= segments;
        out.frequency[b] = double(b) * rate / double(segment);
    }
    // The peak above the first bin, refined by the parabola through its neighbours.
    size_t peak = 1;
    for (size_t b = 2; b + 1 < bins; ++b)
        if (out.power[b] > out.power[peak]) peak = b;
    double offset = 0;
    if (peak > 0 && peak + 1 < bins) {
        const double a = std::log(out.power[peak - 1] + 1e-300), b = std::log(out.power[peak] + 1e-300),
                     c = std::log(out.power[peak + 1] + 1e-300);
        const double d = a - 2 * b + c;
        if (d < 0) offset = std::clamp(0.5 * (a - c) / d, -0.5, 0.5);
    }
    out.peakFrequency = (double(peak) + offset) * rate / double(segment);
    out.rms = std::sqrt(sumSquares / double(n));
    return out;
}

}  // namespace stochtex
