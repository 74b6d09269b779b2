#pragma once
// Images written a band of rows at a time, so that an image larger than
// memory can be produced (bake-image, writeImage): PNG through
// PngStreamWriter (8/16-bit, values clamped to [0, 1]) or OpenEXR through
// ExrStreamWriter (32- or 16-bit floats, values as they are). The file
// appears under its name only when finish() succeeds (AtomicFile).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "stochtex/core/atomic_file.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/image/image.h"

namespace stochtex {

class ImageStreamWriter {
public:
    virtual ~ImageStreamWriter() = default;
    // The next band of rows, top to bottom, with the channels given at opening.
    virtual void writeRows(const Image& band) = 0;
    virtual void finish() = 0;
};

// A scanline OpenEXR file written as its rows come: one FLOAT (or HALF)
// channel per image channel ("Y" for 1 channel; "B", "G", "R" for 3 and "A",
// "B", "G", "R" for 4, in that order as OpenEXR sorts them), ZIP-compressed
// in blocks of 16 rows (OpenEXR's ZIP_COMPRESSION: bytes split into halves,
// a delta predictor, zlib; a block that would not shrink is stored as it
// is). The blocks of a band are compressed in parallel and written in
// order, so the file is the same for any thread count; the offset table,
// known only at the end, is written last over its place. Memory: a band
// and its blocks, whatever the image size. Readers (OpenEXR, OpenCV,
// Blender, Nuke) treat the values as linear. Into memory too (encodeImage).
class ExrStreamWriter final : public ImageStreamWriter {
public:
    // channels: 1, 3 or 4; half: 16-bit half floats (rounded to nearest
    // even, beyond ±65504 infinite), else 32-bit floats as they are.
    ExrStreamWriter(const std::string& path, int width, int height, int channels, bool half = false);
    // Into `out` (appended to), complete when finish() returns; `name` is what errors name.
    ExrStreamWriter(std::vector<unsigned char>& out, const std::string& name, int width, int height, int channels,
                    bool half = false);
    ~ExrStreamWriter() override;
    void writeRows(const Image& band) override;
    void finish() override;

private:
    void start();
    // `count` rows, the next after the blocks written: whole blocks, but the image's last.
    void writeBlocks(const float* rows, int count);
    void append(const std::string& bytes);
    std::unique_ptr<AtomicFile> file_;  // the temporary file, renamed by finish(); none into memory
    std::vector<unsigned char>* memory_ = nullptr;
    size_t memoryStart_ = 0;         // where this image starts in *memory_
    uint64_t size_ = 0;              // bytes written so far
    uint64_t tableAt_ = 0;           // where the offset table starts
    std::vector<uint64_t> offsets_;  // of each block written
    std::vector<float> pending_;     // rows of an unfinished block, between bands
    int width_, height_, channels_, written_ = 0;
    bool half_;
};

// The IEEE 754 half float nearest `value` (ties to even; beyond the largest
// half, 65504, infinite; NaN a quiet NaN), as OpenEXR's HALF stores it.
uint16_t halfFromFloat(float value);

// Throws InputError naming the path unless its extension is .png or .exr.
void checkImageStreamFormat(const std::string& path);

// By extension: .png (bits 8 or 16) or .exr (float; bits not used);
// checkImageStreamFormat's error for any other. channels: 1 or 3.
// transfer: of a PNG's codes (Srgb: the bands are linear colour; Linear:
// data written as it is); an EXR holds the values.
std::unique_ptr<ImageStreamWriter> openImageStream(const std::string& path, int width, int height, int channels,
                                                   int bits, Transfer transfer = Transfer::Srgb);

}  // namespace stochtex
