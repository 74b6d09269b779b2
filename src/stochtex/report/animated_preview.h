#pragma once
// An animated preview of a frame sequence for HTML pages: an animated WebP
// (libwebp's WebPAnimEncoder; every current browser shows it in an <img>,
// in full colour, where a GIF has 256), frames scaled down to at most
// maxSide pixels and encoded lossy as they come; written atomically by
// finish(). The MP4 beside it keeps the full resolution.
#include <memory>
#include <string>

#include "stochtex/image/image.h"

namespace stochtex {

class AnimatedPreviewWriter {
public:
    // path: the .webp to write; width × height: the frames' size; fps > 0.
    AnimatedPreviewWriter(const std::string& path, int width, int height, double fps, int maxSide = 256,
                          float quality = 80.0f);
    ~AnimatedPreviewWriter();
    // A frame of display codes in [0, 1] (already sRGB-encoded where colour), 1 or 3 channels.
    void add(const Image& codes);
    int frames() const { return count_; }
    // Assembles the animation and writes it; returns the path.
    std::string finish();

private:
    struct Encoder;
    std::string path_;
    int width_, height_, outWidth_, outHeight_, count_ = 0;
    double fps_;
    float quality_;
    std::unique_ptr<Encoder> encoder_;
};

}  // namespace stochtex
