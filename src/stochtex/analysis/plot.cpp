#include "stochtex/analysis/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

const cv::Scalar kInk(40, 40, 40), kGrid(225, 225, 225), kWhite(255, 255, 255);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

cv::Scalar bgr(const std::array<float, 3>& rgb) {
    return cv::Scalar(255.0 * rgb[2], 255.0 * rgb[1], 255.0 * rgb[0]);
}

void text(cv::Mat& m, const std::string& s, int x, int y, double scale = 0.4, bool centred = false) {
    int base = 0;
    const cv::Size sz = cv::getTextSize(s, kFont, scale, 1, &base);
    cv::putText(m, s, cv::Point(centred ? x - sz.width / 2 : x, y), kFont, scale, kInk, 1, cv::LINE_AA);
}

void verticalText(cv::Mat& m, const std::string& s, int x, int cy) {
    int base = 0;
    const cv::Size sz = cv::getTextSize(s, kFont, 0.4, 1, &base);
    cv::Mat t(sz.height + base + 2, sz.width + 2, CV_8UC3, kWhite);
    cv::putText(t, s, cv::Point(1, sz.height), kFont, 0.4, kInk, 1, cv::LINE_AA);
    cv::Mat r;
    cv::rotate(t, r, cv::ROTATE_90_COUNTERCLOCKWISE);
    const int y0 = std::clamp(cy - r.rows / 2, 0, std::max(0, m.rows - r.rows));
    const int x0 = std::clamp(x, 0, std::max(0, m.cols - r.cols));
    r.copyTo(m(cv::Rect(x0, y0, std::min(r.cols, m.cols - x0), std::min(r.rows, m.rows - y0))));
}

std::string number(double v) {
    char buf[32];
    if (v != 0 && (std::abs(v) >= 1e4 || std::abs(v) < 1e-2)) std::snprintf(buf, sizeof buf, "%.0e", v);
    else std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

// About five round tick values covering [lo, hi].
std::vector<double> ticks(double lo, double hi) {
    std::vector<double> t;
    if (!(hi > lo)) return {lo};
    const double raw = (hi - lo) / 5.0;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (raw <= m * mag) {
            step = m * mag;
            break;
        }
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) t.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
    return t;
}

std::vector<double> logTicks(double lo, double hi) {
    std::vector<double> t;
    for (double e = std::floor(std::log10(lo)); e <= std::ceil(std::log10(hi)); e += 1.0) {
        const double v = std::pow(10.0, e);
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) t.push_back(v);
    }
    if (t.size() < 2) {  // a narrow range: powers of two instead
        t.clear();
        for (double e = std::ceil(std::log2(lo) - 1e-9); e <= std::floor(std::log2(hi) + 1e-9); e += 1.0) t.push_back(std::exp2(e));
    }
    return t;
}

std::array<uchar, 3> paletteBgr(HeatPalette p, double t) {
    t = std::clamp(t, 0.0, 1.0);
    if (p == HeatPalette::Diverging) {
        // blue (0) – white (½) – red (1), linear in RGB on each side
        const std::array<double, 3> blue{0.23, 0.30, 0.75}, red{0.75, 0.10, 0.15};
        const auto& end = t < 0.5 ? blue : red;
        const double a = t < 0.5 ? 1.0 - 2.0 * t : 2.0 * t - 1.0;  // 0 at white, 1 at the ends
        std::array<uchar, 3> out{};
        for (size_t k = 0; k < 3; ++k) out[2 - k] = uchar(std::lround(255.0 * (1.0 + a * (end[k] - 1.0))));
        return out;
    }
    cv::Mat one(1, 1, CV_8UC1, cv::Scalar(std::lround(255 * t))), out;
    cv::applyColorMap(one, out, cv::COLORMAP_VIRIDIS);
    const cv::Vec3b c = out.at<cv::Vec3b>(0, 0);
    return {c[0], c[1], c[2]};
}

Image fromBgr(const cv::Mat& m) {
    Image out(m.cols, m.rows, 3, Image::Uninitialized{});
    for (int y = 0; y < m.rows; ++y)
        for (int x = 0; x < m.cols; ++x) {
            const cv::Vec3b c = m.at<cv::Vec3b>(y, x);
            for (int k = 0; k < 3; ++k) out.at(x, y, k) = float(c[2 - k]) / 255.0f;
        }
    return out;
}

}  // namespace

