#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/image/image.h"
#include "stochtex/image/image_io.h"
#include "stochtex/image/image_stream.h"

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

// writeImage streams a PNG in bands of rows (libpng); the codes are those
// OpenCV's encoder wrote before it (sRGB, rounded half to even, clamped), and
// encodeImage gives the file's bytes. Over several bands, an odd last band
// and 4 channels; a 2-channel image is refused without leaving a file.
TEST(ImageIo, StreamedPngHasTheCodesOfTheOpenCvEncoder) {
    const fs::path d = tempDir();
    Image img = gradient(53, 150, 4);
    img.at(3, 140, 1) = std::nanf("");  // clamps to 0 in both
    img.at(4, 140, 2) = 1.5f;           // to 255
    const std::string path = (d / "rgba.png").string();
    writeImage(path, img);
    const std::vector<unsigned char> bytes = encodeImage(path, img);
    std::ifstream file(path, std::ios::binary);
    const std::vector<unsigned char> written{std::istreambuf_iterator<char>(file), {}};
    EXPECT_EQ(bytes, written);
    const Image codes = encodeTransfer(img, Transfer::Srgb);
    cv::Mat rgba(codes.height(), codes.width(), CV_32FC4, const_cast<float*>(codes.data().data())), bgra, eight;
    cv::cvtColor(rgba, bgra, cv::COLOR_RGBA2BGRA);
    bgra.convertTo(eight, CV_8U, 255.0);
    const std::string viaOpenCv = (d / "opencv.png").string();
    ASSERT_TRUE(cv::imwrite(viaOpenCv, eight));
    const Image streamed = readImage(path), encoded = readImage(viaOpenCv);
    ASSERT_EQ(streamed.channels(), 4);
    ASSERT_EQ(streamed.height(), 150);
    EXPECT_TRUE(std::equal(streamed.data().begin(), streamed.data().end(), encoded.data().begin()));
    EXPECT_EQ(streamed.at(3, 140, 1), 0.0f);
    EXPECT_EQ(streamed.at(4, 140, 2), 1.0f);
    const std::string two = (d / "two.png").string();
    try {
        writeImage(two, Image(4, 4, 2));
        ADD_FAILURE() << "a 2-channel PNG was written";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("two.png: a PNG is written from 1, 3 or 4 channels, got 2"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(filesIn(d), 2u);  // rgba.png and opencv.png
    fs::remove_all(d);
}

TEST(ImageIo, Png16KeepsSixteenBits) {
    const fs::path d = tempDir();
    Image img(4, 1, 1);
    img.at(0, 0) = 0.0f;
    img.at(1, 0) = 1000.0f / 65535.0f;
    img.at(2, 0) = 0.123456f;
    img.at(3, 0) = 1.0f;
    writeImage((d / "g.png").string(), img, WriteOptions{.bitDepth = 16, .transfer = Transfer::Linear});
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
    EXPECT_THROW(writeImage((d / "x.gif").string(), gradient(4, 4, 3)), InputError);
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
    // The thesis's luminosity formula (Figure 2.17): 0.21 r + 0.72 g + 0.07 b.
    img.at(0, 0, 1) = 1.0f;
    img.at(1, 0, 2) = 1.0f;
    const Image g = toGray(img);
    EXPECT_EQ(g.channels(), 1);
    EXPECT_FLOAT_EQ(g.at(0, 0), 0.72f);
    EXPECT_FLOAT_EQ(g.at(1, 0), 0.21f + 0.07f);
    const Image rgb = toRgb(g);
    EXPECT_FLOAT_EQ(rgb.at(1, 0, 2), 0.28f);
    // Periodic shifts wrap both ways.
    Image row(3, 2, 1);
    for (int i = 0; i < 6; ++i) row.data()[size_t(i)] = float(i);
    const Image s1 = shiftedPeriodic(row, 1, -1);
    EXPECT_EQ(s1.at(0, 0), row.at(1, 1));
    EXPECT_EQ(s1.at(2, 1), row.at(0, 0));
    EXPECT_EQ(shiftedPeriodic(row, 3, 2).data(), row.data());
}

TEST(ImageIo, JpegAndTiffAreWrittenByExtension) {
    const fs::path d = tempDir();
    const Image img = gradient(32, 16, 3);
    // TIFF, lossless: 8 bits exact on the grid, 16 bits within half a step.
    // The values are written as codes (no transfer); the sRGB encoding is
    // tested below and in colour_space_test.cpp.
    const WriteOptions codes{.transfer = Transfer::Linear};
    writeImage((d / "a.tif").string(), img, codes);
    cv::Mat t8 = cv::imread((d / "a.tif").string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(t8.type(), CV_8UC3);
    // Pixel (1, 0) in BGR order: R = 7, G = 38, B = 69 (gradient's formula).
    EXPECT_EQ(t8.at<cv::Vec3b>(0, 1), cv::Vec3b(69, 38, 7));
    writeImage((d / "b.TIFF").string(), img, WriteOptions{.bitDepth = 16, .transfer = Transfer::Linear});
    cv::Mat t16 = cv::imread((d / "b.TIFF").string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(t16.type(), CV_16UC3);
    EXPECT_EQ(t16.at<cv::Vec3w>(0, 1)[2], 1799);  // 7/255 · 65535 = 1799
    // JPEG: 8 bits, lossy at quality 95; a smooth gray ramp comes back within
    // 3 steps per pixel (measured: max 1).
    Image ramp(64, 64, 1);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) ramp.at(x, y) = float(x + y) / 126.0f;
    writeImage((d / "c.jpg").string(), ramp, codes);
    const Image back = readImage((d / "c.jpg").string());
    ASSERT_EQ(back.width(), 64);
    ASSERT_EQ(back.channels(), 1);
    for (size_t i = 0; i < ramp.data().size(); ++i) EXPECT_NEAR(back.data()[i], ramp.data()[i], 3.0 / 255);
    // By default colour is encoded: linear 0.5 is sRGB code 188 in JPEG too.
    Image grey(16, 16, 3);
    for (float& v : grey.data()) v = 0.5f;
    writeImage((d / "d.jpeg").string(), grey);
    const cv::Mat j = cv::imread((d / "d.jpeg").string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(j.type(), CV_8UC3);
    EXPECT_NEAR(j.at<cv::Vec3b>(8, 8)[1], 188, 1);
    EXPECT_EQ(filesIn(d), 4u);  // no temporary file left by any encoder
    fs::remove_all(d);
}

// TIFF's codes are made a band of rows at a time, in OpenCV's channel order:
// over several bands (150 rows, an odd last band), 3 and 4 channels and 8 and
// 16 bits they are the PNG's, sRGB-encoded, clamped (NaN, 1.5) alike.
TEST(ImageIo, TiffHasThePngsCodesOverSeveralBands) {
    const fs::path d = tempDir();
    for (const int channels : {3, 4})
        for (const int bits : {8, 16}) {
            Image img = gradient(53, 150, channels);
            img.at(3, 140, 1) = std::nanf("");
            img.at(4, 70, 2) = 1.5f;
            const std::string png = (d / "a.png").string(), tif = (d / "a.tif").string();
            writeImage(png, img, WriteOptions{.bitDepth = bits});
            writeImage(tif, img, WriteOptions{.bitDepth = bits});
            const cv::Mat t = cv::imread(tif, cv::IMREAD_UNCHANGED), p = cv::imread(png, cv::IMREAD_UNCHANGED);
            ASSERT_EQ(t.type(), CV_MAKETYPE(bits == 16 ? CV_16U : CV_8U, channels));
            ASSERT_EQ(p.type(), t.type());
            EXPECT_EQ(cv::norm(t, p, cv::NORM_INF), 0.0) << channels << " channels, " << bits << " bits";
            cv::Mat wide;
            t.convertTo(wide, CV_32S);
            const int* texel = wide.ptr<int>(140) + 3 * channels;  // (3, 140): green is channel 1 in BGR(A) too
            EXPECT_EQ(texel[1], 0);
            EXPECT_EQ(wide.ptr<int>(70)[4 * channels + 0], bits == 16 ? 65535 : 255);  // blue (RGB 2, BGR 0): 1.5 → max
        }
    fs::remove_all(d);
}

TEST(ImageIo, UnknownFormatsAndDepthsAreRefusedNamingThePath) {
    const fs::path d = tempDir();
    const std::string bmp = (d / "x.bmp").string(), jpg = (d / "x.jpg").string();
    try {
        writeImage(bmp, gradient(4, 4, 3));
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  bmp + ": unsupported output format '.bmp' (use .png, .exr, .jpg/.jpeg or .tif/.tiff)");
    }
    try {
        writeImage(jpg, gradient(4, 4, 3), WriteOptions{16});
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), jpg + ": JPEG holds 8 bits per channel, got 16");
    }
    EXPECT_THROW(checkImageOutputFormat((d / "x.png").string(), WriteOptions{12}), InputError);
    EXPECT_NO_THROW(checkImageOutputFormat((d / "x.tiff").string(), WriteOptions{16}));
    EXPECT_FALSE(isSupportedImagePath("a.gif"));
    EXPECT_TRUE(isSupportedImagePath("a.JPG"));
    EXPECT_EQ(filesIn(d), 0u);
    fs::remove_all(d);
}

// Our half conversion is OpenCV's (round to nearest, ties to even; overflow
// to infinity; subnormals; NaN quiet) on every special value and on 10⁶
// random bit patterns.
TEST(ImageIo, HalfFromFloatIsIeeeRoundToNearestEven) {
    const auto same = [](float f) {
        const uint16_t ours = halfFromFloat(f), opencv = cv::float16_t(f).bits();
        EXPECT_EQ(ours, opencv) << f;
        return ours == opencv;
    };
    for (const float f : {0.0f, -0.0f, 1.0f, -2.5f, 65504.0f, 65519.99f, 65520.0f, 1e9f, -1e9f,
                          std::numeric_limits<float>::infinity(), 6.1035156e-05f, 5.9604645e-08f, 2.9802322e-08f,
                          2.9802326e-08f, 1e-10f, 0.33333334f})
        same(f);
    EXPECT_EQ(halfFromFloat(std::nanf("")) & 0x7e00, 0x7e00);
    std::mt19937 rng(7);
    int differing = 0;
    for (int i = 0; i < 1000000; ++i) {
        const uint32_t bits = uint32_t(rng());
        float f = 0;
        std::memcpy(&f, &bits, 4);
        if (std::isnan(f)) continue;
        if (halfFromFloat(f) != cv::float16_t(f).bits() && ++differing < 5) same(f);
    }
    EXPECT_EQ(differing, 0);
}

// Streamed EXR: ZIP blocks of 16 rows from bands of any height (5, 20, 16,
// the rest), 1, 3 and 4 channels, float and half; OpenCV (OpenEXR) reads
// back the floats exactly and the halves as OpenCV converts them; the file
// is the same for 1 and 2 threads and as encodeImage's bytes; an image in
// steps of 1/256 shrinks.
TEST(ImageIo, ExrStreamIsZipCompressedAndReadsBackExactly) {
    const fs::path d = tempDir();
    for (const int channels : {1, 3, 4})
        for (const bool half : {false, true}) {
            Image img(37, 61, channels);
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x)
                    for (int c = 0; c < channels; ++c)
                        img.at(x, y, c) =
                            std::round(256.0f * std::sin(0.1f * float(x) + 0.07f * float(y) + float(c))) / 256.0f * 3.0f -
                            0.5f;
            const std::string path = (d / "s.exr").string();
            std::vector<std::string> files;
            for (const int threads : {1, 2}) {
                const ThreadLimit limit(threads);
                ExrStreamWriter out(path, img.width(), img.height(), channels, half);
                int y0 = 0;
                for (const int rows : {5, 20, 16, 61 - 41}) {
                    Image band(img.width(), rows, channels);
                    std::copy_n(img.row(y0), band.data().size(), band.data().begin());
                    out.writeRows(band);
                    y0 += rows;
                }
                out.finish();
                std::ifstream in(path, std::ios::binary);
                files.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
            }
            EXPECT_EQ(files[0], files[1]) << "threads change the file";
            const std::vector<unsigned char> encoded =
                encodeImage(path, img, WriteOptions{.exrHalf = half});
            EXPECT_EQ(std::string(encoded.begin(), encoded.end()), files[0]);
            // Steps of 1/256 leave most mantissa bits zero, which ZIP packs
            // (measured, header included: 27–60% of the raw values; sines in
            // full float precision ~87%).
            EXPECT_LT(files[0].size(), img.data().size() * (half ? 2 : 4) * 7 / 10) << "not compressed";
            const Image back = readImage(path);
            ASSERT_EQ(back.channels(), channels);
            ASSERT_EQ(back.height(), 61);
            for (size_t i = 0; i < img.data().size(); ++i) {
                const float expected = half ? float(cv::float16_t(img.data()[i])) : img.data()[i];
                ASSERT_EQ(back.data()[i], expected) << i << " of " << channels << " channels, half " << half;
            }
        }
    fs::remove_all(d);
}

