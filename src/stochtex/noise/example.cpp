#include "stochtex/noise/example.h"

#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace stochtex {

NoiseExample::NoiseExample(Image values, std::optional<HistogramTransform> inverse) : inverse_(std::move(inverse)) {
    if (values.channels() != 1 || values.width() != values.height() || values.width() < 2)
        throw std::invalid_argument("NoiseExample: needs a square 1-channel image of size >= 2");
    mean_ = float(channelStats(values).mean);
    grid_ = PeriodicGrid(std::move(values));
}

int nextPowerOfTwo(int n) {
    int p = 1;
    while (p < n) p *= 2;
    return p;
}

Image resamplePeriodic(const Image& example, int size, float lo, float hi) {
    if (example.channels() != 1 || example.width() != example.height() || size < 1)
        throw std::invalid_argument("resamplePeriodic: needs a square 1-channel example and a positive size");
    const int w = example.width();
    cv::Mat src(w, w, CV_32F, const_cast<float*>(example.data().data()));
    cv::Mat mapX(size, size, CV_32F), mapY(size, size, CV_32F);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            mapX.at<float>(y, x) = float((x + 0.5) * w / size - 0.5);
            mapY.at<float>(y, x) = float((y + 0.5) * w / size - 0.5);
        }
    cv::Mat dst;
    cv::remap(src, dst, mapX, mapY, cv::INTER_CUBIC, cv::BORDER_WRAP);
    Image out(size, size, 1);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) out.at(x, y) = std::clamp(dst.at<float>(y, x), lo, hi);
    return out;
}

}  // namespace stochtex