Image heatmapPlot(const Image& values, const HeatmapOptions& o) {
    if (values.channels() != 1 || values.empty()) throw std::invalid_argument("heatmapPlot: 1-channel values needed");
    const int w = values.width(), h = values.height();
    const int cell = o.cell > 0 ? o.cell : std::max(1, 512 / std::max(w, h));
    const int pw = w * cell, ph = h * cell;
    const int left = 62, right = 90, top = 30, bottom = 46;
    cv::Mat m(ph + top + bottom, pw + left + right, CV_8UC3, kWhite);
    const double span = o.vmax - o.vmin;
    std::vector<std::array<uchar, 3>> lut(256);
    for (int i = 0; i < 256; ++i) lut[size_t(i)] = paletteBgr(o.palette, i / 255.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double v = values.at(x, y);
            const double t = span > 0 ? (v - o.vmin) / span : 0.5;
            const auto c = std::isfinite(v) ? lut[size_t(std::clamp(int(std::lround(255 * t)), 0, 255))]
                                            : std::array<uchar, 3>{128, 128, 128};
            const int row = o.yUp ? h - 1 - y : y;
            cv::rectangle(m, cv::Rect(left + x * cell, top + row * cell, cell, cell), cv::Scalar(c[0], c[1], c[2]),
                          cv::FILLED);
        }
    cv::rectangle(m, cv::Rect(left - 1, top - 1, pw + 2, ph + 2), kInk, 1);
    for (double t : ticks(o.xMin, o.xMax)) {
        const int x = left + int(std::lround((t - o.xMin) / (o.xMax - o.xMin) * pw));
        cv::line(m, {x, top + ph}, {x, top + ph + 4}, kInk);
        text(m, number(t), x, top + ph + 16, 0.35, true);
    }
    for (double t : ticks(o.yMin, o.yMax)) {
        const double f = (t - o.yMin) / (o.yMax - o.yMin);
        const int y = top + int(std::lround(o.yUp ? (1 - f) * ph : f * ph));
        cv::line(m, {left - 4, y}, {left, y}, kInk);
        int base = 0;
        const cv::Size sz = cv::getTextSize(number(t), kFont, 0.35, 1, &base);
        text(m, number(t), left - 6 - sz.width, y + 4, 0.35);
    }
    text(m, o.title, left + pw / 2, 20, 0.45, true);
    text(m, o.xLabel, left + pw / 2, top + ph + 36, 0.4, true);
    verticalText(m, o.yLabel, 4, top + ph / 2);
    // Colour legend.
    const int lx = left + pw + 18, lw = 16;
    for (int y = 0; y < ph; ++y) {
        const auto c = lut[size_t(std::clamp(int(std::lround(255.0 * (1.0 - double(y) / std::max(1, ph - 1)))), 0, 255))];
        cv::line(m, {lx, top + y}, {lx + lw, top + y}, cv::Scalar(c[0], c[1], c[2]));
    }
    cv::rectangle(m, cv::Rect(lx, top, lw, ph), kInk, 1);
    for (double t : ticks(o.vmin, o.vmax)) {
        const int y = top + int(std::lround((1.0 - (t - o.vmin) / span) * (ph - 1)));
        cv::line(m, {lx + lw, y}, {lx + lw + 4, y}, kInk);
        text(m, number(t), lx + lw + 6, y + 4, 0.35);
    }
    return fromBgr(m);
}

Image colourise(const Image& values, double vmin, double vmax, HeatPalette palette) {
    Image out(values.width(), values.height(), 3, Image::Uninitialized{});
    std::vector<std::array<uchar, 3>> lut(256);
    for (int i = 0; i < 256; ++i) lut[size_t(i)] = paletteBgr(palette, i / 255.0);
    const double span = vmax - vmin;
    for (int y = 0; y < values.height(); ++y)
        for (int x = 0; x < values.width(); ++x) {
            const double t = span > 0 ? (values.at(x, y) - vmin) / span : 0.5;
            const auto c = lut[size_t(std::clamp(int(std::lround(255 * t)), 0, 255))];
            for (int k = 0; k < 3; ++k) out.at(x, y, k) = float(c[size_t(2 - k)]) / 255.0f;
        }
    return out;
}

