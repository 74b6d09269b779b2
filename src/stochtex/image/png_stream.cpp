#include "stochtex/image/png_stream.h"

#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"

namespace stochtex {

namespace {

// Where libpng's output goes, a file or memory: our write function keeps the
// reason a write failed (errno), which libpng's own reduces to "Write Error".
struct Sink {
    FILE* file = nullptr;
    std::vector<unsigned char>* memory = nullptr;
    std::string failure;  // why a write failed, if one failed
};

void writeBytes(png_structp png, png_bytep data, png_size_t n) {
    auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
    if (sink->memory) {
        // No exception may cross libpng's C frames, and png_error's longjmp
        // may not leave a catch block (the exception would never be freed).
        bool grown = true;
        try {
            sink->memory->insert(sink->memory->end(), data, data + n);
        } catch (const std::exception&) {  // bad_alloc, length_error
            grown = false;
        }
        if (!grown) {
            sink->failure = "out of memory";
            png_error(png, "write failed");
        }
    } else if (std::fwrite(data, 1, n, sink->file) != n) {
        sink->failure = std::strerror(errno);
        png_error(png, "write failed");
    }
}

void flushBytes(png_structp png) {
    if (FILE* file = static_cast<Sink*>(png_get_io_ptr(png))->file) std::fflush(file);
}

}  // namespace

struct PngStreamWriter::Impl {
    std::string path;
    std::unique_ptr<AtomicFile> output;  // the temporary file, renamed by finish(); none into memory
    Sink sink;                           // the temporary file or memory, as libpng writes to it
    png_structp png = nullptr;
    png_infop info = nullptr;
    int width = 0, height = 0, channels = 0, bits = 8, written = 0;
    Transfer transfer = Transfer::Srgb;
    std::string error;
    // The error after libpng jumped back: the write's reason where a write failed.
    [[noreturn]] void fail() const {
        if (!sink.failure.empty()) throw InputError(path + ": write failed: " + sink.failure);
        throw InputError(path + ": PNG error: " + error);
    }
    // Here rather than in ~PngStreamWriter, so that a constructor that
    // throws half-way (libpng refusing the size) frees what it made too.
    ~Impl() {
        if (png) png_destroy_write_struct(&png, &info);
        if (sink.file) std::fclose(sink.file);
        // output removes the temporary file unless finish() committed it.
    }
};

namespace {

void onError(png_structp png, png_const_charp message) {
    *static_cast<std::string*>(png_get_error_ptr(png)) = message;
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

const int kColourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                            PNG_COLOR_TYPE_RGB_ALPHA};

void checkShape(const std::string& path, int width, int height, int channels, int bits) {
    if (width < 1 || height < 1) throw InputError(path + ": image size must be positive");
    if (channels < 1 || channels > 4) throw std::invalid_argument("PngStreamWriter: 1 to 4 channels");
    if (bits != 8 && bits != 16) throw InputError(path + ": PNG bit depth must be 8 or 16");
}

}  // namespace

PngStreamWriter::PngStreamWriter(const std::string& path, int width, int height, int channels, int bits,
                                 Transfer transfer)
    : impl_(std::make_unique<Impl>()) {
    checkShape(path, width, height, channels, bits);  // before the temporary file exists
    Impl& m = *impl_;
    m.path = path;
    m.output = std::make_unique<AtomicFile>(path);
    const int fd = m.output->releaseDescriptor();
    m.sink.file = fdopen(fd, "wb");
    if (!m.sink.file) {
        ::close(fd);
        throw InputError(path + ": cannot write (out of memory for a stream)");
    }
    start(width, height, channels, bits, transfer);
}

PngStreamWriter::PngStreamWriter(std::vector<unsigned char>& out, const std::string& name, int width, int height,
                                 int channels, int bits, Transfer transfer)
    : impl_(std::make_unique<Impl>()) {
    checkShape(name, width, height, channels, bits);
    impl_->path = name;
    impl_->sink.memory = &out;
    start(width, height, channels, bits, transfer);
}

void PngStreamWriter::start(int width, int height, int channels, int bits, Transfer transfer) {
    Impl& m = *impl_;
    const std::string& path = m.path;
    m.width = width;
    m.height = height;
    m.channels = channels;
    m.bits = bits;
    m.transfer = transfer;
    m.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &m.error, onError, onWarning);
    m.info = m.png ? png_create_info_struct(m.png) : nullptr;
    if (!m.png || !m.info) throw std::runtime_error(path + ": libpng could not start");
    if (setjmp(png_jmpbuf(m.png))) m.fail();
    png_set_write_fn(m.png, &m.sink, writeBytes, flushBytes);
    png_set_compression_level(m.png, 3);
    png_set_IHDR(m.png, m.info, png_uint_32(width), png_uint_32(height), bits, kColourTypes[channels - 1],
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(m.png, m.info);
    if (bits == 16) png_set_swap(m.png);  // our rows are little-endian uint16
}

PngStreamWriter::~PngStreamWriter() = default;

void PngStreamWriter::writeRows(const Image& band) {
    Impl& m = *impl_;
    if (band.width() != m.width || band.channels() != m.channels || m.written + band.height() > m.height)
        throw std::invalid_argument("PngStreamWriter: band does not fit the image");
    const size_t values = size_t(m.width) * size_t(m.channels);
    std::vector<unsigned char> row(values * size_t(m.bits / 8));
    const Image coded = encodeTransfer(band, m.transfer);  // before setjmp: a longjmp skips no destructor
    if (setjmp(png_jmpbuf(m.png))) m.fail();
    for (int y = 0; y < coded.height(); ++y) {
        const float* src = coded.row(y);
        if (m.bits == 8) {
            for (size_t i = 0; i < values; ++i) row[i] = static_cast<unsigned char>(integerCode(src[i], 255.0f));
        } else {
            for (size_t i = 0; i < values; ++i) {
                const auto v = static_cast<uint16_t>(integerCode(src[i], 65535.0f));
                row[2 * i] = static_cast<unsigned char>(v & 0xff);
                row[2 * i + 1] = static_cast<unsigned char>(v >> 8);
            }
        }
        png_write_row(m.png, row.data());
    }
    m.written += band.height();
}

void PngStreamWriter::finish() {
    Impl& m = *impl_;
    if (m.written != m.height) throw std::logic_error("PngStreamWriter: not every row was written");
    if (setjmp(png_jmpbuf(m.png))) m.fail();
    png_write_end(m.png, nullptr);
    png_destroy_write_struct(&m.png, &m.info);
    if (m.sink.memory) return;
    const int closed = std::fclose(m.sink.file);  // writes what stdio still buffers
    m.sink.file = nullptr;
    if (closed != 0) throw InputError(m.path + ": write failed: " + std::strerror(errno));
    m.output->commit();
}

}  // namespace stochtex
