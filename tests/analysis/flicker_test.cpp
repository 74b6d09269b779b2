// The flow-compensated flicker: motion is compensated, blinking is not, a
// blurred blinking texture still flickers relative to its contrast, and a
// flat frame is no winner but a frame without contrast.
#include <gtest/gtest.h>

#include <cmath>

#include "stochtex/analysis/flicker.h"
#include "stochtex/analysis/zoom_stability.h"

namespace stochtex {
namespace {

// A smooth texture moved by (dx, dy) pixels, optionally inverted (a blink)
// and with its contrast scaled.
Image texture(int w, int h, double dx, double dy, bool invert = false, double amplitude = 0.3) {
    Image f(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = x - dx, v = y - dy;
            double s = std::sin(0.29 * u) * std::cos(0.21 * v) + 0.6 * std::sin(0.13 * u + 0.19 * v);
            if (invert) s = -s;
            for (int c = 0; c < 3; ++c) f.at(x, y, c) = float(0.5 + amplitude * 0.5 * s);
        }
    return f;
}

TEST(Flicker, MotionIsCompensatedBlinkingIsNot) {
    const int w = 96, h = 80;
    const FlickerMeasure moving = flowCompensatedFlicker(texture(w, h, 0, 0), texture(w, h, 2, 1));
    const FlickerMeasure blinking = flowCompensatedFlicker(texture(w, h, 0, 0), texture(w, h, 0, 0, true));
    std::printf("[ info ] moving: residual %.4f contrast %.4f relative %.3f; blinking: %.4f %.4f %.3f\n",
                moving.residual, moving.contrast, moving.relative, blinking.residual, blinking.contrast,
                blinking.relative);
    // Measured: 0.002 moving, 0.31 blinking (the flow explains part of an
    // inversion as a half-period shift, so a blink reads below its full size).
    EXPECT_LT(moving.relative, 0.02);
    EXPECT_GT(blinking.relative, 0.2);
    EXPECT_GT(blinking.relative, 20 * moving.relative);
    // The same blink at a fifth of the contrast (a blurred, washed-out
    // texture) is as much flicker relative to what there is to see.
    const FlickerMeasure faint =
        flowCompensatedFlicker(texture(w, h, 0, 0, false, 0.06), texture(w, h, 0, 0, true, 0.06));
    EXPECT_LT(faint.residual, 0.5 * blinking.residual);
    EXPECT_GT(faint.relative, 0.5 * blinking.relative);
    // A flat grey frame does not win: it has no contrast, and no relative figure.
    const Image grey(w, h, 3, 0.5f);
    const FlickerMeasure flat = flowCompensatedFlicker(grey, grey);
    EXPECT_EQ(flat.residual, 0.0);
    EXPECT_EQ(flat.contrast, 0.0);
    EXPECT_TRUE(std::isnan(flat.relative));
}

TEST(Flicker, ResidualMapShowsWhereItBlinks) {
    const int w = 96, h = 80;
    Image a = texture(w, h, 0, 0), b = a;
    for (int y = 20; y < 40; ++y)
        for (int x = 30; x < 60; ++x)
            for (int c = 0; c < 3; ++c) b.at(x, y, c) = 1.0f - b.at(x, y, c);  // a patch blinks
    Image map;
    flowCompensatedFlicker(a, b, &map);
    ASSERT_EQ(map.width(), w);
    double inside = 0, outside = 0;
    int nIn = 0, nOut = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (std::isnan(map.at(x, y))) continue;
            const bool in = x >= 34 && x < 56 && y >= 24 && y < 36;
            const bool far = x < 20 || x >= 70 || y < 10 || y >= 50;
            if (in) inside += map.at(x, y), ++nIn;
            if (far) outside += map.at(x, y), ++nOut;
        }
    EXPECT_GT(inside / nIn, 5 * outside / nOut);
}

// The zoom compensation is the same warped difference.
TEST(Flicker, ZoomCompensationIsAWarpedDifference) {
    const Image a = texture(64, 64, 0, 0), b = texture(64, 64, 1, 0);
    EXPECT_DOUBLE_EQ(compensatedZoomDifference(a, 1.0, b, 1.0),
                     warpedDifference(a, b, [](int x, int y) { return std::array<double, 2>{double(x), double(y)}; }));
}

}  // namespace
}  // namespace stochtex
