// readImage on hostile files: the size comes from the header and is checked
// before any pixel is decoded; every problem is one InputError that names the
// file and says what is wrong, and no library text reaches the terminal.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "test_util.h"

using namespace stochtex;
namespace fs = std::filesystem;

namespace {

void put32(std::string& s, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) s += char((v >> shift) & 0xff);
}

// One PNG chunk with its CRC (zlib's crc32 is PNG's CRC); `breakCrc` flips it.
std::string chunk(const std::string& type, const std::string& data, bool breakCrc = false) {
    std::string c;
    put32(c, uint32_t(data.size()));
    const std::string body = type + data;
    c += body;
    uint32_t crc = uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size())));
    put32(c, breakCrc ? ~crc : crc);
    return c;
}

// A valid 8-bit gray PNG of width × height whose pixel rows are all zero:
// zeros compress about 1000:1, so a 20000² image is a few hundred kB.
std::string zeroPng(uint32_t width, uint32_t height, bool breakIhdrCrc = false) {
    std::string ihdr;
    put32(ihdr, width);
    put32(ihdr, height);
    ihdr += std::string{8, 0, 0, 0, 0};  // depth 8, gray, deflate, adaptive filter, no interlace
    z_stream z{};
    deflateInit(&z, 1);
    const std::string row(size_t(width) + 1, '\0');  // filter byte 0 + pixels
    std::string idat;
    std::string out(1 << 16, '\0');
    for (uint32_t y = 0; y <= height; ++y) {
        const bool last = y == height;
        z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(row.data()));
        z.avail_in = last ? 0 : uInt(row.size());
        do {
            z.next_out = reinterpret_cast<Bytef*>(out.data());
            z.avail_out = uInt(out.size());
            deflate(&z, last ? Z_FINISH : Z_NO_FLUSH);
            idat.append(out.data(), out.size() - z.avail_out);
        } while (z.avail_out == 0 || (last && z.avail_in != 0));
    }
    deflateEnd(&z);
    return "\x89PNG\r\n\x1a\n" + chunk("IHDR", ihdr, breakIhdrCrc) + chunk("IDAT", idat) + chunk("IEND", "");
}

std::string writeFile(const fs::path& dir, const std::string& name, const std::string& bytes) {
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

// Reads `path`, which must fail; returns the message (stderr must stay silent).
std::string failureOf(const std::string& path) {
    testing::internal::CaptureStderr();
    const InputError e = test::inputErrorOf([&] { readImage(path); });
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(err, "") << "a library wrote to the terminal reading " << path;
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << "the message does not start with the file: " << message;
    return message;
}

long peakKilobytes() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

class ImageRead : public test::ScratchFolder {};

}  // namespace

TEST_F(ImageRead, ASmallPngDeclaringAHugeImageFailsFromItsHeader) {
    // A valid PNG (CRCs and data right) of 20000² gray pixels in ~400 kB:
    // decoding it would take 400 MB, 1.6 GB as floats.
    const std::string path = writeFile(dir_, "huge.png", zeroPng(20000, 20000));
    ASSERT_LT(fs::file_size(path), 2u << 20);
    const long before = peakKilobytes();
    const std::string message = failureOf(path);
    EXPECT_NE(message.find("20000x20000 pixels"), std::string::npos) << message;
    EXPECT_NE(message.find("at most 16777216 pixels (4096x4096)"), std::string::npos) << message;
    // Reading the 400 kB file is all it may cost: 50 MB leave a wide margin
    // over that and are far below what a decode takes (≥ 400 MB). (Time is
    // not asserted: unit tests run on shared machines; memory says the same.)
    EXPECT_LT(peakKilobytes() - before, 50 * 1024);
}

TEST_F(ImageRead, ImagesJustInsideTheLimitsAreReadAndJustOutsideAreNot) {
    // Any shape up to 4096² pixels: a 256 × 65536 strip (an export's table
    // atlas is 256 × 25600) and 4096²; one row or one pixel more is refused.
    for (const auto& [w, h] : {std::pair{256u, 65536u}, std::pair{4096u, 4096u}}) {
        const Image img = readImage(writeFile(dir_, "edge.png", zeroPng(w, h)));
        EXPECT_EQ(img.width(), int(w));
        EXPECT_EQ(img.height(), int(h));
        EXPECT_EQ(img.channels(), 1);
    }
    EXPECT_NE(failureOf(writeFile(dir_, "over.png", zeroPng(4096, 4097))).find("4096x4097 pixels"), std::string::npos);
    EXPECT_NE(failureOf(writeFile(dir_, "side.png", zeroPng(65537, 2))).find("65537x2 pixels"), std::string::npos);
}

