#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "stochtex/core/error.h"
#include "stochtex/image/image.h"
#include "stochtex/image/image_io.h"

using namespace stochtex;
namespace fs = std::filesystem;

namespace {

fs::path tempDir() {
    const fs::path d = fs::temp_directory_path() / ("stochtex_image_test_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

Image gradient(int w, int h, int c) {
    Image img(w, h, c);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int k = 0; k < c; ++k) img.at(x, y, k) = float((x * 7 + y * 13 + k * 31) % 256) / 255.0f;
    return img;
}

size_t filesIn(const fs::path& d) {
    size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(d)) ++n;
    return n;
}

}  // namespace

TEST(ImageIo, Png8RoundTripIsExactOnTheGrid) {
    const fs::path d = tempDir();
    const Image img = gradient(37, 23, 3);
    writeImage((d / "a.png").string(), img, kNoTransfer);  // the codec alone (colour_space_test: the sRGB encode)
    const Image back = readImage((d / "a.png").string());
    ASSERT_EQ(back.width(), 37);
    ASSERT_EQ(back.height(), 23);
    ASSERT_EQ(back.channels(), 3);
    for (size_t i = 0; i < img.data().size(); ++i) EXPECT_NEAR(back.data()[i], img.data()[i], 1e-6);
    // Channel order survives (R stays R): pixel (1,0) has distinct channels.
    EXPECT_NEAR(back.at(1, 0, 0), 7.0f / 255.0f, 1e-6);
    EXPECT_NEAR(back.at(1, 0, 2), 69.0f / 255.0f, 1e-6);
    fs::remove_all(d);
}

TEST(ImageIo, Png16KeepsSixteenBits) {
    const fs::path d = tempDir();
    Image img(4, 1, 1);
    img.at(0, 0) = 0.0f;
    img.at(1, 0) = 1000.0f / 65535.0f;
    img.at(2, 0) = 0.123456f;
    img.at(3, 0) = 1.0f;
    writeImage((d / "g.png").string(), img, WriteOptions{.pngBitDepth = 16, .transfer = Transfer::Linear});
    const Image back = readImage((d / "g.png").string());
    ASSERT_EQ(back.channels(), 1);
    for (int x = 0; x < 4; ++x) EXPECT_NEAR(back.at(x, 0), img.at(x, 0), 0.5 / 65535.0 + 1e-7);
    fs::remove_all(d);
}

TEST(ImageIo, ExrKeepsFloatsExactly) {
    const fs::path d = tempDir();
    Image img(5, 3, 3);
    for (size_t i = 0; i < img.data().size(); ++i) img.data()[i] = -0.5f + 0.3337f * float(i);
    writeImage((d / "f.exr").string(), img);
    const Image back = readImage((d / "f.exr").string());
    ASSERT_EQ(back.channels(), 3);
    for (size_t i = 0; i < img.data().size(); ++i) EXPECT_EQ(back.data()[i], img.data()[i]);
    fs::remove_all(d);
}

TEST(ImageIo, WriteLeavesNoTemporaryFiles) {
    const fs::path d = tempDir();
    writeImage((d / "x.png").string(), gradient(8, 8, 1));
    EXPECT_EQ(filesIn(d), 1u);
    fs::remove_all(d);
}

TEST(ImageIo, BadInputsThrowInputErrorNamingThePath) {
    const fs::path d = tempDir();
    try {
        readImage((d / "missing.png").string());
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
    }
    {
        std::ofstream((d / "corrupt.png").string()) << "this is not a png";
    }
    EXPECT_THROW(readImage((d / "corrupt.png").string()), InputError);
    EXPECT_THROW(writeImage((d / "x.jpg").string(), gradient(4, 4, 3)), InputError);
    EXPECT_THROW(writeImage((d / "no" / "such" / "dir.png").string(), gradient(4, 4, 3)), InputError);
    fs::remove_all(d);
}

TEST(Image, StatsAndConversions) {
    Image img(2, 1, 3);
    img.at(0, 0, 0) = 0.0f;
    img.at(1, 0, 0) = 1.0f;
    const ChannelStats s = channelStats(img, 0);
    EXPECT_DOUBLE_EQ(s.mean, 0.5);
    EXPECT_DOUBLE_EQ(s.stddev, 0.5);
    const Image g = toGray(img);
    EXPECT_EQ(g.channels(), 1);
    EXPECT_FLOAT_EQ(g.at(1, 0), 1.0f / 3.0f);
    const Image rgb = toRgb(g);
    EXPECT_FLOAT_EQ(rgb.at(1, 0, 2), 1.0f / 3.0f);
}
