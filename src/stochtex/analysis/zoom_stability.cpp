#include "stochtex/analysis/zoom_stability.h"

#include "stochtex/analysis/flicker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stochtex {

double compensatedZoomDifference(const Image& a, double sa, const Image& b, double sb) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels())
        throw std::invalid_argument("compensatedZoomDifference: frames differ in size");
    const double cx = 0.5 * a.width(), cy = 0.5 * a.height(), k = sa / sb;
    // Position of a's pixel centre in b's pixel coordinates.
    return warpedDifference(a, b, [&](int x, int y) {
        return std::array<double, 2>{cx + (x + 0.5 - cx) * k - 0.5, cy + (y + 0.5 - cy) * k - 0.5};
    });
}

double zoomSequenceScale(int k, int frames, double from, double to) {
    return frames < 2 ? from : from * std::pow(to / from, double(k) / double(frames - 1));
}

namespace {

void append(ZoomStability& z, double difference) {
    z.differences.push_back(difference);
    z.max = std::max(z.max, difference);
    z.mean += (difference - z.mean) / double(z.differences.size());
}

}  // namespace

void ZoomSequenceMeter::add(const Image& frame, const Image& truth, double scale) {
    if (frame.width() != truth.width() || frame.height() != truth.height() || frame.channels() != truth.channels())
        throw std::invalid_argument("ZoomSequenceMeter::add: the frame and its truth differ in size");
    Image error(frame.width(), frame.height(), frame.channels(), Image::Uninitialized{});
    double sum = 0;
    for (size_t i = 0; i < error.data().size(); ++i) {
        error.data()[i] = frame.data()[i] - truth.data()[i];
        sum += std::abs(double(error.data()[i]));
    }
    accuracy_.push_back(error.data().empty() ? 0.0 : sum / double(error.data().size()));
    if (!change_.scales.empty()) {
        const double previous = change_.scales.back();
        append(change_, compensatedZoomDifference(frame_, previous, frame, scale));
        append(flicker_, compensatedZoomDifference(error_, previous, error, scale));
    }
    change_.scales.push_back(scale);
    flicker_.scales.push_back(scale);
    frame_ = frame;
    error_ = std::move(error);
}

double orderedMean(const std::vector<double>& values) {
    double sum = 0;
    for (double v : values) sum += v;
    return values.empty() ? 0.0 : sum / double(values.size());
}

double ZoomSequenceMeter::meanAccuracy() const { return orderedMean(accuracy_); }

ZoomStability zoomStabilityOf(std::vector<double> scales, const std::vector<double>& differences) {
    ZoomStability z;
    z.scales = std::move(scales);
    for (double d : differences) append(z, d);
    return z;
}

ZoomStability measureZoomStability(const std::function<Image(double)>& render, int frames, double from, double to,
                                   const std::function<void(int)>& progress) {
    if (frames < 2) throw std::invalid_argument("measureZoomStability: need at least 2 frames");
    ZoomStability r;
    Image previous;
    for (int k = 0; k < frames; ++k) {
        const double s = zoomSequenceScale(k, frames, from, to);
        Image frame = render(s);
        if (k > 0) r.differences.push_back(compensatedZoomDifference(previous, r.scales.back(), frame, s));
        r.scales.push_back(s);
        previous = std::move(frame);
        if (progress) progress(k);
    }
    for (double d : r.differences) {
        r.mean += d;
        r.max = std::max(r.max, d);
    }
    r.mean /= double(r.differences.size());
    return r;
}

}  // namespace stochtex
