#pragma once
// Images written a band of rows at a time, so that an image larger than
// memory can be produced (bake-image): PNG through PngStreamWriter (8/16-bit,
// values clamped to [0, 1]) or OpenEXR through ExrStreamWriter (32-bit
// float, values as they are). The file appears under its name only when
// finish() succeeds (AtomicFile).
#include <memory>
#include <string>

#include "stochtex/core/atomic_file.h"
#include "stochtex/image/image.h"

namespace stochtex {

class ImageStreamWriter {
public:
    virtual ~ImageStreamWriter() = default;
    // The next band of rows, top to bottom, with the channels given at opening.
    virtual void writeRows(const Image& band) = 0;
    virtual void finish() = 0;
};

// A scanline OpenEXR file, uncompressed, one FLOAT channel per image channel
// ("Y" for 1 channel; "B", "G", "R" for 3, stored in that order as OpenEXR
// sorts them): 12 bytes a pixel for RGB. Without compression every block's
// size is known in advance, so the offset table is written first and the
// rows follow as they come. Readers (OpenEXR, OpenCV, Blender, Nuke) treat
// the values as linear.
class ExrStreamWriter final : public ImageStreamWriter {
public:
    ExrStreamWriter(const std::string& path, int width, int height, int channels);
    void writeRows(const Image& band) override;
    void finish() override;

private:
    AtomicFile file_;
    int width_, height_, channels_, written_ = 0;
};

// Throws InputError naming the path unless its extension is .png or .exr.
void checkImageStreamFormat(const std::string& path);

// By extension: .png (bits 8 or 16) or .exr (float; bits not used);
// checkImageStreamFormat's error for any other. channels: 1 or 3.
std::unique_ptr<ImageStreamWriter> openImageStream(const std::string& path, int width, int height, int channels,
                                                   int bits);

}  // namespace stochtex
