#include "stochtex/noise/slopes.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/noise/spectrum.h"

namespace stochtex {

std::array<Image, 2> spectralSlopes(const Image& height) {
    if (height.channels() != 1 || height.width() != height.height())
        throw std::invalid_argument("spectralSlopes: needs a square 1-channel image");
    const int n = height.width();
    cv::Mat spectrum(n, n, CV_64FC2);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) spectrum.at<cv::Vec2d>(y, x) = {double(height.at(x, y)), 0.0};
    cv::dft(spectrum, spectrum, cv::DFT_COMPLEX_OUTPUT);
    std::array<Image, 2> out{Image(n, n, 1), Image(n, n, 1)};
    for (int axis = 0; axis < 2; ++axis) {
        // d/dx e^{iωx} = iω e^{iωx}, ω = 2πk/W per texel.
        cv::Mat d(n, n, CV_64FC2);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const int k = axis == 0 ? x : y;
                const bool nyquist = 2 * k == n;
                const double w = nyquist ? 0.0 : 2.0 * std::numbers::pi * fftFrequency(k, n) / n;
                const cv::Vec2d z = spectrum.at<cv::Vec2d>(y, x);
                d.at<cv::Vec2d>(y, x) = {-w * z[1], w * z[0]};
            }
        cv::dft(d, d, cv::DFT_INVERSE | cv::DFT_SCALE | cv::DFT_COMPLEX_OUTPUT);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) out[size_t(axis)].at(x, y) = float(d.at<cv::Vec2d>(y, x)[0]);
    }
    return out;
}

TiledField slopeField(const Image& height, double rmsSlope, uint32_t offsetSeed, const GridLayout& grid) {
    if (!(std::isfinite(rmsSlope) && rmsSlope > 0))
        throw InputError::parameter("amplitude", "must be finite and positive, got " + formatValue(rmsSlope));
    std::array<Image, 2> s = spectralSlopes(height);
    double sum2 = 0;
    for (const Image& img : s)
        for (const float v : img.data()) sum2 += double(v) * v;
    const double rms = std::sqrt(sum2 / (2.0 * double(height.width()) * height.height()));
    if (!(rms > 0)) throw InputError::parameter("amplitude", "cannot scale a flat height example (its slopes are 0)");
    const float k = float(rmsSlope / rms);
    std::vector<TilingBlendingNoise> channels;
    for (Image& img : s) {
        for (float& v : img.data()) v *= k;
        channels.emplace_back(std::make_shared<const NoiseExample>(std::move(img)), offsetSeed);
    }
    return TiledField(std::move(channels), grid, OffsetSharing::Shared);
}

}  // namespace stochtex
