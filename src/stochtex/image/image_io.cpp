#include "stochtex/image/image_io.h"

#include <png.h>
#include <unistd.h>  // close

#include <algorithm>
#include <array>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>  // the IMWRITE_ parameter names; the codecs are the plugin's
#include <opencv2/imgproc.hpp>
#include <optional>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/image/image_stream.h"
#include "stochtex/image/media_codecs.h"
#include "stochtex/image/png_stream.h"

namespace stochtex {
namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// What writeImage writes, by the path's extension (any case).
enum class OutputFormat { Png, Exr, Jpeg, Tiff };
constexpr int kTiffCompressionLzw = 5;  // libtiff's COMPRESSION_LZW: lossless

std::optional<OutputFormat> outputFormatOf(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".png") return OutputFormat::Png;
    if (ext == ".exr") return OutputFormat::Exr;
    if (ext == ".jpg" || ext == ".jpeg") return OutputFormat::Jpeg;
    if (ext == ".tif" || ext == ".tiff") return OutputFormat::Tiff;
    return std::nullopt;
}

enum class ImageFormat { Png, Exr, Jpeg };

struct ImageHeader {
    ImageFormat format;
    long long width = 0, height = 0;
};

uint32_t bigEndian32(const uchar* b) {
    return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]);
}
uint32_t bigEndian16(const uchar* b) { return uint32_t(b[0]) << 8 | uint32_t(b[1]); }
int32_t littleEndian32(const uchar* b) {
    return int32_t(uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24);
}

// PNG: the signature, then IHDR, whose first fields are width and height.
ImageHeader pngHeader(const std::string& path, const std::vector<uchar>& b) {
    if (b.size() < 33 || std::memcmp(&b[12], "IHDR", 4) != 0)
        throw InputError(path + ": corrupt PNG (no image header)");
    return {ImageFormat::Png, bigEndian32(&b[16]), bigEndian32(&b[20])};
}

// OpenEXR: magic, version, then attributes `name\0 type\0 size value` up to an
// empty name; the pixel extent is the dataWindow box2i (xMin, yMin, xMax, yMax).
// `b` may be the file's start only (`whole` false): then a header that has
// not ended in it is not read, as a later dataWindow would replace this one.
ImageHeader exrHeader(const std::string& path, const std::vector<uchar>& b, bool whole) {
    size_t at = 8;
    const auto readString = [&](std::string& out) {
        if (at >= b.size()) return false;
        const auto end = std::find(b.begin() + long(at), b.end(), uchar(0));
        if (end == b.end()) return false;
        out.assign(b.begin() + long(at), end);
        at = size_t(end - b.begin()) + 1;
        return true;
    };
    // OpenEXR reads a repeated attribute over the earlier one, so the last
    // dataWindow is the one its decoder uses: checking the first would let a
    // second, huge one through to OpenCV.
    std::string name, type;
    std::optional<ImageHeader> found;
    bool ended = false;
    while (readString(name)) {
        if (name.empty()) {
            ended = true;
            break;
        }
        if (!readString(type) || at + 4 > b.size()) break;
        const int32_t size = littleEndian32(&b[at]);
        at += 4;
        if (size < 0 || size_t(size) > b.size() - at) break;
        if (name == "dataWindow" && type == "box2i" && size == 16) {
            const long long x0 = littleEndian32(&b[at]), y0 = littleEndian32(&b[at + 4]);
            const long long x1 = littleEndian32(&b[at + 8]), y1 = littleEndian32(&b[at + 12]);
            found = ImageHeader{ImageFormat::Exr, std::max(0ll, x1 - x0 + 1), std::max(0ll, y1 - y0 + 1)};
        }
        at += size_t(size);
    }
    if (found && (ended || whole)) return *found;
    throw InputError(path + ": corrupt OpenEXR file (no readable dataWindow in its header)");
}

