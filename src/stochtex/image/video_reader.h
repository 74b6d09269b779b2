#pragma once
// A video file's frames, decoded in order (OpenCV videoio, in the media
// plugin: media_codecs.h), for inputs that
// play a video by time (a ShaderToy video channel). Only the frame asked for
// is held; going back reopens the file and decodes forward again.
#include <memory>
#include <string>

#include "stochtex/image/image.h"

namespace stochtex {

class VideoDecoder;

class VideoReader {
public:
    // InputError naming the file: missing, not a video OpenCV can decode, no frame.
    explicit VideoReader(const std::string& path);
    ~VideoReader();
    VideoReader(const VideoReader&) = delete;
    VideoReader& operator=(const VideoReader&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    double fps() const { return fps_; }
    // Frames in the file: as the container states it until the decoder meets
    // the end, then as counted.
    int frameCount() const { return frameCount_; }
    // Frame `index` (0-based; past the end, looping) as RGB codes in [0, 1],
    // row 0 the top.
    const Image& frame(int index);
    // The frame at `seconds` into the video, looping when `loop`, else held at the last.
    const Image& frameAt(double seconds, bool loop);
    // The index of the frame last returned.
    int frameIndex() const { return current_; }

private:
    void open();
    std::string path_;
    std::unique_ptr<VideoDecoder> video_;
    int width_ = 0, height_ = 0, frameCount_ = 0;
    double fps_ = 0;
    int next_ = 0;      // the index the decoder reads next
    int current_ = -1;  // the index in frame_
    bool countKnown_ = false;
    Image frame_;
};

}  // namespace stochtex