Image colourLegend(double vmin, double vmax, HeatPalette palette, const std::string& title, int width) {
    const int left = 20, barW = width - 2 * left, top = 24, barH = 14;
    cv::Mat m(top + barH + 24, width, CV_8UC3, kWhite);
    for (int x = 0; x < barW; ++x) {
        const auto c = paletteBgr(palette, double(x) / std::max(1, barW - 1));
        cv::line(m, {left + x, top}, {left + x, top + barH}, cv::Scalar(c[0], c[1], c[2]));
    }
    cv::rectangle(m, cv::Rect(left, top, barW, barH), kInk, 1);
    for (double t : ticks(vmin, vmax)) {
        const int x = left + int(std::lround((t - vmin) / (vmax - vmin) * (barW - 1)));
        cv::line(m, {x, top + barH}, {x, top + barH + 4}, kInk);
        text(m, number(t), x, top + barH + 16, 0.35, true);
    }
    text(m, title, width / 2, 16, 0.42, true);
    return fromBgr(m);
}

Image linePlot(const std::vector<PlotSeries>& series, const LinePlotOptions& o) {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const auto& s : series)
        for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            if (o.logX && !(s.x[i] > 0)) continue;
            if (o.logY && !(s.y[i] > 0)) continue;
            x0 = std::min(x0, s.x[i]);
            x1 = std::max(x1, s.x[i]);
            y0 = std::min(y0, s.y[i]);
            y1 = std::max(y1, s.y[i]);
        }
    if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    if (std::isfinite(o.xMin)) x0 = o.xMin;
    if (std::isfinite(o.xMax)) x1 = o.xMax;
    if (std::isfinite(o.yMin)) y0 = o.yMin;
    if (std::isfinite(o.yMax)) y1 = o.yMax;
    if (!std::isfinite(o.yMin) && !o.logY) y0 = std::min(y0, 0.0);
    if (!(x1 > x0)) x1 = x0 + (o.logX ? x0 : 1.0);
    if (!(y1 > y0)) y1 = y0 + (o.logY ? y0 : 1.0);
    if (!std::isfinite(o.yMax) && !o.logY) y1 += 0.05 * (y1 - y0);
    const int left = 64, right = 16, top = 30, bottom = 46;
    const int pw = o.width - left - right, ph = o.height - top - bottom;
    cv::Mat m(o.height, o.width, CV_8UC3, kWhite);
    auto fx = [&](double x) {
        const double t = o.logX ? (std::log(x) - std::log(x0)) / (std::log(x1) - std::log(x0)) : (x - x0) / (x1 - x0);
        return left + int(std::lround(t * pw));
    };
    auto fy = [&](double y) {
        const double t = o.logY ? (std::log(y) - std::log(y0)) / (std::log(y1) - std::log(y0)) : (y - y0) / (y1 - y0);
        return top + int(std::lround((1.0 - std::clamp(t, -0.02, 1.02)) * ph));
    };
    for (const auto& b : o.bands) {
        const int a = std::clamp(fx(b[0]), left, left + pw), c = std::clamp(fx(b[1]), left, left + pw);
        cv::rectangle(m, cv::Rect(std::min(a, c), top, std::abs(c - a) + 1, ph), cv::Scalar(200, 200, 255), cv::FILLED);
    }
    for (double t : o.logX ? logTicks(x0, x1) : ticks(x0, x1)) {
        const int x = fx(t);
        cv::line(m, {x, top}, {x, top + ph}, kGrid);
        text(m, number(t), x, top + ph + 16, 0.35, true);
    }
    for (double t : o.logY ? logTicks(y0, y1) : ticks(y0, y1)) {
        const int y = fy(t);
        cv::line(m, {left, y}, {left + pw, y}, kGrid);
        int base = 0;
        const cv::Size sz = cv::getTextSize(number(t), kFont, 0.35, 1, &base);
        text(m, number(t), left - 6 - sz.width, y + 4, 0.35);
    }
    cv::rectangle(m, cv::Rect(left, top, pw, ph), kInk, 1);
    int legendY = top + 14;
    for (const auto& s : series) {
        const cv::Scalar col = bgr(s.colour);
        const size_t n = std::min(s.x.size(), s.y.size());
        if (s.bars && n > 0) {
            const double step = n > 1 ? (s.x[1] - s.x[0]) : 1.0;
            for (size_t i = 0; i < n; ++i) {
                const int a = fx(s.x[i] - 0.5 * step), b = fx(s.x[i] + 0.5 * step);
                const int yv = fy(s.y[i]), yb = fy(o.logY ? y0 : std::max(y0, 0.0));
                cv::rectangle(m, cv::Rect(std::min(a, b), std::min(yv, yb), std::max(1, std::abs(b - a)),
                                          std::max(1, std::abs(yb - yv))),
                              col, cv::FILLED);
            }
        } else {
            std::vector<cv::Point> pts;
            for (size_t i = 0; i < n; ++i) {
                if (!std::isfinite(s.y[i]) || (o.logY && !(s.y[i] > 0)) || (o.logX && !(s.x[i] > 0))) continue;
                pts.push_back({fx(s.x[i]), fy(s.y[i])});
            }
            if (pts.size() > 1) cv::polylines(m, pts, false, col, 2, cv::LINE_AA);
            if (n <= 16)
                for (const auto& p : pts) cv::circle(m, p, 3, col, cv::FILLED, cv::LINE_AA);
        }
        if (!s.name.empty()) {
            cv::line(m, {left + pw - 150, legendY - 4}, {left + pw - 130, legendY - 4}, col, 3);
            text(m, s.name, left + pw - 124, legendY, 0.35);
            legendY += 14;
        }
    }
    text(m, o.title, left + pw / 2, 20, 0.45, true);
    text(m, o.xLabel, left + pw / 2, top + ph + 36, 0.4, true);
    verticalText(m, o.yLabel, 4, top + ph / 2);
    return fromBgr(m);
}