// JPEG: markers up to the first start-of-frame (SOF0…SOF15 but DHT, JPG and
// DAC), whose segment holds precision, height, width.
ImageHeader jpegHeader(const std::string& path, const std::vector<uchar>& b) {
    size_t at = 2;
    while (at + 4 <= b.size() && b[at] == 0xFF) {
        const uchar marker = b[at + 1];
        if (marker == 0xFF) {  // fill byte
            ++at;
            continue;
        }
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // markers without a length
            at += 2;
            continue;
        }
        if (marker == 0xD9 || marker == 0xDA) break;  // end of image or scan before any frame header
        const size_t length = bigEndian16(&b[at + 2]);
        const bool frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (frame && length >= 7 && at + 9 <= b.size())
            return {ImageFormat::Jpeg, bigEndian16(&b[at + 7]), bigEndian16(&b[at + 5])};  // width, height
        at += 2 + length;
    }
    throw InputError(path + ": corrupt JPEG file (no frame header)");
}

const uchar kExrMagic[] = {0x76, 0x2F, 0x31, 0x01};

// The format from the file's first bytes (never from its name).
ImageHeader readHeader(const std::string& path, const std::vector<uchar>& b, bool whole = true) {
    static const uchar kPng[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (b.size() >= 8 && std::memcmp(b.data(), kPng, 8) == 0) return pngHeader(path, b);
    if (b.size() >= 8 && std::memcmp(b.data(), kExrMagic, 4) == 0) return exrHeader(path, b, whole);
    if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return jpegHeader(path, b);
    throw InputError(path + ": not a PNG, OpenEXR or JPEG image");
}

void checkImageSize(const std::string& path, const ImageHeader& h) {
    const std::string size = std::to_string(h.width) + "x" + std::to_string(h.height);
    if (h.width < 1 || h.height < 1) throw InputError(path + ": the image is " + size + " pixels (empty)");
    if (h.width > kMaxImageSide || h.height > kMaxImageSide || h.width * h.height > kMaxImagePixels)
        throw InputError(path + ": the image is " + size + " pixels; images of at most " +
                         std::to_string(kMaxImagePixels) + " pixels (4096x4096) and " + std::to_string(kMaxImageSide) +
                         " per side are read");
}

// libpng reports through these, never to the terminal: a warning is dropped,
// an error is kept for the InputError and ends the decode (longjmp).
struct PngReader {
    const std::vector<uchar>* bytes = nullptr;
    size_t at = 0;
    std::string error;
    std::vector<uchar> pixels;
    std::vector<png_bytep> rows;
};

void onPngError(png_structp png, png_const_charp message) {
    static_cast<PngReader*>(png_get_error_ptr(png))->error = message;
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

void readPngBytes(png_structp png, png_bytep out, png_size_t n) {
    auto* r = static_cast<PngReader*>(png_get_io_ptr(png));
    if (r->bytes->size() - r->at < n) png_error(png, "the file ends early");
    std::memcpy(out, r->bytes->data() + r->at, n);
    r->at += n;
}

// Called once the header passed checkImageSize, so the pixel buffer is
// bounded. Palettes, low bit depths and tRNS are expanded; gray + alpha
// becomes RGBA.
Image decodePng(const std::string& path, const std::vector<uchar>& bytes) {
    // What the decode changes lives behind a pointer set before setjmp, so
    // nothing is indeterminate when libpng jumps back.
    const auto reader = std::make_unique<PngReader>();
    reader->bytes = &bytes;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, reader.get(), onPngError, onPngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    struct Destroy {
        png_structp* png;
        png_infop* info;
        ~Destroy() {
            if (*png) png_destroy_read_struct(png, info, nullptr);
        }
    } destroy{&png, &info};
    if (!png || !info) throw std::runtime_error("readImage: libpng could not start");
    if (setjmp(png_jmpbuf(png))) throw InputError(path + ": corrupt PNG (" + reader->error + ")");
    png_set_read_fn(png, reader.get(), readPngBytes);
    png_set_user_limits(png, kMaxImageSide, kMaxImageSide);
    png_read_info(png, info);
    png_set_expand(png);
    if (png_get_color_type(png, info) == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const size_t width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    const size_t rowBytes = png_get_rowbytes(png, info);
    reader->pixels.resize(rowBytes * height);
    reader->rows.resize(height);
    for (size_t y = 0; y < height; ++y) reader->rows[y] = reader->pixels.data() + y * rowBytes;
    png_read_image(png, reader->rows.data());
    png_read_end(png, nullptr);

    const int channels = png_get_channels(png, info);
    const bool sixteen = png_get_bit_depth(png, info) == 16;  // stored big-endian
    Image image(int(width), int(height), channels);
    const size_t values = width * size_t(channels);
    for (size_t y = 0; y < height; ++y) {
        const uchar* src = reader->rows[y];
        float* dst = image.row(int(y));
        for (size_t i = 0; i < values; ++i)
            dst[i] = sixteen ? float(bigEndian16(src + 2 * i)) / 65535.0f : float(src[i]) / 255.0f;
    }
    return image;
}

// OpenCV's EXR decoder reads only files: cv::imdecode copies the bytes to
// a temporary file of its own and leaves it behind when its size check
// throws. So the bytes go to a file we own instead (an AtomicFile in the
// temporary folder: exclusive, random name, removed on return, on an
// exception and on SIGINT/SIGTERM), which cv::imread reads in place.
void decodeExr(const std::string& path, const std::vector<uchar>& bytes, cv::Mat& out) {
    std::error_code ec;
    const fs::path folder = fs::temp_directory_path(ec);
    if (ec) throw InputError(path + ": no temporary folder to decode OpenEXR through (" + ec.message() + ")");
    AtomicFile scratch((folder / "stochtex-exr-read").string(), ".exr");
    scratch.write({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
    ::close(scratch.releaseDescriptor());
    mediaCodecs().readImageFile(scratch.tempPath(), out);
}  // the destructor removes the file (it is never committed)

// OpenCV's imread/imdecode print their decoders' failures on std::cerr
// ("imread_(...): can't read data: unknown exception"); the InputError says
// it in our words instead. Decodes are serialised while std::cerr is muted.
class MutedCerr {
public:
    MutedCerr() : lock_(mutex()), saved_(std::cerr.rdbuf(nullptr)) {}
    ~MutedCerr() {
        std::cerr.rdbuf(saved_);
        std::cerr.clear();  // writing to a null buffer set badbit
    }
    MutedCerr(const MutedCerr&) = delete;
    MutedCerr& operator=(const MutedCerr&) = delete;

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> lock_;
    std::streambuf* saved_;
};

// EXR and JPEG through OpenCV, once the header passed checkImageSize.
Image decodeWithOpenCv(const std::string& path, const ImageHeader& header, const std::vector<uchar>& bytes) {
    const MediaCodecs& codecs = mediaCodecs();  // loaded before std::cerr is muted: its failure is not the file's
    cv::Mat m;
    try {
        const MutedCerr muted;
        if (header.format == ImageFormat::Exr)
            decodeExr(path, bytes, m);
        else
            codecs.decodeImage(bytes, m);
    } catch (const cv::Exception&) {
        m.release();  // OpenCV's assertion text says nothing to the user; the message below does
    }
    if (m.empty()) throw InputError(path + ": corrupt image (the pixel data cannot be decoded)");
    const int channels = m.channels();
    if (channels != 1 && channels != 3 && channels != 4)
        throw InputError(path + ": unsupported channel count " + std::to_string(channels));
    double scale = 1.0;
    switch (m.depth()) {
        case CV_8U: scale = 1.0 / 255.0; break;
        case CV_16U: scale = 1.0 / 65535.0; break;
        case CV_32F:
        case CV_64F: scale = 1.0; break;
        default: throw InputError(path + ": unsupported pixel depth");
    }
    cv::Mat f;
    m.convertTo(f, CV_32F, scale);
    if (channels == 3) cv::cvtColor(f, f, cv::COLOR_BGR2RGB);
    if (channels == 4) cv::cvtColor(f, f, cv::COLOR_BGRA2RGBA);
    Image image(f.cols, f.rows, channels);
    for (int y = 0; y < f.rows; ++y) std::copy_n(f.ptr<float>(y), size_t(f.cols) * size_t(channels), image.row(y));
    return image;
}

}  // namespace

bool holdsFloatValues(const std::string& path) {
    char magic[4] = {};
    std::ifstream in(path, std::ios::binary);
    return in.read(magic, 4) && std::memcmp(magic, kExrMagic, 4) == 0;
}

bool isSupportedImagePath(const std::string& path) { return outputFormatOf(path).has_value(); }

void checkImageOutputFormat(const std::string& path, const WriteOptions& options) {
    const std::optional<OutputFormat> format = outputFormatOf(path);
    if (!format)
        throw InputError(path + ": unsupported output format '" + lowerExtension(path) + "' (use " +
                         kImageOutputFormats + ")");
    const int bits = options.bitDepth;
    const bool ok = *format == OutputFormat::Exr || bits == 8 || (bits == 16 && *format != OutputFormat::Jpeg);
    if (!ok)
        throw InputError(path +
                         (*format == OutputFormat::Jpeg ? ": JPEG holds 8 bits per channel, got "
                                                        : ": PNG and TIFF hold 8 or 16 bits per channel, got ") +
                         std::to_string(bits));
}

namespace {

// The file's bytes (its first `most` only, where it is longer), checked as
// readImage checks them before decoding.
std::vector<uchar> readImageBytes(const std::string& path, uintmax_t most = UINTMAX_MAX) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path + ": is a folder, not an image file");
    if (!fs::is_regular_file(path, ec)) throw InputError(path + ": no such image file");
    const uintmax_t fileSize = fs::file_size(path, ec);
    if (ec) throw InputError(path + ": cannot read file: " + ec.message());
    if (fileSize == 0) throw InputError(path + ": the file is empty");
    if (fileSize > uintmax_t(kMaxImageFileBytes))
        throw InputError(path + ": the file is larger than " + std::to_string(kMaxImageFileBytes >> 20) +
                         " MiB, more than an image of " + std::to_string(kMaxImagePixels) + " pixels needs");
    std::vector<uchar> bytes(static_cast<size_t>(std::min(fileSize, most)));
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!in) throw InputError(path + ": cannot read file");
    return bytes;
}

}  // namespace

std::array<int, 2> readImageSize(const std::string& path) {
    // A header is near the start: a PNG's in 33 bytes, a JPEG's after its
    // APP segments (64 KiB each at most), an EXR's after its attributes.
    // One not found in the first MiB is looked for in the whole file, so
    // the answer and the message are readImage's.
    constexpr uintmax_t kHeaderBytes = 1 << 20;
    const std::vector<uchar> start = readImageBytes(path, kHeaderBytes);
    std::optional<ImageHeader> found;
    try {
        found = readHeader(path, start, start.size() < kHeaderBytes);
    } catch (const InputError&) {
        if (start.size() < kHeaderBytes) throw;
    }
    const ImageHeader header = found ? *found : readHeader(path, readImageBytes(path));
    checkImageSize(path, header);
    return {int(header.width), int(header.height)};
}

Image readImage(const std::string& path) {
    const std::vector<uchar> bytes = readImageBytes(path);
    const ImageHeader header = readHeader(path, bytes);
    checkImageSize(path, header);
    Image image = header.format == ImageFormat::Png ? decodePng(path, bytes) : decodeWithOpenCv(path, header, bytes);
    if (image.width() != header.width || image.height() != header.height)
        throw InputError(path + ": corrupt image (its header and its pixels disagree on the size)");
    for (float v : image.data())
        if (!std::isfinite(v)) throw InputError(path + ": contains NaN or infinite values");
    return image;
}

namespace {

// PNG and EXR are streamed a band of rows at a time: beside the image they
// hold a band and its encoding (whole-image encoders held two to four
// copies). An EXR band is 16 of its 16-row blocks, compressed in parallel.
constexpr int kPngBandRows = 64, kExrBandRows = 256;

template <class Writer>
void writeBands(Writer& writer, const Image& image, int bandRows) {
    Image band(image.width(), std::min(bandRows, image.height()), image.channels(), Image::Uninitialized{});
    for (int y0 = 0; y0 < image.height(); y0 += bandRows) {
        const int rows = std::min(bandRows, image.height() - y0);
        if (rows < band.height()) band = Image(image.width(), rows, image.channels(), Image::Uninitialized{});
        std::copy_n(image.row(y0), band.data().size(), band.data().data());
        writer.writeRows(band);
    }
    writer.finish();
}

// The image's integer codes (sRGB for colour, colour_space.h) in OpenCV's
// channel order, a band of rows at a time: beside the image this holds a
// band and the codes (a quarter or half of the image's bytes), where whole
// copies (encoded, swapped, converted) held three.
cv::Mat integerCodes(const Image& image, const WriteOptions& options) {
    const int channels = image.channels(), width = image.width();
    const bool sixteen = options.bitDepth == 16;
    const float maxCode = sixteen ? 65535.0f : 255.0f;
    cv::Mat codes(image.height(), width, CV_MAKETYPE(sixteen ? CV_16U : CV_8U, channels));
    constexpr int kBandRows = 64;
    for (int y0 = 0; y0 < image.height(); y0 += kBandRows) {
        const int rows = std::min(kBandRows, image.height() - y0);
        Image band(width, rows, channels, Image::Uninitialized{});
        std::copy_n(image.row(y0), band.data().size(), band.data().data());
        const Image coded = encodeTransfer(band, options.transfer);
        for (int y = 0; y < rows; ++y) {
            const float* src = coded.row(y);
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < channels; ++c) {
                    const int to = channels >= 3 && c < 3 ? 2 - c : c;  // RGB(A) → BGR(A)
                    const long code = integerCode(src[size_t(x) * size_t(channels) + size_t(c)], maxCode);
                    if (sixteen)
                        codes.ptr<uint16_t>(y0 + y)[size_t(x) * size_t(channels) + size_t(to)] = uint16_t(code);
                    else
                        codes.ptr<uint8_t>(y0 + y)[size_t(x) * size_t(channels) + size_t(to)] = uint8_t(code);
                }
        }
    }
    return codes;
}

void checkWritable(const std::string& path, const Image& image, OutputFormat format) {
    if (image.empty()) throw InputError(path + ": refusing to write an empty image");
    if ((format == OutputFormat::Png || format == OutputFormat::Exr) && image.channels() == 2)
        throw InputError(path + (format == OutputFormat::Png ? ": a PNG" : ": an EXR") +
                         " is written from 1, 3 or 4 channels, got 2");
}

}  // namespace