TEST_F(ImageRead, HugeExrAndJpegHeadersFailBeforeDecoding) {
    // OpenEXR: magic, version 2, then a dataWindow box2i of 0…99999 and an
    // end of header, no pixels.
    std::string exr("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    const auto le32 = [&](int32_t v) {
        for (int i = 0; i < 4; ++i) exr += char((uint32_t(v) >> (8 * i)) & 0xff);
    };
    exr += std::string("dataWindow\0box2i\0", 17);
    le32(16);
    le32(0), le32(0), le32(99999), le32(99999);
    exr += '\0';
    EXPECT_NE(failureOf(writeFile(dir_, "huge.exr", exr)).find("100000x100000 pixels"), std::string::npos);

    // JPEG: SOI, then a baseline SOF0 of 30000 × 20000 (height first), 3 components.
    const std::string jpeg(
        "\xff\xd8\xff\xc0\x00\x11\x08\x4e\x20\x75\x30\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01"
        "\xff\xd9",
        23);
    EXPECT_NE(failureOf(writeFile(dir_, "huge.jpg", jpeg)).find("30000x20000 pixels"), std::string::npos);
}

TEST_F(ImageRead, SizesComeFromTheHeaderWhereverItLies) {
    // A JPEG whose frame header follows 20 APP segments of 64 KiB (past the
    // first MiB readImageSize reads first): its size, as readImage finds it.
    std::string jpeg("\xff\xd8", 2);
    for (int i = 0; i < 20; ++i) jpeg += std::string("\xff\xe1\xff\xff", 4) + std::string(0xffff - 2, 'x');
    jpeg += std::string("\xff\xc0\x00\x11\x08\x00\x30\x00\x40\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01\xff\xd9", 21);
    ASSERT_GT(jpeg.size(), size_t(1) << 20);
    EXPECT_EQ(readImageSize(writeFile(dir_, "late.jpg", jpeg)), (std::array<int, 2>{64, 48}));
    // An EXR header: a dataWindow of 16², an attribute of 1.5 MiB, and a
    // second dataWindow of 20000 × 16, the one OpenEXR reads (never the
    // first, which the first MiB holds).
    std::string exr("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    const auto le32 = [&](int32_t v) {
        for (int i = 0; i < 4; ++i) exr += char((uint32_t(v) >> (8 * i)) & 0xff);
    };
    const auto dataWindow = [&](int32_t width) {
        exr += std::string("dataWindow\0box2i\0", 17);
        le32(16), le32(0), le32(0), le32(width - 1), le32(15);
    };
    dataWindow(16);
    exr += std::string("padding\0opaque\0", 15);
    le32(3 << 19);
    exr += std::string(3 << 19, '\0');
    dataWindow(20000);
    exr += '\0';
    EXPECT_EQ(readImageSize(writeFile(dir_, "late.exr", exr)), (std::array<int, 2>{20000, 16}));
    // A PNG: its size from its image header.
    EXPECT_EQ(readImageSize(writeFile(dir_, "size.png", zeroPng(300, 7))), (std::array<int, 2>{300, 7}));
}

TEST_F(ImageRead, BrokenFilesSayWhatIsWrongAndNothingElse) {
    EXPECT_NE(failureOf(writeFile(dir_, "empty.png", "")).find("the file is empty"), std::string::npos);
    EXPECT_NE(failureOf(writeFile(dir_, "zero.png", zeroPng(0, 0))).find("0x0 pixels (empty)"), std::string::npos);
    EXPECT_NE(failureOf(writeFile(dir_, "crc.png", zeroPng(4, 4, true))).find("corrupt PNG (IHDR: CRC error)"),
              std::string::npos);
    const std::string whole = zeroPng(64, 64);
    EXPECT_NE(failureOf(writeFile(dir_, "cut.png", whole.substr(0, whole.size() - 30))).find("corrupt PNG"),
              std::string::npos);
    EXPECT_NE(failureOf(writeFile(dir_, "text.png", "not an image at all")).find("not a PNG, OpenEXR or JPEG image"),
              std::string::npos);
    EXPECT_NE(failureOf(dir_.string()).find("is a folder"), std::string::npos);
}

