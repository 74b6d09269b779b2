// The sRGB transfer pair (image/colour_space.h over kernel/colour.glsl) and
// the writers' use of it. Expected values are worked from IEC 61966-2-1's
// formulas in double precision, independently of the float kernel.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "stochtex/image/colour_space.h"
#include "stochtex/image/image_io.h"
#include "stochtex/image/png_stream.h"
#include "test_util.h"

namespace stochtex {
namespace {

double encodeRef(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }
double decodeRef(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

TEST(ColourSpace, KnownValuesOfTheSrgbCurve) {
    // Linear ½ is code 188 (0.7354 · 255 = 187.5 + 0.02): a 50/50 mix of black and white.
    EXPECT_NEAR(srgbFromLinear(0.5f), 0.735356983, 1e-6);  // 1e-6: float pow
    EXPECT_EQ(std::lround(255.0f * srgbFromLinear(0.5f)), 188);
    // Code ½ is linear 0.2140 (not 0.5^2.2 = 0.2176: the exact curve, not a power).
    EXPECT_NEAR(linearFromSrgb(0.5f), 0.214041140, 1e-6);
    EXPECT_EQ(srgbFromLinear(0.0f), 0.0f);
    EXPECT_NEAR(srgbFromLinear(1.0f), 1.0f, 1e-6);
    EXPECT_NEAR(linearFromSrgb(1.0f), 1.0f, 1e-6);
    // Out of range is clamped: an encoded value outside [0, 1] has no meaning.
    EXPECT_EQ(srgbFromLinear(-0.25f), 0.0f);
    EXPECT_NEAR(srgbFromLinear(4.0f), 1.0f, 1e-6);
}

TEST(ColourSpace, TheBoundaryAtLinear0_0031308IsContinuous) {
    // Both pieces meet at (0.0031308, 0.04045) within the standard's rounding
    // of its constants (≈ 1e-7): the linear piece below, the power above.
    const float v = 0.0031308f, c = 0.04045f;
    EXPECT_NEAR(srgbFromLinear(v), 12.92 * 0.0031308, 1e-7);
    EXPECT_NEAR(srgbFromLinear(std::nextafter(v, 1.0f)), encodeRef(double(std::nextafter(v, 1.0f))), 1e-6);
    EXPECT_NEAR(srgbFromLinear(std::nextafter(v, 1.0f)) - srgbFromLinear(v), 0.0, 1e-6);
    EXPECT_NEAR(linearFromSrgb(c), 0.04045 / 12.92, 1e-9);
    EXPECT_NEAR(linearFromSrgb(std::nextafter(c, 1.0f)) - linearFromSrgb(c), 0.0, 1e-7);
    // Below the boundary the curve is exactly linear (slope 12.92).
    EXPECT_FLOAT_EQ(srgbFromLinear(0.001f), 12.92f * 0.001f);
    EXPECT_FLOAT_EQ(linearFromSrgb(0.02f), 0.02f / 12.92f);
}

TEST(ColourSpace, MatchesTheDoublePrecisionCurveEverywhere) {
    // 4e-7: a few float ulps of pow near 1.
    for (int i = 0; i <= 10000; ++i) {
        const double x = i / 10000.0;
        ASSERT_NEAR(srgbFromLinear(float(x)), encodeRef(double(float(x))), 4e-7) << x;
        ASSERT_NEAR(linearFromSrgb(float(x)), decodeRef(double(float(x))), 4e-7) << x;
    }
}

TEST(ColourSpace, EveryEightAndSixteenBitCodeSurvivesTheRoundTrip) {
    for (int code = 0; code < 256; ++code) {
        const float linear = linearFromSrgb(float(code) / 255.0f);
        ASSERT_EQ(std::lround(255.0f * srgbFromLinear(linear)), code);
    }
    for (int code = 0; code < 65536; ++code) {
        const float linear = linearFromSrgb(float(code) / 65535.0f);
        ASSERT_EQ(std::lround(65535.0f * srgbFromLinear(linear)), code) << code;
    }
}

class ColourSpaceFiles : public test::ScratchFolder {};

// PNG codes are sRGB (linear ½ → 188, 16-bit 48192), EXR keeps linear values,
// and kNoTransfer writes the values as codes (½ → 128).
TEST_F(ColourSpaceFiles, WritersEncodeIntegerFormatsAndKeepEXRLinear) {
    Image half(2, 2, 3, 0.5f);
    writeImage((dir_ / "c.png").string(), half);
    writeImage((dir_ / "c16.png").string(), half, WriteOptions{.bitDepth = 16});
    writeImage((dir_ / "d.png").string(), half, kNoTransfer);
    writeImage((dir_ / "c.exr").string(), half);
    EXPECT_EQ(std::lround(255.0f * readImage((dir_ / "c.png").string()).at(1, 1, 2)), 188);
    EXPECT_EQ(std::lround(65535.0f * readImage((dir_ / "c16.png").string()).at(1, 1, 2)),
              std::lround(65535.0 * encodeRef(0.5)));
    EXPECT_EQ(std::lround(255.0f * readImage((dir_ / "d.png").string()).at(1, 1, 2)), 128);
    EXPECT_EQ(readImage((dir_ / "c.exr").string()).at(1, 1, 2), 0.5f);
    EXPECT_TRUE(holdsFloatValues((dir_ / "c.exr").string()));
    EXPECT_FALSE(holdsFloatValues((dir_ / "c.png").string()));
    // The streamed PNG encodes as writeImage does.
    PngStreamWriter stream((dir_ / "s.png").string(), 2, 2, 3);
    stream.writeRows(half);
    stream.finish();
    EXPECT_EQ(std::lround(255.0f * readImage((dir_ / "s.png").string()).at(0, 0, 0)), 188);
}

}  // namespace
}  // namespace stochtex
