#include "stochtex/image/image_stream.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/image/png_stream.h"

namespace stochtex {

namespace {

// OpenEXR stores every number little-endian.
void put32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xff);
}
void putFloat(std::string& out, float f) {
    uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    put32(out, bits);
}
void putAttribute(std::string& out, const char* name, const char* type, const std::string& value) {
    out.append(name).push_back('\0');
    out.append(type).push_back('\0');
    put32(out, uint32_t(value.size()));
    out += value;
}

constexpr uint32_t kPixelTypeFloat = 2;

// The channel names in OpenEXR's (alphabetical) order and, for each, the
// channel of our interleaved RGB rows it holds.
struct ExrChannel {
    const char* name;
    int source;
};
std::vector<ExrChannel> exrChannels(int channels) {
    if (channels == 1) return {{"Y", 0}};
    return {{"B", 2}, {"G", 1}, {"R", 0}};
}

std::string exrHeader(int width, int height, int channels) {
    std::string out("\x76\x2f\x31\x01", 4);
    put32(out, 2);  // version 2, single-part scanline file
    std::string list;
    for (const ExrChannel& c : exrChannels(channels)) {
        list.append(c.name).push_back('\0');
        put32(list, kPixelTypeFloat);
        list += std::string(4, '\0');  // pLinear 0, three reserved bytes
        put32(list, 1);                // x sampling
        put32(list, 1);                // y sampling
    }
    list.push_back('\0');
    putAttribute(out, "channels", "chlist", list);
    putAttribute(out, "compression", "compression", std::string(1, '\0'));  // NO_COMPRESSION
    std::string window;
    for (const int v : {0, 0, width - 1, height - 1}) put32(window, uint32_t(v));
    putAttribute(out, "dataWindow", "box2i", window);
    putAttribute(out, "displayWindow", "box2i", window);
    putAttribute(out, "lineOrder", "lineOrder", std::string(1, '\0'));  // INCREASING_Y
    std::string one, centre;
    putFloat(one, 1.0f);
    putFloat(centre, 0.0f);
    putFloat(centre, 0.0f);
    putAttribute(out, "pixelAspectRatio", "float", one);
    putAttribute(out, "screenWindowCenter", "v2f", centre);
    putAttribute(out, "screenWindowWidth", "float", one);
    out.push_back('\0');  // end of header
    return out;
}

class PngStream final : public ImageStreamWriter {
public:
    PngStream(const std::string& path, int width, int height, int channels, int bits)
        : png_(path, width, height, channels, bits) {}
    void writeRows(const Image& band) override { png_.writeRows(band); }
    void finish() override { png_.finish(); }

private:
    PngStreamWriter png_;
};

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace

// The path, once the size is known to be positive (checked before the
// AtomicFile member creates anything).
const std::string& checkedSize(const std::string& path, int width, int height) {
    if (width < 1 || height < 1) throw InputError(path + ": image size must be positive");
    return path;
}

ExrStreamWriter::ExrStreamWriter(const std::string& path, int width, int height, int channels)
    : file_(checkedSize(path, width, height)),
      width_(width),
      height_(height),
      channels_(channels) {
    if (channels != 1 && channels != 3) throw std::invalid_argument("ExrStreamWriter: 1 or 3 channels");
    std::string head = exrHeader(width, height, channels);
    // One scanline per block: its y, its byte count, then each channel's row.
    const uint64_t block = 8 + uint64_t(width) * uint64_t(channels) * 4;
    const uint64_t first = head.size() + 8 * uint64_t(height);
    for (int y = 0; y < height; ++y) {
        const uint64_t offset = first + uint64_t(y) * block;
        put32(head, uint32_t(offset & 0xffffffffu));
        put32(head, uint32_t(offset >> 32));
    }
    file_.write(head);
}

void ExrStreamWriter::writeRows(const Image& band) {
    if (band.width() != width_ || band.channels() != channels_ || written_ + band.height() > height_)
        throw std::invalid_argument("ExrStreamWriter: band does not fit the image");
    const std::vector<ExrChannel> order = exrChannels(channels_);
    std::string out;
    out.reserve(size_t(band.height()) * (8 + size_t(width_) * size_t(channels_) * 4));
    for (int y = 0; y < band.height(); ++y) {
        put32(out, uint32_t(written_ + y));
        put32(out, uint32_t(width_ * channels_ * 4));
        const float* row = band.row(y);
        for (const ExrChannel& c : order)
            for (int x = 0; x < width_; ++x) putFloat(out, row[size_t(x) * size_t(channels_) + size_t(c.source)]);
    }
    file_.write(out);
    written_ += band.height();
}

void ExrStreamWriter::finish() {
    if (written_ != height_) throw std::logic_error("ExrStreamWriter: not every row was written");
    file_.commit();
}

void checkImageStreamFormat(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".png" && ext != ".exr")
        throw InputError(path + ": unsupported output format '" + ext + "' for an image written in bands (use .png or .exr)");
}

std::unique_ptr<ImageStreamWriter> openImageStream(const std::string& path, int width, int height, int channels,
                                                   int bits) {
    checkImageStreamFormat(path);
    if (lowerExtension(path) == ".png") return std::make_unique<PngStream>(path, width, height, channels, bits);
    return std::make_unique<ExrStreamWriter>(path, width, height, channels);
}

}  // namespace stochtex
