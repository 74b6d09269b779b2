#pragma once
// A frame sequence on disk: frame_NNNN.png for every frame, plus an MP4
// (zoom.mp4) where OpenCV's videoio and an encoder are available. The MP4 is
// written under a temporary name and renamed by finish().
#include <memory>
#include <string>

#include "stochtex/image/image.h"

namespace stochtex::cli {

class FrameSequenceWriter {
public:
    // video: also try the MP4 (a note on stderr when it cannot be written).
    FrameSequenceWriter(const std::string& dir, int width, int height, double fps, bool video);
    ~FrameSequenceWriter();
    void write(const Image& frame);  // 1-channel, [0, 1]
    // Closes the MP4; returns its path, or "" when none was written.
    std::string finish();

private:
    struct Video;
    std::string dir_;
    int count_ = 0;
    std::unique_ptr<Video> video_;
};

}  // namespace stochtex::cli