std::vector<double> histogram(const Image& image, int bins, double lo, double hi) {
    std::vector<double> h(static_cast<size_t>(bins), 0.0);
    const size_t n = image.pixelCount();
    for (size_t i = 0; i < n; ++i) {
        const double v = image.data()[i * size_t(image.channels())];
        const int b = std::clamp(int((v - lo) / (hi - lo) * bins), 0, bins - 1);
        h[size_t(b)] += 1.0;
    }
    for (double& v : h) v /= double(std::max<size_t>(n, 1));
    return h;
}

Image sheet(const std::vector<std::vector<Image>>& rows, const std::vector<std::vector<std::string>>& captions) {
    const int pad = 10, captionH = 20;
    int width = pad, height = pad;
    for (const auto& r : rows) {
        int w = pad, h = 0;
        for (const auto& im : r) {
            w += im.width() + pad;
            h = std::max(h, im.height());
        }
        width = std::max(width, w);
        height += h + captionH + pad;
    }
    Image out(width, height, 3, 1.0f);
    cv::Mat canvas(height, width, CV_8UC3, kWhite);
    int y = pad;
    for (size_t r = 0; r < rows.size(); ++r) {
        int x = pad, h = 0;
        for (size_t c = 0; c < rows[r].size(); ++c) {
            const Image& im = rows[r][c];
            paste(out, toRgb(im), x, y);
            if (r < captions.size() && c < captions[r].size()) {
                text(canvas, captions[r][c], x + im.width() / 2, y + im.height() + 15, 0.4, true);
            }
            x += im.width() + pad;
            h = std::max(h, im.height());
        }
        y += h + captionH + pad;
    }
    // Captions were drawn on a white canvas: copy their ink over.
    for (int yy = 0; yy < height; ++yy)
        for (int xx = 0; xx < width; ++xx) {
            const cv::Vec3b c = canvas.at<cv::Vec3b>(yy, xx);
            if (c[0] != 255 || c[1] != 255 || c[2] != 255)
                for (int k = 0; k < 3; ++k) out.at(xx, yy, k) = float(c[2 - k]) / 255.0f;
        }
    return out;
}

}  // namespace stochtex
