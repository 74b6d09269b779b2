#pragma once
// Flicker: change from one frame to the next that motion does not explain
// (thesis §2.1: texture features blinking as a condition crosses its
// limit). The next frame is warped back onto the previous one, by a known
// motion (a zoom about the centre, zoom_stability.h) or by the dense
// optical flow between them, and the warped frames' difference is what
// remains. A flat frame has nothing to flicker and a blurred one little, so
// the residual is reported beside the frames' contrast and relative to it:
// blur lowers both, and a constant grey frame is no flicker-free winner but
// a frame with no contrast (its relative flicker is undefined, NaN). The
// flow may explain part of a blink as motion (an inverted texture looks
// like one moved by half its period), so a blink reads below its full size:
// the measure ranks sequences, it does not recover the blink's amplitude.
#include <array>
#include <cmath>
#include <stdexcept>

#include "stochtex/image/image.h"

namespace stochtex {

// Mean over pixels and channels of |a(p) − b(q)|, q = position(x, y) the
// place of a's pixel (x, y) in b's pixel coordinates (pixel centres at
// integers), b read bilinearly; pixels whose q lies outside b are left out.
// perPixel (if given) gets each pixel's mean over channels, NaN outside.
template <class Position>
double warpedDifference(const Image& a, const Image& b, Position&& position, Image* perPixel = nullptr) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels())
        throw std::invalid_argument("warpedDifference: frames differ in size");
    if (perPixel) *perPixel = Image(a.width(), a.height(), 1, std::nanf(""));
    double sum = 0;
    size_t count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const std::array<double, 2> q = position(x, y);
            const double bx = q[0], by = q[1];
            if (!(bx >= 0 && by >= 0 && bx <= b.width() - 1 && by <= b.height() - 1)) continue;
            const int x0 = std::min(int(bx), b.width() - 2), y0 = std::min(int(by), b.height() - 2);
            const double tx = bx - x0, ty = by - y0;
            double pixel = 0;
            for (int c = 0; c < a.channels(); ++c) {
                const double top = b.at(x0, y0, c) + tx * (b.at(x0 + 1, y0, c) - b.at(x0, y0, c));
                const double bottom = b.at(x0, y0 + 1, c) + tx * (b.at(x0 + 1, y0 + 1, c) - b.at(x0, y0 + 1, c));
                pixel += std::abs(a.at(x, y, c) - (top + ty * (bottom - top)));
            }
            sum += pixel;
            if (perPixel) perPixel->at(x, y) = float(pixel / a.channels());
            ++count;
        }
    return count ? sum / double(count * size_t(a.channels())) : 0.0;
}

// Below a thousandth of the code range a frame has nothing to see flicker:
// residual / contrast, or NaN under that contrast.
double relativeFlicker(double residual, double contrast);

struct FlickerMeasure {
    double residual = 0;  // mean |previous − next warped back by the flow| (gray)
    double contrast = 0;  // mean of the two frames' gray standard deviations
    double relative = 0;  // residual / contrast; NaN for frames without contrast
};
// The flicker from `previous` to `next` (same size, ≥ 16 a side; gray by
// the thesis's luminosity): DIS dense flow from previous to next, next
// read at p + flow(p). residualMap (if given): the per-pixel residual.
FlickerMeasure flowCompensatedFlicker(const Image& previous, const Image& next, Image* residualMap = nullptr);

}  // namespace stochtex
