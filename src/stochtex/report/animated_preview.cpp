#include "stochtex/report/animated_preview.h"

#include <webp/encode.h>
#include <webp/mux.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"

namespace stochtex {

struct AnimatedPreviewWriter::Encoder {
    WebPAnimEncoder* encoder = nullptr;
    ~Encoder() {
        if (encoder) WebPAnimEncoderDelete(encoder);
    }
};

AnimatedPreviewWriter::AnimatedPreviewWriter(const std::string& path, int width, int height, double fps, int maxSide,
                                             float quality)
    : path_(path), width_(width), height_(height), fps_(fps), quality_(quality), encoder_(std::make_unique<Encoder>()) {
    if (width < 1 || height < 1 || !(fps > 0) || maxSide < 1)
        throw std::invalid_argument("AnimatedPreviewWriter: bad size, fps or maxSide");
    const double shrink = std::min(1.0, double(maxSide) / std::max(width, height));
    outWidth_ = std::max(1, int(std::lround(width * shrink)));
    outHeight_ = std::max(1, int(std::lround(height * shrink)));
    WebPAnimEncoderOptions options;
    if (!WebPAnimEncoderOptionsInit(&options)) throw std::runtime_error("libwebp: version mismatch");
    options.anim_params.loop_count = 0;  // forever
    encoder_->encoder = WebPAnimEncoderNew(outWidth_, outHeight_, &options);
    if (!encoder_->encoder) throw std::runtime_error("libwebp: cannot create an animation encoder");
}

AnimatedPreviewWriter::~AnimatedPreviewWriter() = default;

void AnimatedPreviewWriter::add(const Image& codes) {
    if (codes.width() != width_ || codes.height() != height_ || (codes.channels() != 1 && codes.channels() != 3))
        throw std::invalid_argument("AnimatedPreviewWriter::add: frame of another size or channel count");
    const Image small = outWidth_ == width_ ? codes : resizeSmooth(codes, outWidth_, outHeight_);
    std::vector<uint8_t> rgb(size_t(outWidth_) * size_t(outHeight_) * 3);
    for (int y = 0; y < outHeight_; ++y)
        for (int x = 0; x < outWidth_; ++x)
            for (int c = 0; c < 3; ++c) {
                const float v = small.at(x, y, small.channels() == 1 ? 0 : c);
                rgb[(size_t(y) * size_t(outWidth_) + size_t(x)) * 3 + size_t(c)] =
                    uint8_t(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f)));
            }
    WebPConfig config;
    if (!WebPConfigInit(&config)) throw std::runtime_error("libwebp: version mismatch");
    config.quality = quality_;
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("libwebp: version mismatch");
    picture.width = outWidth_;
    picture.height = outHeight_;
    picture.use_argb = 1;
    if (!WebPPictureImportRGB(&picture, rgb.data(), outWidth_ * 3)) throw std::bad_alloc();
    const int timestamp = int(std::lround(1000.0 * count_ / fps_));
    const int ok = WebPAnimEncoderAdd(encoder_->encoder, &picture, timestamp, &config);
    WebPPictureFree(&picture);
    if (!ok) throw std::runtime_error(std::string("libwebp: ") + WebPAnimEncoderGetError(encoder_->encoder));
    ++count_;
}

std::string AnimatedPreviewWriter::finish() {
    const int end = int(std::lround(1000.0 * count_ / fps_));
    if (!WebPAnimEncoderAdd(encoder_->encoder, nullptr, end, nullptr))
        throw std::runtime_error(std::string("libwebp: ") + WebPAnimEncoderGetError(encoder_->encoder));
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAssemble(encoder_->encoder, &data))
        throw std::runtime_error(std::string("libwebp: ") + WebPAnimEncoderGetError(encoder_->encoder));
    const std::string bytes(reinterpret_cast<const char*>(data.bytes), data.size);
    WebPDataClear(&data);
    writeFileAtomic(path_, bytes);
    return path_;
}

}  // namespace stochtex
