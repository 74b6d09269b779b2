#include "stochtex/analysis/optical_flow.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

constexpr double kPi = 3.14159265358979323846;

cv::Mat toGray8(const Image& image) {
    const Image g = toGray(image);
    cv::Mat m(g.height(), g.width(), CV_8UC1);
    for (int y = 0; y < g.height(); ++y)
        for (int x = 0; x < g.width(); ++x)
            m.at<uint8_t>(y, x) = uint8_t(std::lround(std::clamp(g.at(x, y), 0.0f, 1.0f) * 255.0f));
    return m;
}

void checkFrames(const Image& prev, const Image& next) {
    if (prev.width() != next.width() || prev.height() != next.height())
        throw InputError("optical flow: the frames differ in size (" + std::to_string(prev.width()) + "×" +
                         std::to_string(prev.height()) + " and " + std::to_string(next.width()) + "×" +
                         std::to_string(next.height()) + ")");
    if (prev.width() < 16 || prev.height() < 16)
        throw InputError("optical flow: frames must be at least 16×16 pixels, got " + std::to_string(prev.width()) +
                         "×" + std::to_string(prev.height()));
}

// Grid points at step/2 + k·step, at least `margin` from every border.
std::vector<cv::Point2f> gridPoints(int width, int height, int step, int margin) {
    if (step < 1) throw InputError::parameter("step", "must be ≥ 1, got " + std::to_string(step));
    std::vector<cv::Point2f> points;
    for (int y = step / 2; y < height; y += step)
        for (int x = step / 2; x < width; x += step)
            if (x >= margin && y >= margin && x < width - margin && y < height - margin)
                points.emplace_back(float(x), float(y));
    return points;
}

}  // namespace

Image denseFlow(const Image& prev, const Image& next, FlowMethod method) {
    checkFrames(prev, next);
    const cv::Mat a = toGray8(prev), b = toGray8(next);
    cv::Mat flow;
    switch (method) {
        case FlowMethod::Farneback:
            // OpenCV's documented defaults for video: 3 levels halving, 15-pixel
            // windows, 3 iterations, polynomials fitted over 5 pixels (σ 1.2).
            cv::calcOpticalFlowFarneback(a, b, flow, 0.5, 3, 15, 3, 5, 1.2, 0);
            break;
        case FlowMethod::Dis: {
            const cv::Ptr<cv::DISOpticalFlow> dis = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_MEDIUM);
            dis->calc(a, b, flow);
            break;
        }
        case FlowMethod::LucasKanade:
            throw std::invalid_argument("denseFlow: Lucas–Kanade is sparse (flowVectors)");
    }
    Image out(prev.width(), prev.height(), 2);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            const cv::Vec2f f = flow.at<cv::Vec2f>(y, x);
            out.at(x, y, 0) = f[0];
            out.at(x, y, 1) = f[1];
        }
    return out;
}

std::vector<FlowVector> sampleFlow(const Image& flow, int step, int margin) {
    if (flow.channels() != 2) throw std::invalid_argument("sampleFlow: needs a 2-channel flow field");
    std::vector<FlowVector> out;
    for (const cv::Point2f& p : gridPoints(flow.width(), flow.height(), step, margin)) {
        const int x = int(p.x), y = int(p.y);
        out.push_back({p.x, p.y, flow.at(x, y, 0), flow.at(x, y, 1)});
    }
    return out;
}

std::vector<FlowVector> flowVectors(const Image& prev, const Image& next, FlowMethod method, int step, int margin) {
    if (method != FlowMethod::LucasKanade) return sampleFlow(denseFlow(prev, next, method), step, margin);
    checkFrames(prev, next);
    const std::vector<cv::Point2f> points = gridPoints(prev.width(), prev.height(), step, margin);
    std::vector<FlowVector> out;
    if (points.empty()) return out;
    std::vector<cv::Point2f> found;
    std::vector<uint8_t> status;
    std::vector<float> error;
    cv::calcOpticalFlowPyrLK(toGray8(prev), toGray8(next), points, found, status, error, cv::Size(21, 21), 3);
    for (size_t i = 0; i < points.size(); ++i)
        if (status[i]) out.push_back({points[i].x, points[i].y, found[i].x - points[i].x, found[i].y - points[i].y});
    return out;
}

