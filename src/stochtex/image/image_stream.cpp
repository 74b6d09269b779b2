#include "stochtex/image/image_stream.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/png_stream.h"

namespace stochtex {

namespace {

// OpenEXR stores every number little-endian.
void put16(std::string& out, uint16_t v) {
    out += char(v & 0xff);
    out += char(v >> 8);
}
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

constexpr uint32_t kPixelTypeHalf = 1, kPixelTypeFloat = 2;
constexpr char kZipCompression = 3;  // OpenEXR's ZIP_COMPRESSION: zlib over blocks of 16 rows
constexpr int kBlockRows = 16;
// zlib's level: OpenEXR's own default since 3.1, most of level 9's size at a fraction of its time.
constexpr int kZlibLevel = 4;

// The channel names in OpenEXR's (alphabetical) order and, for each, the
// channel of our interleaved rows it holds.
struct ExrChannel {
    const char* name;
    int source;
};
std::vector<ExrChannel> exrChannels(int channels) {
    if (channels == 1) return {{"Y", 0}};
    if (channels == 4) return {{"A", 3}, {"B", 2}, {"G", 1}, {"R", 0}};
    return {{"B", 2}, {"G", 1}, {"R", 0}};
}

std::string exrHeader(int width, int height, int channels, bool half) {
    std::string out("\x76\x2f\x31\x01", 4);
    put32(out, 2);  // version 2, single-part scanline file
    std::string list;
    for (const ExrChannel& c : exrChannels(channels)) {
        list.append(c.name).push_back('\0');
        put32(list, half ? kPixelTypeHalf : kPixelTypeFloat);
        list += std::string(4, '\0');  // pLinear 0, three reserved bytes
        put32(list, 1);                // x sampling
        put32(list, 1);                // y sampling
    }
    list.push_back('\0');
    putAttribute(out, "channels", "chlist", list);
    putAttribute(out, "compression", "compression", std::string(1, kZipCompression));
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

// One block as the file holds it: its first row, its byte count, its data.
// The data are the rows' values, row by row and in each row channel by
// channel; ZIP splits their bytes into the even- and odd-numbered halves
// and replaces each byte by its difference to the one before (+128), which
// zlib compresses better; a block that would not shrink is stored as it is
// (a reader knows it by its size).
std::string encodeBlock(const float* rows, int count, int firstRow, int width, int channels, bool half) {
    std::string raw;
    raw.reserve(size_t(count) * size_t(width) * size_t(channels) * (half ? 2 : 4));
    const std::vector<ExrChannel> order = exrChannels(channels);
    for (int y = 0; y < count; ++y) {
        const float* row = rows + size_t(y) * size_t(width) * size_t(channels);
        for (const ExrChannel& c : order)
            for (int x = 0; x < width; ++x) {
                const float v = row[size_t(x) * size_t(channels) + size_t(c.source)];
                if (half)
                    put16(raw, halfFromFloat(v));
                else
                    putFloat(raw, v);
            }
    }
    std::string split(raw.size(), '\0');
    const size_t halfway = (raw.size() + 1) / 2;
    for (size_t i = 0; i < raw.size(); ++i) split[i % 2 ? halfway + i / 2 : i / 2] = raw[i];
    for (size_t i = split.size(); i-- > 1;) split[i] = char(uint8_t(split[i]) - uint8_t(split[i - 1]) + 128);
    uLongf packedSize = compressBound(uLong(split.size()));
    std::string packed(packedSize, '\0');
    if (compress2(reinterpret_cast<Bytef*>(packed.data()), &packedSize, reinterpret_cast<const Bytef*>(split.data()),
                  uLong(split.size()), kZlibLevel) != Z_OK)
        throw std::bad_alloc();  // zlib fails only for want of memory with a buffer of compressBound
    const std::string& data = packedSize < raw.size() ? packed.erase(packedSize) : raw;
    std::string block;
    block.reserve(8 + data.size());
    put32(block, uint32_t(firstRow));
    put32(block, uint32_t(data.size()));
    block += data;
    return block;
}

class PngStream final : public ImageStreamWriter {
public:
    PngStream(const std::string& path, int width, int height, int channels, int bits, Transfer transfer)
        : png_(path, width, height, channels, bits, transfer) {}
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

namespace {

void checkShape(const std::string& path, int width, int height, int channels) {
    if (width < 1 || height < 1) throw InputError(path + ": image size must be positive");
    if (channels != 1 && channels != 3 && channels != 4)
        throw InputError(path + ": an EXR is written from 1, 3 or 4 channels, got " + std::to_string(channels));
    // A block's byte count is a signed 32-bit field.
    if (uint64_t(width) * uint64_t(channels) * 4 * kBlockRows > uint64_t(INT32_MAX))
        throw InputError(path + ": an EXR row of " + std::to_string(width) + " pixels is too wide for its blocks");
}

}  // namespace

uint16_t halfFromFloat(float value) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, 4);
    const auto sign = uint16_t((bits >> 16) & 0x8000);
    const uint32_t magnitude = bits & 0x7fffffff;
    if (magnitude > 0x7f800000) return sign | 0x7e00;   // NaN: quiet
    if (magnitude >= 0x47800000) return sign | 0x7c00;  // ≥ 65536 (and infinity): infinite
    if (magnitude < 0x38800000) {                       // below 2⁻¹⁴: a subnormal half, in units of 2⁻²⁴
        if (magnitude < 0x33000000) return sign;        // below 2⁻²⁵: zero
        const uint32_t mantissa = (magnitude & 0x7fffff) | 0x800000;
        const uint32_t shift = 126 - (magnitude >> 23);  // 14 … 24
        uint32_t q = mantissa >> shift;
        const uint32_t rest = mantissa & ((1u << shift) - 1), tie = 1u << (shift - 1);
        if (rest > tie || (rest == tie && (q & 1))) ++q;  // to nearest, ties to even (may reach 2⁻¹⁴)
        return sign | uint16_t(q);
    }
    uint32_t h = (magnitude >> 13) - (112u << 10);  // exponent rebiased 127 → 15, top 10 mantissa bits
    const uint32_t rest = magnitude & 0x1fff;
    if (rest > 0x1000 || (rest == 0x1000 && (h & 1))) ++h;  // a carry may reach the exponent, up to infinity
    return sign | uint16_t(h);
}

ExrStreamWriter::ExrStreamWriter(const std::string& path, int width, int height, int channels, bool half)
    : width_(width), height_(height), channels_(channels), half_(half) {
    checkShape(path, width, height, channels);
    file_ = std::make_unique<AtomicFile>(path);
    start();
}

ExrStreamWriter::ExrStreamWriter(std::vector<unsigned char>& out, const std::string& name, int width, int height,
                                 int channels, bool half)
    : memory_(&out), memoryStart_(out.size()), width_(width), height_(height), channels_(channels), half_(half) {
    checkShape(name, width, height, channels);
    start();
}

ExrStreamWriter::~ExrStreamWriter() = default;

void ExrStreamWriter::start() {
    append(exrHeader(width_, height_, channels_, half_));
    tableAt_ = size_;
    const size_t blocks = (size_t(height_) + kBlockRows - 1) / kBlockRows;
    offsets_.reserve(blocks);
    append(std::string(8 * blocks, '\0'));  // the offset table, written by finish()
}

void ExrStreamWriter::append(const std::string& bytes) {
    if (memory_)
        memory_->insert(memory_->end(), bytes.begin(), bytes.end());
    else
        file_->write(bytes);
    size_ += bytes.size();
}

void ExrStreamWriter::writeBlocks(const float* rows, int count) {
    const size_t rowValues = size_t(width_) * size_t(channels_);
    const int blocks = (count + kBlockRows - 1) / kBlockRows;
    std::vector<std::string> encoded(static_cast<size_t>(blocks));
    parallelRows(blocks, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            encoded[size_t(b)] =
                encodeBlock(rows + size_t(b) * kBlockRows * rowValues, std::min(kBlockRows, count - b * kBlockRows),
                            int(offsets_.size()) * kBlockRows + b * kBlockRows, width_, channels_, half_);
    });
    for (const std::string& block : encoded) {
        offsets_.push_back(size_);
        append(block);
    }
}

void ExrStreamWriter::writeRows(const Image& band) {
    if (band.width() != width_ || band.channels() != channels_ || written_ + band.height() > height_)
        throw std::invalid_argument("ExrStreamWriter: band does not fit the image");
    const size_t rowValues = size_t(width_) * size_t(channels_);
    int used = 0;             // rows of the band in blocks or pending
    if (!pending_.empty()) {  // first complete the block the last band began
        const int have = int(pending_.size() / rowValues);
        used = std::min(kBlockRows - have, band.height());
        pending_.insert(pending_.end(), band.row(0), band.row(0) + size_t(used) * rowValues);
        if (have + used == kBlockRows || written_ + used == height_) {
            writeBlocks(pending_.data(), have + used);
            pending_.clear();
        }
    }
    written_ += band.height();
    const int left = band.height() - used;
    // Whole blocks straight from the band; the image's last rows make a block of their own.
    const int whole = written_ == height_ ? left : left / kBlockRows * kBlockRows;
    if (whole > 0) writeBlocks(band.row(used), whole);
    used += whole;
    if (used < band.height())
        pending_.assign(band.row(used), band.row(used) + size_t(band.height() - used) * rowValues);
}

void ExrStreamWriter::finish() {
    if (written_ != height_) throw std::logic_error("ExrStreamWriter: not every row was written");
    std::string table;
    for (const uint64_t offset : offsets_) {
        put32(table, uint32_t(offset & 0xffffffffu));
        put32(table, uint32_t(offset >> 32));
    }
    if (memory_) {
        std::copy(table.begin(), table.end(), memory_->begin() + long(memoryStart_ + tableAt_));
        return;
    }
    file_->writeAt(tableAt_, table);
    file_->commit();
}

void checkImageStreamFormat(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".png" && ext != ".exr")
        throw InputError(path + ": unsupported output format '" + ext +
                         "' for an image written in bands (use .png or .exr)");
}

std::unique_ptr<ImageStreamWriter> openImageStream(const std::string& path, int width, int height, int channels,
                                                   int bits, Transfer transfer) {
    checkImageStreamFormat(path);
    if (lowerExtension(path) == ".png")
        return std::make_unique<PngStream>(path, width, height, channels, bits, transfer);
    return std::make_unique<ExrStreamWriter>(path, width, height, channels);
}

}  // namespace stochtex
