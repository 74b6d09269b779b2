#include "stochtex/image/image.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "stochtex/core/error.h"

namespace stochtex {

void* allocateBulk(size_t bytes) {
    constexpr size_t kHugePage = size_t(2) << 20;
    void* p = nullptr;
    if (bytes > SIZE_MAX - kHugePage) throw std::bad_alloc();
    if (bytes >= kHugePage) {
        const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        p = std::aligned_alloc(kHugePage, rounded);
        if (p) madvise(p, rounded, MADV_HUGEPAGE);  // advice only: without THP the pages stay 4 KiB
    } else {
        p = std::malloc(bytes == 0 ? 1 : bytes);
    }
    if (!p) throw std::bad_alloc();
    return p;
}

void freeBulk(void* p) noexcept { std::free(p); }

Image::Image(int width, int height, int channels, Uninitialized)
    : width_(width), height_(height), channels_(channels) {
    if (width < 0 || height < 0 || channels <= 0 || channels > 4)
        throw std::invalid_argument("Image: invalid dimensions");
    data_.resize(size_t(width) * size_t(height) * size_t(channels));
}

Image::Image(int width, int height, int channels, float fill) : Image(width, height, channels, Uninitialized{}) {
    std::fill(data_.begin(), data_.end(), fill);
}

Image toRgb(const Image& image) {
    if (image.channels() == 3) return image;
    Image out(image.width(), image.height(), 3);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < 3; ++c)
                out.at(x, y, c) = image.at(x, y, image.channels() == 1 ? 0 : std::min(c, image.channels() - 1));
    return out;
}

Image toGray(const Image& image) {
    if (image.channels() == 1) return image;
    Image out(image.width(), image.height(), 1);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            out.at(x, y) = image.channels() == 2
                               ? 0.5f * (image.at(x, y, 0) + image.at(x, y, 1))
                               : 0.21f * image.at(x, y, 0) + 0.72f * image.at(x, y, 1) + 0.07f * image.at(x, y, 2);
    return out;
}

Image channelOf(const Image& image, int c) {
    if (c < 0 || c >= image.channels())
        throw std::out_of_range("channelOf: no channel " + std::to_string(c) + " in an image of " +
                                std::to_string(image.channels()));
    Image out(image.width(), image.height(), 1, Image::Uninitialized{});
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) out.at(x, y) = image.at(x, y, c);
    return out;
}

Image shiftedPeriodic(const Image& image, int dx, int dy) {
    const int w = image.width(), h = image.height(), c = image.channels();
    Image out(w, h, c, Image::Uninitialized{});
    if (w == 0 || h == 0) return out;
    const int ox = ((dx % w) + w) % w, oy = ((dy % h) + h) % h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int k = 0; k < c; ++k) out.at(x, y, k) = image.at((x + ox) % w, (y + oy) % h, k);
    return out;
}

namespace {
cv::Mat wrap(const Image& image) {
    return cv::Mat(image.height(), image.width(), CV_32FC(image.channels()),
                   const_cast<float*>(image.data().data()));
}
}  // namespace

Image resizeNearest(const Image& image, int width, int height) {
    Image out(width, height, image.channels());
    cv::Mat dst = wrap(out);
    cv::resize(wrap(image), dst, cv::Size(width, height), 0, 0, cv::INTER_NEAREST);
    return out;
}

Image resizeSmooth(const Image& image, int width, int height) {
    Image out(width, height, image.channels());
    cv::Mat dst = wrap(out);
    const bool shrink = width < image.width() || height < image.height();
    cv::resize(wrap(image), dst, cv::Size(width, height), 0, 0, shrink ? cv::INTER_AREA : cv::INTER_LINEAR);
    return out;
}

Image crop(const Image& image, int x, int y, int width, int height) {
    if (x < 0 || y < 0 || width < 0 || height < 0 || x + width > image.width() || y + height > image.height())
        throw std::out_of_range("crop: the region leaves the image");
    Image out(width, height, image.channels(), Image::Uninitialized{});
    const size_t c = size_t(image.channels());
    for (int j = 0; j < height; ++j)
        std::copy_n(image.row(y + j) + size_t(x) * c, size_t(width) * c, out.row(j));
    return out;
}

void paste(Image& dst, const Image& src, int x, int y) {
    if (src.channels() != dst.channels()) throw std::invalid_argument("paste: channel mismatch");
    for (int j = 0; j < src.height(); ++j) {
        const int ty = y + j;
        if (ty < 0 || ty >= dst.height()) continue;
        for (int i = 0; i < src.width(); ++i) {
            const int tx = x + i;
            if (tx < 0 || tx >= dst.width()) continue;
            for (int c = 0; c < src.channels(); ++c) dst.at(tx, ty, c) = src.at(i, j, c);
        }
    }
}

void drawLabel(Image& image, int x, int y, int width, const char* text) {
    cv::Mat m = wrap(image);
    const int strip = 18;
    const cv::Rect rect(x, std::max(0, y - strip), width, strip);
    cv::Mat region = m(rect & cv::Rect(0, 0, image.width(), image.height()));
    region *= 0.35;
    cv::putText(m, text, cv::Point(x + 4, y - 5), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar::all(1.0), 1,
                cv::LINE_AA);
}

ChannelStats channelStats(const Image& image, int channel) {
    double sum = 0.0, sum2 = 0.0;
    const size_t n = image.pixelCount();
    const int stride = image.channels();
    const float* p = image.data().data() + channel;
    for (size_t i = 0; i < n; ++i) {
        const double v = p[i * size_t(stride)];
        sum += v;
        sum2 += v * v;
    }
    ChannelStats s;
    if (n == 0) return s;
    s.mean = sum / double(n);
    s.stddev = std::sqrt(std::max(0.0, sum2 / double(n) - s.mean * s.mean));
    return s;
}

void checkPixelRange(const Image& img, const std::string& file, double lo, double hi, const std::string& what) {
    for (int y = 0; y < img.height(); ++y) {
        const float* row = img.row(y);
        for (int i = 0; i < img.width() * img.channels(); ++i)
            if (!(row[i] >= lo && row[i] <= hi))
                throw InputError(file + ": pixel (" + std::to_string(i / img.channels()) + ", " + std::to_string(y) +
                                 ") channel " + std::to_string(i % img.channels()) + " is " + formatValue(row[i]) +
                                 "; " + what + " values must be in [" + formatValue(lo) + ", " + formatValue(hi) + "]");
    }
}

}  // namespace stochtex
