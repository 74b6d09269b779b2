#pragma once
// A video file encoded through FFmpeg's libraries (libavcodec, libavformat,
// libswscale; Debian's FFmpeg builds libx264 and libvpx in): H.264 in MP4 or
// VP9 in WebM, what browsers, repository previews and paper pages play.
// Written for reproducible results: one encoder thread and no x264
// macroblock tree (either made two runs of one study differ), no creation time, the MP4's
// index first ("faststart") so a page can start playing it before it has
// all of it. Frames are 8-bit sRGB codes, converted to BT.709 4:2:0 (which
// needs even sides: an odd side is padded by repeating its last pixel row
// or column, so the video is one pixel larger there). The encoding runs in
// the media plugin (image/media_codecs.h), loaded by the first encoder.
#include <memory>
#include <string>
#include <vector>

#include "stochtex/image/image.h"
#include "stochtex/image/media_codecs.h"

namespace stochtex {

class VideoEncoder {
public:
    // path: written as it is (the container by `codec`: MP4 for H.264, WebM
    // for VP9); fps in (0, 1000]. InputError naming `name` (the output the
    // user asked for, where `path` is its temporary file; empty: path) when
    // FFmpeg lacks the encoder or the file cannot be written.
    VideoEncoder(const std::string& path, VideoCodec codec, int width, int height, double fps,
                 const std::string& name = {});
    ~VideoEncoder();
    // Display codes in [0, 1], 1 (gray) or 3 (RGB) channels, width × height.
    void add(const Image& codes);
    // Flushes the encoder and closes the file.
    void finish();

private:
    int width_, height_;
    std::unique_ptr<VideoFileEncoder> encoder_;
    std::vector<uint8_t> rgb_;  // a frame's codes as the encoder takes them
};

// Whether this FFmpeg build has the codec's encoder. Like the encoder, it
// keeps FFmpeg's log out of the terminal (its last error joins the message
// of a failure) unless the environment sets STOCHTEX_FFMPEG_LOG.
bool hasVideoEncoder(VideoCodec codec);

}  // namespace stochtex