TEST(ImageIo, ExrStreamWritesBandsThatOpenCvReadsBackExactly) {
    const fs::path d = tempDir();
    // Values outside [0, 1] and negative ones: EXR keeps them (linear float).
    Image rgb(7, 5, 3);
    for (size_t i = 0; i < rgb.data().size(); ++i) rgb.data()[i] = -1.25f + 0.173f * float(i);
    Image top(7, 2, 3), bottom(7, 3, 3);
    std::copy_n(rgb.data().begin(), top.data().size(), top.data().begin());
    std::copy_n(rgb.data().begin() + long(top.data().size()), bottom.data().size(), bottom.data().begin());
    {
        auto out = openImageStream((d / "s.exr").string(), 7, 5, 3, 8);
        out->writeRows(top);
        out->writeRows(bottom);
        out->finish();
    }
    const Image back = readImage((d / "s.exr").string());  // OpenCV's (OpenEXR's) decoder
    ASSERT_EQ(back.width(), 7);
    ASSERT_EQ(back.height(), 5);
    ASSERT_EQ(back.channels(), 3);
    EXPECT_EQ(back.data(), rgb.data());  // bit-exact: float32 stored as is
    Image gray(9, 4, 1);
    for (size_t i = 0; i < gray.data().size(); ++i) gray.data()[i] = 0.01f * float(i * i);
    ExrStreamWriter g((d / "g.exr").string(), 9, 4, 1);
    g.writeRows(gray);
    g.finish();
    EXPECT_EQ(readImage((d / "g.exr").string()).data(), gray.data());
    {
        ExrStreamWriter unfinished((d / "u.exr").string(), 9, 4, 1);
        unfinished.writeRows(gray);  // never finished: no file under any name
    }
    EXPECT_EQ(filesIn(d), 2u);
    EXPECT_THROW(openImageStream((d / "x.jpg").string(), 4, 4, 3, 8), InputError);
    fs::remove_all(d);
}
