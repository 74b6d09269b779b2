// The animated preview (animated WebP) decodes to the frames it was given:
// their count, timing, reduced size and colours within the lossy encoder's error.
#include <gtest/gtest.h>

#include <webp/demux.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "stochtex/report/animated_preview.h"
#include "test_util.h"

namespace stochtex {
namespace {

TEST(AnimatedPreview, DecodesToTheFramesScaledDown) {
    const std::string path = test::scratchPath("stochtex_preview.webp").string();
    AnimatedPreviewWriter w(path, 64, 32, 10.0, 32);
    for (int k = 0; k < 3; ++k) {
        Image f(64, 32, 3);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x) {
                f.at(x, y, 0) = float(k) / 2.0f;  // frame k: red k/2, green 0.25, blue 0.75
                f.at(x, y, 1) = 0.25f;
                f.at(x, y, 2) = 0.75f;
            }
        w.add(f);
    }
    EXPECT_EQ(w.finish(), path);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    WebPData data{reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()};
    WebPAnimDecoderOptions options;
    ASSERT_TRUE(WebPAnimDecoderOptionsInit(&options));
    options.color_mode = MODE_RGBA;
    WebPAnimDecoder* dec = WebPAnimDecoderNew(&data, &options);
    ASSERT_NE(dec, nullptr);
    WebPAnimInfo info;
    ASSERT_TRUE(WebPAnimDecoderGetInfo(dec, &info));
    EXPECT_EQ(info.canvas_width, 32u);  // the longer side scaled to maxSide
    EXPECT_EQ(info.canvas_height, 16u);
    EXPECT_EQ(info.frame_count, 3u);
    EXPECT_EQ(info.loop_count, 0u);
    int k = 0;
    while (WebPAnimDecoderHasMoreFrames(dec)) {
        uint8_t* rgba = nullptr;
        int timestamp = 0;
        ASSERT_TRUE(WebPAnimDecoderGetNext(dec, &rgba, &timestamp));
        EXPECT_EQ(timestamp, 100 * (k + 1));  // each frame ends 1/10 s after it starts
        const uint8_t* centre = rgba + (8 * 32 + 16) * 4;
        // Lossy at quality 80 on flat colours: within 4/255.
        EXPECT_NEAR(centre[0], 255.0 * k / 2.0, 4.0) << k;
        EXPECT_NEAR(centre[1], 255.0 * 0.25, 4.0) << k;
        EXPECT_NEAR(centre[2], 255.0 * 0.75, 4.0) << k;
        ++k;
    }
    EXPECT_EQ(k, 3);
    WebPAnimDecoderDelete(dec);
    std::filesystem::remove(path);
    EXPECT_THROW(w.add(Image(8, 8, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace stochtex