TEST_F(ImageRead, PngDecodingAgreesWithOpenCv) {
    // libpng (ours) against OpenCV's decoder on files OpenCV wrote: 16-bit
    // RGBA and 8-bit gray; values must agree exactly (same integers / 65535).
    cv::Mat rgba(5, 7, CV_16UC4), gray(4, 9, CV_8UC1);
    cv::RNG rng(7);
    rng.fill(rgba, cv::RNG::UNIFORM, 0, 65536);
    rng.fill(gray, cv::RNG::UNIFORM, 0, 256);
    for (const auto& [name, mat] : {std::pair{"rgba16.png", rgba}, std::pair{"gray8.png", gray}}) {
        const std::string path = (dir_ / name).string();
        ASSERT_TRUE(cv::imwrite(path, mat));
        const cv::Mat expected = cv::imread(path, cv::IMREAD_UNCHANGED);
        const Image img = readImage(path);
        ASSERT_EQ(img.channels(), expected.channels()) << name;
        const double scale = expected.depth() == CV_16U ? 65535.0 : 255.0;
        for (int y = 0; y < expected.rows; ++y)
            for (int x = 0; x < expected.cols; ++x)
                for (int c = 0; c < expected.channels(); ++c) {
                    // OpenCV stores BGRA; ours is RGBA.
                    const int cv = expected.channels() == 4 && c < 3 ? 2 - c : c;
                    const double v = expected.depth() == CV_16U ? expected.ptr<uint16_t>(y)[x * 4 + cv]
                                                                : expected.ptr<uint8_t>(y)[x];
                    ASSERT_EQ(img.at(x, y, c), float(v / scale)) << name << " at " << x << "," << y << "," << c;
                }
    }
}

namespace {

// An EXR's bytes with one more attribute, a dataWindow of width × 16, just
// before the end of its header (the `\0` after the last attribute, which
// precedes the offset table): OpenEXR reads the later one.
std::string withSecondDataWindow(const std::string& exr, int32_t width) {
    const std::string last = std::string("screenWindowWidth\0float\0", 24);
    const size_t at = exr.find(last);
    EXPECT_NE(at, std::string::npos) << "OpenCV's EXR header has no screenWindowWidth";
    const size_t end = at + last.size() + 4 + 4;  // the size (4) and the float (4)
    std::string attribute = std::string("dataWindow\0box2i\0", 17);
    for (const int32_t v : {16, 0, 0, width - 1, 15})
        for (int i = 0; i < 4; ++i) attribute += char((uint32_t(v) >> (8 * i)) & 0xff);
    return exr.substr(0, end) + attribute + exr.substr(end);
}

// Temporary files OpenCV's decoder names this way; our own reads leave none.
size_t openCvTemporaries(const fs::path& dir) {
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().rfind("__opencv_temp", 0) == 0 ||
            e.path().filename().string().find("stochtex-exr-read") != std::string::npos)
            ++n;
    return n;
}

}  // namespace

TEST_F(ImageRead, ExrReadsLeaveNoTemporaryFileWhenTheDecoderRefuses) {
    // OpenCV's EXR decoder works on files only; imdecode copies the bytes to
    // a temporary file and leaves it when its own size limit (2^20 a side)
    // throws. Both places a temporary file can go are watched.
    const fs::path tmp = dir_ / "tmp";
    fs::create_directories(tmp);
    const std::string savedTmp = std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "";
    setenv("TMPDIR", tmp.c_str(), 1);
    const size_t inSystemTmp = openCvTemporaries("/tmp");

    Image gray(16, 16, 1);
    for (size_t i = 0; i < gray.data().size(); ++i) gray.data()[i] = float(i) / 256.0f;
    writeImage((dir_ / "gray.exr").string(), gray);
    std::ifstream in(dir_ / "gray.exr", std::ios::binary);
    const std::string exr((std::istreambuf_iterator<char>(in)), {});
    // The file itself reads back (through the private file) exactly.
    EXPECT_EQ(readImage((dir_ / "gray.exr").string()).data(), gray.data());

    // A second dataWindow 2^21 wide: refused from the header, in our words.
    const std::string twice = writeFile(dir_, "twice.exr", withSecondDataWindow(exr, 1 << 21));
    EXPECT_NE(failureOf(twice).find("2097152x16 pixels"), std::string::npos);
    // Pixel data cut off after the header: the decode fails, our file goes.
    const std::string cut = writeFile(dir_, "cut.exr", exr.substr(0, exr.size() - 600));
    EXPECT_NE(failureOf(cut).find("corrupt image"), std::string::npos);

    EXPECT_EQ(openCvTemporaries(tmp), 0u);
    EXPECT_EQ(openCvTemporaries("/tmp"), inSystemTmp);
    if (savedTmp.empty())
        unsetenv("TMPDIR");
    else
        setenv("TMPDIR", savedTmp.c_str(), 1);
}