FlowSummary summariseFlow(const std::vector<FlowVector>& vectors, double cx, double cy) {
    FlowSummary s;
    double moving = 0, outward = 0, rr = 0, radialR = 0;
    for (const FlowVector& f : vectors) {
        const double dx = f.x - cx, dy = f.y - cy, r = std::hypot(dx, dy);
        const double magnitude = std::hypot(f.u, f.v);
        const double radial = r > 0 ? (f.u * dx + f.v * dy) / r : 0.0;
        s.meanU += f.u;
        s.meanV += f.v;
        s.meanMagnitude += magnitude;
        s.meanRadial += radial;
        if (magnitude >= 0.05) {
            moving += 1;
            if (radial > 0) outward += 1;
        }
        rr += r * r;
        radialR += radial * r;
        ++s.vectors;
    }
    if (s.vectors == 0) return s;
    const double n = s.vectors;
    s.meanU /= n, s.meanV /= n, s.meanMagnitude /= n, s.meanRadial /= n;
    s.outwardFraction = moving > 0 ? outward / moving : 0.0;
    s.expansionRate = rr > 0 ? radialR / rr : 0.0;
    return s;
}

Image flowColourImage(const Image& flow, double maxMagnitude) {
    if (flow.channels() != 2) throw std::invalid_argument("flowColourImage: needs a 2-channel flow field");
    if (maxMagnitude <= 0)
        for (int y = 0; y < flow.height(); ++y)
            for (int x = 0; x < flow.width(); ++x)
                maxMagnitude = std::max(maxMagnitude, std::hypot(double(flow.at(x, y, 0)), double(flow.at(x, y, 1))));
    cv::Mat hsv(flow.height(), flow.width(), CV_32FC3);
    for (int y = 0; y < flow.height(); ++y)
        for (int x = 0; x < flow.width(); ++x) {
            const double u = flow.at(x, y, 0), v = flow.at(x, y, 1);
            double hue = std::atan2(-v, u) * 180 / kPi;  // counter-clockwise on screen
            if (hue < 0) hue += 360;
            const double value = maxMagnitude > 0 ? std::min(1.0, std::hypot(u, v) / maxMagnitude) : 0.0;
            hsv.at<cv::Vec3f>(y, x) = {float(hue), 1.0f, float(value)};
        }
    cv::Mat rgb;
    cv::cvtColor(hsv, rgb, cv::COLOR_HSV2RGB);  // float HSV: H in degrees, S and V in [0, 1]
    Image out(flow.width(), flow.height(), 3);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x)
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = rgb.at<cv::Vec3f>(y, x)[c];
    return out;
}

Image flowArrowsImage(const Image& frame, const std::vector<FlowVector>& vectors, double scale) {
    const Image g = toGray(frame);
    cv::Mat canvas(g.height(), g.width(), CV_32FC3);
    for (int y = 0; y < g.height(); ++y)
        for (int x = 0; x < g.width(); ++x) {
            const float v = 0.25f + 0.5f * std::clamp(g.at(x, y), 0.0f, 1.0f);  // dimmed, so arrows stand out
            canvas.at<cv::Vec3f>(y, x) = {v, v, v};
        }
    for (const FlowVector& f : vectors) {
        const cv::Point2d from(f.x, f.y), to(f.x + scale * f.u, f.y + scale * f.v);
        if (std::hypot(to.x - from.x, to.y - from.y) < 0.5) {
            cv::circle(canvas, from, 1, cv::Scalar(1.0, 0.85, 0.0), cv::FILLED, cv::LINE_AA);
            continue;
        }
        cv::arrowedLine(canvas, from, to, cv::Scalar(1.0, 0.85, 0.0), 1, cv::LINE_AA, 0, 0.3);
    }
    Image out(g.width(), g.height(), 3);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x)
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = canvas.at<cv::Vec3f>(y, x)[c];
    return out;
}

}  // namespace stochtex
