#pragma once
// An animated GIF of a frame sequence (giflib): each frame quantised to its
// own 256-colour palette (giflib's median cut) and encoded once the next
// frame gives its delay, so memory is two frames; delays in centiseconds,
// rounded so that the clip keeps its pace (at 30 fps: 3, 4, 3, …), and above
// 50 fps frames are dropped rather than shown at under 2 cs, which browsers
// stretch to 10 cs. It loops forever. Written to a temporary file and moved into place by finish();
// unfinished, it leaves no file. A GIF plays everywhere but has 256 colours
// a frame: the animated WebP (animated_preview.h) keeps full colour.
#include <memory>
#include <string>

#include "stochtex/image/image.h"

namespace stochtex {

class AnimatedGifWriter {
public:
    // path: the .gif to write; width × height: the frames' size (≤ 65535); fps in (0, 1000].
    AnimatedGifWriter(const std::string& path, int width, int height, double fps);
    ~AnimatedGifWriter();
    // A frame of display codes in [0, 1] (already sRGB-encoded where colour), 1 or 3 channels.
    void add(const Image& codes);
    int frames() const { return count_; }  // added (above 50 fps some are dropped)
    // Closes the file and moves it into place; returns the path.
    std::string finish();

private:
    struct Encoder;
    struct Pending;
    void put(const Pending& frame, int delay);
    int width_, height_, count_ = 0;
    double fps_;
    std::unique_ptr<Encoder> encoder_;
    std::unique_ptr<Pending> pending_;
};

}  // namespace stochtex