std::vector<unsigned char> encodeImage(const std::string& path, const Image& image, const WriteOptions& options) {
    checkImageOutputFormat(path, options);
    const OutputFormat format = *outputFormatOf(path);
    checkWritable(path, image, format);
    if (format == OutputFormat::Png) {
        std::vector<unsigned char> bytes;
        PngStreamWriter png(bytes, path, image.width(), image.height(), image.channels(), options.bitDepth,
                            options.transfer);
        writeBands(png, image, kPngBandRows);
        return bytes;
    }
    if (format == OutputFormat::Exr) {
        std::vector<unsigned char> bytes;
        ExrStreamWriter exr(bytes, path, image.width(), image.height(), image.channels(), options.exrHalf);
        writeBands(exr, image, kExrBandRows);
        return bytes;
    }
    const cv::Mat encoded = integerCodes(image, options);
    std::vector<int> params;
    if (format == OutputFormat::Jpeg) params = {cv::IMWRITE_JPEG_QUALITY, kJpegQuality};
    if (format == OutputFormat::Tiff) params = {cv::IMWRITE_TIFF_COMPRESSION, kTiffCompressionLzw};
    std::vector<uchar> buffer;
    bool ok = false;
    try {
        // imencode picks its encoder by this name (media_codecs.h).
        const char* extension = format == OutputFormat::Jpeg ? ".jpg" : ".tif";
        ok = mediaCodecs().encodeImage(extension, encoded, params, buffer);
    } catch (const cv::Exception& e) {
        throw InputError(path + ": cannot encode image (" + e.msg + ")");
    }
    if (!ok) throw InputError(path + ": cannot encode image");
    return buffer;
}

void writeImage(const std::string& path, const Image& image, const WriteOptions& options) {
    checkImageOutputFormat(path, options);
    const OutputFormat format = *outputFormatOf(path);
    checkWritable(path, image, format);
    if (format == OutputFormat::Png) {
        PngStreamWriter png(path, image.width(), image.height(), image.channels(), options.bitDepth, options.transfer);
        writeBands(png, image, kPngBandRows);
        return;
    }
    if (format == OutputFormat::Exr) {
        ExrStreamWriter exr(path, image.width(), image.height(), image.channels(), options.exrHalf);
        writeBands(exr, image, kExrBandRows);
        return;
    }
    const std::vector<unsigned char> buffer = encodeImage(path, image, options);
    AtomicFile file(path);
    file.write({reinterpret_cast<const char*>(buffer.data()), buffer.size()});
    file.commit();
}

}  // namespace stochtex
