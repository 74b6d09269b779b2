#include "stochtex/report/video_encoder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stochtex {

bool hasVideoEncoder(VideoCodec codec) { return mediaCodecs().hasVideoEncoder(codec); }

VideoEncoder::VideoEncoder(const std::string& path, VideoCodec codec, int width, int height, double fps,
                           const std::string& name)
    : width_(width),
      height_(height),
      encoder_(mediaCodecs().openVideoEncoder(path, codec, width, height, fps, name.empty() ? path : name)),
      rgb_(size_t(paddedSide(width)) * size_t(paddedSide(height)) * 3) {}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add(const Image& codes) {
    if (codes.width() != width_ || codes.height() != height_ || (codes.channels() != 1 && codes.channels() != 3))
        throw std::invalid_argument("VideoEncoder::add: frame of another size or channel count");
    const int w = paddedSide(width_), h = paddedSide(height_), channels = codes.channels();
    // Padding repeats the last column and row.
    for (int y = 0; y < h; ++y) {
        const float* row = codes.row(std::min(y, height_ - 1));
        uint8_t* out = rgb_.data() + size_t(y) * size_t(w) * 3;
        for (int x = 0; x < w; ++x) {
            const float* p = row + size_t(std::min(x, width_ - 1)) * size_t(channels);
            for (int c = 0; c < 3; ++c)
                out[3 * x + c] = uint8_t(std::lround(255.0f * std::clamp(p[channels == 3 ? c : 0], 0.0f, 1.0f)));
        }
    }
    encoder_->add(rgb_.data());
}

void VideoEncoder::finish() { encoder_->finish(); }

}  // namespace stochtex
