#pragma once
// The plugin's video writer (media_codecs.h): H.264 in MP4 or VP9 in WebM
// through FFmpeg's libraries, as report/video_encoder.h describes.
#include <memory>
#include <string>

#include "stochtex/image/media_codecs.h"

namespace stochtex::media {

bool hasFfmpegEncoder(VideoCodec codec);
std::unique_ptr<VideoFileEncoder> openFfmpegEncoder(const std::string& path, VideoCodec codec, int width, int height,
                                                    double fps, const std::string& name);

}  // namespace stochtex::media
